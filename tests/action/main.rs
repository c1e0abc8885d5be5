//! The `action` layer's integration tests: the AL_d grammar, its translation, golden outputs,
//! malformed descriptions and the fuzz corpus.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod cli;
mod fuzz_corpus;
mod golden;
mod grammar;
mod malformed;
