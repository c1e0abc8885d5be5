//! Pools: unfolding `;` in terms, atoms, literals, bodies, conditions and guards into
//! separate alternatives, as clingo does (a rule's pools into separate statements, an
//! aggregate's into separate elements, a conditional element's within the element).
//!
//! Invariant: a pool-free statement is left as it is (unfolding it would only copy it).

use super::*;

/// True when unfolding changes nothing in `t`: no pool, no argument-tuple pool
/// (`f(1,2;3,4)`), no parentheses (unfolding drops them).
pub(super) fn pool_free_term(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Pool(_) | TermKind::Paren(_) => false,
        TermKind::Function { args, .. } => {
            args.len() <= 1 && args.iter().flatten().all(pool_free_term)
        }
        TermKind::Unary { arg, .. } => pool_free_term(arg),
        TermKind::Binary { lhs, rhs, .. } => pool_free_term(lhs) && pool_free_term(rhs),
        TermKind::Interval { lo, hi } => pool_free_term(lo) && pool_free_term(hi),
        TermKind::ScriptCall { .. } => false,
        _ => true,
    }
}

/// [`pool_free_term`] for a literal.
pub(super) fn pool_free_literal(l: &ast::Literal) -> bool {
    match &l.atom {
        ast::Atom::Symbolic(a) => a.args.len() <= 1 && a.args.iter().flatten().all(pool_free_term),
        ast::Atom::Comparison { lhs, rhs, .. } => pool_free_term(lhs) && pool_free_term(rhs),
        ast::Atom::Boolean(_) => true,
        ast::Atom::Sort { arg, .. } => pool_free_term(arg),
    }
}

/// [`pool_free_term`] for a conditional literal.
pub(super) fn pool_free_cond(c: &ast::ConditionalLiteral) -> bool {
    pool_free_literal(&c.literal) && c.condition.iter().all(pool_free_literal)
}

/// [`pool_free_term`] for a guard.
pub(super) fn pool_free_guard(g: &Option<ast::Guard>) -> bool {
    g.as_ref().is_none_or(|g| pool_free_term(&g.term))
}

/// True when [`Rewriter::rule`]'s unfolding would give the rule back unchanged.
pub(super) fn pool_free_rule(r: &ast::Rule) -> bool {
    let head = match &r.head {
        ast::Head::None => true,
        ast::Head::Disjunction(es) => es.iter().all(pool_free_cond),
        ast::Head::Choice(c) => {
            c.elements.iter().all(pool_free_cond)
                && pool_free_guard(&c.lower)
                && pool_free_guard(&c.upper)
        }
        ast::Head::Aggregate(h) => {
            h.elements.iter().all(|e| {
                e.terms.iter().all(pool_free_term)
                    && pool_free_literal(&e.literal)
                    && e.condition.iter().all(pool_free_literal)
            }) && pool_free_guard(&h.lower)
                && pool_free_guard(&h.upper)
        }
        // Theory atoms keep their pools (they are not unfolded).
        ast::Head::Theory(_) => true,
    };
    let kind = match &r.kind {
        ast::RuleKind::Normal => true,
        ast::RuleKind::ConsistencyRestoring { label } => {
            label.as_ref().is_none_or(|l| pool_free_term(l))
        }
    };
    head && kind
        && r.body.iter().all(|b| match b {
            ast::BodyLiteral::Literal(l) => pool_free_literal(l),
            ast::BodyLiteral::Conditional(c) => pool_free_cond(c),
            ast::BodyLiteral::Aggregate { aggregate: a, .. } => {
                a.elements.iter().all(|e| {
                    e.terms.iter().all(pool_free_term) && e.condition.iter().all(pool_free_literal)
                }) && a.set_syntax.iter().all(pool_free_cond)
                    && pool_free_guard(&a.lower)
                    && pool_free_guard(&a.upper)
            }
            ast::BodyLiteral::Theory { .. } => true,
        })
}

