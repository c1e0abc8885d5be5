//! `Control::on_lower_bound` (clingo's `on_unsat`): core-guided optimization tells each lower
//! bound it proves, branch and bound none. clingo 5.8 on the vertex cover below
//! (run by hand with `--opt-strategy=usc`) reports `[1]`, ..., `[6]`, then the
//! optimal model of cost `[6]`; with two priority levels it reports `[1]`, `[2]`, then
//! `[2, 1]`, ... (the optimum of the level done, then the current level's bound); with the
//! default strategy it reports nothing. The cores, hence the exact sequence, are the
//! solver's own: the tests check the properties.

use lucent::control::{Control, Part, SolveOptions};
use std::sync::{Arc, Mutex};

const COVER: &str = "node(1..8). edge(X,Y) :- node(X), node(Y), X<Y, (X+Y)\\3 != 0.
{in(X)} :- node(X). :- edge(X,Y), not in(X), not in(Y).";

/// The bounds told and the costs of the models, in the order they came.
fn run(args: &[&str], minimize: &str) -> (Vec<Vec<i64>>, Vec<Vec<i64>>) {
    let mut ctl = Control::from_args(args).unwrap();
    ctl.add("base", &[], &format!("{COVER}\n{minimize}"))
        .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let told = Arc::new(Mutex::new(Vec::new()));
    let sink = told.clone();
    ctl.on_lower_bound(Some(Arc::new(Mutex::new(move |b: &[i64]| {
        sink.lock().unwrap().push(b.to_vec())
    }))));
    let mut costs = Vec::new();
    ctl.solve(&SolveOptions::default(), |m| {
        costs.push(m.costs().to_vec());
        true
    });
    let told = told.lock().unwrap().clone();
    (told, costs)
}

#[test]
fn core_guided_search_tells_rising_bounds_up_to_the_optimum() {
    let (told, costs) = run(&["--opt-strategy=usc"], "#minimize{1,X:in(X)}.");
    assert_eq!(costs.last(), Some(&vec![6]));
    assert_eq!(told.first().map(Vec::len), Some(1), "{told:?}");
    assert!(told.windows(2).all(|w| w[0] < w[1]), "{told:?}");
    assert_eq!(
        told.last(),
        Some(&vec![6]),
        "the last core proves the optimum"
    );
}

#[test]
fn each_level_done_leads_the_next_levels_bounds() {
    let (told, costs) = run(
        &["--opt-strategy=usc"],
        "#minimize{1@2,X:in(X), X < 5}. #minimize{1@1,X:in(X), X >= 5}.",
    );
    let best = costs.last().unwrap().clone();
    assert_eq!(best.len(), 2);
    assert!(told.windows(2).all(|w| w[0] < w[1]), "{told:?}");
    for b in &told {
        assert!(
            b.len() <= 2 && b[..] <= best[..b.len()],
            "{b:?} against {best:?}"
        );
        if b.len() == 2 {
            assert_eq!(b[0], best[0], "a level is done at its optimum");
        }
    }
    assert!(told.iter().any(|b| b.len() == 2), "{told:?}");
}

#[test]
fn branch_and_bound_and_plain_solving_tell_nothing() {
    let (told, costs) = run(&[], "#minimize{1,X:in(X)}.");
    assert_eq!((told.len(), costs.last()), (0, Some(&vec![6])));
    let (told, _) = run(&["--opt-strategy=usc"], "");
    assert!(told.is_empty());
}
