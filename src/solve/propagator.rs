//! The solver's side of clingo's propagator interface: [`Hook`], what the CDCL engine calls
//! (`propagate` on watched literals that became true, `undo` on backtracking, `check` on total
//! assignments), and the views it hands over: [`PropagateControl`] (the assignment, clauses,
//! unit propagation, watches) and [`Assignment`]. `control::propagator` puts clingo's
//! `Propagator` (with `init` over symbolic atoms) on top.
//!
//! Literals are clingo's solver literals: `±(v + 1)` for the engine variable `v` of the main
//! solver (thread 0), so `-l` is the complement of `l`. A portfolio's helper engines translate
//! them through a map built from the atoms (`Engine::set_lit_map`); only atom literals (those
//! `Solver::solver_literal` gives, and their complements) are valid there.
//!
//! Invariants:
//! - `PropagateControl::add_clause` never backtracks: a clause it can attach under the current
//!   assignment (satisfied, two non-false literals, or asserting) is attached at once; a
//!   conflicting clause, or a unit clause not yet true at level 0, waits in the engine and the
//!   call answers false (the propagator must return). The engine adds it when the hook
//!   returns, backjumping as for a loop nogood, so it takes part in conflict analysis.
//! - Clauses added during search are learnt clauses (deletable by the clause-database
//!   reduction, as clingo's default `lock=False`), so they must be consequences of the
//!   program plus the propagator's constraint, as in clingo.
//! - The hook is called with the engine's propagation at a fixpoint and never re-entered: an
//!   engine calls it only while no call of it runs on that engine.
//! - Variables `add_literal` makes live for one solve call (retired when it ends, with the
//!   clauses that mention them), as clingo's volatile literals.

use super::engine::Engine;
use super::lit::Lit;

/// A solver literal as clingo numbers them: `±(variable + 1)`.
pub type Literal = i32;

/// What an engine calls: clingo's propagator callbacks after `init`. One instance serves every
/// thread of a portfolio (behind a mutex), told apart by `thread_id`, as in clingo.
pub trait Hook: Send {
    /// Some watched literals became true (`changes`, in trail order).
    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]);
    /// Backtracking unassigns `changes`, which `propagate` was given; `assignment` still holds
    /// them.
    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]);
    /// The assignment is total (clingo's check mode `total`).
    fn check(&mut self, ctl: &mut PropagateControl<'_>);
    /// Propagation reached a fixpoint (clingo's check mode `fixpoint`); called only on engines
    /// told so (`Solver::set_fixpoint_checks`).
    fn check_fixpoint(&mut self, ctl: &mut PropagateControl<'_>) {
        let _ = ctl;
    }
}

/// The assignment of one engine, as a propagator reads it.
pub struct Assignment<'a> {
    pub(crate) engine: &'a Engine,
}

