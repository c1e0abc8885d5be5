//! Builders of the clingo-dialect syntax tree from values: terms, atoms, literals, heads, rules,
//! `#external` declarations. The AL_d translation emits its program through them, and the robot
//! layers build the statements they add to a program (facts of symbols, gated rules) with them
//! instead of printing text and parsing it again.
//!
//! Invariants: pure functions; every node carries the span it is given (the default span for
//! nodes that nothing was written for); a built statement prints, through
//! [`crate::syntax::printer`], as the text that parses back to it.

use super::ast::{
    self, BinaryOp, BodyLiteral, CmpOp, ConditionalLiteral, Head, Literal, Rule, RuleKind, Sign,
    Statement, StatementKind, SymbolicAtom, Term, TermKind,
};
use crate::base::Span;

/// A term of `kind`.
pub fn term(span: Span, kind: TermKind) -> Term {
    Term { span, kind }
}

/// The variable `name`.
pub fn var(span: Span, name: &str) -> Term {
    term(span, TermKind::Variable(name.into()))
}

/// The constant `name`.
pub fn constant(span: Span, name: &str) -> Term {
    term(span, TermKind::Constant(name.into()))
}

/// The integer `n`.
pub fn int(span: Span, n: i64) -> Term {
    term(span, TermKind::Integer(n))
}

/// `lhs + n`.
pub fn plus(span: Span, lhs: Term, n: i64) -> Term {
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
pub fn function(span: Span, name: &str, args: Vec<Term>) -> Term {
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

/// The atom `name(args)`, classically negated (`-name(args)`) when `negated`.
pub fn atom(span: Span, negated: bool, name: &str, args: Vec<Term>) -> SymbolicAtom {
    SymbolicAtom {
        span,
        negated,
        name: name.into(),
        args: vec![args],
    }
}

/// The literal `a` with `sign` (`a`, `not a`, `not not a`).
pub fn lit(span: Span, sign: Sign, a: SymbolicAtom) -> Literal {
    Literal {
        span,
        sign,
        atom: ast::Atom::Symbolic(a),
    }
}

/// The body literal `name(args)` (`-name(args)` when `negated`).
pub fn pos(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Positive, atom(span, negated, name, args)))
}

/// The body literal `not name(args)` (`not -name(args)` when `negated`).
pub fn neg(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Not, atom(span, negated, name, args)))
}

/// The comparison `lhs op rhs` as a body literal.
pub fn compare(span: Span, lhs: Term, op: CmpOp, rhs: Term) -> BodyLiteral {
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

/// The head made of the one atom `a`.
pub fn head_of(span: Span, a: SymbolicAtom) -> Head {
    Head::Disjunction(vec![ConditionalLiteral {
        span,
        literal: lit(span, Sign::Positive, a),
        condition: Vec::new(),
        has_colon: false,
    }])
}

/// The rule `head :- body.`
pub fn rule(span: Span, head: Head, body: Vec<BodyLiteral>) -> Statement {
    Statement {
        span,
        kind: StatementKind::Rule(Rule {
            head,
            body,
            kind: RuleKind::Normal,
        }),
    }
}

/// The consistency-restoring rule `head :+ body.` (unlabelled).
pub fn cr_rule(span: Span, head: Head, body: Vec<BodyLiteral>) -> Statement {
    Statement {
        span,
        kind: StatementKind::Rule(Rule {
            head,
            body,
            kind: RuleKind::ConsistencyRestoring { label: None },
        }),
    }
}

/// The fact `a.`
pub fn fact(span: Span, a: SymbolicAtom) -> Statement {
    rule(span, head_of(span, a), Vec::new())
}

/// `#external a : body. [value]`, the value a constant (`false`, `true`, `free`) or none.
pub fn external(
    span: Span,
    a: SymbolicAtom,
    body: Vec<BodyLiteral>,
    value: Option<&str>,
) -> Statement {
    Statement {
        span,
        kind: StatementKind::External(Box::new(ast::External {
            atom: a,
            body,
            value: value.map(|v| constant(span, v)),
        })),
    }
}
