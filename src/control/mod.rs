//! The library's front door, on the model of clingo's `Control`: load text and files with
//! constants, ground named program parts with parameters, solve with assumptions, and read
//! models as structured terms ([`Symbol`]), with lookup from a term to its atom and back.
//! `cli`, `lucent demo` and every robot layer are its clients, so the parse-ground-solve
//! pipeline exists once.
//!
//! ```
//! use lucent::control::{Control, ControlConfig, Part, Symbol};
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.solve_config_mut().models = 0; // all models (clingo's `-n 0`); one by default
//! ctl.add("base", &[], "q(1..2). {p(X)} :- q(X). :- p(1), p(2).").unwrap();
//! ctl.ground(&[Part::base()]).unwrap();
//! let mut answers = Vec::new();
//! ctl.solve(&Default::default(), |m| {
//!     answers.push(m.symbols().iter().map(|s| s.to_string()).collect::<Vec<_>>().join(" "));
//!     true
//! });
//! answers.sort();
//! assert_eq!(answers, ["q(1) q(2)", "q(1) q(2) p(1)", "q(1) q(2) p(2)"]);
//! let p1 = ctl.lookup(&Symbol::parse("p(1)").unwrap()).unwrap();
//! assert_eq!(ctl.symbol(p1).unwrap().to_string(), "p(1)");
//! ```
//!
//! Multi-shot solving: `#program name(params).` splits the statements into parts (`base`
//! before any directive, in each file); [`Control::ground`] instantiates parts with their
//! parameters bound, on top of everything grounded before. Earlier parts are never
//! re-instantiated: one grounder state lives in the Control (`ground::incremental::Session`:
//! the atoms, predicate domains and indexes of every grounding), a new part's statements join
//! against it, its atoms are matched to the earlier ones by grounder atom, new atoms are
//! numbered after the old ones, and only the new ground rules reach the solver, so a part
//! costs what it adds.
//!
//! ```
//! use lucent::control::{Control, ControlConfig, Part, Symbol, TruthValue};
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.add("base", &[], "at(0).").unwrap();
//! ctl.add("step", &["t"], "at(t) :- at(t-1), not stop(t). #external stop(t).").unwrap();
//! ctl.ground(&[Part::base()]).unwrap();
//! for t in 1..=3 {
//!     ctl.ground(&[Part::new("step", vec![Symbol::number(t)])]).unwrap();
//! }
//! ctl.assign_external(&Symbol::parse("stop(2)").unwrap(), TruthValue::True);
//! let model = ctl.solve_all(&Default::default()).models.remove(0);
//! assert!(model.contains(&Symbol::parse("at(1)").unwrap()));
//! assert!(!model.contains(&Symbol::parse("at(2)").unwrap()));
//! ```
//!
//! Invariants:
//! - Atoms are the solver's numbers ([`AtomId`], aspif's numbering): the first grounding
//!   numbers them exactly as `ground::ground` does (so the command line's output is what it
//!   was), later groundings number new atoms after the old ones; a symbol keeps its atom.
//! - External atoms reach the solver as free atoms; their values (true, false, released) are
//!   assumptions of each solve call, so assigning an external never rebuilds anything.
//! - Diagnostics are values: every call that can meet bad input returns them in its error,
//!   and warnings collect in [`Control::diagnostics`]. Nothing here prints.
//! - Reading files happens only in [`Control::load`] and for `#include` (clingo's `load`).

mod args;
mod aspif_input;
mod backend;
mod context;
mod externals;
mod functions;
pub mod handle;
pub mod incmode;
mod model;
mod parts;
pub mod propagator;
pub mod theory;
pub(crate) mod symbol;

use std::cell::OnceCell;
use std::path::Path;

use hashbrown::{HashMap, HashSet};

use crate::base::{Diagnostic, Diagnostics, FileId, SourceMap, Span, WarningKind};
use crate::ground::program::{
    AtomRecord, AtomStatus, DeadReason, ExternalValue, GAtom, GroundProgram, Output, Provenance,
    RemovedLit, RuleOrigin,
};
use crate::ground::symbol::{SymId, Symbols};
use crate::ground::{self, GroundConfig, Grounding};
use crate::solve::{self, Solver};
use crate::syntax::ast::{self, Dialect, Program, Statement, StatementKind};

pub use args::ArgsError;
pub use backend::Backend;
pub use functions::Context;
pub use handle::{HandleMode, Search, SolveHandle};
use model::Names;
pub use model::{Model, OwnedModel};
pub use propagator::{
    Assignment, CheckMode, Literal, PropagateControl, PropagateInit, Propagator,
    WeightConstraintType,
};
pub use symbol::{Name, ParseSymbolError, Symbol};

