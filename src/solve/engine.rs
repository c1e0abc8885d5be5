//! The CDCL core: assignment, two-watched-literal unit propagation, native weight constraints,
//! first-UIP conflict analysis with recursive clause minimisation, VSIDS with phase saving,
//! Luby and glucose-style restarts, and learnt clause deletion by LBD and activity.
//!
//! Follows MiniSat/Glucose as restated by varisat and kissat: per-variable data in parallel
//! vectors, long clauses in one `Vec<u32>` arena with a three-word header, binary clauses only in
//! the watch lists. Weight constraints `b <-> sum(w_i * l_i) >= k` are propagated natively with
//! explanations stored per variable (clasp's weight constraints, AIJ 2012 section 6). An optional
//! `Unfounded` propagator (source pointers) runs at every propagation fixpoint on the trail
//! segment assigned since its previous run and contributes loop nogoods as learnt clauses.
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

mod loops;

use super::config::{Deletion, ReduceSchedule};
use super::lit::{Lit, Var};
use super::unfounded::Unfounded;
use loops::{is_loop_watch, Loops};
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
    /// Implied with the explanation stored in `Engine::stored[var]` (weight constraints).
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
    /// The literal equivalent to the constraint.
    head: Lit,
    /// Literals with positive weights.
    lits: Vec<(Lit, u64)>,
    /// The lower bound.
    bound: u64,
    /// Detached by `remove_weight`: no longer watched or propagated.
    removed: bool,
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

/// How many trail positions ahead of the propagation queue head watch lists are prefetched.
const PREFETCH_AHEAD: usize = 4;

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

