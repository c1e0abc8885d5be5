//! Grounding: from a parsed program to a ground program (issue 3), and the ground program's
//! exchange format, aspif.
//!
//! Invariant: the ground program is the only thing the solver sees, and it round-trips through
//! aspif (`program` is the in-memory form, `aspif` reads and writes it), so our grounder can be
//! checked by clasp and our solver can be fed by gringo.
//!
//! Pipeline: `rewrite` (constants, pools, intervals, safety, body order) ->
//! `instantiate` (components in dependency order, semi-naive joins) -> `simplify`
//! (propagate false atoms and facts, number atoms, build outputs). [`text`] prints the result as
//! `gringo --text` does; [`mod@reference`] is the naive grounder the tests compare against.

pub mod program;
pub mod aspif;
pub(crate) mod symbol;
pub(crate) mod term;
pub mod include;
pub(crate) mod rewrite;
pub(crate) mod sparc;
pub(crate) mod instantiate;
pub(crate) mod simplify;
pub(crate) mod incremental;
pub mod text;
pub mod reference;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span};
use crate::syntax::ast;

pub(crate) use instantiate::Calls;
pub use instantiate::{Limits, StopReason};
pub use program::GroundProgram;

/// How to ground.
#[derive(Clone, Debug, Default)]
pub struct GroundConfig {
    /// `-c name=value` definitions (they override `#const` definitions without `[override]`).
    pub consts: Vec<(String, ast::Term)>,
    /// Stop with a diagnostic when ground rules plus atoms exceed this number.
    pub max_size: Option<usize>,
    /// Stop with a diagnostic after this instant (checked every few thousand rules).
    pub deadline: Option<std::time::Instant>,
    /// Record the provenance of every ground rule and atom in `GroundProgram::provenance`.
    pub provenance: bool,
    /// Diagnostics limit (gringo's default is 20).
    pub message_limit: Option<usize>,
}

/// The result of grounding.
#[derive(Debug)]
pub struct Grounding {
    /// The ground program (empty when errors stopped grounding).
    pub program: GroundProgram,
    /// Errors and warnings.
    pub diagnostics: Diagnostics,
    /// Symbol of each aspif atom (`atom_syms[a - 1]`), `None` for auxiliary atoms: ids into
    /// `symbols`. Their text is rendered only on demand ([`Grounding::atom_name`]): a library
    /// client reading symbols never pays for strings.
    pub atom_syms: Vec<Option<symbol::SymId>>,
    /// Symbol of every atom known to be true (facts), including those simplified away from
    /// bodies, ids into `symbols` ([`Grounding::facts`] renders them).
    pub fact_syms: Vec<symbol::SymId>,
    /// Span of each source statement, by statement index (what `RuleOrigin` statement ids
    /// index).
    pub statement_spans: Vec<Span>,
    /// The symbol table: provenance bindings are (variable name, symbol) ids into it, atom
    /// records' symbols are symbol ids.
    pub symbols: symbol::Symbols,
    /// Why grounding stopped early, if it did.
    pub stopped: Option<StopReason>,
}

impl Grounding {
    /// The printed name of aspif atom `a`, `None` for an auxiliary atom (or one out of range).
    pub fn atom_name(&self, a: program::Atom) -> Option<String> {
        let s = (*self.atom_syms.get((a as usize).checked_sub(1)?)?)?;
        Some(self.symbols.show(s))
    }

    /// The printed name of every aspif atom (`[a - 1]`), `None` for auxiliary atoms.
    pub fn atom_names(&self) -> Vec<Option<String>> {
        self.atom_syms
            .iter()
            .map(|s| s.map(|s| self.symbols.show(s)))
            .collect()
    }

    /// The text of every atom known to be true (facts), including those simplified away from
    /// bodies.
    pub fn facts(&self) -> Vec<String> {
        self.fact_syms
            .iter()
            .map(|&s| self.symbols.show(s))
            .collect()
    }

