//! The traps a clingo API user fell into with `Control` (issue 33): each test failed before
//! the fix it names. Expected values are derived by hand from clingo's documented behaviour
//! (its Python API: `Control.add(name, params, program)`, one model by default, statistics
//! per call and accumulated kept apart, settings read at every solve call).

use lucent::control::{Control, ControlConfig, Part, Symbol, TruthValue};
use lucent::solve::StopReason;

fn sym(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

fn shown(ctl: &mut Control) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    ctl.solve(&Default::default(), |m| {
        let mut v: Vec<String> = m.symbols().iter().map(|s| s.to_string()).collect();
        v.sort();
        out.push(v);
        true
    });
    out
}

/// `add` takes a part name and its parameters, as clingo's does: the text belongs to
/// `step(t)`, so grounding `step(1)` gives `q(1)` (it used to be a file name, and the text
/// landed in `base`, where `t` is an unknown constant).
#[test]
fn add_files_the_text_under_the_named_part() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("step", &["t"], "q(t).").unwrap();
    // A directive in the text still switches part; a file-like source starts in base.
    ctl.add("base", &[], "r. #program step(t). s(t).").unwrap();
    ctl.add_source("more.lp", "u.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(
        shown(&mut ctl),
        vec![vec!["r".to_string(), "u".to_string()]]
    );
    ctl.ground(&[Part::new("step", vec![Symbol::number(1)])])
        .unwrap();
    let m = &shown(&mut ctl)[0];
    for a in ["q(1)", "r", "s(1)", "u"] {
        assert!(m.contains(&a.to_string()), "{a} in {m:?}");
    }
}

/// clingo solves for one model unless told otherwise (`-n 1`, `solve.models = 1`).
#[test]
fn the_default_config_asks_for_one_model() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "{a; b; c}.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(shown(&mut ctl).len(), 1);
    ctl.solve_config_mut().models = 0;
    assert_eq!(shown(&mut ctl).len(), 8);
}

/// A conflict limit set between calls applies to the next call, counts that call's conflicts
/// only, and the stop says it was the conflict limit, not the clock.
#[test]
fn a_conflict_limit_set_later_applies_and_is_named() {
    // The pigeonhole principle, 8 pigeons in 7 holes: unsatisfiable, thousands of conflicts.
    let text = "pigeon(1..8). hole(1..7).
        1 { in(P,H) : hole(H) } 1 :- pigeon(P).
        :- in(P,H), in(Q,H), P < Q.";
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.solve_config_mut().conflict_limit = Some(50);
    let first = ctl.solve(&Default::default(), |_| true);
    assert_eq!(first.stop, Some(StopReason::ConflictLimit));
    // The limit is checked every 256 steps of the search loop, so a call may overshoot a little.
    let c = first.stats.conflicts;
    assert!((50..50 + 256).contains(&c), "{c}");
    // The second call gets its own 50 conflicts (the limit counted all calls' conflicts, so
    // this call stopped at once).
    let second = ctl.solve(&Default::default(), |_| true);
    assert_eq!(second.stop, Some(StopReason::ConflictLimit));
    assert!(second.stats.conflicts >= 50, "{}", second.stats.conflicts);
    ctl.solve_config_mut().conflict_limit = None;
    let third = ctl.solve(&Default::default(), |_| true);
    assert_eq!(third.stop, None);
    assert!(third.is_unsatisfiable());
}

/// Every figure of a call's statistics is that call's; the accumulated ones sum the calls.
#[test]
fn call_statistics_and_accumulated_ones_are_kept_apart() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "{a(1..20)}. :- a(X), a(X+1). b :- a(1).")
        .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.solve_config_mut().models = 0;
    let one = ctl.solve(&Default::default(), |_| true).stats;
    let two = ctl.solve(&Default::default(), |_| true).stats;
    assert!(one.propagations > 0 && two.propagations > 0);
    assert!(
        two.propagations < one.propagations + two.choices * 100,
        "the second call's propagations include the first's? {} then {}",
        one.propagations,
        two.propagations
    );
    let total = ctl.accumulated_stats();
    assert_eq!(total.choices, one.choices + two.choices);
    assert_eq!(total.conflicts, one.conflicts + two.conflicts);
    assert_eq!(total.propagations, one.propagations + two.propagations);
    assert_eq!(total.time, one.time + two.time);
}