/// Unfolds the pools of a term: every alternative, pool-free.
pub fn unpool_term(t: &ast::Term) -> Vec<ast::Term> {
    let mk = |kind| ast::Term { span: t.span, kind };
    match &t.kind {
        TermKind::Pool(alts) => alts.iter().flat_map(unpool_term).collect(),
        TermKind::Function {
            name,
            args,
            trailing_comma,
        } => {
            let mut out = Vec::new();
            for list in args {
                for combo in unpool_list(list) {
                    out.push(mk(TermKind::Function {
                        name: name.clone(),
                        args: vec![combo],
                        trailing_comma: *trailing_comma,
                    }));
                }
            }
            if args.is_empty() {
                out.push(t.clone());
            }
            out
        }
        TermKind::Unary { op, arg } => unpool_term(arg)
            .into_iter()
            .map(|a| {
                mk(TermKind::Unary {
                    op: *op,
                    arg: Box::new(a),
                })
            })
            .collect(),
        TermKind::Binary { op, lhs, rhs } => {
            let mut out = Vec::new();
            for l in unpool_term(lhs) {
                for r in unpool_term(rhs) {
                    out.push(mk(TermKind::Binary {
                        op: *op,
                        lhs: Box::new(l.clone()),
                        rhs: Box::new(r),
                    }));
                }
            }
            out
        }
        TermKind::Interval { lo, hi } => {
            let mut out = Vec::new();
            for l in unpool_term(lo) {
                for h in unpool_term(hi) {
                    out.push(mk(TermKind::Interval {
                        lo: Box::new(l.clone()),
                        hi: Box::new(h),
                    }));
                }
            }
            out
        }
        TermKind::Paren(inner) => unpool_term(inner),
        _ => vec![t.clone()],
    }
}

/// Unfolds the pools of an argument list into pool-free lists (the cross product).
///
/// Linear in the size of the result: a term without alternatives is pushed onto every prefix
/// in place, and prefixes are copied only when a pool multiplies them (an atom with 2,000,000
/// pool-free arguments is one pass, not 2,000,000 growing copies).
pub fn unpool_list(list: &[ast::Term]) -> Vec<Vec<ast::Term>> {
    product(list.iter().map(unpool_term).collect())
}

/// Unfolds the pools of a literal.
pub fn unpool_literal(l: &ast::Literal) -> Vec<ast::Literal> {
    match &l.atom {
        ast::Atom::Symbolic(a) => unpool_atom(a)
            .into_iter()
            .map(|atom| ast::Literal {
                span: l.span,
                sign: l.sign,
                atom: ast::Atom::Symbolic(atom),
            })
            .collect(),
        ast::Atom::Comparison { lhs, op, rhs } => {
            let mut out = Vec::new();
            for a in unpool_term(lhs) {
                for b in unpool_term(rhs) {
                    out.push(ast::Literal {
                        span: l.span,
                        sign: l.sign,
                        atom: ast::Atom::Comparison {
                            lhs: Box::new(a.clone()),
                            op: *op,
                            rhs: Box::new(b),
                        },
                    });
                }
            }
            out
        }
        _ => vec![l.clone()],
    }
}

/// Unfolds the pools of an atom.
pub fn unpool_atom(a: &ast::SymbolicAtom) -> Vec<ast::SymbolicAtom> {
    let mut out = Vec::new();
    for list in &a.args {
        for combo in unpool_list(list) {
            out.push(ast::SymbolicAtom {
                span: a.span,
                negated: a.negated,
                name: a.name.clone(),
                args: vec![combo],
            });
        }
    }
    if a.args.is_empty() {
        out.push(a.clone());
    }
    out
}

/// Cross product of alternatives, in order (the first choice varies slowest); linear in the
/// size of the result, see [`unpool_list`].
pub(super) fn product<T: Clone>(choices: Vec<Vec<T>>) -> Vec<Vec<T>> {
    let mut acc: Vec<Vec<T>> = vec![Vec::with_capacity(choices.len())];
    for mut alts in choices {
        if alts.len() == 1 {
            // The common case (no pool here): push onto every prefix in place.
            let a = alts.pop().expect("one alternative");
            if let Some((last, rest)) = acc.split_last_mut() {
                for prefix in rest {
                    prefix.push(a.clone());
                }
                last.push(a);
            }
            continue;
        }
        let mut next = Vec::with_capacity(acc.len() * alts.len());
        if let Some((last, rest)) = alts.split_last() {
            for mut prefix in acc {
                for a in rest {
                    let mut p = prefix.clone();
                    p.push(a.clone());
                    next.push(p);
                }
                prefix.push(last.clone());
                next.push(prefix);
            }
        }
        acc = next;
    }
    acc
}

