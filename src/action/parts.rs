//! The incremental form of a translation (`horizon_mode = incremental`): the statements of
//! Π(D, H) split into clingo's incremental parts, so that a multi-shot solver grounds one new
//! step per horizon instead of the whole program again (clingo's incmode: `base`, then
//! `step(t)` and `check(t)` for t = 1, 2, ..., with the external `query(t)`).
//!
//! Each statement the translator emits carries a [`Time`]: whether it has no step (`Fixed`),
//! speaks of the state at its step I (`Now`), or of the step I and the transition to I + 1
//! (`Before`: causal laws, inertia, executability conditions, action generation and CWA, the
//! history's `occurs(A, I) :- hpd(A, I)`). The split is:
//! - `#program base.`: the `Fixed` statements, `step(0).`, and the `Now` statements at I = 0;
//! - `#program step(t).`: `step(t).`, the `Now` statements at I = t and the `Before`
//!   statements at I = t - 1 (so every atom of step t, `occurs(_, t-1)` included, gets all of
//!   its rules in one part, as multi-shot solving requires);
//! - `#program check(t).`: `#external query(t).` and `:- query(t), not goal(t).`, grounded
//!   for t = 0 too.
//!
//! `#program` switches the part of the file it is written in (gringo's rule for included
//! files), and the statements carry the spans of the AL_d files they came from, so a
//! directive (spanning nothing in that file) goes before the first statement of each file in
//! each part.
//!
//! Invariants: grounding `base`, `check(0)`, then `step(k)` and `check(k)` for k = 1..n with
//! only `query(n)` true has the same answer sets, projected on `occurs`, `holds` at steps
//! 0..n and the applied CR rules, as the `iterative` translation at horizon n (the `Before`
//! instances at I = n, which that translation also grounds, only derive `-occurs(_, n)`);
//! the step variable is replaced by a term (`0`, `t`, `t - 1`), and the `step(I)` and
//! `I < horizon` literals are dropped; origins stay aligned with statements.

use std::collections::HashMap;

use crate::base::{FileId, Span};
use crate::syntax::ast::{
    self, Atom, BinaryOp, BodyLiteral, Head, Literal, ProgramPart, Rule, RuleKind, Sign,
    StatementKind as K, SymbolicAtom, Term, TermKind,
};

use super::translate::{AxiomOrigin, OriginKind};

/// When a generated statement applies, relative to its step variable I.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Time {
    /// No step variable (statics, signature, history at step 0).
    Fixed,
    /// `step(0..horizon).`
    StepRange,
    /// About the state at I.
    Now,
    /// About the action at I and the transition from I to I + 1.
    Before,
    /// `:- not goal(horizon).`
    Query,
}

/// The part parameter: `t`, unless the program uses that name (then `t_`, `t__`, ...).
fn parameter(statements: &[ast::Statement]) -> String {
    let mut names = std::collections::BTreeSet::new();
    for s in statements {
        if let K::Rule(r) = &s.kind {
            let mut r = r.clone();
            rule_terms(&mut r, &mut |t| collect_names(t, &mut names));
        }
    }
    let mut name = "t".to_string();
    while names.contains(&name) {
        name.push('_');
    }
    name
}

fn collect_names(t: &Term, out: &mut std::collections::BTreeSet<String>) {
    match &t.kind {
        TermKind::Constant(c) => {
            out.insert(c.to_string());
        }
        TermKind::Function { name, args, .. } => {
            out.insert(name.to_string());
            args.iter().flatten().for_each(|a| collect_names(a, out));
        }
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => collect_names(arg, out),
        TermKind::Binary { lhs, rhs, .. } => {
            collect_names(lhs, out);
            collect_names(rhs, out);
        }
        TermKind::Interval { lo, hi } => {
            collect_names(lo, out);
            collect_names(hi, out);
        }
        TermKind::Pool(ts) | TermKind::ScriptCall { args: ts, .. } => {
            ts.iter().for_each(|a| collect_names(a, out))
        }
        _ => {}
    }
}

