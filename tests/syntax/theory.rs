//! Theory syntax (`#theory` definitions, theory atoms in heads, bodies and directives): the
//! printer's text parses back to the same tree, operator runs lex as gringo's theory mode
//! lexes them, and errors are placed as gringo places them (`gringo -t`, clingo 5.4.1).

use lucent::base::SourceMap;
use lucent::syntax::ast::{Dialect, Head, StatementKind, TheoryTermKind};
use lucent::syntax::{parse, print};

const PROGRAM: &str = "#theory t { term { + : 1, binary, left; * : 2, binary, right; - : 3, unary; \
    not : 0, unary }; &a/0 : term, body; &b/1 : term, {<=, =, !=}, term, any; &d/0 : term, directive }.
q :- &a{ 1 + 2 * -x, f(X) : p(X), X < 3; (1,); (); [a, \"s\"]; {#sup} : r }, not &b(2){ not y } != - - 1.
&b(1){ x..y : p(1) } <= 3.
&d { 1 }.
&b(X) { } :- p(X).
% a comment inside: the theory mode keeps comments
p(1). r.";

#[test]
fn theory_syntax_round_trips() {
    let mut sources = SourceMap::new();
    let id = sources.add("t.lp", PROGRAM);
    let first = parse(id, PROGRAM, Dialect::Clingo);
    assert!(first.diagnostics.is_empty(), "{:?}", first.diagnostics);
    assert_eq!(first.program.statements.len(), 7);
    let text = print(&first.program);
    let again = parse(id, &text, Dialect::Clingo);
    assert!(
        again.diagnostics.is_empty(),
        "{text}: {:?}",
        again.diagnostics
    );
    assert!(first.program.same_shape(&again.program), "{text}");
    // `x..y` is one operator run in theory mode, and `!=` a guard operator.
    let StatementKind::Rule(r) = &first.program.statements[2].kind else {
        panic!("a rule");
    };
    let Head::Theory(a) = &r.head else {
        panic!("a theory head");
    };
    let TheoryTermKind::Unparsed(parts) = &a.elements[0].terms[0].kind else {
        panic!("an operator term");
    };
    assert_eq!(parts[1].0, vec!["..".to_string()]);
}

/// `(input, gringo's first error line)`, recorded with `gringo -t FILE` (clingo 5.4.1).
#[test]
fn theory_syntax_errors_are_placed_as_gringo_places_them() {
    let cases: &[(&str, &str)] = &[
        (
            "#theory t{term{+:1,binary,left}}.",
            "t.lp:1:18-19: error: syntax error, unexpected <NUMBER>, expecting :",
        ),
        (
            "#theory t{term{}; &a/0 : term, bdy}.",
            "t.lp:1:32-35: error: syntax error, unexpected <IDENTIFIER>, expecting {",
        ),
        (
            "q :- &a{ 1 ; }.",
            "t.lp:1:14-15: error: syntax error, unexpected }, expecting :",
        ),
        (
            "q :- &a{ f(1 }.",
            "t.lp:1:14-15: error: syntax error, unexpected }, expecting )",
        ),
        (
            "q :- &a{ 1 } <= .",
            "t.lp:1:17-18: error: syntax error, unexpected .",
        ),
    ];
    for (input, expected) in cases {
        let mut sources = SourceMap::new();
        let id = sources.add("t.lp", *input);
        let parsed = parse(id, input, Dialect::Clingo);
        let d = parsed.diagnostics.first().expect("an error");
        let line = format!("{}: error: {}", sources.location(d.span), d.message);
        assert_eq!(&line, expected, "{input}");
    }
}