/// The CDCL engine.
pub struct Engine {
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
    /// Per variable: saved phase (last value).
    phase: Vec<bool>,
    /// Per variable: whether `phase` was saved by a backjump (not the initial sign).
    phase_saved: Vec<bool>,
    /// Per variable: occurrences in learnt clauses, +1 per positive and -1 per negative
    /// literal (clasp's sign score, used when `sign_from_learnts` is set).
    occ: Vec<i32>,
    /// Per variable: VSIDS activity.
    activity: Vec<f64>,
    /// Per variable: position in `heap`, or `NO_SLOT`.
    heap_pos: Vec<u32>,
    /// Per variable: whether it may be chosen as a decision.
    decidable: Vec<bool>,
    /// Per variable: scratch mark used by conflict analysis.
    seen: Vec<u8>,
    /// Per variable: its list in `weight_watch`, or `NO_SLOT` when the variable occurs in no
    /// weight constraint. Four bytes per variable, so that the (usually many) variables
    /// outside every weight constraint cost no `Vec` header, and their propagation and
    /// backtracking test one small word instead of loading a header from a cold cache line.
    weight_slot: Vec<u32>,
    /// Occurrences in weight constraints (the head occurs with weight 0), one list per
    /// variable that has a `weight_slot`.
    weight_watch: Vec<Vec<WeightWatch>>,
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
    /// Weight constraints.
    weights: Vec<WeightConstraint>,
    /// Assigned literals in order.
    trail: Vec<Lit>,
    /// Trail length at the start of each decision level.
    trail_lim: Vec<usize>,
    /// Next trail position to propagate.
    qhead: usize,
    /// Trail position up to which watch lists were prefetched (may lag behind `qhead`).
    pf_head: usize,
    /// Binary heap of decision candidates ordered by activity.
    heap: Vec<Var>,
    /// Activity increment.
    var_inc: f64,
    /// Activity decay factor.
    var_decay: f64,
    /// Clause activity increment.
    cla_inc: f64,
    /// True once a conflict at level 0 was found.
    inconsistent: bool,
    /// After a search that answered `Unsat` under assumptions: the assumptions (true on the
    /// trail, as assumed) that imply the failed one's complement, the failed one first; empty
    /// when no assumption took part (a level-0 conflict).
    failed: Vec<Lit>,
    /// Literals of the last conflict (all false).
    conflict: Vec<Lit>,
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
    /// Restart state.
    pub restarts: Restarts,
    /// Maximum number of learnt clauses before a reduction (`ReduceSchedule::Size`).
    max_learnts: f64,
    /// When the learnt clause database is reduced.
    pub reduce: ReduceSchedule,
    /// Conflict count at which the next reduction is due (`ReduceSchedule::Conflicts`).
    next_reduce: u64,
    /// Number of reductions so far.
    reductions: u64,
    /// Position in the current run of `ReduceSchedule::Conflicts` intervals.
    reduce_idx: u64,
    /// Length of the current run (0 before the first reduction).
    reduce_len: u64,
    /// Which learnt clauses a reduction deletes.
    pub deletion: Deletion,
    /// Pseudo-random state.
    rng: u64,
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
    /// Deadline, checked every few hundred conflicts or decisions.
    pub deadline: Option<Instant>,
    /// Interrupt flag, checked like the deadline.
    pub interrupt: Option<Arc<AtomicBool>>,
    /// Portfolio flag: another thread finished first (not reported as an interrupt).
    pub portfolio_stop: Option<Arc<AtomicBool>>,
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
    /// Whether the last `search` stopped because the interrupt flag was raised.
    pub interrupted: bool,
    /// Level-0 trail length at the last `simplify`.
    simp_assigns: usize,
    /// Propagation count before which `simplify` is not worth running again.
    simp_props: u64,
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
    /// Whether initial activities should still be set from clause occurrences (MOMS).
    pub init_moms: bool,
    /// Stop with `Unknown` after this many conflicts in total (clasp `--solve-limit`).
    pub conflict_limit: Option<u64>,
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
    /// Trail length at the last conflict, before backjumping.
    conflict_trail: usize,
    /// Per variable: retired by `retire_vars` and not yet reusable.
    retired: Vec<bool>,
    /// Variables retired since the last level-0 simplification; that pass deletes every
    /// clause, learnt or not, that mentions one, and then frees them.
    dead_vars: Vec<Var>,
    /// Variables free for reuse by `new_var` (no clause, watch, weight constraint or
    /// assignment mentions them).
    free_vars: Vec<Var>,
    /// Slots of removed weight constraints, reused by `add_weight`.
    free_weights: Vec<u32>,
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
            values: Vec::new(),
            level: Vec::new(),
            reason: Vec::new(),
            stored_slot: Vec::new(),
            stored: Vec::new(),
            phase: Vec::new(),
            phase_saved: Vec::new(),
            occ: Vec::new(),
            activity: Vec::new(),
            heap_pos: Vec::new(),
            decidable: Vec::new(),
            seen: Vec::new(),
            weight_slot: Vec::new(),
            weight_watch: Vec::new(),
            watches: Vec::new(),
            arena: Vec::new(),
            wasted: 0,
            learnts: Vec::new(),
            loops: Loops::default(),
            weights: Vec::new(),
            trail: Vec::new(),
            trail_lim: Vec::new(),
            qhead: 0,
            pf_head: 0,
            heap: Vec::new(),
            var_inc: 1.0,
            var_decay: 0.95,
            cla_inc: 1.0,
            inconsistent: false,
            failed: Vec::new(),
            conflict: Vec::new(),
            unfounded: None,
            uf_relevant: Vec::new(),
            uf_clean_upto: 0,
            uf_dirty: true,
            restarts: Restarts::Glucose {
                fast: 0.0,
                slow: 0.0,
                since: 0,
                trail: 0.0,
            },
            max_learnts: 4000.0,
            reduce: ReduceSchedule::Size,
            next_reduce: 0,
            reductions: 0,
            reduce_idx: 0,
            reduce_len: 0,
            deletion: Deletion::Sorted,
            rng: 0x9E37_79B9_7F4A_7C15,
            random_permille: 0,
            default_phase: false,
            body_phase: false,
            save_progress: 0,
            deadline: None,
            interrupt: None,
            portfolio_stop: None,
            decisions: 0,
            conflicts: 0,
            num_restarts: 0,
            propagations: 0,
            loop_nogoods: 0,
            num_clauses: 0,
            interrupted: false,
            simp_assigns: 0,
            simp_props: 0,
            learnt: Vec::new(),
            to_clear: Vec::new(),
            min_stack: Vec::new(),
            min_buf: Vec::new(),
            level_seen: Vec::new(),
            lbd_stamp: 0,
            init_moms: false,
            score_other: false,
            shared_loops: false,
            sign_from_learnts: false,
            restart_blocking: false,
            conflict_trail: 0,
            conflict_limit: None,
            retired: Vec::new(),
            dead_vars: Vec::new(),
            free_vars: Vec::new(),
            free_weights: Vec::new(),
        }
    }

    /// Sets the VSIDS decay and the random seed.
    pub fn configure(&mut self, var_decay: f64, seed: u64) {
        self.var_decay = var_decay.clamp(0.5, 0.999);
        self.rng = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    }

    /// Number of variables.
    pub fn num_vars(&self) -> usize {
        self.level.len()
    }

    /// Number of learnt constraints kept: long clauses and shared loop formulas.
    pub fn num_learnts(&self) -> usize {
        self.learnts.len() + self.loops.live
    }

    /// Between two solve calls: reduces the learnt clause database (as a search does, worst
    /// half first, glue and locked clauses kept) until it holds at most `cap` learnt
    /// constraints or a reduction deletes nothing. clasp likewise starts every solve call with
    /// a database limit set from the problem size, so that what many calls learnt does not
    /// make every later propagation slower.
    pub fn limit_learnts(&mut self, cap: usize) {
        self.backtrack(0);
        loop {
            let before = self.learnts.len() + self.loops.clauses;
            if before <= cap {
                return;
            }
            self.reduce_db();
            if self.learnts.len() + self.loops.clauses >= before {
                return;
            }
        }
    }

    /// What the engine holds now (a pass over the clauses and watch lists).
    pub fn size(&self) -> EngineSize {
        let mut clauses = 0;
        let mut pos = 0usize;
        while pos < self.arena.len() {
            let len = self.arena[pos] as usize;
            if self.arena[pos + 1] & (FLAG_DELETED | FLAG_LEARNT) == 0 {
                clauses += 1;
            }
            pos += HEADER + len;
        }
        let binary: usize = self
            .watches
            .iter()
            .map(|ws| ws.iter().filter(|w| w.cref == u32::MAX).count())
            .sum();
        EngineSize {
            vars: self.num_vars(),
            clauses: clauses + binary / 2,
            learnts: self.num_learnts(),
            weights: self.weights.iter().filter(|c| !c.removed).count(),
            level0: self.trail_lim.first().copied().unwrap_or(self.trail.len()),
        }
    }

    /// Reserves room for `additional` more variables in every per-variable (and per-literal)
    /// vector, so that translating a large program grows each vector once: grown by doubling,
    /// the abandoned smaller copies stay in the allocator's heap and count in the peak memory.
    pub fn reserve_vars(&mut self, additional: usize) {
        self.values.reserve(2 * additional);
        self.level.reserve(additional);
        self.reason.reserve(additional);
        self.stored_slot.reserve(additional);
        self.phase.reserve(additional);
        self.activity.reserve(additional);
        self.heap_pos.reserve(additional);
        self.decidable.reserve(additional);
        self.seen.reserve(additional);
        self.weight_slot.reserve(additional);
        self.uf_relevant.reserve(additional);
        self.watches.reserve(2 * additional);
        self.heap.reserve(additional);
    }

    /// Creates a new variable, decidable by default; a variable freed by `retire_vars` is
    /// reused when there is one.
    pub fn new_var(&mut self) -> Var {
        if let Some(v) = self.free_vars.pop() {
            let i = v.index();
            debug_assert!(self.values[v.positive().code()] == 0);
            debug_assert!(self.watches[v.positive().code()].is_empty());
            debug_assert!(self.watches[v.negative().code()].is_empty());
            self.retired[i] = false;
            self.level[i] = 0;
            self.reason[i] = Reason::Decision;
            self.phase[i] = self.default_phase;
            self.phase_saved[i] = false;
            self.occ[i] = 0;
            self.seen[i] = 0;
            self.uf_relevant[i] = false;
            self.activity[i] = 0.0;
            self.decidable[i] = true;
            if self.heap_pos[i] == NO_SLOT {
                self.heap_insert(v);
            } else {
                self.heap_down(self.heap_pos[i] as usize);
            }
            return v;
        }
        let v = Var::new(self.level.len());
        self.retired.push(false);
        self.values.push(0);
        self.values.push(0);
        self.level.push(0);
        self.reason.push(Reason::Decision);
        self.stored_slot.push(NO_SLOT);
        self.phase.push(self.default_phase);
        self.phase_saved.push(false);
        self.occ.push(0);
        self.activity.push(0.0);
        self.heap_pos.push(NO_SLOT);
        self.decidable.push(true);
        self.seen.push(0);
        self.weight_slot.push(NO_SLOT);
        self.uf_relevant.push(false);
        self.watches.push(Vec::new());
        self.watches.push(Vec::new());
        self.heap_insert(v);
        v
    }

    /// Creates a new variable standing for a rule body (or another conjunction); its initial
    /// phase is `body_phase`.
    pub fn new_body_var(&mut self) -> Var {
        let v = self.new_var();
        self.phase[v.index()] = self.body_phase;
        v
    }

    /// Excludes a variable from decisions (its value is always implied).
    pub fn set_decidable(&mut self, v: Var, decidable: bool) {
        self.decidable[v.index()] = decidable;
        if decidable {
            self.heap_insert(v);
        }
    }

    /// Retires variables that nothing will mention again (the guard of a finished call and
    /// the auxiliary variables of its constraints, whose weight constraints the caller removed).
    /// They stop being decided at once; the next level-0 simplification deletes every clause
    /// that mentions one, learnt clauses included, drops their level-0 assignments, and makes
    /// them free for `new_var`. Sound because each such variable either only occurs negated
    /// in clauses that hold for one call (a guard, false from now on), or was defined by a
    /// constraint the caller removed (a definition extends the program conservatively, so what
    /// was learnt without mentioning the variable stays a consequence of the rest).
    pub fn retire_vars(&mut self, vars: &[Var]) {
        for &v in vars {
            if !self.retired[v.index()] {
                self.retired[v.index()] = true;
                self.decidable[v.index()] = false;
                self.dead_vars.push(v);
            }
        }
    }

    /// Bumps the initial activity of a variable so it is decided early.
    pub fn bump_initial(&mut self, v: Var, amount: f64) {
        self.activity[v.index()] += amount;
        if self.heap_pos[v.index()] != NO_SLOT {
            self.heap_up(self.heap_pos[v.index()] as usize);
        }
    }

    /// Installs (or removes) the unfounded-set propagator; the next propagation rechecks the
    /// whole assignment.
    pub fn set_unfounded(&mut self, uf: Option<Unfounded>) {
        self.uf_relevant.iter_mut().for_each(|x| *x = false);
        if let Some(u) = &uf {
            for v in u.relevant_vars() {
                self.uf_relevant[v.index()] = true;
            }
        }
        self.unfounded = uf;
        self.uf_clean_upto = 0;
        self.uf_dirty = true;
    }

    /// Whether an unfounded-set propagator is installed (the program is not tight).
    pub fn has_unfounded(&self) -> bool {
        self.unfounded.is_some()
    }

    /// Whether a conflict at level 0 was derived: no more models under any assumption.
    pub fn is_inconsistent(&self) -> bool {
        self.inconsistent
    }

    /// After a search that answered [`SearchResult::Unsat`]: a subset of its assumptions that
    /// the constraints refute together (MiniSat's `analyzeFinal`), the one found false first;
    /// empty when the constraints alone are unsatisfiable. Meaningless after other answers.
    pub fn failed_assumptions(&self) -> &[Lit] {
        &self.failed
    }

    /// Fills `failed` when assumption `a` is found false at decision level
    /// `<= assumptions.len()`: walks the implication graph of `!a` back to the assumption
    /// decisions it rests on (every decision at these levels is an assumption).
    fn analyze_final(&mut self, a: Lit) {
        self.failed.clear();
        self.failed.push(a);
        let v0 = a.var();
        if self.level[v0.index()] == 0 {
            return;
        }
        let Some(&start) = self.trail_lim.first() else {
            return;
        };
        let mut marked: Vec<Var> = vec![v0];
        self.seen[v0.index()] = 1;
        let mut reason = Vec::new();
        for i in (start..self.trail.len()).rev() {
            let x = self.trail[i];
            let v = x.var();
            if self.seen[v.index()] == 0 {
                continue;
            }
            if matches!(self.reason[v.index()], Reason::Decision) {
                // An assumption (`!a` itself when both `a` and `!a` were assumed).
                self.failed.push(x);
                continue;
            }
            reason.clear();
            self.reason_lits(v, &mut reason);
            for &q in &reason {
                let w = q.var();
                if self.seen[w.index()] == 0 && self.level[w.index()] > 0 {
                    self.seen[w.index()] = 1;
                    marked.push(w);
                }
            }
        }
        for v in marked {
            self.seen[v.index()] = 0;
        }
    }

    /// The value of a literal: `Some(true)`, `Some(false)` or `None`.
    pub fn value(&self, l: Lit) -> Option<bool> {
        match self.values[l.code()] {
            1 => Some(true),
            -1 => Some(false),
            _ => None,
        }
    }

    fn val(&self, l: Lit) -> i8 {
        self.values[l.code()]
    }

    /// The current decision level.
    pub fn decision_level(&self) -> u32 {
        self.trail_lim.len() as u32
    }

    /// The assigned literals in order (the unfounded-set propagator reads what changed).
    pub fn trail(&self) -> &[Lit] {
        &self.trail
    }

    /// The decision level at which the variable of `l` was assigned.
    pub fn level_of(&self, l: Lit) -> u32 {
        self.level[l.var().index()]
    }

    /// The literals that were decided (not implied) on the current trail, in order.
    pub fn decisions_on_trail(&self) -> Vec<Lit> {
        self.trail_lim
            .iter()
            .filter_map(|&start| self.trail.get(start).copied())
            .filter(|l| self.reason[l.var().index()] == Reason::Decision)
            .collect()
    }

    fn assign(&mut self, l: Lit, reason: Reason) {
        let v = l.var().index();
        debug_assert_eq!(self.values[l.code()], 0);
        self.values[l.code()] = 1;
        self.values[(!l).code()] = -1;
        self.level[v] = self.decision_level();
        self.reason[v] = reason;
        self.trail.push(l);
        prefetch(self.watches.as_ptr().wrapping_add((!l).code()));
    }

    /// Undoes all assignments above `level`.
    pub fn backtrack(&mut self, level: u32) {
        if self.decision_level() <= level {
            return;
        }
        let start = self.trail_lim[level as usize];
        let save = self.decision_level() - level > self.save_progress;
        for i in (start..self.trail.len()).rev() {
            let l = self.trail[i];
            let v = l.var();
            let slot = self.weight_slot[v.index()];
            if i < self.qhead && slot != NO_SLOT {
                // Undo the weight counters of processed assignments.
                for k in 0..self.weight_watch[slot as usize].len() {
                    let w = self.weight_watch[slot as usize][k];
                    let c = &mut self.weights[w.id as usize];
                    if w.lit == l {
                        c.sum_true -= w.weight;
                    } else {
                        c.sum_false -= w.weight;
                    }
                }
            }
            self.values[l.code()] = 0;
            self.values[(!l).code()] = 0;
            if save {
                self.phase[v.index()] = !l.is_neg();
                self.phase_saved[v.index()] = true;
            }
            if self.heap_pos[v.index()] == NO_SLOT && self.decidable[v.index()] {
                self.heap_insert(v);
            }
        }
        self.trail.truncate(start);
        self.trail_lim.truncate(level as usize);
        self.qhead = self.trail.len();
        self.pf_head = self.qhead;
        self.uf_clean_upto = self.uf_clean_upto.min(self.trail.len());
    }

    // ---------------------------------------------------------------- clauses

    fn clause_len(&self, cref: ClauseRef) -> usize {
        self.arena[cref as usize] as usize
    }

    fn clause_lit(&self, cref: ClauseRef, i: usize) -> Lit {
        Lit::from_code(self.arena[cref as usize + HEADER + i])
    }

    fn clause_flags(&self, cref: ClauseRef) -> u32 {
        self.arena[cref as usize + 1]
    }

    fn alloc_clause(&mut self, lits: &[Lit], learnt: bool, lbd: u32) -> ClauseRef {
        let cref = self.arena.len() as u32;
        self.arena.push(lits.len() as u32);
        self.arena
            .push(if learnt { FLAG_LEARNT } else { 0 } | (lbd.min(1 << 20) << 2));
        self.arena.push(match self.deletion {
            Deletion::Sorted => 0f32.to_bits(),
            // As clasp: a new clause counts one use per restart so far, so that new clauses
            // outrank old ones whose counts were halved.
            Deletion::Basic => (1 + self.num_restarts).min(MAX_USES as u64) as u32,
        });
        self.arena.extend(lits.iter().map(|l| l.code() as u32));
        self.watches[(lits[0]).code()].push(Watch {
            cref,
            other: lits[1],
        });
        self.watches[(lits[1]).code()].push(Watch {
            cref,
            other: lits[0],
        });
        if learnt {
            self.learnts.push(cref);
        }
        cref
    }

    /// Watches the binary clause `a ∨ b` inline (no arena entry): each literal's list holds
    /// the other.
    fn watch_binary(&mut self, a: Lit, b: Lit) {
        self.watches[a.code()].push(Watch {
            cref: u32::MAX,
            other: b,
        });
        self.watches[b.code()].push(Watch {
            cref: u32::MAX,
            other: a,
        });
    }

    fn attach(&mut self, lits: &[Lit], learnt: bool, lbd: u32) -> Reason {
        if lits.len() == 2 {
            self.watch_binary(lits[0], lits[1]);
            Reason::Binary(lits[1])
        } else {
            Reason::Long(self.alloc_clause(lits, learnt, lbd))
        }
    }

    /// Adds a clause at decision level 0 (backtracking there first). Returns false when the
    /// engine became inconsistent.
    pub fn add_clause(&mut self, lits: &[Lit]) -> bool {
        self.backtrack(0);
        if self.inconsistent {
            return false;
        }
        let mut c: Vec<Lit> = lits.to_vec();
        c.sort();
        c.dedup();
        for w in c.windows(2) {
            if w[0] == !w[1] {
                return true;
            }
        }
        if c.iter().any(|&l| self.val(l) == 1) {
            return true;
        }
        c.retain(|&l| self.val(l) == 0);
        self.num_clauses += 1;
        match c.len() {
            0 => {
                self.inconsistent = true;
                false
            }
            1 => {
                self.assign(c[0], Reason::Decision);
                if self.propagate().is_some() {
                    self.inconsistent = true;
                    return false;
                }
                true
            }
            _ => {
                self.attach(&c, false, 0);
                true
            }
        }
    }

    /// Adds a clause that the current (total) assignment falsifies, such as the clause blocking
    /// an enumerated model's decisions, without leaving the search: backtracks only to the
    /// second-highest level of its literals, where the clause is unit and implies its
    /// highest-level literal's complement, so that `search_from(.., true)` goes on from there
    /// (clasp's enumeration likewise backtracks instead of starting over; starting each model
    /// from level 0 made 10-queens' 724 models cost 3x clasp's choices). Falls back to
    /// [`Engine::add_clause`] (level 0) when the clause is not of that shape. Returns false when
    /// the problem became inconsistent.
    pub fn add_clause_resuming(&mut self, lits: &[Lit]) -> bool {
        let mut c: Vec<Lit> = lits.to_vec();
        c.sort();
        c.dedup();
        let all_false = c.iter().all(|&l| self.val(l) == -1);
        let distinct = c.windows(2).all(|w| w[0] != !w[1]);
        if !all_false || !distinct || c.len() < 2 || self.decision_level() == 0 {
            return self.add_clause(lits);
        }
        c.sort_by_key(|&l| std::cmp::Reverse(self.level[l.var().index()]));
        let top = self.level[c[0].var().index()];
        let second = self.level[c[1].var().index()];
        if top == second || second == 0 {
            return self.add_clause(lits);
        }
        self.backtrack(second);
        self.num_clauses += 1;
        // Now c[0] is unassigned and the rest false: the clause is asserting, never conflicting.
        let conflicting = self.add_clause_in_search(&mut c, false);
        debug_assert!(!conflicting);
        true
    }

    /// Adds a clause while a search is in progress (loop nogoods): watches are chosen so that
    /// the clause is propagating or conflicting as appropriate. Returns true when the clause is
    /// conflicting under the current assignment (the conflict is then in `self.conflict`).
    fn add_clause_in_search(&mut self, lits: &mut [Lit], learnt: bool) -> bool {
        // Order: true literals first, then unassigned, then false by decreasing level.
        lits.sort_by_key(|&l| {
            let v = self.val(l);
            match v {
                1 => 0u64,
                0 => 1,
                _ => 2 + (u32::MAX - self.level[l.var().index()]) as u64,
            }
        });
        if lits.is_empty() {
            self.conflict.clear();
            return true;
        }
        if lits.len() == 1 {
            // A unit clause: it holds at level 0; assign it there through a restart.
            let l = lits[0];
            if self.level_of(l) == 0 && self.val(l) == 1 {
                return false;
            }
            if self.val(l) == -1 && self.level_of(l) == 0 {
                self.conflict.clear();
                self.conflict.push(l);
                return true;
            }
            self.backtrack(0);
            self.assign(l, Reason::Decision);
            return false;
        }
        if self.val(lits[0]) == 0 && self.val(lits[1]) == -1 {
            // Asserting: imply lits[0] at the level where the clause became unit, so the
            // implication survives backtracking above that level (the watches stay valid).
            let level = self.level[lits[1].var().index()];
            if level < self.decision_level() {
                self.backtrack(level);
            }
        }
        let reason = self.attach(lits, learnt, lits.len() as u32);
        let (v0, v1) = (self.val(lits[0]), self.val(lits[1]));
        if v0 == -1 {
            self.conflict.clear();
            self.conflict.extend_from_slice(lits);
            return true;
        }
        if v0 == 0 && v1 == -1 {
            let r = match reason {
                Reason::Binary(_) => Reason::Binary(lits[1]),
                other => other,
            };
            self.assign(lits[0], r);
        }
        false
    }

    /// Adds a native weight constraint `head <-> sum(w * l) >= bound` at level 0. Weights may be
    /// negative; they are normalised by negating their literals.
    pub fn add_weight(&mut self, head: Lit, lits: &[(Lit, i64)], bound: i64) -> bool {
        self.backtrack(0);
        let mut bound = bound as i128;
        let mut norm: Vec<(Lit, u64)> = Vec::new();
        for &(l, w) in lits {
            if w > 0 {
                norm.push((l, w as u64));
            } else if w < 0 {
                // w * l = w - w * (not l), so move -w to the other side.
                bound -= w as i128;
                norm.push((!l, (-(w as i128)) as u64));
            }
        }
        if bound <= 0 {
            return self.add_clause(&[head]);
        }
        let total: i128 = norm.iter().map(|&(_, w)| w as i128).sum();
        if total < bound {
            return self.add_clause(&[!head]);
        }
        let bound = bound as u64;
        norm.sort_by_key(|x| std::cmp::Reverse(x.1));
        if self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        let id = match self.free_weights.last() {
            Some(&id) => id,
            None => self.weights.len() as u32,
        };
        let (mut sum_true, mut sum_false) = (0u64, 0u64);
        for &(l, w) in &norm {
            let slot = self.weight_slot_of(l.var());
            self.weight_watch[slot].push(WeightWatch {
                id,
                lit: l,
                weight: w,
            });
            match self.val(l) {
                1 => sum_true += w,
                -1 => sum_false += w,
                _ => {}
            }
        }
        let slot = self.weight_slot_of(head.var());
        self.weight_watch[slot].push(WeightWatch {
            id,
            lit: head,
            weight: 0,
        });
        let total = norm.iter().map(|&(_, w)| w).sum();
        let max_weight = norm.iter().map(|&(_, w)| w).max().unwrap_or(0);
        let c = WeightConstraint {
            sum_true,
            sum_false,
            total,
            max_weight,
            head,
            lits: norm,
            bound,
            removed: false,
        };
        if id as usize == self.weights.len() {
            self.weights.push(c);
        } else {
            self.free_weights.pop();
            self.weights[id as usize] = c;
        }
        self.num_clauses += 1;
        if self.propagate_weight(id as usize) || self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        true
    }

    /// The index in `weight_watch` of `v`'s occurrence list, made on first use.
    fn weight_slot_of(&mut self, v: Var) -> usize {
        if self.weight_slot[v.index()] == NO_SLOT {
            self.weight_slot[v.index()] = self.weight_watch.len() as u32;
            self.weight_watch.push(Vec::new());
        }
        self.weight_slot[v.index()] as usize
    }

    /// Detaches the weight constraint whose literal is `head` (if `add_weight` made one), at
    /// level 0. Its head variable becomes unconstrained by it; clauses learnt with its help
    /// stay valid for every assignment of the other variables (the constraint only defined
    /// `head`), so callers may retire auxiliary bounds this way once nothing reads `head`.
    pub fn remove_weight(&mut self, head: Lit) {
        self.backtrack(0);
        // The constraint is found through its head's occurrence (weight 0, which no body
        // literal has); its slot is reused by a later `add_weight`.
        let slot = self.weight_slot[head.var().index()];
        if slot == NO_SLOT {
            return;
        }
        let Some(id) = self.weight_watch[slot as usize]
            .iter()
            .find(|w| w.weight == 0 && w.lit == head && !self.weights[w.id as usize].removed)
            .map(|w| w.id as usize)
        else {
            return;
        };
        self.free_weights.push(id as u32);
        let c = &mut self.weights[id];
        c.removed = true;
        let lits = std::mem::take(&mut c.lits);
        let idu = id as u32;
        for v in lits.iter().map(|&(l, _)| l.var()).chain([head.var()]) {
            // The slot stays (possibly with an empty list): propagation then finds nothing.
            let slot = self.weight_slot[v.index()];
            if slot != NO_SLOT {
                self.weight_watch[slot as usize].retain(|w| w.id != idu);
            }
        }
    }

    // ---------------------------------------------------------------- propagation

    /// Unit propagation to fixpoint, including weight constraints and unfounded sets. Returns
    /// `Some(())` on conflict, with the falsified clause in `self.conflict`.
    pub fn propagate(&mut self) -> Option<()> {
        loop {
            if self.propagate_units() {
                return Some(());
            }
            self.unfounded.as_ref()?;
            let start = self.uf_clean_upto.min(self.trail.len());
            if !self.uf_dirty
                && !self.trail[start..]
                    .iter()
                    .any(|l| self.uf_relevant[l.var().index()])
            {
                self.uf_clean_upto = self.trail.len();
                return None;
            }
            let mut uf = self.unfounded.take().expect("checked above");
            let sets = uf.check(self, start);
            self.unfounded = Some(uf);
            // The propagator has seen everything up to here; the nogoods' own assignments
            // (and a backjump they may cause) start the next segment.
            self.uf_clean_upto = self.trail.len();
            self.uf_dirty = false;
            if sets.is_empty() {
                return None;
            }
            for set in sets {
                if self.add_loop_set(&set.atoms, &set.ext) {
                    return Some(());
                }
            }
        }
    }

    /// Clause and weight propagation; returns true on conflict.
    #[inline(never)]
    fn propagate_units(&mut self) -> bool {
        while self.qhead < self.trail.len() {
            let p = self.trail[self.qhead];
            self.qhead += 1;
            self.propagations += 1;
            // The watch lists of the next few literals: their headers were prefetched when
            // they were assigned; now start loading the lists themselves.
            let end = self.trail.len().min(self.qhead + PREFETCH_AHEAD);
            let mut k = self.pf_head.max(self.qhead);
            while k < end {
                prefetch(self.watches[(!self.trail[k]).code()].as_ptr());
                k += 1;
            }
            self.pf_head = k;
            let slot = self.weight_slot[p.var().index()];
            if slot == NO_SLOT {
                if self.propagate_clauses(p) {
                    return true;
                }
                continue;
            }
            // Count `p` in its weight constraints now: backtracking undoes every processed
            // position, even when a clause conflict stops this iteration early.
            let slot = slot as usize;
            for k in 0..self.weight_watch[slot].len() {
                let w = self.weight_watch[slot][k];
                let c = &mut self.weights[w.id as usize];
                if w.lit == p {
                    c.sum_true += w.weight;
                } else {
                    c.sum_false += w.weight;
                }
            }
            if self.propagate_clauses(p) {
                return true;
            }
            let wl = std::mem::take(&mut self.weight_watch[slot]);
            let mut wconflict = false;
            for w in &wl {
                if self.weight_may_propagate(w.id as usize) && self.propagate_weight(w.id as usize)
                {
                    wconflict = true;
                    break;
                }
            }
            self.weight_watch[slot] = wl;
            if wconflict {
                return true;
            }
        }
        false
    }

    /// Visits the watch list of `!p` after `p` became true: binary clauses assign or conflict
    /// directly, long clauses are skipped when their blocker is true, else get a new watch or
    /// assign their other watched literal. Returns true on conflict (in `self.conflict`).
    fn propagate_clauses(&mut self, p: Lit) -> bool {
        let false_lit = !p;
        let false_code = false_lit.code() as u32;
        let dl = self.trail_lim.len() as u32;
        let mut ws = std::mem::take(&mut self.watches[false_lit.code()]);
        // Disjoint borrows of the fields the loop touches, so that assignments do not force
        // the compiler to reload every vector through `self`.
        let Engine {
            values,
            level,
            reason,
            trail,
            arena,
            watches,
            conflict: conflict_lits,
            ..
        } = self;
        let n = ws.len();
        let mut i = 0;
        let mut j = 0;
        let mut conflict = false;
        let mut loop_watches = false;
        while i < n {
            let w = ws[i];
            i += 1;
            let bv = values[w.other.code()];
            if bv == 1 {
                ws[j] = w;
                j += 1;
                continue;
            }
            if w.cref == u32::MAX {
                ws[j] = w;
                j += 1;
                if bv == 0 {
                    let l = w.other;
                    values[l.code()] = 1;
                    values[(!l).code()] = -1;
                    level[l.var().index()] = dl;
                    reason[l.var().index()] = Reason::Binary(false_lit);
                    trail.push(l);
                    prefetch(watches.as_ptr().wrapping_add((!l).code()));
                } else {
                    conflict_lits.clear();
                    conflict_lits.push(w.other);
                    conflict_lits.push(false_lit);
                    conflict = true;
                    break;
                }
                continue;
            }
            if is_loop_watch(w.cref) {
                // Loop formulas are visited after the clauses (`propagate_loops`).
                ws[j] = w;
                j += 1;
                loop_watches = true;
                continue;
            }
            let cref = w.cref;
            debug_assert!(
                arena[cref as usize + 1] & FLAG_DELETED == 0,
                "watches of deleted clauses are removed"
            );
            let len = arena[cref as usize] as usize;
            let base = cref as usize + HEADER;
            let c = &mut arena[base..base + len];
            // Make sure the false literal is at position 1.
            if c[0] == false_code {
                c.swap(0, 1);
            }
            let first = Lit::from_code(c[0]);
            let fv = values[first.code()];
            if first != w.other && fv == 1 {
                ws[j] = Watch { cref, other: first };
                j += 1;
                continue;
            }
            let mut found = 0;
            for k in 2..len {
                if values[c[k] as usize] != -1 {
                    found = k;
                    break;
                }
            }
            if found != 0 {
                c.swap(1, found);
                watches[c[1] as usize].push(Watch { cref, other: first });
                continue;
            }
            ws[j] = Watch { cref, other: first };
            j += 1;
            if fv == -1 {
                conflict_lits.clear();
                conflict_lits.extend(c.iter().map(|&x| Lit::from_code(x)));
                conflict = true;
                break;
            }
            values[first.code()] = 1;
            values[(!first).code()] = -1;
            level[first.var().index()] = dl;
            reason[first.var().index()] = Reason::Long(cref);
            trail.push(first);
            prefetch(watches.as_ptr().wrapping_add((!first).code()));
        }
        keep_unvisited(&mut ws, i, j);
        // No watch of `false_lit` was added during the loop: new watches go to non-false
        // literals only.
        debug_assert!(self.watches[false_lit.code()].is_empty());
        self.watches[false_lit.code()] = ws;
        if loop_watches && !conflict {
            return self.propagate_loops(false_lit);
        }
        conflict
    }

    /// Whether the counters allow a propagation or conflict of the constraint (cheap test).
    fn weight_may_propagate(&self, id: usize) -> bool {
        let c = &self.weights[id];
        let max = c.total - c.sum_false;
        if c.sum_true >= c.bound || max < c.bound {
            return true;
        }
        match self.val(c.head) {
            1 => max.saturating_sub(c.max_weight) < c.bound,
            -1 => c.sum_true + c.max_weight >= c.bound,
            _ => false,
        }
    }

    /// Evaluates one weight constraint; returns true on conflict. Decisions use the counters
    /// (which lag behind the values only for assignments not yet processed, and only in the
    /// safe direction: fewer true and false literals), so every inference is sound; the
    /// remaining ones happen when the lagging assignments are processed. Literals are sorted by
    /// decreasing weight, so the scans stop at the first literal too light to matter.
    fn propagate_weight(&mut self, id: usize) -> bool {
        let c = &self.weights[id];
        let head = c.head;
        let bound = c.bound;
        let sum_true = c.sum_true;
        let max = c.total - c.sum_false;
        let hv = self.val(head);
        if sum_true >= bound {
            match hv {
                1 => {}
                0 => self.assign_weight_implied(head, None, id, true),
                _ => {
                    let mut r = std::mem::take(&mut self.conflict);
                    r.clear();
                    r.push(head);
                    self.weight_lits(id, true, &mut r);
                    self.conflict = r;
                    return true;
                }
            }
            return false;
        }
        if max < bound {
            match hv {
                -1 => {}
                0 => self.assign_weight_implied(!head, None, id, false),
                _ => {
                    let mut r = std::mem::take(&mut self.conflict);
                    r.clear();
                    r.push(!head);
                    self.weight_lits(id, false, &mut r);
                    self.conflict = r;
                    return true;
                }
            }
            return false;
        }
        if hv == 1 {
            // Every unassigned literal whose loss would drop the maximum below the bound must
            // hold: weight > max - bound. The explanation (the false literals) does not change
            // while these literals become true.
            let slack = max - bound;
            for k in 0..self.weights[id].lits.len() {
                let (l, w) = self.weights[id].lits[k];
                if w <= slack {
                    break;
                }
                if self.val(l) == 0 {
                    self.assign_weight_implied(l, Some(!head), id, false);
                }
            }
        } else if hv == -1 {
            // Every unassigned literal that would reach the bound must be false:
            // weight >= bound - sum_true. The explanation (the true literals) does not change
            // while these literals become false.
            let gap = bound - sum_true;
            for k in 0..self.weights[id].lits.len() {
                let (l, w) = self.weights[id].lits[k];
                if w < gap {
                    break;
                }
                if self.val(l) == 0 {
                    self.assign_weight_implied(!l, Some(head), id, true);
                }
            }
        }
        false
    }

    /// Appends the currently false literals of constraint `id` to `out`, or, when `of_true`,
    /// the negations of its currently true literals (both are false literals).
    fn weight_lits(&self, id: usize, of_true: bool, out: &mut Vec<Lit>) {
        let want: i8 = if of_true { 1 } else { -1 };
        for &(l, _) in &self.weights[id].lits {
            if self.values[l.code()] == want {
                out.push(if of_true { !l } else { l });
            }
        }
    }

    /// Assigns `l` with a stored explanation: `l`, then `extra` if given, then the literals of
    /// `weight_lits(id, of_true)`. Reuses the variable's explanation buffer.
    fn assign_weight_implied(&mut self, l: Lit, extra: Option<Lit>, id: usize, of_true: bool) {
        let v = l.var().index();
        if self.stored_slot[v] == NO_SLOT {
            self.stored_slot[v] = self.stored.len() as u32;
            self.stored.push(Vec::new());
        }
        let slot = self.stored_slot[v] as usize;
        let mut r = std::mem::take(&mut self.stored[slot]);
        r.clear();
        r.push(l);
        r.extend(extra);
        self.weight_lits(id, of_true, &mut r);
        self.stored[slot] = r;
        self.assign(l, Reason::Stored);
    }

    /// Appends the false literals of the reason of `v` (excluding `v` itself) to `out`.
    fn reason_lits(&self, v: Var, out: &mut Vec<Lit>) {
        match self.reason[v.index()] {
            Reason::Decision => {}
            Reason::Binary(l) => out.push(l),
            Reason::Long(cref) => {
                // The implied literal is at position 0 of its reason (module invariant).
                let c = cref as usize;
                let lits = &self.arena[c + HEADER..c + HEADER + self.arena[c] as usize];
                debug_assert_eq!(Lit::from_code(lits[0]).var(), v);
                out.extend(lits[1..].iter().map(|&x| Lit::from_code(x)));
            }
            Reason::Stored => out.extend(
                self.stored[self.stored_slot[v.index()] as usize]
                    .iter()
                    .copied()
                    .filter(|l| l.var() != v),
            ),
            Reason::Loop(id) => self.loop_reason_lits(id, v, out),
        }
    }

    // ---------------------------------------------------------------- analysis

    /// First-UIP analysis of `self.conflict`; leaves the learnt clause in `self.learnt`
    /// (asserting literal first, a literal of the backjump level second) and returns the
    /// backjump level. Works in reused buffers: no allocation per conflict once they are warm.
    fn analyze(&mut self) -> u32 {
        let current = self.decision_level();
        let mut learnt = std::mem::take(&mut self.learnt);
        learnt.clear();
        learnt.push(Lit::from_code(0));
        let mut counter = 0usize;
        let mut index = self.trail.len();
        let mut clause = std::mem::take(&mut self.conflict);
        let mut to_clear = std::mem::take(&mut self.to_clear);
        to_clear.clear();
        let mut p: Option<Lit> = None;
        loop {
            for &q in &clause {
                if Some(q) == p.map(|x| !x) || Some(q) == p {
                    continue;
                }
                let v = q.var();
                if self.seen[v.index()] == 0 && self.level[v.index()] > 0 {
                    self.seen[v.index()] = 1;
                    to_clear.push(v);
                    self.bump_var(v);
                    if self.level[v.index()] >= current {
                        counter += 1;
                    } else {
                        learnt.push(q);
                    }
                }
            }
            // Next literal of the current level on the trail.
            loop {
                index -= 1;
                if self.seen[self.trail[index].var().index()] != 0 {
                    break;
                }
            }
            let pl = self.trail[index];
            p = Some(pl);
            counter -= 1;
            if counter == 0 {
                learnt[0] = !pl;
                break;
            }
            clause.clear();
            match self.reason[pl.var().index()] {
                Reason::Long(cref) => {
                    self.bump_clause(cref);
                    self.update_lbd(cref, pl);
                }
                Reason::Loop(id) => self.bump_loop(id),
                _ => {}
            }
            // The implied literal itself is not added, and the filter above skips it.
            self.reason_lits(pl.var(), &mut clause);
        }
        self.conflict = clause;
        // Recursive minimisation: drop literals implied by the others.
        let mut abstract_levels = 0u64;
        for &l in &learnt[1..] {
            abstract_levels |= 1u64 << (self.level[l.var().index()] & 63);
        }
        let mut kept = 1;
        for k in 1..learnt.len() {
            let l = learnt[k];
            if matches!(self.reason[l.var().index()], Reason::Decision)
                || !self.redundant(l, abstract_levels, &mut to_clear)
            {
                learnt[kept] = l;
                kept += 1;
            }
        }
        learnt.truncate(kept);
        for &l in &learnt {
            let v = l.var();
            self.occ[v.index()] += if l.is_neg() { -1 } else { 1 };
        }
        for &v in &to_clear {
            self.seen[v.index()] = 0;
        }
        self.to_clear = to_clear;
        // Put a literal of the highest remaining level second.
        let mut bt = 0;
        if learnt.len() > 1 {
            let mut best = 1;
            for k in 2..learnt.len() {
                if self.level[learnt[k].var().index()] > self.level[learnt[best].var().index()] {
                    best = k;
                }
            }
            learnt.swap(1, best);
            bt = self.level[learnt[1].var().index()];
        }
        self.learnt = learnt;
        bt
    }

    /// Whether `l` (false, in the learnt clause) is implied by other literals of the clause.
    fn redundant(&mut self, l: Lit, abstract_levels: u64, to_clear: &mut Vec<Var>) -> bool {
        let mut stack = std::mem::take(&mut self.min_stack);
        let mut buf = std::mem::take(&mut self.min_buf);
        stack.clear();
        stack.push(l);
        let top = to_clear.len();
        let mut result = true;
        'outer: while let Some(q) = stack.pop() {
            buf.clear();
            if self.deletion == Deletion::Basic {
                // clasp counts a use of a clause in minimisation as in resolution.
                if let Reason::Long(cref) = self.reason[q.var().index()] {
                    self.bump_clause(cref);
                }
            }
            self.reason_lits(q.var(), &mut buf);
            for &r in &buf {
                let v = r.var();
                if self.seen[v.index()] != 0 || self.level[v.index()] == 0 {
                    continue;
                }
                let decision = matches!(self.reason[v.index()], Reason::Decision);
                if !decision && (abstract_levels >> (self.level[v.index()] & 63)) & 1 == 1 {
                    self.seen[v.index()] = 1;
                    to_clear.push(v);
                    stack.push(r);
                } else {
                    for w in to_clear.drain(top..) {
                        self.seen[w.index()] = 0;
                    }
                    result = false;
                    break 'outer;
                }
            }
        }
        self.min_stack = stack;
        self.min_buf = buf;
        result
    }

    /// Lowers the stored LBD of a learnt clause met in analysis when its literals now span
    /// fewer levels (clasp `--update-lbd=less`), so reductions keep clauses that became good.
    /// Under `Deletion::Basic` the levels are counted over the reason literals only (without
    /// the implied literal `implied`), as clasp does.
    fn update_lbd(&mut self, cref: ClauseRef, implied: Lit) {
        let flags = self.clause_flags(cref);
        let old = flags >> 2;
        if flags & FLAG_LEARNT == 0 || old <= 2 {
            return;
        }
        self.lbd_stamp += 1;
        let stamp = self.lbd_stamp;
        let len = self.clause_len(cref);
        let mut n = 0;
        let skip_implied = self.deletion == Deletion::Basic;
        for k in 0..len {
            let l = self.clause_lit(cref, k);
            if skip_implied && l == implied {
                continue;
            }
            let lv = self.level[l.var().index()] as usize;
            if lv >= self.level_seen.len() {
                self.level_seen.resize(lv + 1, 0);
            }
            if self.level_seen[lv] != stamp {
                self.level_seen[lv] = stamp;
                n += 1;
                if n >= old {
                    return;
                }
            }
        }
        self.arena[cref as usize + 1] = (flags & 3) | (n << 2);
    }

    /// Number of distinct decision levels among `lits` (literal block distance).
    fn lbd(&mut self, lits: &[Lit]) -> u32 {
        self.lbd_stamp += 1;
        let stamp = self.lbd_stamp;
        let mut n = 0;
        for l in lits {
            let lv = self.level[l.var().index()] as usize;
            if lv >= self.level_seen.len() {
                self.level_seen.resize(lv + 1, 0);
            }
            if self.level_seen[lv] != stamp {
                self.level_seen[lv] = stamp;
                n += 1;
            }
        }
        n
    }

    // ---------------------------------------------------------------- heuristic

    fn bump_var(&mut self, v: Var) {
        let a = &mut self.activity[v.index()];
        *a += self.var_inc;
        if *a > 1e100 {
            for x in self.activity.iter_mut() {
                *x *= 1e-100;
            }
            self.var_inc *= 1e-100;
        }
        if self.heap_pos[v.index()] != NO_SLOT {
            self.heap_up(self.heap_pos[v.index()] as usize);
        }
    }

    fn bump_clause(&mut self, cref: ClauseRef) {
        if self.clause_flags(cref) & FLAG_LEARNT == 0 {
            return;
        }
        let i = cref as usize + 2;
        if self.deletion == Deletion::Basic {
            self.arena[i] = (self.arena[i] + 1).min(MAX_USES);
            return;
        }
        let a = f32::from_bits(self.arena[i]) + self.cla_inc as f32;
        self.arena[i] = a.to_bits();
        if a > 1e20 {
            self.rescale_clause_activities();
        }
    }

    /// Scales every learnt clause's and loop formula's activity, and the increment, by 1e-20.
    /// Under `Deletion::Basic` the clauses hold use counters, which are left alone.
    fn rescale_clause_activities(&mut self) {
        if self.deletion == Deletion::Sorted {
            for &c in &self.learnts {
                let k = c as usize + 2;
                self.arena[k] = (f32::from_bits(self.arena[k]) * 1e-20).to_bits();
            }
        }
        self.rescale_loop_activities();
        self.cla_inc *= 1e-20;
    }

    fn heap_less(&self, a: Var, b: Var) -> bool {
        self.activity[a.index()] > self.activity[b.index()]
    }

    fn heap_insert(&mut self, v: Var) {
        if self.heap_pos[v.index()] != NO_SLOT || !self.decidable[v.index()] {
            return;
        }
        self.heap.push(v);
        let i = self.heap.len() - 1;
        self.heap_pos[v.index()] = i as u32;
        self.heap_up(i);
    }

    fn heap_up(&mut self, mut i: usize) {
        let v = self.heap[i];
        while i > 0 {
            let parent = (i - 1) / 2;
            if !self.heap_less(v, self.heap[parent]) {
                break;
            }
            self.heap[i] = self.heap[parent];
            self.heap_pos[self.heap[i].index()] = i as u32;
            i = parent;
        }
        self.heap[i] = v;
        self.heap_pos[v.index()] = i as u32;
    }

    fn heap_down(&mut self, mut i: usize) {
        let v = self.heap[i];
        let n = self.heap.len();
        loop {
            let l = 2 * i + 1;
            if l >= n {
                break;
            }
            let r = l + 1;
            let c = if r < n && self.heap_less(self.heap[r], self.heap[l]) {
                r
            } else {
                l
            };
            if !self.heap_less(self.heap[c], v) {
                break;
            }
            self.heap[i] = self.heap[c];
            self.heap_pos[self.heap[i].index()] = i as u32;
            i = c;
        }
        self.heap[i] = v;
        self.heap_pos[v.index()] = i as u32;
    }

    fn heap_pop(&mut self) -> Option<Var> {
        if self.heap.is_empty() {
            return None;
        }
        let top = self.heap[0];
        let last = self.heap.pop().expect("non-empty heap");
        self.heap_pos[top.index()] = NO_SLOT;
        if !self.heap.is_empty() {
            self.heap[0] = last;
            self.heap_pos[last.index()] = 0;
            self.heap_down(0);
        }
        Some(top)
    }

    fn next_random(&mut self) -> u64 {
        // xorshift64*.
        self.rng ^= self.rng >> 12;
        self.rng ^= self.rng << 25;
        self.rng ^= self.rng >> 27;
        self.rng.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// The sign to decide `v` with: its saved phase, else (with `sign_from_learnts`) the
    /// polarity occurring more often in learnt clauses, else its initial sign.
    fn decision_sign(&self, v: Var) -> bool {
        let i = v.index();
        if self.sign_from_learnts && !self.phase_saved[i] && self.occ[i] != 0 {
            return self.occ[i] > 0;
        }
        self.phase[i]
    }

    fn pick_branch(&mut self) -> Option<Lit> {
        if self.random_permille > 0
            && !self.heap.is_empty()
            && self.next_random() % 1000 < self.random_permille as u64
        {
            let k = (self.next_random() % self.heap.len() as u64) as usize;
            let v = self.heap[k];
            if self.val(v.positive()) == 0 && self.decidable[v.index()] {
                return Some(Lit::new(v, self.decision_sign(v)));
            }
        }
        while let Some(v) = self.heap_pop() {
            if self.val(v.positive()) == 0 && self.decidable[v.index()] {
                return Some(Lit::new(v, self.decision_sign(v)));
            }
        }
        None
    }

    // ---------------------------------------------------------------- learnt clause database

    fn locked(&self, cref: ClauseRef) -> bool {
        let l = self.clause_lit(cref, 0);
        self.val(l) == 1 && self.reason[l.var().index()] == Reason::Long(cref)
    }

    fn reduce_db(&mut self) {
        // Loop formulas first: the passes over the watch lists below drop their watches.
        self.reduce_loops();
        match self.deletion {
            Deletion::Sorted => self.reduce_sorted(),
            Deletion::Basic => self.reduce_basic(),
        }
        if self.wasted * 2 > self.arena.len() {
            self.collect_garbage();
        } else {
            // Propagation never looks at deleted clauses: drop their watches now.
            let (arena, loops) = (&self.arena, &self.loops);
            for ws in self.watches.iter_mut() {
                ws.retain(|w| {
                    w.cref == u32::MAX
                        || if is_loop_watch(w.cref) {
                            loops.is_live(w.cref & !loops::LOOP_TAG)
                        } else {
                            arena[w.cref as usize + 1] & FLAG_DELETED == 0
                        }
                })
            }
        }
    }

    fn delete_learnt(&mut self, c: ClauseRef) {
        self.arena[c as usize + 1] |= FLAG_DELETED;
        self.wasted += HEADER + self.clause_len(c);
    }

    /// `Deletion::Basic` (clasp's linear reduction): oldest first, keeps reasons, glue
    /// clauses (LBD <= 2), clauses of at most three literals and clauses used more than 1.5
    /// times the average; the uses of every kept clause are halved.
    fn reduce_basic(&mut self) {
        let mut learnts = std::mem::take(&mut self.learnts);
        // Clauses of at most three literals live outside the database in clasp: they are
        // neither counted nor deleted.
        let (mut n, mut sum) = (0u64, 0u64);
        for &c in &learnts {
            if self.clause_len(c) > 3 {
                n += 1;
                sum += self.arena[c as usize + 2] as u64;
            }
        }
        let mut to_remove = n / 2;
        let avg = if n == 0 { 0.0 } else { sum as f64 / n as f64 };
        let mut active = avg * 1.5;
        if active > MAX_USES as f64 {
            active = (MAX_USES as f64 + avg) / 2.0;
        }
        learnts.retain(|&c| {
            let uses = self.arena[c as usize + 2];
            if self.clause_len(c) <= 3 {
                return true;
            }
            let keep = to_remove == 0
                || self.clause_flags(c) >> 2 <= 2
                || uses as f64 > active
                || self.locked(c);
            if keep {
                self.arena[c as usize + 2] = uses >> 1;
            } else {
                self.delete_learnt(c);
                to_remove -= 1;
            }
            keep
        });
        self.learnts = learnts;
    }

    /// `Deletion::Sorted`: deletes the worst half by LBD, then activity.
    fn reduce_sorted(&mut self) {
        let mut cands: Vec<(u32, f32, ClauseRef)> = self
            .learnts
            .iter()
            .map(|&c| {
                (
                    self.clause_flags(c) >> 2,
                    f32::from_bits(self.arena[c as usize + 2]),
                    c,
                )
            })
            .collect();
        // Worst first: high LBD, then low activity.
        cands.sort_by(|a, b| {
            b.0.cmp(&a.0)
                .then(a.1.partial_cmp(&b.1).unwrap_or(std::cmp::Ordering::Equal))
        });
        let target = cands.len() / 2;
        let mut removed = 0;
        let mut keep = Vec::with_capacity(cands.len());
        for (lbd, _, c) in cands {
            if removed < target && lbd > 2 && !self.locked(c) {
                self.delete_learnt(c);
                removed += 1;
            } else {
                keep.push(c);
            }
        }
        self.learnts = keep;
    }

    /// Moves the live clauses to the front of the arena, in order, and redirects the watch
    /// lists, reasons and learnt references. In place, so that the peak memory holds one
    /// arena, not the old one and a growing copy: a first pass writes each live clause's new
    /// position into its activity word (keeping the activities aside), the references are
    /// redirected through that word, and a second pass moves the clauses and puts the
    /// activities back.
    fn collect_garbage(&mut self) {
        let mut activities = Vec::with_capacity(self.learnts.len());
        let (mut pos, mut to) = (0usize, 0usize);
        while pos < self.arena.len() {
            let len = self.arena[pos] as usize;
            if self.arena[pos + 1] & FLAG_DELETED == 0 {
                activities.push(self.arena[pos + 2]);
                self.arena[pos + 2] = to as u32;
                to += HEADER + len;
            }
            pos += HEADER + len;
        }
        let (arena, loops) = (&self.arena, &self.loops);
        let live = |c: u32| arena[c as usize + 1] & FLAG_DELETED == 0;
        for ws in self.watches.iter_mut() {
            ws.retain_mut(|w| {
                if w.cref == u32::MAX {
                    true
                } else if is_loop_watch(w.cref) {
                    loops.is_live(w.cref & !loops::LOOP_TAG)
                } else if live(w.cref) {
                    w.cref = arena[w.cref as usize + 2];
                    true
                } else {
                    false
                }
            });
        }
        // Only assigned variables have meaningful reasons; an unassigned one may hold a stale
        // reference that is not a clause start any more, so it is cleared, never followed.
        for (v, r) in self.reason.iter_mut().enumerate() {
            if let Reason::Long(c) = r {
                if self.values[2 * v] != 0 && live(*c) {
                    *c = arena[*c as usize + 2];
                } else {
                    *r = Reason::Decision;
                }
            }
        }
        for c in self.learnts.iter_mut() {
            debug_assert!(live(*c), "learnt references are live");
            *c = arena[*c as usize + 2];
        }
        let (mut pos, mut to) = (0usize, 0usize);
        let mut live_index = 0;
        while pos < self.arena.len() {
            let len = self.arena[pos] as usize;
            if self.arena[pos + 1] & FLAG_DELETED == 0 {
                self.arena.copy_within(pos..pos + HEADER + len, to);
                self.arena[to + 2] = activities[live_index];
                live_index += 1;
                to += HEADER + len;
            }
            pos += HEADER + len;
        }
        self.arena.truncate(to);
        self.wasted = 0;
    }

    // ---------------------------------------------------------------- level-0 simplification

    /// Removes clauses satisfied at decision level 0 and the literals false there, turning
    /// long clauses that shrink to two literals into binary watches (MiniSat's `simplify`,
    /// clasp's removal of satisfied constraints). Must be called at level 0 after a
    /// conflict-free propagation. Rebuilds the arena and the long-clause watches; every
    /// level-0 assignment gets `Reason::Decision` (analysis never looks at level 0).
    fn simplify(&mut self) {
        debug_assert_eq!(self.decision_level(), 0);
        debug_assert_eq!(self.qhead, self.trail.len());
        for &l in &self.trail {
            self.reason[l.var().index()] = Reason::Decision;
        }
        // Binary clauses with an assigned literal are satisfied at level 0 (a false literal
        // forced its partner true).
        // Clauses mentioning a retired variable go too (`retire_vars`).
        for code in 0..self.watches.len() {
            if self.values[code] != 0 || self.retired[code >> 1] {
                self.watches[code].clear();
                continue;
            }
            let (values, retired) = (&self.values, &self.retired);
            self.watches[code].retain(|w| {
                w.cref == u32::MAX && values[w.other.code()] == 0 && !retired[w.other.var().index()]
            });
        }
        // In place (see `collect_garbage`): a clause only shrinks or goes, so the write
        // position never passes the read position, and a clause's literals are read before
        // its new place is written.
        let mut learnts = Vec::with_capacity(self.learnts.len());
        let mut lits: Vec<Lit> = Vec::new();
        let (mut pos, mut to) = (0usize, 0usize);
        let end = self.arena.len();
        while pos < end {
            let len = self.arena[pos] as usize;
            let flags = self.arena[pos + 1];
            let activity = self.arena[pos + 2];
            let next = pos + HEADER + len;
            if flags & FLAG_DELETED != 0 {
                pos = next;
                continue;
            }
            lits.clear();
            let mut satisfied = false;
            for k in pos + HEADER..next {
                let l = Lit::from_code(self.arena[k]);
                if self.retired[l.var().index()] {
                    satisfied = true;
                    break;
                }
                match self.values[l.code()] {
                    1 => {
                        satisfied = true;
                        break;
                    }
                    0 => lits.push(l),
                    _ => {}
                }
            }
            if !satisfied {
                debug_assert!(lits.len() >= 2, "propagation reached a fixpoint");
                if lits.len() == 2 {
                    self.watch_binary(lits[0], lits[1]);
                } else {
                    let cref = to as u32;
                    self.arena[to] = lits.len() as u32;
                    self.arena[to + 1] = flags;
                    self.arena[to + 2] = activity;
                    for (k, l) in lits.iter().enumerate() {
                        self.arena[to + HEADER + k] = l.code() as u32;
                    }
                    to += HEADER + lits.len();
                    self.watches[lits[0].code()].push(Watch {
                        cref,
                        other: lits[1],
                    });
                    self.watches[lits[1].code()].push(Watch {
                        cref,
                        other: lits[0],
                    });
                    if flags & FLAG_LEARNT != 0 {
                        learnts.push(cref);
                    }
                }
            }
            pos = next;
        }
        self.arena.truncate(to);
        self.learnts = learnts;
        self.wasted = 0;
        self.simplify_loops();
        self.free_dead_vars();
        self.simp_assigns = self.trail.len();
        self.simp_props = self.propagations + self.arena.len() as u64;
    }

    /// The end of `simplify`, once no clause mentions a retired variable: drops their level-0
    /// assignments (facts derived through them stay: see `retire_vars`) and frees them.
    fn free_dead_vars(&mut self) {
        if self.dead_vars.is_empty() {
            return;
        }
        let retired = &self.retired;
        if self.trail.iter().any(|l| retired[l.var().index()]) {
            let mut kept = Vec::with_capacity(self.trail.len());
            for &l in &self.trail {
                if self.retired[l.var().index()] {
                    self.values[l.code()] = 0;
                    self.values[(!l).code()] = 0;
                } else {
                    kept.push(l);
                }
            }
            self.trail = kept;
            self.qhead = self.trail.len();
            self.pf_head = self.qhead;
            self.uf_clean_upto = self.uf_clean_upto.min(self.trail.len());
        }
        for v in std::mem::take(&mut self.dead_vars) {
            let slot = self.weight_slot[v.index()];
            debug_assert!(
                slot == NO_SLOT || self.weight_watch[slot as usize].is_empty(),
                "a retired variable is in no weight constraint"
            );
            self.free_vars.push(v);
        }
    }

    /// Runs `simplify` when new level-0 facts exist and enough propagation work was done since
    /// the last run to pay for a pass over the arena, or when many variables wait to be freed
    /// (a pass per quarter of the variables retired keeps their number bounded, at a cost per
    /// retired variable of about the clauses per variable).
    fn maybe_simplify(&mut self) {
        if self.decision_level() == 0
            && ((self.trail.len() > self.simp_assigns && self.propagations >= self.simp_props)
                || self.dead_vars.len() > 256 + self.num_vars() / 4)
        {
            self.simplify();
        }
    }

    /// Seeds the VSIDS activities with a MOMS-like score (clasp `--init-moms`): variables
    /// occurring often in both polarities in short clauses come first. Scores are scaled into
    /// [0, 1], below one conflict bump, so learning takes over at the first conflict.
    fn seed_activities(&mut self) {
        let n = self.num_vars();
        let mut occ = vec![0u64; 2 * n];
        for (code, ws) in self.watches.iter().enumerate() {
            // Each binary clause appears in two lists; count it once per literal.
            occ[code] += ws.iter().filter(|w| w.cref == u32::MAX).count() as u64;
        }
        let mut pos = 0usize;
        while pos < self.arena.len() {
            let len = self.arena[pos] as usize;
            if self.arena[pos + 1] & (FLAG_DELETED | FLAG_LEARNT) == 0 {
                for &c in &self.arena[pos + HEADER..pos + HEADER + len] {
                    occ[c as usize] += 1;
                }
            }
            pos += HEADER + len;
        }
        let score: Vec<f64> = (0..n)
            .map(|v| {
                let (p, q) = (occ[2 * v], occ[2 * v + 1]);
                ((p * q) as f64) * 1024.0 + (p + q) as f64
            })
            .collect();
        let max = score.iter().copied().fold(0.0f64, f64::max);
        if max <= 0.0 {
            return;
        }
        for (v, s) in score.into_iter().enumerate() {
            self.activity[v] = s / max;
        }
        let vars: Vec<Var> = self.heap.clone();
        self.heap.clear();
        for v in vars {
            self.heap_pos[v.index()] = NO_SLOT;
        }
        for v in 0..n {
            self.heap_insert(Var::new(v));
        }
    }

    // ---------------------------------------------------------------- search

    fn luby(mut i: u32) -> u64 {
        // The Luby sequence 1 1 2 1 1 2 4 ... at 0-based index i.
        let mut size = 1u64;
        let mut seq = 0u32;
        while size < i as u64 + 1 {
            seq += 1;
            size = 2 * size + 1;
        }
        let mut x = i as u64;
        while size - 1 != x {
            size = (size - 1) >> 1;
            seq -= 1;
            x %= size;
        }
        let _ = &mut i;
        1u64 << seq
    }

    fn should_restart(&mut self, lbd: Option<u32>) -> bool {
        match &mut self.restarts {
            Restarts::Never => false,
            Restarts::Luby { unit, index, left } => {
                if lbd.is_some() {
                    *left = left.saturating_sub(1);
                }
                if *left == 0 {
                    *index += 1;
                    *left = Engine::luby(*index) * *unit as u64;
                    return true;
                }
                false
            }
            Restarts::Glucose {
                fast,
                slow,
                since,
                trail,
            } => {
                if let Some(l) = lbd {
                    let l = l as f64;
                    *fast += (l - *fast) / 32.0;
                    *slow += (l - *slow) / 10000.0f64.min(self.conflicts as f64 + 1.0);
                    *since += 1;
                    let t = self.conflict_trail as f64;
                    if self.restart_blocking && self.conflicts > 10000 && t > 1.4 * *trail {
                        *since = 0;
                    }
                    *trail += (t - *trail) / 5000.0f64.min(self.conflicts as f64 + 1.0);
                }
                if *since >= 50 && *fast > 1.25 * *slow {
                    *since = 0;
                    return true;
                }
                false
            }
        }
    }

    fn limit_reached(&mut self) -> bool {
        if let Some(flag) = &self.portfolio_stop {
            if flag.load(Ordering::Relaxed) {
                return true;
            }
        }
        if let Some(flag) = &self.interrupt {
            if flag.load(Ordering::Relaxed) {
                self.interrupted = true;
                return true;
            }
        }
        if let Some(d) = self.deadline {
            if Instant::now() >= d {
                return true;
            }
        }
        self.conflict_limit.is_some_and(|n| self.conflicts >= n)
    }

    /// Searches for a total assignment extending `assumptions`. On `Sat` the assignment stays
    /// on the trail until the next `backtrack`/`add_clause`.
    pub fn search(&mut self, assumptions: &[Lit]) -> SearchResult {
        self.search_from(assumptions, false)
    }

    /// [`Engine::search`]; with `resume`, goes on from the current assignment instead of level
    /// 0 (after [`Engine::add_clause_resuming`], with the same assumptions as the search that
    /// made this assignment).
    pub fn search_from(&mut self, assumptions: &[Lit], resume: bool) -> SearchResult {
        self.interrupted = false;
        self.failed.clear();
        if self.inconsistent {
            return SearchResult::Unsat;
        }
        if !resume || self.decision_level() == 0 {
            self.backtrack(0);
            if self.propagate().is_some() {
                self.inconsistent = true;
                return SearchResult::Unsat;
            }
            self.maybe_simplify();
        }
        if self.init_moms {
            self.init_moms = false;
            self.seed_activities();
        }
        let mut ticks: u64 = 0;
        loop {
            ticks += 1;
            if ticks & 255 == 0 && self.limit_reached() {
                self.backtrack(0);
                return SearchResult::Unknown;
            }
            if self.propagate().is_some() {
                self.conflicts += 1;
                // The conflict may lie entirely below the current level (clauses added during
                // search); move down to its highest level first.
                let max_level = self
                    .conflict
                    .iter()
                    .map(|l| self.level[l.var().index()])
                    .max()
                    .unwrap_or(0);
                if max_level == 0 {
                    self.inconsistent = true;
                    self.backtrack(0);
                    return SearchResult::Unsat;
                }
                if max_level < self.decision_level() {
                    self.backtrack(max_level);
                }
                self.conflict_trail = self.trail.len();
                let bt = self.analyze();
                let learnt = std::mem::take(&mut self.learnt);
                let lbd = self.lbd(&learnt);
                self.backtrack(bt);
                if learnt.len() == 1 {
                    self.assign(learnt[0], Reason::Decision);
                } else {
                    let r = self.attach(&learnt, true, lbd);
                    let r = match r {
                        Reason::Binary(_) => Reason::Binary(learnt[1]),
                        other => other,
                    };
                    self.assign(learnt[0], r);
                }
                self.learnt = learnt;
                self.var_inc /= self.var_decay;
                self.cla_inc /= 0.999;
                if self.should_restart(Some(lbd)) {
                    self.num_restarts += 1;
                    self.backtrack(0);
                }
                continue;
            }
            self.maybe_simplify();
            match self.reduce {
                ReduceSchedule::Size => {
                    // A loop formula counts as the clauses it stands for.
                    let learnts = self.learnts.len() + self.loops.clauses;
                    if learnts as f64 >= self.max_learnts + self.trail.len() as f64 {
                        self.reduce_db();
                        self.max_learnts *= 1.1;
                    }
                }
                ReduceSchedule::Conflicts { first, inc, repeat } => {
                    if self.next_reduce == 0 {
                        self.next_reduce = self.conflicts + first;
                        self.reduce_len = repeat;
                    }
                    if self.conflicts >= self.next_reduce {
                        self.reductions += 1;
                        self.reduce_idx += 1;
                        if self.reduce_len > 0 && self.reduce_idx >= self.reduce_len {
                            self.reduce_idx = 0;
                            self.reduce_len += 1;
                        }
                        self.next_reduce = self.conflicts + first + self.reduce_idx * inc;
                        self.reduce_db();
                    }
                }
            }
            let level = self.decision_level() as usize;
            let next = if level < assumptions.len() {
                let a = assumptions[level];
                match self.val(a) {
                    1 => {
                        // Already true: open an empty level to keep levels aligned.
                        self.trail_lim.push(self.trail.len());
                        continue;
                    }
                    -1 => {
                        self.analyze_final(a);
                        self.backtrack(0);
                        return SearchResult::Unsat;
                    }
                    _ => a,
                }
            } else {
                match self.pick_branch() {
                    Some(l) => l,
                    None => return SearchResult::Sat,
                }
            };
            self.decisions += 1;
            self.trail_lim.push(self.trail.len());
            self.assign(next, Reason::Decision);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lits(e: &mut Engine, n: usize) -> Vec<Var> {
        (0..n).map(|_| e.new_var()).collect()
    }

    #[test]
    fn luby_sequence() {
        let got: Vec<u64> = (0..7).map(Engine::luby).collect();
        assert_eq!(got, vec![1, 1, 2, 1, 1, 2, 4]);
    }

    #[test]
    fn failed_assumptions_are_the_ones_the_refutation_uses() {
        // x -> y, y -> -z; w is unrelated. Assuming w, x, z fails on z, because of x.
        let mut e = Engine::new();
        let v = lits(&mut e, 4);
        let (x, y, z, w) = (v[0], v[1], v[2], v[3]);
        e.add_clause(&[x.negative(), y.positive()]);
        e.add_clause(&[y.negative(), z.negative()]);
        let assumptions = [w.positive(), x.positive(), z.positive()];
        assert_eq!(e.search(&assumptions), SearchResult::Unsat);
        let mut failed = e.failed_assumptions().to_vec();
        assert_eq!(failed[0], z.positive(), "the failed assumption comes first");
        failed.sort_by_key(|l| l.code());
        let mut expected = vec![z.positive(), x.positive()];
        expected.sort_by_key(|l| l.code());
        assert_eq!(failed, expected);
        // The core alone is refuted; without x the rest is satisfiable.
        assert_eq!(e.search(&[x.positive(), z.positive()]), SearchResult::Unsat);
        assert_eq!(e.search(&[w.positive(), z.positive()]), SearchResult::Sat);
        // Contradictory assumptions are a core of two; a fact false at level 0 one of one.
        assert_eq!(e.search(&[w.positive(), w.negative()]), SearchResult::Unsat);
        let mut failed = e.failed_assumptions().to_vec();
        failed.sort_by_key(|l| l.code());
        assert_eq!(failed, vec![w.positive(), w.negative()]);
        e.add_clause(&[y.negative()]);
        assert_eq!(e.search(&[w.positive(), y.positive()]), SearchResult::Unsat);
        assert_eq!(e.failed_assumptions(), &[y.positive()]);
    }

    #[test]
    fn pigeonhole_three_in_two_is_unsat() {
        // p(i, j): pigeon i in hole j; each pigeon somewhere, no two share a hole.
        let mut e = Engine::new();
        let v = lits(&mut e, 6);
        let p = |i: usize, j: usize| v[i * 2 + j];
        for i in 0..3 {
            e.add_clause(&[p(i, 0).positive(), p(i, 1).positive()]);
        }
        for j in 0..2 {
            for a in 0..3 {
                for b in a + 1..3 {
                    e.add_clause(&[p(a, j).negative(), p(b, j).negative()]);
                }
            }
        }
        assert_eq!(e.search(&[]), SearchResult::Unsat);
    }

    /// Pigeons into holes as clauses: every pigeon somewhere, no two in one hole.
    fn pigeons(e: &mut Engine, pigeons: usize, holes: usize) -> Vec<Var> {
        let v = lits(e, pigeons * holes);
        for i in 0..pigeons {
            let some: Vec<Lit> = (0..holes).map(|j| v[i * holes + j].positive()).collect();
            e.add_clause(&some);
        }
        for j in 0..holes {
            for a in 0..pigeons {
                for b in a + 1..pigeons {
                    e.add_clause(&[v[a * holes + j].negative(), v[b * holes + j].negative()]);
                }
            }
        }
        v
    }

    #[test]
    fn both_deletion_policies_stay_sound_under_frequent_reductions() {
        // Reductions every few conflicts delete clauses while others are reasons; the answers
        // must not change: 7 pigeons do not fit in 6 holes (thousands of conflicts), 6 do,
        // and the model found must satisfy every clause.
        for deletion in [Deletion::Sorted, Deletion::Basic] {
            for (first, inc, repeat) in [(20, 5, 3), (50, 0, 0)] {
                let mut e = Engine::new();
                e.deletion = deletion;
                e.reduce = ReduceSchedule::Conflicts { first, inc, repeat };
                e.restarts = Restarts::Luby {
                    unit: 16,
                    index: 0,
                    left: 16,
                };
                pigeons(&mut e, 7, 6);
                assert_eq!(e.search(&[]), SearchResult::Unsat, "{deletion:?}");
                assert!(
                    e.reductions > 3,
                    "the test needs reductions: {}",
                    e.reductions
                );
                let mut e = Engine::new();
                e.deletion = deletion;
                e.reduce = ReduceSchedule::Conflicts { first, inc, repeat };
                let v = pigeons(&mut e, 6, 6);
                assert_eq!(e.search(&[]), SearchResult::Sat, "{deletion:?}");
                for j in 0..6 {
                    let in_hole = (0..6)
                        .filter(|&i| e.value(v[i * 6 + j].positive()) == Some(true))
                        .count();
                    assert_eq!(in_hole, 1, "{deletion:?}: hole {j}");
                }
            }
        }
    }

    #[test]
    fn weight_constraint_propagates() {
        // h <-> 2a + 1b + 1c >= 3, h true, a false: then b and c must be true... 1+1 < 3, so
        // the constraint is unsatisfiable with a false and h true.
        let mut e = Engine::new();
        let v = lits(&mut e, 4);
        let (h, a, b, c) = (v[0], v[1], v[2], v[3]);
        e.add_weight(
            h.positive(),
            &[(a.positive(), 2), (b.positive(), 1), (c.positive(), 1)],
            3,
        );
        e.add_clause(&[h.positive()]);
        assert_eq!(e.search(&[a.negative()]), SearchResult::Unsat);
        assert_eq!(e.search(&[a.positive(), c.negative()]), SearchResult::Sat);
        assert_eq!(e.value(b.positive()), Some(true));
    }

    /// Opens a decision level and decides `l` (as `search` does).
    fn decide(e: &mut Engine, l: Lit) {
        e.trail_lim.push(e.trail.len());
        e.assign(l, Reason::Decision);
        assert!(e.propagate().is_none());
    }

    #[test]
    fn shared_loop_formula_propagates_atoms_and_external_bodies() {
        // Unfounded set {a1, a2} with external bodies b1, b2, b3: the loop nogoods are
        // a1 -> b1 | b2 | b3 and a2 -> b1 | b2 | b3, learnt as one formula (hand-derived).
        let mut e = Engine::new();
        e.shared_loops = true;
        let v = lits(&mut e, 5);
        let (a1, a2) = (v[0].positive(), v[1].positive());
        let (b1, b2, b3) = (v[2].positive(), v[3].positive(), v[4].positive());
        decide(&mut e, !b1);
        decide(&mut e, !b2);
        decide(&mut e, !b3);
        // Every external body false: both atoms false, at the level of the latest body.
        assert!(!e.add_loop_set(&[a1, a2], &[b1, b2, b3]));
        assert_eq!(e.loops.live, 1, "one formula, not two clauses");
        assert_eq!(e.value(a1), Some(false));
        assert_eq!(e.value(a2), Some(false));
        assert_eq!(e.level_of(a1), 3);
        let mut r = Vec::new();
        e.reason_lits(a1.var(), &mut r);
        r.sort();
        assert_eq!(r, vec![b1, b2, b3]);
        // Undo b3; making a2 true leaves b3 as the only support: it is implied, with the
        // reason "a2 true, b1 and b2 false".
        e.backtrack(2);
        decide(&mut e, a2);
        assert_eq!(e.value(b3), Some(true));
        let mut r = Vec::new();
        e.reason_lits(b3.var(), &mut r);
        r.sort();
        let mut want = vec![b1, b2, !a2];
        want.sort();
        assert_eq!(r, want);
        // b3 false with a2 true is a conflict.
        e.backtrack(2);
        decide(&mut e, !b3);
        assert!(e.value(a2) == Some(false) && e.value(a1) == Some(false));
        e.backtrack(1);
        e.trail_lim.push(e.trail.len());
        for l in [a1, !b2, !b3] {
            e.assign(l, Reason::Decision);
        }
        assert!(
            e.propagate().is_some(),
            "a1 true and every external body false"
        );
        // At level 0 with b1 false, the formula shrinks to b2 | b3 and keeps propagating.
        e.backtrack(0);
        e.assign(!b1, Reason::Decision);
        assert!(e.propagate().is_none());
        e.simplify();
        assert_eq!(e.loops.live, 1);
        decide(&mut e, !b2);
        decide(&mut e, !b3);
        assert_eq!(e.value(a1), Some(false));
        assert_eq!(e.value(a2), Some(false));
    }
}