/// Identical calls asking for one model give the same model (the module's promise).
#[test]
fn identical_calls_give_the_same_model() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add(
        "base",
        &[],
        "{a(1..6)}. :- a(X), a(X+1). :- not a(2), not a(5).",
    )
    .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let first = shown(&mut ctl);
    for _ in 0..4 {
        assert_eq!(shown(&mut ctl), first);
    }
    // Still so under an assumption, call after call.
    let opts = lucent::control::SolveOptions {
        assumptions: vec![(sym("a(3)"), false)],
    };
    let mut under = Vec::new();
    for _ in 0..3 {
        let mut m = Vec::new();
        ctl.solve(&opts, |x| {
            m = x.symbols().iter().map(|s| s.to_string()).collect();
            true
        });
        under.push(m);
    }
    assert!(under.windows(2).all(|w| w[0] == w[1]), "{under:?}");
}

/// A seed changed after the solver was made is used by its next call (it used to be read
/// once, at construction): a solver made with seed 1 and switched to seed 5 enumerates the
/// models of `1 { a(1..12) } 1` in the order a solver made with seed 5 does, with every
/// decision random; seed 1's own order differs (checked, so the test can fail).
#[test]
fn a_seed_set_after_construction_is_used() {
    use lucent::solve::{Config, Solver};
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "1 { a(1..12) } 1.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.solve(&Default::default(), |_| true);
    let prog = ctl.program().clone();
    let config = |seed| Config {
        seed,
        random_freq_permille: 1000,
        models: 0,
        ..Config::default()
    };
    let order = |s: &mut Solver| {
        let mut v = Vec::new();
        s.for_each_model(&[], &mut |m| {
            v.push(m.atoms.clone());
            true
        });
        v
    };
    let five = order(&mut Solver::new(&prog, config(5)));
    let one = order(&mut Solver::new(&prog, config(1)));
    assert_ne!(
        five, one,
        "seeds 1 and 5 give one order: the test shows nothing"
    );
    let mut switched = Solver::new(&prog, config(1));
    switched.config_mut().seed = 5;
    assert_eq!(order(&mut switched), five);
}

/// The default asks for one model of a decision problem but the optimum of a program that
/// optimizes, as clingo (`-n` defaults to clasp's "auto"): `{a; b; c}` minimizing the atoms
/// left false has the optimum `a b c` (cost 0); the first model, with every decision's sign
/// false, is not it.
#[test]
fn the_default_config_finds_the_optimum_of_an_optimization() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add(
        "base",
        &[],
        "{a; b; c}. #minimize{1,a: not a; 1,b: not b; 1,c: not c}.",
    )
    .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let mut last = Vec::new();
    let summary = ctl.solve(&Default::default(), |m| {
        last = m.symbols().iter().map(|s| s.to_string()).collect();
        last.sort();
        true
    });
    assert!(summary.optimum_proven);
    assert_eq!(last, ["a", "b", "c"]);
}

/// Another thread stops a long solve call through the Control's interrupter (it had to be set
/// up in advance as an `AtomicBool` in the configuration); the next call runs again.
#[test]
fn an_interrupter_stops_the_running_call_from_another_thread() {
    // 12 pigeons in 11 holes: far beyond a few hundred milliseconds for any CDCL solver.
    let text = "pigeon(1..12). hole(1..11).
        1 { in(P,H) : hole(H) } 1 :- pigeon(P).
        :- in(P,H), in(Q,H), P < Q.";
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let stop = ctl.interrupter();
    let waker = std::thread::spawn(move || {
        std::thread::sleep(std::time::Duration::from_millis(200));
        stop.interrupt();
    });
    let summary = ctl.solve(&Default::default(), |_| true);
    waker.join().unwrap();
    assert_eq!(summary.stop, Some(StopReason::Interrupted));
    assert!(!summary.exhausted);
    // The flag was lowered: the next call is stopped only by its conflict limit.
    ctl.solve_config_mut().conflict_limit = Some(10);
    let next = ctl.solve(&Default::default(), |_| true);
    assert_eq!(next.stop, Some(StopReason::ConflictLimit));
}

