//! Solving: conflict-driven stable-model search over ground programs (issue 4).
//!
//! Pipeline inside this module: `translate` turns a `GroundProgram` into clauses and native
//! weight constraints over solver variables (Clark completion with body variables);
//! `engine` is a CDCL core (two watched literals, first-UIP learning, VSIDS, restarts) with
//! `unfounded`-set propagation for non-tight programs and the component-wise `stability` check
//! of non-head-cycle-free ones; `solver` drives it for enumeration,
//! optimization, consequences, CR-Prolog semantics, limits, multi-shot steps and the portfolio,
//! and produces a `SolveResult`. `lit` holds the literal encoding, `config` and `result` the
//! caller-facing types; `check` and `brute` are independent references for tests;
//! `fuzzing` is the body of the aspif fuzz target.

pub mod brute;
pub mod check;
pub(crate) mod config;
pub(crate) mod result;

pub use config::{
    Config, CrMode, Deletion, EnumMode, Heuristic, OptMode, OptStrategy, Project, ReduceSchedule,
    RestartPolicy, SearchProfile,
};
pub use result::{Model, Outcome, SolveResult, Stats, StopReason};
pub(crate) mod engine;
pub mod fuzzing;
pub(crate) mod lit;
pub mod propagator;
pub(crate) mod solver;
pub(crate) mod stability;
pub(crate) mod translate;
pub(crate) mod unfounded;

pub use solver::{LowerBoundObserver, ModelClauses, SolveError, Solver};
