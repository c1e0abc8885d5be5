//! A walk over every span of a syntax tree, and the shape comparison built on it.
//!
//! Role: [`for_each_span`] visits each [`Span`] stored in a [`Program`]; [`erase_spans`] and
//! [`Program::same_shape`] use it to compare trees while ignoring positions (the printer's round
//! trip), and the fuzzing checks use it to validate positions.
//!
//! Invariant: every `Span` field of every node type in `ast.rs` is visited; a node type added to
//! the tree must be added here too (the round-trip tests fail otherwise, because spans of an
//! unvisited node would differ between the parse of a text and the parse of its printed form).

use crate::base::Span;

use super::ast::*;

impl Program {
    /// True when both trees are equal once spans are ignored.
    pub fn same_shape(&self, other: &Program) -> bool {
        let mut a = self.clone();
        let mut b = other.clone();
        erase_spans(&mut a);
        erase_spans(&mut b);
        a == b
    }
}

/// Sets every span of the tree to the default span.
pub fn erase_spans(program: &mut Program) {
    for_each_span(program, &mut |s| *s = Span::default());
}

/// Calls `f` on every span of the tree.
pub fn for_each_span(program: &mut Program, f: &mut dyn FnMut(&mut Span)) {
    for st in &mut program.statements {
        f(&mut st.span);
        statement(&mut st.kind, f);
    }
}

/// Spans of a statement.
fn statement(kind: &mut StatementKind, f: &mut dyn FnMut(&mut Span)) {
    match kind {
        StatementKind::Rule(rule) => {
            head(&mut rule.head, f);
            body(&mut rule.body, f);
            if let RuleKind::ConsistencyRestoring { label: Some(t) } = &mut rule.kind {
                term(t, f);
            }
        }
        StatementKind::WeakConstraint(w) => {
            body(&mut w.body, f);
            term(&mut w.weight, f);
            if let Some(p) = &mut w.priority {
                term(p, f);
            }
            terms(&mut w.terms, f);
        }
        StatementKind::Optimize(o) => {
            for e in &mut o.elements {
                f(&mut e.span);
                term(&mut e.weight, f);
                if let Some(p) = &mut e.priority {
                    term(p, f);
                }
                terms(&mut e.terms, f);
                literals(&mut e.condition, f);
            }
        }
        StatementKind::Show(show) => {
            if let Show::Term { term: t, body: b } = &mut **show {
                term(t, f);
                body(b, f);
            }
        }
        StatementKind::Project(project) => {
            if let Project::Atom { atom, body: b } = &mut **project {
                symbolic(atom, f);
                body(b, f);
            }
        }
        StatementKind::Const(c) => term(&mut c.value, f),
        StatementKind::External(e) => {
            symbolic(&mut e.atom, f);
            body(&mut e.body, f);
            if let Some(v) = &mut e.value {
                term(v, f);
            }
        }
        StatementKind::Heuristic(h) => {
            symbolic(&mut h.atom, f);
            body(&mut h.body, f);
            term(&mut h.weight, f);
            if let Some(p) = &mut h.priority {
                term(p, f);
            }
            term(&mut h.modifier, f);
        }
        StatementKind::Edge(e) => {
            term(&mut e.from, f);
            term(&mut e.to, f);
            body(&mut e.body, f);
        }
        StatementKind::SortDef(d) => sort_expr(&mut d.expr, f),
        StatementKind::Display(l) => literal(l, f),
        StatementKind::MaxInt(t) => term(t, f),
        StatementKind::Theory(d) => {
            for t in &mut d.terms {
                f(&mut t.span);
                for op in &mut t.ops {
                    f(&mut op.span);
                }
            }
            for a in &mut d.atoms {
                f(&mut a.span);
            }
        }
        StatementKind::Defined(_)
        | StatementKind::Include(_)
        | StatementKind::ProgramPart(_)
        | StatementKind::Script(_)
        | StatementKind::Section(_)
        | StatementKind::PredicateDecl(_)
        | StatementKind::DisplaySort(_)
        | StatementKind::Error => {}
    }
}

/// Spans of a head.
fn head(h: &mut Head, f: &mut dyn FnMut(&mut Span)) {
    match h {
        Head::None => {}
        Head::Disjunction(els) => {
            for e in els {
                conditional(e, f);
            }
        }
        Head::Choice(c) => {
            f(&mut c.span);
            guard(&mut c.lower, f);
            for e in &mut c.elements {
                conditional(e, f);
            }
            guard(&mut c.upper, f);
        }
        Head::Aggregate(a) => {
            f(&mut a.span);
            guard(&mut a.lower, f);
            for e in &mut a.elements {
                f(&mut e.span);
                terms(&mut e.terms, f);
                literal(&mut e.literal, f);
                literals(&mut e.condition, f);
            }
            guard(&mut a.upper, f);
        }
        Head::Theory(a) => theory_atom(a, f),
    }
}

/// Spans of a theory atom.
fn theory_atom(a: &mut TheoryAtom, f: &mut dyn FnMut(&mut Span)) {
    f(&mut a.span);
    symbolic(&mut a.name, f);
    for e in &mut a.elements {
        f(&mut e.span);
        for t in &mut e.terms {
            theory_term(t, f);
        }
        literals(&mut e.condition, f);
    }
    if let Some((_, t)) = &mut a.guard {
        theory_term(t, f);
    }
}

