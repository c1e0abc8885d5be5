//! The CDCL core: assignment, two-watched-literal unit propagation, native weight constraints,
//! first-UIP conflict analysis with recursive clause minimisation, VSIDS with phase saving,
//! Luby and glucose-style restarts, and learnt clause deletion (clasp's use counts, or LBD and
//! activity).
//!
//! Follows MiniSat/Glucose as restated by varisat and kissat: per-variable data in parallel
//! vectors, long clauses in one `Vec<u32>` arena with a three-word header, binary clauses only in
//! the watch lists. Weight constraints `b <-> sum(w_i * l_i) >= k` are propagated natively with
//! explanations stored per variable (clasp's weight constraints, AIJ 2012 section 6). An optional
//! `Unfounded` propagator (source pointers) runs at every propagation fixpoint on the trail
//! segment assigned since its previous run and contributes loop nogoods as learnt clauses.
//!
//! This file holds the engine's state, its construction, assignment and backtracking; the
//! techniques live in submodules: `clauses` (clause arena, weight constraints), `propagate`,
//! `analyze` (conflict analysis, LBD), `heuristic` (VSIDS, phases), `database` (learnt-clause
//! reduction, garbage collection, level-0 simplification), `search` (the CDCL loop, restarts),
//! `loops` (shared loop formulas) and `vars` (making, reserving and retiring variables). The state is grouped into parts, as varisat's solver
//! context is: `asg` (assignment and trail), `heur` (VSIDS, phases, domain heuristic), `db`
//! (clause arena, watch lists, learnt clauses, loop formulas), `wc` (weight constraints), `an`
//! (conflict analysis), `uf` (unfounded-set propagator), `sched` (restarts, reductions,
//! simplification), `limits`, `stats`, `settings` (from `solve::Config`) and `pool` (variable
//! recycling). Techniques access the parts' fields directly (`self.asg.values[..]`), so
//! disjoint parts borrow independently and the code compiles as with one flat struct.
//!
//! Invariants:
//! - The first two literals of every long clause are its watched literals; when a clause is the
//!   reason of an assignment, the implied literal is at position 0.
//! - `values[l.code()]` is 1 when `l` is true, -1 when false, 0 when unassigned, and
//!   `values[(!l).code()] == -values[l.code()]`.
//! - Assumptions occupy decision levels `1..=assumptions.len()` during `search`.
//! - Variables are recycled: `retire_vars` marks variables nothing will mention again (a
//!   finished call's guard, the auxiliary variables of its bounds); they are never decided, and
//!   the next level-0 `simplify` deletes every clause and loop formula mentioning one (learnt or
//!   not), drops their level-0 assignments and puts them on the free list that `new_var` takes
//!   from first. A free variable occurs in no clause, watch list, weight constraint or trail.
//!   Removed weight constraints leave their slot to the next `add_weight`.

mod analyze;
mod clauses;
mod database;
mod external;
mod heuristic;
mod loops;
mod propagate;
mod search;
mod share;
mod vars;
pub(crate) use external::{LitMap, SharedHook};
pub use share::Hub;

use super::config::{Config, Deletion, ReduceSchedule};
use super::lit::{Lit, Var};
use super::stability::Stability;
use super::unfounded::Unfounded;
use loops::{is_loop_watch, Loops, LOOP_TAG};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// Offset of a long clause's header in the arena.
pub type ClauseRef = u32;

/// Words of a clause header: length, flags (learnt, deleted, lbd), activity bits.
const HEADER: usize = 3;
const FLAG_LEARNT: u32 = 1;
const FLAG_DELETED: u32 = 2;
/// "None" in the per-variable `u32` indexes (`heap_pos`, `stored_slot`, `weight_slot`).
const NO_SLOT: u32 = u32::MAX;
/// Largest use count of a learnt clause under `Deletion::Basic` (clasp's 20-bit activity).
const MAX_USES: u32 = (1 << 20) - 1;

/// Why a variable has its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Reason {
    /// A decision or an assumption, or a fact at level 0.
    Decision,
    /// Implied by a binary clause whose other literal is given.
    Binary(Lit),
    /// Implied by a long clause.
    Long(ClauseRef),
    /// Implied with the explanation stored in `Assignment::stored` (weight constraints).
    Stored,
    /// Implied by a shared loop formula (`loops`), by its id.
    Loop(u32),
}