/// Calls `f` on every top-level term of a rule (atom arguments, comparison sides, label).
fn rule_terms(rule: &mut Rule, f: &mut dyn FnMut(&mut Term)) {
    fn atom(a: &mut Atom, f: &mut dyn FnMut(&mut Term)) {
        match a {
            Atom::Symbolic(s) => s.args.iter_mut().flatten().for_each(f),
            Atom::Comparison { lhs, rhs, .. } => {
                f(lhs);
                f(rhs)
            }
            _ => {}
        }
    }
    fn cond(c: &mut ast::ConditionalLiteral, f: &mut dyn FnMut(&mut Term)) {
        atom(&mut c.literal.atom, f);
        for l in &mut c.condition {
            atom(&mut l.atom, f);
        }
    }
    match &mut rule.head {
        Head::Disjunction(cs) => cs.iter_mut().for_each(|c| cond(c, f)),
        Head::Choice(c) => c.elements.iter_mut().for_each(|c| cond(c, f)),
        _ => {}
    }
    for b in &mut rule.body {
        match b {
            BodyLiteral::Literal(l) => atom(&mut l.atom, f),
            BodyLiteral::Conditional(c) => cond(c, f),
            BodyLiteral::Aggregate { aggregate, .. } => {
                let g = aggregate.as_mut();
                for guard in [&mut g.lower, &mut g.upper].into_iter().flatten() {
                    f(&mut guard.term);
                }
                for e in &mut g.elements {
                    e.terms.iter_mut().for_each(&mut *f);
                    for l in &mut e.condition {
                        atom(&mut l.atom, f);
                    }
                }
                g.set_syntax.iter_mut().for_each(|c| cond(c, f));
            }
            // AL_d translations make no theory atoms.
            BodyLiteral::Theory { .. } => {}
        }
    }
    if let RuleKind::ConsistencyRestoring { label: Some(l) } = &mut rule.kind {
        f(l);
    }
}

/// Replaces the variable `var` by `by` everywhere in `t`.
fn substitute(t: &mut Term, var: &str, by: &Term) {
    match &mut t.kind {
        TermKind::Variable(v) if v == var => *t = by.clone(),
        TermKind::Function { args, .. } => args
            .iter_mut()
            .flatten()
            .for_each(|a| substitute(a, var, by)),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => substitute(arg, var, by),
        TermKind::Binary { lhs, rhs, .. } => {
            substitute(lhs, var, by);
            substitute(rhs, var, by);
        }
        TermKind::Interval { lo, hi } => {
            substitute(lo, var, by);
            substitute(hi, var, by);
        }
        TermKind::Pool(ts) => ts.iter_mut().for_each(|a| substitute(a, var, by)),
        _ => {}
    }
}

fn is_var(t: &Term, name: &str) -> bool {
    matches!(&t.kind, TermKind::Variable(v) if v == name)
}

/// True for `step(I)` and `I < horizon`, the literals the parts make redundant.
fn is_step_guard(b: &BodyLiteral, step: &str) -> bool {
    match b {
        BodyLiteral::Literal(Literal {
            sign: Sign::Positive,
            atom: Atom::Symbolic(a),
            ..
        }) => {
            !a.negated
                && a.name == "step"
                && matches!(a.args.as_slice(), [args] if matches!(args.as_slice(), [x] if is_var(x, step)))
        }
        BodyLiteral::Literal(Literal {
            sign: Sign::Positive,
            atom: Atom::Comparison { lhs, op, rhs },
            ..
        }) => {
            *op == ast::CmpOp::Lt
                && is_var(lhs, step)
                && matches!(&rhs.kind, TermKind::Constant(c) if c == "horizon")
        }
        _ => false,
    }
}

/// The statement with the step variable bound to `at`.
fn at_step(s: &ast::Statement, step: &str, at: &Term) -> ast::Statement {
    let mut s = s.clone();
    if let K::Rule(r) = &mut s.kind {
        r.body.retain(|b| !is_step_guard(b, step));
        rule_terms(r, &mut |t| substitute(t, step, at));
    }
    s
}

fn term(kind: TermKind) -> Term {
    Term {
        span: Span::default(),
        kind,
    }
}

