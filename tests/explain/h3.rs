//! H3 (docs/domain.md 7.5): on generated (scene, goal, plan) triples over KB_full, every proof tree
//! passes the re-check, no literal repeats on a path, and every leaf is of a kind docs/domain.md
//! 6.2 lists (`explain::h3::check_tree`). By default a subset of the triples runs (the first seeds
//! of each preset); the full 200 run with `cargo run --release --example h3 -- 100`, whose
//! figures are in docs/bench/h3-2026-12-01.txt.
//!
//! Also here: the generator's invariants over many seeds (no solving), and that the checks can
//! fail (a tree with a repeated literal, a leaf of the wrong kind, a body that does not hold).

use crate::support::ra_scenes;

use lucent::control::Symbol;
use lucent::explain::h3::{check_history, check_tree, generate, Goal, ScenePreset};
use lucent::explain::tree::{AxiomKind, Kind, ModelOracle, Node, ProofTree, RuleInstance};
use ra_scenes::{history, load_text, plans};

#[test]
fn generated_scenes_keep_their_invariants() {
    for preset in ScenePreset::ALL {
        for seed in 0..300 {
            let s = generate(preset, seed);
            assert_eq!(s, generate(preset, seed), "deterministic");
            let n = s.objects.len();
            let (lo, hi) = match preset {
                ScenePreset::Real => (5, 7),
                ScenePreset::Simulated => (7, 9),
            };
            assert!((lo..=hi).contains(&n), "{}: {n} objects", s.name());
            // Every object stands on exactly one thing; supports are flat, not small, and carry
            // one object; towers are at most 4 high.
            for o in &s.objects {
                assert_eq!(s.on.iter().filter(|(a, _)| *a == o.name).count(), 1);
            }
            let mut stacked = 0;
            for (a, b) in &s.on {
                if b == "table" {
                    continue;
                }
                let sup = s.object(b).expect("support is an object");
                assert_eq!(sup.surface, "flat", "{}: {a} on {b}", s.name());
                assert_ne!(sup.size, "small", "{}: {a} on {b}", s.name());
                assert_eq!(s.on.iter().filter(|(_, c)| c == b).count(), 1);
                stacked += 1 + usize::from(s.support(b) == Some("table"));
                let mut level = 1;
                let mut at = a.as_str();
                while let Some(next) = s.support(at) {
                    if next == "table" {
                        break;
                    }
                    level += 1;
                    at = next;
                }
                assert!(level <= 4, "{}: {a} at level {level}", s.name());
            }
            if preset == ScenePreset::Simulated {
                assert!(
                    (3..=5).contains(&stacked),
                    "{}: {stacked} stacked {:?}",
                    s.name(),
                    s
                );
            }
            for (a, b) in &s.behind {
                assert_ne!(a, b);
                assert_eq!(s.support(a), Some("table"));
                assert_eq!(s.support(b), Some("table"));
            }
            match &s.goal {
                Goal::On(x, y) => {
                    assert_ne!(x, y);
                    assert_ne!(
                        s.support(x),
                        Some(y.as_str()),
                        "{}: goal already true",
                        s.name()
                    );
                    if y != "table" {
                        let o = s.object(y).unwrap();
                        assert!(o.surface == "flat" && o.size != "small", "{}", s.name());
                    }
                }
                Goal::InHand(x) => assert!(s.object(x).is_some()),
            }
        }
    }
}

/// Plans one generated scene under KB_full, explains its first minimal plan and checks every
/// tree. Returns the number of trees.
fn trial(preset: ScenePreset, seed: u64) -> usize {
    let scene = generate(preset, seed);
    let text = scene.to_ald("../kb_full.ald", true);
    let (desc, mut sources) = load_text("generated.ald", &text);
    let found =
        plans(&desc, &sources, None, 10).unwrap_or_else(|e| panic!("{}: {e}", scene.name()));
    let chosen = &found.plans[0];
    let h = history(&desc, &mut sources, &chosen.actions, None);
    let report = check_history(&h.scenario(), &h.objects(), seed);
    assert!(
        report.failures.is_empty(),
        "{} ({}): {:#?}",
        scene.name(),
        chosen.to_text(),
        report.failures
    );
    // The trees reach the leaves a history has: observations of the initial state, and the
    // actions when the plan is not empty.
    assert!(
        report.counts.leaves[1] > 0,
        "{}: no observation leaf",
        scene.name()
    );
    if !chosen.actions.is_empty() {
        assert!(
            report.counts.leaves[2] > 0,
            "{}: no action leaf",
            scene.name()
        );
    }
    report.trees
}

