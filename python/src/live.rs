//! Live views of the solver for Python propagators: one [`Live`] object per callback points
//! at the engine's `PropagateControl`, `Assignment` or `PropagateInit` while the callback
//! runs, so the Python `Assignment`, `PropagateControl` and `PropagateInit`
//! (python/lucent/__init__.py) read the assignment as it is now and act at once, as in
//! clingo: `add_clause` answers whether the propagator may go on, `propagate` propagates,
//! `add_literal` makes a variable the next clause can use.
//!
//! Invariants:
//! - A `Live` object is valid only inside the callback that made it ([`scoped`]): when the
//!   callback returns (or unwinds) its target becomes `Gone`, and every later use raises
//!   `RuntimeError`, so a propagator that keeps `control.assignment` cannot reach a dead
//!   engine.
//! - Every literal is checked (`has_literal`) before it reaches the engine, whose views panic
//!   on foreign literals; a bad literal is a Python `RuntimeError`.
//! - The target is used only under its mutex, from the thread holding the GIL, and the Rust
//!   frame that lent it does not touch it until the callback returns; the engine never calls
//!   the hook again while one of its calls runs, so nothing here re-enters Python.

use lucent::control::{Assignment, Literal, PropagateControl, PropagateInit, WeightConstraintType};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use std::sync::Mutex;