/// An atom of the Control's ground program: the aspif numbering, from 1
/// ([`ground::program::Atom`], the numbering of `GroundProgram`, the solver and models). Not the
/// grounder's own atom numbers (`ground::program::GAtom` in provenance): the Control maps a
/// grounding's atoms to these.
pub type AtomId = ground::program::Atom;

/// How a [`Control`] grounds and solves.
#[derive(Clone, Debug)]
pub struct ControlConfig {
    /// The solver's configuration (models to enumerate, optimization, CR semantics, ...).
    pub solve: solve::Config,
    /// The grounder's configuration: `-c name=value` constants ([`const_term`] reads a value
    /// written as text), provenance, the size and time limits, the diagnostics limit per call.
    /// Each grounding gets it with the part's parameters appended to the constants.
    pub ground: GroundConfig,
    /// Warning kinds not reported (`-W no-...`).
    pub disabled_warnings: Vec<WarningKind>,
    /// The language of added text; `None` detects it per text (SPARC or clingo).
    pub dialect: Option<Dialect>,
}

impl Default for ControlConfig {
    fn default() -> Self {
        ControlConfig {
            // clingo's default: one model, or the optimum of a program that optimizes.
            solve: solve::Config {
                models: solve::Config::AUTO_MODELS,
                ..solve::Config::default()
            },
            ground: GroundConfig {
                // gringo's default.
                message_limit: Some(20),
                ..GroundConfig::default()
            },
            disabled_warnings: Vec::new(),
            dialect: None,
        }
    }
}

/// A program part to ground: `#program name(params).` with the parameters bound to `args`.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Part {
    /// The part's name (`base` for the statements before any `#program` directive).
    pub name: String,
    /// One value per parameter.
    pub args: Vec<Symbol>,
}

impl Part {
    /// The part `name(args)`.
    pub fn new(name: impl Into<String>, args: Vec<Symbol>) -> Part {
        Part {
            name: name.into(),
            args,
        }
    }

    /// The `base` part.
    pub fn base() -> Part {
        Part::new("base", Vec::new())
    }
}

/// The truth value given to an external atom.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TruthValue {
    /// The atom is true.
    True,
    /// The atom is false (the default of `#external`).
    False,
    /// The atom is open: the solver chooses.
    Free,
}

/// Options of one solve call.
#[derive(Clone, Debug, Default)]
pub struct SolveOptions {
    /// Literals assumed for this call only: the atom `Symbol` true (`true`) or false. Assuming
    /// an atom that does not exist false has no effect; assuming it true makes the call
    /// unsatisfiable.
    pub assumptions: Vec<(Symbol, bool)>,
}

/// True when a call that reported `count` models stopped at its model limit: clingo's library
/// then reports the call as not exhausted, even when the solver could tell that no model is left
/// (clingo's command line prints `Models : 1` there; 5.8's `Control.solve` says not exhausted).
/// Optimization counts its limit in optimal models, so it is left as the solver says.
pub(crate) fn at_model_limit(solver: &mut solve::Solver, count: usize) -> bool {
    let limit = solver.config_mut().models;
    let optimizing = !solver.program().minimize.is_empty()
        && solver.config_mut().opt_mode != solve::OptMode::Ignore;
    limit > 0 && count >= limit && !optimizing
}

/// What a solve call answers besides its models.
#[derive(Clone, Debug)]
pub struct Summary {
    /// Satisfiable, unsatisfiable, unknown or optimum.
    pub outcome: solve::Outcome,
    /// True when the search space was fully explored; false for a call stopped at its model
    /// limit (clingo 5.8's `SolveResult.exhausted`).
    pub exhausted: bool,
    /// True when the solver found no model left, even in a call stopped at its model limit
    /// (what clingo's command line reports: `Models : 1` and exit code 30 for `a.`).
    pub search_exhausted: bool,
    /// True when the last model's costs are proven optimal.
    pub optimum_proven: bool,
    /// Why the search stopped early, if it did.
    pub stop: Option<solve::StopReason>,
    /// Search statistics.
    pub stats: solve::Stats,
    /// Models reported to the callback.
    pub models: usize,
    /// When the call found no model and was not stopped: the assumptions of
    /// [`SolveOptions::assumptions`] that the refutation used, in their order, under which the
    /// program has no answer set either (clingo's `on_core`; not minimal). Empty when the
    /// program has no answer set under any assumption; `None` after a model or a stop.
    pub core: Option<Vec<(Symbol, bool)>>,
}

