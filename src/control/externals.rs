//! External atoms of a [`Control`]: their values (clingo's `assign_external`), their
//! release, and what each solve call makes of them (the values assumed, the releases handed
//! to the solver, the released atoms that leave the symbolic atoms at the next update).
//!
//! Invariants: `externals` holds every atom that is still external, with its value, or `None`
//! once released and until the next solve call hands the release to the solver, which makes
//! the atom false for good (`released`); an atom released and handed over is listed among the
//! symbolic atoms until the next update call (grounding, assignment, release, backend), as in
//! clingo 5.8, then flagged `DROPPED`.

use super::*;

impl Control {
    /// Every external atom, free, for the solver built at the first solve call (the values
    /// of each call are its assumptions).
    pub(super) fn free_externals(&self) -> Vec<(AtomId, ExternalValue)> {
        let mut v: Vec<(AtomId, ExternalValue)> = self
            .externals
            .keys()
            .map(|&a| (a, ExternalValue::Free))
            .collect();
        v.sort_unstable_by_key(|&(a, _)| a);
        v
    }

    /// Sets the value of an external atom (clingo's `assign_external`). Atoms that are not
    /// external are left alone, as clingo does.
    pub fn assign_external(&mut self, atom: &Symbol, value: TruthValue) {
        self.begin_update();
        if let Some(a) = self.lookup(atom) {
            // (A released atom left the map: it stays false.)
            if let Some(v) = self.externals.get_mut(&a) {
                if v.is_some() {
                    *v = Some(value);
                }
            }
        }
    }

    /// Releases an external atom: it is false from now on and no longer external (clingo's
    /// `release_external`).
    pub fn release_external(&mut self, atom: &Symbol) {
        self.begin_update();
        if let Some(a) = self.lookup(atom) {
            if let Some(v) = self.externals.get_mut(&a) {
                *v = None;
            }
        }
    }

    /// What every call that changes the program or its externals does first: the externals
    /// released by earlier solve calls leave the symbolic atoms, as in clingo.
    pub(super) fn begin_update(&mut self) {
        for a in std::mem::take(&mut self.fresh_releases) {
            self.flags[a as usize - 1] |= DROPPED;
        }
    }

    /// Released externals become false for good in the solver (no assumption per call).
    pub(super) fn release_in_solver(&mut self) {
        let Some(solver) = &mut self.solver else {
            return;
        };
        let released: Vec<AtomId> = self
            .externals
            .iter()
            .filter(|(_, v)| v.is_none())
            .map(|(&a, _)| a)
            .collect();
        for a in released {
            // An atom that is no longer free in the solver is complete already.
            let _ = solver.release_external(a);
            self.externals.remove(&a);
            self.released.insert(a);
            self.fresh_releases.push(a);
        }
    }

    /// The literals assumed in every call: the values of the externals.
    pub(super) fn external_assumptions(&self, out: &mut Vec<i32>) {
        for (&a, v) in &self.externals {
            match v {
                Some(TruthValue::True) => out.push(a as i32),
                Some(TruthValue::False) | None => out.push(-(a as i32)),
                Some(TruthValue::Free) => {}
            }
        }
        out.sort_unstable_by_key(|l| l.unsigned_abs());
    }
}