/// A watch list entry.
#[derive(Clone, Copy, Debug)]
struct Watch {
    /// The clause, or `u32::MAX` for a binary clause.
    cref: u32,
    /// For a binary clause the other literal; for a long clause a blocker literal.
    other: Lit,
}

/// Closes a watch list after a propagation pass stopped early: the watches from `i` on were not
/// visited and are kept, moved down to follow the `j` kept so far.
fn keep_unvisited(ws: &mut Vec<Watch>, i: usize, j: usize) {
    let n = ws.len();
    ws.copy_within(i..n, j);
    ws.truncate(j + (n - i));
}

/// One occurrence of a variable in a weight constraint.
#[derive(Clone, Copy, Debug)]
struct WeightWatch {
    /// The constraint.
    id: u32,
    /// The literal as it occurs.
    lit: Lit,
    /// Its weight (0 for the head).
    weight: u64,
}

/// A weight constraint `head <-> sum of weights of true lits >= bound`, weights positive.
///
/// `sum_true` and `sum_false` count the literals processed by propagation (trail positions
/// below `qhead`) and are undone on backtracking; they only decide whether a full evaluation
/// is needed, which then reads the actual values.
#[derive(Clone, Debug)]
struct WeightConstraint {
    /// Sum of weights of processed true literals.
    sum_true: u64,
    /// Sum of weights of processed false literals.
    sum_false: u64,
    /// Sum of all weights.
    total: u64,
    /// Largest weight.
    max_weight: u64,
    /// The literal equivalent to the constraint (only implying it when `implication`).
    head: Lit,
    /// `head -> sum >= bound` only: the constraint never makes `head` true and a false `head`
    /// constrains nothing, so its bound may be raised later (`raise_weight_bound`) without
    /// invalidating a clause learnt with its help.
    implication: bool,
    /// What normalising negative weights added to the bound given by the caller.
    shift: i128,
    /// Literals with positive weights.
    lits: Vec<(Lit, u64)>,
    /// The lower bound.
    bound: u64,
    /// Detached by `remove_weight`: no longer watched or propagated.
    removed: bool,
    /// `lits[..scan_from]` are all assigned, as `propagate_weight`'s scans found them during
    /// epoch `scan_epoch` ([`WeightDb::epoch`]); within an epoch nothing is unassigned, so the
    /// scans start there instead of rescanning the assigned prefix at every call.
    scan_from: u32,
    scan_epoch: u64,
}

/// Asks the processor to start loading the cache line at `p` into its caches. Propagation
/// is bound by cache misses on watch lists (a list header per literal, then the list itself):
/// issuing the loads one propagation step early overlaps them with the current step.
#[inline(always)]
fn prefetch<T>(p: *const T) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: a prefetch is only a hint: it never faults, whatever the address (it may be
    // dangling or past the end), and neither reads a value into the program nor writes.
    unsafe {
        std::arch::x86_64::_mm_prefetch::<{ std::arch::x86_64::_MM_HINT_T0 }>(p.cast::<i8>())
    };
    #[cfg(not(target_arch = "x86_64"))]
    let _ = p;
}

/// `Settings::save_progress` after a phase switch (`Settings::phase_switch`): clasp's tweety value.
const PHASE_SWITCH_PROGRESS: u32 = 160;

/// How many trail positions ahead of the propagation queue head watch lists are prefetched.
const PREFETCH_AHEAD: usize = 4;

/// How many watch list entries ahead of the one visited the clause of a watch is prefetched.
const CLAUSE_AHEAD: usize = 3;

/// The size of an engine's contents (`Engine::size`), for tests that check that repeated calls
/// leave nothing behind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EngineSize {
    /// Variables, free ones for reuse included.
    pub vars: usize,
    /// Problem clauses (long ones) plus binary clauses (problem and learnt).
    pub clauses: usize,
    /// Learnt long clauses and loop formulas.
    pub learnts: usize,
    /// Weight constraints attached.
    pub weights: usize,
    /// Assignments at decision level 0.
    pub level0: usize,
}

/// Answer of a search.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SearchResult {
    /// A total assignment satisfying all constraints was found; it stays on the trail.
    Sat,
    /// No assignment extends the assumptions.
    Unsat,
    /// A limit was reached.
    Unknown,
}