/// The atoms of one signature, and the signatures (clingo's `symbolic_atoms.by_signature` and
/// `signatures`).
#[test]
fn symbolic_atoms_by_signature() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "p(1..3). -p(4). p. q(1,2). {r(X)} :- p(X).")
        .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let mut p1: Vec<String> = ctl
        .symbolic_atoms_by_signature("p", 1, true)
        .map(|a| a.symbol.to_string())
        .collect();
    p1.sort();
    assert_eq!(p1, ["p(1)", "p(2)", "p(3)"]);
    let neg: Vec<String> = ctl
        .symbolic_atoms_by_signature("p", 1, false)
        .map(|a| a.symbol.to_string())
        .collect();
    assert_eq!(neg, ["-p(4)"]);
    assert!(ctl
        .symbolic_atoms_by_signature("r", 1, true)
        .all(|a| !a.fact));
    let sigs = ctl.signatures();
    let want = [
        ("p", 0, true),
        ("p", 1, false),
        ("p", 1, true),
        ("q", 2, true),
        ("r", 1, true),
    ];
    let want: Vec<(String, usize, bool)> = want
        .iter()
        .map(|&(n, a, p)| (n.to_string(), a, p))
        .collect();
    assert_eq!(sigs, want);
}

/// A call that stops at its model limit is not exhausted, as clingo 5.8's library says even
/// when no model is left; below the limit (or with no limit) it is. Recorded with clingo 5.8.3:
/// `python3 -c "import clingo; c = clingo.Control(['1']); c.add('base', [], 'a.');
/// c.ground([('base', [])]); print(c.solve().exhausted)"` prints False (True with `['0']` and
/// with `['2']`; `{a}.` under `['2']`: False), and the same through `solve(yield_=True)`.
#[test]
fn a_call_stopped_at_its_model_limit_is_not_exhausted() {
    use lucent::control::HandleMode;
    for (program, limit, exhausted) in [
        ("a.", 1, false),
        ("a.", 0, true),
        ("a.", 2, true),
        ("{a}.", 2, false),
        ("{a}.", 3, true),
    ] {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add("base", &[], program).unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.solve_config_mut().models = limit;
        let summary = ctl.solve(&Default::default(), |_| true);
        assert_eq!(summary.exhausted, exhausted, "{program} with limit {limit}");
        // the default mode is clingo's `yield_=True`
        let mut handle = ctl.solve_handle(&Default::default(), HandleMode::default());
        while handle.model().is_some() {
            handle.resume();
        }
        let summary = handle.get();
        assert_eq!(
            summary.exhausted, exhausted,
            "{program} with limit {limit} (handle)"
        );
    }
}

/// clingo 5.8's `Control.is_conflicting` after grounding and after solving, recorded with
/// clingo 5.8.3's Python API (a script grounding each program below with `clingo.Control()`
/// and with `clingo.Control(["0"])`, printing the property before grounding, after grounding
/// and after `solve()`; the external case as written at the end): true after
/// grounding exactly when a constraint with an empty body remains, and after a solve call
/// also for a program whose conflict only the search finds; an external assigned true that a
/// constraint forbids gives an unsatisfiable call but no conflict.
#[test]
fn is_conflicting_as_clingo() {
    for (program, after_ground, after_solve) in [
        (":- a. a.", true, true),
        ("a.", false, false),
        (":- not a. {a}.", false, false),
        (":- .", true, true),
        ("-a. a.", true, true),
        ("#false.", true, true),
        ("a :- not a.", false, true),
        ("{a; b}. #minimize{1,X : X = a; 1,X : X = b}.", false, false),
    ] {
        let mut ctl = Control::new(ControlConfig::default());
        assert!(!ctl.is_conflicting(), "{program}: before grounding");
        ctl.add("base", &[], program).unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(
            ctl.is_conflicting(),
            after_ground,
            "{program}: after grounding"
        );
        let mut all = Control::from_args(&["0"]).unwrap();
        all.add("base", &[], program).unwrap();
        all.ground(&[Part::base()]).unwrap();
        for c in [&mut ctl, &mut all] {
            c.solve(&Default::default(), |_| true);
            assert_eq!(c.is_conflicting(), after_solve, "{program}: after solving");
        }
    }
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "#external e. :- e.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.assign_external(&sym("e"), TruthValue::True);
    let summary = ctl.solve(&Default::default(), |_| true);
    assert!(summary.is_unsatisfiable());
    assert!(!ctl.is_conflicting());
    ctl.assign_external(&sym("e"), TruthValue::False);
    assert!(ctl.solve(&Default::default(), |_| true).is_satisfiable());
    assert!(!ctl.is_conflicting());
}

