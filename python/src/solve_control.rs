//! `Model.context` (clingo's `SolveControl`): what a model callback may use of its solve
//! call, the symbolic atoms and clauses for the rest of the call
//! (`lucent::control::Control::model_clauses`). One object per solve call, made before the
//! call starts, since the Control itself is busy while the callback runs.
//!
//! Invariants: the atoms are those of the call (symbols from the Control's table, fact and
//! external flags as the call started); a clause names only atoms of the program (a literal of
//! no atom is a `RuntimeError`; a symbol without an atom is a false atom, so it leaves the
//! clause, or satisfies it when negated, as in clingo).

use std::sync::OnceLock;

use lucent::solve::ModelClauses;
use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;
use std::collections::HashMap;

use crate::model::AtomNames;
use crate::symbol::{to_symbol, Symbol};

/// A solve call's `SolveControl`.
#[pyclass(frozen, module = "lucent._lucent")]
pub struct SolveControl {
    names: AtomNames,
    /// Per atom (`[a - 1]`): whether it is a fact.
    facts: Vec<bool>,
    /// The external atoms, increasing.
    externals: Vec<u32>,
    clauses: ModelClauses,
    by_symbol: OnceLock<HashMap<lucent::Symbol, u32>>,
}

impl SolveControl {
    /// The view of a call over `names` (every atom's symbol), the flags and the clause queue.
    pub fn new(
        names: AtomNames,
        (facts, externals): (Vec<bool>, Vec<u32>),
        clauses: ModelClauses,
    ) -> SolveControl {
        SolveControl {
            names,
            facts,
            externals,
            clauses,
            by_symbol: OnceLock::new(),
        }
    }

    pub(crate) fn kinds(&self, atom: u32) -> (bool, bool) {
        let fact = self.facts.get(atom as usize - 1).copied().unwrap_or(false);
        (fact, self.externals.binary_search(&atom).is_ok())
    }

    fn atom_of(&self, symbol: &lucent::Symbol) -> Option<u32> {
        self.by_symbol
            .get_or_init(|| {
                let mut map = HashMap::new();
                for (i, s) in self.names.symbols.iter().enumerate() {
                    if let Some(s) = s {
                        map.insert(s.clone(), i as u32 + 1);
                    }
                }
                map
            })
            .get(symbol)
            .copied()
    }

    /// A clause of clingo's literals (`(Symbol, bool)` pairs or program literals), each
    /// negated with `negate`; `None` when a literal is true for sure (a negated unknown atom).
    fn clause(&self, literals: &[Bound<'_, PyAny>], negate: bool) -> PyResult<Option<Vec<i32>>> {
        let n = self.names.symbols.len();
        let mut out = Vec::with_capacity(literals.len());
        for l in literals {
            let lit = if let Ok(t) = l.downcast::<PyTuple>() {
                if t.len() != 2 {
                    return Err(PyTypeError::new_err("expected a (Symbol, bool) pair"));
                }
                let positive = t.get_item(1)?.is_truthy()? != negate;
                match self.atom_of(&to_symbol(&t.get_item(0)?)?) {
                    Some(a) => {
                        if positive {
                            a as i32
                        } else {
                            -(a as i32)
                        }
                    }
                    // An atom that does not exist is false.
                    None if positive => continue,
                    None => return Ok(None),
                }
            } else {
                let l: i64 = l.extract().map_err(|_| {
                    PyTypeError::new_err("expected a (Symbol, bool) pair or a program literal")
                })?;
                if l == 0 || l.unsigned_abs() > n as u64 {
                    return Err(PyRuntimeError::new_err(format!(
                        "lucent: {l} is not a program literal"
                    )));
                }
                let l = l as i32;
                if negate {
                    -l
                } else {
                    l
                }
            };
            out.push(lit);
        }
        Ok(Some(out))
    }

    fn push(&self, clause: Option<Vec<i32>>) {
        if let Some(c) = clause {
            self.clauses
                .lock()
                .unwrap_or_else(|p| p.into_inner())
                .push(c);
        }
    }
}

#[pymethods]
impl SolveControl {
    /// clingo's `SolveControl.symbolic_atoms` (a `lucent.SymbolicAtoms` over this object).
    #[getter]
    fn symbolic_atoms<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyAny>> {
        slf.py()
            .import_bound("lucent")?
            .getattr("SymbolicAtoms")?
            .call1((slf.clone(),))
    }

    /// Adds a clause for the rest of the solve call: literals are `(Symbol, bool)` pairs or
    /// program literals.
    fn add_clause(&self, literals: Vec<Bound<'_, PyAny>>) -> PyResult<()> {
        let c = self.clause(&literals, false)?;
        self.push(c);
        Ok(())
    }

    /// Adds a nogood (the clause of the literals' complements) for the rest of the call.
    fn add_nogood(&self, literals: Vec<Bound<'_, PyAny>>) -> PyResult<()> {
        let c = self.clause(&literals, true)?;
        self.push(c);
        Ok(())
    }

    /// Every atom with a symbol: `(symbol, literal, is_fact, is_external)` (what
    /// `SymbolicAtoms` reads).
    #[pyo3(name = "_atoms")]
    fn atoms(&self) -> Vec<(Symbol, u32, bool, bool)> {
        self.names
            .symbols
            .iter()
            .enumerate()
            .filter_map(|(i, s)| {
                let a = i as u32 + 1;
                let (fact, external) = self.kinds(a);
                Some((Symbol(s.clone()?), a, fact, external))
            })
            .collect()
    }

    /// The atom of `symbol`: `(literal, is_fact, is_external)`, or `None`.
    #[pyo3(name = "_atom")]
    fn atom(&self, symbol: &Symbol) -> Option<(u32, bool, bool)> {
        let a = self.atom_of(&symbol.0)?;
        let (fact, external) = self.kinds(a);
        Some((a, fact, external))
    }
}
