//! clingo's propagator interface on [`Control`]: a [`Propagator`] registered with
//! [`Control::register_propagator`] gets `init` before every solve call (symbolic atoms to
//! solver literals, watches, static clauses, fixed values), then `propagate` when watched
//! literals become true, `undo` when backtracking unassigns them, and `check` on every total
//! assignment or at every propagation fixpoint as its [`CheckMode`] says (clingo's
//! `check_mode`, set in `init`), from inside the CDCL search (`solve::propagator`).
//!
//! Semantics, as clingo's where they agree, and the differences:
//! - Clauses a propagator adds during search are learnt clauses (clingo's default
//!   `lock=False`): they take part in conflict analysis, are kept across solve calls like
//!   other learnt clauses, and may be deleted by the clause-database reduction; clauses added
//!   in `init` are problem clauses.
//! - With `threads >= 2` every thread of the portfolio calls the same propagator instance,
//!   with its own `thread_id` (`0..number_of_threads`), serialized by one mutex: as in clingo,
//!   state that depends on the assignment must be kept per thread.
//! - Several propagators: each is called in registration order with every change of a
//!   literal any of them watches (clingo filters by each one's watches); a propagator that
//!   added a conflicting clause ends the round.
//! - Watches persist across solve calls; `init` may add them again (no effect).
//! - Literals: `PropagateInit::add_literal` makes a variable kept across calls,
//!   `PropagateControl::add_literal` one for the current call (clingo's volatile literal),
//!   both with one thread only; `PropagateInit::condition_literal` names a theory element's
//!   condition by a variable defined as the conjunction (one per condition, kept across
//!   calls), also with one thread only.
//!
//! Invariant: the propagators are installed on the solver once it exists and reinstalled (watches
//! reset, every `init` called again) after a registration.

use super::{AtomId, Control, SymbolicAtom};
use crate::solve::engine::SharedHook;
use crate::solve::propagator::Hook;
pub use crate::solve::propagator::{Assignment, Literal, PropagateControl};
use crate::solve::Solver;
use hashbrown::HashMap;
use std::sync::{Arc, Mutex};

/// A propagator (clingo's `Propagator`): every method has a default that does nothing.
pub trait Propagator: Send {
    /// Before each solve call: map atoms to solver literals, add watches, read fixed values.
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        let _ = init;
    }
    /// Watched literals became true (`changes`); add clauses or propagate through `ctl`. When
    /// `add_clause` or `propagate` answers false, return at once.
    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        let _ = (ctl, changes);
    }
    /// Backtracking unassigns `changes` (literals `propagate` was given on `thread_id`).
    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        let _ = (thread_id, assignment, changes);
    }
    /// The assignment is total (or, as the check mode says, propagation reached a fixpoint); a
    /// clause refuting it makes the search go on.
    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let _ = ctl;
    }
}

/// When a propagator's `check` is called (clingo's `PropagatorCheckMode`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CheckMode {
    /// Never.
    None,
    /// On total assignments (clingo's default).
    #[default]
    Total,
    /// At every propagation fixpoint (a total assignment is one too).
    Fixpoint,
    /// At fixpoints and on total assignments.
    Both,
}

impl CheckMode {
    fn total(self) -> bool {
        matches!(self, CheckMode::Total | CheckMode::Both)
    }

    fn fixpoint(self) -> bool {
        matches!(self, CheckMode::Fixpoint | CheckMode::Both)
    }
}

/// How [`PropagateInit::add_weight_constraint`] ties its literal to the constraint (clingo's
/// `type_`: -1, 1, 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum WeightConstraintType {
    /// The constraint implies the literal (-1).
    LeftImplication,
    /// The literal implies the constraint (1).
    RightImplication,
    /// The literal holds exactly when the constraint does (0, the default).
    #[default]
    Equivalence,
}

/// What `init` gets (clingo's `PropagateInit`).
pub struct PropagateInit<'a> {
    solver: &'a mut Solver,
    atoms: &'a [SymbolicAtom],
    theory: &'a [super::theory::TheoryAtom],
    mode: &'a mut CheckMode,
    conditions: &'a mut HashMap<Vec<i32>, Literal>,
}