fn fact(name: &str, arg: Term) -> ast::Statement {
    ast::Statement {
        span: Span::default(),
        kind: K::Rule(Rule {
            head: Head::Disjunction(vec![ast::ConditionalLiteral {
                span: Span::default(),
                literal: Literal {
                    span: Span::default(),
                    sign: Sign::Positive,
                    atom: Atom::Symbolic(symbolic(name, arg)),
                },
                condition: Vec::new(),
                has_colon: false,
            }]),
            body: Vec::new(),
            kind: RuleKind::Normal,
        }),
    }
}

fn symbolic(name: &str, arg: Term) -> SymbolicAtom {
    SymbolicAtom {
        span: Span::default(),
        negated: false,
        name: name.into(),
        args: vec![vec![arg]],
    }
}

fn body_atom(sign: Sign, name: &str, arg: Term) -> BodyLiteral {
    BodyLiteral::Literal(Literal {
        span: Span::default(),
        sign,
        atom: Atom::Symbolic(symbolic(name, arg)),
    })
}

/// Splits a translation's statements into the incremental parts (see the module docs).
pub fn split(
    out: Vec<ast::Statement>,
    origins: Vec<AxiomOrigin>,
    times: &[Time],
    step: &str,
) -> (Vec<ast::Statement>, Vec<AxiomOrigin>) {
    debug_assert_eq!(out.len(), times.len());
    let param = parameter(&out);
    let t = term(TermKind::Constant(param.as_str().into()));
    let before = term(TermKind::Binary {
        op: BinaryOp::Sub,
        lhs: Box::new(t.clone()),
        rhs: Box::new(term(TermKind::Integer(1))),
    });
    let zero = term(TermKind::Integer(0));
    let schema = |kind: OriginKind, text: &str| AxiomOrigin {
        kind,
        label: None,
        statement: None,
        span: None,
        text: text.into(),
    };
    let mut base = Vec::new();
    let mut steps = Vec::new();
    let mut checks = Vec::new();
    for ((s, o), time) in out.into_iter().zip(origins).zip(times) {
        match time {
            Time::Fixed => base.push((s, o)),
            Time::StepRange => {
                base.push((fact("step", zero.clone()), o.clone()));
                steps.push((fact("step", t.clone()), o));
            }
            Time::Now => {
                base.push((at_step(&s, step, &zero), o.clone()));
                steps.push((at_step(&s, step, &t), o));
            }
            Time::Before => steps.push((at_step(&s, step, &before), o)),
            Time::Query => {
                // #external query(t).   :- query(t), not goal(t).
                checks.push((
                    ast::Statement {
                        span: Span::default(),
                        kind: K::External(Box::new(ast::External {
                            atom: symbolic("query", t.clone()),
                            body: Vec::new(),
                            value: None,
                        })),
                    },
                    o.clone(),
                ));
                checks.push((
                    ast::Statement {
                        span: s.span,
                        kind: K::Rule(Rule {
                            head: Head::None,
                            body: vec![
                                body_atom(Sign::Positive, "query", t.clone()),
                                body_atom(Sign::Not, "goal", t.clone()),
                            ],
                            kind: RuleKind::Normal,
                        }),
                    },
                    o,
                ));
            }
        }
    }
    // `#program` switches the part of the file it is written in, and the statements come from
    // several files: a directive goes before a statement whose file is not yet in its part.
    let mut current: HashMap<FileId, &str> = HashMap::new();
    let mut statements = Vec::new();
    let mut origins = Vec::new();
    let named = [
        ("base", Vec::new()),
        ("step", vec![param.clone()]),
        ("check", vec![param]),
    ];
    for ((name, params), part) in named.iter().zip([base, steps, checks]) {
        let mut first = true;
        for (s, o) in part {
            let file = s.span.file;
            if first || current.get(&file).copied().unwrap_or("base") != *name {
                first = false;
                current.insert(file, name);
                statements.push(ast::Statement {
                    span: Span {
                        file,
                        start: 0,
                        end: 0,
                    },
                    kind: K::ProgramPart(ProgramPart {
                        name: name.to_string(),
                        params: params.clone(),
                    }),
                });
                origins.push(schema(OriginKind::Signature, "part"));
            }
            statements.push(s);
            origins.push(o);
        }
    }
    (statements, origins)
}
