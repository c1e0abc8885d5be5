//! Axiom learning (docs/domain.md section 5): surprises, samples, decision trees, candidate axioms,
//! the ensemble vote, scoring against the targets, and learned axioms with a strength.
//!
//! Data flow: a one-step trial (a random state and action, `state`) is run against the learner's
//! knowledge base and an oracle; a discrepancy (`surprise`) starts sample collection; samples are
//! lifted to variables (`lift`) into binary feature tables; an ensemble of CART trees (`cart`,
//! `ensemble`) yields candidate axioms, which are voted on and compared up to variable renaming;
//! `score` compares what was found with the targets. Literals and axioms are structured terms
//! (`term`), never strings.

pub mod cart;
pub mod term;
pub mod lift;
pub(crate) mod ensemble;
pub mod score;
pub mod state;
pub mod surprise;
pub mod strength;
pub mod episode;
pub mod kb;
#[cfg(feature = "sim")]
pub mod physics;
pub mod h1;
