//! Grounding: from a parsed program to a ground program (issue 3), and the ground program's
//! exchange format, aspif.
//!
//! Invariant: the ground program is the only thing the solver sees, and it round-trips through
//! aspif (`program` is the in-memory form, `aspif` reads and writes it), so our grounder can be
//! checked by clasp and our solver can be fed by gringo.
//!
//! Pipeline: [`rewrite`] (constants, pools, intervals, safety, body order) ->
//! [`instantiate`] (components in dependency order, semi-naive joins) -> [`simplify`]
//! (propagate false atoms and facts, number atoms, build outputs). [`text`] prints the result as
//! `gringo --text` does; [`reference`] is the naive grounder the tests compare against.

pub mod program;
pub mod aspif;
pub mod symbol;
pub mod term;
pub mod include;
pub mod rewrite;
pub mod sparc;
pub mod instantiate;
pub mod simplify;
pub mod text;
pub mod reference;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span};
use crate::syntax::ast;

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
    /// Record the origin of every ground rule in `GroundProgram::origins`.
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
    /// Printed name of each aspif atom (`atom_names[a - 1]`), `None` for auxiliary atoms.
    pub atom_names: Vec<Option<String>>,
    /// Every atom known to be true (facts), including those simplified away from bodies.
    pub facts: Vec<String>,
    /// Symbol of each aspif atom (`atom_syms[a - 1]`, parallel to `atom_names`), `None` for
    /// auxiliary atoms: ids into `symbols`.
    pub atom_syms: Vec<Option<symbol::SymId>>,
    /// Symbol of every fact atom (parallel to `facts`), ids into `symbols`.
    pub fact_syms: Vec<symbol::SymId>,
    /// Span of each source statement, by statement index (what `Origin::rule` indexes).
    pub statement_spans: Vec<Span>,
    /// The symbol table: `Origin::bindings` are (variable name, symbol) ids into it.
    pub symbols: symbol::Symbols,
    /// Why grounding stopped early, if it did.
    pub stopped: Option<StopReason>,
}

impl Grounding {
    /// `X=1,Y=a` for an origin's bindings.
    pub fn bindings_text(&self, origin: &program::Origin) -> String {
        origin
            .bindings
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
}

/// Grounds `program`. `sources`, when given, supplies the text shown in diagnostics.
pub fn ground(
    program: &ast::Program,
    sources: Option<&SourceMap>,
    config: &GroundConfig,
) -> Grounding {
    let mut diags = Diagnostics::new(config.message_limit.unwrap_or(20));
    let mut syms = symbol::Symbols::new();
    let compiled = {
        let mut rw = rewrite::Rewriter::new(&mut syms, &mut diags, sources);
        rw.program(program, &config.consts);
        rw.out
    };
    let statement_spans = compiled.stmt_spans.clone();
    if diags.has_errors() {
        return Grounding {
            program: GroundProgram::new(),
            diagnostics: diags,
            atom_names: Vec::new(),
            facts: Vec::new(),
            atom_syms: Vec::new(),
            fact_syms: Vec::new(),
            statement_spans,
            symbols: syms,
            stopped: None,
        };
    }
    let limits = Limits {
        max_size: config.max_size,
        deadline: config.deadline,
    };
    let npreds = compiled.preds.len();
    let mut g =
        instantiate::Grounder::new(syms, npreds, &mut diags, sources, config.provenance, limits);
    g.run(&compiled);
    g.release_dedup();
    let stopped = g.stopped;
    let fin = simplify::finish(&mut g, &compiled);
    let syms = std::mem::take(&mut g.syms);
    drop(g);
    if let Some(reason) = stopped {
        let span = statement_spans.first().copied().unwrap_or_default();
        diags.push(Diagnostic::error(
            span,
            match reason {
                StopReason::SizeLimit => {
                    "grounding stopped: the size limit on ground rules and atoms was exceeded"
                }
                StopReason::Deadline => "grounding stopped: the time limit was reached",
            },
        ));
    }
    let error = diags.has_errors();
    Grounding {
        program: if error {
            GroundProgram::new()
        } else {
            fin.program
        },
        diagnostics: diags,
        atom_names: if error { Vec::new() } else { fin.names },
        facts: fin.facts,
        atom_syms: if error { Vec::new() } else { fin.atom_syms },
        fact_syms: fin.fact_syms,
        statement_spans,
        symbols: syms,
        stopped,
    }
}
