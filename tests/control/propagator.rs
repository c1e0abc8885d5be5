//! clingo's propagator interface on `Control` (issue 33 item 1): the same propagators as
//! `tests/data/propagator/clingo_propagators.py`, whose answers clingo 5.8's Python API gives
//! live (the test runs the script; it fails without `import clingo`).
//!
//! - `NoConsecutive` watches every `p/1` atom and, when `p(i)` becomes true, adds the clause
//!   `-p(i) | -p(i+1)` (and with `p(i-1)`): enumeration of all answer sets with one and two
//!   threads, multi-shot steps that add atoms, assumptions, and `#maximize`.
//! - `EvenOnly` only checks total assignments and refutes an odd number of true `p` atoms.
//! - `Counter` keeps the number of true watched atoms through `propagate` and `undo`, per
//!   thread, and compares it with the assignment at every `check` (hand-checked invariant).

use lucent::control::{
    Assignment, Control, ControlConfig, Literal, Part, PropagateControl, PropagateInit, Propagator,
    SolveOptions, Symbol, WeightConstraintType,
};
use lucent::solve::{Config, OptMode};
use std::collections::HashMap;
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

/// The answers of clingo 5.8 (run live: `python3 tests/data/propagator/clingo_propagators.py`).
fn clingo_answers() -> HashMap<String, String> {
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/propagator/clingo_propagators.py"
    );
    let out = Command::new("python3")
        .arg(script)
        .output()
        .unwrap_or_else(|e| panic!("python3 is needed (apt-get install -y python3): {e}"));
    assert!(
        out.status.success(),
        "clingo 5.8's Python module is needed (`python3 -m pip install clingo`): {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .filter_map(|l| l.split_once('\t'))
        .map(|(k, v)| (k.to_string(), v.to_string()))
        .collect()
}

/// The `p/1` atoms of the program: index and solver literal.
fn p_literals(init: &PropagateInit<'_>) -> Vec<(i32, Literal)> {
    init.symbolic_atoms()
        .iter()
        .filter(|a| a.symbol.is("p", 1))
        .map(|a| {
            let i = a.symbol.args()[0].as_number().unwrap();
            (i, init.solver_literal(a.atom))
        })
        .collect()
}

#[derive(Default)]
struct NoConsecutive {
    lit: HashMap<i32, Literal>,
}

impl Propagator for NoConsecutive {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        self.lit.clear();
        for (i, l) in p_literals(init) {
            self.lit.insert(i, l);
            init.add_watch(l);
        }
    }

    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        for &l in changes {
            for (&i, &li) in &self.lit {
                if li != l {
                    continue;
                }
                for j in [i - 1, i + 1] {
                    if let Some(&lj) = self.lit.get(&j) {
                        if !ctl.add_clause(&[-li, -lj]) || !ctl.propagate() {
                            return;
                        }
                    }
                }
            }
        }
    }
}

#[derive(Default)]
struct EvenOnly {
    lits: Vec<Literal>,
}

impl Propagator for EvenOnly {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        self.lits = p_literals(init).into_iter().map(|(_, l)| l).collect();
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let a = ctl.assignment();
        assert!(a.is_total(), "check is called on total assignments");
        let odd = self.lits.iter().filter(|&&l| a.is_true(l)).count() % 2 == 1;
        if odd {
            let clause: Vec<Literal> = self
                .lits
                .iter()
                .map(|&l| if a.is_true(l) { -l } else { l })
                .collect();
            ctl.add_clause(&clause);
        }
    }
}

fn control(threads: usize, models: usize, optimize: bool) -> Control {
    Control::new(ControlConfig {
        solve: Config {
            models,
            threads,
            opt_mode: if optimize {
                OptMode::Opt
            } else {
                OptMode::Enum(Vec::new())
            },
            ..Config::default()
        },
        ..ControlConfig::default()
    })
}

/// Sorted answer sets, each sorted, as the script prints them.
fn sets(ctl: &mut Control, options: &SolveOptions) -> String {
    let solved = ctl.solve_all(options);
    let mut sets: Vec<Vec<String>> = solved
        .models
        .iter()
        .map(|m| {
            let mut a: Vec<String> = m.shown.iter().map(Symbol::to_string).collect();
            a.sort();
            a
        })
        .collect();
    sets.sort();
    format!("{sets:?}")
}

fn p(i: i32) -> Symbol {
    Symbol::function("p", vec![Symbol::number(i)])
}

