//! clingo's propagator check modes and literals on `Control`: `check` at every propagation
//! fixpoint (`CheckMode::Fixpoint`, answers against clingo 5.8 run live by
//! `tests/data/propagator/clingo_check_modes.py`), `Assignment::decision`, and variables a
//! propagator adds (`add_literal` in `init` and during search; hand-derived answers).

use lucent::control::{
    CheckMode, Control, ControlConfig, Literal, Part, PropagateControl, PropagateInit, Propagator,
    SolveOptions,
};
use std::collections::HashMap;
use std::process::Command;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

fn clingo_answers() -> HashMap<String, String> {
    let script = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/propagator/clingo_check_modes.py"
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

fn p_lits(init: &PropagateInit<'_>) -> Vec<(i32, Literal)> {
    let mut out: Vec<(i32, Literal)> = init
        .symbolic_atoms()
        .iter()
        .filter(|a| a.symbol.is("p", 1))
        .map(|a| {
            let i = a.symbol.args()[0].as_number().unwrap();
            (i, init.solver_literal(a.atom))
        })
        .collect();
    out.sort();
    out
}

/// The answers of each call, as the clingo script prints them.
fn answers(program: &str, propagator: Box<dyn Propagator>, steps: usize) -> String {
    let mut config = ControlConfig::default();
    config.solve.models = 0;
    let mut ctl = Control::new(config);
    ctl.add("base", &[], program).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.register_propagator(propagator);
    let mut out = Vec::new();
    for _ in 0..steps {
        let mut models: Vec<String> = ctl
            .solve_all(&SolveOptions::default())
            .models
            .iter()
            .map(|m| {
                let mut a: Vec<String> = m.atoms.iter().map(|s| s.to_string()).collect();
                a.sort();
                a.join(" ")
            })
            .collect();
        models.sort();
        out.push(models.join(";"));
    }
    out.join("|")
}

/// More than two true `p` atoms are refuted as soon as propagation is quiet; every decision
/// is true at its level; `partial` records a check on a partial assignment.
struct AtMostTwo {
    lits: Vec<Literal>,
    partial: Arc<AtomicBool>,
}

impl Propagator for AtMostTwo {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        init.set_check_mode(CheckMode::Fixpoint);
        self.lits = p_lits(init).into_iter().map(|(_, l)| l).collect();
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let a = ctl.assignment();
        if !a.is_total() {
            self.partial.store(true, Ordering::Relaxed);
        }
        for level in 1..=a.decision_level() {
            if let Some(d) = a.decision(level) {
                assert!(a.is_true(d) && a.level(d) == level);
            }
        }
        assert_eq!(a.decision(a.decision_level() + 1), None);
        let t: Vec<Literal> = self
            .lits
            .iter()
            .copied()
            .filter(|&l| a.is_true(l))
            .collect();
        if t.len() > 2 {
            let clause: Vec<Literal> = t[..3].iter().map(|&l| -l).collect();
            ctl.add_clause(&clause);
        }
    }
}

#[test]
fn fixpoint_checks_refute_partial_assignments_as_clingo() {
    let expected = clingo_answers();
    let partial = Arc::new(AtomicBool::new(false));
    let got = answers(
        "{p(1..5)}.",
        Box::new(AtMostTwo {
            lits: Vec::new(),
            partial: partial.clone(),
        }),
        1,
    );
    assert_eq!(got, expected["at_most_two"]);
    assert!(
        partial.load(Ordering::Relaxed),
        "a check at a partial fixpoint"
    );
}

/// When `p(1)` becomes true: a volatile literal `y` defined as `p(1) & p(2)` (three clauses,
/// so it adds no models) and the clause `-y | -p(3)`. Hand-derived: `{p(1..3)}` has 8 subsets,
/// all but `{p(1), p(2), p(3)}` remain: 7 models without duplicates, in every call (the
/// variable and its clauses end with the call; the next call defines a new one).
struct NotAllThree {
    p: Vec<Literal>,
    y: Option<Literal>,
    made: Arc<std::sync::atomic::AtomicUsize>,
}

