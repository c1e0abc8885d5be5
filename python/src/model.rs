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

use std::sync::{Arc, Mutex, OnceLock};

use lucent::solve::EnumMode;
use pyo3::prelude::*;

use crate::solve_control::SolveControl;
use crate::symbol::{to_symbol, Symbol};

/// The Control's atoms as models read them (both `[a - 1]`): each one's symbol (`None` for
/// auxiliary atoms) and its place in a model's list of atoms (`Control::atom_order`: clingo's
/// order, by predicate domain, then by atom).
#[derive(Clone, Default)]
pub struct AtomTable {
    pub symbols: Vec<Option<lucent::Symbol>>,
    pub keys: Vec<u64>,
}

/// The Control's atom table, shared by its models.
pub type AtomNames = Arc<AtomTable>;

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
    /// In clingo's order (`AtomTable::keys`), for `symbols(atoms=True)`.
    atoms_listed: OnceLock<Vec<lucent::Symbol>>,
    /// The priority of each cost level, highest first (clingo's `Model.priority`).
    priorities: Arc<Vec<i64>>,
    /// Symbols added by `extend` (printed after the model by `lucent.application`).
    extended: Mutex<Vec<lucent::Symbol>>,
    /// The portfolio thread that found it.
    thread_id: u32,
    /// The solve call's `SolveControl` (`solve_control.rs`).
    context: Option<Py<SolveControl>>,
    /// What the call enumerates: answer sets, or brave or cautious consequences.
    mode: EnumMode,
}

/// What a solve call asks for, as its models report it.
#[derive(Clone, Copy)]
pub struct CallKind {
    /// Answer sets, or brave or cautious consequences (`Model.type`).
    pub mode: EnumMode,
    /// `--opt-mode=ignore`: the minimize statements are ignored, so models have no costs.
    pub ignore_costs: bool,
}

impl Model {
    /// Copies the model the solver reports; `names` covers its atoms, `priorities` are the
    /// program's minimize priorities, highest first, `context` the call's `SolveControl`.
    pub fn new(
        m: &lucent::Model<'_>,
        names: AtomNames,
        priorities: Arc<Vec<i64>>,
        context: Option<Py<SolveControl>>,
        kind: CallKind,
    ) -> Model {
        Model {
            mode: kind.mode,
            thread_id: m.thread_id(),
            context,
            number: m.number(),
            costs: if kind.ignore_costs {
                Vec::new()
            } else {
                m.costs().to_vec()
            },
            optimal: m.optimal(),
            atom_ids: m.atom_ids().to_vec(),
            names,
            shown_text: m.shown_text().to_vec(),
            shown: OnceLock::new(),
            atoms: OnceLock::new(),
            atoms_listed: OnceLock::new(),
            priorities,
            extended: Mutex::new(Vec::new()),
        }
    }

    fn shown(&self) -> &[lucent::Symbol] {
        self.shown.get_or_init(|| {
            self.shown_text
                .iter()
                .map(|s| lucent::Symbol::from_shown(s))
                .collect()
        })
    }

    fn atoms(&self) -> &[lucent::Symbol] {
        self.atoms.get_or_init(|| {
            let mut atoms = self.atoms_listed().to_vec();
            atoms.sort();
            atoms
        })
    }

