//! The order of predicate domains as clingo lists a model's atoms: clingo prints (and its API's
//! `Model.symbols` returns) the atoms of a model domain by domain, in the order gringo met the
//! predicates while preparing the statements for grounding, and within a domain in the order
//! its atoms were made. This module ranks the predicates of each rewritten program in that
//! order; the simplifier sorts the outputs by (rank, atom), so that a script printing a model
//! prints what it prints under clingo.
//!
//! The order, read off clingo 5.8 on small programs (the probes are in the tests of
//! `tests/control/model_order.rs`; gringo's source defines it through its rewriting, which
//! Lucent does not copy, so this is a description of what it does on the common forms):
//! - the statements other than facts, in program order; then the predicates of the facts
//!   whose arguments are values (`p(1,a).`), in program order, then those of the other
//!   ground facts (`p(-1).`, `p((1,2)).`, `p(1;2).`); a fact with an interval is a statement;
//! - in a rule: the atoms of the head elements that have a condition, and of every element of
//!   a head aggregate, of a bounded choice and of an unbounded one with several elements one
//!   of which has a condition (the condition's literals last to first, then the element's
//!   atom; in an unbounded choice with a single conditional element, the atom comes after the
//!   body), then the body: first its conditional literals last to first, each as
//!   its condition then its atom, then the other literals last to first (an aggregate as its
//!   elements' conditions in order), then the aggregates that assign a variable
//!   (`X = #count { ... }`), then the remaining head atoms;
//! - a weak constraint, `#show t : body`, an edge: the body last to first; a `#minimize`
//!   element: its condition last to first; `#external a : body`: the body, then `a`;
//!   `#heuristic a : body` and `#project a : body`: `a`, then the body.
//!
//! Invariant: a rank, once given to a predicate, never changes (multi-shot: later groundings
//! append); a predicate that no statement names keeps no rank (`u32::MAX`) and sorts last.

use super::*;

/// A predicate with no rank yet.
pub const UNRANKED: u32 = u32::MAX;

impl Rewriter<'_> {
    /// Notes the predicates of statement `st` in clingo's domain order (see the module
    /// documentation); plain facts are noted apart, ranked after the program's statements by
    /// [`Rewriter::rank_facts`].
    pub(super) fn note_domains(&mut self, index: u32, st: &ast::Statement) {
        match &st.kind {
            ast::StatementKind::Rule(r) => {
                if let Some(late) = plain_fact(r) {
                    if late {
                        self.out.late_facts.push(index);
                    }
                    if let ast::Head::Disjunction(e) = &r.head {
                        let a = match &e[0].literal.atom {
                            ast::Atom::Symbolic(a) => a,
                            _ => return,
                        };
                        for args in &a.args {
                            if let Some(p) = self.known_pred(a, args.len()) {
                                if late {
                                    self.late_facts.push(p);
                                } else {
                                    self.facts.push(p);
                                }
                            }
                        }
                    }
                    return;
                }
                let mut late: Vec<&ast::SymbolicAtom> = Vec::new();
                match &r.head {
                    ast::Head::Disjunction(elems) => {
                        for e in elems {
                            if e.condition.is_empty() {
                                late.push_literal(&e.literal);
                            } else {
                                self.note_literals_rev(&e.condition);
                                self.note_literal(&e.literal);
                            }
                        }
                    }
                    ast::Head::Choice(c)
                        if c.lower.is_some()
                            || c.upper.is_some()
                            || (c.elements.len() > 1
                                && c.elements.iter().any(|e| !e.condition.is_empty())) =>
                    {
                        // A bounded choice is a head aggregate for gringo; so is, for the
                        // order, an unbounded one with several elements, one conditional.
                        for e in &c.elements {
                            self.note_literals_rev(&e.condition);
                            self.note_literal(&e.literal);
                        }
                    }
                    ast::Head::Choice(c) => {
                        // No element, or one alone, has a condition.
                        for e in &c.elements {
                            self.note_literals_rev(&e.condition);
                            late.push_literal(&e.literal);
                        }
                    }
                    ast::Head::Aggregate(h) => {
                        for e in &h.elements {
                            self.note_literals_rev(&e.condition);
                            self.note_literal(&e.literal);
                        }
                    }
                    ast::Head::None | ast::Head::Theory(_) => {}
                }
                self.note_body(&r.body);
                for a in late {
                    self.note_atom(a);
                }
            }
            ast::StatementKind::WeakConstraint(w) => self.note_body(&w.body),
            ast::StatementKind::Optimize(o) => {
                for e in &o.elements {
                    self.note_literals_rev(&e.condition);
                }
            }
            ast::StatementKind::Show(s) => {
                if let ast::Show::Term { body, .. } = &**s {
                    self.note_body(body);
                }
            }
            ast::StatementKind::External(e) => {
                self.note_body(&e.body);
                self.note_atom(&e.atom);
            }
            ast::StatementKind::Heuristic(h) => {
                self.note_atom(&h.atom);
                self.note_body(&h.body);
            }
            ast::StatementKind::Project(p) => {
                if let ast::Project::Atom { atom, body } = &**p {
                    self.note_atom(atom);
                    self.note_body(body);
                }
            }
            ast::StatementKind::Edge(e) => self.note_body(&e.body),
            _ => {}
        }
    }

    /// Ranks the predicates of the plain facts noted so far, after every other predicate.
    pub(super) fn rank_facts(&mut self) {
        let facts = std::mem::take(&mut self.facts);
        let late = std::mem::take(&mut self.late_facts);
        for p in facts.into_iter().chain(late) {
            self.rank(p);
        }
    }

    fn note_body(&mut self, body: &[ast::BodyLiteral]) {
        for l in body.iter().rev() {
            if let ast::BodyLiteral::Conditional(c) = l {
                for l in &c.condition {
                    self.note_literal(l);
                }
                self.note_literal(&c.literal);
            }
        }
        for assignments in [false, true] {
            for l in body.iter().rev() {
                match l {
                    ast::BodyLiteral::Literal(l) if !assignments => self.note_literal(l),
                    ast::BodyLiteral::Aggregate { aggregate, .. }
                        if assigns(aggregate) == assignments =>
                    {
                        for e in &aggregate.elements {
                            for l in &e.condition {
                                self.note_literal(l);
                            }
                        }
                        for c in &aggregate.set_syntax {
                            self.note_literal(&c.literal);
                            for l in &c.condition {
                                self.note_literal(l);
                            }
                        }
                    }
                    _ => {}
                }
            }
        }
    }

    fn note_literals_rev(&mut self, lits: &[ast::Literal]) {
        for l in lits.iter().rev() {
            self.note_literal(l);
        }
    }

    fn note_literal(&mut self, l: &ast::Literal) {
        if let ast::Atom::Symbolic(a) = &l.atom {
            self.note_atom(a);
        }
    }

    fn note_atom(&mut self, a: &ast::SymbolicAtom) {
        for args in &a.args {
            if let Some(p) = self.known_pred(a, args.len()) {
                self.rank(p);
            }
        }
    }

    /// The id of `a`'s predicate with `arity` arguments, when the rewriting made one.
    fn known_pred(&mut self, a: &ast::SymbolicAtom, arity: usize) -> Option<PredId> {
        let name = self.name_id(&a.name);
        self.find_pred(name, arity as u32, a.negated)
    }

    /// Gives predicate `p` the next rank unless it has one.
    fn rank(&mut self, p: PredId) {
        let ranks = &mut self.out.domain_rank;
        if ranks.len() <= p as usize {
            ranks.resize(p as usize + 1, UNRANKED);
        }
        if ranks[p as usize] == UNRANKED {
            ranks[p as usize] = self.out.domains_ranked;
            self.out.domains_ranked += 1;
        }
    }
}