#[test]
fn h3_subset_real() {
    let trees: usize = (0..2).map(|s| trial(ScenePreset::Real, s)).sum();
    assert!(trees >= 20, "{trees} trees");
}

#[test]
fn h3_subset_simulated() {
    let trees: usize = (0..2).map(|s| trial(ScenePreset::Simulated, s)).sum();
    assert!(trees >= 20, "{trees} trees");
}

fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

fn rule(kind: AxiomKind, head: &str, body: &[&str]) -> RuleInstance {
    RuleInstance {
        label: "r".into(),
        kind,
        rule: None,
        head: t(head),
        body: body
            .iter()
            .map(|b| lucent::explain::tree::BodyLiteral::Pos(t(b)))
            .collect(),
    }
}

#[test]
fn the_checks_can_fail() {
    // p(1) :- q(1).  q(1) :- p(1).  q(1) is also an observation.
    let obs = rule(AxiomKind::Fact, "holds(q,1)", &[]);
    let pq = rule(AxiomKind::StateConstraint, "holds(p,1)", &["holds(q,1)"]);
    let qp = rule(AxiomKind::StateConstraint, "holds(q,1)", &["holds(p,1)"]);
    let oracle = ModelOracle {
        rules: vec![obs.clone(), pq.clone(), qp.clone()],
        model: [t("holds(p,1)"), t("holds(q,1)")].into_iter().collect(),
    };
    let axiom = |r: &RuleInstance| Kind::Axiom {
        label: "r".into(),
        kind: r.kind,
    };
    // A good tree: p from q, q observed.
    let mut good = ProofTree::default();
    let leaf = good.add(Node::supported(
        t("holds(q,1)"),
        Kind::Observation,
        obs.clone(),
    ));
    let mut root = Node::supported(t("holds(p,1)"), axiom(&pq), pq.clone());
    root.children = vec![leaf];
    let r = good.add(root);
    good.roots = vec![r];
    let counts = check_tree(&good, &oracle).unwrap();
    assert_eq!(counts.leaves, [0, 1, 0, 0, 0]);
    assert_eq!(counts.paths, 1);
    // A cycle: p from q from p.
    let mut cyc = ProofTree::default();
    let p0 = cyc.add(Node::supported(t("holds(p,1)"), axiom(&pq), pq.clone()));
    let mut q = Node::supported(t("holds(q,1)"), axiom(&qp), qp.clone());
    q.children = vec![p0];
    let q = cyc.add(q);
    let mut p = Node::supported(t("holds(p,1)"), axiom(&pq), pq.clone());
    p.children = vec![q];
    let p = cyc.add(p);
    cyc.roots = vec![p];
    assert!(check_tree(&cyc, &oracle).is_err());
    // A leaf that is not one of the five kinds: q as an axiom node without children.
    let mut bad = ProofTree::default();
    let q = bad.add(Node::supported(t("holds(q,1)"), axiom(&qp), qp.clone()));
    let mut p = Node::supported(t("holds(p,1)"), axiom(&pq), pq);
    p.children = vec![q];
    let p = bad.add(p);
    bad.roots = vec![p];
    assert!(check_tree(&bad, &oracle).is_err());
    // A body that does not hold: r(1) is not in the model.
    let pr = rule(AxiomKind::StateConstraint, "holds(p,1)", &["holds(r,1)"]);
    let oracle2 = ModelOracle {
        rules: vec![pr.clone()],
        model: [t("holds(p,1)")].into_iter().collect(),
    };
    let mut nb = ProofTree::default();
    let p = nb.add(Node::supported(t("holds(p,1)"), axiom(&pr), pr));
    nb.roots = vec![p];
    assert!(check_tree(&nb, &oracle2).is_err());
}
