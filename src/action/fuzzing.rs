//! The body of the AL_d fuzz target (`fuzz/fuzz_targets/action.rs`), also run by
//! tests/action/fuzz_corpus.rs on a seed corpus so it cannot rot.
//!
//! Invariants checked: parsing arbitrary bytes terminates without panicking; every span of the
//! diagnostics lies inside the text on character boundaries and renders; checking and
//! translating the parse (under no profile and under every profile it declares) never panics,
//! and when they report no error the printed program parses as the clingo dialect without
//! errors.

use crate::base::{FileId, SourceMap, Span};
use crate::syntax::ast::Dialect;

use super::{parse, translate, Options};

fn check_span(text: &str, span: Span) -> Result<(), String> {
    let (s, e) = (span.start as usize, span.end as usize);
    if s > e || e > text.len() || !text.is_char_boundary(s) || !text.is_char_boundary(e) {
        return Err(format!(
            "span {s}..{e} invalid for a text of {} bytes",
            text.len()
        ));
    }
    Ok(())
}

/// Checks the invariants above for one input.
pub fn check_action_invariants(bytes: &[u8]) -> Result<(), String> {
    let (text, _) = crate::syntax::decode_source(FileId(0), bytes);
    let parsed = parse(FileId(0), &text);
    let mut map = SourceMap::new();
    map.add("-", text.as_str());
    for d in &parsed.diagnostics {
        check_span(&text, d.span)?;
        let _ = d.render(&map);
    }
    let mut profiles = vec![None];
    for s in &parsed.description.statements {
        if let super::ast::StatementKind::Profile { name, .. } = &s.kind {
            profiles.push(Some(name.text.clone()));
        }
    }
    profiles.truncate(4);
    for profile in profiles {
        let options = Options {
            profile,
            switches: super::Switches {
                horizon: Some(2),
                ..Default::default()
            },
            ..Default::default()
        };
        let t = translate(&parsed.description, &options);
        for d in &t.diagnostics {
            check_span(&text, d.span)?;
            let _ = d.render(&map);
        }
        if t.program.statements.len() != t.origins.len() {
            return Err("origins are not parallel to the statements".into());
        }
        if !parsed.has_errors() && !t.has_errors() {
            let printed = crate::syntax::print(&t.program);
            let again = crate::syntax::parse(FileId(0), &printed, Dialect::Clingo);
            if again.has_errors() {
                return Err(format!(
                    "the translation does not parse: {:?}\n{printed}",
                    again.diagnostics
                ));
            }
        }
    }
    Ok(())
}
