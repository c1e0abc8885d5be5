//! Theory atoms (`#theory`, `&name{...}`) rewritten for the instantiator: the definitions of
//! the program are collected first (they may follow their uses), then each theory atom is
//! checked against its definition and becomes a guard-less aggregate ([`NAgg`]) marked by a
//! [`NTheory`]: its elements are grounded like aggregate elements (conditions over the
//! element's local variables), and the instantiator makes one atom per distinct ground theory
//! atom (`instantiate::theory`).
//!
//! Theory terms become ordinary terms: an operator term is a function named by its operator,
//! sets are functions named `{}`, lists `[]`, tuples keep the empty name. No identifier has
//! such a name, so ground theory terms are symbols and compare as the terms they denote.
//!
//! Invariants: a theory atom whose name is not defined with its arity, used where its
//! definition forbids (head, body, directive), with a guard its definition does not allow, or
//! with an operator its term definition lacks, is reported with clingo's wording and its
//! statement dropped. The name's arguments and the guard's variables are global (the body
//! must bind them): they are carried as `!=` guards of the aggregate, which only the safety
//! planning reads.

use hashbrown::HashMap;

use super::*;
use crate::syntax::ast::{TheoryAtomKind, TheoryTermKind};
use crate::syntax::theory::{resolve, OpTable};

/// The theory atom of an aggregate that stands for one.
#[derive(Clone, Debug)]
pub struct NTheory {
    /// The atom's name term (its arguments evaluated as ordinary terms).
    pub name: NTerm,
    /// The guard: operator and term.
    pub guard: Option<(Sym, NTerm)>,
    /// A head occurrence (or a directive): the atom is the rule's head, not a body literal.
    pub head: bool,
    /// A directive: no atom, only the theory data.
    pub directive: bool,
}

/// One atom definition, with its term definitions' operator tables.
#[derive(Clone, Debug)]
struct AtomDef {
    elements: Option<OpTable>,
    guard: Option<(Vec<String>, Option<OpTable>)>,
    kind: TheoryAtomKind,
}

/// The theory definitions in force.
#[derive(Clone, Debug, Default)]
pub struct Theories {
    /// Theory names with the span of their definition.
    names: HashMap<String, Span>,
    /// Atom definitions by name and arity.
    atoms: HashMap<(String, u32), AtomDef>,
}

impl Theories {
    /// Records `def` (written at `span`); a second theory of the same name is clingo's
    /// `redefinition of theory` error.
    pub fn add(&mut self, def: &ast::TheoryDef, span: Span, diags: &mut Diagnostics) {
        if let Some(&first) = self.names.get(&def.name) {
            diags.push(
                Diagnostic::error(span, "redefinition of theory")
                    .with_snippet(def.name.clone())
                    .with_note(Some(first), "theory first defined here"),
            );
            return;
        }
        self.names.insert(def.name.clone(), span);
        let tables: HashMap<&str, OpTable> = def
            .terms
            .iter()
            .map(|t| (t.name.as_str(), OpTable::new(t)))
            .collect();
        for a in &def.atoms {
            let d = AtomDef {
                elements: tables.get(a.elements.as_str()).cloned(),
                guard: a
                    .guard
                    .as_ref()
                    .map(|(ops, t)| (ops.clone(), tables.get(t.as_str()).cloned())),
                kind: a.kind,
            };
            self.atoms.insert((a.name.clone(), a.arity), d);
        }
    }
}

/// Where a theory atom was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Position {
    /// A rule head with a body (or a fact of a head atom).
    Head,
    /// A rule body.
    Body,
    /// A statement of its own: a fact-like head without body.
    Alone,
}

