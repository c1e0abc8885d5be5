//! `lucent._lucent.Control`: the native half of the Python `Control` (python/lucent/
//! __init__.py holds the clingo-shaped layer: argument parsing, solve handles, symbolic atoms,
//! configuration, the backend's context manager). Each method is one call of
//! `lucent::control::Control`.
//!
//! Invariants: bad input is a Python `RuntimeError` carrying gringo's diagnostics, never a
//! panic; an exception raised by `on_model` stops the search and is raised again by `solve`;
//! without an explicit model count a program with `#minimize` enumerates until the optimum
//! (clingo's default `-n 0` for optimization), any other one model.

use lucent::control::{HandleMode, Part, Search, SolveOptions, Summary, TruthValue};
use lucent::solve::{EnumMode, OptMode, Outcome, Stats, StopReason};
use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};

use std::sync::Arc;

use crate::handle::SolveHandle;
use crate::model::{AtomNames, CallKind, Model};
use crate::solve_control::SolveControl;
use crate::symbol::{to_symbol, Symbol};

fn error(e: impl std::fmt::Display) -> PyErr {
    PyRuntimeError::new_err(e.to_string())
}

/// The native Control (see the module documentation).
#[pyclass(unsendable, module = "lucent._lucent")]
pub struct Control {
    ctl: lucent::Control,
    /// The model count given (`-n`, `configuration.solve.models`); `None`: clingo's default.
    models: Option<usize>,
    /// The last call's figures (`statistics["summary"]`, `["solving"]`).
    last: Option<LastCall>,
    /// Solve calls made so far (clingo's `summary.call` of the last is this minus one).
    calls: u32,
    /// The first error of a registered propagator (`propagator.rs`), raised by `solve`.
    failure: crate::propagator::Failure,
    /// The symbol of each atom, shared with the models (extended before each solve call).
    names: AtomNames,
    /// The current (or last) solve call's `SolveControl`, given to its models.
    context: Option<Py<SolveControl>>,
}

/// What the statistics report of the last solve call.
#[derive(Clone, Default)]
struct LastCall {
    stats: Stats,
    models: usize,
    /// The last model's costs, highest priority first.
    costs: Vec<i64>,
    /// The models reported as optimal (clingo's `summary.models.optimal`): those flagged so
    /// as they came (`--opt-mode=optN`), else 1 when the last one was proven optimal after.
    optimal: usize,
    /// clingo's `summary.result`: 1 satisfiable, 2 unsatisfiable, 0 unknown.
    result: u8,
    exhausted: bool,
}

impl LastCall {
    fn new(summary: &Summary, mut costs: Vec<i64>, optimal: usize, kind: CallKind) -> LastCall {
        if kind.ignore_costs {
            costs.clear();
        }
        let optimal = if optimal == 0 && summary.optimum_proven && summary.models > 0 {
            1
        } else {
            optimal
        };
        let result = if summary.is_unsatisfiable() {
            2
        } else if summary.is_satisfiable() && summary.outcome != Outcome::Unknown {
            1
        } else {
            0
        };
        LastCall {
            stats: summary.stats.clone(),
            models: summary.models,
            costs,
            optimal,
            result,
            exhausted: summary.exhausted,
        }
    }
}

/// A summary as flags: satisfiable, unsatisfiable, exhausted, interrupted, and the core.
pub type Flags = (bool, bool, bool, bool, Option<Vec<i32>>);

/// Stops the running solve call of a Control from any thread (`Control.interrupt`).
#[pyclass(frozen, module = "lucent._lucent")]
pub struct Interrupter(lucent::control::Interrupter);

#[pymethods]
impl Interrupter {
    /// Asks the running (or the next) solve call to stop.
    fn interrupt(&self) {
        self.0.interrupt();
    }
}

/// The outcome of one solve call: satisfiable, unsatisfiable, exhausted, interrupted, models
/// (when collected), the core (program literals of the failed assumptions, when unsatisfiable
/// under assumptions).
type SolveOut = (
    bool,
    bool,
    bool,
    bool,
    Option<Vec<Py<Model>>>,
    Option<Vec<i32>>,
);