impl Summary {
    /// True when a model was found.
    pub fn is_satisfiable(&self) -> bool {
        matches!(
            self.outcome,
            solve::Outcome::Satisfiable | solve::Outcome::Optimum
        )
    }

    /// True when the search was exhausted without a model.
    pub fn is_unsatisfiable(&self) -> bool {
        self.outcome == solve::Outcome::Unsatisfiable
    }
}

/// A solve call's models, collected (see [`Control::solve_all`]).
#[derive(Clone, Debug)]
pub struct Solved {
    /// The models, in the order found.
    pub models: Vec<OwnedModel>,
    /// The call's summary.
    pub summary: Summary,
}

/// Bad input met by a [`Control`] call: the diagnostics (gringo's format once rendered
/// against [`Control::sources`]) and their rendered text.
#[derive(Clone, Debug)]
pub struct Error {
    /// The call's diagnostics: errors, and the warnings that came with them.
    pub diagnostics: Diagnostics,
    /// The diagnostics rendered as gringo prints them.
    pub message: String,
}

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.message.trim_end())
    }
}

impl std::error::Error for Error {}

/// Parses a constant's value written as text (`-c name=value`), as `#const name = value.`
/// would; `None` when it is not a term.
pub fn const_term(value: &str) -> Option<ast::Term> {
    let mut sources = SourceMap::new();
    let text = format!("#const c = {value}.");
    let file = sources.add("<cmd>", text.clone());
    let parse = crate::syntax::parse(file, &text, Dialect::Clingo);
    if parse.has_errors() {
        return None;
    }
    parse.program.statements.iter().find_map(|s| match &s.kind {
        StatementKind::Const(c) => Some(c.value.clone()),
        _ => None,
    })
}

/// Values of part parameters, by name.
type Binding = Vec<(String, Symbol)>;

/// The statements of one `#program name(params).` part, in source order.
#[derive(Clone, Debug)]
struct Block {
    name: String,
    params: Vec<String>,
    statements: Vec<Statement>,
}

/// Per-atom flags.
const FACT: u8 = 1;
/// The atom heads a rule (it is no longer only an external or a body atom).
const DEFINED: u8 = 2;
/// A released external no longer listed among the symbolic atoms: clingo drops it at the first
/// update (grounding, external assignment or release, backend) after the solve call that
/// handed the release to the solver.
const DROPPED: u8 = 4;

/// The front door: see the module documentation.
pub struct Control {
    config: ControlConfig,
    sources: SourceMap,
    diags: Diagnostics,
    dialect: Option<Dialect>,
    /// Parts, by name and parameters, in order of first appearance (`base` first when present).
    blocks: Vec<Block>,
    /// `#const` and `#show` signature statements of every part: gringo applies them globally.
    globals: Vec<(usize, Statement)>,
    /// Set by `#include <incmode>.`
    incmode: bool,
    /// Part instances grounded so far (a second request grounds nothing, as the atoms exist).
    grounded: HashSet<Part>,
    /// Number of groundings done.
    groundings: usize,
    /// The symbols of the atoms (one table for every grounding).
    syms: Symbols,
    /// Symbol of each atom, `atom_sym[a - 1]`; `None` for auxiliary atoms.
    atom_sym: Vec<Option<SymId>>,
    /// Where clingo lists each atom in a model, `atom_key[a - 1]` ([`Control::atom_order`]).
    atom_key: Vec<u64>,
    /// Atom of each symbol id (0: none), indexed by `SymId`.
    sym_atom: Vec<AtomId>,
    /// Per atom flags (`FACT`, `DEFINED`), index `a - 1`.
    flags: Vec<u8>,
    /// External atoms and their current values; released ones are `None` (false for good).
    externals: HashMap<AtomId, Option<TruthValue>>,
    /// Output statements already in the program, for deduplication across groundings.
    outputs_seen: Option<HashSet<(String, Vec<i32>)>>,
    /// Ground statements not yet handed to the solver (the whole program before the first
    /// solve call, then what later groundings added).
    pending: GroundProgram,
    /// Externals declared since the solver last took the pending statements.
    new_externals: Vec<AtomId>,
    /// Released externals (false for good).
    released: HashSet<AtomId>,
    /// Externals whose release the last solve calls handed to the solver, to drop from the
    /// symbolic atoms at the next update ([`Control::begin_update`]).
    fresh_releases: Vec<AtomId>,
    solver: Option<Solver>,
    /// The last grounding's tables, for `--text` output (`take_grounding`).
    last: Option<Grounding>,
    /// With provenance on: the statements grounded so far, by the Control's statement id
    /// (what the origins of [`Control::provenance`] index).
    stmts: Vec<GroundedStatement>,
    /// With provenance on: every atom the grounder made over all groundings, by the Control's
    /// grounder atom minus one (symbols in the Control's table, aspif numbers its atoms).
    gatoms: Vec<AtomRecord>,
    /// Grounder atom of each symbol id in `gatoms`.
    gatom_of_sym: HashMap<u32, GAtom>,
    /// The grounder's state across groundings (atoms, domains, indexes).
    session: ground::incremental::Session,
    /// The Control's atom of each of the session's grounder atoms (0: none).
    ctl_of_gatom: Vec<AtomId>,
    /// Registered propagators (`propagator`).
    propagators: propagator::Propagators,
    /// A detached search has the solver (`handle`).
    searching: bool,
    /// Told the lower bounds core-guided optimization proves (`handle`).
    lower_observer: Option<solve::LowerBoundObserver>,
    /// Clauses model callbacks add (`handle`), made at the first `model_clauses`.
    model_clauses: Option<solve::ModelClauses>,
}