    /// `X=1,Y=a` for bindings (an origin's).
    pub fn bindings_text(&self, bindings: &[(u32, u32)]) -> String {
        bindings
            .iter()
            .map(|&(v, s)| {
                format!(
                    "{}={}",
                    self.symbols.names.resolve(crate::base::intern::Sym(v)),
                    self.symbols.show(symbol::SymId(s))
                )
            })
            .collect::<Vec<_>>()
            .join(",")
    }

    /// A grounder atom as text (provenance on): its symbol, else `#aux(N)` with its aspif
    /// number, else `#aux`.
    pub fn atom_text(&self, g: program::GAtom) -> String {
        match self.program.provenance.atom(g) {
            Some(program::AtomRecord { sym: Some(s), .. }) => self.symbols.show(symbol::SymId(*s)),
            Some(r) if r.aspif != 0 => format!("#aux({})", r.aspif),
            _ => "#aux".to_string(),
        }
    }

    /// A removed body literal as text: `p(1)` or `not q(2)`.
    pub fn removed_text(&self, l: &program::RemovedLit) -> String {
        let a = self.atom_text(l.atom);
        if l.positive {
            a
        } else {
            format!("not {a}")
        }
    }

    /// The grounder atom of a symbol written as text (`p(1,"a")`), if the grounder made it
    /// (provenance on).
    pub fn find_atom(&self, text: &str) -> Option<program::GAtom> {
        self.program
            .provenance
            .atoms
            .iter()
            .position(|r| {
                r.sym
                    .is_some_and(|s| self.symbols.show(symbol::SymId(s)) == text)
            })
            .map(|i| i as program::GAtom + 1)
    }
}

/// Grounds `program`. `sources`, when given, supplies the text shown in diagnostics. One
/// grounding pipeline: this is a multi-shot `incremental::Session` used once.
///
/// ```
/// use lucent::base::SourceMap;
/// use lucent::ground::{self, GroundConfig};
/// use lucent::syntax::{self, ast::Dialect};
/// let mut sources = SourceMap::new();
/// let text = "p(1..3). q(X) :- p(X), X > 1. {r(X)} :- q(X).";
/// let file = sources.add("t.lp", text);
/// let parsed = syntax::parse(file, text, Dialect::Clingo);
/// let g = ground::ground(&parsed.program, Some(&sources), &GroundConfig::default());
/// assert!(!g.diagnostics.has_errors());
/// // p(1..3) and q(2), q(3) are facts; r(2), r(3) are the choice's two atoms.
/// assert_eq!(g.program.rules.len(), 5 + 2);
/// ```
pub fn ground(
    program: &ast::Program,
    sources: Option<&SourceMap>,
    config: &GroundConfig,
) -> Grounding {
    incremental::Session::new().ground_part(
        program,
        sources,
        config,
        symbol::Symbols::new(),
        false,
        None,
    )
}

/// The [`Grounding`] of a finished instantiation, one-shot or incremental: the limit error added
/// when it `stopped`, and no program nor atom names when any error was reported.
fn finished(
    fin: simplify::Finished,
    mut diags: Diagnostics,
    statement_spans: Vec<Span>,
    symbols: symbol::Symbols,
    stopped: Option<StopReason>,
) -> Grounding {
    if let Some(reason) = stopped.filter(|&r| r != StopReason::Error) {
        diags.push(stopped_error(reason, &statement_spans));
    }
    let error = diags.has_errors();
    Grounding {
        program: if error {
            GroundProgram::new()
        } else {
            fin.program
        },
        diagnostics: diags,
        atom_syms: if error { Vec::new() } else { fin.atom_syms },
        fact_syms: fin.fact_syms,
        statement_spans,
        symbols,
        stopped,
    }
}

/// The error of a grounding that stopped early (size or time limit), placed at the program's
/// first statement; one-shot and incremental grounding report it the same way.
fn stopped_error(reason: StopReason, statement_spans: &[Span]) -> Diagnostic {
    let span = statement_spans.first().copied().unwrap_or_default();
    Diagnostic::error(
        span,
        match reason {
            StopReason::SizeLimit => {
                "grounding stopped: the size limit on ground rules and atoms was exceeded"
            }
            StopReason::Deadline => "grounding stopped: the time limit was reached",
            StopReason::Error => "grounding stopped: an error was reported",
        },
    )
}
