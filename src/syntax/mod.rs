//! Syntax: text to syntax tree (lexer, parser), and syntax tree back to text (printer).
//!
//! Invariant: parsing never fails; it returns the tree and every diagnostic, recovering at the
//! next rule. The syntax layer knows nothing about grounding.
//!
//! Input that is not UTF-8 goes through [`decode_source`] first: invalid bytes become U+FFFD
//! (lossy conversion) and one error points at the first of them; spans then refer to the
//! converted text, which is what the [`crate::base::SourceMap`] should hold.

pub mod ast;
pub mod build;
pub mod fuzzing;
pub mod lexer;
pub(crate) mod name;
pub(crate) mod parser;
pub mod printer;
pub mod theory;
pub(crate) mod visit;

pub use parser::{detect_dialect, parse, parse_auto, Parse, MAX_DEPTH, UNSUPPORTED_SCRIPT};
pub use printer::print;
pub use visit::erase_spans;

use crate::base::{Diagnostic, FileId, Span};

/// Turns raw file contents into text for the parser. Valid UTF-8 is taken as is; otherwise
/// invalid sequences become U+FFFD and one error is reported at the first of them.
pub fn decode_source(file: FileId, bytes: &[u8]) -> (String, Option<Diagnostic>) {
    match std::str::from_utf8(bytes) {
        Ok(text) => (text.to_string(), None),
        Err(err) => {
            let at = err.valid_up_to();
            let text = String::from_utf8_lossy(bytes).into_owned();
            let end = (at + '\u{fffd}'.len_utf8()).min(text.len());
            let span = Span::new(file, at as u32, end as u32);
            let diag = Diagnostic::error(
                span,
                format!(
                    "input is not valid UTF-8 (first invalid byte at offset {at}); \
                     invalid bytes were replaced by U+FFFD"
                ),
            );
            (text, Some(diag))
        }
    }
}
