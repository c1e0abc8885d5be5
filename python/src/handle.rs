//! `lucent._lucent.SolveHandle`: the native half of clingo's `SolveHandle` (python/lucent/
//! __init__.py adds the callbacks `on_model`, `on_finish`, ...). It holds a detached search
//! (`lucent::control::Search`, its own thread owning the solver) and the Python Control it came
//! from; every wait releases the GIL, so the search thread (and a Python propagator in it, or
//! another Python thread calling `Control.interrupt`) runs meanwhile.
//!
//! Invariants: the solver goes back to the Control as soon as the search is over (seen by
//! `get`/`model`) or the handle is cancelled, closed or dropped, so the Control is usable
//! afterwards; while the search runs the Control refuses every other call with a
//! `RuntimeError` (`Control::idle`). Models are built on the reader's thread from the
//! Control's symbol table.

use std::time::Duration;

use lucent::control::{Search, Summary};
use pyo3::prelude::*;

use crate::control::{Control, Flags};
use crate::model::{AtomNames, Model};

/// A solve call read one result at a time (see the module documentation).
#[pyclass(unsendable, module = "lucent._lucent")]
pub struct SolveHandle {
    control: Py<Control>,
    /// `None` once the solver is back in the Control.
    search: Option<Search>,
    names: AtomNames,
    /// The Python model of the current result (so reading it twice gives one object).
    current: Option<Py<Model>>,
    /// The summary once the search is over.
    summary: Option<Summary>,
    /// The last model's costs, and how many models were reported optimal (for the
    /// statistics).
    costs: Vec<i64>,
    optimal: usize,
}

impl SolveHandle {
    pub fn new(control: Py<Control>, search: Search, names: AtomNames) -> SolveHandle {
        SolveHandle {
            control,
            search: Some(search),
            names,
            current: None,
            summary: None,
            costs: Vec::new(),
            optimal: 0,
        }
    }

    /// Gives the solver back once the search is over (or after cancelling it): the summary is
    /// kept and the Control records the call; a propagator's exception is raised.
    fn close_search(&mut self, py: Python<'_>) -> PyResult<()> {
        let Some(mut search) = self.search.take() else {
            return Ok(());
        };
        // Waiting for the thread's end without the GIL: a propagator may need it.
        py.allow_threads(|| {
            search.cancel();
        });
        let mut control = self.control.borrow_mut(py);
        let summary = control.end_handle(search, self.costs.clone(), self.optimal);
        self.summary = Some(summary);
        self.current = None;
        control.raise_propagator_error()
    }

    /// Waits (without the GIL) for the next result; closes the search when it is over.
    fn wait_result(&mut self, py: Python<'_>, timeout: Option<Duration>) -> PyResult<bool> {
        let Some(search) = self.search.as_mut() else {
            return Ok(true);
        };
        let ready = py.allow_threads(|| search.wait(timeout));
        if ready && search.is_finished() {
            self.close_search(py)?;
        }
        Ok(ready)
    }
}

#[pymethods]
impl SolveHandle {
    /// Discards the current model; the search goes on (starts, if it has not).
    fn resume(&mut self) {
        if let Some(s) = self.search.as_mut() {
            s.resume();
            self.current = None;
        }
    }

    /// Waits up to `timeout` seconds (`None`: forever) for a model or the end; true when one is
    /// there.
    #[pyo3(signature = (timeout = None))]
    fn wait(&mut self, py: Python<'_>, timeout: Option<f64>) -> PyResult<bool> {
        let timeout = timeout.map(|t| Duration::from_secs_f64(t.max(0.0)));
        self.wait_result(py, timeout)
    }

    /// The current model (waiting for it), `None` once the search is over.
    fn model(&mut self, py: Python<'_>) -> PyResult<Option<Py<Model>>> {
        self.wait_result(py, None)?;
        if let Some(m) = &self.current {
            return Ok(Some(m.clone_ref(py)));
        }
        let Some(search) = self.search.as_mut() else {
            return Ok(None);
        };
        let Some(raw) = search.model() else {
            return Ok(None);
        };
        self.costs = raw.costs.clone();
        self.optimal += usize::from(raw.optimal);
        let control = self.control.borrow(py);
        let model = control.read_model(raw, &self.names);
        let model = Py::new(py, model)?;
        self.current = Some(model.clone_ref(py));
        Ok(Some(model))
    }

    /// The result so far, after waiting for the next one: `((satisfiable, unsatisfiable,
    /// exhausted, interrupted, core), finished)`.
    fn get(&mut self, py: Python<'_>) -> PyResult<(Flags, bool)> {
        self.wait_result(py, None)?;
        let summary = match (&self.summary, self.search.as_mut()) {
            (Some(s), _) => s.clone(),
            (None, Some(search)) => search.get(),
            (None, None) => unreachable!("a handle has a search or its summary"),
        };
        let flags = self.control.borrow(py).outcome(&summary);
        Ok((flags, self.summary.is_some()))
    }

    /// Stops the search; the solver goes back to the Control.
    fn cancel(&mut self, py: Python<'_>) -> PyResult<()> {
        self.close_search(py)
    }

    /// clingo's `close` (leaving a `with` block): cancels what is unfinished.
    fn close(&mut self, py: Python<'_>) -> PyResult<()> {
        self.close_search(py)
    }
}

impl Drop for SolveHandle {
    /// A handle dropped open (no `with`, no `close`) ends its search, so that its Control works.
    fn drop(&mut self) {
        if self.search.is_some() {
            Python::with_gil(|py| {
                let _ = self.close_search(py);
            });
        }
    }
}
