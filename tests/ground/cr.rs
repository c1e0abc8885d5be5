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

#[test]
fn dependencies_follow_unification_and_source_order() {
    // Each expected text was recorded with `gringo --text` (5.4.1) on the program above it.
    // `s(X) :- n(e,X)` depends on the rule for `n(e,X)` alone, not on the one for `n(w,X)`
    // (whose atoms cannot unify with it), so it is grounded before `t`, `u` and `n(w,X)`.
    let (g, _) = run(
        "f(1..3).\nt(X) :- f(X), not u(X).\nu(X) :- f(X), X > 2.\nn(e,X) :- f(X).\nn(w,X) :- t(X).\ns(X) :- n(e,X).\n",
        false,
    );
    assert_eq!(
        text::write_text(&g, None),
        "f(1).\nf(2).\nf(3).\nn(e,1).\nn(e,2).\nn(e,3).\ns(1).\ns(2).\ns(3).\nu(3).\nt(1).\nt(2).\nn(w,1).\nn(w,2).\n"
    );
    // The depth-first search follows the body as written (`d` then `c`, searched last to
    // first), not the order the rule is evaluated in (`c` binds fewer variables, so it comes
    // first there).
    let (g, _) = run(
        "a(1..2).\nb(X) :- a(X).\nc(X) :- a(X).\nd(X,Y,Z) :- b(X), Y=X+1, Z=X+2.\nr(X) :- d(X,Y,Z), c(X).\n",
        false,
    );
    assert_eq!(
        text::write_text(&g, None),
        "a(1).\na(2).\nc(1).\nc(2).\nb(1).\nb(2).\nd(1,2,3).\nd(2,3,4).\nr(1).\nr(2).\n"
    );
}

#[test]
fn new_atoms_of_an_unbound_recursive_literal_are_read_newest_first() {
    // `gringo --text` (5.4.1) on this program prints the rules in this order:
    //   a(1). a(2). a(3). b(3):-not c(3). b(2):-not c(2). b(1):-not c(1). c(3):-b(3). c(2):-b(2).
    // `a` and `b` form a positive cycle; `b(X) :- a(X), ...` reads the atoms of `a` new in the
    // round with no argument bound, which gringo walks from the newest to the oldest. Lucent
    // prints the same order; it also drops `not c(1)`, since no rule can derive `c(1)`.
    let (g, _) = run(
        "n(1..3).\na(X) :- n(X).\na(X) :- b(X).\nb(X) :- a(X), not c(X).\nc(X) :- b(X), X > 1.\n",
        false,
    );
    assert_eq!(
        text::write_text(&g, None),
        "n(1).\nn(2).\nn(3).\na(1).\na(2).\na(3).\nb(3):-not c(3).\nb(2):-not c(2).\nb(1).\nc(3):-b(3).\nc(2):-b(2).\n"
    );
}
