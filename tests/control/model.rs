//! `Model::atoms_named` against `Model::atoms` filtered by name, arity and sign: the same
//! symbols in the same order, for every model of a small program.

use lucent::control::{Control, ControlConfig, Part, SolveOptions};

#[test]
fn atoms_named_is_atoms_filtered() {
    let text = "{ occurs(a, 0); occurs(b, 1) }. -occurs(c, 2). occurs. occurs(d). \
                occurs(e, 3) :- occurs(a, 0). h(occurs(f, 4)). other(1, 2).";
    let mut cc = ControlConfig::default();
    cc.solve.models = 0;
    let mut ctl = Control::new(cc);
    ctl.add("base", &[], text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let mut seen = 0;
    ctl.solve(&SolveOptions::default(), |m| {
        for (name, arity) in [
            ("occurs", 2),
            ("occurs", 0),
            ("occurs", 1),
            ("other", 2),
            ("h", 1),
        ] {
            let filtered: Vec<String> = m
                .atoms()
                .into_iter()
                .filter(|s| s.is(name, arity) && !s.is_negative())
                .map(|s| s.to_string())
                .collect();
            let named: Vec<String> = m
                .atoms_named(name, arity)
                .into_iter()
                .map(|s| s.to_string())
                .collect();
            assert_eq!(named, filtered, "{name}/{arity}");
        }
        seen += 1;
        true
    });
    assert_eq!(seen, 4);
}

/// `Control::model_clauses` (clingo's `SolveControl.add_clause` from `on_model`): after the
/// first model the clause `p(1)` holds for the rest of the call, so every later model has
/// `p(1)` and none is missed; the next call has all eight again.
#[test]
fn a_clause_from_the_model_callback_holds_for_the_rest_of_the_call() {
    let mut cc = ControlConfig::default();
    cc.solve.models = 0;
    let mut ctl = Control::new(cc);
    ctl.add("base", &[], "{p(1..3)}.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let p1 = lucent::Symbol::parse("p(1)").unwrap();
    let atom = ctl.lookup(&p1).unwrap() as i32;
    let clauses = ctl.model_clauses();
    let mut seen: Vec<bool> = Vec::new();
    ctl.solve(&SolveOptions::default(), |m| {
        if seen.is_empty() {
            clauses.lock().unwrap().push(vec![atom]);
        }
        seen.push(m.contains(&p1));
        true
    });
    assert!(seen[1..].iter().all(|&x| x), "{seen:?}");
    let with_p1 = seen.iter().filter(|&&x| x).count();
    assert_eq!(with_p1, 4, "every model with p(1): {seen:?}");
    let mut n = 0;
    ctl.solve(&SolveOptions::default(), |_| {
        n += 1;
        true
    });
    assert_eq!(n, 8, "the clause ended with its call");
}

/// `Model::thread_id`: 0 with one thread; with `-t 3` every model names a thread below 3.
#[test]
fn models_name_their_thread() {
    for (threads, bound) in [("1", 1), ("3", 3)] {
        let mut ctl = Control::from_args(&["-t", threads, "0"]).unwrap();
        ctl.add("base", &[], "{p(1..6)}.").unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        let mut ids = Vec::new();
        ctl.solve(&SolveOptions::default(), |m| {
            ids.push(m.thread_id());
            true
        });
        assert_eq!(ids.len(), 64);
        assert!(ids.iter().all(|&t| t < bound), "{ids:?}");
    }
}

/// What `read` gives of the last model of a call (sorted, as text) and whether the search was
/// exhausted, for clingo's `args`.
fn last_model(
    args: &[&str],
    program: &str,
    read: fn(&lucent::control::Model<'_>) -> Vec<lucent::control::Symbol>,
) -> (Vec<String>, bool) {
    let mut ctl = Control::from_args(args).unwrap();
    ctl.add("base", &[], program).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let mut last = Vec::new();
    let summary = ctl.solve(&SolveOptions::default(), |m| {
        last = read(m).iter().map(|s| s.to_string()).collect();
        last.sort();
        true
    });
    (last, summary.exhausted)
}

/// The shown symbols of the last model, and whether the search was exhausted.
fn last_shown(args: &[&str], program: &str) -> (Vec<String>, bool) {
    last_model(args, program, |m| m.symbols())
}

#[test]
fn consequences_through_the_enum_mode_argument() {
    // clingo 5.8.3's Python API (`Control(args)`, `solve(on_model=...)`, the last model's
    // `symbols(shown=True)` and `SolveResult.exhausted`) on this program:
    // --enum-mode=brave: [a, b, c, d, e] exhausted; --enum-mode=cautious: [d] exhausted;
    // --enum-mode=cautious 1: [c, d] not exhausted (its first model is {c, d}, as Lucent's).
    let program = "1{a;b;c}1. d. e :- a. e :- b. \
                   #show a/0. #show b/0. #show c/0. #show d/0. #show e/0.";
    let all = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    assert_eq!(
        last_shown(&["--enum-mode=brave"], program),
        (all(&["a", "b", "c", "d", "e"]), true)
    );
    assert_eq!(
        last_shown(&["-e", "cautious"], program),
        (all(&["d"]), true)
    );
    let (first, exhausted) = last_shown(&["--enum-mode=cautious", "1"], program);
    assert!(!exhausted);
    assert!(
        first.contains(&"d".to_string()) && first.len() == 2,
        "{first:?}"
    );
    assert!(Control::from_args(&["--enum-mode=all"]).is_err());
}

#[test]
fn a_consequence_model_holds_the_consequences_as_atoms() {
    // clingo 5.8.3's Python API, `symbols(atoms=True)` of the last model on this program:
    // brave [a, b, c, d, e], cautious [d] (the consequences, not the last answer set found).
    let program = "1{a;b;c}1. d. e :- a. e :- b.";
    for (mode, want) in [
        ("brave", vec!["a", "b", "c", "d", "e"]),
        ("cautious", vec!["d"]),
    ] {
        let (last, _) = last_model(&["--enum-mode", mode], program, |m| m.atoms());
        assert_eq!(last, want, "{mode}");
    }
}
