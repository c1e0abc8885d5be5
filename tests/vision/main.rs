//! The `vision` layer's integration tests (the `sim` feature): golden recognitions and
//! `lucent vision`.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.
#![cfg(feature = "sim")]

mod cli;
mod golden;
