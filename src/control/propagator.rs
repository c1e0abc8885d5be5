//! clingo's propagator interface on [`Control`]: a [`Propagator`] registered with
//! [`Control::register_propagator`] gets `init` before every solve call (symbolic atoms to
//! solver literals, watches, static clauses, fixed values), then `propagate` when watched
//! literals become true, `undo` when backtracking unassigns them, and `check` on every total
//! assignment (clingo's check mode `total`), from inside the CDCL search (`solve::propagator`).
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
//!
//! Invariant: the propagators are installed on the solver once it exists and reinstalled (watches
//! reset, every `init` called again) after a registration.

use super::{AtomId, Control, SymbolicAtom};
use crate::solve::engine::SharedHook;
use crate::solve::propagator::Hook;
pub use crate::solve::propagator::{Assignment, Literal, PropagateControl};
use crate::solve::Solver;
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
    /// The assignment is total; a clause refuting it makes the search go on.
    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        let _ = ctl;
    }
}

/// What `init` gets (clingo's `PropagateInit`).
pub struct PropagateInit<'a> {
    solver: &'a mut Solver,
    atoms: &'a [SymbolicAtom],
    theory: &'a [super::theory::TheoryAtom],
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

    /// The threads the propagator will be called from.
    pub fn number_of_threads(&self) -> usize {
        self.solver.num_threads()
    }

    /// The assignment at level 0: the values fixed before search.
    pub fn assignment(&self) -> Assignment<'_> {
        self.solver.propagator_assignment()
    }
}

/// The registered propagators, one hook for the engines.
#[derive(Default)]
pub(super) struct Registered(Vec<Box<dyn Propagator>>);

impl Hook for Registered {
    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        for p in &mut self.0 {
            p.propagate(ctl, changes);
            if ctl.assignment().has_conflict() {
                return;
            }
        }
    }

    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        for p in &mut self.0 {
            p.undo(thread_id, assignment, changes);
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        for p in &mut self.0 {
            p.check(ctl);
            if ctl.assignment().has_conflict() {
                return;
            }
        }
    }
}

/// The propagators of a Control and whether the solver has them.
#[derive(Default)]
pub(super) struct Propagators {
    hook: Option<Arc<Mutex<Registered>>>,
    installed: bool,
}

impl Control {
    /// Registers a propagator (clingo's `register_propagator`); it takes part in every later
    /// solve call.
    pub fn register_propagator(&mut self, propagator: Box<dyn Propagator + Send>) {
        let hook = self.propagators.hook.get_or_insert_with(Default::default);
        hook.lock()
            .unwrap_or_else(|p| p.into_inner())
            .0
            .push(propagator);
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
            for p in &mut guard.0 {
                p.init(&mut PropagateInit {
                    solver: &mut *solver,
                    atoms: &atoms,
                    theory: &theory,
                });
            }
        }
        solver.end_propagator_init();
    }
}
