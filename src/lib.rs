//! Lucent: a native answer-set programming system for a robot that reasons, plans, learns and
//! explains itself.
//!
//! Modules are listed in pipeline order; each uses only the modules above it in this list
//! (`base` at the bottom of the dependency order, `cli` at the top). See ARCHITECTURE.md.

#![warn(missing_docs)]

pub mod base;
pub mod syntax;
pub mod ground;
pub mod solve;
pub mod control;
pub mod action;
#[cfg(feature = "sim")]
pub mod sim;
pub mod plan;
pub mod learn;
#[cfg(feature = "sim")]
pub mod vision;
pub mod explain;
pub mod experiment;
pub mod cli;

// The front door: what a program that solves, plans or explains starts from.
pub use action::{HorizonMode, Options, Switches};
pub use control::{Control, ControlConfig, Model, Part, Symbol};
pub use plan::{PlanConfig, Problem};

/// README.md as documentation, so its Rust example runs as a doctest (`cargo test --doc`);
/// its shell commands are run by `tests/cli/readme.rs`.
#[doc = include_str!("../README.md")]
#[cfg(doctest)]
pub struct ReadmeDoctests;
