//! The body of the `action` fuzz target (`lucent::action::fuzzing::check_action_invariants`) on
//! the seed corpus, so the target cannot rot: the AL_d files of `domains/ra` and
//! `tests/data/action`, each also cut short at every line break and at every byte of its first
//! 300, plus inputs that once broke the parser's invariants.

use std::path::{Path, PathBuf};

use lucent::action::fuzzing::check_action_invariants;

fn ald_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            ald_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "ald") {
            out.push(p);
        }
    }
}

#[test]
fn seed_corpus_keeps_the_invariants() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    ald_files(&root.join("domains/ra"), &mut files);
    ald_files(&root.join("tests/data/action"), &mut files);
    files.sort();
    assert!(files.len() > 20, "{}", files.len());
    for path in files {
        let bytes = std::fs::read(&path).unwrap();
        check_action_invariants(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let cuts = bytes
            .iter()
            .enumerate()
            .filter(|(_, &b)| b == b'\n')
            .map(|(i, _)| i)
            .chain(0..bytes.len().min(300));
        for i in cuts {
            check_action_invariants(&bytes[..i])
                .unwrap_or_else(|e| panic!("{} cut at {i}: {e}", path.display()));
        }
    }
}

#[test]
fn hostile_inputs() {
    let deep = format!("a({}.", "(".repeat(10_000));
    let minus = format!("a({}1).", "-".repeat(10_000));
    for input in [
        &b""[..],
        b".",
        b"...",
        b"[",
        b"[not",
        b"C1:",
        b"C1: C2: a.",
        b"sort s = 1..2000000.",
        b"sort s = {a}. sort s = {b}.",
        b"sort s = s.",
        b"exception to : a may be assumed.",
        b"profile p: drop X. profile p: drop Y.",
        b"include \"\xff\".",
        b"a(\xff).",
        deep.as_bytes(),
        minus.as_bytes(),
        b"sort s = {a}. inertial fluent f(s). goal f(X), X > 1.",
        b"sort s = {a}. static p(s). p(X) if p(X + 1).",
        b"switch horizon = off.",
        b"set horizon = x.",
    ] {
        check_action_invariants(input)
            .unwrap_or_else(|e| panic!("{:?}: {e}", String::from_utf8_lossy(input)));
    }
}

/// Words and punctuation of AL_d, for random token soups that reach deep into the checker.
const TOKENS: &[&str] = &[
    "sort",
    "static",
    "inertial",
    "defined",
    "fluent",
    "action",
    "causes",
    "if",
    "impossible",
    "normally",
    "exception",
    "to",
    "may",
    "be",
    "assumed",
    "never",
    "goal",
    "observed",
    "happened",
    "at",
    "initially",
    "false",
    "except",
    "switch",
    "set",
    "profile",
    "drop",
    "no",
    "without",
    "cwa",
    "include",
    "s",
    "t",
    "f",
    "g",
    "a",
    "b",
    "p",
    "X",
    "Y",
    "N",
    "C1",
    "D1",
    "1",
    "0",
    "-1",
    "3",
    ".",
    ".",
    ".",
    ",",
    ",",
    ":",
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    "=",
    "!=",
    "<",
    ">",
    "+",
    "-",
    "*",
    "..",
    "not",
    "\"x.ald\"",
];

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(500))]

    #[test]
    fn random_token_soups_keep_the_invariants(
        picks in proptest::collection::vec(0..TOKENS.len(), 0..60),
        prefix in 0usize..4,
    ) {
        // A valid prefix declares names, so later tokens are checked, not only parsed.
        let header = [
            "",
            "sort s = {a, b}. inertial fluent f(s). action g(s). ",
            "sort s = {a, b} + 1..3. sort t = s + {c}. defined fluent f(s) without cwa. \
             static p(t). action g(s, t). D1: normally -f(X) if p(X). ",
            "switch x = false. profile q: x, drop D1. [x] D1: normally -f(a). \
             sort s = {a}. defined fluent f(s). ",
        ][prefix];
        let body: Vec<&str> = picks.iter().map(|&i| TOKENS[i]).collect();
        let text = format!("{header}{}", body.join(" "));
        check_action_invariants(text.as_bytes()).map_err(proptest::test_runner::TestCaseError::fail)?;
    }
}

