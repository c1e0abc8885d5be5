//! `#include` resolution: reading included files is I/O, so it happens here, before grounding.
//!
//! Invariants: every `#include "file".` statement is replaced by the statements of the file it
//! names (parsed in the including file's dialect unless the extension says `.sp`), in place, so
//! the grounder never sees an include; a file is read at most once per run (the inputs named on
//! the command line count as read), later includes of it give gringo's `already included file`
//! warning; unreadable files are errors at the include's position; nesting is bounded, so
//! include cycles terminate (they are caught by the once-only rule anyway).

use std::path::{Path, PathBuf};

use crate::base::{Diagnostic, Diagnostics, FileId, SourceMap, WarningKind};
use crate::syntax::ast::{Dialect, Program, Statement, StatementKind};

/// Deepest include nesting followed.
const MAX_INCLUDE_DEPTH: usize = 100;

/// Tracks which files were read.
#[derive(Default)]
pub struct Includes {
    /// Canonical paths of files read so far.
    seen: Vec<PathBuf>,
}

impl Includes {
    /// Records an input given on the command line.
    pub fn mark_input(&mut self, name: &str) {
        if name != "-" {
            if let Ok(path) = std::fs::canonicalize(name) {
                self.seen.push(path);
            }
        }
    }

    /// Replaces the includes of `program` (parsed from `file`) by the included statements.
    pub fn resolve(
        &mut self,
        program: &mut Program,
        file: FileId,
        sources: &mut SourceMap,
        diags: &mut Diagnostics,
    ) {
        self.resolve_depth(program, file, sources, diags, 0);
    }

    fn resolve_depth(
        &mut self,
        program: &mut Program,
        file: FileId,
        sources: &mut SourceMap,
        diags: &mut Diagnostics,
        depth: usize,
    ) {
        if !program
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Include(_)))
        {
            return;
        }
        let base_dir = {
            let name = &sources.get(file).name;
            if name == "-" {
                PathBuf::from(".")
            } else {
                Path::new(name)
                    .parent()
                    .map(Path::to_path_buf)
                    .unwrap_or_else(|| PathBuf::from("."))
            }
        };
        let statements = std::mem::take(&mut program.statements);
        let mut out: Vec<Statement> = Vec::with_capacity(statements.len());
        for statement in statements {
            let include = match &statement.kind {
                StatementKind::Include(inc) => inc.clone(),
                _ => {
                    out.push(statement);
                    continue;
                }
            };
            let span = statement.span;
            if include.system {
                diags.push(
                    Diagnostic::error(
                        span,
                        "unsupported: system includes such as <incmode> (clingo's incremental mode) are not supported by lucent",
                    )
                    .with_snippet(format!("<{}>", include.path)),
                );
                continue;
            }
            if depth >= MAX_INCLUDE_DEPTH {
                diags.push(Diagnostic::error(span, "includes nested too deeply"));
                continue;
            }
            let relative = base_dir.join(&include.path);
            let path = if relative.exists() {
                relative
            } else {
                PathBuf::from(&include.path)
            };
            let canonical = match std::fs::canonicalize(&path) {
                Ok(c) => c,
                Err(_) => {
                    diags.push(
                        Diagnostic::error(span, "file could not be opened")
                            .with_snippet(include.path.clone()),
                    );
                    continue;
                }
            };
            if self.seen.contains(&canonical) {
                diags.push(
                    Diagnostic::warning(WarningKind::FileIncluded, span, "already included file")
                        .with_snippet(include.path.clone()),
                );
                continue;
            }
            self.seen.push(canonical);
            let bytes = match std::fs::read(&path) {
                Ok(b) => b,
                Err(_) => {
                    diags.push(
                        Diagnostic::error(span, "file could not be opened")
                            .with_snippet(include.path.clone()),
                    );
                    continue;
                }
            };
            let name = path.to_string_lossy().into_owned();
            let (child, decode_diag) = super::input::add_bytes(sources, &name, bytes);
            diags.extend(decode_diag);
            let dialect = if name.ends_with(".sp") {
                Dialect::Sparc
            } else {
                program.dialect
            };
            let parse = crate::syntax::parse(child, &sources.get(child).text, dialect);
            diags.extend(parse.diagnostics);
            let mut included = parse.program;
            self.resolve_depth(&mut included, child, sources, diags, depth + 1);
            out.extend(included.statements);
        }
        program.statements = out;
    }
}