/// What a live view points at.
pub enum Target {
    /// The callback returned.
    Gone,
    /// `propagate` or `check`.
    Control(*mut PropagateControl<'static>),
    /// `undo`.
    Assignment(*const Assignment<'static>),
    /// `init`.
    Init(*mut PropagateInit<'static>),
}

// SAFETY: a target's pointer is dereferenced only under the `Live` mutex, and only while the
// callback that lent the referent runs (`scoped` resets it to `Gone` before the borrow ends),
// so no access outlives the referent or races the frame that owns it.
unsafe impl Send for Target {}

impl Target {
    /// The view of a `propagate` or `check` call.
    pub fn control(ctl: &mut PropagateControl<'_>) -> Target {
        Target::Control((ctl as *mut PropagateControl<'_>).cast())
    }

    /// The view of an `undo` call.
    pub fn assignment(a: &Assignment<'_>) -> Target {
        Target::Assignment((a as *const Assignment<'_>).cast())
    }

    /// The view of an `init` call.
    pub fn init(init: &mut PropagateInit<'_>) -> Target {
        Target::Init((init as *mut PropagateInit<'_>).cast())
    }
}

/// A view that lives as long as one propagator callback (see the module documentation).
#[pyclass(frozen, module = "lucent._lucent")]
pub struct Live {
    target: Mutex<Target>,
}

/// Runs `f` with a live view of `target`; the view is dead when this returns.
pub fn scoped<R>(
    py: Python<'_>,
    target: Target,
    f: impl FnOnce(&Bound<'_, Live>) -> PyResult<R>,
) -> PyResult<R> {
    struct Reset<'a>(&'a Live);
    impl Drop for Reset<'_> {
        fn drop(&mut self) {
            *self.0.target.lock().unwrap_or_else(|p| p.into_inner()) = Target::Gone;
        }
    }
    let live = Bound::new(
        py,
        Live {
            target: Mutex::new(target),
        },
    )?;
    let _reset = Reset(live.get());
    f(&live)
}

fn gone() -> PyErr {
    PyRuntimeError::new_err(
        "lucent: a propagator's control or assignment was used after its callback returned",
    )
}

fn bad(l: Literal) -> PyErr {
    PyRuntimeError::new_err(format!("lucent: {l} is not a solver literal"))
}

fn unsupported(what: &str) -> PyErr {
    PyRuntimeError::new_err(format!("lucent: {what} is not available in this callback"))
}

impl Live {
    /// `f` over the assignment the view sees.
    fn read<R>(&self, f: impl FnOnce(&Assignment<'_>) -> PyResult<R>) -> PyResult<R> {
        let t = self.target.lock().unwrap_or_else(|p| p.into_inner());
        // SAFETY: see `Target`: the referent lives while the target is not `Gone`.
        match *t {
            Target::Gone => Err(gone()),
            Target::Control(p) => f(&unsafe { &*p }.assignment()),
            Target::Assignment(p) => f(unsafe { &*p }),
            Target::Init(p) => f(&unsafe { &*p }.assignment()),
        }
    }

    /// `f` over the control of a `propagate` or `check` call.
    fn control<R>(&self, f: impl FnOnce(&mut PropagateControl<'_>) -> PyResult<R>) -> PyResult<R> {
        let t = self.target.lock().unwrap_or_else(|p| p.into_inner());
        match *t {
            Target::Gone => Err(gone()),
            // SAFETY: see `Target`; the mutex makes this the only reference in use.
            Target::Control(p) => f(unsafe { &mut *p }),
            _ => Err(unsupported("this operation")),
        }
    }

    /// `f` over the init of an `init` call.
    fn init<R>(&self, f: impl FnOnce(&mut PropagateInit<'_>) -> PyResult<R>) -> PyResult<R> {
        let t = self.target.lock().unwrap_or_else(|p| p.into_inner());
        match *t {
            Target::Gone => Err(gone()),
            // SAFETY: see `Target`; the mutex makes this the only reference in use.
            Target::Init(p) => f(unsafe { &mut *p }),
            _ => Err(unsupported("this operation")),
        }
    }

    /// Checks that every literal names a variable.
    fn checked(&self, lits: &[Literal]) -> PyResult<()> {
        self.read(|a| match lits.iter().find(|&&l| !a.has_literal(l)) {
            Some(&l) => Err(bad(l)),
            None => Ok(()),
        })
    }

    fn is_init(&self) -> bool {
        matches!(
            *self.target.lock().unwrap_or_else(|p| p.into_inner()),
            Target::Init(_)
        )
    }
}

#[pymethods]
impl Live {
    /// `True`, `False` or `None` (unassigned).
    fn value(&self, l: Literal) -> PyResult<Option<bool>> {
        self.read(|a| {
            if !a.has_literal(l) {
                return Err(bad(l));
            }
            Ok(a.value(l))
        })
    }

    /// The decision level `l` was assigned at.
    fn level(&self, l: Literal) -> PyResult<u32> {
        self.read(|a| {
            if !a.has_literal(l) {
                return Err(bad(l));
            }
            Ok(a.level(l))
        })
    }

    /// Whether `l` is assigned at level 0.
    fn is_fixed(&self, l: Literal) -> PyResult<bool> {
        self.read(|a| {
            if !a.has_literal(l) {
                return Err(bad(l));
            }
            Ok(a.is_fixed(l))
        })
    }

    fn has_literal(&self, l: Literal) -> PyResult<bool> {
        self.read(|a| Ok(a.has_literal(l)))
    }

    /// The decision literal of `level`; level 0 answers `None` (the Python side gives clingo's
    /// answer there).
    fn decision(&self, level: u32) -> PyResult<Option<Literal>> {
        self.read(|a| Ok(a.decision(level)))
    }

    fn decision_level(&self) -> PyResult<u32> {
        self.read(|a| Ok(a.decision_level()))
    }

    fn root_level(&self) -> PyResult<u32> {
        self.read(|a| Ok(a.root_level()))
    }

    fn is_total(&self) -> PyResult<bool> {
        self.read(|a| Ok(a.is_total()))
    }

    fn size(&self) -> PyResult<usize> {
        self.read(|a| Ok(a.size()))
    }

    fn has_conflict(&self) -> PyResult<bool> {
        self.read(|a| Ok(a.has_conflict()))
    }

    fn trail_len(&self) -> PyResult<usize> {
        self.read(|a| Ok(a.trail_len()))
    }

    fn trail_at(&self, i: usize) -> PyResult<Option<Literal>> {
        self.read(|a| Ok(a.trail_at(i)))
    }

    fn trail_begin(&self, level: u32) -> PyResult<usize> {
        self.read(|a| Ok(a.trail_begin(level)))
    }

    /// Adds a clause: in `init` a problem clause (false: the problem is unsatisfiable), during
    /// search a learnt one (false: return at once).
    fn add_clause(&self, clause: Vec<Literal>) -> PyResult<bool> {
        self.checked(&clause)?;
        if self.is_init() {
            return self.init(|i| Ok(i.add_clause(&clause)));
        }
        self.control(|c| Ok(c.add_clause(&clause)))
    }

    /// Unit propagation of what was added (in `init`: before the search); false on a
    /// conflict.
    fn propagate(&self) -> PyResult<bool> {
        if self.is_init() {
            return self.init(|i| Ok(i.propagate()));
        }
        self.control(|c| Ok(c.propagate()))
    }

    /// In `init`: `literal` tied to `sum(w * l) >= bound` (clingo's `add_weight_constraint`;
    /// `kind` -1 left implication, 0 equivalence, 1 right implication); false on a conflict.
    fn add_weight_constraint(
        &self,
        literal: Literal,
        lits: Vec<(Literal, i32)>,
        bound: i32,
        kind: i32,
        compare_equal: bool,
    ) -> PyResult<bool> {
        let kind = match kind {
            -1 => WeightConstraintType::LeftImplication,
            0 => WeightConstraintType::Equivalence,
            1 => WeightConstraintType::RightImplication,
            _ => {
                return Err(PyRuntimeError::new_err(format!(
                    "invalid weight constraint type: {kind} (-1, 0 or 1)"
                )))
            }
        };
        let all: Vec<Literal> = std::iter::once(literal)
            .chain(lits.iter().map(|&(l, _)| l))
            .collect();
        self.checked(&all)?;
        self.init(|i| Ok(i.add_weight_constraint(literal, &lits, bound, kind, compare_equal)))
    }

    /// Watches `l` (in `init`: on every thread).
    fn add_watch(&self, l: Literal) -> PyResult<()> {
        self.checked(&[l])?;
        if self.is_init() {
            return self.init(|i| {
                i.add_watch(l);
                Ok(())
            });
        }
        self.control(|c| {
            c.add_watch(l);
            Ok(())
        })
    }

    fn remove_watch(&self, l: Literal) -> PyResult<()> {
        self.checked(&[l])?;
        if self.is_init() {
            return self.init(|i| {
                i.remove_watch(l);
                Ok(())
            });
        }
        self.control(|c| {
            c.remove_watch(l);
            Ok(())
        })
    }

    fn has_watch(&self, l: Literal) -> PyResult<bool> {
        self.checked(&[l])?;
        self.control(|c| Ok(c.has_watch(l)))
    }

    /// In `init`: the solver literal of a theory element's condition (program literals), a
    /// variable defined as their conjunction when there are several. One thread only.
    fn condition_literal(&self, condition: Vec<i32>) -> PyResult<Literal> {
        self.init(|i| {
            i.condition_literal(&condition).ok_or_else(|| {
                PyRuntimeError::new_err(
                    "lucent: a condition of several literals has a solver literal with one thread (-t 1) only",
                )
            })
        })
    }

    /// A new variable's positive literal: in `init` kept across solve calls, during search
    /// for this call only (clingo's volatile literal). One thread only.
    fn add_literal(&self) -> PyResult<Literal> {
        let one_thread = PyRuntimeError::new_err(
            "lucent: add_literal needs one thread (-t 1): helper threads cannot name new variables",
        );
        if self.is_init() {
            return self.init(|i| {
                if i.number_of_threads() > 1 {
                    return Err(one_thread);
                }
                Ok(i.add_literal())
            });
        }
        self.control(|c| {
            if c.thread_id() != 0 {
                return Err(one_thread);
            }
            Ok(c.add_literal())
        })
    }
}
