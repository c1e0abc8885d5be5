//! The `plan` layer's integration tests: the planner (golden plans, checks, generated tasks,
//! `lucent plan`) and the sense-plan-act loop (`lucent run`, scripted and simulated episodes).
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod check;
mod cli;
#[cfg(feature = "sim")]
mod generated;
mod golden;
#[cfg(feature = "sim")]
mod run_cli;
#[cfg(feature = "sim")]
mod run_episodes;
mod run_loop;