/// Whether an aggregate assigns a variable (`X = #count { ... }`).
fn assigns(a: &ast::BodyAggregate) -> bool {
    [&a.lower, &a.upper]
        .into_iter()
        .flatten()
        .any(|g| g.op == ast::CmpOp::Eq && matches!(g.term.kind, TermKind::Variable(_)))
}

/// Whether rule `r` is a fact gringo keeps apart from the other statements (an atom alone over
/// ground terms): `Some(late)`, `late` when an argument is not a value but an operation, a
/// tuple or a pool (`p(-1).`, `p((1,2)).`, `p(1;2).`), whose predicates gringo meets after
/// the other facts'. A fact with an interval or a variable is no such fact.
fn plain_fact(r: &ast::Rule) -> Option<bool> {
    if !r.body.is_empty() || !matches!(r.kind, ast::RuleKind::Normal) {
        return None;
    }
    let ast::Head::Disjunction(elems) = &r.head else {
        return None;
    };
    let [e] = elems.as_slice() else {
        return None;
    };
    if e.has_colon || e.literal.sign != Sign::Positive {
        return None;
    }
    let ast::Atom::Symbolic(a) = &e.literal.atom else {
        return None;
    };
    let mut late = a.args.len() > 1;
    for t in a.args.iter().flatten() {
        late |= !value(t)?;
    }
    Some(late)
}

/// Whether ground term `t` is a value as written (a number, string or constant, or a
/// function of values); `None` when it is not ground (a variable, an interval, a call). A
/// tuple, an operation or a pool is ground but no value.
fn value(t: &ast::Term) -> Option<bool> {
    Some(match &t.kind {
        TermKind::Integer(_) | TermKind::String(_) | TermKind::Constant(_) => true,
        TermKind::Infimum | TermKind::Supremum => true,
        TermKind::Function { name, args, .. } => {
            let mut all = !name.is_empty() && args.len() <= 1;
            for t in args.iter().flatten() {
                all &= value(t)?;
            }
            all
        }
        TermKind::Unary { arg, .. } => {
            value(arg)?;
            false
        }
        TermKind::Binary { lhs, rhs, .. } => {
            value(lhs)?;
            value(rhs)?;
            false
        }
        TermKind::Paren(t) => {
            value(t)?;
            false
        }
        TermKind::Pool(ts) => {
            for t in ts {
                value(t)?;
            }
            false
        }
        TermKind::Variable(_)
        | TermKind::Anonymous
        | TermKind::Interval { .. }
        | TermKind::ScriptCall { .. } => return None,
    })
}

/// Head atoms kept for after the body.
trait Late<'t> {
    fn push_literal(&mut self, l: &'t ast::Literal);
}

impl<'t> Late<'t> for Vec<&'t ast::SymbolicAtom> {
    fn push_literal(&mut self, l: &'t ast::Literal) {
        if let ast::Atom::Symbolic(a) = &l.atom {
            self.push(a);
        }
    }
}
