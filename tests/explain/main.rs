//! The `explain` layer's integration tests: proof trees, questions and their English, the H3
//! and H4 runs, oracles and `lucent explain`/`lucent ask`.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod build;
mod cli;
mod english;
mod examples;
mod h3;
mod h4;
mod no_plan;
mod oracle;
mod paraphrases;
mod questions;
mod random;
mod tree;
mod verbalize;