/// Restart schedule state.
#[derive(Clone, Debug)]
pub enum Restarts {
    /// Luby sequence: unit and current index.
    Luby {
        /// Conflicts per Luby unit.
        unit: u32,
        /// Position in the sequence.
        index: u32,
        /// Conflicts left before the next restart.
        left: u64,
    },
    /// Glucose: fast and slow exponential moving averages of learnt clause LBDs.
    Glucose {
        /// Fast moving average.
        fast: f64,
        /// Slow moving average.
        slow: f64,
        /// Conflicts since the last restart.
        since: u64,
        /// Moving average of the trail length at conflicts (restart blocking).
        trail: f64,
    },
    /// Never restart.
    Never,
}

/// The assignment: per-literal values, per-variable levels and reasons, the trail and the
/// propagation queue.
struct Assignment {
    /// Per literal code: 1 true, -1 false, 0 unassigned.
    values: Vec<i8>,
    /// Per variable: decision level of the assignment.
    level: Vec<u32>,
    /// Per variable: why it is assigned.
    reason: Vec<Reason>,
    /// Per variable: its buffer in `stored`, or `NO_SLOT` if it never had a stored reason.
    /// Few variables are ever implied by a weight constraint, so the buffers live in a pool
    /// and the per-variable cost is four bytes instead of an empty `Vec` header (24 bytes).
    stored_slot: Vec<u32>,
    /// Stored explanations (implied literal first, then false literals), one buffer per
    /// variable that had one; reused when the variable is implied again.
    stored: Vec<Vec<Lit>>,
    /// Assigned literals in order.
    trail: Vec<Lit>,
    /// Trail length at the start of each decision level.
    trail_lim: Vec<usize>,
    /// Next trail position to propagate.
    qhead: usize,
    /// Trail position up to which watch lists were prefetched (may lag behind `qhead`).
    pf_head: usize,
}

/// The decision heuristic: VSIDS activities and their heap, saved phases, the domain heuristic and
/// random decisions.
struct Heuristic {
    /// Per variable: saved phase (last value).
    phase: Vec<bool>,
    /// Per variable: whether `phase` was saved by a backjump (not the initial sign).
    phase_saved: Vec<bool>,
    /// Domain heuristic: per variable, the sign to decide it with (-1 false, 1 true, 0 none).
    dom_sign: Vec<i8>,
    /// Domain heuristic: variables with a positive level, highest level first; decided before
    /// any other.
    dom_order: Vec<(i32, Var)>,
    /// Per variable: occurrences in learnt clauses, +1 per positive and -1 per negative
    /// literal (clasp's sign score, used when `sign_from_learnts` is set).
    occ: Vec<i32>,
    /// Per variable: VSIDS activity.
    activity: Vec<f64>,
    /// Per variable: position in `heap`, or `NO_SLOT`.
    heap_pos: Vec<u32>,
    /// Binary heap of decision candidates ordered by activity.
    heap: Vec<Var>,
    /// Per variable: whether it may be chosen as a decision.
    decidable: Vec<bool>,
    /// Activity increment.
    var_inc: f64,
    /// Activity decay factor.
    var_decay: f64,
    /// Pseudo-random state.
    rng: u64,
    /// The configured `save_progress` and `sign_from_learnts` while a phase switch is in force.
    phase_switched: Option<(u32, bool)>,
}

/// The clause database: the arena of long clauses, the watch lists, learnt clauses and shared loop
/// formulas.
struct ClauseDb {
    /// Per literal code: watches of clauses in which that literal is watched.
    watches: Vec<Vec<Watch>>,
    /// The clause arena: headers followed by literal codes.
    arena: Vec<u32>,
    /// Words of deleted clauses still in the arena.
    wasted: usize,
    /// References of learnt long clauses.
    learnts: Vec<ClauseRef>,
    /// Shared loop formulas (learnt, watched in `watches` with tagged references).
    loops: Loops,
    /// Clause activity increment.
    cla_inc: f64,
    /// Scratch space of `add_clause` (empty between calls).
    clause_buf: Vec<Lit>,
}

/// The weight constraints and their per-variable occurrence lists.
struct WeightDb {
    /// Per variable: its list in `weight_watch`, or `NO_SLOT` when the variable occurs in no
    /// weight constraint. Four bytes per variable, so that the (usually many) variables
    /// outside every weight constraint cost no `Vec` header, and their propagation and
    /// backtracking test one small word instead of loading a header from a cold cache line.
    weight_slot: Vec<u32>,
    /// Occurrences in weight constraints (the head occurs with weight 0), one list per
    /// variable that has a `weight_slot`.
    weight_watch: Vec<Vec<WeightWatch>>,
    /// Weight constraints.
    weights: Vec<WeightConstraint>,
    /// Slots of removed weight constraints, reused by `add_weight`.
    free_weights: Vec<u32>,
    /// Counts the operations that unassign variables (backtracking, dropping retired
    /// variables); a constraint's `scan_from` holds only within the epoch it was found in.
    epoch: u64,
}

