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
