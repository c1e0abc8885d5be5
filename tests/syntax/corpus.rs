//! Data-driven parser tests: the project's own programs in `tests/data/parse/` must parse
//! without errors and round-trip through the printer; every file in `tests/data/malformed/`
//! (named after its error) has its rendered diagnostics snapshotted; both sets go through the
//! fuzz targets' checks, so the fuzz bodies are exercised on every test run.

use std::path::{Path, PathBuf};

use lucent::base::{FileId, SourceMap};
use lucent::syntax::ast::{Dialect, StatementKind};
use lucent::syntax::fuzzing::{
    check_parse_invariants, check_parse_invariants_bytes, check_round_trip, check_round_trip_bytes,
};
use lucent::syntax::{decode_source, detect_dialect, parse, parse_auto, UNSUPPORTED_SCRIPT};

/// The files of a data directory, sorted.
fn files(dir: &str) -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(dir);
    let mut out: Vec<PathBuf> = std::fs::read_dir(&root)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", root.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.is_file())
        .collect();
    out.sort();
    out
}

/// The dialect a file is read in: `.sp` is SPARC, anything else is detected.
fn dialect_of(path: &Path, text: &str) -> Dialect {
    if path.extension().and_then(|e| e.to_str()) == Some("sp") {
        Dialect::Sparc
    } else {
        detect_dialect(text)
    }
}

/// The file name, for snapshot names and messages.
fn name(path: &Path) -> String {
    path.file_name()
        .expect("file name")
        .to_string_lossy()
        .into_owned()
}

#[test]
fn own_programs_parse_and_round_trip() {
    let paths = files("parse");
    assert!(paths.len() >= 8, "the corpus lost files");
    for path in paths {
        let text = std::fs::read_to_string(&path).expect("UTF-8 program");
        let dialect = dialect_of(&path, &text);
        let parsed = parse(FileId(0), &text, dialect);
        let errors: Vec<_> = parsed.diagnostics.iter().filter(|d| d.is_error()).collect();
        if name(&path) == "scripts.lp" {
            assert_eq!(errors.len(), 1, "{}: {errors:?}", path.display());
            assert_eq!(errors[0].message, UNSUPPORTED_SCRIPT);
        } else {
            assert!(errors.is_empty(), "{}: {errors:?}", path.display());
        }
        assert!(parsed
            .program
            .statements
            .iter()
            .all(|s| s.kind != StatementKind::Error));
        check_parse_invariants(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        check_round_trip(&text, dialect).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        check_round_trip_bytes(text.as_bytes())
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    }
}

#[test]
fn sparc_is_detected() {
    for path in files("parse") {
        let text = std::fs::read_to_string(&path).expect("UTF-8 program");
        let expected = if name(&path).ends_with(".sp") {
            Dialect::Sparc
        } else {
            Dialect::Clingo
        };
        assert_eq!(parse_auto(FileId(0), &text).program.dialect, expected);
    }
}

#[test]
fn malformed_inputs_snapshot() {
    for path in files("malformed") {
        let bytes = std::fs::read(&path).expect("readable file");
        check_parse_invariants_bytes(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        check_round_trip_bytes(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let file_name = name(&path);
        let mut map = SourceMap::new();
        let (text, decode_error) = decode_source(FileId(0), &bytes);
        let file = map.add(file_name.clone(), text.clone());
        let dialect = dialect_of(&path, &text);
        let parsed = parse(file, &text, dialect);
        let mut rendered = String::new();
        for d in decode_error.iter().chain(parsed.diagnostics.iter()) {
            rendered.push_str(&d.render(&map));
        }
        if file_name == "empty.lp" {
            assert!(rendered.is_empty());
            assert!(parsed.program.statements.is_empty());
        } else {
            assert!(
                parsed.diagnostics.iter().any(|d| d.is_error()) || decode_error.is_some(),
                "{file_name} gives no error"
            );
        }
        let stem = file_name.replace('.', "_");
        insta::assert_snapshot!(stem, rendered);
    }
}

#[test]
fn recovery_keeps_statements_after_errors() {
    let text = "a b.\nok.\np(.\nalso(1).\n";
    let parsed = parse(FileId(0), text, Dialect::Clingo);
    let kinds: Vec<bool> = parsed
        .program
        .statements
        .iter()
        .map(|s| s.kind == StatementKind::Error)
        .collect();
    assert_eq!(kinds, vec![true, false, true, false]);
    assert_eq!(parsed.diagnostics.len(), 2);
}

#[test]
fn fifty_megabytes_on_one_line() {
    // One line of 50 MB: facts, a long identifier, a long string, a long comment, and an
    // error at the very end, so locations far into a line are computed.
    let mut text = String::with_capacity(50 << 20);
    for i in 0..100_000 {
        text.push_str(&format!("p({i},{}). ", i + 1));
    }
    text.push_str("q(a");
    text.push_str(&"b".repeat(12 << 20));
    text.push_str(", \"");
    text.push_str(&"s".repeat(12 << 20));
    text.push_str("\"). %* ");
    while text.len() < 50 << 20 {
        text.push_str("comment text ");
    }
    text.push_str("*% r s.");
    assert!(!text.contains('\n'));
    assert!(text.len() >= 50 << 20);
    let mut map = SourceMap::new();
    let file = map.add("big.lp", text.clone());
    let parsed = parse(file, &text, Dialect::Clingo);
    assert_eq!(parsed.program.statements.len(), 100_002);
    assert_eq!(parsed.diagnostics.len(), 1);
    let rendered = parsed.diagnostics[0].render(&map);
    assert!(
        rendered.starts_with("big.lp:1:") && rendered.contains("unexpected <IDENTIFIER>"),
        "{rendered}"
    );
}

#[test]
fn deep_nesting_is_capped_not_overflowing() {
    for depth in [400usize, 100_000] {
        let text = format!(
            "p({}1{}).\nq({}1).\n",
            "(".repeat(depth),
            ")".repeat(depth),
            "-".repeat(depth)
        );
        let parsed = parse(FileId(0), &text, Dialect::Clingo);
        let deep = depth > lucent::syntax::MAX_DEPTH as usize;
        assert_eq!(
            parsed.diagnostics.len(),
            if deep { 2 } else { 0 },
            "{depth}"
        );
        check_parse_invariants(&text).expect("invariants");
    }
    let long_sum = format!("p({}1).", "1+".repeat(100_000));
    assert_eq!(
        parse(FileId(0), &long_sum, Dialect::Clingo)
            .diagnostics
            .len(),
        1
    );
}

#[test]
fn non_utf8_input_gets_one_diagnostic() {
    let bytes = b"p(1). q(\xff\xfe). r.";
    let (text, diag) = decode_source(FileId(0), bytes);
    let diag = diag.expect("a diagnostic");
    assert_eq!(diag.span.start, 8);
    assert!(text.is_char_boundary(diag.span.end as usize));
    check_parse_invariants(&text).expect("invariants");
}
