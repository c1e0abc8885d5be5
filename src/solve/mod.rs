//! Solving: conflict-driven stable-model search over ground programs (issue 4).
//!
//! Pipeline inside this module: `translate` turns a `GroundProgram` into clauses and native
//! weight constraints over solver variables (Clark completion with body variables);
//! `engine` is a CDCL core (two watched literals, first-UIP learning, VSIDS, restarts) with
//! `unfounded`-set propagation for non-tight programs; `search` drives it for enumeration,
//! optimization, consequences and CR-Prolog semantics and produces a `SolveResult`.

pub mod brute;
pub mod check;
pub mod config;
pub mod result;

pub use config::{Config, CrMode, EnumMode, OptMode, RestartPolicy};
pub use result::{Model, Outcome, SolveResult, Stats, StopReason};
pub mod engine;
pub mod lit;
pub mod solver;
pub mod translate;
pub mod unfounded;

pub use solver::{SolveError, Solver};