impl Assignment<'_> {
    fn lit(&self, l: Literal) -> Lit {
        self.engine
            .user_to_local(l)
            .unwrap_or_else(|| panic!("{l} is not a solver literal of this solver"))
    }

    /// The value of `l`: `Some(true)`, `Some(false)` or `None` (unassigned).
    pub fn value(&self, l: Literal) -> Option<bool> {
        self.engine.value(self.lit(l))
    }

    /// Whether `l` is true.
    pub fn is_true(&self, l: Literal) -> bool {
        self.value(l) == Some(true)
    }

    /// Whether `l` is false.
    pub fn is_false(&self, l: Literal) -> bool {
        self.value(l) == Some(false)
    }

    /// Whether `l` is assigned at decision level 0 (fixed for the rest of the search).
    pub fn is_fixed(&self, l: Literal) -> bool {
        self.value(l).is_some() && self.level(l) == 0
    }

    /// The decision level `l` was assigned at (meaningless when unassigned).
    pub fn level(&self, l: Literal) -> u32 {
        self.engine.level_of(self.lit(l))
    }

    /// The current decision level.
    pub fn decision_level(&self) -> u32 {
        self.engine.decision_level()
    }

    /// The decision literal of `level` (`1..=decision_level()`; assumptions are decisions too,
    /// as in clasp); `None` for another level, and for a level an assumption that was already
    /// true left without a decision.
    pub fn decision(&self, level: u32) -> Option<Literal> {
        self.engine
            .decision_at(level)
            .map(|l| self.engine.user_lit(l))
    }

    /// The number of variables (clingo's `size`): solver literals are `±1..=size`.
    pub fn size(&self) -> usize {
        self.engine.user_vars()
    }

    /// Whether every variable the search decides on is assigned.
    pub fn is_total(&self) -> bool {
        self.engine.is_total()
    }

    /// Whether the propagator must return: a conflict, or a clause that needs a backjump,
    /// waits for the engine.
    pub fn has_conflict(&self) -> bool {
        self.engine.external_conflict()
    }

    /// Whether `l` names a variable of this solver (clingo's `has_literal`): the other
    /// methods panic on a literal that does not.
    pub fn has_literal(&self, l: Literal) -> bool {
        self.engine.user_to_local(l).is_some()
    }

    /// The decision levels the solve call's assumptions occupy (clingo's `root_level`; the
    /// search never backjumps below it). Each call assumes its guard variable, so during
    /// search it is usually 1, as clingo's.
    pub fn root_level(&self) -> u32 {
        self.engine.external_root()
    }

    /// The number of assigned literals (the trail's length).
    pub fn trail_len(&self) -> usize {
        self.engine.trail().len()
    }

    /// The `i`-th assigned literal, in assignment order (clingo's `Trail`); `None` past the
    /// end. On a portfolio's helper thread a variable of the helper's own (no atom) reads 0.
    pub fn trail_at(&self, i: usize) -> Option<Literal> {
        self.engine.trail().get(i).map(|&l| self.engine.user_lit(l))
    }

    /// Where decision level `level` starts on the trail (clingo's `Trail.begin`); its end is
    /// where `level + 1` starts (the trail's length for the current level).
    pub fn trail_begin(&self, level: u32) -> usize {
        self.engine.level_start(level)
    }
}

/// What a propagator may do during search (clingo's `PropagateControl`).
pub struct PropagateControl<'a> {
    pub(crate) engine: &'a mut Engine,
}

impl PropagateControl<'_> {
    fn lits(&self, clause: &[Literal]) -> Vec<Lit> {
        clause
            .iter()
            .map(|&l| {
                self.engine
                    .user_to_local(l)
                    .unwrap_or_else(|| panic!("{l} is not a solver literal of this solver"))
            })
            .collect()
    }

    /// The thread this engine runs on (0 is the caller's thread).
    pub fn thread_id(&self) -> u32 {
        self.engine.external_thread()
    }

    /// The current assignment.
    pub fn assignment(&self) -> Assignment<'_> {
        Assignment {
            engine: self.engine,
        }
    }

    /// Adds a clause (learnt). False means the propagator must return at once: the clause is
    /// conflicting (or a unit clause that needs a restart at level 0, or a conflict is already
    /// pending).
    pub fn add_clause(&mut self, clause: &[Literal]) -> bool {
        let lits = self.lits(clause);
        self.engine.external_clause(lits)
    }

    /// Adds a nogood: the clause of the complements of `nogood`'s literals.
    pub fn add_nogood(&mut self, nogood: &[Literal]) -> bool {
        let lits: Vec<Lit> = self.lits(nogood).into_iter().map(|l| !l).collect();
        self.engine.external_clause(lits)
    }

    /// Unit propagation of what the propagator added; false on a conflict (then return).
    pub fn propagate(&mut self) -> bool {
        self.engine.external_propagate()
    }

    /// Watches `l`: `propagate` is called when it becomes true.
    pub fn add_watch(&mut self, l: Literal) {
        let l = self.lits(&[l])[0];
        self.engine.watch_external(l, true);
    }

    /// Stops watching `l`.
    pub fn remove_watch(&mut self, l: Literal) {
        let l = self.lits(&[l])[0];
        self.engine.watch_external(l, false);
    }

    /// A new variable for this solve call (clingo's volatile `add_literal`): free, decided on
    /// like any other, and retired with every clause that mentions it when the call ends.
    /// Answers its positive literal. Panics on a portfolio's helper thread (`thread_id() > 0`),
    /// whose literals must name the main engine's variables.
    pub fn add_literal(&mut self) -> Literal {
        let v = self.engine.external_var().expect(
            "add_literal during search needs one thread (-t 1): helpers cannot name new variables",
        );
        self.engine.user_lit(v.positive())
    }

    /// Whether `l` is watched.
    pub fn has_watch(&self, l: Literal) -> bool {
        let l = self.lits(&[l])[0];
        self.engine.is_watched_external(l)
    }
}