/// Conflict analysis: the last conflict, the learnt clause, failed assumptions and scratch space.
struct Analysis {
    /// Per variable: scratch mark used by conflict analysis.
    seen: Vec<u8>,
    /// Learnt clause of the last `analyze`.
    learnt: Vec<Lit>,
    /// Variables marked `seen` during analysis.
    to_clear: Vec<Var>,
    /// Work stack of clause minimisation.
    min_stack: Vec<Lit>,
    /// Reason buffer of clause minimisation.
    min_buf: Vec<Lit>,
    /// Per decision level: stamp of the last LBD computation that met it.
    level_seen: Vec<u64>,
    /// Current LBD stamp.
    lbd_stamp: u64,
    /// Literals of the last conflict (all false).
    conflict: Vec<Lit>,
    /// After a search that answered `Unsat` under assumptions: the assumptions (true on the
    /// trail, as assumed) that imply the failed one's complement, the failed one first; empty
    /// when no assumption took part (a level-0 conflict).
    failed: Vec<Lit>,
    /// Trail length at the last conflict, before backjumping.
    conflict_trail: usize,
}

/// The unfounded-set propagator and what decides when it reruns.
struct UfState {
    /// Unfounded-set propagator for non-tight programs (install with `set_unfounded`).
    unfounded: Option<Unfounded>,
    /// Per variable: whether its value can affect foundedness (a support or weight-body
    /// literal of a cyclic atom's support).
    uf_relevant: Vec<bool>,
    /// Trail length up to which the assignment is known to have no unfounded cyclic atom; the
    /// check reruns only when a relevant variable was assigned after it (foundedness is lost
    /// only when a support literal becomes false).
    uf_clean_upto: usize,
    /// Set when the propagator was (re)installed and the assignment was never checked.
    uf_dirty: bool,
    /// The stability check of the non-head-cycle-free components (install with
    /// `set_stability`), run at fixpoints after the unfounded-set propagator.
    stability: Option<Box<Stability>>,
}

/// Restarts, learnt-clause reductions and level-0 simplifications: when each is due next.
pub struct Schedule {
    /// Restart state.
    pub restarts: Restarts,
    /// Maximum number of learnt clauses before a reduction (`ReduceSchedule::Size`).
    max_learnts: f64,
    /// Conflict count at which the next reduction is due (`ReduceSchedule::Conflicts`).
    next_reduce: u64,
    /// Number of reductions so far.
    reductions: u64,
    /// Position in the current run of `ReduceSchedule::Conflicts` intervals.
    reduce_idx: u64,
    /// Length of the current run (0 before the first reduction).
    reduce_len: u64,
    /// Level-0 trail length at the last `simplify`.
    simp_assigns: usize,
    /// Propagation count before which `simplify` is not worth running again.
    simp_props: u64,
}

/// What stops a search early: deadline, interrupt flags and the conflict limit.
pub struct Limits {
    /// Deadline, checked every few hundred conflicts or decisions.
    pub deadline: Option<Instant>,
    /// Interrupt flag, checked like the deadline.
    pub interrupt: Option<Arc<AtomicBool>>,
    /// Portfolio flag: another thread finished first (not reported as an interrupt).
    pub portfolio_stop: Option<Arc<AtomicBool>>,
    /// Stop with `Unknown` once the engine's conflict count reaches this (the solver sets it at
    /// every call: the call's first conflict count plus `Config::conflict_limit`).
    pub conflict_limit: Option<u64>,
    /// Whether the last `search` stopped because the interrupt flag was raised.
    pub interrupted: bool,
    /// Whether the last `search` stopped at the conflict limit.
    pub conflict_hit: bool,
    /// Portfolio: a counter a peer bumps when it publishes a better optimization bound; the
    /// search stops with `Unknown` when it differs from `bound_seen`, setting `bound_news`.
    pub bound_gen: Option<Arc<std::sync::atomic::AtomicU64>>,
    /// The value of `bound_gen` the solver last acted on.
    pub bound_seen: u64,
    /// Whether the last `search` stopped for a new bound (not a limit).
    pub bound_news: bool,
}

