//! Proof trees built over hand-written ground programs shaped like the RA translation
//! (docs/domain.md 3), each re-checked independently: support, preference (facts, spatial
//! algebra, domain axioms, inertia, closed world), cycles cut, inertia chains carried back to the
//! action that caused a value, CR assumptions, literals that do not hold, normalization, and the
//! branch limit.

use std::collections::HashSet;

use lucent::control::Symbol;
use lucent::explain::build::{normalize, BuildConfig, Builder};
use lucent::explain::tree::{recheck, AxiomKind::*, Kind, ModelOracle, ProofTree, MAX_BRANCHES};

use crate::support::ra_oracle;
use ra_oracle::{example3, rule, t};

fn build(o: &ModelOracle, lit: &str) -> ProofTree {
    let config = BuildConfig {
        agents: vec![t("rob1")],
        ..BuildConfig::default()
    };
    let tree = Builder::new(o, config).build(&t(lit));
    recheck(&tree, o).unwrap_or_else(|e| panic!("{lit}: {e}\n{tree:#?}"));
    tree
}

/// The tree in lines: depth, literal, kind; `*` marks the path.
fn show(tree: &ProofTree) -> String {
    fn walk(tree: &ProofTree, id: lucent::explain::tree::NodeId, depth: usize, out: &mut String) {
        let n = tree.node(id);
        let mark = if tree.on_path(id) { "*" } else { " " };
        out.push_str(&format!(
            "{mark}{}{} [{}]\n",
            "  ".repeat(depth),
            n.literal,
            n.kind.words()
        ));
        for c in &n.children {
            walk(tree, *c, depth + 1, out);
        }
    }
    let mut out = String::new();
    for r in &tree.roots {
        walk(tree, *r, 0, &mut out);
    }
    out
}

#[test]
fn why_not_pick_up_the_green_can_at_step_5() {
    let o = example3();
    let tree = build(&o, "-occurs(pickup(rob1,green_can),5)");
    // E7 (it mentions the green can) before E5, the action CWA last.
    let kinds: Vec<String> = tree
        .roots
        .iter()
        .map(|r| tree.node(*r).kind.words())
        .collect();
    assert_eq!(
        kinds,
        [
            "E7 \u{b7} executability condition",
            "E5 \u{b7} executability condition",
            "closed world"
        ]
    );
    // Normalizing below(green_can, white_block)@5 reaches on(white_block, green_can)@5, which
    // is carried by inertia.
    let below = tree.path[1];
    let normal = normalize(&tree, below, &BuildConfig::default().spatial_labels);
    assert_eq!(
        tree.node(normal).literal,
        t("holds(relation(on,white_block,green_can),5)")
    );
    assert_eq!(tree.node(normal).kind, Kind::Inertia);
    insta::assert_snapshot!(show(&tree));
}

#[test]
fn belief_carried_back_by_inertia_to_the_action() {
    let o = example3();
    let tree = build(&o, "holds(relation(on,white_block,green_can),5)");
    let leaf = tree.node(*tree.path.last().unwrap());
    assert_eq!(leaf.kind, Kind::Action);
    assert_eq!(
        leaf.literal,
        t("occurs(putdown(rob1,white_block,green_can),3)")
    );
    // SR1a's branch is dropped: touch@5 comes only from on@5, a cycle.
    assert_eq!(tree.roots.len(), 1);
    insta::assert_snapshot!(show(&tree));
}

#[test]
fn an_applied_cr_rule_is_an_assumption() {
    let o = example3();
    let tree = build(&o, "holds(stable(white_block),4)");
    assert_eq!(tree.node(tree.roots[0]).kind, Kind::Assumption);
    // -stable does not hold at 5: its one rule, D1, is blocked by the missing small base.
    let tree = build(&o, "-holds(stable(white_block),5)");
    assert_eq!(tree.node(tree.roots[0]).kind, Kind::Unsupported);
    insta::assert_snapshot!(show(&tree));
}

#[test]
fn a_literal_that_does_not_hold_and_its_blocked_rules() {
    let o = example3();
    let tree = build(&o, "occurs(pickup(rob1,green_can),5)");
    let root = tree.node(tree.roots[0]);
    assert!(!root.holds);
    assert_eq!(root.blocked.len(), 1);
    assert_eq!(
        tree.node(root.children[0]).literal,
        t("hpd(pickup(rob1,green_can),5)")
    );
}

#[test]
fn cycles_are_cut_and_preference_follows_facts_first() {
    // a@0 is a fact and also follows from b@0, which follows from a@0: the fact wins, the cycle
    // branch through b is dropped.
    let rules = vec![
        rule("fact", Fact, "h(a,0)"),
        rule("R1", StateConstraint, "h(a,0) :- h(b,0)"),
        rule("R2", StateConstraint, "h(b,0) :- h(a,0)"),
    ];
    let model: HashSet<Symbol> = [t("holds(a,0)"), t("holds(b,0)")].into_iter().collect();
    let o = ModelOracle { rules, model };
    let tree = build(&o, "holds(a,0)");
    let kinds: Vec<Kind> = tree
        .roots
        .iter()
        .map(|r| tree.node(*r).kind.clone())
        .collect();
    assert_eq!(kinds[0], Kind::Observation);
    // R1's branch: b@0 by R2 from a@0 is a cycle, so b@0 has no support below a@0 and R1 is
    // dropped.
    assert_eq!(kinds.len(), 1);
    let tree = build(&o, "holds(b,0)");
    assert_eq!(tree.path.len(), 2);
}

#[test]
fn at_most_sixteen_branches() {
    let mut rules = Vec::new();
    let mut model: HashSet<Symbol> = HashSet::new();
    model.insert(t("holds(goal,0)"));
    for k in 0..40 {
        rules.push(rule("fact", Fact, &format!("h(p({k}),0)")));
        rules.push(rule(
            "R",
            StateConstraint,
            &format!("h(goal,0) :- h(p({k}),0)"),
        ));
        model.insert(t(&format!("holds(p({k}),0)")));
    }
    let o = ModelOracle { rules, model };
    let tree = build(&o, "holds(goal,0)");
    assert_eq!(tree.roots.len(), MAX_BRANCHES);
}