/// Stops a solve call from another thread: see [`Control::interrupter`].
#[derive(Clone, Debug)]
pub struct Interrupter(std::sync::Arc<std::sync::atomic::AtomicBool>);

impl Interrupter {
    /// Asks the running solve call to stop.
    pub fn interrupt(&self) {
        self.0.store(true, std::sync::atomic::Ordering::Relaxed);
    }
}

/// A statement of a grounded part (see [`Control::statement`]).
#[derive(Clone, Debug)]
pub struct GroundedStatement {
    /// The part instance it was grounded in.
    pub part: Part,
    /// The statement.
    pub statement: Statement,
}

impl Control {
    /// A control with nothing added.
    pub fn new(config: ControlConfig) -> Control {
        Control::with_sources(config, SourceMap::new())
    }

    /// A control whose diagnostics are rendered against `sources` (files the caller read and
    /// adds with [`Control::add_file`]).
    pub fn with_sources(config: ControlConfig, sources: SourceMap) -> Control {
        let mut diags = Diagnostics::new(usize::MAX);
        for &k in &config.disabled_warnings {
            diags.disable(k);
        }
        Control {
            dialect: config.dialect,
            config,
            sources,
            diags,
            blocks: Vec::new(),
            globals: Vec::new(),
            incmode: false,
            grounded: HashSet::new(),
            groundings: 0,
            syms: Symbols::new(),
            atom_sym: Vec::new(),
            atom_key: Vec::new(),
            sym_atom: Vec::new(),
            flags: Vec::new(),
            externals: HashMap::new(),
            outputs_seen: None,
            pending: GroundProgram::new(),
            new_externals: Vec::new(),
            released: HashSet::new(),
            fresh_releases: Vec::new(),
            solver: None,
            last: None,
            stmts: Vec::new(),
            gatoms: Vec::new(),
            gatom_of_sym: HashMap::new(),
            session: ground::incremental::Session::new(),
            ctl_of_gatom: Vec::new(),
            propagators: Default::default(),
            searching: false,
            lower_observer: None,
            model_clauses: None,
        }
    }

    /// The configuration.
    pub fn config(&self) -> &ControlConfig {
        &self.config
    }

    /// The statistics of every solve call so far, added up (clingo's accumulated statistics;
    /// each call's own are in its [`Summary::stats`]).
    pub fn accumulated_stats(&self) -> solve::Stats {
        self.solver
            .as_ref()
            .map(|s| s.accumulated_stats().clone())
            .unwrap_or_default()
    }

    /// The solver's configuration as the next solve call reads it: once a call has built the
    /// solver, its own (what [`Control::solve_config_mut`] changes), no longer
    /// `config().solve`, which keeps the values the Control was made with.
    pub fn solve_config(&self) -> &solve::Config {
        match &self.solver {
            Some(s) => s.config(),
            None => &self.config.solve,
        }
    }

    /// The solver's configuration, to change between solve calls (e.g. the model count); a
    /// change takes effect at the next call.
    pub fn solve_config_mut(&mut self) -> &mut solve::Config {
        match &mut self.solver {
            Some(s) => s.config_mut(),
            None => &mut self.config.solve,
        }
    }

    /// The texts diagnostics refer to.
    pub fn sources(&self) -> &SourceMap {
        &self.sources
    }

    /// The texts diagnostics refer to, to add a file that a caller reads or generates.
    pub fn sources_mut(&mut self) -> &mut SourceMap {
        &mut self.sources
    }

    /// Warnings collected so far (errors come back in each call's [`Error`]).
    pub fn diagnostics(&self) -> &Diagnostics {
        &self.diags
    }