impl Propagator for NotAllThree {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        self.p = p_lits(init).into_iter().map(|(_, l)| l).collect();
        init.add_watch(self.p[0]);
        self.y = None;
    }

    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, _changes: &[Literal]) {
        let y = match self.y {
            Some(y) => y,
            None => {
                let y = ctl.add_literal();
                self.made.fetch_add(1, Ordering::Relaxed);
                self.y = Some(y);
                y
            }
        };
        let [p1, p2, p3] = [self.p[0], self.p[1], self.p[2]];
        for c in [vec![-y, p1], vec![-y, p2], vec![y, -p1, -p2], vec![-y, -p3]] {
            if !ctl.add_clause(&c) {
                return;
            }
        }
    }
}

#[test]
fn a_volatile_literal_lives_for_one_call() {
    let made = Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let got = answers(
        "{p(1..3)}.",
        Box::new(NotAllThree {
            p: Vec::new(),
            y: None,
            made: made.clone(),
        }),
        2,
    );
    let one = ";p(1);p(1) p(2);p(1) p(3);p(2);p(2) p(3);p(3)";
    assert_eq!(got, format!("{one}|{one}"));
    assert_eq!(made.load(Ordering::Relaxed), 2, "one literal per call");
}

/// A literal added in `init` without clauses is a free variable: every answer set twice, as
/// clingo 5.8 answers `{a}.` with such a propagator (`'', '', 'a', 'a'`: a four-line script,
/// `init.add_literal()` in `init`, run by hand).
struct FreeLiteral;

impl Propagator for FreeLiteral {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        let l = init.add_literal();
        assert!(init.assignment().value(l).is_none());
    }
}

#[test]
fn a_literal_added_in_init_is_free() {
    assert_eq!(answers("{a}.", Box::new(FreeLiteral), 1), ";;a;a");
}

/// Reads the whole assignment at every total assignment and checks it against itself: the
/// trail holds exactly the assigned literals, level by level from `trail_begin`, each decision
/// first on its level; `has_literal` covers `±1..=size`; the root level is within the search.
/// Counts the checks in `seen` (the answers must stay those of `{p(1..3)}`).
struct TrailReader {
    seen: Arc<std::sync::atomic::AtomicUsize>,
}

impl Propagator for TrailReader {
    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let a = ctl.assignment();
        let size = a.size() as Literal;
        assert!(a.has_literal(size) && a.has_literal(-size) && a.has_literal(1));
        assert!(!a.has_literal(0) && !a.has_literal(size + 1));
        let assigned = (1..=size).filter(|&v| a.value(v).is_some()).count();
        assert_eq!(a.trail_len(), assigned);
        assert_eq!(a.trail_begin(0), 0);
        assert!(a.root_level() <= a.decision_level());
        for level in 0..=a.decision_level() {
            let (begin, end) = (a.trail_begin(level), a.trail_begin(level + 1));
            assert!(begin <= end && end <= a.trail_len());
            for i in begin..end {
                let l = a.trail_at(i).unwrap();
                assert!(a.is_true(l) && a.level(l) == level, "{l} on level {level}");
            }
            if let Some(d) = a.decision(level).filter(|_| level > 0) {
                assert_eq!(a.trail_at(begin), Some(d));
            }
        }
        assert_eq!(a.trail_at(a.trail_len()), None);
        self.seen.fetch_add(1, Ordering::Relaxed);
    }
}

#[test]
fn the_trail_and_root_level_describe_the_assignment() {
    let seen = Arc::new(std::sync::atomic::AtomicUsize::new(0));
    let got = answers(
        "{p(1..3)}.",
        Box::new(TrailReader { seen: seen.clone() }),
        2,
    );
    let one = ";p(1);p(1) p(2);p(1) p(2) p(3);p(1) p(3);p(2);p(2) p(3);p(3)";
    assert_eq!(got, format!("{one}|{one}"));
    assert!(seen.load(Ordering::Relaxed) >= 16, "a check per model");
}