/// Counters of the search, for statistics.
pub struct EngineStats {
    /// Statistics: decisions.
    pub decisions: u64,
    /// Statistics: conflicts.
    pub conflicts: u64,
    /// Statistics: restarts.
    pub num_restarts: u64,
    /// Statistics: propagated assignments.
    pub propagations: u64,
    /// Statistics: loop nogoods.
    pub loop_nogoods: u64,
    /// Problem clauses added.
    pub num_clauses: u64,
    /// Statistics: phase switches made.
    pub phase_switches: u64,
}

/// Search settings, set from `solve::Config` (`Settings::from_config`) and by the search profile.
pub struct Settings {
    /// When the learnt clause database is reduced.
    pub reduce: ReduceSchedule,
    /// Which learnt clauses a reduction deletes.
    pub deletion: Deletion,
    /// Random decision probability in 1/1000.
    pub random_permille: u32,
    /// Phase of a variable never assigned before.
    pub default_phase: bool,
    /// Phase of a new body variable (`new_body_var`): clasp's `--sign-def=asp` tries bodies
    /// true and atoms false.
    pub body_phase: bool,
    /// Save phases only on backjumps over more than this many levels (clasp
    /// `--save-progress`); 0 saves on every backtrack.
    pub save_progress: u32,
    /// Whether initial activities should still be set from clause occurrences (MOMS).
    pub init_moms: bool,
    /// Bump the variables of every loop nogood when it is learnt (clasp `--score-other=all`).
    pub score_other: bool,
    /// Learn unfounded sets as shared loop formulas (`loops`) rather than one clause per atom.
    pub shared_loops: bool,
    /// Choose the sign of a decision variable without a saved phase from its occurrences in
    /// learnt clauses (the polarity that satisfies more of them), as clasp's VSIDS does;
    /// ties fall back to the initial sign.
    pub sign_from_learnts: bool,
    /// Glucose restarts are postponed while the trail at a conflict is much longer than
    /// usual (Audemard and Simon's blocking: the search may be close to a model).
    pub restart_blocking: bool,
    /// After this many conflicts in one search call (without a model: a model ends the call),
    /// switch to clasp's phase handling until the call returns: every saved phase is
    /// forgotten, phases are saved only on backjumps over more than `PHASE_SWITCH_PROGRESS`
    /// levels, and unsaved ones come from the sign score (`sign_from_learnts`). The next call
    /// starts with the configured values again.
    pub phase_switch: Option<u64>,
}

/// Variable recycling: retired variables and variables free for reuse.
struct VarPool {
    /// Per variable: retired by `retire_vars` and not yet reusable.
    retired: Vec<bool>,
    /// Variables retired since the last level-0 simplification; that pass deletes every
    /// clause, learnt or not, that mentions one, and then frees them.
    dead_vars: Vec<Var>,
    /// Variables free for reuse by `new_var` (no clause, watch, weight constraint or
    /// assignment mentions them).
    free_vars: Vec<Var>,
}

impl Settings {
    /// The settings `config` gives, read in one place; the search profile may change some of
    /// them afterwards (`save_progress`, `sign_from_learnts`, `phase_switch`, which starts off).
    pub fn from_config(config: &Config) -> Settings {
        Settings {
            reduce: config.reduce,
            deletion: config.deletion,
            random_permille: config.random_freq_permille.min(1000),
            default_phase: !config.default_phase_false,
            body_phase: config.body_phase_true,
            save_progress: config.save_progress,
            init_moms: config.init_moms,
            score_other: config.score_other,
            shared_loops: config.shared_loops,
            sign_from_learnts: config.sign_from_learnts,
            restart_blocking: config.restart_blocking,
            phase_switch: None,
        }
    }
}

/// The CDCL engine, in parts (as varisat's solver context): each technique reads and writes
/// the parts it needs, and field access is direct (`self.asg.values[..]`).
pub struct Engine {
    /// The assignment: per-literal values, per-variable levels and reasons, the trail and the
    /// propagation queue.
    asg: Assignment,
    /// The decision heuristic: VSIDS activities and their heap, saved phases, the domain heuristic
    /// and random decisions.
    heur: Heuristic,
    /// The clause database: the arena of long clauses, the watch lists, learnt clauses and shared
    /// loop formulas.
    db: ClauseDb,
    /// The weight constraints and their per-variable occurrence lists.
    wc: WeightDb,
    /// Conflict analysis: the last conflict, the learnt clause, failed assumptions and scratch
    /// space.
    an: Analysis,
    /// The unfounded-set propagator and what decides when it reruns.
    uf: UfState,
    /// Restarts, learnt-clause reductions and level-0 simplifications: when each is due next.
    pub sched: Schedule,
    /// What stops a search early: deadline, interrupt flags, the conflict limit, and news of a
    /// better bound from a portfolio peer.
    pub limits: Limits,
    /// Counters of the search, for statistics.
    pub stats: EngineStats,
    /// Search settings, set from `solve::Config` (`Settings::from_config`) and by the search
    /// profile.
    pub settings: Settings,
    /// Variable recycling: retired variables and variables free for reuse.
    pool: VarPool,
    /// True once a conflict at level 0 was found.
    inconsistent: bool,
    /// Clause sharing in a portfolio: the shared numbering and the hub (`share`).
    share: share::Sharing,
    /// The external propagator (clingo's propagator interface), if one is installed.
    ext: Option<Box<external::External>>,
}

