//! The `learn` layer's integration tests: the knowledge base, the learning episode, the physics
//! oracle, the learned planner's check and the decision tree against linfa.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

#[path = "../support/mod.rs"]
mod support;

mod cart_linfa;
mod episode;
mod kb;
#[cfg(feature = "sim")]
mod physics;
#[cfg(feature = "sim")]
mod physics_rest;
mod planning_check;