/// Every constant with its value, as `get_const` gives each (`-c` over `#const`; a constant
/// defined by another is evaluated): what a client reads while the control is busy solving.
/// Values derived by hand from the program: `n = 2`, `m = n+1 = 3`, `k = 3` from the
/// command line overriding `#const k = 7.`.
#[test]
fn constants_are_listed_with_their_values() {
    let mut ctl = Control::from_args(&["-c", "k=3"]).unwrap();
    ctl.add(
        "base",
        &[],
        "#const n = 2. #const m = n+1. #const k = 7. p(n).",
    )
    .unwrap();
    let listed: Vec<(String, String)> = ctl
        .consts()
        .into_iter()
        .map(|(n, v)| (n, v.to_string()))
        .collect();
    let expected: Vec<(String, String)> = [("k", "3"), ("m", "3"), ("n", "2")]
        .map(|(n, v)| (n.to_string(), v.to_string()))
        .into();
    assert_eq!(listed, expected);
    for (name, value) in ctl.consts() {
        assert_eq!(ctl.get_const(&name), Some(value));
    }
}

/// A released external is no longer external (clingo 5.8's `is_external`, recorded with
/// `ctl.release_external(Function("e", [Number(2)]))` on `#external e(1..2). a :- e(1).`:
/// `e(1)` external, `e(2)` not, before and after the next solve call).
#[test]
fn a_released_external_is_not_external() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "#external e(1..2). a :- e(1).")
        .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let flags = |ctl: &Control| -> Vec<(String, bool)> {
        ctl.symbolic_atoms_by_signature("e", 1, true)
            .map(|a| (a.symbol.to_string(), a.external))
            .collect()
    };
    let both = [("e(1)".to_string(), true), ("e(2)".to_string(), true)];
    assert_eq!(flags(&ctl), both);
    ctl.release_external(&sym("e(2)"));
    let released = [("e(1)".to_string(), true), ("e(2)".to_string(), false)];
    assert_eq!(flags(&ctl), released);
    ctl.solve(&Default::default(), |_| true);
    assert_eq!(flags(&ctl), released);
    // A second solve call keeps it listed; the next update (here an assignment) drops it, as
    // clingo 5.8 does (`python3 rel.py`: release, solve, solve lists e(2); release, solve,
    // assign_external, ground or release_external does not).
    ctl.solve(&Default::default(), |_| true);
    assert_eq!(flags(&ctl), released);
    ctl.assign_external(&sym("e(1)"), TruthValue::True);
    assert_eq!(flags(&ctl), [("e(1)".to_string(), true)]);
    assert!(ctl.symbolic_atoms().all(|a| a.symbol != sym("e(2)")));
}

/// Settings changed after the first solve call are read back as changed (`solve_config`),
/// where `config().solve` keeps the values the Control was made with (derived by hand).
#[test]
fn settings_changed_after_a_solve_are_read_back() {
    let mut ctl = Control::from_args(&["0", "--opt-mode=ignore"]).unwrap();
    ctl.add("base", &[], "{a}. #minimize{1:a}.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.solve(&Default::default(), |_| true);
    ctl.solve_config_mut().opt_mode = lucent::solve::OptMode::OptN;
    assert_eq!(ctl.solve_config().opt_mode, lucent::solve::OptMode::OptN);
    let mut costs = Vec::new();
    ctl.solve(&Default::default(), |m| {
        costs.push(m.costs().to_vec());
        true
    });
    assert_eq!(
        costs.last(),
        Some(&vec![0]),
        "the optimum {{}} costs 0: {costs:?}"
    );
}