    /// Takes the warnings collected so far.
    pub fn take_diagnostics(&mut self) -> Diagnostics {
        let fresh = self.new_diags();
        std::mem::replace(&mut self.diags, fresh)
    }

    /// True when the program asked for clingo's incremental mode (`#include <incmode>.`);
    /// [`incmode::run`] runs it.
    pub fn incmode(&self) -> bool {
        self.incmode
    }

    fn error(&self, diags: Diagnostics) -> Error {
        Error {
            message: diags.render(&self.sources),
            diagnostics: diags,
        }
    }

    /// A collector for one call: unlimited, so that a caller merging the diagnostics of
    /// several calls applies the message limit once.
    fn new_diags(&self) -> Diagnostics {
        let mut d = Diagnostics::new(usize::MAX);
        for &k in &self.config.disabled_warnings {
            d.disable(k);
        }
        d
    }

    /// The atom of a symbol, if some grounding produced it.
    pub fn lookup(&self, symbol: &Symbol) -> Option<AtomId> {
        let id = symbol.find_in(&self.syms)?;
        self.atom_of_sym(id)
    }

    /// The symbol of an atom (`None` for auxiliary atoms and numbers out of range).
    pub fn symbol(&self, atom: AtomId) -> Option<Symbol> {
        let s = (*self.atom_sym.get((atom as usize).checked_sub(1)?)?)?;
        Some(Symbol::from_table(&self.syms, s))
    }

    /// Where clingo lists `atom` among a model's atoms: models list their atoms by increasing
    /// key, as clingo does (by predicate, in the order gringo met the predicates, then in the
    /// order the atoms were made). Atoms added through the backend come last.
    pub fn atom_order(&self, atom: AtomId) -> u64 {
        (atom as usize)
            .checked_sub(1)
            .and_then(|i| self.atom_key.get(i))
            .copied()
            .unwrap_or(Output::LAST)
    }

