//! Builders of AL_d statements from values: the layers above `action` (scene understanding, and
//! any client that has a scene, a literal or a learned axiom in hand) add statements to a
//! description through these functions instead of printing AL_d text and parsing it again.
//!
//! Invariants: every node gets the default (empty) span, since nothing was written; names are
//! taken as given (the checker reports an unknown sort, fluent or constant as for parsed text);
//! a built statement prints, through `action`'s printer, as the text a person would write.

use super::ast::{Atom, BodyItem, Lit, Name, SortExpr, SortPart, Statement, StatementKind};
use crate::base::Span;
use crate::syntax::ast::{Term, TermKind};

/// An argument of a built atom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Arg {
    /// A constant (`table`, `small`).
    Const(String),
    /// A variable (`O1`).
    Var(String),
    /// An integer.
    Int(i64),
    /// Any other term (a nested function, a string).
    Term(Term),
}

impl Arg {
    /// A constant argument.
    pub fn constant(name: &str) -> Arg {
        Arg::Const(name.to_string())
    }

    fn term(&self) -> Term {
        let kind = match self {
            Arg::Const(c) => TermKind::Constant(c.as_str().into()),
            Arg::Var(v) => TermKind::Variable(v.as_str().into()),
            Arg::Int(n) => TermKind::Integer(*n),
            Arg::Term(t) => return t.clone(),
        };
        Term {
            span: Span::default(),
            kind,
        }
    }
}

fn name(text: &str) -> Name {
    Name {
        span: Span::default(),
        text: text.to_string(),
    }
}

/// The atom `name(args)`.
pub fn atom(predicate: &str, args: &[Arg]) -> Atom {
    Atom {
        span: Span::default(),
        name: name(predicate),
        args: args.iter().map(Arg::term).collect(),
    }
}

/// The literal `[-]name(args)`.
pub fn lit(negated: bool, predicate: &str, args: &[Arg]) -> Lit {
    Lit {
        span: Span::default(),
        negated,
        atom: atom(predicate, args),
    }
}

fn statement(label: Option<&str>, kind: StatementKind) -> Statement {
    Statement {
        span: Span::default(),
        guards: Vec::new(),
        label: label.map(name),
        kind,
    }
}

/// `sort name = {m1, ..., mk}.`
pub fn sort(sort_name: &str, members: &[&str]) -> Statement {
    let set = members.iter().map(|m| Arg::constant(m).term()).collect();
    statement(
        None,
        StatementKind::Sort {
            name: name(sort_name),
            expr: SortExpr {
                span: Span::default(),
                parts: vec![SortPart::Set(set)],
            },
        },
    )
}

/// `l.`: a static fact.
pub fn fact(l: Lit) -> Statement {
    statement(
        None,
        StatementKind::Constraint {
            head: l,
            body: Vec::new(),
        },
    )
}

/// `initially l.`
pub fn initially(l: Lit) -> Statement {
    statement(None, StatementKind::Initially { lit: l })
}

/// `goal l1, ..., lk.`: one goal, the conjunction of `lits`.
pub fn goal(lits: Vec<Lit>) -> Statement {
    statement(
        None,
        StatementKind::Goal {
            body: lits.into_iter().map(BodyItem::Lit).collect(),
        },
    )
}

/// `happened a at step.`
pub fn happened(action: Atom, step: i64) -> Statement {
    statement(
        None,
        StatementKind::Happened {
            action,
            step: Arg::Int(step).term(),
        },
    )
}

/// `observed l at step.`
pub fn observed(l: Lit, step: i64) -> Statement {
    statement(
        None,
        StatementKind::Observed {
            lit: l,
            step: Arg::Int(step).term(),
        },
    )
}

/// `label: a causes effect if body.`: a causal law.
pub fn causal(label: &str, action: Atom, effect: Lit, body: Vec<Lit>) -> Statement {
    statement(
        Some(label),
        StatementKind::Causal {
            action,
            effect,
            body: body.into_iter().map(BodyItem::Lit).collect(),
        },
    )
}

/// `label: impossible a if body.`: an executability condition.
pub fn impossible(label: &str, action: Atom, body: Vec<Lit>) -> Statement {
    statement(
        Some(label),
        StatementKind::Impossible {
            action,
            body: body.into_iter().map(BodyItem::Lit).collect(),
        },
    )
}

/// `label: head if body.`: a state constraint.
pub fn constraint(label: &str, head: Lit, body: Vec<Lit>) -> Statement {
    statement(
        Some(label),
        StatementKind::Constraint {
            head,
            body: body.into_iter().map(BodyItem::Lit).collect(),
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn built_statements_are_what_the_parser_reads() {
        let text = "sort movable = {a, b}.\nhas_size(a, small).\ninitially relation(on, a, table).\nL1: -stable(O1) if irreg_below(O1).\n";
        let parsed = crate::action::parse(crate::base::FileId(0), text);
        assert!(!parsed.has_errors());
        let strip = |mut s: Statement| {
            s.span = Span::default();
            s
        };
        let built = [
            sort("movable", &["a", "b"]),
            fact(lit(
                false,
                "has_size",
                &[Arg::constant("a"), Arg::constant("small")],
            )),
            initially(lit(
                false,
                "relation",
                &[
                    Arg::constant("on"),
                    Arg::constant("a"),
                    Arg::constant("table"),
                ],
            )),
            constraint(
                "L1",
                lit(true, "stable", &[Arg::Var("O1".into())]),
                vec![lit(false, "irreg_below", &[Arg::Var("O1".into())])],
            ),
        ];
        // Spans differ (parsed nodes cover their text); compare the printed statements.
        for (b, p) in built.iter().zip(parsed.description.statements) {
            assert_eq!(
                format!("{:?}", strip_spans(b)),
                format!("{:?}", strip_spans(&strip(p)))
            );
        }
    }

    /// Debug text of a statement with every span blanked.
    fn strip_spans(s: &Statement) -> String {
        let text = format!("{s:?}");
        let mut out = String::new();
        let mut rest = text.as_str();
        while let Some(i) = rest.find("span: Span {") {
            out.push_str(&rest[..i]);
            let tail = &rest[i..];
            let end = tail.find('}').map_or(tail.len(), |e| e + 1);
            out.push_str("span: _");
            rest = &tail[end..];
        }
        out.push_str(rest);
        out
    }
}