#[pymethods]
impl Control {
    /// A Control from clingo's command-line `arguments` (`lucent::Control::from_args`: `-n`,
    /// `-c`, `--opt-mode`, `--project`, `-t`, `--heuristic`); a bad option is a
    /// `RuntimeError`, as in clingo.
    #[new]
    #[pyo3(signature = (arguments = Vec::new()))]
    fn new(arguments: Vec<String>) -> PyResult<Control> {
        let args: Vec<&str> = arguments.iter().map(String::as_str).collect();
        let mut ctl = lucent::Control::from_args(&args).map_err(error)?;
        let config = ctl.solve_config_mut();
        let models = (config.models != lucent::solve::Config::AUTO_MODELS).then_some(config.models);
        // The robot layers read supports; a Python caller cannot.
        config.supports = false;
        Ok(Control {
            ctl,
            models,
            last: None,
            calls: 0,
            failure: Default::default(),
            names: AtomNames::default(),
            context: None,
        })
    }

    /// The `--enum-mode` in effect (`configuration.solve.enum_mode`).
    #[getter]
    fn enum_mode(&self) -> &'static str {
        match self.ctl.solve_config().enum_mode {
            EnumMode::Auto => "auto",
            EnumMode::Brave => "brave",
            EnumMode::Cautious => "cautious",
        }
    }

    /// The `--opt-mode` in effect, as clasp names it (`configuration.solve.opt_mode`).
    #[getter]
    fn opt_mode(&self) -> String {
        match &self.ctl.solve_config().opt_mode {
            OptMode::Opt => "opt".into(),
            OptMode::OptN => "optN".into(),
            OptMode::Ignore => "ignore".into(),
            OptMode::Enum(bounds) => std::iter::once("enum".to_string())
                .chain(bounds.iter().map(i64::to_string))
                .collect::<Vec<_>>()
                .join(","),
        }
    }

    /// `Control.add(name, params, program)`.
    fn add(&mut self, name: &str, params: Vec<String>, program: &str) -> PyResult<()> {
        self.idle()?;
        let params: Vec<&str> = params.iter().map(String::as_str).collect();
        self.ctl.add(name, &params, program).map_err(error)
    }

    /// `Control.load(path)`.
    fn load(&mut self, path: &str) -> PyResult<()> {
        self.idle()?;
        self.ctl.load(path).map_err(error)
    }

    /// `Control.ground(parts, context)`: `@f(...)` calls `context.f` with `Symbol` arguments;
    /// it returns a `Symbol` or a sequence of them. The first exception a function raises
    /// (an `AttributeError` for an unknown one) is raised again, as clingo does.
    #[pyo3(signature = (parts, context = None))]
    fn ground(
        &mut self,
        py: Python<'_>,
        parts: Vec<(String, Vec<Symbol>)>,
        context: Option<PyObject>,
    ) -> PyResult<()> {
        self.idle()?;
        let parts: Vec<Part> = parts
            .into_iter()
            .map(|(n, a)| Part::new(n, a.into_iter().map(|s| s.0).collect()))
            .collect();
        let Some(object) = context else {
            return self.ctl.ground(&parts).map_err(error);
        };
        let mut ctx = PyContext {
            py,
            object,
            raised: None,
        };
        let result = self.ctl.ground_with_context(&parts, &mut ctx);
        match (result, ctx.raised) {
            (Err(_), Some(e)) => Err(e),
            (r, _) => r.map_err(error),
        }
    }

    /// Solves under `assumptions` (`(Symbol, bool)` pairs or literals), calling `on_model` on
    /// each model (a `False` result stops) and, with `collect`, returning the models.
    #[pyo3(signature = (assumptions, on_model = None, collect = false, on_unsat = None))]
    fn solve(
        &mut self,
        py: Python<'_>,
        assumptions: Vec<Bound<'_, PyAny>>,
        on_model: Option<PyObject>,
        collect: bool,
        on_unsat: Option<PyObject>,
    ) -> PyResult<SolveOut> {
        let options = self.begin(&assumptions)?;
        self.observe_lower_bounds(on_unsat);
        let names = &self.names;
        let context = self.context.as_ref().map(|c| c.clone_ref(py));
        let priorities = Arc::new(self.ctl.minimize_priorities());
        let kind = self.call_kind();
        let mut failure: Option<PyErr> = None;
        let mut kept: Vec<Py<Model>> = Vec::new();
        let mut costs = Vec::new();
        let mut optimal = 0;
        let summary = self.ctl.solve(&options, |m| {
            costs = m.costs().to_vec();
            optimal += usize::from(m.optimal());
            if on_model.is_none() && !collect {
                return true;
            }
            let model = Model::new(
                m,
                names.clone(),
                priorities.clone(),
                context.as_ref().map(|c| c.clone_ref(py)),
                kind,
            );
            let model = match Py::new(py, model) {
                Ok(model) => model,
                Err(e) => {
                    failure = Some(e);
                    return false;
                }
            };
            if let Some(f) = &on_model {
                match f.call1(py, (model.clone_ref(py),)) {
                    Ok(r) => {
                        if r.bind(py)
                            .downcast::<pyo3::types::PyBool>()
                            .is_ok_and(|b| !b.is_true())
                        {
                            if collect {
                                kept.push(model);
                            }
                            return false;
                        }
                    }
                    Err(e) => {
                        failure = Some(e);
                        return false;
                    }
                }
            }
            if collect {
                kept.push(model);
            }
            true
        });
        if let Some(e) = failure {
            return Err(e);
        }
        self.raise_propagator_error()?;
        let (sat, unsat, exhausted, interrupted, core) = self.outcome(&summary);
        self.last = Some(LastCall::new(&summary, costs, optimal, self.call_kind()));
        self.calls += 1;
        Ok((
            sat,
            unsat,
            exhausted,
            interrupted,
            collect.then_some(kept),
            core,
        ))
    }

    /// `Control.solve(yield_=..., async_=...)`: a `SolveHandle` over a search on its own thread
    /// (python/src/handle.rs); `yield_` stops it after each model, `async_` starts it at once.
    #[pyo3(signature = (assumptions, yield_, async_, on_unsat = None))]
    fn solve_handle(
        slf: &Bound<'_, Self>,
        assumptions: Vec<Bound<'_, PyAny>>,
        yield_: bool,
        async_: bool,
        on_unsat: Option<PyObject>,
    ) -> PyResult<SolveHandle> {
        let mut this = slf.borrow_mut();
        let options = this.begin(&assumptions)?;
        this.observe_lower_bounds(on_unsat);
        let mode = HandleMode {
            yield_models: yield_,
            background: async_,
        };
        let search = this.ctl.start_search(&options, mode);
        let names = this.names.clone();
        drop(this);
        Ok(SolveHandle::new(slf.clone().unbind(), search, names))
    }

    /// `Control.interrupt` from any thread: an `Interrupter` of this Control's solve calls.
    fn interrupter(&mut self) -> Interrupter {
        Interrupter(self.ctl.interrupter())
    }

    /// `Control.assign_external(atom, value)`: `value` true, false or `None` (free).
    #[pyo3(signature = (atom, value))]
    fn assign_external(&mut self, atom: &Bound<'_, PyAny>, value: Option<bool>) -> PyResult<()> {
        self.idle()?;
        let (symbol, positive) = self.target(atom)?;
        let value = match value {
            None => TruthValue::Free,
            Some(v) if v == positive => TruthValue::True,
            Some(_) => TruthValue::False,
        };
        self.ctl.assign_external(&symbol, value);
        Ok(())
    }

    /// `Control.release_external(atom)`.
    fn release_external(&mut self, atom: &Bound<'_, PyAny>) -> PyResult<()> {
        self.idle()?;
        let (symbol, _) = self.target(atom)?;
        self.ctl.release_external(&symbol);
        Ok(())
    }

    /// `Control.register_propagator`: `adapter` is the Python `_PropagatorAdapter`.
    fn register_propagator(&mut self, adapter: PyObject) -> PyResult<()> {
        self.idle()?;
        let interrupter = self.ctl.interrupter();
        self.ctl
            .register_propagator(Box::new(crate::propagator::PyPropagator {
                adapter,
                failure: self.failure.clone(),
                interrupter,
            }));
        Ok(())
    }

    /// Every symbolic atom: `(symbol, literal, is_fact, is_external)`.
    fn symbolic_atoms(&self) -> Vec<(Symbol, u32, bool, bool)> {
        self.ctl
            .symbolic_atoms()
            .map(|a| (Symbol(a.symbol), a.atom, a.fact, a.external))
            .collect()
    }

    /// The ground theory atoms, as data (see `theory.rs`).
    fn theory_atoms(&self) -> Vec<crate::theory::Atom> {
        crate::theory::atoms(&self.ctl)
    }

    /// The warnings collected since the last call, each as clingo's `MessageCode` number and
    /// the message as gringo prints it (what `Control`'s `logger` receives).
    fn take_messages(&mut self) -> Vec<(u8, String)> {
        use lucent::base::WarningKind;
        let diags = self.ctl.take_diagnostics();
        let sources = self.ctl.sources();
        diags
            .items()
            .iter()
            .filter(|d| !d.is_error())
            .map(|d| {
                let code = match d.kind {
                    Some(WarningKind::OperationUndefined) => 0,
                    Some(WarningKind::AtomUndefined) => 2,
                    Some(WarningKind::FileIncluded) => 3,
                    Some(WarningKind::VariableUnbounded) => 4,
                    Some(WarningKind::GlobalVariable) => 5,
                    Some(WarningKind::Other) | None => 6,
                };
                // One line end, as clingo's messages (the command line's blank line after
                // each message is not part of it).
                let text = d.render(sources);
                (code, format!("{}\n", text.trim_end_matches('\n')))
            })
            .collect()
    }

    /// The value of the constant `name` (`#const` or `-c`), or `None` (clingo's `get_const`).
    fn get_const(&self, name: &str) -> Option<Symbol> {
        self.ctl.get_const(name).map(Symbol)
    }

    /// Every constant with its value: what `get_const` answers while a model callback runs
    /// (the control is busy then).
    fn consts(&self) -> Vec<(String, Symbol)> {
        self.ctl
            .consts()
            .into_iter()
            .map(|(n, v)| (n, Symbol(v)))
            .collect()
    }

    /// clingo's `is_conflicting`: the program has no answer set whatever the externals and
    /// assumptions (a constraint with an empty body, or a top-level conflict found by a
    /// search).
    fn is_conflicting(&self) -> bool {
        self.ctl.is_conflicting()
    }

    /// The atom of `symbol`: `(literal, is_fact, is_external)`, or `None`.
    fn symbolic_atom(&self, symbol: &Symbol) -> Option<(u32, bool, bool)> {
        let atom = self.ctl.lookup(&symbol.0)?;
        self.ctl
            .symbolic_atoms()
            .find(|a| a.atom == atom)
            .map(|a| (a.atom, a.fact, a.external))
    }

    /// The model count given (`None`: clingo's default).
    #[getter]
    fn get_models(&self) -> Option<usize> {
        self.models
    }

    #[setter]
    fn set_models(&mut self, n: Option<usize>) {
        self.models = n;
    }

    /// `--enum-mode`: `auto` (also `bt`, `record`), `brave` or `cautious`.
    fn set_enum_mode(&mut self, mode: &str) -> PyResult<()> {
        self.idle()?;
        self.ctl.solve_config_mut().enum_mode = EnumMode::from_name(mode)
            .ok_or_else(|| error(format!("invalid value for option --enum-mode: {mode}")))?;
        Ok(())
    }

    /// `--opt-mode`.
    fn set_opt_mode(&mut self, mode: &str) -> PyResult<()> {
        self.idle()?;
        self.ctl.solve_config_mut().opt_mode = OptMode::from_name(mode)
            .ok_or_else(|| error(format!("invalid value for option --opt-mode: {mode}")))?;
        Ok(())
    }

    /// clingo-shaped statistics: `summary` of the last call, `solving` its search figures,
    /// `accu` the search figures of every call added up.
    fn statistics<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new_bound(py);
        let summary = PyDict::new_bound(py);
        let models = PyDict::new_bound(py);
        let times = PyDict::new_bound(py);
        let LastCall {
            stats,
            models: n,
            costs,
            optimal,
            result,
            exhausted,
        } = self.last.clone().unwrap_or_default();
        models.set_item("enumerated", n as f64)?;
        let optimal = if costs.is_empty() { 0 } else { optimal };
        models.set_item("optimal", optimal as f64)?;
        times.set_item("solve", stats.time.as_secs_f64())?;
        summary.set_item("models", models)?;
        summary.set_item("times", times)?;
        summary.set_item("costs", costs.iter().map(|&c| c as f64).collect::<Vec<_>>())?;
        // As clingo's summary: the call's index, its result, whether the search space was
        // exhausted, the lower bounds of the costs (the costs once proven optimal, else 0),
        // the threads, the signal that stopped it (none) and the winning thread (the first).
        summary.set_item("call", f64::from(self.calls.saturating_sub(1)))?;
        summary.set_item("result", f64::from(result))?;
        summary.set_item("exhausted", if exhausted { 1.0 } else { 0.0 })?;
        summary.set_item(
            "lower",
            costs
                .iter()
                .map(|&c| if optimal > 0 { c as f64 } else { 0.0 })
                .collect::<Vec<_>>(),
        )?;
        summary.set_item("concurrency", self.ctl.solve_config().threads.max(1) as f64)?;
        summary.set_item("signal", 0.0)?;
        summary.set_item("winner", 0.0)?;
        out.set_item("summary", summary)?;
        out.set_item("solving", solving(py, &stats)?)?;
        let accu = PyDict::new_bound(py);
        accu.set_item("solving", solving(py, &self.ctl.accumulated_stats())?)?;
        out.set_item("accu", accu)?;
        Ok(out)
    }

    /// `Backend.add_atom(symbol=None)`.
    #[pyo3(signature = (symbol = None))]
    fn backend_add_atom(&mut self, symbol: Option<Symbol>) -> PyResult<u32> {
        self.with_backend(|b| Ok(b.add_atom(symbol.as_ref().map(|s| &s.0))))
    }

    /// `Backend.add_rule(head, body, choice)`.
    fn backend_add_rule(&mut self, head: Vec<u32>, body: Vec<i32>, choice: bool) -> PyResult<()> {
        self.with_backend(|b| b.add_rule(&head, &body, choice))
    }

    /// `Backend.add_weight_rule(head, lower, body, choice)`.
    fn backend_add_weight_rule(
        &mut self,
        head: Vec<u32>,
        lower: i64,
        body: Vec<(i32, i64)>,
        choice: bool,
    ) -> PyResult<()> {
        self.with_backend(|b| b.add_weight_rule(&head, lower, &body, choice))
    }

    /// `Backend.add_minimize(priority, literals)`.
    fn backend_add_minimize(&mut self, priority: i64, literals: Vec<(i32, i64)>) -> PyResult<()> {
        self.with_backend(|b| b.add_minimize(priority, &literals))
    }

    /// `Backend.add_external(atom, value)`: `value` true, false or `None` (free).
    #[pyo3(signature = (atom, value))]
    fn backend_add_external(&mut self, atom: u32, value: Option<bool>) -> PyResult<()> {
        let value = match value {
            None => TruthValue::Free,
            Some(true) => TruthValue::True,
            Some(false) => TruthValue::False,
        };
        self.with_backend(|b| b.add_external(atom, value))
    }

    /// `Backend.add_assume(literals)`.
    fn backend_add_assume(&mut self, literals: Vec<i32>) -> PyResult<()> {
        self.with_backend(|b| b.add_assume(&literals))
    }

    /// `Backend.add_project(atoms)`.
    fn backend_add_project(&mut self, atoms: Vec<u32>) -> PyResult<()> {
        self.with_backend(|b| b.add_project(&atoms))
    }

    /// `Backend.add_heuristic(atom, type, bias, priority, condition)`; `kind` is the value of
    /// clingo's `HeuristicType` (aspif's numbering: level, sign, factor, init, true, false).
    fn backend_add_heuristic(
        &mut self,
        atom: u32,
        kind: u32,
        bias: i32,
        priority: u32,
        condition: Vec<i32>,
    ) -> PyResult<()> {
        use lucent::ground::program::HeuristicModifier as M;
        let modifier = match kind {
            0 => M::Level,
            1 => M::Sign,
            2 => M::Factor,
            3 => M::Init,
            4 => M::True,
            5 => M::False,
            _ => return Err(error(format!("invalid heuristic type: {kind}"))),
        };
        self.with_backend(|b| b.add_heuristic(atom, modifier, bias, priority, &condition))
    }

    /// `Backend.add_acyc_edge(node_u, node_v, condition)`.
    fn backend_add_acyc_edge(&mut self, from: i32, to: i32, condition: Vec<i32>) -> PyResult<()> {
        self.with_backend(|b| b.add_acyc_edge(from, to, &condition))
    }
}

