//! Multi-shot grounding (gringo's incremental grounding): a [`Session`] keeps what one grounding
//! leaves for the next (the predicate table, the grounder's atoms, their predicate domains with
//! their indexes, and which atoms earlier groundings numbered or found true), so that grounding
//! a later program part joins its statements against the existing domains and costs what the
//! part adds, not what was grounded before.
//!
//! Invariants:
//! - [`super::ground`] is a session used once (one grounding pipeline); the first grounding of
//!   a session is exactly its grounding (same atoms, numbering, output); each later one numbers
//!   only the atoms that occur in its own output, from 1, and [`Session::last_gatoms`] maps
//!   those numbers to the session's grounder atoms, which never change.
//! - An atom an earlier grounding numbered is *frozen*: it stays in its domain, is possible or
//!   a fact, and later groundings never make it false (`simplify::finish_after`).
//! - Grounder-made `#projN` predicates are numbered across the session (a later part's
//!   `#proj1` is another predicate than an earlier one's).
//! - A grounding that fails in rewriting leaves the session as it was; one that stops during
//!   instantiation (size or time limit, unsupported construct) spends it: later groundings
//!   report an error.

use crate::base::{Diagnostic, Diagnostics, SourceMap};
use crate::syntax::ast;

use super::instantiate::{self, Calls, GroundAtom, Grounder, Limits};
use super::program::Output;
use super::rewrite::{self, Pred};
use super::simplify::{self, KNOWN_FACT, NUMBERED};
use super::symbol::Symbols;
use super::{GroundConfig, GroundProgram, Grounding};

/// Symbols reserved per statement before a session's first grounding.
const SYMBOLS_PER_STATEMENT: usize = 8;
/// Ground rules (and atoms) reserved per rewritten statement before a session's first
/// grounding.
const RULES_PER_STATEMENT: usize = 4;

/// The grounder's state across the groundings of one multi-shot program.
#[derive(Default)]
pub struct Session {
    /// The rewriter's predicate table (predicates keep their ids).
    preds: Vec<Pred>,
    /// Projection predicates made so far.
    projections: u32,
    /// The predicates' ranks in clingo's order of domains, and how many are ranked
    /// ([`rewrite::Compiled::domain_rank`]).
    ranks: Vec<u32>,
    ranked: u32,
    /// Atoms and domains.
    state: instantiate::State,
    /// Per grounder atom `a` at `flags[a]`: [`NUMBERED`], [`KNOWN_FACT`].
    flags: Vec<u8>,
    /// `prefer(l1, l2)` facts so far.
    prefer: Vec<GroundAtom>,
    /// The grounder atom of each aspif atom of the last grounding (`[a - 1]`).
    last_gatoms: Vec<GroundAtom>,
    /// The simplification's arrays over every atom, kept between groundings.
    scratch: simplify::Scratch,
    /// Set when a grounding stopped half-way: the state is no longer consistent.
    spent: bool,
    /// Groundings done.
    groundings: usize,
}

impl Session {
    /// A session with nothing grounded.
    pub fn new() -> Session {
        Session::default()
    }

    /// The session's grounder atom of aspif atom `a` of the last grounding.
    pub fn last_gatoms(&self) -> &[GroundAtom] {
        &self.last_gatoms
    }

    /// Where clingo lists grounder atom `a` in a model ([`Output::atom_order`]: its predicate's
    /// domain rank, then the atom); [`Output::LAST`] for an auxiliary atom.
    pub fn atom_order(&self, a: GroundAtom) -> u64 {
        match self.state.pred(a) {
            Some(p) => {
                let rank = self
                    .ranks
                    .get(p as usize)
                    .copied()
                    .unwrap_or(rewrite::UNRANKED);
                Output::atom_order(rank, a.get())
            }
            None => Output::LAST,
        }
    }

    /// Grounder atom `a` is no fact: its rules did not reach the program (the caller dropped
    /// them as a redefinition).
    pub fn forget_fact(&mut self, a: GroundAtom) {
        if let Some(f) = self.flags.get_mut(a.get() as usize) {
            *f &= !KNOWN_FACT;
        }
        self.state.clear_fact(a);
    }

    /// Grounds `program` on top of the earlier groundings, over `syms`, the table they used
    /// (it comes back in [`Grounding::symbols`]). Rules, outputs, externals and provenance of
    /// the result are this grounding's only; statement ids count its own statements.
    /// `calls`, when given, evaluates the external function calls `@f(...)` (without it they
    /// are reported).
    pub fn ground(
        &mut self,
        program: &ast::Program,
        sources: Option<&SourceMap>,
        config: &GroundConfig,
        syms: Symbols,
        calls: Option<&mut dyn Calls>,
    ) -> Grounding {
        self.ground_part(program, sources, config, syms, true, calls)
    }