impl Default for Engine {
    fn default() -> Engine {
        Engine::new()
    }
}

impl Engine {
    /// An empty engine.
    pub fn new() -> Engine {
        Engine {
            asg: Assignment {
                values: Vec::new(),
                level: Vec::new(),
                reason: Vec::new(),
                stored_slot: Vec::new(),
                stored: Vec::new(),
                trail: Vec::new(),
                trail_lim: Vec::new(),
                qhead: 0,
                pf_head: 0,
            },
            heur: Heuristic {
                phase: Vec::new(),
                phase_saved: Vec::new(),
                dom_sign: Vec::new(),
                dom_order: Vec::new(),
                occ: Vec::new(),
                activity: Vec::new(),
                heap_pos: Vec::new(),
                heap: Vec::new(),
                decidable: Vec::new(),
                var_inc: 1.0,
                var_decay: 0.95,
                rng: 0x9E37_79B9_7F4A_7C15,
                phase_switched: None,
            },
            db: ClauseDb {
                watches: Vec::new(),
                arena: Vec::new(),
                wasted: 0,
                learnts: Vec::new(),
                loops: Loops::default(),
                cla_inc: 1.0,
                clause_buf: Vec::new(),
            },
            wc: WeightDb {
                weight_slot: Vec::new(),
                weight_watch: Vec::new(),
                weights: Vec::new(),
                free_weights: Vec::new(),
                epoch: 0,
            },
            an: Analysis {
                seen: Vec::new(),
                learnt: Vec::new(),
                to_clear: Vec::new(),
                min_stack: Vec::new(),
                min_buf: Vec::new(),
                level_seen: Vec::new(),
                lbd_stamp: 0,
                conflict: Vec::new(),
                failed: Vec::new(),
                conflict_trail: 0,
            },
            uf: UfState {
                unfounded: None,
                uf_relevant: Vec::new(),
                uf_clean_upto: 0,
                uf_dirty: true,
                stability: None,
            },
            sched: Schedule {
                restarts: Restarts::Glucose {
                    fast: 0.0,
                    slow: 0.0,
                    since: 0,
                    trail: 0.0,
                },
                max_learnts: 4000.0,
                next_reduce: 0,
                reductions: 0,
                reduce_idx: 0,
                reduce_len: 0,
                simp_assigns: 0,
                simp_props: 0,
            },
            limits: Limits {
                deadline: None,
                interrupt: None,
                portfolio_stop: None,
                conflict_limit: None,
                interrupted: false,
                conflict_hit: false,
                bound_gen: None,
                bound_seen: 0,
                bound_news: false,
            },
            stats: EngineStats {
                decisions: 0,
                conflicts: 0,
                num_restarts: 0,
                propagations: 0,
                loop_nogoods: 0,
                num_clauses: 0,
                phase_switches: 0,
            },
            settings: Settings {
                reduce: ReduceSchedule::Size,
                deletion: Deletion::Sorted,
                random_permille: 0,
                default_phase: false,
                body_phase: false,
                save_progress: 0,
                init_moms: false,
                score_other: false,
                shared_loops: false,
                sign_from_learnts: false,
                restart_blocking: false,
                phase_switch: None,
            },
            pool: VarPool {
                retired: Vec::new(),
                dead_vars: Vec::new(),
                free_vars: Vec::new(),
            },
            inconsistent: false,
            share: share::Sharing::default(),
            ext: None,
        }
    }

    /// Sets the VSIDS decay and the random seed.
    pub fn configure(&mut self, var_decay: f64, seed: u64) {
        self.heur.var_decay = var_decay.clamp(0.5, 0.999);
        self.reseed(seed);
    }

