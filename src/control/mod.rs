//! The library's front door, on the model of clingo's `Control`: load text and files with
//! constants, ground named program parts with parameters, solve with assumptions, and read
//! models as structured terms ([`Symbol`]), with lookup from a term to its atom and back.
//! `cli`, `lucent demo` and every robot layer are its clients, so the parse-ground-solve
//! pipeline exists once.
//!
//! ```
//! use lucent::control::{Control, ControlConfig, Part, Symbol};
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.add("example", "q(1..2). {p(X)} :- q(X). :- p(1), p(2).").unwrap();
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
//! re-instantiated: a new part is grounded against a context made of the atoms derived earlier
//! (facts as facts, the other atoms as free externals), its atoms are matched to the earlier
//! ones by symbol, new atoms are numbered after the old ones, and only the new ground rules
//! reach the solver.
//!
//! ```
//! use lucent::control::{Control, ControlConfig, Part, Symbol, TruthValue};
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.add("inc", "
//!     #program base. at(0).
//!     #program step(t). at(t) :- at(t-1), not stop(t). #external stop(t).
//! ").unwrap();
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

pub mod incmode;
pub mod symbol;

use std::path::Path;
use std::time::Instant;

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

pub use symbol::{ParseSymbolError, Symbol};

/// An atom of the ground program, as the solver numbers it (aspif's numbering, from 1).
pub type AtomId = u32;

/// How a [`Control`] grounds and solves.
#[derive(Clone, Debug)]
pub struct ControlConfig {
    /// The solver's configuration (models to enumerate, optimization, CR semantics, ...).
    pub solve: solve::Config,
    /// `-c name=value` constants; they override `#const` definitions without `[override]`.
    /// [`const_term`] reads a value written as text.
    pub consts: Vec<(String, ast::Term)>,
    /// Record the origin of every ground rule.
    pub provenance: bool,
    /// Diagnostics limit per call (gringo's default is 20).
    pub message_limit: usize,
    /// Warning kinds not reported (`-W no-...`).
    pub disabled_warnings: Vec<WarningKind>,
    /// Grounding stops with a diagnostic after this instant.
    pub deadline: Option<Instant>,
    /// Grounding stops with a diagnostic when ground rules plus atoms exceed this number.
    pub max_size: Option<usize>,
    /// The language of added text; `None` detects it per text (SPARC or clingo).
    pub dialect: Option<Dialect>,
}

impl Default for ControlConfig {
    fn default() -> Self {
        ControlConfig {
            solve: solve::Config {
                models: 0,
                ..solve::Config::default()
            },
            consts: Vec::new(),
            provenance: false,
            message_limit: 20,
            disabled_warnings: Vec::new(),
            deadline: None,
            max_size: None,
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

/// What a solve call answers besides its models.
#[derive(Clone, Debug)]
pub struct Summary {
    /// Satisfiable, unsatisfiable, unknown or optimum.
    pub outcome: solve::Outcome,
    /// True when the search space was fully explored.
    pub exhausted: bool,
    /// True when the last model's costs are proven optimal.
    pub optimum_proven: bool,
    /// Why the search stopped early, if it did.
    pub stop: Option<solve::StopReason>,
    /// Search statistics.
    pub stats: solve::Stats,
    /// Models reported to the callback.
    pub models: usize,
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
            sym_atom: Vec::new(),
            flags: Vec::new(),
            externals: HashMap::new(),
            outputs_seen: None,
            pending: GroundProgram::new(),
            new_externals: Vec::new(),
            released: HashSet::new(),
            solver: None,
            last: None,
            stmts: Vec::new(),
            gatoms: Vec::new(),
            gatom_of_sym: HashMap::new(),
        }
    }

    /// The configuration.
    pub fn config(&self) -> &ControlConfig {
        &self.config
    }

    /// The solver's configuration, to change between solve calls (e.g. the model count).
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

    /// Parses `text` (named `name` in diagnostics) and keeps its statements.
    pub fn add(&mut self, name: &str, text: &str) -> Result<(), Error> {
        let file = self.sources.add(name, text);
        self.add_file(file, None)
    }

    /// Reads the file at `path` and adds it (clingo's `load`).
    pub fn load(&mut self, path: impl AsRef<Path>) -> Result<(), Error> {
        let path = path.as_ref();
        match std::fs::read_to_string(path) {
            Ok(text) => self.add(&path.display().to_string(), &text),
            Err(e) => {
                let cmd = self.sources.add("<cmd>", "");
                let mut d = self.new_diags();
                d.push(
                    Diagnostic::error(Span::new(cmd, 0, 0), "file could not be opened")
                        .with_snippet(format!("{}: {e}", path.display())),
                );
                Err(self.error(d))
            }
        }
    }

    /// Parses the file `file` of [`Control::sources`] (added by the caller) in `dialect`
    /// (detected when `None`), resolves its includes and keeps its statements.
    pub fn add_file(&mut self, file: FileId, dialect: Option<Dialect>) -> Result<(), Error> {
        let text = &self.sources.get(file).text;
        let dialect = dialect
            .or(self.config.dialect)
            .unwrap_or_else(|| crate::syntax::detect_dialect(text));
        let parse = crate::syntax::parse(file, text, dialect);
        let mut d = self.new_diags();
        d.extend(parse.diagnostics);
        self.add_parsed(parse.program, d)
    }

    /// Keeps the statements of an already parsed program. Spans refer to files of
    /// [`Control::sources`] (a generated program may use default spans).
    pub fn add_program(&mut self, program: Program) -> Result<(), Error> {
        let d = self.new_diags();
        self.add_parsed(program, d)
    }

    fn add_parsed(&mut self, program: Program, mut d: Diagnostics) -> Result<(), Error> {
        if self.sources.is_empty() {
            // Default spans name file 0: give it a name.
            self.sources.add("<program>", "");
        }
        // `#include <incmode>.` is clingo's incremental mode: taken out here (it is no file),
        // its part `#program check(t). #external query(t).` added below.
        let mut program = program;
        let before = program.statements.len();
        program.statements.retain(
            |s| !matches!(&s.kind, StatementKind::Include(i) if i.system && i.path == "incmode"),
        );
        let wants_incmode = program.statements.len() != before;
        let mut load =
            |path: &std::path::Path| std::fs::read_to_string(path).map_err(|e| e.to_string());
        // Resolving copies the statements: only when there is an include.
        let program = if program
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Include(_)))
        {
            ground::include::resolve_includes(&program, &mut self.sources, &mut d, &mut load)
        } else {
            program
        };
        if d.has_errors() {
            return Err(self.error(d));
        }
        self.diags.extend(d.items().iter().cloned());
        if self.dialect.is_none() {
            self.dialect = Some(program.dialect);
        }
        self.split(program.statements, program.dialect);
        if wants_incmode && !self.incmode {
            self.incmode = true;
            let text = "#program check(t).\n#external query(t).\n";
            let file = self.sources.add("<incmode>", text);
            let parse = crate::syntax::parse(file, text, Dialect::Clingo);
            self.split(parse.program.statements, Dialect::Clingo);
        }
        Ok(())
    }

    /// Files the statements into parts: each file starts in `base`; `#program` switches the
    /// part of the file it is written in (an included file's parts do not leak).
    fn split(&mut self, statements: Vec<Statement>, dialect: Dialect) {
        let mut current: HashMap<FileId, usize> = HashMap::new();
        for st in statements {
            if dialect == Dialect::Sparc {
                let b = self.block("base", &[]);
                self.blocks[b].statements.push(st);
                continue;
            }
            if let StatementKind::ProgramPart(p) = &st.kind {
                let b = self.block(&p.name, &p.params);
                current.insert(st.span.file, b);
                continue;
            }
            let b = match current.get(&st.span.file) {
                Some(&b) => b,
                None => self.block("base", &[]),
            };
            let global = match &st.kind {
                StatementKind::Const(_) => true,
                StatementKind::Show(s) => !matches!(**s, ast::Show::Term { .. }),
                _ => false,
            };
            if global {
                self.globals.push((b, st.clone()));
            }
            self.blocks[b].statements.push(st);
        }
    }

    fn block(&mut self, name: &str, params: &[String]) -> usize {
        if let Some(i) = self
            .blocks
            .iter()
            .position(|b| b.name == name && b.params == params)
        {
            return i;
        }
        self.blocks.push(Block {
            name: name.to_string(),
            params: params.to_vec(),
            statements: Vec::new(),
        });
        self.blocks.len() - 1
    }

    /// The value of the constant `name` (`-c` first, then `#const`), if it is defined and
    /// evaluates to a symbol.
    pub fn get_const(&self, name: &str) -> Option<Symbol> {
        let term = self
            .config
            .consts
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.clone())
            .or_else(|| {
                self.globals.iter().find_map(|(_, st)| match &st.kind {
                    StatementKind::Const(c) if c.name == name => Some(c.value.clone()),
                    _ => None,
                })
            })?;
        self.eval_const(&term, 0)
    }

    fn eval_const(&self, t: &ast::Term, depth: usize) -> Option<Symbol> {
        use ast::TermKind as K;
        if depth > 64 {
            return None;
        }
        Some(match &t.kind {
            K::Integer(n) => Symbol::Number(*n as i32),
            K::String(s) => Symbol::String(s.clone()),
            K::Infimum => Symbol::Inf,
            K::Supremum => Symbol::Sup,
            K::Constant(c) => match self.get_const_depth(c, depth + 1) {
                Some(v) => v,
                None => Symbol::constant(c.clone()),
            },
            K::Function { name, args, .. } if args.len() <= 1 => {
                let list = args.first().map(Vec::as_slice).unwrap_or(&[]);
                let mut out = Vec::new();
                for a in list {
                    out.push(self.eval_const(a, depth + 1)?);
                }
                Symbol::function(name.clone(), out)
            }
            K::Unary {
                op: ast::UnaryOp::Minus,
                arg,
            } => match self.eval_const(arg, depth + 1)? {
                Symbol::Number(n) => Symbol::Number(n.wrapping_neg()),
                Symbol::Function {
                    name,
                    args,
                    negative,
                } if !name.is_empty() => Symbol::Function {
                    name,
                    args,
                    negative: !negative,
                },
                _ => return None,
            },
            K::Binary { op, lhs, rhs } => {
                let a = self.eval_const(lhs, depth + 1)?.as_number()?;
                let b = self.eval_const(rhs, depth + 1)?.as_number()?;
                Symbol::Number(match op {
                    ast::BinaryOp::Add => a.wrapping_add(b),
                    ast::BinaryOp::Sub => a.wrapping_sub(b),
                    ast::BinaryOp::Mul => a.wrapping_mul(b),
                    ast::BinaryOp::Div if b != 0 => a.wrapping_div(b),
                    ast::BinaryOp::Mod if b != 0 => a.wrapping_rem(b),
                    _ => return None,
                })
            }
            _ => return None,
        })
    }

    fn get_const_depth(&self, name: &str, depth: usize) -> Option<Symbol> {
        let term = self
            .config
            .consts
            .iter()
            .rev()
            .find(|(n, _)| n == name)
            .map(|(_, t)| t.clone())
            .or_else(|| {
                self.globals.iter().find_map(|(_, st)| match &st.kind {
                    StatementKind::Const(c) if c.name == name => Some(c.value.clone()),
                    _ => None,
                })
            })?;
        self.eval_const(&term, depth)
    }

    /// Grounds the given parts (clingo's `ground`). Each part `name(args)` instantiates every
    /// `#program name(params).` block with as many parameters, the parameters bound to `args`.
    /// Parts without parameters are grounded first, together; then each group of parts whose
    /// parameter bindings agree. A part instance grounded before is skipped.
    pub fn ground(&mut self, parts: &[Part]) -> Result<(), Error> {
        let mut plain: Vec<usize> = Vec::new();
        let mut groups: Vec<(Binding, Vec<usize>)> = Vec::new();
        let mut requested: Vec<Part> = Vec::new();
        for part in parts {
            if self.grounded.contains(part) || requested.contains(part) {
                continue;
            }
            requested.push(part.clone());
            for (i, b) in self.blocks.iter().enumerate() {
                if b.name != part.name || b.params.len() != part.args.len() {
                    continue;
                }
                if b.params.is_empty() {
                    plain.push(i);
                    continue;
                }
                let binding: Vec<(String, Symbol)> = b
                    .params
                    .iter()
                    .cloned()
                    .zip(part.args.iter().cloned())
                    .collect();
                let fits = |g: &Vec<(String, Symbol)>| {
                    binding
                        .iter()
                        .all(|(n, v)| g.iter().all(|(m, w)| m != n || w == v))
                };
                match groups.iter_mut().find(|(g, _)| fits(g)) {
                    Some((g, blocks)) => {
                        for kv in &binding {
                            if !g.contains(kv) {
                                g.push(kv.clone());
                            }
                        }
                        blocks.push(i);
                    }
                    None => groups.push((binding, vec![i])),
                }
            }
        }
        if !plain.is_empty() || self.groundings == 0 && groups.is_empty() {
            self.ground_blocks(&plain, &[])?;
        }
        for (binding, blocks) in groups {
            self.ground_blocks(&blocks, &binding)?;
        }
        self.grounded.extend(requested);
        Ok(())
    }

    /// Grounds the statements of `blocks` with `binding` as constants, against the atoms of
    /// earlier groundings, and merges the result.
    fn ground_blocks(
        &mut self,
        blocks: &[usize],
        binding: &[(String, Symbol)],
    ) -> Result<(), Error> {
        let first = self.groundings == 0;
        let mut statements: Vec<Statement> = Vec::new();
        // A part without parameters is grounded once: its statements move into the grounding
        // (and back if it fails) instead of being copied.
        let take = binding.is_empty();
        let mut counts = Vec::with_capacity(blocks.len());
        // With provenance on, the part of each statement (the Control's statement table).
        let mut parts: Vec<Part> = Vec::new();
        for &b in blocks {
            counts.push(self.blocks[b].statements.len());
            if self.config.provenance {
                let block = &self.blocks[b];
                let args = block
                    .params
                    .iter()
                    .map(|p| {
                        let v = binding.iter().find(|(n, _)| n == p);
                        v.map(|(_, v)| v.clone()).expect("every parameter is bound")
                    })
                    .collect();
                let part = Part::new(block.name.clone(), args);
                parts.extend(std::iter::repeat_n(part, block.statements.len()));
            }
            if take {
                statements.append(&mut self.blocks[b].statements);
            } else {
                statements.extend(self.blocks[b].statements.iter().cloned());
            }
        }
        for (b, st) in &self.globals {
            if !blocks.contains(b) {
                statements.push(st.clone());
                if self.config.provenance {
                    let block = &self.blocks[*b];
                    parts.push(Part::new(block.name.clone(), Vec::new()));
                }
            }
        }
        let own = statements.len();
        if !first {
            self.context(&mut statements);
        }
        let program = Program {
            dialect: self.dialect.unwrap_or_default(),
            statements,
        };
        let mut consts = self.config.consts.clone();
        consts.extend(binding.iter().map(|(n, v)| (n.clone(), v.to_term())));
        let gconfig = GroundConfig {
            consts,
            max_size: self.config.max_size,
            deadline: self.config.deadline,
            provenance: self.config.provenance,
            message_limit: Some(self.config.message_limit),
        };
        let mut grounding = ground::ground(&program, Some(&self.sources), &gconfig);
        for &k in &self.config.disabled_warnings {
            grounding.diagnostics.disable(k);
        }
        let mut d = self.new_diags();
        d.extend(
            grounding
                .diagnostics
                .items()
                .iter()
                .filter(|x| {
                    x.is_error()
                        || x.kind
                            .is_none_or(|k| !self.config.disabled_warnings.contains(&k))
                })
                .cloned(),
        );
        grounding.diagnostics = Diagnostics::new(self.config.message_limit);
        if d.has_errors() {
            if take {
                let mut rest = program.statements.into_iter();
                for (&b, &n) in blocks.iter().zip(&counts) {
                    self.blocks[b].statements = rest.by_ref().take(n).collect();
                }
            }
            return Err(self.error(d));
        }
        self.diags.extend(d.items().iter().cloned());
        self.groundings += 1;
        let offset = self.stmts.len() as u32;
        if self.config.provenance {
            let statements = program.statements.into_iter().take(own);
            self.stmts.extend(
                parts
                    .into_iter()
                    .zip(statements)
                    .map(|(part, statement)| GroundedStatement { part, statement }),
            );
        }
        if first {
            self.adopt(grounding);
            Ok(())
        } else {
            self.merge(grounding, offset).map_err(|e| {
                let mut d = self.new_diags();
                d.push(e);
                self.error(d)
            })
        }
    }

    /// The atoms of earlier groundings as statements: facts as facts, the others as externals.
    fn context(&self, statements: &mut Vec<Statement>) {
        for (i, s) in self.atom_sym.iter().enumerate() {
            let Some(s) = s else { continue };
            let sym = Symbol::from_table(&self.syms, *s);
            let Some(atom) = sym.to_atom() else { continue };
            let lit = ast::Literal {
                span: Span::default(),
                sign: ast::Sign::Positive,
                atom: ast::Atom::Symbolic(atom.clone()),
            };
            let kind = if self.flags[i] & FACT != 0 {
                StatementKind::Rule(ast::Rule {
                    head: ast::Head::Disjunction(vec![ast::ConditionalLiteral {
                        span: Span::default(),
                        literal: lit,
                        condition: Vec::new(),
                        has_colon: false,
                    }]),
                    body: Vec::new(),
                    kind: ast::RuleKind::Normal,
                })
            } else {
                StatementKind::External(Box::new(ast::External {
                    atom,
                    body: Vec::new(),
                    value: Some(ast::Term {
                        span: Span::default(),
                        kind: ast::TermKind::Constant("free".into()),
                    }),
                }))
            };
            statements.push(Statement {
                span: Span::default(),
                kind,
            });
        }
    }

    /// Takes the first grounding as it is: its numbering is the global one.
    fn adopt(&mut self, mut g: Grounding) {
        let program = std::mem::take(&mut g.program);
        self.syms = std::mem::take(&mut g.symbols);
        self.atom_sym = std::mem::take(&mut g.atom_syms);
        self.atom_sym.resize(program.num_atoms as usize, None);
        for s in self.atom_sym.iter_mut() {
            if s.is_some_and(|s| is_internal(&self.syms, s)) {
                *s = None;
            }
        }
        self.flags = vec![0; self.atom_sym.len()];
        self.sym_atom = vec![0; self.syms.len()];
        for (i, s) in self.atom_sym.iter().enumerate() {
            if let Some(s) = s {
                self.sym_atom[s.0 as usize] = i as AtomId + 1;
            }
        }
        for &s in &g.fact_syms {
            if let Some(a) = self.atom_of_sym(s) {
                self.flags[a as usize - 1] |= FACT;
            }
        }
        for r in program.rules.iter() {
            for &h in r.head {
                self.flags[h as usize - 1] |= DEFINED;
            }
        }
        for &(a, v) in &program.externals {
            if self.flags[a as usize - 1] & DEFINED == 0 {
                self.externals.insert(a, external_value(v));
            }
        }
        if self.config.provenance {
            self.gatoms = program.provenance.atoms.clone();
            self.gatom_of_sym = self
                .gatoms
                .iter()
                .enumerate()
                .filter_map(|(i, r)| Some((r.sym?, i as GAtom + 1)))
                .collect();
        }
        self.pending = program;
        self.last = Some(g);
    }

    fn atom_of_sym(&self, s: SymId) -> Option<AtomId> {
        match self.sym_atom.get(s.0 as usize) {
            Some(&a) if a != 0 => Some(a),
            _ => None,
        }
    }

    fn free_externals(&self) -> Vec<(AtomId, ExternalValue)> {
        let mut v: Vec<(AtomId, ExternalValue)> = self
            .externals
            .keys()
            .map(|&a| (a, ExternalValue::Free))
            .collect();
        v.sort_unstable_by_key(|&(a, _)| a);
        v
    }

    fn new_atom(&mut self, sym: Option<SymId>) -> AtomId {
        self.atom_sym.push(sym);
        self.flags.push(0);
        let a = self.atom_sym.len() as AtomId;
        if let Some(s) = sym {
            let i = s.0 as usize;
            if self.sym_atom.len() <= i {
                self.sym_atom.resize(i + 1, 0);
            }
            self.sym_atom[i] = a;
        }
        a
    }

    /// Merges a later grounding: atoms matched by symbol, new ones numbered after the old,
    /// origins moved to the Control's statement ids, symbols and grounder atoms. A rule for an
    /// atom that an earlier solve call completed is gringo's redefinition error: the rules of
    /// such atoms are dropped (clingo keeps the rest of the step) and the error returned.
    fn merge(&mut self, mut g: Grounding, stmt_offset: u32) -> Result<(), Diagnostic> {
        let local = std::mem::take(&mut g.program);
        let old_atoms = self.atom_sym.len() as AtomId;
        // Local symbol ids to global ones.
        let mut memo: Vec<u32> = vec![u32::MAX; g.symbols.len()];
        let mut map = vec![0 as AtomId; local.num_atoms as usize + 1];
        for (a, slot) in map.iter_mut().enumerate().skip(1) {
            let sym = g
                .atom_syms
                .get(a - 1)
                .copied()
                .flatten()
                .filter(|&s| !is_internal(&g.symbols, s));
            *slot = match sym {
                Some(s) => {
                    let gs = translate(&g.symbols, s, &mut self.syms, &mut memo);
                    match self.atom_of_sym(gs) {
                        Some(x) => x,
                        None => self.new_atom(Some(gs)),
                    }
                }
                None => self.new_atom(None),
            };
        }
        let is_old = |a: AtomId| a <= old_atoms;
        let lit = |l: i32| -> i32 {
            let a = map[l.unsigned_abs() as usize] as i32;
            if l < 0 {
                -a
            } else {
                a
            }
        };
        // Atoms an earlier solve call completed: in the solver and no longer external there,
        // or released since.
        let solver_atoms = self.solver.as_ref().map_or(0, |s| s.program().num_atoms);
        let complete = |a: AtomId, solver: &Option<Solver>, ext: &HashMap<AtomId, _>| {
            a <= solver_atoms
                && (solver.as_ref().is_some_and(|s| !s.is_external(a))
                    || matches!(ext.get(&a), Some(None)))
        };
        let was_fact: Vec<bool> = self.flags.iter().map(|f| f & FACT != 0).collect();
        let old_fact = |a: AtomId| is_old(a) && was_fact[a as usize - 1];
        let gmap = self.translate_atom_records(&g, &local, &map, &mut memo);
        let mut delta = GroundProgram::new();
        let mut defined_here: HashSet<AtomId> = HashSet::new();
        let mut redefined: Vec<AtomId> = Vec::new();
        let mut first_redefinition: Option<usize> = None;
        let mut kept: Vec<usize> = Vec::new();
        for (i, r) in local.rules.iter().enumerate() {
            let heads: Vec<AtomId> = r.head.iter().map(|&h| map[h as usize]).collect();
            // A rule whose heads are all old facts adds nothing (the context's facts).
            if !heads.is_empty() && heads.iter().all(|&h| old_fact(h)) {
                continue;
            }
            if let Some(&h) = heads
                .iter()
                .find(|&&h| complete(h, &self.solver, &self.externals))
            {
                if redefined.is_empty() {
                    first_redefinition = Some(i);
                }
                if !redefined.contains(&h) {
                    redefined.push(h);
                }
                continue;
            }
            let mut rule = r.to_rule();
            rule.head = heads;
            match &mut rule.body {
                ground::program::Body::Normal(ls) => ls.iter_mut().for_each(|l| *l = lit(*l)),
                ground::program::Body::Weight { lits, .. } => {
                    lits.iter_mut().for_each(|(l, _)| *l = lit(*l))
                }
            }
            for &h in &rule.head {
                defined_here.insert(h);
                // An external defined by a rule becomes an ordinary atom (the solver takes
                // such rules incrementally).
                self.externals.remove(&h);
            }
            delta.rules.push(rule);
            kept.push(i);
        }
        // The rules of a redefined atom are dropped, all of them (clingo's state after the
        // error).
        if !redefined.is_empty() {
            let mut keep_rules = GroundProgram::new();
            let mut keep_idx = Vec::new();
            for (r, &i) in delta.rules.iter().zip(&kept) {
                if r.head.iter().any(|h| redefined.contains(h)) {
                    continue;
                }
                keep_rules.rules.push_ref(r);
                keep_idx.push(i);
            }
            delta.rules = keep_rules.rules;
            kept = keep_idx;
            defined_here = delta.rules.iter().flat_map(|r| r.head.to_vec()).collect();
        }
        for &h in &defined_here {
            self.flags[h as usize - 1] |= DEFINED;
        }
        for &s in &g.fact_syms {
            let gs = translate(&g.symbols, s, &mut self.syms, &mut memo);
            if let Some(a) = self.atom_of_sym(gs) {
                if !redefined.contains(&a) {
                    self.flags[a as usize - 1] |= FACT;
                }
            }
        }
        for &(a, v) in &local.externals {
            let ga = map[a as usize];
            if is_old(ga) || defined_here.contains(&ga) {
                continue;
            }
            if !self.released.contains(&ga) {
                self.externals.insert(ga, external_value(v));
                self.new_externals.push(ga);
            }
        }
        for m in &local.minimize {
            let mut m = m.clone();
            m.lits.iter_mut().for_each(|(l, _)| *l = lit(*l));
            delta.minimize.push(m);
        }
        for c in &local.cr_rules {
            delta.cr_rules.push(ground::program::CrRule {
                appl: map[c.appl as usize],
                label: c.label.clone(),
            });
        }
        for p in &local.prefers {
            delta.prefers.push(ground::program::Prefer {
                better: map[p.better as usize],
                worse: map[p.worse as usize],
            });
        }
        for h in &local.heuristics {
            let mut h = h.clone();
            h.atom = map[h.atom as usize];
            h.condition.iter_mut().for_each(|l| *l = lit(*l));
            delta.heuristics.push(h);
        }
        for e in &local.edges {
            let mut e = e.clone();
            e.condition.iter_mut().for_each(|l| *l = lit(*l));
            delta.edges.push(e);
        }
        for &p in &local.projections {
            delta.projections.push(map[p as usize]);
        }
        for &l in &local.assumptions {
            delta.assumptions.push(lit(l));
        }
        // Outputs, without those already present (the context shows old atoms again).
        if self.outputs_seen.is_none() {
            let solver_outputs = match &self.solver {
                Some(s) => s.program().outputs.as_slice(),
                None => &[],
            };
            let seen = solver_outputs
                .iter()
                .chain(self.pending.outputs.iter())
                .map(|o| (o.symbol.clone(), o.condition.clone()))
                .collect();
            self.outputs_seen = Some(seen);
        }
        let seen = self.outputs_seen.as_mut().expect("set above");
        for o in &local.outputs {
            let condition: Vec<i32> = o.condition.iter().map(|&l| lit(l)).collect();
            if seen.insert((o.symbol.clone(), condition.clone())) {
                delta.outputs.push(Output {
                    symbol: o.symbol.clone(),
                    condition,
                });
            }
        }
        if let Some(gmap) = &gmap {
            let mut prov = ground::program::Provenance::new();
            for &i in &kept {
                let origins: Vec<_> = local
                    .provenance
                    .origins(i)
                    .iter()
                    .filter_map(|o| self.translate_origin(o, &g, gmap, &mut memo, stmt_offset))
                    .collect();
                prov.push_rule(origins);
            }
            for d in &local.provenance.dead {
                let why = match d.why {
                    DeadReason::Literal { positive, atom } => DeadReason::Literal {
                        positive,
                        atom: gmap[atom as usize],
                    },
                    DeadReason::HeadFact(a) => DeadReason::HeadFact(gmap[a as usize]),
                    w => w,
                };
                prov.dead.push(ground::program::DeadRule {
                    head: d.head.iter().map(|&h| gmap[h as usize]).collect(),
                    origins: d
                        .origins
                        .iter()
                        .filter_map(|o| self.translate_origin(o, &g, gmap, &mut memo, stmt_offset))
                        .collect(),
                    why,
                });
            }
            prov.set_atoms(self.gatoms.clone());
            delta.provenance = prov;
        }
        delta.num_atoms = self.atom_sym.len() as AtomId;
        // Append the delta to what is pending.
        let p = &mut self.pending;
        if !delta.provenance.is_empty() {
            p.provenance.resize_rules(p.rules.len());
            p.provenance.append(std::mem::take(&mut delta.provenance));
        }
        p.num_atoms = delta.num_atoms;
        p.rules.extend(delta.rules.iter());
        p.minimize.extend(delta.minimize);
        p.projections.extend(delta.projections);
        p.outputs.extend(delta.outputs);
        p.assumptions.extend(delta.assumptions);
        p.heuristics.extend(delta.heuristics);
        p.edges.extend(delta.edges);
        p.cr_rules.extend(delta.cr_rules);
        p.prefers.extend(delta.prefers);
        self.last = Some(g);
        match redefined.first() {
            None => Ok(()),
            Some(&a) => {
                let name = self.symbol(a).map_or_else(String::new, |s| s.to_string());
                // The statement of the first rule dropped (known with provenance on).
                let span = first_redefinition
                    .and_then(|i| {
                        local
                            .provenance
                            .origins(i)
                            .iter()
                            .find_map(|o| o.rule.stmt())
                    })
                    .and_then(|k| self.stmts.get((k + stmt_offset) as usize))
                    .map(|st| st.statement.span);
                let span = span.unwrap_or_else(|| self.no_position());
                Err(Diagnostic::error(
                    span,
                    format!("redefinition of atom <'{name}',{a}>"),
                ))
            }
        }
    }

    /// A span for errors without a source position (gringo's `<cmd>`-like pseudo files).
    fn no_position(&mut self) -> Span {
        let file = self.sources.add("<ground>", "");
        Span::new(file, 0, 0)
    }

    /// Moves a later grounding's atom records into the Control's table (by symbol; auxiliary
    /// atoms are new) and returns the local-to-global grounder atom map (`None` without
    /// provenance).
    fn translate_atom_records(
        &mut self,
        g: &Grounding,
        local: &GroundProgram,
        map: &[AtomId],
        memo: &mut [u32],
    ) -> Option<Vec<GAtom>> {
        if !self.config.provenance || local.provenance.atoms.is_empty() {
            return None;
        }
        let mut gmap = vec![0 as GAtom; local.provenance.atoms.len() + 1];
        for (i, r) in local.provenance.atoms.iter().enumerate() {
            let aspif = if r.aspif == 0 {
                0
            } else {
                map[r.aspif as usize]
            };
            let sym = r
                .sym
                .map(|s| translate(&g.symbols, SymId(s), &mut self.syms, memo).0);
            let known = sym
                .filter(|&s| !is_internal(&self.syms, SymId(s)))
                .and_then(|s| self.gatom_of_sym.get(&s).copied());
            gmap[i + 1] = match known {
                Some(ga) => {
                    let old = &mut self.gatoms[ga as usize - 1];
                    if r.status != AtomStatus::False && old.status != AtomStatus::Fact {
                        old.status = r.status;
                    }
                    if aspif != 0 {
                        old.aspif = aspif;
                    }
                    ga
                }
                None => {
                    self.gatoms.push(AtomRecord {
                        sym,
                        status: r.status,
                        aspif,
                    });
                    let ga = self.gatoms.len() as GAtom;
                    if let Some(s) = sym {
                        self.gatom_of_sym.insert(s, ga);
                    }
                    ga
                }
            };
        }
        Some(gmap)
    }

    /// One origin of a later grounding in the Control's ids: statement ids shifted by the
    /// grounding's offset, bindings and atoms in the global tables; `None` for the context
    /// statements (they are no statements of the program).
    fn translate_origin(
        &mut self,
        o: &ground::program::Origin,
        g: &Grounding,
        gmap: &[GAtom],
        memo: &mut [u32],
        offset: u32,
    ) -> Option<ground::program::Origin> {
        let n = self.stmts.len() as u32;
        let mut bind = |b: &[(u32, u32)], syms: &mut Symbols| -> Vec<(u32, u32)> {
            b.iter()
                .map(|&(name, value)| {
                    let text = g.symbols.names.resolve(crate::base::intern::Sym(name));
                    let name = syms.names.intern(text).0;
                    (name, translate(&g.symbols, SymId(value), syms, memo).0)
                })
                .collect()
        };
        let rule = match &o.rule {
            RuleOrigin::Statement { stmt, bindings } if stmt + offset < n => {
                RuleOrigin::Statement {
                    stmt: stmt + offset,
                    bindings: bind(bindings, &mut self.syms),
                }
            }
            RuleOrigin::Auxiliary {
                of_stmt,
                kind,
                bindings,
            } if of_stmt + offset < n => RuleOrigin::Auxiliary {
                of_stmt: of_stmt + offset,
                kind: *kind,
                bindings: bind(bindings, &mut self.syms),
            },
            RuleOrigin::Complement => RuleOrigin::Complement,
            _ => return None,
        };
        Some(ground::program::Origin {
            rule,
            removed: o
                .removed
                .iter()
                .map(|r| RemovedLit {
                    positive: r.positive,
                    atom: gmap[r.atom as usize],
                })
                .collect(),
        })
    }

    /// Sets the value of an external atom (clingo's `assign_external`). Atoms that are not
    /// external are left alone, as clingo does.
    pub fn assign_external(&mut self, atom: &Symbol, value: TruthValue) {
        if let Some(a) = self.lookup(atom) {
            // (A released atom left the map: it stays false.)
            if let Some(v) = self.externals.get_mut(&a) {
                if v.is_some() {
                    *v = Some(value);
                }
            }
        }
    }

    /// Releases an external atom: it is false from now on and no longer external (clingo's
    /// `release_external`).
    pub fn release_external(&mut self, atom: &Symbol) {
        if let Some(a) = self.lookup(atom) {
            if let Some(v) = self.externals.get_mut(&a) {
                *v = None;
            }
        }
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

    /// Every atom with a symbol: its number, its symbol, and whether it is a fact and external.
    pub fn symbolic_atoms(&self) -> impl Iterator<Item = SymbolicAtom> + '_ {
        self.atom_sym.iter().enumerate().filter_map(|(i, s)| {
            let s = (*s)?;
            let atom = i as AtomId + 1;
            Some(SymbolicAtom {
                atom,
                symbol: Symbol::from_table(&self.syms, s),
                fact: self.flags[i] & FACT != 0,
                external: self.externals.contains_key(&atom),
            })
        })
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

    /// Takes the grounding of a one-shot control (one grounding, no solve call yet) with its
    /// program, for output as aspif or text. Panics when used otherwise.
    pub fn take_grounding(&mut self) -> Grounding {
        assert!(
            self.groundings == 1 && self.solver.is_none(),
            "take_grounding needs exactly one grounding and no solve call"
        );
        let mut g = self.last.take().expect("one grounding was done");
        g.program = std::mem::take(&mut self.pending);
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

    /// Released externals become false for good in the solver (no assumption per call).
    fn release_in_solver(&mut self) {
        let Some(solver) = &mut self.solver else {
            return;
        };
        let released: Vec<AtomId> = self
            .externals
            .iter()
            .filter(|(_, v)| v.is_none())
            .map(|(&a, _)| a)
            .collect();
        for a in released {
            // An atom that is no longer free in the solver is complete already.
            let _ = solver.release_external(a);
            self.externals.remove(&a);
            self.released.insert(a);
        }
    }

    /// The literals assumed in every call: the values of the externals.
    fn external_assumptions(&self, out: &mut Vec<i32>) {
        for (&a, v) in &self.externals {
            match v {
                Some(TruthValue::True) => out.push(a as i32),
                Some(TruthValue::False) | None => out.push(-(a as i32)),
                Some(TruthValue::Free) => {}
            }
        }
        out.sort_unstable_by_key(|l| l.unsigned_abs());
    }

    /// Solves under the options' assumptions and the externals' values, calling `on_model`
    /// on every model as it is found (return false to stop). Solving twice without changes
    /// gives the same models; learnt clauses are kept between calls.
    pub fn solve(
        &mut self,
        options: &SolveOptions,
        mut on_model: impl FnMut(&Model<'_>) -> bool,
    ) -> Summary {
        self.prepare();
        let mut assumptions = Vec::new();
        self.external_assumptions(&mut assumptions);
        let mut impossible = false;
        for (s, positive) in &options.assumptions {
            match self.lookup(s) {
                Some(a) => assumptions.push(if *positive { a as i32 } else { -(a as i32) }),
                None if *positive => impossible = true,
                None => {}
            }
        }
        let Control {
            solver,
            syms,
            atom_sym,
            sym_atom,
            ..
        } = self;
        let solver = solver.as_mut().expect("prepared");
        if impossible {
            return Summary {
                outcome: solve::Outcome::Unsatisfiable,
                exhausted: true,
                optimum_proven: false,
                stop: None,
                stats: solve::Stats::default(),
                models: 0,
            };
        }
        let names = Names {
            syms,
            atom_sym,
            sym_atom,
        };
        let mut count = 0;
        let result = if solver.config_mut().threads >= 2 && assumptions.is_empty() {
            let mut r = solver.solve();
            for m in std::mem::take(&mut r.models) {
                count += 1;
                if !on_model(&Model {
                    raw: &m,
                    names: &names,
                }) {
                    break;
                }
            }
            r
        } else {
            solver.for_each_model(&assumptions, &mut |m| {
                count += 1;
                on_model(&Model {
                    raw: m,
                    names: &names,
                })
            })
        };
        Summary {
            outcome: result.outcome,
            exhausted: result.exhausted,
            optimum_proven: result.optimum_proven,
            stop: result.stop,
            stats: result.stats,
            models: count,
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

    /// With provenance on ([`ControlConfig::provenance`]): statement `id` of the origins in
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

fn external_value(v: ExternalValue) -> Option<TruthValue> {
    match v {
        ExternalValue::Free => Some(TruthValue::Free),
        ExternalValue::True => Some(TruthValue::True),
        ExternalValue::False => Some(TruthValue::False),
        ExternalValue::Release => None,
    }
}

/// Whether `s` names a grounder-made atom (`#projN(..)`): such atoms belong to their
/// grounding, so a later grounding's `#proj1(1)` is another atom than an earlier one's, and
/// they are neither looked up nor part of the context.
fn is_internal(syms: &Symbols, s: SymId) -> bool {
    match syms.get(s) {
        crate::ground::symbol::SymData::Fun { name, .. } => {
            syms.names.resolve(name).starts_with("#proj")
        }
        _ => false,
    }
}

/// Copies symbol `s` of table `from` into `to` (memoised by local id).
fn translate(from: &Symbols, s: SymId, to: &mut Symbols, memo: &mut [u32]) -> SymId {
    if memo[s.0 as usize] != u32::MAX {
        return SymId(memo[s.0 as usize]);
    }
    use crate::ground::symbol::SymData;
    let out = match from.get(s) {
        SymData::Inf => to.inf(),
        SymData::Sup => to.sup(),
        SymData::Num(n) => to.int(n),
        SymData::Str(x) => to.string(from.names.resolve(x)),
        SymData::Fun { name, neg, .. } => {
            let args: Vec<SymId> = from
                .args(s)
                .iter()
                .map(|&a| translate(from, a, to, memo))
                .collect();
            to.fun_str(from.names.resolve(name), neg, &args)
        }
    };
    memo[s.0 as usize] = out.0;
    out
}

/// The atom tables a model reads its symbols from.
struct Names<'a> {
    syms: &'a Symbols,
    atom_sym: &'a [Option<SymId>],
    sym_atom: &'a [AtomId],
}

/// One answer set, as the callback of [`Control::solve`] sees it.
pub struct Model<'a> {
    raw: &'a solve::Model,
    names: &'a Names<'a>,
}

impl Model<'_> {
    /// The model's number in its call (1-based).
    pub fn number(&self) -> usize {
        self.raw.number
    }

    /// The shown symbols (`#show`), in output order, without duplicates.
    pub fn symbols(&self) -> Vec<Symbol> {
        self.raw
            .symbols
            .iter()
            .filter_map(|s| Symbol::parse(s).ok())
            .collect()
    }

    /// Every true atom with a symbol: the whole answer set (shown or not), in atom order.
    pub fn atoms(&self) -> Vec<Symbol> {
        self.raw
            .atoms
            .iter()
            .filter_map(|&a| {
                let s = (*self.names.atom_sym.get(a as usize - 1)?)?;
                Some(Symbol::from_table(self.names.syms, s))
            })
            .collect()
    }

    /// Whether the atom of `symbol` is true.
    pub fn contains(&self, symbol: &Symbol) -> bool {
        let Some(id) = symbol.find_in(self.names.syms) else {
            return false;
        };
        match self.names.sym_atom.get(id.0 as usize) {
            Some(&a) if a != 0 => self.raw.holds(a),
            _ => false,
        }
    }

    /// Whether atom `atom` is true.
    pub fn holds(&self, atom: AtomId) -> bool {
        self.raw.holds(atom)
    }

    /// The costs, one per priority level, highest first (empty without optimization).
    pub fn costs(&self) -> &[i64] {
        &self.raw.costs
    }

    /// True when the model is known to be optimal.
    pub fn optimal(&self) -> bool {
        self.raw.optimal
    }

    /// The labels of the applied consistency-restoring rules.
    pub fn cr_applied(&self) -> Vec<Symbol> {
        self.raw
            .cr_applied
            .iter()
            .map(|l| Symbol::parse(l).unwrap_or_else(|_| Symbol::String(l.clone())))
            .collect()
    }

    /// For every true atom, the index of one rule of [`Control::program`] that supports it
    /// (`None` for externals and assumptions without a rule).
    pub fn supports(&self) -> impl Iterator<Item = (AtomId, Option<usize>)> + '_ {
        self.raw
            .atoms
            .iter()
            .copied()
            .zip(self.raw.support.iter().copied())
    }

    /// The solver's form of the model (true atoms as numbers, shown symbols as text).
    pub fn raw(&self) -> &solve::Model {
        self.raw
    }

    /// An owned copy, with the whole answer set as symbols.
    pub fn to_owned_model(&self) -> OwnedModel {
        let mut atoms = self.atoms();
        atoms.sort();
        OwnedModel {
            number: self.number(),
            shown: self.symbols(),
            atoms,
            costs: self.raw.costs.clone(),
            cr_applied: self.cr_applied(),
            optimal: self.raw.optimal,
            raw: self.raw.clone(),
        }
    }
}

/// A model kept after its solve call (see [`Control::solve_all`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OwnedModel {
    /// Its number in its call.
    pub number: usize,
    /// The shown symbols.
    pub shown: Vec<Symbol>,
    /// Every true atom with a symbol, in clingo's order.
    pub atoms: Vec<Symbol>,
    /// The costs, highest priority first.
    pub costs: Vec<i64>,
    /// The labels of the applied CR rules.
    pub cr_applied: Vec<Symbol>,
    /// True when known to be optimal.
    pub optimal: bool,
    /// The solver's form.
    pub raw: solve::Model,
}

