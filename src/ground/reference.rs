//! A reference grounder for tests: naive, obviously correct, slow. It evaluates small
//! stratified normal programs (function-free, integer constants) by iterating every rule over
//! every assignment of the Herbrand universe to its variables until a fixpoint, stratum by
//! stratum, and returns the perfect model. For such programs the real grounder must turn every
//! derived atom into a fact, so its fact set must equal this model.
//!
//! Invariant: predicate `i` may use predicate `j` positively only if `j <= i` and negatively only
//! if `j < i` (the generator guarantees it), so evaluating predicates in index order is a
//! stratification.

use std::collections::BTreeSet;

use crate::base::Span;
use crate::syntax::ast;

/// A term of the small language: a variable or an integer constant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RTerm {
    /// Variable number `n` (printed `Vn`).
    Var(u8),
    /// An integer.
    Const(i32),
}

/// An atom `p<pred>(args)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RAtom {
    /// Predicate index.
    pub pred: u8,
    /// Arguments.
    pub args: Vec<RTerm>,
}

/// A rule `head :- pos, not neg.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RRule {
    /// The head.
    pub head: RAtom,
    /// Positive body atoms.
    pub pos: Vec<RAtom>,
    /// Default-negated body atoms.
    pub neg: Vec<RAtom>,
}

/// A ground atom: predicate and integer arguments.
pub type GAtom = (u8, Vec<i32>);

fn ground(a: &RAtom, vals: &[i32]) -> GAtom {
    (
        a.pred,
        a.args
            .iter()
            .map(|t| match *t {
                RTerm::Var(v) => vals[v as usize],
                RTerm::Const(c) => c,
            })
            .collect(),
    )
}

fn num_vars(r: &RRule) -> usize {
    let mut n = 0;
    for a in std::iter::once(&r.head).chain(&r.pos).chain(&r.neg) {
        for t in &a.args {
            if let RTerm::Var(v) = t {
                n = n.max(*v as usize + 1);
            }
        }
    }
    n
}

/// The perfect model of a stratified program, by naive iteration over the universe.
pub fn perfect_model(rules: &[RRule], num_preds: u8) -> BTreeSet<GAtom> {
    let mut universe: BTreeSet<i32> = BTreeSet::new();
    for r in rules {
        for a in std::iter::once(&r.head).chain(&r.pos).chain(&r.neg) {
            for t in &a.args {
                if let RTerm::Const(c) = t {
                    universe.insert(*c);
                }
            }
        }
    }
    let universe: Vec<i32> = universe.into_iter().collect();
    let mut model: BTreeSet<GAtom> = BTreeSet::new();
    for p in 0..num_preds {
        loop {
            let mut added = false;
            for r in rules.iter().filter(|r| r.head.pred == p) {
                let n = num_vars(r);
                let total = universe.len().checked_pow(n as u32).unwrap_or(0);
                if n > 0 && universe.is_empty() {
                    continue;
                }
                for code in 0..total.max(1) {
                    let mut vals = Vec::with_capacity(n);
                    let mut c = code;
                    for _ in 0..n {
                        vals.push(universe[c % universe.len()]);
                        c /= universe.len();
                    }
                    let body = r.pos.iter().all(|a| model.contains(&ground(a, &vals)))
                        && r.neg.iter().all(|a| !model.contains(&ground(a, &vals)));
                    if body && model.insert(ground(&r.head, &vals)) {
                        added = true;
                    }
                }
            }
            if !added {
                break;
            }
        }
    }
    model
}

/// The printed form of a ground atom, as the grounder shows it.
pub fn show(a: &GAtom) -> String {
    if a.1.is_empty() {
        format!("p{}", a.0)
    } else {
        let args: Vec<String> = a.1.iter().map(|v| v.to_string()).collect();
        format!("p{}({})", a.0, args.join(","))
    }
}

fn term(t: &RTerm) -> ast::Term {
    ast::Term {
        span: Span::default(),
        kind: match *t {
            RTerm::Var(v) => ast::TermKind::Variable(format!("V{v}").into()),
            RTerm::Const(c) => ast::TermKind::Integer(c as i64),
        },
    }
}

fn atom(a: &RAtom) -> ast::Atom {
    ast::Atom::Symbolic(ast::SymbolicAtom {
        span: Span::default(),
        negated: false,
        name: format!("p{}", a.pred).into(),
        args: vec![a.args.iter().map(term).collect()],
    })
}

fn literal(a: &RAtom, sign: ast::Sign) -> ast::Literal {
    ast::Literal {
        span: Span::default(),
        sign,
        atom: atom(a),
    }
}

/// The program as a syntax tree, as the parser would produce it.
pub fn to_ast(rules: &[RRule]) -> ast::Program {
    let statements = rules
        .iter()
        .map(|r| {
            let head = ast::Head::Disjunction(vec![ast::ConditionalLiteral {
                span: Span::default(),
                literal: literal(&r.head, ast::Sign::Positive),
                condition: Vec::new(),
                has_colon: false,
            }]);
            let mut body: Vec<ast::BodyLiteral> = r
                .pos
                .iter()
                .map(|a| ast::BodyLiteral::Literal(literal(a, ast::Sign::Positive)))
                .collect();
            body.extend(
                r.neg
                    .iter()
                    .map(|a| ast::BodyLiteral::Literal(literal(a, ast::Sign::Not))),
            );
            ast::Statement {
                span: Span::default(),
                kind: ast::StatementKind::Rule(ast::Rule {
                    head,
                    body,
                    kind: ast::RuleKind::Normal,
                }),
            }
        })
        .collect();
    ast::Program {
        dialect: ast::Dialect::Clingo,
        statements,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn transitive_closure() {
        let e = |a, b| RRule {
            head: RAtom {
                pred: 0,
                args: vec![RTerm::Const(a), RTerm::Const(b)],
            },
            pos: vec![],
            neg: vec![],
        };
        let v = RTerm::Var;
        let rules = vec![
            e(1, 2),
            e(2, 3),
            RRule {
                head: RAtom {
                    pred: 1,
                    args: vec![v(0), v(1)],
                },
                pos: vec![RAtom {
                    pred: 0,
                    args: vec![v(0), v(1)],
                }],
                neg: vec![],
            },
            RRule {
                head: RAtom {
                    pred: 1,
                    args: vec![v(0), v(2)],
                },
                pos: vec![
                    RAtom {
                        pred: 1,
                        args: vec![v(0), v(1)],
                    },
                    RAtom {
                        pred: 0,
                        args: vec![v(1), v(2)],
                    },
                ],
                neg: vec![],
            },
        ];
        let m = perfect_model(&rules, 2);
        assert!(m.contains(&(1, vec![1, 3])));
        assert_eq!(m.len(), 5);
    }
}
