//! A Python propagator (clingo's protocol: `init`, `propagate`, `undo`, `check`) as a
//! `lucent::control::Propagator`. The Python side (`_PropagatorAdapter` in
//! python/lucent/__init__.py) builds clingo's `PropagateInit` / `PropagateControl` /
//! `Assignment` objects over plain data: each callback gets a snapshot of the assignment
//! (values `±1`, `±2` when fixed at level 0, `0` unassigned, per variable; the decisions) and
//! returns the
//! operations the propagator asked for (clauses, `propagate`, watches), which are replayed
//! here on the real engine in order, stopping at the first conflict.
//!
//! Differences from clingo, documented in the package: inside one callback the propagator sees
//! the assignment as it was when the callback started (its own clauses and `propagate` act
//! when it returns), and `add_clause`/`propagate` answer `True`; for the same reason
//! `PropagateControl.add_literal` is missing (the literal would be needed inside the callback,
//! before the replay makes the variable). A snapshot costs one pass over the variables per
//! callback; a live view would need the engine borrowed by a Python object across the call. The Python Control runs one thread, so the GIL is never
//! awaited by a solver thread while the caller's thread holds it.
//!
//! Invariant: an exception raised by the propagator (or a literal it invents) is kept, the
//! solve call is interrupted, and `Control.solve` raises it; nothing panics.

use lucent::control::{
    Assignment, CheckMode, Literal, PropagateControl, PropagateInit, Propagator,
};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::{Arc, Mutex};

use crate::symbol::Symbol;

/// The first error of a propagator callback, raised by `Control.solve`.
pub type Failure = Arc<Mutex<Option<PyErr>>>;

/// The adapter object and where its errors go.
pub struct PyPropagator {
    pub adapter: PyObject,
    pub failure: Failure,
    pub interrupter: lucent::control::Interrupter,
}

/// The assignment as the Python side reads it: values per variable, decision level, total,
/// the decision literal of each level (0: an empty level).
fn snapshot(a: &Assignment<'_>) -> (Vec<i8>, u32, bool, Vec<Literal>) {
    let values = (1..=a.size() as Literal)
        .map(|l| match a.value(l) {
            None => 0,
            Some(v) => {
                let s = if v { 1 } else { -1 };
                if a.level(l) == 0 {
                    2 * s
                } else {
                    s
                }
            }
        })
        .collect();
    let decisions = (1..=a.decision_level())
        .map(|l| a.decision(l).unwrap_or(0))
        .collect();
    (values, a.decision_level(), a.is_total(), decisions)
}

type Ops = Vec<(String, Vec<Literal>)>;

impl PyPropagator {
    fn fail(&self, e: PyErr) {
        let mut f = self.failure.lock().unwrap_or_else(|p| p.into_inner());
        f.get_or_insert(e);
        self.interrupter.interrupt();
    }

    fn failed(&self) -> bool {
        self.failure
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .is_some()
    }

    /// Replays `ops` on `ctl` in order; stops at a conflict.
    fn replay(&self, ctl: &mut PropagateControl<'_>, ops: Ops) {
        let size = ctl.assignment().size();
        for (op, lits) in ops {
            if let Some(&bad) = lits
                .iter()
                .find(|&&l| l == 0 || l.unsigned_abs() as usize > size)
            {
                self.fail(PyRuntimeError::new_err(format!(
                    "{bad} is not a solver literal"
                )));
                return;
            }
            let go_on = match (op.as_str(), lits.first()) {
                ("c", _) => ctl.add_clause(&lits),
                ("p", _) => ctl.propagate(),
                ("w", Some(&l)) => {
                    ctl.add_watch(l);
                    true
                }
                ("u", Some(&l)) => {
                    ctl.remove_watch(l);
                    true
                }
                _ => true,
            };
            if !go_on {
                return;
            }
        }
    }
}

impl Propagator for PyPropagator {
    fn init(&mut self, init: &mut PropagateInit<'_>) {
        let atoms: Vec<(Symbol, u32, bool, bool, Literal)> = init
            .symbolic_atoms()
            .iter()
            .map(|a| {
                (
                    Symbol(a.symbol.clone()),
                    a.atom,
                    a.fact,
                    a.external,
                    init.solver_literal(a.atom),
                )
            })
            .collect();
        let (values, _, _, _) = snapshot(&init.assignment());
        let threads = init.number_of_threads();
        let size = values.len();
        let out: PyResult<(Vec<Literal>, Vec<Vec<Literal>>, u8)> = Python::with_gil(|py| {
            self.adapter
                .call_method1(py, "_init", (atoms, threads, values))?
                .extract(py)
        });
        match out {
            Ok((watches, clauses, mode)) => {
                init.set_check_mode(match mode {
                    0 => CheckMode::None,
                    2 => CheckMode::Fixpoint,
                    3 => CheckMode::Both,
                    _ => CheckMode::Total,
                });
                let bad = watches
                    .iter()
                    .chain(clauses.iter().flatten())
                    .find(|&&l| l == 0 || l.unsigned_abs() as usize > size);
                if let Some(&bad) = bad {
                    self.fail(PyRuntimeError::new_err(format!(
                        "{bad} is not a solver literal"
                    )));
                    return;
                }
                for l in watches {
                    init.add_watch(l);
                }
                for c in clauses {
                    init.add_clause(&c);
                }
            }
            Err(e) => self.fail(e),
        }
    }

    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        if self.failed() {
            return;
        }
        let (values, level, total, decisions) = snapshot(&ctl.assignment());
        let thread = ctl.thread_id();
        let ops: PyResult<Ops> = Python::with_gil(|py| {
            self.adapter
                .call_method1(
                    py,
                    "_propagate",
                    (thread, changes.to_vec(), (values, level, total, decisions)),
                )?
                .extract(py)
        });
        match ops {
            Ok(ops) => self.replay(ctl, ops),
            Err(e) => self.fail(e),
        }
    }

    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        if self.failed() {
            return;
        }
        let snap = snapshot(assignment);
        let r = Python::with_gil(|py| {
            self.adapter
                .call_method1(py, "_undo", (thread_id, changes.to_vec(), snap))
                .map(|_| ())
        });
        if let Err(e) = r {
            self.fail(e);
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        if self.failed() {
            return;
        }
        let snap = snapshot(&ctl.assignment());
        let thread = ctl.thread_id();
        let ops: PyResult<Ops> = Python::with_gil(|py| {
            self.adapter
                .call_method1(py, "_check", (thread, snap))?
                .extract(py)
        });
        match ops {
            Ok(ops) => self.replay(ctl, ops),
            Err(e) => self.fail(e),
        }
    }
}
