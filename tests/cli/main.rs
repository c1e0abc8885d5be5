//! End-to-end tests of the `lucent` binary and the `cli` layer: exit codes and diagnostics, the
//! printer against clingo and its snapshots, the built-in domains, wide inputs, running from any
//! directory, `lucent demo` and the README's commands.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod anywhere;
mod binary;
mod demo;
mod domains;
mod readme;
mod report_clingo;
mod report_snapshots;
mod wide;