#[test]
fn a_propagator_forbids_consecutive_atoms_as_in_clingo() {
    let want = clingo_answers();
    for threads in [1, 2] {
        let mut ctl = control(threads, 0, false);
        ctl.add_source("p.lp", "{p(1..6)}.").unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.register_propagator(Box::new(NoConsecutive::default()));
        let got = sets(&mut ctl, &SolveOptions::default());
        assert_eq!(
            got,
            want[&format!("consecutive-t{threads}")],
            "{threads} threads"
        );
        // 21 = the Fibonacci number F(8): subsets of 1..6 without consecutive elements.
        assert_eq!(got.matches('[').count() - 1, 21);
        // A second call gives the same answer sets (learnt clauses and watches kept).
        assert_eq!(sets(&mut ctl, &SolveOptions::default()), got);
    }
}

#[test]
fn a_check_only_propagator_refutes_odd_models_as_in_clingo() {
    let want = clingo_answers();
    for threads in [1, 2] {
        let mut ctl = control(threads, 0, false);
        ctl.add_source("even.lp", "{p(1..4)}. q :- p(1), p(4).")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.register_propagator(Box::new(EvenOnly::default()));
        assert_eq!(
            sets(&mut ctl, &SolveOptions::default()),
            want["even"],
            "{threads} threads"
        );
    }
}

#[test]
fn steps_and_assumptions_follow_clingo() {
    let want = clingo_answers();
    for threads in [1, 2] {
        let mut ctl = control(threads, 0, false);
        ctl.add_source(
            "steps.lp",
            "{p(1..2)}.\n#program step(k).\n{p(k+2)}. r(k) :- p(k+2), not p(k).",
        )
        .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.register_propagator(Box::new(NoConsecutive::default()));
        for k in 1..=4 {
            ctl.ground(&[Part::new("step", vec![Symbol::number(k)])])
                .unwrap();
            let plain = SolveOptions::default();
            assert_eq!(
                sets(&mut ctl, &plain),
                want[&format!("step{k}")],
                "step {k}"
            );
            for (value, name) in [(true, "p2"), (false, "not-p2")] {
                let options = SolveOptions {
                    assumptions: vec![(p(2), value)],
                };
                assert_eq!(
                    sets(&mut ctl, &options),
                    want[&format!("step{k}-{name}")],
                    "step {k}, {name}, {threads} threads"
                );
            }
        }
    }
}

#[test]
fn optimization_reaches_clingos_optimum() {
    let want = clingo_answers();
    for threads in [1, 2] {
        let mut ctl = control(threads, 0, true);
        ctl.add_source("opt.lp", "{p(1..7)}. #maximize{ I : p(I) }.")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.register_propagator(Box::new(NoConsecutive::default()));
        let solved = ctl.solve_all(&SolveOptions::default());
        let best = solved.models.last().expect("a model");
        let mut atoms: Vec<String> = best.shown.iter().map(Symbol::to_string).collect();
        atoms.sort();
        let got = format!("{:?} {:?}", best.costs, vec![atoms]);
        assert_eq!(got, want["optimum"], "{threads} threads");
        assert!(solved.summary.optimum_proven);
    }
}

/// Counts the true watched literals per thread through `propagate` and `undo`; every `check`
/// compares the count with the assignment.
struct Counter {
    lits: Vec<Literal>,
    count: Vec<usize>,
    checks: Arc<AtomicUsize>,
    undos: Arc<AtomicUsize>,
}

impl Propagator for Counter {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        self.lits = p_literals(init).into_iter().map(|(_, l)| l).collect();
        for &l in &self.lits {
            init.add_watch(l);
            init.add_watch(-l);
        }
        self.count = vec![0; init.number_of_threads()];
    }

    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        let t = ctl.thread_id() as usize;
        for &l in changes {
            assert!(ctl.assignment().is_true(l));
            if l > 0 {
                self.count[t] += 1;
            }
        }
        // At most three of the p atoms: refute a fourth at once.
        if self.count[t] > 3 {
            let a = ctl.assignment();
            let clause: Vec<Literal> = self
                .lits
                .iter()
                .filter(|&&l| a.is_true(l))
                .map(|&l| -l)
                .collect();
            ctl.add_clause(&clause);
        }
    }

    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        self.undos.fetch_add(1, Ordering::Relaxed);
        for &l in changes {
            assert!(assignment.is_true(l), "undo sees the values it undoes");
            if l > 0 {
                self.count[thread_id as usize] -= 1;
            }
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        self.checks.fetch_add(1, Ordering::Relaxed);
        let a = ctl.assignment();
        let truth = self.lits.iter().filter(|&&l| a.is_true(l)).count();
        assert_eq!(self.count[ctl.thread_id() as usize], truth);
    }
}