    /// Every atom with a symbol: its number, its symbol, and whether it is a fact and external.
    pub fn symbolic_atoms(&self) -> impl Iterator<Item = SymbolicAtom> + '_ {
        self.atom_sym.iter().enumerate().filter_map(|(i, s)| {
            let s = (*s)?;
            if self.flags[i] & DROPPED != 0 {
                return None;
            }
            let atom = i as AtomId + 1;
            Some(SymbolicAtom {
                atom,
                symbol: Symbol::from_table(&self.syms, s),
                fact: self.flags[i] & FACT != 0,
                // A released external (value `None` until the next solve call hands the
                // release to the solver) is no longer external, as in clingo.
                external: matches!(self.externals.get(&atom), Some(Some(_))),
            })
        })
    }

    /// The atoms of signature `name/arity` (clingo's `symbolic_atoms.by_signature`): those whose
    /// symbol is a function (or constant) of that name and arity, classically negated when
    /// `positive` is false.
    pub fn symbolic_atoms_by_signature<'a>(
        &'a self,
        name: &'a str,
        arity: usize,
        positive: bool,
    ) -> impl Iterator<Item = SymbolicAtom> + 'a {
        self.symbolic_atoms().filter(move |a| {
            a.symbol.name() == Some(name)
                && a.symbol.args().len() == arity
                && a.symbol.is_negative() != positive
        })
    }

    /// The signatures of the atoms, `(name, arity, positive)`, sorted and without repeats
    /// (clingo's `symbolic_atoms.signatures`).
    pub fn signatures(&self) -> Vec<(String, usize, bool)> {
        let mut out: Vec<(String, usize, bool)> = self
            .symbolic_atoms()
            .filter_map(|a| {
                let name = a.symbol.name()?.to_string();
                Some((name, a.symbol.args().len(), !a.symbol.is_negative()))
            })
            .collect();
        out.sort();
        out.dedup();
        out
    }

    /// A handle that stops the running (or the next) solve call from another thread (clingo's
    /// `Control.interrupt`): the call returns with [`solve::StopReason::Interrupted`]. A raised
    /// flag is lowered when the call it stopped returns. The handle is the solver's interrupt
    /// flag ([`solve::Config::interrupt`], made here if the configuration has none).
    pub fn interrupter(&mut self) -> Interrupter {
        let flag = self
            .solve_config_mut()
            .interrupt
            .get_or_insert_with(Default::default)
            .clone();
        Interrupter(flag)
    }

    /// True when the program has a minimize statement (grounded or added from code, solved or
    /// not): clingo then enumerates until the optimum unless a model count was given.
    pub fn has_minimize(&self) -> bool {
        !self.pending.minimize.is_empty()
            || self
                .solver
                .as_ref()
                .is_some_and(|s| !s.program().minimize.is_empty())
    }

    /// The priorities of the minimize statements grounded or added so far, highest first: the
    /// levels of a model's costs (clingo's `Model.priority`).
    pub fn minimize_priorities(&self) -> Vec<i64> {
        let solved = self.solver.as_ref().map(|s| &s.program().minimize);
        let mut levels: Vec<i64> = self
            .pending
            .minimize
            .iter()
            .chain(solved.into_iter().flatten())
            .map(|m| m.priority)
            .collect();
        levels.sort_unstable_by(|a, b| b.cmp(a));
        levels.dedup();
        levels
    }

    /// Number of atoms so far.
    pub fn num_atoms(&self) -> u32 {
        self.atom_sym.len() as u32
    }

    /// The ground program: before the first solve call the whole program grounded so far,
    /// afterwards the solver's (what later groundings added reaches it at the next call).
    pub fn program(&self) -> &GroundProgram {
        match &self.solver {
            Some(s) => s.program(),
            None => &self.pending,
        }
    }

    /// Whether the program is known to have no answer set whatever the externals and
    /// assumptions (clingo's `is_conflicting`): a constraint with an empty body was grounded
    /// (`:- .`, as `a. :- a.` simplifies), or a solve call met a conflict that holds at the top
    /// level. A program found unsatisfiable only under its assumptions or its externals' values
    /// is not conflicting; nor is one whose inconsistency only a search would show before the
    /// first solve call (`a :- not a.`), as in clingo.
    pub fn is_conflicting(&self) -> bool {
        let empty_constraint = |p: &GroundProgram| {
            p.rules.iter().any(|r| {
                r.head.is_empty()
                    && r.head_kind == crate::ground::program::HeadKind::Disjunction
                    && r.body.is_empty_normal()
            })
        };
        empty_constraint(&self.pending) || self.solver.as_ref().is_some_and(Solver::is_conflicting)
    }

    /// Takes the grounding of a one-shot control (one grounding, no solve call yet) with its
    /// program and its symbol table (which provenance bindings and atom records index), for
    /// output as aspif or text; the control is spent afterwards. Panics when used otherwise.
    pub fn take_grounding(&mut self) -> Grounding {
        assert!(
            self.groundings == 1 && self.solver.is_none() && self.last.is_some(),
            "take_grounding needs exactly one grounding and no solve call"
        );
        let mut g = self.last.take().expect("one grounding was done");
        g.program = std::mem::take(&mut self.pending);
        // `adopt` moved the grounding's symbols into the control.
        g.symbols = std::mem::take(&mut self.syms);
        g
    }

    /// Hands pending statements to the solver (building it at the first call).
    fn prepare(&mut self) {
        if let Some(solver) = &mut self.solver {
            let mut delta = std::mem::take(&mut self.pending);
            delta.num_atoms = self.atom_sym.len() as AtomId;
            delta.externals = std::mem::take(&mut self.new_externals)
                .into_iter()
                .filter(|a| self.externals.contains_key(a))
                .map(|a| (a, ExternalValue::Free))
                .collect();
            solver
                .add_program(&delta)
                .expect("grounding dropped the rules of completed atoms (redefinitions)");
        } else {
            // The one-shot grounding's tables are not needed once solving starts.
            self.last = None;
            let mut program = std::mem::take(&mut self.pending);
            program.num_atoms = self.atom_sym.len() as AtomId;
            program.externals = self.free_externals();
            let config = self.config.solve.clone();
            self.solver = Some(Solver::from_program(program, config));
            self.new_externals.clear();
        }
        self.release_in_solver();
    }

    /// Solves under the options' assumptions and the externals' values, calling `on_model`
    /// on every model as it is found (return false to stop). Solving twice without changes
    /// gives the same models; learnt clauses are kept between calls.
    pub fn solve(
        &mut self,
        options: &SolveOptions,
        mut on_model: impl FnMut(&Model<'_>) -> bool,
    ) -> Summary {
        let call = match self.begin_call(options) {
            Ok(call) => call,
            Err(summary) => return *summary,
        };
        let Control {
            solver,
            syms,
            atom_sym,
            sym_atom,
            ..
        } = self;
        let names = Names {
            syms,
            atom_sym,
            sym_atom,
        };
        let solver = solver.as_mut().expect("prepared");
        let mut count = 0;
        let result = {
            // Supports are built only for the models whose reader asks for them.
            let want_supports = solver.config_mut().supports;
            solver.for_each_model_lazy(&call.assumptions, &mut |m, prog| {
                count += 1;
                on_model(&Model {
                    raw: m,
                    names,
                    lazy_support: want_supports.then_some(prog),
                    full: OnceCell::new(),
                })
            })
        };
        let core = (count == 0)
            .then(|| solver.core())
            .flatten()
            .map(|core| handle::map_core(&options.assumptions, &call.lits, core));
        if result.stop == Some(solve::StopReason::Interrupted) {
            if let Some(flag) = &solver.config_mut().interrupt {
                flag.store(false, std::sync::atomic::Ordering::Relaxed);
            }
        }
        let at_limit = at_model_limit(solver, count);
        Summary {
            outcome: result.outcome,
            exhausted: result.exhausted && !at_limit,
            search_exhausted: result.exhausted,
            optimum_proven: result.optimum_proven,
            stop: result.stop,
            stats: result.stats,
            models: count,
            core,
        }
    }

    /// Solves and collects the models.
    pub fn solve_all(&mut self, options: &SolveOptions) -> Solved {
        let mut models = Vec::new();
        let summary = self.solve(options, |m| {
            models.push(m.to_owned_model());
            true
        });
        Solved { models, summary }
    }

    /// With provenance on ([`GroundConfig::provenance`]): statement `id` of the origins in
    /// [`Control::provenance`] (ids count the statements of every grounding, in order) and
    /// the part instance it was grounded in. `None` without provenance.
    pub fn statement(&self, id: u32) -> Option<&GroundedStatement> {
        self.stmts.get(id as usize)
    }

    /// The provenance of [`Control::program`]'s rules (empty without provenance): origins
    /// of every grounding's rules in the Control's statement ids, symbols (bindings) and
    /// grounder atoms (removed body literals, dead rules); the atom table covers every
    /// grounding. Rules of groundings made after the last solve call join at the next call.
    pub fn provenance(&self) -> &Provenance {
        &self.program().provenance
    }

    /// The symbol of a symbol id of the provenance tables ([`Control::provenance`]: binding
    /// values, atom records' symbols).
    pub fn symbol_of_id(&self, id: u32) -> Symbol {
        Symbol::from_table(&self.syms, SymId(id))
    }

    /// The variable name of a binding's name id ([`Control::provenance`]).
    pub fn name_of_id(&self, id: u32) -> &str {
        self.syms.names.resolve(crate::base::intern::Sym(id))
    }

    /// The solver, once a solve call built it (for statistics and low-level access).
    pub fn solver(&self) -> Option<&Solver> {
        self.solver.as_ref()
    }
}