    /// Restarts the random generator from `seed`.
    pub fn reseed(&mut self, seed: u64) {
        self.heur.rng = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    }

    /// Number of variables.
    pub fn num_vars(&self) -> usize {
        self.asg.level.len()
    }

    /// Number of learnt constraints kept: long clauses and shared loop formulas.
    pub fn num_learnts(&self) -> usize {
        self.db.learnts.len() + self.db.loops.live
    }

    /// Between two solve calls: reduces the learnt clause database (as a search does, worst
    /// half first, glue and locked clauses kept) until it holds at most `cap` learnt
    /// constraints or a reduction deletes nothing. clasp likewise starts every solve call with
    /// a database limit set from the problem size, so that what many calls learnt does not
    /// make every later propagation slower.
    pub fn limit_learnts(&mut self, cap: usize) {
        self.backtrack(0);
        loop {
            let before = self.db.learnts.len() + self.db.loops.clauses;
            if before <= cap {
                return;
            }
            self.reduce_db();
            if self.db.learnts.len() + self.db.loops.clauses >= before {
                return;
            }
        }
    }

    /// What the engine holds now (a pass over the clauses and watch lists).
    pub fn size(&self) -> EngineSize {
        let mut clauses = 0;
        let mut pos = 0usize;
        while pos < self.db.arena.len() {
            let len = self.db.arena[pos] as usize;
            if self.db.arena[pos + 1] & (FLAG_DELETED | FLAG_LEARNT) == 0 {
                clauses += 1;
            }
            pos += HEADER + len;
        }
        let binary: usize = self
            .db
            .watches
            .iter()
            .map(|ws| ws.iter().filter(|w| w.cref == u32::MAX).count())
            .sum();
        EngineSize {
            vars: self.num_vars(),
            clauses: clauses + binary / 2,
            learnts: self.num_learnts(),
            weights: self.wc.weights.iter().filter(|c| !c.removed).count(),
            level0: self
                .asg
                .trail_lim
                .first()
                .copied()
                .unwrap_or(self.asg.trail.len()),
        }
    }

    /// Installs (or removes) the unfounded-set propagator; the next propagation rechecks the
    /// whole assignment.
    pub fn set_unfounded(&mut self, uf: Option<Unfounded>) {
        self.uf.uf_relevant.iter_mut().for_each(|x| *x = false);
        if let Some(u) = &uf {
            for v in u.relevant_vars() {
                self.uf.uf_relevant[v.index()] = true;
            }
        }
        self.uf.unfounded = uf;
        self.uf.uf_clean_upto = 0;
        self.uf.uf_dirty = true;
    }

    /// Installs (or removes) the stability check of non-head-cycle-free components; it counts
    /// the whole trail at the next propagation.
    pub fn set_stability(&mut self, st: Option<Stability>) {
        self.uf.stability = st.map(Box::new);
    }

    /// Whether the stability check passed for every component on the current assignment
    /// (true when none is installed).
    pub fn stability_verified(&self) -> bool {
        self.uf.stability.as_ref().is_none_or(|s| s.all_verified())
    }

    /// Component stability checks run, and how many found an unfounded set.
    pub fn stability_checks(&self) -> (u64, u64) {
        self.uf
            .stability
            .as_ref()
            .map_or((0, 0), |s| (s.checks, s.found))
    }

    /// Whether an unfounded-set propagator is installed (the program is not tight).
    pub fn has_unfounded(&self) -> bool {
        self.uf.unfounded.is_some()
    }

    /// After a search that answered [`SearchResult::Unsat`]: a subset of its assumptions that
    /// the constraints refute together (MiniSat's `analyzeFinal`), the one found false first;
    /// empty when the constraints alone are unsatisfiable. Meaningless after other answers.
    pub fn failed_assumptions(&self) -> &[Lit] {
        &self.an.failed
    }

    /// The value of a literal: `Some(true)`, `Some(false)` or `None`.
    pub fn value(&self, l: Lit) -> Option<bool> {
        match self.asg.values[l.code()] {
            1 => Some(true),
            -1 => Some(false),
            _ => None,
        }
    }

    /// Whether the engine is at decision level 0 and `l` is true (true in every assignment
    /// from now on): a clause with such a literal is one `add_clause` drops.
    #[inline]
    pub fn true_at_level0(&self, l: Lit) -> bool {
        self.asg.trail_lim.is_empty() && self.val(l) == 1
    }

    fn val(&self, l: Lit) -> i8 {
        self.asg.values[l.code()]
    }

