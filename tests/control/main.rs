//! The `control` layer's integration tests: multi-shot control, incremental mode and provenance.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod grid;
mod incmode;
mod multishot;
mod propagator;
mod provenance;
mod threads;
mod traps;
