//! Syntax: text to syntax tree (lexer, parser), and syntax tree back to text (printer).
//!
//! Invariant: parsing never fails; it returns the tree and every diagnostic, recovering at the
//! next rule. The syntax layer knows nothing about grounding.

pub mod ast;
