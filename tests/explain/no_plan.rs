//! Why no plan (issue 14): the goal literals, observations and constraints the explainer names
//! are a *minimal* unsolvable set, found from the solver's unsatisfiable core and shrunk by
//! deletion. Checked by solving again: the set is unsolvable on its own (every other hypothesis
//! off), removing any one element makes the task solvable, and switching the set off (every
//! other hypothesis on) makes the task possible. Scenes: `domains/ra/scenes`.

use lucent::control::Symbol;
use lucent::explain::counterfactual::{why_no_plan, Hyp, NoPlan};
use lucent::explain::history::{HistoryConfig, Problem};
use lucent::explain::lexicon::Lexicon;

use crate::support::ra_scenes;

fn problem(scene: &str) -> Problem {
    let (desc, sources) = ra_scenes::load_scene(scene);
    Problem {
        desc,
        sources,
        config: HistoryConfig::default(),
    }
}

fn goal(text: &[&str]) -> Vec<Symbol> {
    text.iter().map(|g| Symbol::parse(g).unwrap()).collect()
}

/// The minimal core of the task, checked minimal and necessary; returns its hypotheses.
fn checked_core(p: &Problem, goal: &[Symbol], horizon: usize) -> Vec<Hyp> {
    let mut np = NoPlan::new(p, goal, horizon).unwrap();
    let n = np.hypotheses().len();
    let core = np.minimal_core().expect("no plan with every hypothesis");
    assert!(!core.is_empty(), "the task is possible without hypotheses");
    let first = np.first_core.unwrap();
    assert!(
        first >= core.len() && first < n,
        "the solver's core ({first} of {n}) is where deletion starts"
    );
    assert!(np.refute(&core).is_some(), "the core alone is unsolvable");
    for &k in &core {
        let without: Vec<usize> = core.iter().copied().filter(|&x| x != k).collect();
        assert!(
            np.refute(&without).is_none(),
            "minimal: without {:?} the rest is solvable",
            np.hypotheses()[k]
        );
    }
    let rest: Vec<usize> = (0..n).filter(|k| !core.contains(k)).collect();
    assert!(
        np.refute(&rest).is_none(),
        "every other hypothesis on, the task is possible"
    );
    core.iter().map(|&k| np.hypotheses()[k].clone()).collect()
}

#[test]
fn contradictory_goal_literals_are_the_core() {
    // Holding the white block while the green can stands on it is no state at all.
    let p = problem("execution_example.ald");
    let g = goal(&[
        "relation(on,green_can,white_block)",
        "in_hand(rob1,white_block)",
    ]);
    assert_eq!(
        checked_core(&p, &g, 3),
        vec![Hyp::Goal(g[0].clone()), Hyp::Goal(g[1].clone())]
    );
}

#[test]
fn an_observation_and_a_goal_too_far_away() {
    // In one step the robot cannot hold the white block: the green can is on it (an
    // observation of the initial state). Without that observation one pickup would do.
    let p = problem("execution_example.ald");
    let g = goal(&["in_hand(rob1,white_block)"]);
    let core = checked_core(&p, &g, 1);
    assert_eq!(core.len(), 2, "{core:?}");
    assert!(core.contains(&Hyp::Goal(g[0].clone())), "{core:?}");
    assert!(
        core.contains(&Hyp::Observation(
            Symbol::parse("holds(relation(on,green_can,white_block),0)").unwrap()
        )),
        "{core:?}"
    );
    // In words: the observation and the goal.
    let a = why_no_plan(&p, &Lexicon::ra(), &g, 1).unwrap();
    insta::assert_snapshot!(a.text);
    // With enough steps there is a plan, and nothing to blame.
    let mut np = NoPlan::new(&p, &g, 3).unwrap();
    assert_eq!(np.minimal_core(), None);
}
