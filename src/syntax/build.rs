//! Builders of the CR-Prolog syntax tree that the translation emits: terms, atoms, literals,
//! heads. Pure functions; every node carries the span it is given.

use super::*;

pub(super) fn term(span: Span, kind: TermKind) -> Term {
    Term { span, kind }
}

pub(super) fn var(span: Span, name: &str) -> Term {
    term(span, TermKind::Variable(name.into()))
}

pub(super) fn constant(span: Span, name: &str) -> Term {
    term(span, TermKind::Constant(name.into()))
}

pub(super) fn int(span: Span, n: i64) -> Term {
    term(span, TermKind::Integer(n))
}

pub(super) fn plus(span: Span, lhs: Term, n: i64) -> Term {
    term(
        span,
        TermKind::Binary {
            op: BinaryOp::Add,
            lhs: Box::new(lhs),
            rhs: Box::new(int(span, n)),
        },
    )
}

/// `name(args)`, or the constant `name` without arguments.
pub(super) fn function(span: Span, name: &str, args: Vec<Term>) -> Term {
    if args.is_empty() {
        constant(span, name)
    } else {
        term(
            span,
            TermKind::Function {
                name: name.into(),
                args: vec![args],
                trailing_comma: false,
            },
        )
    }
}

pub(super) fn atom(span: Span, negated: bool, name: &str, args: Vec<Term>) -> SymbolicAtom {
    SymbolicAtom {
        span,
        negated,
        name: name.into(),
        args: vec![args],
    }
}

pub(super) fn lit(span: Span, sign: Sign, a: SymbolicAtom) -> Literal {
    Literal {
        span,
        sign,
        atom: ast::Atom::Symbolic(a),
    }
}

pub(super) fn pos(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Positive, atom(span, negated, name, args)))
}

pub(super) fn neg(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Not, atom(span, negated, name, args)))
}

pub(super) fn compare(span: Span, lhs: Term, op: CmpOp, rhs: Term) -> BodyLiteral {
    BodyLiteral::Literal(Literal {
        span,
        sign: Sign::Positive,
        atom: ast::Atom::Comparison {
            lhs: Box::new(lhs),
            op,
            rhs: Box::new(rhs),
        },
    })
}

pub(super) fn head_of(span: Span, a: SymbolicAtom) -> Head {
    Head::Disjunction(vec![ConditionalLiteral {
        span,
        literal: lit(span, Sign::Positive, a),
        condition: Vec::new(),
        has_colon: false,
    }])
}
