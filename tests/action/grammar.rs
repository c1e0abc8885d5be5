//! Keeps `grammar/action.ebnf` in step with the AL_d parser: every production has an example
//! below, every example names a production, and every example parses without errors (and
//! yields no error statement). Adding a production without an example fails this test.

use std::collections::BTreeSet;
use std::path::Path;

use lucent::action::ast::StatementKind;
use lucent::action::parse;
use lucent::base::FileId;

/// `(production, example)`; each example is a whole `.ald` text.
const EXAMPLES: &[(&str, &str)] = &[
    ("description", "sort s = {a}. static p(s)."),
    ("statement", "[on] [not off] L1: p(a) if q(a)."),
    ("guard", "[strict] [not sticky] a."),
    ("label", "C1: a. e7: b."),
    ("statement_body", "sort s = {a}. never f. goal f."),
    (
        "sort_definition",
        "sort location = object + {table} + 1..3.",
    ),
    ("sort_part", "sort s = {a, 1} + 0..6 + t + {}."),
    ("member", "sort s = {a, -1, 2}."),
    ("integer", "sort s = -2..0x0f."),
    (
        "declaration",
        "static p(s). inertial fluent f(s, t). defined fluent g(s) without cwa. action a(s).",
    ),
    ("signature", "static p. static q(). static r(s, t)."),
    (
        "causal_law",
        "C1: putdown(R, A, L) causes relation(on, A, L) if A != L.",
    ),
    (
        "state_constraint",
        "-relation(S, A, A). on(A, B) if above(A, B), touch(A, B).",
    ),
    (
        "executability_condition",
        "impossible pickup(R, A) if in_hand(R, B).",
    ),
    ("default", "D1: normally -stable(A) if small_base(A)."),
    (
        "exception",
        "exception to D1: stable(A) may be assumed if small_base(A).",
    ),
    ("never_constraint", "never -stable(A). never f(A) if g(A)."),
    ("goal", "goal relation(on, X, can), X != table."),
    ("observation", "observed -in_hand(rob1, a) at 2."),
    ("happened", "happened pickup(rob1, a) at 0."),
    ("initial_literal", "initially relation(on, a, table)."),
    (
        "initial_default",
        "initially normally false. initially normally false except p, q.",
    ),
    (
        "switch",
        "switch strict = false. switch mode = fixed. switch n = 3.",
    ),
    ("setting", "set horizon = 4."),
    (
        "profile",
        "profile tabletop: sticky, horizon = 4, drop SR5.",
    ),
    (
        "profile_item",
        "profile p: drop E8, no strict, planning = off, sticky.",
    ),
    (
        "value",
        "set a = 3. set b = -1. set c = creation_only. set d = on.",
    ),
    ("include", "include \"../kb_full.ald\"."),
    ("conditions", "p(X) if q(X), X > 1, r(X) = 2."),
    ("condition", "p(X) if q(X), -r(X), X + 1 <= 3."),
    (
        "comparison_op",
        "a if 1 = 1, 1 == 1, 1 != 2, 1 <> 2, 1 < 2, 1 <= 2, 2 > 1, 2 >= 1.",
    ),
    ("literal", "-p(a) if q, -r."),
    ("atom", "p. q(). r(a, X, 1)."),
    ("term", "p(N + 1 - M) if q(N, M)."),
    ("product", "p(N * 2 / 3 \\ 4) if q(N)."),
    ("factor", "p(-N, 3, X, f(a, b), (N + 1)) if q(N, X)."),
];

/// The production names defined in the grammar (`name ::=` at the start of a line).
fn productions() -> BTreeSet<String> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("grammar/action.ebnf");
    let text = std::fs::read_to_string(path).expect("grammar file");
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
    let defined = productions();
    assert!(defined.len() > 20, "action.ebnf lost its productions");
    let covered: BTreeSet<String> = EXAMPLES.iter().map(|(p, _)| p.to_string()).collect();
    let missing: Vec<_> = defined.difference(&covered).collect();
    assert!(
        missing.is_empty(),
        "productions without an example: {missing:?}"
    );
    let stale: Vec<_> = covered.difference(&defined).collect();
    assert!(stale.is_empty(), "examples for no production: {stale:?}");
}

#[test]
fn every_example_parses() {
    for (production, text) in EXAMPLES {
        let parsed = parse(FileId(0), text);
        assert!(
            !parsed.has_errors(),
            "{production}: {text:?}: {:?}",
            parsed.diagnostics
        );
        assert!(
            parsed
                .description
                .statements
                .iter()
                .all(|s| s.kind != StatementKind::Error),
            "{production}"
        );
    }
}

#[test]
fn non_examples_are_rejected() {
    for text in [
        "sort = {a}.",
        "a causes.",
        "-a causes b.",
        "impossible -a.",
        "exception D1: a may be assumed.",
        "observed a.",
        "goal.",
        "[x y] a.",
        "p(a",
        "a if.",
    ] {
        let parsed = parse(FileId(0), text);
        assert!(parsed.has_errors(), "{text:?} was accepted");
    }
}