    /// The true atoms with a symbol as clingo lists them (by `AtomTable::keys`).
    fn atoms_listed(&self) -> &[lucent::Symbol] {
        self.atoms_listed.get_or_init(|| {
            let table = &self.names;
            let mut ids: Vec<u32> = self
                .atom_ids
                .iter()
                .copied()
                .filter(|&a| matches!(table.symbols.get(a as usize - 1), Some(Some(_))))
                .collect();
            // Stable: equal keys (atoms from the backend) stay in atom order.
            ids.sort_by_key(|&a| table.keys.get(a as usize - 1).copied().unwrap_or(u64::MAX));
            ids.iter()
                .filter_map(|&a| table.symbols[a as usize - 1].clone())
                .collect()
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
        py: Python<'_>,
        atoms: bool,
        terms: bool,
        shown: bool,
        theory: bool,
        complement: bool,
    ) -> PyResult<PyObject> {
        let _ = theory;
        if complement {
            return Err(pyo3::exceptions::PyRuntimeError::new_err(
                "Model.symbols(complement=True) is not supported by lucent",
            ));
        }
        // The shown symbols come without repeats; the atoms are sorted, so a shown symbol is
        // looked up among them (linear in the model, where a scan of `out` per symbol was
        // quadratic: 1.6 s for a model of 20,000 shown atoms).
        let mut out: Vec<lucent::Symbol> = Vec::new();
        if atoms {
            out.extend(self.atoms_listed().iter().cloned());
        }
        if shown || terms {
            let skip_atoms = atoms || !shown;
            for s in self.shown() {
                if !skip_atoms || self.atoms().binary_search(s).is_err() {
                    out.push(s.clone());
                }
            }
        }
        let list: Vec<Symbol> = out.into_iter().map(Symbol).collect();
        symbol_sequence(py, list)
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

    /// The priority of each cost level, as `cost` (empty without optimization).
    #[getter]
    fn priority(&self) -> Vec<i64> {
        if self.costs.is_empty() {
            Vec::new()
        } else {
            self.priorities.to_vec()
        }
    }

    /// Whether the program literal (an atom's literal from `symbolic_atoms`, negative for its
    /// negation) is true in the model.
    fn is_true(&self, literal: i64) -> bool {
        let atom = literal.unsigned_abs();
        let holds = u32::try_from(atom).is_ok_and(|a| self.atom_ids.binary_search(&a).is_ok());
        holds == (literal > 0)
    }

    /// clingo's `Model.is_consequence(literal)`: for a stable model whether the literal is
    /// true; for brave consequences `True` for an atom of the model and `None` (not known yet)
    /// otherwise; for cautious consequences `False` for an atom not in the model, `True` for a
    /// fact and `None` otherwise. A negative literal under `--enum-mode` is `None`.
    fn is_consequence(&self, py: Python<'_>, literal: i64) -> Option<bool> {
        if self.mode == EnumMode::Auto {
            return Some(self.is_true(literal));
        }
        let atom = u32::try_from(literal).ok()?;
        let holds = self.atom_ids.binary_search(&atom).is_ok();
        match self.mode {
            EnumMode::Brave => holds.then_some(true),
            _ if !holds => Some(false),
            _ => {
                let fact = self
                    .context
                    .as_ref()
                    .is_some_and(|c| c.bind(py).get().kinds(atom).0);
                fact.then_some(true)
            }
        }
    }

    /// clingo's `Model.type`: a stable model, or the brave or cautious consequences found so
    /// far under `--enum-mode` (`configuration.solve.enum_mode`).
    #[getter]
    fn r#type<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let name = match self.mode {
            EnumMode::Auto => "StableModel",
            EnumMode::Brave => "BraveConsequences",
            EnumMode::Cautious => "CautiousConsequences",
        };
        py.import_bound("lucent")?
            .getattr("ModelType")?
            .getattr(name)
    }

    /// Adds symbols to the model's output (clingo prints them after the model when an
    /// application runs; `str(model)` and `symbols` do not change, as in clingo).
    fn extend(&self, symbols: Vec<Bound<'_, PyAny>>) -> PyResult<()> {
        let mut added = Vec::with_capacity(symbols.len());
        for s in &symbols {
            added.push(to_symbol(s)?);
        }
        self.extended
            .lock()
            .map_err(|_| pyo3::exceptions::PyRuntimeError::new_err("model lock poisoned"))?
            .extend(added);
        Ok(())
    }

    /// The symbols added by `extend`, in order (for `lucent.application`).
    #[getter]
    fn _extended(&self) -> Vec<Symbol> {
        self.extended
            .lock()
            .map(|e| e.iter().cloned().map(Symbol).collect())
            .unwrap_or_default()
    }

    /// The portfolio thread that found the model (0 with one thread).
    #[getter]
    fn thread_id(&self) -> u32 {
        self.thread_id
    }

    /// The solve call's `SolveControl`: its symbolic atoms, clauses for the rest of the call.
    #[getter]
    fn context(&self, py: Python<'_>) -> PyResult<Py<SolveControl>> {
        self.context
            .as_ref()
            .map(|c| c.clone_ref(py))
            .ok_or_else(|| {
                pyo3::exceptions::PyRuntimeError::new_err("lucent: this model has no solve call")
            })
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

/// `symbols` as clingo's sequence of a model's symbols (`lucent._SymbolSequence`, a list that
/// prints its symbols as `str`: `[a, b(1)]`).
fn symbol_sequence(py: Python<'_>, symbols: Vec<Symbol>) -> PyResult<PyObject> {
    static CLASS: pyo3::sync::GILOnceCell<PyObject> = pyo3::sync::GILOnceCell::new();
    let class = CLASS.get_or_try_init(py, || -> PyResult<PyObject> {
        Ok(py
            .import_bound("lucent")?
            .getattr("_SymbolSequence")?
            .unbind())
    })?;
    class.call1(py, (symbols,))
}