/// A symbolic atom of the program (see [`Control::symbolic_atoms`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SymbolicAtom {
    /// Its number.
    pub atom: AtomId,
    /// Its symbol.
    pub symbol: Symbol,
    /// True when grounding made it a fact.
    pub fact: bool,
    /// True when it is (still) an external atom.
    pub external: bool,
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym(s: &str) -> Symbol {
        Symbol::parse(s).unwrap()
    }

    /// A configuration that enumerates every model (the default asks for one, as clingo).
    fn all_models() -> ControlConfig {
        let mut c = ControlConfig::default();
        c.solve.models = 0;
        c
    }

    fn answers(ctl: &mut Control) -> Vec<String> {
        let mut out: Vec<String> = ctl
            .solve_all(&SolveOptions::default())
            .models
            .iter()
            .map(|m| {
                let mut s: Vec<String> = m.shown.iter().map(|s| s.to_string()).collect();
                s.sort();
                s.join(" ")
            })
            .collect();
        out.sort();
        out
    }

    #[test]
    fn one_shot_models_lookup_and_assumptions() {
        let mut ctl = Control::new(all_models());
        ctl.add_source("t", "{a; b}. c :- a. #show c/0. #show b/0.")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), ["", "b", "b c", "c"]);
        let solved = ctl.solve_all(&SolveOptions {
            assumptions: vec![(sym("a"), true), (sym("b"), false)],
        });
        assert_eq!(solved.models.len(), 1);
        let m = &solved.models[0];
        assert_eq!(m.atoms, vec![sym("a"), sym("c")]);
        assert!(m.contains(&sym("a")) && !m.contains(&sym("b")));
        // Unknown atoms: assumed false is harmless, assumed true is unsatisfiable.
        let s = ctl.solve_all(&SolveOptions {
            assumptions: vec![(sym("zzz"), false)],
        });
        assert_eq!(s.models.len(), 4);
        let s = ctl.solve_all(&SolveOptions {
            assumptions: vec![(sym("zzz"), true)],
        });
        assert!(s.summary.is_unsatisfiable());
        let names: Vec<String> = ctl.symbolic_atoms().map(|a| a.symbol.to_string()).collect();
        assert!(names.contains(&"c".to_string()));
    }

    #[test]
    fn errors_come_back_as_diagnostics() {
        let mut ctl = Control::new(ControlConfig::default());
        let e = ctl.add_source("bad.lp", "p(1)\nq.").unwrap_err();
        assert!(e.diagnostics.has_errors());
        assert!(
            e.message.starts_with("bad.lp:2:1-2: error: syntax error"),
            "{}",
            e.message
        );
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source("unsafe.lp", "p(X) :- not q(X).").unwrap();
        let e = ctl.ground(&[Part::base()]).unwrap_err();
        assert!(e.message.contains("unsafe variables in"), "{}", e.message);
    }

    #[test]
    fn parts_are_grounded_on_demand_with_parameters() {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source(
            "p",
            "#program base. q(0).\n#program step(t). q(t) :- q(t-1). r(t) :- not q(t+5).\n",
        )
        .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), ["q(0)"]);
        let before = ctl.lookup(&sym("q(0)")).unwrap();
        ctl.ground(&[Part::new("step", vec![Symbol::number(1)])])
            .unwrap();
        ctl.ground(&[Part::new("step", vec![Symbol::number(2)])])
            .unwrap();
        assert_eq!(
            ctl.lookup(&sym("q(0)")),
            Some(before),
            "atoms keep their numbers"
        );
        assert_eq!(answers(&mut ctl), ["q(0) q(1) q(2) r(1) r(2)"]);
    }

    #[test]
    fn comparisons_in_disjunctive_heads_are_read_as_gringo_reads_them() {
        // `h ; X < 2 :- B.` holds when the comparison does: as `h :- B, not X < 2.`
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source("c", "q(X) ; X < 2 :- X = 1..3. r ; 3 < 1. s ; 1 < 3.")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), ["q(2) q(3) r"]);
    }

    #[test]
    fn a_later_part_shows_a_term_on_an_atom_of_an_earlier_one() {
        // `#show x : p(k).` in part k reads p(k), grounded (and numbered) by `base`.
        let mut ctl = Control::new(all_models());
        ctl.add_source(
            "s",
            "#program base. 1 { p(0..1) } 1. #program check(k). #show p/1. #show x : p(k).",
        )
        .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), ["p(0)", "p(1)"]);
        ctl.ground(&[Part::new("check", vec![Symbol::number(1)])])
            .unwrap();
        assert_eq!(answers(&mut ctl), ["p(0)", "p(1) x"]);
    }

    #[test]
    fn externals_are_assigned_and_released() {
        let mut ctl = Control::new(all_models());
        ctl.add_source("e", "#external e(1..2). p :- e(1). q :- e(2).")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), [""]);
        ctl.assign_external(&sym("e(1)"), TruthValue::True);
        assert_eq!(answers(&mut ctl), ["e(1) p"]);
        ctl.assign_external(&sym("e(2)"), TruthValue::Free);
        assert_eq!(answers(&mut ctl), ["e(1) e(2) p q", "e(1) p"]);
        ctl.release_external(&sym("e(1)"));
        ctl.assign_external(&sym("e(1)"), TruthValue::True);
        assert_eq!(answers(&mut ctl), ["", "e(2) q"]);
    }

    #[test]
    fn supports_are_built_when_read_and_only_when_configured() {
        let text = "a. b :- a. c :- b, not d. {d}.";
        let read = |supports: bool| {
            let mut config = ControlConfig::default();
            config.solve.supports = supports;
            let mut ctl = Control::new(config);
            ctl.add_source("s", text).unwrap();
            ctl.ground(&[Part::base()]).unwrap();
            let mut out = Vec::new();
            ctl.solve(&SolveOptions::default(), |m| {
                let via_raw = m.raw().support.clone();
                let pairs: Vec<(AtomId, Option<usize>)> = m.supports().collect();
                // Computed independently from the program the lazy supports are built from.
                let expect = m
                    .lazy_support
                    .map(|p| solve::solver::supports(p, &m.raw.atoms));
                out.push((via_raw, pairs, expect, m.to_owned_model().raw.support));
                true
            });
            out
        };
        for (via_raw, pairs, expect, owned) in read(true) {
            assert_eq!(via_raw.len(), pairs.len());
            assert!(!via_raw.is_empty() && via_raw.iter().all(Option::is_some));
            assert_eq!(Some(via_raw.clone()), expect);
            assert_eq!(pairs.iter().map(|p| p.1).collect::<Vec<_>>(), via_raw);
            assert_eq!(owned, via_raw);
        }
        for (via_raw, pairs, expect, owned) in read(false) {
            assert!(via_raw.is_empty() && pairs.is_empty() && owned.is_empty());
            assert_eq!(expect, None);
        }
    }
}