/// Unfolds pools in body literals: each alternative of a plain literal is a separate rule;
/// inside aggregates and conditions alternatives become separate elements.
pub(super) fn unpool_body(body: &[ast::BodyLiteral]) -> Vec<Vec<ast::BodyLiteral>> {
    let choices: Vec<Vec<Vec<ast::BodyLiteral>>> = body
        .iter()
        .map(|b| match b {
            ast::BodyLiteral::Theory { .. } => vec![vec![b.clone()]],
            ast::BodyLiteral::Literal(l) => unpool_literal(l)
                .into_iter()
                .map(|l| vec![ast::BodyLiteral::Literal(l)])
                .collect(),
            // The literal keeps its pools (alternatives of one conditional literal); the
            // condition's alternatives are further conditional literals of the same rule.
            ast::BodyLiteral::Conditional(c) => vec![unpool_condition(c)
                .into_iter()
                .map(ast::BodyLiteral::Conditional)
                .collect()],
            ast::BodyLiteral::Aggregate { sign, aggregate } => {
                let mut agg = aggregate.clone();
                agg.elements = aggregate
                    .elements
                    .iter()
                    .flat_map(|e| {
                        let conds = product(e.condition.iter().map(unpool_literal).collect());
                        let tuples = unpool_list(&e.terms);
                        let mut out = Vec::new();
                        for t in &tuples {
                            for c in &conds {
                                out.push(ast::BodyAggregateElement {
                                    span: e.span,
                                    terms: t.clone(),
                                    condition: c.clone(),
                                });
                            }
                        }
                        out
                    })
                    .collect();
                agg.set_syntax = aggregate.set_syntax.iter().flat_map(unpool_cond).collect();
                // Alternatives of the guards are separate rules.
                let mut out = Vec::new();
                for lower in unpool_guard(&aggregate.lower) {
                    for upper in unpool_guard(&aggregate.upper) {
                        let mut a = agg.clone();
                        a.lower = lower.clone();
                        a.upper = upper;
                        out.push(vec![ast::BodyLiteral::Aggregate {
                            sign: *sign,
                            aggregate: a,
                        }]);
                    }
                }
                out
            }
        })
        .collect();
    product(choices).into_iter().map(|b| b.concat()).collect()
}

/// Unfolds pools in a conditional literal into several.
pub(super) fn unpool_cond(c: &ast::ConditionalLiteral) -> Vec<ast::ConditionalLiteral> {
    let conds = product(c.condition.iter().map(unpool_literal).collect());
    let mut out = Vec::new();
    for l in unpool_literal(&c.literal) {
        for cond in &conds {
            out.push(ast::ConditionalLiteral {
                span: c.span,
                literal: l.clone(),
                condition: cond.clone(),
                has_colon: c.has_colon,
            });
        }
    }
    out
}

/// The alternatives of an optional guard.
pub(super) fn unpool_guard(g: &Option<ast::Guard>) -> Vec<Option<ast::Guard>> {
    match g {
        None => vec![None],
        Some(g) => unpool_term(&g.term)
            .into_iter()
            .map(|term| Some(ast::Guard { op: g.op, term }))
            .collect(),
    }
}

/// Unfolds the pools of a conditional literal's condition only, one literal per alternative.
pub(super) fn unpool_condition(c: &ast::ConditionalLiteral) -> Vec<ast::ConditionalLiteral> {
    product(c.condition.iter().map(unpool_literal).collect())
        .into_iter()
        .map(|condition| ast::ConditionalLiteral {
            span: c.span,
            literal: c.literal.clone(),
            condition,
            has_colon: c.has_colon,
        })
        .collect()
}
