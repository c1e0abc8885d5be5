//! Consistency-restoring rules, `prefer/2`, provenance and the text form.

use lucent::base::SourceMap;
use lucent::ground::program::{BodyRef, HeadKind};
use lucent::ground::{text, GroundConfig, Grounding};

use crate::support::ground as ground_support;

fn run(src: &str, provenance: bool) -> (Grounding, SourceMap) {
    let config = GroundConfig {
        provenance,
        ..GroundConfig::default()
    };
    ground_support::ground_text("-", src, &config)
}

#[test]
fn cr_rules_get_application_atoms_labels_and_preferences() {
    let (g, _) = run(
        "item(1..2). r(X): ab(X) :+ item(X). q :+ item(2). prefer(r(1), r(2)). :- not ab(1), not ab(2).",
        false,
    );
    let mut labels: Vec<&str> = g
        .program
        .cr_rules
        .iter()
        .map(|c| c.label.as_str())
        .collect();
    labels.sort();
    // The unlabelled rule gets r<statement index>.
    assert_eq!(labels, vec!["r(1)", "r(2)", "r2"]);
    // {appl}. and h :- b, appl.
    for c in &g.program.cr_rules {
        assert!(g
            .program
            .rules
            .iter()
            .any(|r| r.head_kind == HeadKind::Choice
                && r.head == [c.appl]
                && r.body.is_empty_normal()));
        assert!(g
            .program
            .rules
            .iter()
            .any(|r| r.head_kind == HeadKind::Disjunction
                && matches!(r.body, BodyRef::Normal(b) if b.contains(&(c.appl as i32)))));
    }
    let appl = |l: &str| {
        g.program
            .cr_rules
            .iter()
            .find(|c| c.label == l)
            .unwrap()
            .appl
    };
    assert_eq!(g.program.prefers.len(), 1);
    assert_eq!(g.program.prefers[0].better, appl("r(1)"));
    assert_eq!(g.program.prefers[0].worse, appl("r(2)"));
}

#[test]
fn provenance_is_parallel_and_printed() {
    let (g, sources) = run("n(1..2).\n{ p(X) } :- n(X).\nq(X) :- p(X), not r.\n", true);
    assert_eq!(g.program.provenance.num_rules(), g.program.rules.len());
    let out = text::write_text(&g, Some(&sources));
    assert!(
        out.contains("% from rule at -:3:1 with X=2; grounding proved not r\nq(2):-p(2).\n"),
        "{out}"
    );
    assert!(out.contains("{p(1)}."), "{out}");
    // Facts stay queryable after simplification.
    assert!(g.facts().contains(&"n(1)".to_string()));
}

#[test]
fn text_form_is_gringos() {
    let (g, _) = run("a. b :- not c. c :- not b. d :- b, a. {e}. :- e, b.", false);
    let out = text::write_text(&g, None);
    // Recorded with `gringo -t` (5.4.1) on this program: the same rules in the same order
    // (its statement dependency graph, searched from the last statement), bodies positive
    // literals last to first, then negative ones.
    assert_eq!(out, "a.\nb:-not c.\nc:-not b.\n{e}.\n:-b,e.\nd:-b.\n");
}
