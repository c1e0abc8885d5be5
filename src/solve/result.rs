//! What a solver call answers: the models, the overall outcome and statistics.
//!
//! Invariants: `models` are in the order they were found; `costs` have one entry per
//! optimization priority, highest priority first (as clasp prints them); `exhausted` is true
//! only when the search space was fully explored, and `optimum_proven` only when the last
//! reported cost is optimal. These types are the contract with the output writer
//! (`cli::report`); they only grow.

use std::time::Duration;

/// One answer set as reported to callers.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Model {
    /// 1-based number of the model in this call, as in clasp's `Answer: N`.
    pub number: usize,
    /// Shown symbols (output statements whose condition holds), in output-statement order and
    /// without duplicates.
    pub symbols: Vec<String>,
    /// True atoms of the ground program (aspif numbering), sorted.
    pub atoms: Vec<u32>,
    /// Costs, one per priority level, highest priority first; empty without `#minimize`.
    pub costs: Vec<i64>,
    /// Labels of the applied consistency-restoring rules, sorted.
    pub cr_applied: Vec<String>,
    /// For every true atom (parallel to `atoms`), the index into `GroundProgram::rules` of one
    /// rule whose body holds and that supports the atom (well-founded order: following the
    /// supports of the positive body atoms never cycles); `None` for atoms that are true as
    /// externals or assumptions without a rule. Empty when `Config::supports` is off, and in the
    /// models of `Solver::for_each_model_lazy` (whose caller computes them on demand).
    pub support: Vec<Option<usize>>,
    /// True when this model is known to be optimal (optN enumeration phase, or the last model of
    /// an optimization whose optimum was proven).
    pub optimal: bool,
    /// The portfolio thread that found it (clingo's `Model.thread_id`; 0 with one thread).
    pub thread_id: u32,
}

impl Model {
    /// Whether the atom is true in this model.
    pub fn holds(&self, atom: u32) -> bool {
        self.atoms.binary_search(&atom).is_ok()
    }
}

/// The overall answer of a solver call, as clasp prints it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// At least one model was found (and no optimum was proven).
    Satisfiable,
    /// The search was exhausted without a model.
    Unsatisfiable,
    /// The search stopped (limit or interrupt) before finding a model or exhausting the space.
    Unknown,
    /// A model was found and proven optimal.
    Optimum,
}

/// Why the search stopped early, if it did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopReason {
    /// The deadline passed.
    TimeLimit,
    /// The interrupt flag was raised.
    Interrupted,
    /// The call met `Config::conflict_limit` conflicts (clasp's `--solve-limit`).
    ConflictLimit,
}

/// Search statistics of one solve call (the counters count that call's work; `learnt`, `vars`
/// and `clauses` are sizes at its end); for people, never asserted on by tests.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Stats {
    /// Decisions made.
    pub choices: u64,
    /// Conflicts met.
    pub conflicts: u64,
    /// Restarts done.
    pub restarts: u64,
    /// Unit propagations (assignments by propagation).
    pub propagations: u64,
    /// Loop nogoods learnt from unfounded sets.
    pub loop_nogoods: u64,
    /// Learnt clauses currently kept.
    pub learnt: u64,
    /// Solver variables (atoms, bodies, auxiliaries).
    pub vars: u64,
    /// Problem clauses after translation.
    pub clauses: u64,
    /// Wall-clock time of the call.
    pub time: Duration,
    /// Wall-clock time from the start of the call to the first reported model, if any (clasp's
    /// `1st Model`).
    pub first_model: Option<Duration>,
    /// Wall-clock time from the last reported model (or the start of the call, without one) to
    /// the end of the call when the search space was exhausted, zero otherwise: the time spent
    /// proving that nothing (better) is left (clasp's `Unsat`).
    pub unsat: Duration,
}

impl Stats {
    /// Adds the counters and times of a later call (`other`) to these, and takes its sizes:
    /// the accumulated statistics of several calls (clingo's `accu` beside `summary`).
    pub fn accumulate(&mut self, other: &Stats) {
        self.choices += other.choices;
        self.conflicts += other.conflicts;
        self.restarts += other.restarts;
        self.propagations += other.propagations;
        self.loop_nogoods += other.loop_nogoods;
        self.learnt = other.learnt;
        self.vars = other.vars;
        self.clauses = other.clauses;
        self.time += other.time;
        if self.first_model.is_none() {
            self.first_model = other.first_model;
        }
        self.unsat += other.unsat;
    }
}

/// Everything one call of the solver answers.
#[derive(Clone, Debug, PartialEq)]
pub struct SolveResult {
    /// Models in the order found (improving models during optimization, then optimal ones in
    /// optN; the consequences as a single model in brave/cautious mode, updated to the last).
    pub models: Vec<Model>,
    /// The overall outcome.
    pub outcome: Outcome,
    /// True when the whole search space was explored (all models enumerated, or optimum proven,
    /// or unsatisfiability shown).
    pub exhausted: bool,
    /// True when the cost of the last model is proven optimal.
    pub optimum_proven: bool,
    /// Why the search stopped early, when it did.
    pub stop: Option<StopReason>,
    /// Statistics.
    pub stats: Stats,
}

impl SolveResult {
    /// The costs of the best model found, if any model had costs.
    pub fn best_costs(&self) -> Option<&[i64]> {
        self.models
            .last()
            .filter(|m| !m.costs.is_empty())
            .map(|m| m.costs.as_slice())
    }
}
