//! Shared helpers of the integration tests (each test crate that needs them says `mod support;`).

pub mod random_program;
