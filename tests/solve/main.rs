//! The `solve` layer's integration tests: the solver on hand-derived and clingo-recorded
//! answers, limits, multi-shot solving, properties, the brute-force reference and the checker.
//!
//! One test binary per layer (issue 29): each module is one former `tests/*.rs` file.

mod basic;
mod check_brute;
mod check_checker;
mod clingo;
mod limits;
mod multishot;
mod opt_strategies;
mod portfolio;
mod props;
mod random_aspif;