#[test]
fn undo_keeps_a_counting_propagator_consistent() {
    for threads in [1, 2] {
        let checks = Arc::new(AtomicUsize::new(0));
        let undos = Arc::new(AtomicUsize::new(0));
        let mut ctl = control(threads, 0, false);
        ctl.add_source("count.lp", "{p(1..6)}. :- p(1), not p(2).")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        ctl.register_propagator(Box::new(Counter {
            lits: Vec::new(),
            count: Vec::new(),
            checks: checks.clone(),
            undos: undos.clone(),
        }));
        for round in 0..3 {
            let solved = ctl.solve_all(&SolveOptions::default());
            // By hand: subsets of p(1..6) of at most 3 atoms (1 + 6 + 15 + 20 = 42), minus
            // those with p(1) but not p(2), at most two of p(3..6) besides: 1 + 4 + 6 = 11.
            assert_eq!(solved.models.len(), 31, "round {round}, {threads} threads");
            assert!(solved.models.iter().all(|m| m.shown.len() <= 3));
        }
        assert!(checks.load(Ordering::Relaxed) >= 31);
        assert!(undos.load(Ordering::Relaxed) > 0);
    }
}

/// The solver literal of the atom `q`.
fn q_literal(init: &PropagateInit<'_>) -> Literal {
    init.symbolic_atoms()
        .iter()
        .find(|a| a.symbol.is("q", 0))
        .map(|a| init.solver_literal(a.atom))
        .expect("the program has the atom q")
}

/// Ties `q` to `p(1) + p(2) + p(3) >= 2` in `init` (clingo's `add_weight_constraint`).
struct WeightTie {
    kind: WeightConstraintType,
    equal: bool,
}

impl Propagator for WeightTie {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        let ps: Vec<(Literal, i32)> = p_literals(init).into_iter().map(|(_, l)| (l, 1)).collect();
        let q = q_literal(init);
        assert!(init.add_weight_constraint(q, &ps, 2, self.kind, self.equal));
    }
}

#[test]
fn weight_constraints_added_in_init_follow_clingo() {
    let want = clingo_answers();
    for threads in [1, 2] {
        for (kind, name) in [
            (WeightConstraintType::LeftImplication, "-1"),
            (WeightConstraintType::Equivalence, "0"),
            (WeightConstraintType::RightImplication, "1"),
        ] {
            for equal in [false, true] {
                let mut ctl = control(threads, 0, false);
                ctl.add_source("w.lp", "{p(1..3)}. {q}.").unwrap();
                ctl.ground(&[Part::base()]).unwrap();
                ctl.register_propagator(Box::new(WeightTie { kind, equal }));
                let key = format!("weight{name}-{}", if equal { "eq" } else { "ge" });
                assert_eq!(
                    sets(&mut ctl, &SolveOptions::default()),
                    want[&key],
                    "{key}, {threads} threads"
                );
            }
        }
    }
}

/// Clauses added in `init` and propagated there fix what they imply before the search, and a
/// watch removed in `init` is not reported (derived by hand: `p(1)` and `p(1) -> q` fix `q`).
#[test]
fn init_propagates_and_removes_watches() {
    struct Fix(Arc<AtomicUsize>);
    impl Propagator for Fix {
        fn init(&mut self, init: &mut PropagateInit<'_>) {
            let ps = p_literals(init);
            let q = q_literal(init);
            let p1 = ps.iter().find(|(i, _)| *i == 1).unwrap().1;
            assert!(init.add_clause(&[p1]) && init.add_clause(&[-p1, q]));
            assert!(init.propagate());
            assert_eq!(init.assignment().value(q), Some(true));
            for &(_, l) in &ps {
                init.add_watch(l);
                init.remove_watch(l);
            }
        }
        fn propagate(&mut self, _: &mut PropagateControl<'_>, changes: &[Literal]) {
            self.0.fetch_add(changes.len(), Ordering::Relaxed);
        }
    }
    let calls = Arc::new(AtomicUsize::new(0));
    let mut ctl = control(1, 0, false);
    ctl.add_source("fix.lp", "{p(1..2)}. {q}.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.register_propagator(Box::new(Fix(calls.clone())));
    let got = sets(&mut ctl, &SolveOptions::default());
    assert_eq!(got, r#"[["p(1)", "p(2)", "q"], ["p(1)", "q"]]"#);
    assert_eq!(calls.load(Ordering::Relaxed), 0, "no watch left");
}
