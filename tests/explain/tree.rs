//! Proof trees: the data type, its independent re-check (accepting a correct tree and rejecting
//! each kind of wrong one), and the drawings (DOT and SVG snapshots). The tree is the paper's
//! execution example 2 (docs/domain.md 6.8), written out by hand from the tabletop encoding's
//! rules: `-occurs(pickup(rob1,white_block),0)` by E7 from `below(white_block, green_can)@0`, by
//! SR3 from `above(green_can, white_block)@0`, by SR1b from the observation
//! `on(green_can, white_block)@0`; the action-CWA branch beside it.

use std::collections::HashSet;

use lucent::control::Symbol;
use lucent::explain::draw;
use lucent::explain::tree::{
    recheck, AxiomKind, BodyLiteral, Kind, ModelOracle, Node, NodeId, ProofTree, RuleInstance,
};

fn t(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

fn rule(label: &str, kind: AxiomKind, head: &str, body: &[&str]) -> RuleInstance {
    RuleInstance {
        label: label.to_string(),
        kind,
        rule: None,
        head: t(head),
        body: body
            .iter()
            .map(|b| match b.strip_prefix("not ") {
                Some(n) => BodyLiteral::Not(t(n)),
                None => BodyLiteral::Pos(t(b)),
            })
            .collect(),
    }
}

const ROOT: &str = "-occurs(pickup(rob1,white_block),0)";
const BELOW: &str = "holds(relation(below,white_block,green_can),0)";
const ABOVE: &str = "holds(relation(above,green_can,white_block),0)";
const ON: &str = "holds(relation(on,green_can,white_block),0)";
const OBS: &str = "obs(relation(on,green_can,white_block),true,0)";
const ACTION: &str = "action(pickup(rob1,white_block))";
const COMPLEMENT: &str = "complement(above,below)";
const OCCURS: &str = "occurs(pickup(rob1,white_block),0)";
const HPD: &str = "hpd(pickup(rob1,white_block),0)";

/// The ground program's rules for the literals of the example, and the model.
fn oracle() -> ModelOracle {
    let mut rules = vec![rule("E7", AxiomKind::Executability, ROOT, &[ACTION, BELOW])];
    rules.push(rule(
        "action CWA",
        AxiomKind::ClosedWorld,
        ROOT,
        &[ACTION, &format!("not {OCCURS}")],
    ));
    rules.push(rule(
        "SR3",
        AxiomKind::StateConstraint,
        BELOW,
        &[ABOVE, COMPLEMENT],
    ));
    rules.push(rule("SR1b", AxiomKind::StateConstraint, ABOVE, &[ON]));
    rules.push(rule("initial state", AxiomKind::History, ON, &[OBS]));
    rules.push(rule("fact", AxiomKind::Fact, ACTION, &[]));
    rules.push(rule("fact", AxiomKind::Fact, COMPLEMENT, &[]));
    rules.push(rule("fact", AxiomKind::Fact, OBS, &[]));
    rules.push(rule("history", AxiomKind::History, OCCURS, &[HPD]));
    let model: HashSet<Symbol> = [ROOT, BELOW, ABOVE, ON, OBS, ACTION, COMPLEMENT]
        .iter()
        .map(|s| t(s))
        .collect();
    ModelOracle { rules, model }
}

fn leaf(
    tree: &mut ProofTree,
    lit: &str,
    kind: Kind,
    label: &str,
    akind: AxiomKind,
    body: &[&str],
) -> NodeId {
    tree.add(Node::supported(t(lit), kind, rule(label, akind, lit, body)))
}

fn example2() -> ProofTree {
    let o = oracle();
    let find = |label: &str| o.rules.iter().find(|r| r.label == label).unwrap().clone();
    let mut tree = ProofTree::default();
    let on = leaf(
        &mut tree,
        ON,
        Kind::Observation,
        "initial state",
        AxiomKind::History,
        &[OBS],
    );
    let mut above = Node::supported(
        t(ABOVE),
        Kind::Axiom {
            label: "SR1b".into(),
            kind: AxiomKind::StateConstraint,
        },
        find("SR1b"),
    );
    above.children = vec![on];
    let above = tree.add(above);
    let complement = leaf(
        &mut tree,
        COMPLEMENT,
        Kind::Static,
        "fact",
        AxiomKind::Fact,
        &[],
    );
    let mut below = Node::supported(
        t(BELOW),
        Kind::Axiom {
            label: "SR3".into(),
            kind: AxiomKind::StateConstraint,
        },
        find("SR3"),
    );
    below.children = vec![above, complement];
    let below = tree.add(below);
    let action = leaf(
        &mut tree,
        ACTION,
        Kind::Static,
        "fact",
        AxiomKind::Fact,
        &[],
    );
    let mut root = Node::supported(
        t(ROOT),
        Kind::Axiom {
            label: "E7".into(),
            kind: AxiomKind::Executability,
        },
        find("E7"),
    );
    root.children = vec![action, below];
    let root = tree.add(root);
    let cwa = tree.add(Node::supported(
        t(ROOT),
        Kind::ClosedWorld,
        find("action CWA"),
    ));
    tree.roots = vec![root, cwa];
    tree.path = vec![root, below, above, on];
    tree
}

#[test]
fn a_correct_tree_passes_the_recheck() {
    let tree = example2();
    recheck(&tree, &oracle()).unwrap();
    assert_eq!(tree.node(tree.roots[1]).no_evidence, vec![t(OCCURS)]);
    assert_eq!(tree.leaves().len(), 4);
    assert_eq!(tree.edges().len(), 5);
    assert_eq!(tree.node(tree.path[3]).step, Some(0));
}

#[test]
fn a_literal_that_does_not_hold() {
    // occurs(pickup(rob1,white_block),0) is false: its one rule is blocked by hpd(..), which
    // has no rule at all.
    let o = oracle();
    let mut tree = ProofTree::default();
    let hpd = tree.add(Node::unsupported(t(HPD)));
    let mut occ = Node::unsupported(t(OCCURS));
    occ.children = vec![hpd];
    occ.blocked = vec![o
        .rules
        .iter()
        .find(|r| r.label == "history")
        .unwrap()
        .clone()];
    let occ = tree.add(occ);
    tree.roots = vec![occ];
    tree.path = vec![occ, hpd];
    recheck(&tree, &o).unwrap();
    // A blocked rule left out is an error.
    let mut missing = tree.clone();
    missing.nodes[1].children.clear();
    missing.nodes[1].blocked.clear();
    missing.path = vec![occ];
    assert!(recheck(&missing, &o)
        .unwrap_err()
        .message
        .contains("not shown blocked"));
}

#[test]
fn the_recheck_rejects_wrong_trees() {
    let o = oracle();
    let good = example2();
    let mut failures = Vec::new();
    let mut check = |name: &str, tree: ProofTree| {
        let e = recheck(&tree, &o).expect_err(name);
        failures.push(format!("{name}: {e}"));
    };

    // A rule the program does not have.
    let mut t1 = good.clone();
    t1.nodes[1].rule.as_mut().unwrap().label = "SR1b".into();
    t1.nodes[1]
        .rule
        .as_mut()
        .unwrap()
        .body
        .push(BodyLiteral::Pos(t(COMPLEMENT)));
    check("invented rule", t1);

    // A body literal that is false in the model.
    let mut o2 = oracle();
    o2.model.remove(&t(ON));
    assert!(recheck(&good, &o2).is_err());

    // A child that is not in the body.
    let mut t3 = good.clone();
    t3.nodes[3].children.push(NodeId(0));
    check("child not in the body", t3);

    // A literal repeated on a path.
    let mut t4 = good.clone();
    let again = t4.add(Node::supported(
        t(ROOT),
        Kind::ClosedWorld,
        o.rules
            .iter()
            .find(|r| r.label == "action CWA")
            .unwrap()
            .clone(),
    ));
    let mut root = t4.nodes[5].clone();
    root.children.push(again);
    let root = t4.add(root);
    t4.roots = vec![root];
    t4.path = vec![];
    check("repeated literal", t4);

    // An inner kind as a leaf.
    let mut t5 = good.clone();
    t5.nodes[1].children.clear();
    t5.path = vec![];
    check("inner node as a leaf", t5);

    // A leaf kind that does not fit its rule.
    let mut t6 = good.clone();
    t6.nodes[6].kind = Kind::Assumption;
    check("wrong leaf kind", t6);

    // A step that is not the literal's.
    let mut t7 = good.clone();
    t7.nodes[0].step = Some(1);
    check("wrong step", t7);

    // A path that leaves the tree.
    let mut t8 = good.clone();
    t8.path = vec![NodeId(5), NodeId(0)];
    check("path off the tree", t8);

    // A "no evidence" literal that is not in the body.
    let mut t9 = good.clone();
    t9.nodes[6].no_evidence = vec![t(HPD)];
    check("invented no-evidence literal", t9);

    insta::assert_snapshot!(failures.join("\n"));
}

#[test]
fn drawn_as_dot() {
    insta::assert_snapshot!(draw::dot(&example2()));
}

#[test]
fn drawn_as_svg() {
    let svg = draw::svg(&example2());
    // Well-formed enough for a browser: one root element, every box and text closed.
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert_eq!(svg.matches("<rect").count(), 1 + 7);
    assert_eq!(svg.matches("<line").count(), 5);
    assert_eq!(svg.matches("stroke=\"#2e7d32\"").count(), 4 + 3);
    insta::assert_snapshot!(svg);
}
