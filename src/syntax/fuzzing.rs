//! Checks shared by the fuzz targets (`fuzz/fuzz_targets/*.rs`) and the corpus tests, so the
//! fuzz targets' bodies are exercised by ordinary tests and cannot rot.
//!
//! Invariants checked: parsing arbitrary bytes (after [`super::decode_source`]) terminates
//! without panicking in both dialects; every span of the tree and of the diagnostics lies in
//! the text and on character boundaries; diagnostics render; and for input that parses
//! without errors (other than the one "unsupported script" diagnostic),
//! `parse(print(tree))` has the same shape as `tree` and the same diagnostics.

use crate::base::{FileId, SourceMap, Span};

use super::ast::{Dialect, Program};
use super::parser::{parse, Parse, UNSUPPORTED_SCRIPT};
use super::printer::print;
use super::visit::for_each_span;

/// Checks that `span` lies in `text` on character boundaries.
fn check_span(text: &str, span: Span, what: &str) -> Result<(), String> {
    let (s, e) = (span.start as usize, span.end as usize);
    if s > e || e > text.len() {
        return Err(format!(
            "{what} span {s}..{e} outside the text of {} bytes",
            text.len()
        ));
    }
    if !text.is_char_boundary(s) || !text.is_char_boundary(e) {
        return Err(format!("{what} span {s}..{e} not on character boundaries"));
    }
    Ok(())
}

/// Checks the spans of a parse of `text`.
fn check_spans(text: &str, parsed: &Parse) -> Result<(), String> {
    let mut program = parsed.program.clone();
    let mut result = Ok(());
    for_each_span(&mut program, &mut |span| {
        if result.is_ok() {
            result = check_span(text, *span, "tree");
        }
    });
    result?;
    let mut map = SourceMap::new();
    map.add("-", text);
    for d in &parsed.diagnostics {
        check_span(text, d.span, "diagnostic")?;
        let _ = d.render(&map);
    }
    Ok(())
}

/// Parses `text` in both dialects and checks that spans are valid and diagnostics render.
pub fn check_parse_invariants(text: &str) -> Result<(), String> {
    for dialect in [Dialect::Clingo, Dialect::Sparc] {
        let parsed = parse(FileId(0), text, dialect);
        check_spans(text, &parsed).map_err(|e| format!("{dialect:?}: {e}"))?;
    }
    Ok(())
}

/// Same as [`check_parse_invariants`] for raw bytes, decoded as the command line decodes files.
pub fn check_parse_invariants_bytes(bytes: &[u8]) -> Result<(), String> {
    let (text, _) = super::decode_source(FileId(0), bytes);
    check_parse_invariants(&text)
}

/// True when every error of the parse is the unsupported-script diagnostic.
fn only_unsupported(parsed: &Parse) -> bool {
    parsed
        .diagnostics
        .iter()
        .all(|d| !d.is_error() || d.message == UNSUPPORTED_SCRIPT)
}

/// Checks `parse(print(parse(text)))` against `parse(text)` when `text` parses without
/// syntax errors; inputs with syntax errors pass trivially.
pub fn check_round_trip(text: &str, dialect: Dialect) -> Result<(), String> {
    let first = parse(FileId(0), text, dialect);
    if !only_unsupported(&first) {
        return Ok(());
    }
    let printed = print(&first.program);
    let second = parse(FileId(0), &printed, dialect);
    let messages = |p: &Parse| {
        p.diagnostics
            .iter()
            .map(|d| d.message.clone())
            .collect::<Vec<_>>()
    };
    if messages(&first) != messages(&second) {
        return Err(format!(
            "diagnostics differ after printing:\n{:?}\nprinted:\n{printed}",
            messages(&second)
        ));
    }
    if !first.program.same_shape(&second.program) {
        return Err(format!(
            "tree changed after printing; printed:\n{printed}\nreprinted:\n{}",
            print(&second.program)
        ));
    }
    Ok(())
}

/// Same as [`check_round_trip`] for raw bytes, in both dialects.
pub fn check_round_trip_bytes(bytes: &[u8]) -> Result<(), String> {
    let (text, _) = super::decode_source(FileId(0), bytes);
    check_round_trip(&text, Dialect::Clingo)?;
    check_round_trip(&text, Dialect::Sparc)
}

/// The program of a parse without its diagnostics, for callers that only need the tree.
pub fn tree(text: &str, dialect: Dialect) -> Program {
    parse(FileId(0), text, dialect).program
}
