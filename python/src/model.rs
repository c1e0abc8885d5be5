//! `lucent.Model`: one answer set as a Python object (clingo's `Model`), copied out of the
//! solve callback so that it can be kept (clingo's models die with the callback; keeping them
//! here is harmless).
//!
//! Invariant: `shown` is what `#show` outputs (atoms and terms), `atoms` every true atom with a
//! symbol; `symbols(...)` combines them as clingo's selectors do.

use pyo3::prelude::*;

use crate::symbol::{to_symbol, Symbol};

/// An answer set (clingo's `Model`).
#[pyclass(frozen, module = "lucent")]
pub struct Model {
    number: usize,
    shown: Vec<lucent::Symbol>,
    /// Sorted, for `contains`.
    atoms: Vec<lucent::Symbol>,
    costs: Vec<i64>,
    optimal: bool,
}

impl Model {
    /// Copies the model the solver reports.
    pub fn new(m: &lucent::Model<'_>) -> Model {
        let mut atoms = m.atoms();
        atoms.sort();
        Model {
            number: m.number(),
            shown: m.symbols(),
            atoms,
            costs: m.costs().to_vec(),
            optimal: m.optimal(),
        }
    }
}

#[pymethods]
impl Model {
    /// The symbols selected: `atoms` every true atom, `shown` what `#show` shows, `terms` the
    /// shown terms that are no atoms.
    #[pyo3(signature = (atoms = false, terms = false, shown = false, theory = false, complement = false))]
    fn symbols(
        &self,
        atoms: bool,
        terms: bool,
        shown: bool,
        theory: bool,
        complement: bool,
    ) -> PyResult<Vec<Symbol>> {
        let _ = theory;
        if complement {
            return Err(pyo3::exceptions::PyRuntimeError::new_err(
                "Model.symbols(complement=True) is not supported by lucent",
            ));
        }
        let mut out: Vec<lucent::Symbol> = Vec::new();
        if atoms {
            out.extend(self.atoms.iter().cloned());
        }
        if shown {
            for s in &self.shown {
                if !out.contains(s) {
                    out.push(s.clone());
                }
            }
        } else if terms {
            for s in &self.shown {
                if self.atoms.binary_search(s).is_err() && !out.contains(s) {
                    out.push(s.clone());
                }
            }
        }
        Ok(out.into_iter().map(Symbol).collect())
    }

    /// Whether the atom `symbol` is true.
    fn contains(&self, symbol: &Bound<'_, PyAny>) -> PyResult<bool> {
        Ok(self.atoms.binary_search(&to_symbol(symbol)?).is_ok())
    }

    /// The costs, highest priority first.
    #[getter]
    fn cost(&self) -> Vec<i64> {
        self.costs.clone()
    }

    /// The model's number in its solve call (from 1).
    #[getter]
    fn number(&self) -> usize {
        self.number
    }

    /// True when the model is known to be optimal.
    #[getter]
    fn optimality_proven(&self) -> bool {
        self.optimal
    }

    fn __str__(&self) -> String {
        let text: Vec<String> = self.shown.iter().map(|s| s.to_string()).collect();
        text.join(" ")
    }

    fn __repr__(&self) -> String {
        self.__str__()
    }
}