    /// [`Session::ground`]; `carry`: keep what a later grounding needs (the frozen and fact
    /// atoms, the domains, the predicate table). A session used once ([`super::ground`])
    /// leaves it, and its reserves, out: it does exactly the one-shot grounding's work.
    pub(super) fn ground_part(
        &mut self,
        program: &ast::Program,
        sources: Option<&SourceMap>,
        config: &GroundConfig,
        mut syms: Symbols,
        carry: bool,
        mut calls: Option<&mut dyn Calls>,
    ) -> Grounding {
        let mut diags = Diagnostics::new(config.message_limit.unwrap_or(20));
        let empty = |diags, syms, statement_spans| Grounding {
            program: GroundProgram::new(),
            diagnostics: diags,
            atom_syms: Vec::new(),
            fact_syms: Vec::new(),
            statement_spans,
            symbols: syms,
            stopped: None,
        };
        if self.spent {
            let span = program
                .statements
                .first()
                .map(|s| s.span)
                .unwrap_or_default();
            diags.push(Diagnostic::error(
                span,
                "grounding cannot continue: an earlier grounding of this program stopped",
            ));
            return empty(diags, syms, Vec::new());
        }
        if carry && self.groundings == 0 {
            // A first grounding makes a few symbols per statement at least (atoms, their
            // arguments): reserved at once instead of rehashing the table from empty.
            syms.reserve(SYMBOLS_PER_STATEMENT * program.statements.len());
        }
        let (compiled, projections) = {
            let mut rw = rewrite::Rewriter::new(&mut syms, &mut diags, sources);
            rw.resume(
                self.preds.clone(),
                self.projections,
                self.ranks.clone(),
                self.ranked,
            );
            rw.calls = calls.is_some();
            if let Some(c) = calls.as_mut() {
                rw.host = Some(&mut **c);
            }
            rw.program(program, &config.consts);
            let p = rw.projections();
            (rw.out, p)
        };
        let statement_spans = compiled.stmt_spans.clone();
        if diags.has_errors() {
            return empty(diags, syms, statement_spans);
        }
        let limits = Limits {
            max_size: config.max_size,
            deadline: config.deadline,
        };
        let state = std::mem::take(&mut self.state);
        let mut g = Grounder::resume(
            state,
            syms,
            compiled.preds.len(),
            &mut diags,
            sources,
            config.provenance,
            limits,
        );
        if carry && self.groundings == 0 {
            g.reserve(RULES_PER_STATEMENT * compiled.stmts.len());
        }
        if let Some(calls) = calls {
            g.set_calls(calls);
        }
        g.run(&compiled);
        g.release_dedup();
        let stopped = g.stopped;
        let mut fin = simplify::finish_after(
            &mut g,
            &compiled,
            &self.flags,
            &self.prefer,
            &mut self.scratch,
        );
        if carry {
            self.carry(&mut g, &fin);
        }
        let syms = std::mem::take(&mut g.syms);
        drop(g);
        if carry {
            self.preds = compiled.preds;
            self.projections = projections;
            self.ranks = compiled.domain_rank;
            self.ranked = compiled.domains_ranked;
        } else {
            // Nothing was kept for a later grounding.
            self.spent = true;
        }
        self.groundings += 1;
        let gatoms = std::mem::take(&mut fin.atom_gatoms);
        let grounding = super::finished(fin, diags, statement_spans, syms, stopped);
        if grounding.diagnostics.has_errors() {
            self.spent = true;
            self.last_gatoms = Vec::new();
        } else {
            self.last_gatoms = gatoms;
        }
        grounding
    }

    /// What the next grounding starts from: the atoms the grounding `fin` of `g` numbered are
    /// frozen (and in their domains, as the one-shot context of facts and externals had them),
    /// its facts are facts for good; the atoms and domains move into the session.
    fn carry(&mut self, g: &mut Grounder<'_>, fin: &simplify::Finished) {
        self.flags.resize(g.atoms.len() + 1, 0);
        for &a in &fin.atom_gatoms {
            self.flags[a.get() as usize] |= NUMBERED;
            g.put_in_domain(a);
        }
        for &a in &fin.fact_atoms {
            self.flags[a.get() as usize] |= KNOWN_FACT;
            g.set_fact(a);
        }
        self.prefer.extend_from_slice(&fin.prefer_atoms);
        self.state = g.suspend();
    }
}