impl Control {
    /// `f` over the Control's backend (clingo's `Control.backend()`), refused while a solve
    /// handle's search has the solver; a rejected statement is a `RuntimeError`.
    fn with_backend<R>(
        &mut self,
        f: impl FnOnce(&mut lucent::control::Backend<'_>) -> Result<R, String>,
    ) -> PyResult<R> {
        self.idle()?;
        let mut b = self.ctl.backend().map_err(error)?;
        f(&mut b).map_err(error)
    }

    /// Refuses a call while a solve handle's search has the solver.
    fn idle(&self) -> PyResult<()> {
        if self.ctl.is_searching() {
            return Err(error(
                "a solve handle is running: close it (or leave its `with` block) first",
            ));
        }
        Ok(())
    }

    /// What every solve call does first: the model count, the assumptions, the symbols of the
    /// atoms added since the last call.
    fn begin(&mut self, assumptions: &[Bound<'_, PyAny>]) -> PyResult<SolveOptions> {
        self.idle()?;
        let mut options = SolveOptions::default();
        for a in assumptions {
            options.assumptions.push(self.assumption(a)?);
        }
        let models = match self.models {
            Some(n) => n,
            // clingo's default: every model of an optimization or of consequences, else one.
            None if self.ctl.has_minimize()
                || self.ctl.solve_config().enum_mode != EnumMode::Auto =>
            {
                0
            }
            None => 1,
        };
        self.ctl.solve_config_mut().models = models;
        // The symbols of the atoms added since the last call (an atom keeps its symbol, so
        // the table only grows; models of earlier calls may share the old one).
        // The last call's context shares the table: dropped first, so that the table is
        // extended in place rather than copied whole (models kept by the caller still copy).
        self.context = None;
        let known = self.names.symbols.len() as u32;
        if known < self.ctl.num_atoms() {
            let names = Arc::make_mut(&mut self.names);
            let added = known + 1..=self.ctl.num_atoms();
            names
                .symbols
                .extend(added.clone().map(|a| self.ctl.symbol(a)));
            names.keys.extend(added.map(|a| self.ctl.atom_order(a)));
        }
        let context = SolveControl::new(
            self.names.clone(),
            self.ctl.atom_kinds(),
            self.ctl.model_clauses(),
        );
        self.context = Some(Python::with_gil(|py| Py::new(py, context))?);
        Ok(options)
    }

    /// clingo's `on_unsat`: `f` gets each lower bound the next call proves (a list, highest
    /// priority first) on the solving thread; its exception stops the call and is raised by
    /// it, as a propagator's. `None` removes the previous call's.
    fn observe_lower_bounds(&mut self, f: Option<PyObject>) {
        let observer = f.map(|f| {
            let failure = self.failure.clone();
            let interrupter = self.ctl.interrupter();
            let call = move |bound: &[i64]| {
                let failed = || failure.lock().unwrap_or_else(|p| p.into_inner());
                if failed().is_some() {
                    return;
                }
                if let Err(e) = Python::with_gil(|py| f.call1(py, (bound.to_vec(),))) {
                    failed().get_or_insert(e);
                    interrupter.interrupt();
                }
            };
            let observer: lucent::solve::LowerBoundObserver = Arc::new(std::sync::Mutex::new(call));
            observer
        });
        self.ctl.on_lower_bound(observer);
    }

    /// The first exception a propagator raised during the last call, raised.
    pub fn raise_propagator_error(&self) -> PyResult<()> {
        match self
            .failure
            .lock()
            .unwrap_or_else(|p| p.into_inner())
            .take()
        {
            Some(e) => Err(e),
            None => Ok(()),
        }
    }

    /// A summary as `SolveResult` flags and clingo's core (the program literals of the failed
    /// assumptions, in assumption order).
    pub fn outcome(&self, summary: &Summary) -> Flags {
        let sat = summary.is_satisfiable() && summary.outcome != Outcome::Unknown;
        let unsat = summary.is_unsatisfiable();
        let interrupted = summary.stop == Some(StopReason::Interrupted);
        let core = summary.core.as_ref().map(|core| {
            core.iter()
                .filter_map(|(symbol, value)| {
                    let atom = self.ctl.lookup(symbol)? as i32;
                    Some(if *value { atom } else { -atom })
                })
                .collect()
        });
        (sat, unsat, summary.exhausted, interrupted, core)
    }

    /// What the solve calls ask for, as their models report it.
    fn call_kind(&self) -> CallKind {
        let config = self.ctl.solve_config();
        CallKind {
            mode: config.enum_mode,
            ignore_costs: matches!(config.opt_mode, OptMode::Ignore),
        }
    }

    /// A model of a handle's search as a Python `Model`.
    pub fn read_model(&self, raw: &lucent::solve::Model, names: &AtomNames) -> Model {
        let priorities = Arc::new(self.ctl.minimize_priorities());
        let context = Python::with_gil(|py| self.context.as_ref().map(|c| c.clone_ref(py)));
        self.ctl.read_model(raw, |m| {
            Model::new(m, names.clone(), priorities, context, self.call_kind())
        })
    }

    /// The end of a handle's search: the solver back, the call recorded for the statistics.
    pub fn end_handle(&mut self, search: Search, costs: Vec<i64>, optimal: usize) -> Summary {
        let summary = self.ctl.end_search(search);
        self.last = Some(LastCall::new(&summary, costs, optimal, self.call_kind()));
        self.calls += 1;
        summary
    }

    /// An assumption: a `(Symbol, bool)` pair or a literal of a symbolic atom.
    fn assumption(&self, a: &Bound<'_, PyAny>) -> PyResult<(lucent::Symbol, bool)> {
        if let Ok(t) = a.downcast::<PyTuple>() {
            if t.len() == 2 {
                return Ok((to_symbol(&t.get_item(0)?)?, t.get_item(1)?.is_truthy()?));
            }
        }
        self.target(a)
    }

    /// The atom a Python value names: a `Symbol` (positive) or a literal of a symbolic atom.
    fn target(&self, a: &Bound<'_, PyAny>) -> PyResult<(lucent::Symbol, bool)> {
        if let Ok(s) = a.downcast::<Symbol>() {
            return Ok((s.get().0.clone(), true));
        }
        let lit: i64 = a.extract().map_err(|_| {
            PyTypeError::new_err("expected a Symbol, a literal or a (Symbol, bool) pair")
        })?;
        let atom = u32::try_from(lit.unsigned_abs()).unwrap_or(0);
        match self.ctl.symbol(atom) {
            Some(s) => Ok((s, lit > 0)),
            None => Err(error(format!(
                "literal {lit} names no symbolic atom (lucent assumes and assigns symbolic atoms only)"
            ))),
        }
    }
}

/// clingo's `solving.solvers` figures of `stats`.
fn solving<'py>(py: Python<'py>, stats: &Stats) -> PyResult<Bound<'py, PyDict>> {
    let solvers = PyDict::new_bound(py);
    solvers.set_item("choices", stats.choices as f64)?;
    solvers.set_item("conflicts", stats.conflicts as f64)?;
    solvers.set_item("restarts", stats.restarts as f64)?;
    let out = PyDict::new_bound(py);
    out.set_item("solvers", solvers)?;
    Ok(out)
}

