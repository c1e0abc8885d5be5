//! clingo's solve handle on `Control` (`Control::solve_handle`): models read one at a time
//! from a search that stops after each model, cancelled, interrupted from another thread, and
//! the Control usable afterwards. The same behaviour from Python, against clingo 5.8, is
//! `python/tests/test_handle.py`.

use lucent::control::{Control, ControlConfig, HandleMode, Part, SolveOptions};
use lucent::solve::{Outcome, StopReason};
use std::time::Duration;

fn control(text: &str) -> Control {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.solve_config_mut().models = 0;
    ctl.add("base", &[], text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl
}

fn sorted_answers(models: impl Iterator<Item = Vec<String>>) -> Vec<String> {
    let mut out: Vec<String> = models
        .map(|mut m| {
            m.sort();
            m.join(" ")
        })
        .collect();
    out.sort();
    out
}

/// `{p(1..40)}.` has 2^40 answer sets; reading three and cancelling answers three models,
/// a result that is satisfiable, not exhausted and interrupted (clingo 5.8's Python API gives
/// `SAT`, `interrupted=True`, `exhausted=False`: python/tests/test_handle.py runs it), and
/// the Control solves again afterwards (the solver came back).
#[test]
fn three_models_of_two_to_the_forty() {
    let mut ctl = control("{p(1..40)}.");
    let mut h = ctl.solve_handle(&SolveOptions::default(), HandleMode::default());
    let mut read = 0;
    while let Some(m) = h.next_model() {
        assert_eq!(m.number(), read + 1);
        read += 1;
        if read == 3 {
            break;
        }
    }
    let s = h.cancel();
    assert_eq!(
        (s.models, s.outcome, s.exhausted),
        (3, Outcome::Satisfiable, false)
    );
    assert_eq!(s.stop, Some(StopReason::Interrupted));
    drop(h);
    ctl.solve_config_mut().models = 5;
    let again = ctl.solve_all(&SolveOptions::default());
    assert_eq!(again.models.len(), 5);
    assert_eq!(again.summary.stop, None, "the interrupt flag was lowered");
}

/// Iterating a handle to the end gives the models `solve` gives, then the final summary; a
/// model read twice is the same model, and `resume` moves on (clingo's `model`/`resume`).
#[test]
fn a_handle_enumerates_what_solve_enumerates() {
    let text = "{a; b; c}. :- a, b. d :- c, not a.";
    let mut ctl = control(text);
    let expect = sorted_answers(
        ctl.solve_all(&SolveOptions::default())
            .models
            .into_iter()
            .map(|m| m.atoms.iter().map(|s| s.to_string()).collect()),
    );
    // {a;b;c} minus a&b: 6 sets, d added when c and not a.
    assert_eq!(expect.len(), 6);
    let mut h = ctl.solve_handle(&SolveOptions::default(), HandleMode::default());
    let first: Vec<String> = h
        .model()
        .unwrap()
        .atoms()
        .iter()
        .map(|s| s.to_string())
        .collect();
    let again: Vec<String> = h
        .model()
        .unwrap()
        .atoms()
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(first, again);
    let rest: Vec<Vec<String>> = h
        .by_ref()
        .map(|m| m.atoms.iter().map(|s| s.to_string()).collect())
        .collect();
    let got = sorted_answers(std::iter::once(first).chain(rest));
    assert_eq!(got, expect);
    let s = h.get();
    assert_eq!((s.models, s.exhausted, s.stop), (6, true, None));
    assert!(h.model().is_none());
}

/// A background handle without yield runs ahead of its reader (at most `QUEUE` unread models);
/// `wait` with a timeout answers as soon as a result is there, and cancelling ends the search.
#[test]
fn a_background_search_is_waited_for_and_cancelled() {
    let mut ctl = control("{p(1..40)}.");
    let mode = HandleMode {
        yield_models: false,
        background: true,
    };
    let mut h = ctl.solve_handle(&SolveOptions::default(), mode);
    assert!(h.wait(Some(Duration::from_secs(60))));
    assert!(h.model().is_some());
    let s = h.cancel();
    assert!(s.models >= 1 && s.models <= lucent::control::handle::QUEUE + 2);
    assert_eq!(s.stop, Some(StopReason::Interrupted));
}

/// `Interrupter::interrupt` from another thread stops a background search with no model in
/// sight (the pigeonhole principle, 11 pigeons in 10 holes: hopeless for resolution).
#[test]
fn another_thread_interrupts_a_handle() {
    let mut ctl = control(
        "p(1..11). h(1..10). 1 { in(P, H) : h(H) } 1 :- p(P). :- in(P, H), in(Q, H), P < Q.",
    );
    let stop = ctl.interrupter();
    let mode = HandleMode {
        yield_models: true,
        background: true,
    };
    let mut h = ctl.solve_handle(&SolveOptions::default(), mode);
    assert!(
        !h.wait(Some(Duration::from_millis(50))),
        "solved 11 pigeons in 50 ms?"
    );
    std::thread::spawn(move || stop.interrupt()).join().unwrap();
    let s = h.get();
    assert_eq!(
        (s.outcome, s.stop),
        (Outcome::Unknown, Some(StopReason::Interrupted))
    );
    drop(h);
    // The flag was lowered: the next call runs (a small program, so it ends).
    let mut small = control("{a}.");
    assert_eq!(small.solve_all(&SolveOptions::default()).models.len(), 2);
}

/// A handle cancelled before any request searched nothing (clingo: `UNKNOWN`).
#[test]
fn a_handle_cancelled_at_once_is_unknown() {
    let mut ctl = control("{a}.");
    let mut h = ctl.solve_handle(&SolveOptions::default(), HandleMode::default());
    let s = h.cancel();
    assert_eq!((s.outcome, s.models), (Outcome::Unknown, 0));
}

/// An assumption of an atom that does not exist: unsatisfiable at once, with it as the core.
#[test]
fn a_handle_under_impossible_assumptions() {
    let mut ctl = control("{a}.");
    let opts = SolveOptions {
        assumptions: vec![(lucent::Symbol::parse("zz").unwrap(), true)],
    };
    let mut h = ctl.solve_handle(&opts, HandleMode::default());
    assert!(h.model().is_none());
    let s = h.get();
    assert_eq!(s.outcome, Outcome::Unsatisfiable);
    assert_eq!(s.core.unwrap().len(), 1);
}
