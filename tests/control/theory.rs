//! Theory atoms through `Control`: `theory_atoms()` (terms, elements, guards, literals) and a
//! small difference-logic propagator reading them in `init` and refusing, in `check`, total
//! assignments whose true `&diff{ u - v } <= c` atoms (`u - v <= c`, an edge u -> v of weight
//! c) close a negative cycle. Expected answer sets are derived by hand in each test.

use lucent::control::theory::{TheoryTerm, TheoryTermType};
use lucent::control::{
    Control, ControlConfig, Literal, Part, PropagateControl, PropagateInit, Propagator,
    SolveOptions, Symbol,
};
use lucent::solve::Config;

const THEORY: &str = "#theory dl { term { - : 1, binary, left }; constant { - : 0, unary };
    &diff/0 : term, {<=}, constant, any }.";

/// The difference-logic propagator: edges (from, to, weight, literal).
#[derive(Default)]
struct Diff {
    edges: Vec<(String, String, i64, Literal)>,
}

fn constant(t: &TheoryTerm) -> i64 {
    match t {
        TheoryTerm::Number(n) => i64::from(*n),
        TheoryTerm::Function(op, a) if op == "-" && a.len() == 1 => -constant(&a[0]),
        _ => panic!("not a constant: {t}"),
    }
}

impl Propagator for Diff {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        self.edges.clear();
        let atoms = init.theory_atoms().to_vec();
        for a in atoms {
            assert_eq!(a.term.name(), Some("diff"));
            let (op, c) = a.guard.clone().expect("a guard");
            assert_eq!(op, "<=");
            let t = &a.elements[0].terms[0];
            assert_eq!(t.term_type(), TheoryTermType::Function);
            let [u, v] = t.arguments() else {
                panic!("u - v expected")
            };
            let lit = init.solver_literal(a.atom);
            self.edges
                .push((u.to_string(), v.to_string(), constant(&c), lit));
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let a = ctl.assignment();
        let true_edges: Vec<_> = self.edges.iter().filter(|e| a.is_true(e.3)).collect();
        // Bellman-Ford from a virtual source at distance 0 to every node.
        let mut dist: std::collections::HashMap<&str, i64> = std::collections::HashMap::new();
        for e in &true_edges {
            dist.insert(&e.0, 0);
            dist.insert(&e.1, 0);
        }
        let n = dist.len();
        let mut changed = false;
        for _ in 0..=n {
            changed = false;
            for e in &true_edges {
                let d = dist[e.0.as_str()] + e.2;
                if d < dist[e.1.as_str()] {
                    dist.insert(&e.1, d);
                    changed = true;
                }
            }
        }
        if changed {
            let clause: Vec<Literal> = true_edges.iter().map(|e| -e.3).collect();
            ctl.add_clause(&clause);
        }
    }
}

fn sets(program: &str, propagate: bool) -> Vec<Vec<String>> {
    let mut ctl = Control::new(ControlConfig {
        solve: Config {
            models: 0,
            ..Config::default()
        },
        ..ControlConfig::default()
    });
    ctl.add_source("d.lp", &format!("{THEORY}\n{program}"))
        .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    if propagate {
        ctl.register_propagator(Box::new(Diff::default()));
    }
    let mut sets: Vec<Vec<String>> = ctl
        .solve_all(&SolveOptions::default())
        .models
        .iter()
        .map(|m| {
            let mut a: Vec<String> = m.shown.iter().map(Symbol::to_string).collect();
            a.sort();
            a
        })
        .collect();
    sets.sort();
    sets
}

/// All subsets of `atoms` except those in `without`, as sorted answer sets.
fn subsets(atoms: &[&str], without: &[&[&str]]) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for m in 0..1u32 << atoms.len() {
        let s: Vec<String> = (0..atoms.len())
            .filter(|i| m >> i & 1 == 1)
            .map(|i| atoms[i].to_string())
            .collect();
        if !without
            .iter()
            .any(|w| w.len() == s.len() && w.iter().all(|x| s.contains(&x.to_string())))
        {
            out.push(s);
        }
    }
    out.sort();
    out
}

#[test]
fn theory_atoms_are_read_as_clingo_gives_them() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add_source(
        "d.lp",
        &format!("{THEORY}\n{{a}}. &diff{{ x - y }} <= -1 :- a."),
    )
    .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let atoms = ctl.theory_atoms().to_vec();
    assert_eq!(atoms.len(), 1);
    // clingo 5.8: str(atom) == '&diff{(x-y)}<=(-1)'.
    assert_eq!(ctl.theory_atom_text(&atoms[0]), "&diff{(x-y)}<=(-1)");
    assert_eq!(atoms[0].term.term_type(), TheoryTermType::Symbol);
    assert!(atoms[0].atom != 0);
    let t = &atoms[0].elements[0].terms[0];
    assert_eq!(t.name(), Some("-"));
    assert_eq!(t.arguments()[0].name(), Some("x"));
}

