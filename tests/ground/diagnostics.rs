//! Diagnostics of the grounder on bad input, rendered as gringo renders them, snapshotted.

use lucent::base::SourceMap;
use lucent::ground::{ground, GroundConfig};
use lucent::syntax::ast::Dialect;
use lucent::syntax::parse;

fn check(text: &str) -> String {
    let mut sources = SourceMap::new();
    let id = sources.add("-", text);
    let parsed = parse(id, text, Dialect::Clingo);
    assert!(!parsed.has_errors(), "parse errors in {text}");
    let g = ground(&parsed.program, Some(&sources), &GroundConfig::default());
    g.diagnostics.render(&sources)
}

#[test]
fn unsafe_head_variable() {
    insta::assert_snapshot!(check("p(X)."));
}

#[test]
fn unsafe_variables_in_negation_and_comparison() {
    insta::assert_snapshot!(check("q(X,Y) :- not r(Y), X=1.\nr(Z) :- Z > 1, s(W)."));
}

#[test]
fn undefined_operation_drops_the_instance() {
    insta::assert_snapshot!(check("n(0;2). p(10/X) :- n(X). q(a+1)."));
}

#[test]
fn atom_not_in_any_head() {
    insta::assert_snapshot!(check("a :- b, not c."));
}

#[test]
fn size_limit_stops_grounding() {
    let text = "n(1..1000). p(X,Y) :- n(X), n(Y).";
    let mut sources = SourceMap::new();
    let id = sources.add("-", text);
    let parsed = parse(id, text, Dialect::Clingo);
    let config = GroundConfig {
        max_size: Some(10_000),
        ..GroundConfig::default()
    };
    let g = ground(&parsed.program, Some(&sources), &config);
    assert!(g.diagnostics.has_errors());
    assert!(g.program.rules.is_empty());
    insta::assert_snapshot!(g.diagnostics.render(&sources));
}

#[test]
fn redefinition_of_constant() {
    // clingo 5.8.3 reports the second and third definitions, each with a note at the first.
    insta::assert_snapshot!(check("#const a=1.\n#const a=2.\n#const a=3.\np(a)."));
}

#[test]
fn cyclic_constant_definition() {
    // One error per cycle, at its first definition; `b` only depends on the cycle. clingo 5.8.3
    // prints the same messages (with the value normalised as `(d+1)`).
    insta::assert_snapshot!(check(
        "#const a=f(c).\n#const b=a.\n#const c=d+1.\n#const d=a.\np(b)."
    ));
}

#[test]
fn constants_in_any_order_and_self_reference() {
    // `#const a=b. #const b=1.` gives a=1; `#const s=s.` leaves the name (clingo 5.8.3).
    assert_eq!(check("#const a=b.\n#const b=1.\n#const s=s.\np(a,s)."), "");
}

#[test]
fn undefined_tuple_in_head_aggregate() {
    // clingo 5.8.3 warns about the same two terms, printed as `(X+0)` (its own weight check)
    // and `(X+1)`, and locates an operation at its first operand.
    insta::assert_snapshot!(check("p(bot).\n#sum{X:q(X):p(X)}.\n#count{X+1:q(X):p(X)}."));
}
