//! Keeps `grammar/asp.ebnf` and `grammar/sparc.ebnf` in step with the parser: every production
//! of the grammars must have an example below, every example must name a production, and every
//! example must parse without errors (and round-trip through the printer). Adding a production
//! without an example fails this test.

use std::collections::BTreeSet;
use std::path::Path;

use lucent::base::FileId;
use lucent::syntax::ast::{Dialect, StatementKind};
use lucent::syntax::fuzzing::check_round_trip;
use lucent::syntax::{parse, UNSUPPORTED_SCRIPT};

/// A SPARC program with every section, around which SPARC examples are placed.
const SPARC_FRAME: &str = "sorts\n#s = {a, b}.\npredicates\np(#s).\nrules\np(a).\ndisplay\np.\n";

/// `(grammar file, production, example)`. Clingo-dialect examples are whole programs; SPARC
/// examples are whole programs too (most use [`SPARC_FRAME`] pieces).
const EXAMPLES: &[(&str, &str, &str)] = &[
    ("asp", "identifier", "_p'x1."),
    ("asp", "variable", "p(X) :- q(_Y1, X)."),
    ("asp", "anonymous", "p :- q(_)."),
    ("asp", "number", "p(42, 0x2A, 0o52, 0b101010)."),
    ("asp", "string", "p(\"a \\\"b\\\" \\\\ c\\n\")."),
    ("asp", "program", "a. b :- a."),
    ("asp", "statement", "a. :~ a. [1] #show a/0."),
    ("asp", "rule", "a. b :- a. :- not b."),
    ("asp", "cr_rule", "a :+ b. r(X) : p(X) :+ q(X). :+ c. k : :+ d."),
    ("asp", "head", "a | b. {c}. 1 #sum { 1 : d }."),
    ("asp", "disjunction", "a | b ; c, d."),
    ("asp", "head_element", "p(X) : q(X) :- r."),
    ("asp", "choice", "1 { a : b ; c } 2. { d }. 1 < { e } <= 3."),
    ("asp", "head_aggregate", "#count { X : p(X) : q(X) } = 1."),
    (
        "asp",
        "head_aggregate_element",
        "#sum { 1, a : p ; : q : r }.",
    ),
    ("asp", "lower_guard", "1 { a }. X < { b } :- c(X)."),
    ("asp", "upper_guard", "{ a } 2. { b } != 1."),
    (
        "asp",
        "aggregate_function",
        "a :- #count{1:b}, #sum{1:b}, #sum+{1:b}, #min{1:b}, #max{1:b}.",
    ),
    ("asp", "body", "a :- b, c; d."),
    (
        "asp",
        "body_literal",
        "a :- b : c; not #count { 1 : d } > 0; 1 < 2 < 3.",
    ),
    ("asp", "conditional_literal", "a :- b(X) : c(X), d(X); e."),
    (
        "asp",
        "body_aggregate",
        "a :- 1 < #sum { X : p(X) } < 4, 1 { b ; c }.",
    ),
    (
        "asp",
        "body_aggregate_element",
        "a :- #count { X, Y : p(X, Y) ; : q ; Z : }.",
    ),
    ("asp", "condition", "a :- b : c, not d, 1 < 2."),
    ("asp", "condition_literal", "a :- b : 1 < X < 3, c(X)."),
    ("asp", "comparison_chain", "a :- 1 < X <= 3, X = 2."),
    ("asp", "sign", "a :- b, not c, not not d."),
    ("asp", "literal", "a :- not -b(1), #true, not #false."),
    ("asp", "atom", "-a(1) :- b, 1 < 2, #true."),
    ("asp", "symbolic_atom", "-p(1, 2; 3, 4). q. r()."),
    ("asp", "comparison", "a :- 1 != 2."),
    (
        "asp",
        "comparison_op",
        "a :- 1 = 1, 1 == 1, 1 != 2, 1 <> 2, 1 < 2, 1 <= 2, 2 > 1, 2 >= 1.",
    ),
    ("asp", "terms", "p(1, a, X) :- q(X)."),
    ("asp", "argument_pool", "p(1, 2; 3, 4)."),
    (
        "asp",
        "term",
        "p(1 + 2 * 3 ** 2 - -4 / ~5 \\ 6 & 7 ? 8 ^ 9).",
    ),
    (
        "asp",
        "binary_op",
        "p(1..2, 1^2, 1?2, 1&2, 1+2, 1-2, 1*2, 1/2, 1\\2, 1**2).",
    ),
    (
        "asp",
        "primary_term",
        "p(1, \"s\", #inf, #sup, f(a), |-3|, (1, 2)).",
    ),
    ("asp", "tuple_or_pool", "p(()). q((1,)). r((1, 2; 3))."),
    ("asp", "tuple_items", "p((1, 2,))."),
    ("asp", "script_call", "p(@f(1))."),
    ("asp", "weak_constraint", ":~ p(X). [X@2, X]"),
    ("asp", "weight_tuple", ":~ p(X). [1@X, a, b]"),
    ("asp", "optimize", "#minimize { 1 : a }. #maximise { }."),
    (
        "asp",
        "optimize_element",
        "#maximize { X@2, X : p(X) ; 1 }.",
    ),
    ("asp", "signature", "#show -p/2."),
    ("asp", "show", "#show. #show p/1. #show X : p(X)."),
    ("asp", "defined", "#defined q/3."),
    ("asp", "project", "#project p/1. #project p(X) : q(X)."),
    ("asp", "const", "#const n = 3. #const m = n + 1. [override]"),
    ("asp", "external", "#external e(X) : p(X). [false]"),
    ("asp", "heuristic", "#heuristic a : b. [2@1, level]"),
    ("asp", "edge", "#edge (a, b) : c."),
    ("asp", "include", "#include \"f.lp\". #include <incmode>."),
    ("asp", "program_part", "#program step(t). #program base."),
    ("asp", "script", "#script (python)\nx = 1\n#end."),
    ("sparc", "sparc_program", SPARC_FRAME),
    (
        "sparc",
        "sorts_section",
        "#const n = 2.\nsorts\n#s = 1..n.\n#const m = 1.",
    ),
    (
        "sparc",
        "predicates_section",
        "sorts\n#s = {a}.\npredicates\np(#s).\nq().",
    ),
    (
        "sparc",
        "rules_section",
        "sorts\n#s = {a}.\nrules\np(X) :- #s(X).\n:~ p(a). [1]",
    ),
    (
        "sparc",
        "display_section",
        "sorts\n#s = {a}.\nrules\np(a).\ndisplay\np.\n#s(X).",
    ),
    (
        "sparc",
        "sort_name",
        "sorts\n#_s1 = {a}.\n#program = #_s1.\npredicates\np(#program).\nrules\np(X) :- #program(X).",
    ),
    ("sparc", "sort_definition", "sorts\n#s = {a}.\n#t = #s."),
    ("sparc", "sort_expression", "sorts\n#s = {a} + {b} - {c}."),
    ("sparc", "sort_term", "sorts\n#s = {a, b} * {b}."),
    ("sparc", "sort_primary", "sorts\n#s = ({a} + {b}) * #t."),
    ("sparc", "sort_set", "sorts\n#s = {a, f(b), 1}.\n#e = {}."),
    ("sparc", "sort_range", "#const n = 3.\nsorts\n#s = 0..n."),
    ("sparc", "range_end", "sorts\n#s = -1..(2 + 3)."),
    ("sparc", "concatenation", "sorts\n#s = [book][1..3]."),
    ("sparc", "concat_part", "sorts\n#s = [a, b][#t][0..2]."),
    (
        "sparc",
        "record_sort",
        "sorts\n#s = {a}.\n#r = pick(#s(X), #s(Y)) : X != Y.\n#q = {b} + f(#s(X)) : X = a + {c}.",
    ),
    (
        "sparc",
        "record_condition",
        "sorts\n#s = 1..2.\n#r = f(#s(X), #s(Y)) : X < Y or X = 2.",
    ),
    (
        "sparc",
        "record_conjunction",
        "sorts\n#s = 1..2.\n#r = f(#s(X), #s(Y)) : X <= Y and Y > 1, X != 0.",
    ),
    (
        "sparc",
        "record_comparison",
        "sorts\n#s = 1..2.\n#r = f(#s(X), #s(Y)) : not(X = Y) and (X > Y or Y = 2).",
    ),
    (
        "sparc",
        "record_operand",
        "sorts\n#s = 1..2.\n#r = f(#s(X)) : X != -1 and X < c.",
    ),
    ("sparc", "maxint", "#const n = 9.\n#maxint = n + 1.\nsorts\n#s = 1..2."),
    (
        "sparc",
        "record_argument",
        "sorts\n#s = {a}.\n#r = pair(#s, {b} + #s).",
    ),
    (
        "sparc",
        "predicate_declaration",
        "sorts\n#s = {a}.\npredicates\np(#s, #s).\nq().",
    ),
    (
        "sparc",
        "sort_atom",
        "sorts\n#s = {a}.\nrules\np(X) :- #s(X).",
    ),
    (
        "sparc",
        "display_item",
        "sorts\n#s = {a}.\ndisplay\np.\n-q(X).\n#s(X).\n#s.",
    ),
];