#[test]
fn a_negative_cycle_is_refused() {
    // x - y <= -1, y - z <= -1, z - x <= -1 sum to 0 <= -3: the three together are refused, every
    // other choice of a, b, c is an answer set (8 - 1 = 7).
    let p = "{a; b; c}. &diff{ x - y } <= -1 :- a. &diff{ y - z } <= -1 :- b.
             &diff{ z - x } <= -1 :- c.";
    assert_eq!(sets(p, false), subsets(&["a", "b", "c"], &[]));
    assert_eq!(
        sets(p, true),
        subsets(&["a", "b", "c"], &[&["a", "b", "c"]])
    );
    // With z - x <= 2 the cycle weighs 0: nothing is refused.
    let q = "{a; b; c}. &diff{ x - y } <= -1 :- a. &diff{ y - z } <= -1 :- b.
             &diff{ z - x } <= 2 :- c.";
    assert_eq!(sets(q, true), subsets(&["a", "b", "c"], &[]));
    // Two 2-cycles: x - y <= -1 with y - x <= 0 (a, b), and y - x <= 0 with x - y <= 0 is
    // fine; so only sets holding both a and b are refused.
    let r = "{a; b; c}. &diff{ x - y } <= -1 :- a. &diff{ y - x } <= 0 :- b.
             &diff{ x - y } <= 0 :- c.";
    assert_eq!(
        sets(r, true),
        subsets(&["a", "b", "c"], &[&["a", "b"], &["a", "b", "c"]])
    );
}

/// Theory conditions of several literals named by one literal (clingo's `condition_id`; clingo
/// 5.8 numbers `x` and `z` below `2^28 + 1` and `2^28 + 2`, `y` by `p(3)`'s atom, `w` 0):
/// `condition_literal` is true exactly when its condition holds, at every total assignment,
/// and a clause over it acts as over the conjunction. `checks` counts the checks.
struct Conditions {
    defs: Vec<(Vec<Literal>, Literal)>,
    checks: std::sync::Arc<std::sync::atomic::AtomicUsize>,
}

const CONDITIONS: &str = "#theory t { term { }; &a/0 : term, any }.
    {p(1..3)}. {q}. &a { x : p(1), p(2); y : p(3); z : q, not p(1); w }.";

impl Propagator for Conditions {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        let signed = |init: &PropagateInit<'_>, l: i32| {
            let x = init.solver_literal(l.unsigned_abs());
            if l < 0 {
                -x
            } else {
                x
            }
        };
        let atoms = init.theory_atoms().to_vec();
        self.defs.clear();
        let mut x_of_p12 = None;
        for e in &atoms[0].elements {
            let lit = init.condition_literal(&e.condition).unwrap();
            let body = e.condition.iter().map(|&l| signed(init, l)).collect();
            init.add_watch(lit);
            self.defs.push((body, lit));
            if e.terms[0].name() == Some("x") {
                x_of_p12 = Some(lit);
                // The same condition twice: one variable.
                assert_eq!(init.condition_literal(&e.condition), Some(lit));
            }
        }
        let p3 = init
            .symbolic_atoms()
            .iter()
            .find(|a| a.symbol.to_string() == "p(3)")
            .map(|a| init.solver_literal(a.atom))
            .unwrap();
        assert!(init.add_clause(&[-x_of_p12.unwrap(), -p3]));
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let a = ctl.assignment();
        for (body, lit) in &self.defs {
            assert_eq!(a.is_true(*lit), body.iter().all(|&b| a.is_true(b)));
        }
        self.checks
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    }
}

#[test]
fn a_condition_of_several_literals_is_one_literal() {
    let mut ctl = Control::new(ControlConfig {
        solve: Config {
            models: 0,
            ..Config::default()
        },
        ..ControlConfig::default()
    });
    ctl.add("base", &[], CONDITIONS).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let atoms = ctl.theory_atoms().to_vec();
    let p3 = ctl.lookup(&Symbol::parse("p(3)").unwrap()).unwrap() as i32;
    let base = lucent::control::theory::CONDITION_BASE;
    assert_eq!(
        lucent::control::theory::condition_ids(&atoms),
        vec![vec![base + 1, p3, base + 2, 0]]
    );
    let checks = std::sync::Arc::new(std::sync::atomic::AtomicUsize::new(0));
    ctl.register_propagator(Box::new(Conditions {
        defs: Vec::new(),
        checks: checks.clone(),
    }));
    for _ in 0..2 {
        let models = ctl.solve_all(&SolveOptions::default()).models;
        // {p(1..3)} x {q}, without p(1), p(2), p(3) together: 16 - 2.
        assert_eq!(models.len(), 14);
        assert!(models.iter().all(|m| !["p(1)", "p(2)", "p(3)"]
            .iter()
            .all(|s| m.shown.iter().any(|x| x.to_string() == *s))));
    }
    assert!(checks.load(std::sync::atomic::Ordering::Relaxed) >= 28);
}