impl PropagateInit<'_> {
    /// Every atom with a symbol (as [`Control::symbolic_atoms`]).
    pub fn symbolic_atoms(&self) -> &[SymbolicAtom] {
        self.atoms
    }

    /// The ground theory atoms (as [`Control::theory_atoms`]); map an atom's `atom` to a
    /// solver literal with [`PropagateInit::solver_literal`].
    pub fn theory_atoms(&self) -> &[super::theory::TheoryAtom] {
        self.theory
    }

    /// The solver literal of a program atom.
    pub fn solver_literal(&self, atom: AtomId) -> Literal {
        self.solver.solver_literal(atom)
    }

    /// Watches `l` on every thread.
    pub fn add_watch(&mut self, l: Literal) {
        self.solver.propagator_watch(l);
    }

    /// Adds a problem clause; false when the problem became unsatisfiable.
    pub fn add_clause(&mut self, clause: &[Literal]) -> bool {
        self.solver.propagator_clause(clause)
    }

    /// Stops watching `l` on every thread.
    pub fn remove_watch(&mut self, l: Literal) {
        self.solver.propagator_unwatch(l);
    }

    /// Propagates what the clauses added so far imply before the search (clingo's
    /// `PropagateInit.propagate`); false when the problem became unsatisfiable.
    pub fn propagate(&mut self) -> bool {
        self.solver.propagator_propagate()
    }

    /// Adds the weight constraint `sum(w * l for (l, w) in lits) >= bound` tied to `literal`
    /// as `kind` says (clingo's `add_weight_constraint`); false when the problem became
    /// unsatisfiable. With `compare_equal`, as clasp: the same tie of `-literal` to
    /// `sum >= bound + 1` is added too (so under an equivalence only `sum == bound` with
    /// `literal` true remains; recorded from clingo 5.8, tests/control/propagator.rs).
    pub fn add_weight_constraint(
        &mut self,
        literal: Literal,
        lits: &[(Literal, i32)],
        bound: i32,
        kind: WeightConstraintType,
        compare_equal: bool,
    ) -> bool {
        let ws: Vec<(Literal, i64)> = lits.iter().map(|&(l, w)| (l, i64::from(w))).collect();
        // `sum < bound` is `sum(-w * l) >= 1 - bound`.
        let neg: Vec<(Literal, i64)> = ws.iter().map(|&(l, w)| (l, -w)).collect();
        let s = &mut *self.solver;
        let mut tie = |lit: Literal, b: i64| match kind {
            WeightConstraintType::RightImplication => s.propagator_weight(lit, &ws, b, true),
            // The constraint implies `lit`: without it the sum stays below the bound.
            WeightConstraintType::LeftImplication => s.propagator_weight(-lit, &neg, 1 - b, true),
            WeightConstraintType::Equivalence => s.propagator_weight(lit, &ws, b, false),
        };
        let b = i64::from(bound);
        let mut ok = tie(literal, b);
        if compare_equal {
            ok &= tie(-literal, b + 1);
        }
        ok
    }

    /// The threads the propagator will be called from.
    pub fn number_of_threads(&self) -> usize {
        self.solver.num_threads()
    }

    /// The assignment at level 0: the values fixed before search.
    pub fn assignment(&self) -> Assignment<'_> {
        self.solver.propagator_assignment()
    }

    /// When this propagator's `check` runs (clingo's `check_mode`; `Total` unless set).
    pub fn check_mode(&self) -> CheckMode {
        *self.mode
    }

    /// Sets when this propagator's `check` runs.
    pub fn set_check_mode(&mut self, mode: CheckMode) {
        *self.mode = mode;
    }

    /// The solver literal of a theory element's condition (program literals, all of which
    /// must hold; clingo's `solver_literal(condition_id)`): the literal itself for one, else
    /// a variable defined as their conjunction by three kinds of problem clauses, made once
    /// per condition and kept across calls (so it adds no models). `None` with helper
    /// threads (`-t N`), whose literals name only atoms, when a variable would be needed.
    pub fn condition_literal(&mut self, condition: &[i32]) -> Option<Literal> {
        let lit = |s: &Solver, l: i32| {
            let x = s.solver_literal(l.unsigned_abs());
            if l < 0 {
                -x
            } else {
                x
            }
        };
        if let [l] = condition {
            return Some(lit(self.solver, *l));
        }
        if let Some(&x) = self.conditions.get(condition) {
            return Some(x);
        }
        let x = self.solver.propagator_new_var()?;
        let body: Vec<Literal> = condition.iter().map(|&l| lit(self.solver, l)).collect();
        for &b in &body {
            self.solver.propagator_clause(&[-x, b]);
        }
        let mut all: Vec<Literal> = body.iter().map(|&b| -b).collect();
        all.push(x);
        self.solver.propagator_clause(&all);
        self.conditions.insert(condition.to_vec(), x);
        Some(x)
    }

    /// A new solver variable, kept across solve calls (clingo's `add_literal`): its positive
    /// literal. Unconstrained, it doubles the models, as in clingo. Panics with helper threads
    /// (`-t N`), whose literals name only atoms.
    pub fn add_literal(&mut self) -> Literal {
        self.solver
            .propagator_new_var()
            .expect("PropagateInit::add_literal needs one thread (-t 1)")
    }
}

