//! Diagnostics: what went wrong in the user's input, where, and how to render it as gringo does.
//!
//! Invariants: user-input problems are values of [`Diagnostic`], never panics; every diagnostic
//! has a span; warnings have a [`WarningKind`] so they can be switched off one kind at a time
//! (`-W no-<kind>`); at most `limit` messages are rendered, after which one closing line says
//! that the rest were suppressed (gringo's `logger.hh` does the same).

use super::source::SourceMap;
use super::span::Span;

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Severity {
    /// The input cannot be processed; the run exits with code 65.
    Error,
    /// Something probably unintended; gringo calls these `info`.
    Warning,
}

/// The kinds of warnings, named as gringo's `-W` option names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum WarningKind {
    /// An atom occurs in a body but in no rule head.
    AtomUndefined,
    /// A file was included twice.
    FileIncluded,
    /// An arithmetic operation is undefined (e.g. division by zero); the instance is dropped.
    OperationUndefined,
    /// A variable in a SPARC program is not bound by any sort.
    VariableUnbounded,
    /// A global variable occurs in a tuple of an aggregate element.
    GlobalVariable,
    /// Everything else.
    Other,
}

impl WarningKind {
    /// All kinds, in the order of their names.
    pub const ALL: [WarningKind; 6] = [
        WarningKind::AtomUndefined,
        WarningKind::FileIncluded,
        WarningKind::OperationUndefined,
        WarningKind::VariableUnbounded,
        WarningKind::GlobalVariable,
        WarningKind::Other,
    ];

    /// The name used by `-W`.
    pub fn name(self) -> &'static str {
        match self {
            WarningKind::AtomUndefined => "atom-undefined",
            WarningKind::FileIncluded => "file-included",
            WarningKind::OperationUndefined => "operation-undefined",
            WarningKind::VariableUnbounded => "variable-unbounded",
            WarningKind::GlobalVariable => "global-variable",
            WarningKind::Other => "other",
        }
    }

    /// The kind named `name` by `-W`.
    pub fn from_name(name: &str) -> Option<WarningKind> {
        WarningKind::ALL.into_iter().find(|k| k.name() == name)
    }
}

/// A secondary message attached to a diagnostic, usually pointing elsewhere in the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Note {
    /// Where the note points, if anywhere.
    pub span: Option<Span>,
    /// The note's text.
    pub message: String,
}

/// One problem found in the input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// Error or warning.
    pub severity: Severity,
    /// For warnings, the kind that `-W no-<kind>` switches off.
    pub kind: Option<WarningKind>,
    /// The main message, without location or severity.
    pub message: String,
    /// Where the problem is.
    pub span: Span,
    /// The offending text, printed indented under the message (gringo prints the rule here).
    pub snippet: Option<String>,
    /// Further notes.
    pub notes: Vec<Note>,
}

impl Diagnostic {
    /// An error at `span`.
    pub fn error(span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Error,
            kind: None,
            message: message.into(),
            span,
            snippet: None,
            notes: Vec::new(),
        }
    }

    /// A warning of kind `kind` at `span`.
    pub fn warning(kind: WarningKind, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            severity: Severity::Warning,
            kind: Some(kind),
            message: message.into(),
            span,
            snippet: None,
            notes: Vec::new(),
        }
    }

    /// Adds the offending text.
    pub fn with_snippet(mut self, snippet: impl Into<String>) -> Diagnostic {
        self.snippet = Some(snippet.into());
        self
    }

    /// Adds a note pointing at `span`.
    pub fn with_note(mut self, span: Option<Span>, message: impl Into<String>) -> Diagnostic {
        self.notes.push(Note {
            span,
            message: message.into(),
        });
        self
    }

    /// True for errors.
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// Renders in gringo's format: `file:line:col-col: error: message`, the snippet indented by
    /// two spaces, then one line per note, then an empty line.
    pub fn render(&self, sources: &SourceMap) -> String {
        let mut out = String::new();
        let label = match self.severity {
            Severity::Error => "error",
            Severity::Warning => "info",
        };
        out.push_str(&format!(
            "{}: {}: {}",
            sources.location(self.span),
            label,
            self.message
        ));
        if let Some(snippet) = &self.snippet {
            out.push_str(":\n");
            for line in snippet.lines() {
                out.push_str("  ");
                out.push_str(line);
                out.push('\n');
            }
        } else {
            out.push('\n');
        }
        for note in &self.notes {
            match note.span {
                Some(span) => out.push_str(&format!(
                    "{}: note: {}\n",
                    sources.location(span),
                    note.message
                )),
                None => out.push_str(&format!("note: {}\n", note.message)),
            }
        }
        out.push('\n');
        out
    }
}