/// Spans of a theory term.
fn theory_term(t: &mut TheoryTerm, f: &mut dyn FnMut(&mut Span)) {
    f(&mut t.span);
    match &mut t.kind {
        TheoryTermKind::Symbol(s) => term(s, f),
        TheoryTermKind::Function { args: ts, .. }
        | TheoryTermKind::Tuple(ts)
        | TheoryTermKind::Set(ts)
        | TheoryTermKind::List(ts) => ts.iter_mut().for_each(|t| theory_term(t, f)),
        TheoryTermKind::Unparsed(parts) => parts.iter_mut().for_each(|(_, t)| theory_term(t, f)),
    }
}

/// Spans of an optional guard.
fn guard(g: &mut Option<Guard>, f: &mut dyn FnMut(&mut Span)) {
    if let Some(g) = g {
        term(&mut g.term, f);
    }
}

/// Spans of a conditional literal.
fn conditional(c: &mut ConditionalLiteral, f: &mut dyn FnMut(&mut Span)) {
    f(&mut c.span);
    literal(&mut c.literal, f);
    literals(&mut c.condition, f);
}

/// Spans of body literals.
fn body(b: &mut [BodyLiteral], f: &mut dyn FnMut(&mut Span)) {
    for l in b {
        match l {
            BodyLiteral::Literal(l) => literal(l, f),
            BodyLiteral::Conditional(c) => conditional(c, f),
            BodyLiteral::Aggregate { aggregate: a, .. } => {
                f(&mut a.span);
                guard(&mut a.lower, f);
                for e in &mut a.elements {
                    f(&mut e.span);
                    terms(&mut e.terms, f);
                    literals(&mut e.condition, f);
                }
                for e in &mut a.set_syntax {
                    conditional(e, f);
                }
                guard(&mut a.upper, f);
            }
            BodyLiteral::Theory { atom, .. } => theory_atom(atom, f),
        }
    }
}

/// Spans of literals.
fn literals(ls: &mut [Literal], f: &mut dyn FnMut(&mut Span)) {
    for l in ls {
        literal(l, f);
    }
}

/// Spans of a literal.
fn literal(l: &mut Literal, f: &mut dyn FnMut(&mut Span)) {
    f(&mut l.span);
    match &mut l.atom {
        Atom::Symbolic(a) => symbolic(a, f),
        Atom::Comparison { lhs, rhs, .. } => {
            term(lhs, f);
            term(rhs, f);
        }
        Atom::Boolean(_) => {}
        Atom::Sort { arg, .. } => term(arg, f),
    }
}

/// Spans of a symbolic atom.
fn symbolic(a: &mut SymbolicAtom, f: &mut dyn FnMut(&mut Span)) {
    f(&mut a.span);
    for alt in &mut a.args {
        terms(alt, f);
    }
}

/// Spans of terms.
fn terms(ts: &mut [Term], f: &mut dyn FnMut(&mut Span)) {
    for t in ts {
        term(t, f);
    }
}

/// Spans of a term.
fn term(t: &mut Term, f: &mut dyn FnMut(&mut Span)) {
    f(&mut t.span);
    match &mut t.kind {
        TermKind::Function { args, .. } => {
            for alt in args {
                terms(alt, f);
            }
        }
        TermKind::ScriptCall { args, .. } => terms(args, f),
        TermKind::Unary { arg, .. } => term(arg, f),
        TermKind::Binary { lhs, rhs, .. } => {
            term(lhs, f);
            term(rhs, f);
        }
        TermKind::Interval { lo, hi } => {
            term(lo, f);
            term(hi, f);
        }
        TermKind::Pool(alts) => terms(alts, f),
        TermKind::Paren(inner) => term(inner, f),
        TermKind::Integer(_)
        | TermKind::String(_)
        | TermKind::Constant(_)
        | TermKind::Variable(_)
        | TermKind::Anonymous
        | TermKind::Infimum
        | TermKind::Supremum => {}
    }
}

/// Spans of a record sort's condition.
fn record_condition(c: &mut RecordCondition, f: &mut dyn FnMut(&mut Span)) {
    match c {
        RecordCondition::Compare { lhs, rhs, .. } => {
            term(lhs, f);
            term(rhs, f);
        }
        RecordCondition::And(a, b) | RecordCondition::Or(a, b) => {
            record_condition(a, f);
            record_condition(b, f);
        }
        RecordCondition::Not(a) | RecordCondition::Paren(a) => record_condition(a, f),
    }
}

/// Spans of a sort expression.
fn sort_expr(e: &mut SortExpr, f: &mut dyn FnMut(&mut Span)) {
    f(&mut e.span);
    match &mut e.kind {
        SortExprKind::Set(ts) => terms(ts, f),
        SortExprKind::Range(lo, hi) => {
            term(lo, f);
            term(hi, f);
        }
        SortExprKind::Ref(_) => {}
        SortExprKind::Concat(parts) => {
            for p in parts {
                sort_expr(p, f);
            }
        }
        SortExprKind::Record {
            args, condition, ..
        } => {
            for (a, _) in args {
                sort_expr(a, f);
            }
            if let Some(c) = condition {
                record_condition(c, f);
            }
        }
        SortExprKind::Union(a, b)
        | SortExprKind::Difference(a, b)
        | SortExprKind::Intersection(a, b) => {
            sort_expr(a, f);
            sort_expr(b, f);
        }
        SortExprKind::Paren(a) => sort_expr(a, f),
    }
}