/// The registered propagators with their check modes, one hook for the engines.
#[derive(Default)]
pub(super) struct Registered(Vec<(Box<dyn Propagator>, CheckMode)>);

impl Hook for Registered {
    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        for (p, _) in &mut self.0 {
            p.propagate(ctl, changes);
            if ctl.assignment().has_conflict() {
                return;
            }
        }
    }

    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        for (p, _) in &mut self.0 {
            p.undo(thread_id, assignment, changes);
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        for (p, mode) in &mut self.0 {
            if mode.total() {
                p.check(ctl);
                if ctl.assignment().has_conflict() {
                    return;
                }
            }
        }
    }

    fn check_fixpoint(&mut self, ctl: &mut PropagateControl<'_>) {
        for (p, mode) in &mut self.0 {
            if mode.fixpoint() {
                p.check(ctl);
                if ctl.assignment().has_conflict() {
                    return;
                }
            }
        }
    }
}

/// The propagators of a Control and whether the solver has them.
#[derive(Default)]
pub(super) struct Propagators {
    hook: Option<Arc<Mutex<Registered>>>,
    installed: bool,
    /// The variable of each theory condition named so far (`condition_literal`).
    conditions: HashMap<Vec<i32>, Literal>,
}

impl Control {
    /// Registers a propagator (clingo's `register_propagator`); it takes part in every later
    /// solve call.
    pub fn register_propagator(&mut self, propagator: Box<dyn Propagator + Send>) {
        let hook = self.propagators.hook.get_or_insert_with(Default::default);
        hook.lock()
            .unwrap_or_else(|p| p.into_inner())
            .0
            .push((propagator, CheckMode::Total));
        self.propagators.installed = false;
    }

    /// Before a solve call (the solver prepared): installs the propagators if needed and calls
    /// every `init`.
    pub(super) fn init_propagators(&mut self) {
        let Some(hook) = self.propagators.hook.clone() else {
            return;
        };
        let atoms: Vec<SymbolicAtom> = self.symbolic_atoms().collect();
        let theory = self.program().theory_atoms.clone();
        let solver = self.solver.as_mut().expect("prepared");
        if !self.propagators.installed {
            let shared: SharedHook = hook.clone();
            solver.set_propagator(Some(shared));
            self.propagators.installed = true;
        }
        solver.begin_propagator_init();
        {
            let mut guard = hook.lock().unwrap_or_else(|p| p.into_inner());
            for (p, mode) in &mut guard.0 {
                *mode = CheckMode::Total;
                p.init(&mut PropagateInit {
                    solver: &mut *solver,
                    atoms: &atoms,
                    theory: &theory,
                    mode,
                    conditions: &mut self.propagators.conditions,
                });
            }
            let fixpoint = guard.0.iter().any(|(_, m)| m.fixpoint());
            solver.set_fixpoint_checks(fixpoint);
        }
        solver.end_propagator_init();
    }
}
