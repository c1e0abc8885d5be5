//! A Python propagator (clingo's protocol: `init`, `propagate`, `undo`, `check`) as a
//! `lucent::control::Propagator`. The Python side (`_PropagatorAdapter` in
//! python/lucent/__init__.py) builds clingo's `PropagateInit` / `PropagateControl` /
//! `Assignment` objects over a live view of the engine (`live.rs`), valid for the callback:
//! the assignment is read as it is, clauses, `propagate`, watches and `add_literal` act at
//! once, as in clingo. The Python Control runs one thread, so the GIL is never awaited by a
//! solver thread while the caller's thread holds it.
//!
//! Invariant: an exception raised by the propagator (or a literal it invents) is kept, the
//! solve call is interrupted, and `Control.solve` raises it; nothing panics.

use lucent::control::{
    Assignment, CheckMode, Literal, PropagateControl, PropagateInit, Propagator,
};
use pyo3::prelude::*;
use std::sync::{Arc, Mutex};

use crate::live::{scoped, Target};
use crate::symbol::Symbol;

/// The first error of a propagator callback, raised by `Control.solve`.
pub type Failure = Arc<Mutex<Option<PyErr>>>;

/// The adapter object and where its errors go.
pub struct PyPropagator {
    pub adapter: PyObject,
    pub failure: Failure,
    pub interrupter: lucent::control::Interrupter,
}

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
        let threads = init.number_of_threads();
        let mode: PyResult<u8> = Python::with_gil(|py| {
            scoped(py, Target::init(init), |live| {
                self.adapter
                    .call_method1(py, "_init", (atoms, threads, live))?
                    .extract(py)
            })
        });
        match mode {
            Ok(mode) => init.set_check_mode(match mode {
                0 => CheckMode::None,
                2 => CheckMode::Fixpoint,
                3 => CheckMode::Both,
                _ => CheckMode::Total,
            }),
            Err(e) => self.fail(e),
        }
    }

    fn propagate(&mut self, ctl: &mut PropagateControl<'_>, changes: &[Literal]) {
        if self.failed() {
            return;
        }
        let thread = ctl.thread_id();
        let r = Python::with_gil(|py| {
            scoped(py, Target::control(ctl), |live| {
                self.adapter
                    .call_method1(py, "_propagate", (thread, changes.to_vec(), live))
                    .map(|_| ())
            })
        });
        if let Err(e) = r {
            self.fail(e);
        }
    }

    fn undo(&mut self, thread_id: u32, assignment: &Assignment<'_>, changes: &[Literal]) {
        if self.failed() {
            return;
        }
        let r = Python::with_gil(|py| {
            scoped(py, Target::assignment(assignment), |live| {
                self.adapter
                    .call_method1(py, "_undo", (thread_id, changes.to_vec(), live))
                    .map(|_| ())
            })
        });
        if let Err(e) = r {
            self.fail(e);
        }
    }

    fn check(&mut self, ctl: &mut PropagateControl<'_>) {
        if self.failed() {
            return;
        }
        let thread = ctl.thread_id();
        let r = Python::with_gil(|py| {
            scoped(py, Target::control(ctl), |live| {
                self.adapter
                    .call_method1(py, "_check", (thread, live))
                    .map(|_| ())
            })
        });
        if let Err(e) = r {
            self.fail(e);
        }
    }
}