impl OwnedModel {
    /// Whether `symbol` is a true atom.
    pub fn contains(&self, symbol: &Symbol) -> bool {
        self.atoms.binary_search(symbol).is_ok()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sym(s: &str) -> Symbol {
        Symbol::parse(s).unwrap()
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
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add("t", "{a; b}. c :- a. #show c/0. #show b/0.")
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
        let e = ctl.add("bad.lp", "p(1)\nq.").unwrap_err();
        assert!(e.diagnostics.has_errors());
        assert!(
            e.message.starts_with("bad.lp:2:1-2: error: syntax error"),
            "{}",
            e.message
        );
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add("unsafe.lp", "p(X) :- not q(X).").unwrap();
        let e = ctl.ground(&[Part::base()]).unwrap_err();
        assert!(e.message.contains("unsafe variables in"), "{}", e.message);
    }

    #[test]
    fn parts_are_grounded_on_demand_with_parameters() {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add(
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
        ctl.add("c", "q(X) ; X < 2 :- X = 1..3. r ; 3 < 1. s ; 1 < 3.")
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        assert_eq!(answers(&mut ctl), ["q(2) q(3) r"]);
    }

    #[test]
    fn externals_are_assigned_and_released() {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add("e", "#external e(1..2). p :- e(1). q :- e(2).")
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
}
