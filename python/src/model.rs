//! `lucent.Model`: one answer set as a Python object (clingo's `Model`), copied out of the
//! solve callback so that it can be kept (clingo's models die with the callback; keeping them
//! here is harmless).
//!
//! Invariants: `shown` is what `#show` outputs (atoms and terms), `atoms` every true atom with a
//! symbol; `symbols(...)` combines them as clingo's selectors do. A model copies only its true
//! atoms' numbers and its shown text when it is made; the symbols are built on first use, from
//! the Control's table of atom symbols ([`AtomNames`], shared, extended as atoms are added and
//! never changed, since an atom keeps its symbol), so a callback that only counts models (or
//! reads the costs) does not pay for the whole answer set as symbols.

use std::sync::{Arc, OnceLock};

use pyo3::prelude::*;

use crate::symbol::{to_symbol, Symbol};

/// The symbol of each atom (`[a - 1]`), `None` for auxiliary atoms.
pub type AtomNames = Arc<Vec<Option<lucent::Symbol>>>;

/// An answer set (clingo's `Model`).
#[pyclass(frozen, module = "lucent")]
pub struct Model {
    number: usize,
    costs: Vec<i64>,
    optimal: bool,
    /// The true atoms, increasing.
    atom_ids: Vec<u32>,
    names: AtomNames,
    /// The shown symbols as the solver printed them.
    shown_text: Vec<String>,
    shown: OnceLock<Vec<lucent::Symbol>>,
    /// Sorted, for `contains`.
    atoms: OnceLock<Vec<lucent::Symbol>>,
}

impl Model {
    /// Copies the model the solver reports; `names` covers its atoms.
    pub fn new(m: &lucent::Model<'_>, names: AtomNames) -> Model {
        Model {
            number: m.number(),
            costs: m.costs().to_vec(),
            optimal: m.optimal(),
            atom_ids: m.atom_ids().to_vec(),
            names,
            shown_text: m.shown_text().to_vec(),
            shown: OnceLock::new(),
            atoms: OnceLock::new(),
        }
    }

    fn shown(&self) -> &[lucent::Symbol] {
        self.shown.get_or_init(|| {
            self.shown_text
                .iter()
                .filter_map(|s| lucent::Symbol::parse(s).ok())
                .collect()
        })
    }

    fn atoms(&self) -> &[lucent::Symbol] {
        self.atoms.get_or_init(|| {
            let mut atoms: Vec<lucent::Symbol> = self
                .atom_ids
                .iter()
                .filter_map(|&a| self.names.get(a as usize - 1).cloned().flatten())
                .collect();
            atoms.sort();
            atoms
        })
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
            out.extend(self.atoms().iter().cloned());
        }
        if shown {
            for s in self.shown() {
                if !out.contains(s) {
                    out.push(s.clone());
                }
            }
        } else if terms {
            for s in self.shown() {
                if self.atoms().binary_search(s).is_err() && !out.contains(s) {
                    out.push(s.clone());
                }
            }
        }
        Ok(out.into_iter().map(Symbol).collect())
    }

    /// Whether the atom `symbol` is true.
    fn contains(&self, symbol: &Bound<'_, PyAny>) -> PyResult<bool> {
        Ok(self.atoms().binary_search(&to_symbol(symbol)?).is_ok())
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
        self.shown_text.join(" ")
    }

    fn __repr__(&self) -> String {
        self.__str__()
    }
}
