//! Shared helpers of the integration tests. A test binary that needs them says
//! `#[path = "../support/mod.rs"] mod support;` in its `main.rs`, and its modules use
//! `crate::support::...`. A binary uses only some of the helpers, so the rest are dead code there.
#![allow(dead_code)]

pub mod cli;
pub mod ground;
pub mod learn;
pub mod plan;
pub mod ra_oracle;
pub mod ra_scenes;
pub mod random_program;
