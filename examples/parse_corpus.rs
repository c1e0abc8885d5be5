//! Runs the parser checks over every `.lp` and `.sp` file under a directory: the file must parse
//! without errors (or with only the single "unsupported script" diagnostic), the parse
//! invariants must hold, and printing must round-trip.
//!
//! Usage: `cargo run --no-default-features --example parse_corpus -- DIR...`. Exits with 1 when
//! a file fails; prints one line per failure and a summary.

use std::path::{Path, PathBuf};

use lucent::base::{FileId, SourceMap};
use lucent::syntax::fuzzing::{check_parse_invariants, check_round_trip};
use lucent::syntax::{decode_source, detect_dialect, parse, UNSUPPORTED_SCRIPT};

/// Collects the `.lp` and `.sp` files under `dir`, sorted.
fn collect(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            collect(&path, out);
        } else if matches!(
            path.extension().and_then(|e| e.to_str()),
            Some("lp") | Some("sp")
        ) {
            out.push(path);
        }
    }
}

fn main() {
    let dirs: Vec<String> = std::env::args().skip(1).collect();
    if dirs.is_empty() {
        eprintln!("usage: parse_corpus DIR...");
        std::process::exit(128);
    }
    let mut files = Vec::new();
    for d in &dirs {
        collect(Path::new(d), &mut files);
    }
    files.sort();
    let (mut clean, mut scripts, mut failed) = (0usize, 0usize, 0usize);
    for path in &files {
        let bytes = match std::fs::read(path) {
            Ok(b) => b,
            Err(e) => {
                println!("FAIL {}: {e}", path.display());
                failed += 1;
                continue;
            }
        };
        let (text, decode_error) = decode_source(FileId(0), &bytes);
        let dialect = if path.extension().and_then(|e| e.to_str()) == Some("sp") {
            lucent::syntax::ast::Dialect::Sparc
        } else {
            detect_dialect(&text)
        };
        let parsed = parse(FileId(0), &text, dialect);
        let errors: Vec<_> = decode_error
            .iter()
            .chain(parsed.diagnostics.iter())
            .filter(|d| d.is_error())
            .collect();
        let script_only =
            !errors.is_empty() && errors.iter().all(|d| d.message == UNSUPPORTED_SCRIPT);
        let mut problems = Vec::new();
        if !(errors.is_empty() || (script_only && errors.len() == 1)) {
            let mut map = SourceMap::new();
            map.add(path.display().to_string(), text.clone());
            let rendered: String = errors.iter().map(|d| d.render(&map)).collect();
            problems.push(format!("diagnostics:\n{rendered}"));
        }
        if let Err(e) = check_parse_invariants(&text) {
            problems.push(format!("invariants: {e}"));
        }
        if let Err(e) = check_round_trip(&text, dialect) {
            problems.push(format!("round trip: {e}"));
        }
        if problems.is_empty() {
            if script_only {
                scripts += 1;
            } else {
                clean += 1;
            }
        } else {
            failed += 1;
            println!("FAIL {}: {}", path.display(), problems.join("\n"));
        }
    }
    println!(
        "{} files: {clean} parsed cleanly, {scripts} with the single unsupported-script \
         diagnostic, {failed} failed",
        files.len()
    );
    if failed > 0 {
        std::process::exit(1);
    }
}
