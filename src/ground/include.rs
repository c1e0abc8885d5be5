//! `#include` resolution: replaces each `#include "file".` by the statements of that file,
//! recursively, before grounding.
//!
//! Rules (as gringo): a path is resolved relative to the directory of the including file; a
//! file already read (a top-level input or an earlier include) is skipped with an
//! `already included file` warning (`-W no-file-included` switches it off), so include cycles
//! end; `#include <name>.` (a library) is reported as unsupported.
//!
//! Invariant: this module reads nothing itself; the caller passes a loader (only `cli` and tests
//! touch files), and every file read is added to the [`SourceMap`] so spans stay valid.

use std::path::{Component, Path, PathBuf};

use hashbrown::HashSet;

use crate::base::{Diagnostic, Diagnostics, SourceMap, WarningKind};
use crate::syntax::ast::{self, StatementKind};
use crate::syntax::parse;

/// `a/./b/../c` as `a/c`, without touching the file system.
fn normalize(p: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            c => out.push(c),
        }
    }
    out
}

/// Expands the includes of `program`; `load` reads a file's text.
pub fn resolve_includes(
    program: &ast::Program,
    sources: &mut SourceMap,
    diags: &mut Diagnostics,
    load: &mut dyn FnMut(&Path) -> Result<String, String>,
) -> ast::Program {
    let mut seen: HashSet<PathBuf> = (0..sources.len())
        .map(|i| normalize(Path::new(&sources.get(crate::base::FileId(i as u32)).name)))
        .collect();
    let mut statements = Vec::new();
    expand(
        &program.statements,
        program.dialect,
        sources,
        diags,
        load,
        &mut seen,
        &mut statements,
    );
    ast::Program {
        dialect: program.dialect,
        statements,
    }
}

fn expand(
    input: &[ast::Statement],
    dialect: ast::Dialect,
    sources: &mut SourceMap,
    diags: &mut Diagnostics,
    load: &mut dyn FnMut(&Path) -> Result<String, String>,
    seen: &mut HashSet<PathBuf>,
    out: &mut Vec<ast::Statement>,
) {
    for st in input {
        let StatementKind::Include(inc) = &st.kind else {
            out.push(st.clone());
            continue;
        };
        if inc.system {
            diags.push(Diagnostic::error(
                st.span,
                format!("unsupported: library include <{}>", inc.path),
            ));
            continue;
        }
        let including = Path::new(&sources.get(st.span.file).name);
        let dir = including.parent().unwrap_or(Path::new(""));
        let path = normalize(&dir.join(&inc.path));
        if !seen.insert(path.clone()) {
            diags.push(
                Diagnostic::warning(WarningKind::FileIncluded, st.span, "already included file")
                    .with_snippet(inc.path.clone()),
            );
            continue;
        }
        let text = match load(&path) {
            Ok(t) => t,
            Err(e) => {
                diags.push(
                    Diagnostic::error(st.span, format!("file could not be opened: {e}"))
                        .with_snippet(inc.path.clone()),
                );
                continue;
            }
        };
        let id = sources.add(path.display().to_string(), text.clone());
        let parsed = parse(id, &text, dialect);
        diags.extend(parsed.diagnostics);
        expand(
            &parsed.program.statements,
            dialect,
            sources,
            diags,
            load,
            seen,
            out,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::ast::Dialect;

    #[test]
    fn includes_are_relative_and_read_once() {
        let files = [
            ("a.lp", "#include \"sub/b.lp\".\n#include \"sub/b.lp\".\na."),
            ("sub/b.lp", "#include \"c.lp\".\nb."),
            ("sub/c.lp", "c.\n#include \"c.lp\"."),
        ];
        let mut sources = SourceMap::new();
        let id = sources.add("a.lp", files[0].1);
        let program = parse(id, files[0].1, Dialect::Clingo).program;
        let mut diags = Diagnostics::default();
        let mut load = |p: &Path| -> Result<String, String> {
            files
                .iter()
                .find(|(n, _)| Path::new(n) == p)
                .map(|(_, t)| t.to_string())
                .ok_or_else(|| format!("no file {}", p.display()))
        };
        let out = resolve_includes(&program, &mut sources, &mut diags, &mut load);
        assert_eq!(out.statements.len(), 3, "c, b, a");
        let warnings: Vec<&str> = diags.items().iter().map(|d| d.message.as_str()).collect();
        assert_eq!(
            warnings,
            vec!["already included file", "already included file"]
        );
        assert!(!diags.has_errors());
    }
}