/// Builds a random, mostly well-typed statement from choices: fluents `f/1`, `g/2` (inertial)
/// and `h/1` (defined), statics `p/1`, `q/2`, the sort `s/1`, actions `go/1`, `mv/2`; now and
/// then a wrong argument, so checking errors come up too.
fn statement(c: &[usize], index: usize) -> String {
    let at = |k: usize| c[k % c.len()];
    // One argument in twenty is out of its sort or unsorted.
    let arg = |k: usize| match at(k) % 40 {
        0 => "c",
        1 => "N + 1",
        n => ["X", "Y", "a", "b"][n % 4],
    };
    let atom = |k: usize, names: &[&str]| {
        let n = names[at(k) % names.len()];
        match n {
            "g" | "q" | "mv" => format!("{n}({}, {})", arg(k + 1), arg(k + 2)),
            _ => format!("{n}({})", arg(k + 1)),
        }
    };
    let fluent = |k: usize| format!("{}{}", ["", "-"][at(k) % 2], atom(k + 1, &["f", "g", "h"]));
    let any = |k: usize| {
        format!(
            "{}{}",
            ["", "-"][at(k) % 2],
            atom(k + 1, &["f", "g", "h", "p", "q", "s"])
        )
    };
    let action = |k: usize| atom(k, &["go", "mv"]);
    let cond = |k: usize| match at(k) % 4 {
        0 => format!(" if {}", any(k + 1)),
        1 => format!(" if {}, {} != {}", any(k + 1), arg(k + 5), arg(k + 6)),
        2 => format!(" if {}, {}", fluent(k + 1), any(k + 5)),
        _ => String::new(),
    };
    let label = if at(9) % 2 == 0 {
        format!("L{index}: ")
    } else {
        String::new()
    };
    let ground = |k: usize, names: &[&str]| {
        let n = names[at(k) % names.len()];
        let x = ["a", "b"][at(k + 1) % 2];
        match n {
            "g" | "mv" => format!("{n}({x}, b)"),
            _ => format!("{n}({x})"),
        }
    };
    match at(0) % 11 {
        0 => format!("{label}{} causes {}{}.", action(1), fluent(3), cond(6)),
        1 => format!("{label}{}{}.", fluent(1), cond(4)),
        2 => format!("{}{}.", atom(1, &["p", "q"]), cond(4)),
        3 => format!("{label}impossible {}{}.", action(1), cond(4)),
        4 => format!("{label}normally {}{}.", fluent(1), cond(4)),
        5 => {
            let f = atom(1, &["f", "g", "h"]);
            format!(
                "D{index}: normally -{f}. exception to D{index}: {f} may be assumed{}.",
                cond(4)
            )
        }
        6 => format!("never {}{}.", fluent(1), cond(4)),
        7 => format!("goal {}.", fluent(1)),
        8 => format!(
            "observed {} at {}.",
            ground(1, &["f", "g", "h"]),
            ["0", "1", "X"][at(4) % 20 / 9]
        ),
        9 => format!("happened {} at 0.", ground(1, &["go", "mv"])),
        _ => format!("initially {}.", ground(1, &["f", "g", "h"])),
    }
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(300))]

    #[test]
    fn random_descriptions_keep_the_invariants(
        choices in proptest::collection::vec(proptest::collection::vec(0usize..1000, 10), 0..12),
    ) {
        let mut text = String::from(
            "sort s = {a, b}. inertial fluent f(s). inertial fluent g(s, s). \
             defined fluent h(s). static p(s). static q(s, s). action go(s). action mv(s, s). \
             initially normally false. ",
        );
        for (index, c) in choices.iter().enumerate() {
            text.push_str(&statement(c, index));
            text.push('\n');
        }
        check_action_invariants(text.as_bytes())
            .map_err(proptest::test_runner::TestCaseError::fail)?;
        // Sorted variables make every rule safe: an error-free translation grounds without
        // errors.
        let parsed = lucent::action::parse(lucent::base::FileId(0), &text);
        let options = lucent::action::Options {
            profile: None,
            switches: lucent::action::Switches {
                horizon: Some(2),
                ..Default::default()
            },
            ..Default::default()
        };
        let t = lucent::action::translate(&parsed.description, &options);
        if !parsed.has_errors() && !t.has_errors() {
            let config = lucent::ground::GroundConfig {
                max_size: Some(100_000),
                ..Default::default()
            };
            let g = lucent::ground::ground(&t.program, None, &config);
            let errors: Vec<_> = g.diagnostics.items().iter().filter(|d| d.is_error()).collect();
            proptest::prop_assert!(errors.is_empty(), "{text}\n{errors:?}");
        }
    }
}