/// The production names defined in a grammar file (`name ::=` at the start of a line).
fn productions(file: &str) -> BTreeSet<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("grammar")
        .join(format!("{file}.ebnf"));
    let text = std::fs::read_to_string(&path).expect("grammar file");
    text.lines()
        .filter_map(|line| {
            let (name, _) = line.split_once("::=")?;
            let name = name.trim();
            let valid = !name.is_empty()
                && !line.starts_with(char::is_whitespace)
                && name.chars().all(|c| c.is_ascii_lowercase() || c == '_');
            valid.then(|| name.to_string())
        })
        .collect()
}

#[test]
fn every_production_has_an_example() {
    for file in ["asp", "sparc"] {
        let defined = productions(file);
        assert!(defined.len() > 10, "{file}.ebnf lost its productions");
        let covered: BTreeSet<String> = EXAMPLES
            .iter()
            .filter(|(f, _, _)| *f == file)
            .map(|(_, p, _)| p.to_string())
            .collect();
        let missing: Vec<_> = defined.difference(&covered).collect();
        assert!(
            missing.is_empty(),
            "{file}.ebnf productions without an example: {missing:?}"
        );
        let stale: Vec<_> = covered.difference(&defined).collect();
        assert!(
            stale.is_empty(),
            "examples for no production of {file}.ebnf: {stale:?}"
        );
    }
}

#[test]
fn every_example_parses() {
    for (file, production, text) in EXAMPLES {
        let dialect = if *file == "sparc" {
            Dialect::Sparc
        } else {
            Dialect::Clingo
        };
        let parsed = parse(FileId(0), text, dialect);
        let errors: Vec<_> = parsed
            .diagnostics
            .iter()
            .filter(|d| d.is_error() && d.message != UNSUPPORTED_SCRIPT)
            .collect();
        assert!(
            errors.is_empty(),
            "{file}:{production}: {text:?}: {errors:?}"
        );
        assert!(
            parsed
                .program
                .statements
                .iter()
                .all(|s| s.kind != StatementKind::Error),
            "{file}:{production}"
        );
        check_round_trip(text, dialect).unwrap_or_else(|e| panic!("{file}:{production}: {e}"));
    }
}
