//! Grounding: from a parsed program to a ground program (issue 3), and the ground program's
//! exchange format, aspif.
//!
//! Invariant: the ground program is the only thing the solver sees, and it round-trips through
//! aspif (`program` is the in-memory form, `aspif` reads and writes it), so our grounder can be
//! checked by clasp and our solver can be fed by gringo.

pub mod aspif;
pub mod program;