    /// Unit propagation at decision level 0 (what clauses added before the search imply);
    /// false, and the engine inconsistent, on a conflict.
    pub(crate) fn propagate_root(&mut self) -> bool {
        if self.inconsistent {
            return false;
        }
        self.backtrack(0);
        if self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        true
    }

    /// True once a conflict was found at decision level 0: no assignment of the assumptions
    /// (nor of the externals, which are assumed) can give a model any more.
    pub fn is_inconsistent(&self) -> bool {
        self.inconsistent
    }

    /// The current decision level.
    pub fn decision_level(&self) -> u32 {
        self.asg.trail_lim.len() as u32
    }

    /// The decision literal of `level` (`1..=decision_level()`); `None` for a level outside
    /// that range or one an assumption already true left empty.
    pub(crate) fn decision_at(&self, level: u32) -> Option<Lit> {
        let start = *self.asg.trail_lim.get((level as usize).checked_sub(1)?)?;
        let l = *self.asg.trail.get(start)?;
        let i = l.var().index();
        (self.asg.level[i] == level && matches!(self.asg.reason[i], Reason::Decision)).then_some(l)
    }

    /// The assigned literals in order (the unfounded-set propagator reads what changed).
    pub fn trail(&self) -> &[Lit] {
        &self.asg.trail
    }

    /// The trail position where decision level `level` starts (0 for level 0, the trail's
    /// length past the current level).
    pub(crate) fn level_start(&self, level: u32) -> usize {
        match (level as usize).checked_sub(1) {
            None => 0,
            Some(i) => self
                .asg
                .trail_lim
                .get(i)
                .copied()
                .unwrap_or(self.asg.trail.len()),
        }
    }

    /// The decision level at which the variable of `l` was assigned.
    pub fn level_of(&self, l: Lit) -> u32 {
        self.asg.level[l.var().index()]
    }

    /// The literals that were decided (not implied) on the current trail, in order.
    pub fn decisions_on_trail(&self) -> Vec<Lit> {
        self.asg
            .trail_lim
            .iter()
            .filter_map(|&start| self.asg.trail.get(start).copied())
            .filter(|l| self.asg.reason[l.var().index()] == Reason::Decision)
            .collect()
    }

    fn assign(&mut self, l: Lit, reason: Reason) {
        let v = l.var().index();
        debug_assert_eq!(self.asg.values[l.code()], 0);
        self.asg.values[l.code()] = 1;
        self.asg.values[(!l).code()] = -1;
        self.asg.level[v] = self.decision_level();
        self.asg.reason[v] = reason;
        self.asg.trail.push(l);
        prefetch(self.db.watches.as_ptr().wrapping_add((!l).code()));
    }

    /// Undoes all assignments above `level`.
    pub fn backtrack(&mut self, level: u32) {
        if self.decision_level() <= level {
            return;
        }
        let start = self.asg.trail_lim[level as usize];
        self.wc.epoch += 1;
        if self.ext.is_some() {
            self.undo_external(start);
        }
        if let Some(st) = &mut self.uf.stability {
            st.undo(&self.asg.trail[start..], start);
        }
        let save = self.decision_level() - level > self.settings.save_progress;
        for i in (start..self.asg.trail.len()).rev() {
            let l = self.asg.trail[i];
            let v = l.var();
            let slot = self.wc.weight_slot[v.index()];
            if i < self.asg.qhead && slot != NO_SLOT {
                // Undo the weight counters of processed assignments.
                for k in 0..self.wc.weight_watch[slot as usize].len() {
                    let w = self.wc.weight_watch[slot as usize][k];
                    let c = &mut self.wc.weights[w.id as usize];
                    if w.lit == l {
                        c.sum_true -= w.weight;
                    } else {
                        c.sum_false -= w.weight;
                    }
                }
            }
            self.asg.values[l.code()] = 0;
            self.asg.values[(!l).code()] = 0;
            if save {
                self.save_phase(l);
            }
            if self.heur.heap_pos[v.index()] == NO_SLOT && self.heur.decidable[v.index()] {
                self.heap_insert(v);
            }
        }
        self.asg.trail.truncate(start);
        self.asg.trail_lim.truncate(level as usize);
        self.asg.qhead = self.asg.trail.len();
        self.asg.pf_head = self.asg.qhead;
        self.uf.uf_clean_upto = self.uf.uf_clean_upto.min(self.asg.trail.len());
    }
}

#[cfg(test)]
mod tests;
