//! The `sim` layer's integration tests (the `sim` feature): physics, actions, perception, scene
//! generation and `lucent sim`.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.
#![cfg(feature = "sim")]

mod actions;
mod cli;
mod generate;
mod perception;
mod physics;
