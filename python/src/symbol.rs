//! `lucent.Symbol` and its constructors, on the model of clingo's `Symbol`: an immutable
//! ground term that prints, orders and hashes as clingo's does (through `lucent::Symbol`, whose
//! `Display` and `Ord` are clingo's).
//!
//! Invariant: a Python `Symbol` owns a `lucent::Symbol`; constructors never panic (a bad name or
//! an unparsable term is a Python `RuntimeError`, as clingo raises).

use lucent::control::Name;
use pyo3::basic::CompareOp;
use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use std::collections::hash_map::DefaultHasher;
use std::hash::{Hash, Hasher};

/// clingo's `SymbolType`.
#[pyclass(eq, eq_int, frozen, hash, module = "lucent")]
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub enum SymbolType {
    /// `#inf`.
    Infimum,
    /// An integer.
    Number,
    /// A string.
    String,
    /// A function, constant or tuple.
    Function,
    /// `#sup`.
    Supremum,
}

#[pymethods]
impl SymbolType {
    /// The member's name, as a Python enum's (`Number`).
    #[getter]
    fn name(&self) -> &'static str {
        match self {
            SymbolType::Infimum => "Infimum",
            SymbolType::Number => "Number",
            SymbolType::String => "String",
            SymbolType::Function => "Function",
            SymbolType::Supremum => "Supremum",
        }
    }

    /// clingo's number for the member (`SymbolType.Number.value == 1`).
    #[getter]
    fn value(&self) -> u8 {
        match self {
            SymbolType::Infimum => 0,
            SymbolType::Number => 1,
            SymbolType::String => 4,
            SymbolType::Function => 5,
            SymbolType::Supremum => 7,
        }
    }

    fn __repr__(&self) -> String {
        format!("<SymbolType.{}: {}>", self.name(), self.value())
    }

    fn __str__(&self) -> String {
        format!("SymbolType.{}", self.name())
    }
}

/// A ground term (clingo's `Symbol`).
#[pyclass(frozen, module = "lucent")]
#[derive(Clone)]
pub struct Symbol(pub lucent::Symbol);

impl Symbol {
    fn function_parts(&self) -> Option<(&str, &[lucent::Symbol], bool)> {
        match &self.0 {
            lucent::Symbol::Function {
                name,
                args,
                negative,
            } => Some((name.as_str(), args, *negative)),
            _ => None,
        }
    }
}

#[pymethods]
impl Symbol {
    /// The symbol's type.
    #[getter(r#type)]
    fn symbol_type(&self) -> SymbolType {
        match &self.0 {
            lucent::Symbol::Inf => SymbolType::Infimum,
            lucent::Symbol::Sup => SymbolType::Supremum,
            lucent::Symbol::Number(_) => SymbolType::Number,
            lucent::Symbol::String(_) => SymbolType::String,
            lucent::Symbol::Function { .. } => SymbolType::Function,
        }
    }

    /// The name of a function (empty for a tuple).
    #[getter]
    fn name(&self) -> PyResult<String> {
        self.function_parts()
            .map(|(n, _, _)| n.to_string())
            .ok_or_else(|| PyRuntimeError::new_err("unexpected: the symbol is not a function"))
    }

    /// The arguments of a function.
    #[getter]
    fn arguments(&self) -> PyResult<Vec<Symbol>> {
        self.function_parts()
            .map(|(_, a, _)| a.iter().cloned().map(Symbol).collect())
            .ok_or_else(|| PyRuntimeError::new_err("unexpected: the symbol is not a function"))
    }

    /// The value of a number.
    #[getter]
    fn number(&self) -> PyResult<i32> {
        self.0
            .as_number()
            .ok_or_else(|| PyRuntimeError::new_err("unexpected: the symbol is not a number"))
    }

    /// The text of a string.
    #[getter]
    fn string(&self) -> PyResult<String> {
        self.0
            .as_str()
            .map(str::to_string)
            .ok_or_else(|| PyRuntimeError::new_err("unexpected: the symbol is not a string"))
    }

    /// True for a function without classical negation.
    #[getter]
    fn positive(&self) -> PyResult<bool> {
        Ok(!self.negative()?)
    }

    /// True for a classically negated function.
    #[getter]
    fn negative(&self) -> PyResult<bool> {
        self.function_parts()
            .map(|(_, _, n)| n)
            .ok_or_else(|| PyRuntimeError::new_err("unexpected: the symbol is not a function"))
    }

