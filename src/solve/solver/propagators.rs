//! The solver's side of an external propagator (`solve::propagator`): one hook installed on
//! every engine of the portfolio (engine `k` calls it with thread id `k`, behind one mutex, as
//! clingo calls one propagator from every thread), the solver literals of atoms, and what
//! `init` does before each solve call (watches, static clauses, fixed values).
//!
//! Invariants: user literals name the main engine's variables; before every init the helpers'
//! literal maps are rebuilt from the atoms (a multi-shot step adds atoms, and helpers recycle
//! variables differently), so an atom's literal means the same atom on every thread. During an
//! init every engine is at level 0 and its hook is paused (`Engine::set_external_busy`).

use super::*;
use crate::solve::engine::{LitMap, SharedHook};
use crate::solve::propagator::{Assignment, Literal};

impl Solver {
    /// Installs `hook` on every engine (thread ids `0..threads`), or removes it; watches
    /// start empty.
    pub(crate) fn set_propagator(&mut self, hook: Option<SharedHook>) {
        self.engine.set_external(hook.clone().map(|h| (h, 0)));
        if let Some(par) = self.par.as_mut() {
            for (k, h) in par.helpers_mut().iter_mut().enumerate() {
                h.engine
                    .set_external(hook.clone().map(|x| (x, k as u32 + 1)));
            }
        }
    }

    /// The number of engines (threads) a propagator is called from.
    pub fn num_threads(&self) -> usize {
        1 + self.par.as_ref().map_or(0, |p| p.helpers_len())
    }

    /// The solver literal of `atom` (clingo's `solver_literal`): `±(v + 1)` for the main
    /// engine's variable `v`; atom 0 is the literal that is always true. Panics for an atom the
    /// solver does not have.
    pub fn solver_literal(&self, atom: u32) -> Literal {
        let l = *self
            .tr
            .atom_lit
            .get(atom as usize)
            .unwrap_or_else(|| panic!("atom {atom} is not an atom of this solver"));
        self.engine.user_lit(l)
    }

    /// Before a propagator's `init`: every engine at level 0 (undoing for the hook), the
    /// helpers' literal maps rebuilt, hooks paused until [`Solver::end_propagator_init`].
    pub(crate) fn begin_propagator_init(&mut self) {
        self.engine.backtrack(0);
        self.engine.set_external_busy(true);
        let main_lits = &self.tr.atom_lit;
        let main_vars = self.engine.num_vars();
        if let Some(par) = self.par.as_mut() {
            for h in par.helpers_mut() {
                h.engine.backtrack(0);
                let mut m = LitMap {
                    to_local: vec![None; main_vars],
                    to_user: vec![0; h.engine.num_vars()],
                };
                for (&ml, &hl) in main_lits.iter().zip(&h.tr.atom_lit) {
                    // `hpos` is the helper's literal of the main variable's positive literal.
                    let hpos = if ml.is_neg() { !hl } else { hl };
                    let user = ml.var().index() as Literal + 1;
                    m.to_local[ml.var().index()] = Some(hpos);
                    m.to_user[hpos.var().index()] = if hpos.is_neg() { -user } else { user };
                }
                h.engine.set_lit_map(Some(m));
                h.engine.set_external_busy(true);
            }
        }
    }

    /// After the inits: hooks called again.
    pub(crate) fn end_propagator_init(&mut self) {
        self.engine.set_external_busy(false);
        if let Some(par) = self.par.as_mut() {
            for h in par.helpers_mut() {
                h.engine.set_external_busy(false);
            }
        }
    }

    /// Whether every engine calls the hook's `check_fixpoint` at each propagation fixpoint.
    pub(crate) fn set_fixpoint_checks(&mut self, on: bool) {
        for e in self.engines_mut() {
            e.set_fixpoint_checks(on);
        }
    }

    /// A new variable of the main engine for a propagator's `init` (clingo's
    /// `PropagateInit.add_literal`): kept across calls, decided on like any other. `None` with
    /// helper threads, whose literal maps name only atoms.
    pub(crate) fn propagator_new_var(&mut self) -> Option<Literal> {
        if self.par.is_some() {
            return None;
        }
        let v = self.engine.new_var();
        Some(self.engine.user_lit(v.positive()))
    }

    /// Every engine of the solver, the main one first.
    fn engines_mut(&mut self) -> Vec<&mut Engine> {
        let mut out = vec![&mut self.engine];
        if let Some(par) = self.par.as_mut() {
            out.extend(par.helpers_mut().iter_mut().map(|h| &mut h.engine));
        }
        out
    }

    /// Watches `l` on every engine (`PropagateInit::add_watch`).
    pub(crate) fn propagator_watch(&mut self, l: Literal) {
        for e in self.engines_mut() {
            let local = e
                .user_to_local(l)
                .unwrap_or_else(|| panic!("{l} is not a solver literal of this solver"));
            e.watch_external(local, true);
        }
    }

    /// Stops watching `l` on every engine (`PropagateInit::remove_watch`).
    pub(crate) fn propagator_unwatch(&mut self, l: Literal) {
        for e in self.engines_mut() {
            if let Some(local) = e.user_to_local(l) {
                e.watch_external(local, false);
            }
        }
    }

    /// Unit propagation at level 0 on every engine (`PropagateInit::propagate`); false when the
    /// problem became inconsistent.
    pub(crate) fn propagator_propagate(&mut self) -> bool {
        let mut ok = true;
        for e in self.engines_mut() {
            ok &= e.propagate_root();
        }
        ok
    }

    /// Adds the weight constraint `head -> sum >= bound` (with `implication`) or
    /// `head <-> sum >= bound` at level 0 to every engine; false when the problem became
    /// inconsistent.
    pub(crate) fn propagator_weight(
        &mut self,
        head: Literal,
        lits: &[(Literal, i64)],
        bound: i64,
        implication: bool,
    ) -> bool {
        let mut ok = true;
        for e in self.engines_mut() {
            let local = |l: Literal| {
                e.user_to_local(l)
                    .unwrap_or_else(|| panic!("{l} is not a solver literal of this solver"))
            };
            let h = local(head);
            let ls: Vec<(Lit, i64)> = lits.iter().map(|&(l, w)| (local(l), w)).collect();
            ok &= if implication {
                e.add_weight_implication(h, &ls, bound)
            } else {
                e.add_weight(h, &ls, bound)
            };
        }
        ok
    }

    /// Adds a clause at level 0 to every engine (`PropagateInit::add_clause`); false when the
    /// problem became inconsistent.
    pub(crate) fn propagator_clause(&mut self, clause: &[Literal]) -> bool {
        let mut ok = true;
        for e in self.engines_mut() {
            let lits: Vec<Lit> = clause
                .iter()
                .map(|&l| {
                    e.user_to_local(l)
                        .unwrap_or_else(|| panic!("{l} is not a solver literal of this solver"))
                })
                .collect();
            ok &= e.add_clause(&lits);
        }
        ok
    }

    /// The main engine's assignment (at level 0 during an init: the fixed values).
    pub(crate) fn propagator_assignment(&self) -> Assignment<'_> {
        Assignment {
            engine: &self.engine,
        }
    }
}
