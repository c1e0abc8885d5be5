//! The `ground` layer's integration tests: grounding, its diagnostics and provenance, SPARC,
//! the aspif reader and writer, and the differential test against gringo, clasp and clingo.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod aspif_diagnostics;
mod aspif_fuzz_corpus;
mod aspif_malformed;
mod aspif_properties;
mod aspif_roundtrip;
mod cr;
mod diagnostics;
mod diff_random;
mod diff_random_py;
mod programs;
mod provenance;
mod reference;
mod sparc;
mod theory;