    /// Whether the symbol is a function `name/arity` with the given sign.
    #[pyo3(signature = (name, arity, positive = true))]
    fn r#match(&self, name: &str, arity: usize, positive: bool) -> bool {
        self.function_parts()
            .is_some_and(|(n, a, neg)| n == name && a.len() == arity && neg != positive)
    }

    fn __str__(&self) -> String {
        self.0.to_string()
    }

    /// clingo's constructor form: `Number(3)`, `String('s')`, `Function('f', [Number(1)],
    /// True)`, `Infimum`, `Supremum` (what a list of symbols prints; a model's `symbols()`
    /// prints its elements as `str`, see `_SymbolSequence`).
    fn __repr__(&self, py: Python<'_>) -> PyResult<String> {
        let mut out = String::new();
        constructor_form(py, &self.0, &mut out)?;
        Ok(out)
    }

    fn __hash__(&self) -> u64 {
        let mut h = DefaultHasher::new();
        self.0.hash(&mut h);
        h.finish()
    }

    fn __richcmp__(&self, other: &Bound<'_, PyAny>, op: CompareOp) -> PyObject {
        let py = other.py();
        match other.downcast::<Symbol>() {
            Ok(o) => op.matches(self.0.cmp(&o.get().0)).into_py(py),
            Err(_) => py.NotImplemented(),
        }
    }
}

/// Reads a Python `Symbol` (anything else is a `TypeError`).
pub fn to_symbol(obj: &Bound<'_, PyAny>) -> PyResult<lucent::Symbol> {
    if let Ok(s) = obj.downcast::<Symbol>() {
        return Ok(s.get().0.clone());
    }
    Err(PyTypeError::new_err(format!(
        "expected a Symbol, got {}",
        obj.get_type().name()?
    )))
}

/// clingo's `Function(name, arguments=[], positive=True)`.
///
/// Any name is taken, as clingo takes it (`Function("FOO")` prints `FOO`, which would read back
/// as a variable): a script that builds names from data runs unchanged.
#[pyfunction]
#[pyo3(name = "Function", signature = (name, arguments = Vec::new(), positive = true))]
pub fn function(name: &str, arguments: Vec<Symbol>, positive: bool) -> Symbol {
    Symbol(lucent::Symbol::Function {
        name: Name::from(name),
        args: arguments.into_iter().map(|s| s.0).collect(),
        negative: !positive,
    })
}

/// clingo's `Number(n)`.
#[pyfunction]
#[pyo3(name = "Number")]
pub fn number(n: i32) -> Symbol {
    Symbol(lucent::Symbol::Number(n))
}

/// clingo's `String(s)`.
#[pyfunction]
#[pyo3(name = "String")]
pub fn string(s: String) -> Symbol {
    Symbol(lucent::Symbol::String(s))
}

/// clingo's `Tuple_(arguments)`.
#[pyfunction]
#[pyo3(name = "Tuple_")]
pub fn tuple(arguments: Vec<Symbol>) -> Symbol {
    Symbol(lucent::Symbol::tuple(
        arguments.into_iter().map(|s| s.0).collect(),
    ))
}

/// clingo's `parse_term(text)`: a ground term written as clingo prints it.
#[pyfunction]
pub fn parse_term(text: &str) -> PyResult<Symbol> {
    lucent::Symbol::parse(text.trim())
        .map(Symbol)
        .map_err(|e| PyRuntimeError::new_err(format!("parsing failed: {e:?}")))
}

/// The symbol constants and constructors of the module.
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Symbol>()?;
    m.add_class::<SymbolType>()?;
    m.add_function(wrap_pyfunction!(function, m)?)?;
    m.add_function(wrap_pyfunction!(number, m)?)?;
    m.add_function(wrap_pyfunction!(string, m)?)?;
    m.add_function(wrap_pyfunction!(tuple, m)?)?;
    m.add_function(wrap_pyfunction!(parse_term, m)?)?;
    m.add("Infimum", Symbol(lucent::Symbol::Inf))?;
    m.add("Supremum", Symbol(lucent::Symbol::Sup))?;
    Ok(())
}

/// `symbol` as clingo's `repr` writes it, strings quoted as Python quotes them.
fn constructor_form(py: Python<'_>, symbol: &lucent::Symbol, out: &mut String) -> PyResult<()> {
    let quoted = |t: &str| -> PyResult<String> {
        Ok(pyo3::types::PyString::new_bound(py, t).repr()?.to_string())
    };
    match symbol {
        lucent::Symbol::Number(n) => out.push_str(&format!("Number({n})")),
        lucent::Symbol::String(t) => out.push_str(&format!("String({})", quoted(t)?)),
        lucent::Symbol::Inf => out.push_str("Infimum"),
        lucent::Symbol::Sup => out.push_str("Supremum"),
        lucent::Symbol::Function {
            name,
            args,
            negative,
        } => {
            out.push_str(&format!("Function({}, [", quoted(name)?));
            for (i, a) in args.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                constructor_form(py, a, out)?;
            }
            out.push_str(if *negative { "], False)" } else { "], True)" });
        }
    }
    Ok(())
}
