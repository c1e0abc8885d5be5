//! AL_d: action-language system descriptions and histories (grammar/action.ebnf), translated to
//! CR-Prolog programs (docs/domain.md section 3).
//!
//! Pipeline: [`parse`] (text to [`ast::Description`], never fails), [`load`] (resolves
//! `include`s through a caller-supplied reader: only `cli` and tests touch files), [`fn@check`]
//! (switches, profile, signature, sorts of variables) and [`fn@translate`] (a syntax tree of the
//! clingo dialect, printed by [`crate::syntax::printer`], with one [`AxiomOrigin`] per generated
//! statement).
//!
//! Invariants: this module depends only on `base` and `syntax`; bad input is a positioned
//! diagnostic, never a panic; every generated statement has an origin naming its AL_d statement
//! (label, span, kind) or the translation schema it instantiates.

pub mod ast;
pub mod build;
pub(crate) mod check;
pub mod fuzzing;
pub(crate) mod parser;
pub(crate) mod parts;
pub(crate) mod switches;
pub mod translate;

pub use check::{check, Checked};
pub use parser::{parse, Parse};
pub use switches::{HorizonMode, Options, Switches};
pub use translate::{translate, AxiomOrigin, OriginKind, Translation};

use crate::base::{Diagnostic, FileId, SourceMap};

/// KB_full, the robot assistant's knowledge base (`domains/ra/kb_full.ald`), built in so that
/// the binary and the library work outside the checkout.
pub const KB_FULL: &str = include_str!("../../domains/ra/kb_full.ald");

/// How deep `include`s may nest.
pub const MAX_INCLUDE_DEPTH: usize = 16;

/// Parses the file `file` of `sources` and every file it includes (depth first, each once),
/// adding the included files to `sources`. `read(path)` returns a file's text or an error
/// message; include paths are relative to the including file's directory.
pub fn load(
    sources: &mut SourceMap,
    file: FileId,
    read: &mut dyn FnMut(&std::path::Path) -> Result<String, String>,
) -> Parse {
    let mut out = Parse::default();
    let mut seen = std::collections::BTreeSet::new();
    seen.insert(std::path::PathBuf::from(&sources.get(file).name));
    load_into(sources, file, read, &mut out, &mut seen, 0);
    out
}

fn load_into(
    sources: &mut SourceMap,
    file: FileId,
    read: &mut dyn FnMut(&std::path::Path) -> Result<String, String>,
    out: &mut Parse,
    seen: &mut std::collections::BTreeSet<std::path::PathBuf>,
    depth: usize,
) {
    let parsed = parse(file, &sources.get(file).text);
    out.diagnostics.extend(parsed.diagnostics);
    let name = sources.get(file).name.clone();
    let dir = std::path::Path::new(&name)
        .parent()
        .map(std::path::Path::to_path_buf)
        .unwrap_or_default();
    for st in parsed.description.statements {
        if let ast::StatementKind::Include { path } = &st.kind {
            let full = dir.join(path);
            if !seen.insert(full.clone()) {
                continue;
            }
            if depth >= MAX_INCLUDE_DEPTH {
                out.diagnostics.push(Diagnostic::error(
                    st.span,
                    format!("includes nested deeper than {MAX_INCLUDE_DEPTH} levels"),
                ));
                continue;
            }
            match read(&full) {
                Ok(text) => {
                    let included = sources.add(full.to_string_lossy().into_owned(), text);
                    load_into(sources, included, read, out, seen, depth + 1);
                }
                Err(e) => out.diagnostics.push(
                    Diagnostic::error(st.span, "file could not be opened")
                        .with_note(None, format!("{}: {e}", full.display())),
                ),
            }
        }
        out.description.statements.push(st);
    }
}