/// Collects diagnostics under a configuration: which warnings are off, and the message limit.
#[derive(Clone, Debug)]
pub struct Diagnostics {
    /// Everything reported and not switched off, in order, up to `limit` entries.
    items: Vec<Diagnostic>,
    /// Warning kinds switched off with `-W no-<kind>`.
    disabled: Vec<WarningKind>,
    /// Maximum number of diagnostics kept; later ones are counted only.
    limit: usize,
    /// Number of diagnostics dropped because of the limit.
    suppressed: usize,
    /// Number of errors reported (kept or suppressed).
    errors: usize,
}

impl Default for Diagnostics {
    fn default() -> Self {
        Diagnostics::new(20)
    }
}

impl Diagnostics {
    /// An empty collector keeping at most `limit` messages (gringo's default is 20).
    pub fn new(limit: usize) -> Diagnostics {
        Diagnostics {
            items: Vec::new(),
            disabled: Vec::new(),
            limit,
            suppressed: 0,
            errors: 0,
        }
    }

    /// Switches a warning kind off.
    pub fn disable(&mut self, kind: WarningKind) {
        if !self.disabled.contains(&kind) {
            self.disabled.push(kind);
        }
    }

    /// Switches a warning kind back on.
    pub fn enable(&mut self, kind: WarningKind) {
        self.disabled.retain(|k| *k != kind);
    }

    /// True when warnings of `kind` are reported.
    pub fn is_enabled(&self, kind: WarningKind) -> bool {
        !self.disabled.contains(&kind)
    }

    /// Records a diagnostic, unless it is a switched-off warning.
    pub fn push(&mut self, diagnostic: Diagnostic) {
        if let Some(kind) = diagnostic.kind {
            if diagnostic.severity == Severity::Warning && !self.is_enabled(kind) {
                return;
            }
        }
        if diagnostic.is_error() {
            self.errors += 1;
        }
        if self.items.len() < self.limit {
            self.items.push(diagnostic);
        } else {
            self.suppressed += 1;
        }
    }

    /// Records every diagnostic of `list`.
    pub fn extend(&mut self, list: impl IntoIterator<Item = Diagnostic>) {
        for d in list {
            self.push(d);
        }
    }

    /// Number of errors reported.
    pub fn error_count(&self) -> usize {
        self.errors
    }

    /// True when at least one error was reported.
    pub fn has_errors(&self) -> bool {
        self.errors > 0
    }

    /// The kept diagnostics.
    pub fn items(&self) -> &[Diagnostic] {
        &self.items
    }

    /// Renders every kept diagnostic, plus a line on suppressed ones.
    pub fn render(&self, sources: &SourceMap) -> String {
        let mut out = String::new();
        for d in &self.items {
            out.push_str(&d.render(sources));
        }
        if self.suppressed > 0 {
            out.push_str(&format!(
                "*** Info : (lucent): {} further messages suppressed (message limit {})\n",
                self.suppressed, self.limit
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::source::SourceMap;

    #[test]
    fn renders_like_gringo() {
        let mut map = SourceMap::new();
        let f = map.add("-", "p(X).");
        let d = Diagnostic::error(Span::new(f, 0, 5), "unsafe variables in")
            .with_snippet("p(X).")
            .with_note(Some(Span::new(f, 2, 3)), "'X' is unsafe");
        assert_eq!(
            d.render(&map),
            "-:1:1-6: error: unsafe variables in:\n  p(X).\n-:1:3-4: note: 'X' is unsafe\n\n"
        );
    }

    #[test]
    fn warnings_switch_off_and_limit_holds() {
        let mut map = SourceMap::new();
        let f = map.add("-", "a.");
        let mut ds = Diagnostics::new(2);
        ds.disable(WarningKind::AtomUndefined);
        ds.push(Diagnostic::warning(
            WarningKind::AtomUndefined,
            Span::new(f, 0, 1),
            "x",
        ));
        assert!(ds.items().is_empty());
        for _ in 0..3 {
            ds.push(Diagnostic::error(Span::new(f, 0, 1), "e"));
        }
        assert_eq!(ds.items().len(), 2);
        assert_eq!(ds.error_count(), 3);
        assert!(ds.render(&map).contains("1 further messages suppressed"));
    }
}
