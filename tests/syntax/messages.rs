//! Syntax and lexer errors are worded and placed as gringo 5.4 words and places them. Each
//! expected line below is what `echo INPUT | gringo -t -` printed for the same input (its
//! first error line), so a change of wording or position shows up here. One deliberate
//! difference: comparison chains such as `X = Y = Z` are accepted, as clingo 5.8 accepts them.

use lucent::base::SourceMap;
use lucent::syntax::ast::Dialect;
use lucent::syntax::parse;

/// `(input, gringo's first error line)`; the input is followed by a newline, as `echo` does.
const CASES: &[(&str, &str)] = &[
    ("p(\"abc).", "-:1:3-4: error: lexer error, unexpected \""),
    (
        "p(1",
        "-:2:1-2: error: syntax error, unexpected EOF, expecting ) or ;",
    ),
    (
        "p(1.",
        "-:1:4-5: error: syntax error, unexpected ., expecting ) or ;",
    ),
    (
        "a b.",
        "-:1:3-4: error: syntax error, unexpected <IDENTIFIER>",
    ),
    (
        "p(X) :- q(X)",
        "-:2:1-2: error: syntax error, unexpected EOF",
    ),
    ("%* abc", "-:2:1-2: error: lexer error, unexpected <EOF>"),
    (
        "a :- #sum{X:p(X)} .. 2.",
        "-:1:19-21: error: syntax error, unexpected .., expecting \",\" or . or ;",
    ),
    (
        "p(1..2.",
        "-:1:7-8: error: syntax error, unexpected ., expecting ) or ;",
    ),
    ("a :- b,", "-:2:1-2: error: syntax error, unexpected EOF"),
    ("a :- b,.", "-:1:8-9: error: syntax error, unexpected ."),
    (
        "a :- 1 #count{X:p(X)} 2 3.",
        "-:1:25-26: error: syntax error, unexpected <NUMBER>, expecting \",\" or . or ;",
    ),
    (
        "a :- #foo{}.",
        "-:1:6-10: error: lexer error, unexpected #foo",
    ),
    ("p(1)) .", "-:1:5-6: error: syntax error, unexpected )"),
    (
        "p(1a).",
        "-:1:4-5: error: syntax error, unexpected <IDENTIFIER>, expecting ) or ;",
    ),
    ("a :- b; .", "-:1:9-10: error: syntax error, unexpected ."),
    (
        "p(X) :- #count{X:q(X).",
        "-:1:22-23: error: syntax error, unexpected ., expecting } or ;",
    ),
    ("\"", "-:1:1-2: error: lexer error, unexpected \""),
    (
        "p(X)\n:- q(X)\nr.",
        "-:3:1-2: error: syntax error, unexpected <IDENTIFIER>",
    ),
    ("a :~ b.", "-:1:3-5: error: syntax error, unexpected :~"),
    ("#foo.", "-:1:1-5: error: lexer error, unexpected #foo"),
    ("p(1,).", "-:1:5-6: error: syntax error, unexpected )"),
    (
        "a :- not not not b.",
        "-:1:14-17: error: syntax error, unexpected not",
    ),
    (
        "a :- b : c d.",
        "-:1:12-13: error: syntax error, unexpected <IDENTIFIER>",
    ),
    (
        "a :- 1 < 2 3.",
        "-:1:12-13: error: syntax error, unexpected <NUMBER>, expecting : or \",\" or . or ;",
    ),
    (
        "a :- b : 1 < 2 3.",
        "-:1:16-17: error: syntax error, unexpected <NUMBER>, expecting . or ;",
    ),
    (
        "a :- not b c.",
        "-:1:12-13: error: syntax error, unexpected <IDENTIFIER>",
    ),
    (
        "a :- #true c.",
        "-:1:12-13: error: syntax error, unexpected <IDENTIFIER>, expecting : or \",\" or . or ;",
    ),
    (
        "a | b c.",
        "-:1:7-8: error: syntax error, unexpected <IDENTIFIER>",
    ),
    (
        "#show a b.",
        "-:1:9-10: error: syntax error, unexpected <IDENTIFIER>",
    ),
    (
        ":~ a. [1 2]",
        "-:1:10-11: error: syntax error, unexpected <NUMBER>, expecting ]",
    ),
    (
        "#const a = 1 2.",
        "-:1:14-15: error: syntax error, unexpected <NUMBER>",
    ),
    (
        "1 #count{ 1 : a } 2 3.",
        "-:1:21-22: error: syntax error, unexpected <NUMBER>, expecting . or :-",
    ),
];

#[test]
fn errors_match_gringo() {
    let mut mismatches = Vec::new();
    for (input, expected) in CASES {
        let text = format!("{input}\n");
        let mut map = SourceMap::new();
        let file = map.add("-", text.clone());
        let parsed = parse(file, &text, Dialect::Clingo);
        let first = parsed
            .diagnostics
            .first()
            .map(|d| d.render(&map).lines().next().unwrap_or("").to_string())
            .unwrap_or_default();
        if first != *expected {
            mismatches.push(format!(
                "{input:?}\n  gringo: {expected}\n  lucent: {first}"
            ));
        }
    }
    assert!(mismatches.is_empty(), "{}", mismatches.join("\n"));
}
