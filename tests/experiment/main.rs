//! The `experiment` layer's integration tests: `lucent experiment` and its job lists.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

mod cli;
mod jobs;
