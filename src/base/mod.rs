//! Vocabulary shared by every stage: source files and spans, diagnostics, interned symbols.
//!
//! Invariants: nothing here knows about the syntax, grounding or solving; every type here is
//! plain data (ids and owned values), so it can cross stage boundaries freely.

pub(crate) mod diag;
pub(crate) mod intern;
pub mod rng;
pub(crate) mod source;
pub(crate) mod span;

pub use diag::{Diagnostic, Diagnostics, Note, Severity, WarningKind};
pub use source::{SourceFile, SourceMap};
pub use span::{FileId, Span};