impl Rewriter<'_> {
    /// Collects the theory definitions of `program`.
    pub(super) fn theory_definitions(&mut self, program: &ast::Program) {
        for st in &program.statements {
            if let ast::StatementKind::Theory(def) = &st.kind {
                let mut theories = std::mem::take(&mut self.theories);
                theories.add(def, st.span, self.diags);
                self.theories = theories;
            }
        }
    }

    fn theory_error(&mut self, span: Span, msg: &str, detail: String) {
        self.diags
            .push(Diagnostic::error(span, msg.to_string()).with_snippet(detail));
    }

    /// Lowers theory atom `a` written at `pos`; `None` after reporting an error.
    pub(super) fn theory_atom(
        &mut self,
        sign: Sign,
        a: &ast::TheoryAtom,
        pos: Position,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NLit> {
        let name = a.name.name.as_str().to_string();
        let arity = a.name.args.first().map_or(0, |l| l.len()) as u32;
        let sig = format!("{name}/{arity}");
        let Some(def) = self.theories.atoms.get(&(name, arity)).cloned() else {
            self.theory_error(a.span, "no definition found for theory atom", sig);
            return None;
        };
        // clingo's wording, whose "head"/"body" name the position the definition allows.
        let misuse = match (def.kind, pos) {
            (TheoryAtomKind::Head, Position::Body) => Some("theory body atom used in head"),
            (TheoryAtomKind::Body, Position::Head | Position::Alone) => {
                Some("theory head atom used in body")
            }
            (TheoryAtomKind::Directive, Position::Body) => Some("theory directive used in body"),
            (TheoryAtomKind::Directive, Position::Head) => Some("theory directive used with body"),
            _ => None,
        };
        if let Some(msg) = misuse {
            self.theory_error(a.span, msg, sig);
            return None;
        }
        if sign == Sign::NotNot {
            self.unsupported(a.span, "a doubly negated theory atom");
            return None;
        }
        // The name as an ordinary term.
        let name_term = atom_as_term(&a.name);
        let name = self.term(&name_term, vars, extra)?;
        let guard = match (&a.guard, &def.guard) {
            (None, _) => None,
            (Some((op, _)), None) => {
                self.theory_error(a.span, "unexpected guard", sig);
                let _ = op;
                return None;
            }
            (Some((op, t)), Some((ops, table))) => {
                if !ops.contains(op) {
                    let d = Diagnostic::error(a.span, "unexpected operator")
                        .with_snippet(op.clone())
                        .with_note(
                            Some(a.span),
                            format!("expected one of:\n  {}", ops.join(" ")),
                        );
                    self.diags.push(d);
                    return None;
                }
                let t = self.theory_term(t, table.as_ref(), a.span, vars)?;
                let op = self.syms.names.intern(op);
                Some((op, t))
            }
        };
        let mut elems = Vec::new();
        for e in &a.elements {
            let mut terms = Vec::new();
            for t in &e.terms {
                terms.push(self.theory_term(t, def.elements.as_ref(), a.span, vars)?);
            }
            let mut cond = Vec::new();
            self.condition(&e.condition, vars, &mut cond)?;
            elems.push(NElem {
                terms,
                cond,
                lit: None,
            });
        }
        // The name and the guard must be bound by the body: `!=` guards (see the module doc).
        let mut guards = vec![(CmpOp::Ne, name.clone())];
        if let Some((_, t)) = &guard {
            guards.push((CmpOp::Ne, t.clone()));
        }
        Some(NLit::Agg(Box::new(NAgg {
            sign,
            func: AggregateFunction::Count,
            guards,
            binder: None,
            elems,
            theory: Some(Box::new(NTheory {
                name,
                guard,
                head: pos != Position::Body,
                directive: def.kind == TheoryAtomKind::Directive,
            })),
        })))
    }

    /// A theory term as an ordinary term (see the module doc), its operators resolved by
    /// `table`.
    fn theory_term(
        &mut self,
        t: &ast::TheoryTerm,
        table: Option<&OpTable>,
        at: Span,
        vars: &mut Vars,
    ) -> Option<NTerm> {
        let empty = OpTable::default();
        let resolved = match resolve(t, table.unwrap_or(&empty)) {
            Ok(r) => r,
            Err(op) => {
                self.theory_error(at, "missing definition for operator", op);
                return None;
            }
        };
        self.lower_theory_term(&resolved, vars)
    }

    fn lower_theory_term(&mut self, t: &ast::TheoryTerm, vars: &mut Vars) -> Option<NTerm> {
        let (name, args) = match &t.kind {
            TheoryTermKind::Symbol(s) => {
                let mut extra = Vec::new();
                return self.term(s, vars, &mut extra);
            }
            TheoryTermKind::Function { name, args } => (name.as_str(), args),
            TheoryTermKind::Tuple(ts) => ("", ts),
            TheoryTermKind::Set(ts) => ("{}", ts),
            TheoryTermKind::List(ts) => ("[]", ts),
            TheoryTermKind::Unparsed(_) => return None,
        };
        let mut nargs = Vec::with_capacity(args.len());
        for a in args {
            nargs.push(self.lower_theory_term(a, vars)?);
        }
        let name = self.syms.names.intern(name);
        Some(if let Some(ground) = ground_args(&nargs) {
            NTerm::Sym(self.syms.fun(name, false, &ground))
        } else {
            NTerm::Fun {
                name,
                neg: false,
                args: nargs,
            }
        })
    }
}

/// The symbols of `args` when all are ground.
fn ground_args(args: &[NTerm]) -> Option<Vec<SymId>> {
    args.iter()
        .map(|a| match a {
            NTerm::Sym(s) => Some(*s),
            _ => None,
        })
        .collect()
}