/// A Python object as a grounding context (clingo's protocol: the method named as the
/// function, called with `Symbol` arguments, returning a `Symbol` or a sequence of them).
struct PyContext<'py> {
    py: Python<'py>,
    object: PyObject,
    /// The first exception raised by a function (raised again by `ground`).
    raised: Option<PyErr>,
}

impl PyContext<'_> {
    fn values(&self, name: &str, args: &[lucent::Symbol]) -> PyResult<Vec<lucent::Symbol>> {
        let py = self.py;
        let f = self.object.bind(py).getattr(name)?;
        let args: Vec<Py<Symbol>> = args
            .iter()
            .map(|a| Py::new(py, Symbol(a.clone())))
            .collect::<PyResult<_>>()?;
        let r = f.call1(PyTuple::new_bound(py, args))?;
        if let Ok(s) = r.downcast::<Symbol>() {
            return Ok(vec![s.get().0.clone()]);
        }
        let mut out = Vec::new();
        for item in r.iter().map_err(|_| {
            PyTypeError::new_err(format!(
                "function {name} returned neither a Symbol nor a sequence of them"
            ))
        })? {
            out.push(to_symbol(&item?)?);
        }
        Ok(out)
    }
}

impl lucent::control::Context for PyContext<'_> {
    fn call(&mut self, name: &str, args: &[lucent::Symbol]) -> Result<Vec<lucent::Symbol>, String> {
        self.values(name, args).map_err(|e| {
            let message = e.to_string();
            self.raised.get_or_insert(e);
            message
        })
    }
}
