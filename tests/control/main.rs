//! The `control` layer's integration tests: multi-shot control, incremental mode, provenance
//! and grounding contexts.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod aspif;
mod functions;
mod handle;
mod grid;
mod incmode;
mod lower_bound;
mod model;
mod model_order;
mod multishot;
mod propagator;
mod theory;
mod propagator_modes;
mod provenance;
mod threads;
mod traps;
