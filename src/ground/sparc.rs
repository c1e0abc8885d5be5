//! SPARC sorted programs (Balai, Gelfond, Zhang): sort definitions are evaluated to sets of
//! ground terms, predicate declarations type every argument position, and the program is
//! lowered to the clingo dialect the rest of the grounder understands.
//!
//! Rules implemented:
//! - a sort is the set its expression denotes: `{a, f(b)}` its elements, `lo..hi` the integers
//!   between (ends may be `#const` names), `[id][1..3]` the constants made by concatenating one
//!   choice per part (`id1`, `id2`, `id3`), `f(#s1, #s2)` every `f(x, y)` with `x` in `#s1` and
//!   `y` in `#s2`, `+` union, `-` difference, `*` intersection, `#s` a sort defined earlier;
//! - a sort `#s` becomes facts `#s(x)` of a hidden predicate;
//! - every atom `p(t1, ..., tn)` of a rule must match the declaration `p(#s1, ..., #sn)`: an
//!   undeclared predicate, a wrong arity, or a ground argument outside its sort is an error at
//!   the atom; an argument with variables gets the typing literal `#si(ti)` (in the rule body,
//!   or in the condition of the element it occurs in), so every variable ranges over the sort
//!   of the positions it occupies;
//! - the `display` section becomes `#show` statements: `p.` shows every `p` atom, `-p.` every
//!   `-p` literal, a pattern `p(X, a).` the atoms matching it; without a display section every
//!   atom is shown.

use hashbrown::{HashMap, HashSet};

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{self, Sign, SortExpr, SortExprKind, StatementKind, TermKind};

use super::rewrite::{unpool_term, Rewriter};
use super::symbol::SymId;

/// The evaluated sorts and predicate declarations of a SPARC program.
#[derive(Default)]
struct Typing {
    /// Elements of each sort (name without `#`), in definition order of first appearance.
    sorts: HashMap<String, Vec<SymId>>,
    /// The same as sets, for membership checks.
    members: HashMap<String, HashSet<SymId>>,
    /// Argument sorts of each declared predicate.
    decls: HashMap<String, Vec<String>>,
}

fn has_vars(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Variable(_) | TermKind::Anonymous => true,
        TermKind::Function { args, .. } => args.iter().flatten().any(has_vars),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => has_vars(arg),
        TermKind::Binary { lhs, rhs, .. } => has_vars(lhs) || has_vars(rhs),
        TermKind::Interval { lo, hi } => has_vars(lo) || has_vars(hi),
        TermKind::Pool(ts) => ts.iter().any(has_vars),
        TermKind::ScriptCall { args, .. } => args.iter().any(has_vars),
        _ => false,
    }
}

fn push_unique(out: &mut Vec<SymId>, seen: &mut HashSet<SymId>, s: SymId) {
    if seen.insert(s) {
        out.push(s);
    }
}

impl Typing {
    /// Evaluates a sort expression; `None` after reporting an error.
    fn eval(&self, rw: &mut Rewriter<'_>, e: &SortExpr) -> Option<Vec<SymId>> {
        let mut out = Vec::new();
        let mut seen = HashSet::new();
        match &e.kind {
            SortExprKind::Set(terms) => {
                for t in terms {
                    for t in unpool_term(t) {
                        let v = rw.eval_ground(&t)?;
                        push_unique(&mut out, &mut seen, v);
                    }
                }
            }
            SortExprKind::Range(lo, hi) => {
                let (lo, hi) = (rw.eval_ground(lo)?, rw.eval_ground(hi)?);
                let (Some(lo), Some(hi)) = (rw.syms.num(lo), rw.syms.num(hi)) else {
                    rw.diags.push(Diagnostic::error(
                        e.span,
                        "range sort with non-integer ends",
                    ));
                    return None;
                };
                for i in lo..=hi {
                    let v = rw.syms.int(i);
                    push_unique(&mut out, &mut seen, v);
                }
            }
            SortExprKind::Ref(name) => match self.sorts.get(name) {
                Some(v) => out = v.clone(),
                None => {
                    rw.diags
                        .push(Diagnostic::error(e.span, format!("undefined sort #{name}")));
                    return None;
                }
            },
            SortExprKind::Concat(parts) => {
                let mut texts = vec![String::new()];
                for p in parts {
                    let vals = self.eval(rw, p)?;
                    let mut next = Vec::new();
                    for prefix in &texts {
                        for &v in &vals {
                            next.push(format!("{prefix}{}", rw.syms.show(v)));
                        }
                    }
                    texts = next;
                }
                for t in texts {
                    let v = match t.parse::<i32>() {
                        Ok(n) => rw.syms.int(n),
                        Err(_) => rw.syms.fun_str(&t, false, &[]),
                    };
                    push_unique(&mut out, &mut seen, v);
                }
            }
            SortExprKind::Record {
                name,
                args,
                condition,
            } => {
                if !condition.is_empty() {
                    rw.unsupported(e.span, "conditions on record sorts");
                    return None;
                }
                let mut tuples: Vec<Vec<SymId>> = vec![Vec::new()];
                for (arg, _) in args {
                    let vals = self.eval(rw, arg)?;
                    let mut next = Vec::with_capacity(tuples.len() * vals.len());
                    for t in &tuples {
                        for &v in &vals {
                            let mut t = t.clone();
                            t.push(v);
                            next.push(t);
                        }
                    }
                    tuples = next;
                }
                for t in tuples {
                    let v = rw.syms.fun_str(name, false, &t);
                    push_unique(&mut out, &mut seen, v);
                }
            }
            SortExprKind::Union(a, b) => {
                for v in self.eval(rw, a)?.into_iter().chain(self.eval(rw, b)?) {
                    push_unique(&mut out, &mut seen, v);
                }
            }
            SortExprKind::Difference(a, b) => {
                let remove: HashSet<SymId> = self.eval(rw, b)?.into_iter().collect();
                for v in self.eval(rw, a)? {
                    if !remove.contains(&v) {
                        push_unique(&mut out, &mut seen, v);
                    }
                }
            }
            SortExprKind::Intersection(a, b) => {
                let keep: HashSet<SymId> = self.eval(rw, b)?.into_iter().collect();
                for v in self.eval(rw, a)? {
                    if keep.contains(&v) {
                        push_unique(&mut out, &mut seen, v);
                    }
                }
            }
            SortExprKind::Paren(inner) => out = self.eval(rw, inner)?,
        }
        Some(out)
    }

    /// Checks an atom against its declaration and returns the typing literals of its
    /// arguments with variables; `None` after reporting an error.
    fn typing(&self, rw: &mut Rewriter<'_>, a: &ast::SymbolicAtom) -> Option<Vec<ast::Literal>> {
        let args: Vec<ast::Term> = a.args.first().cloned().unwrap_or_default();
        let Some(sorts) = self.decls.get(&a.name) else {
            rw.diags.push(
                Diagnostic::error(
                    a.span,
                    format!("predicate {}/{} is not declared", a.name, args.len()),
                )
                .with_snippet(snippet(rw, a.span)),
            );
            return None;
        };
        if sorts.len() != args.len() {
            rw.diags.push(
                Diagnostic::error(
                    a.span,
                    format!(
                        "{} has {} argument(s) in its declaration, not {}",
                        a.name,
                        sorts.len(),
                        args.len()
                    ),
                )
                .with_snippet(snippet(rw, a.span)),
            );
            return None;
        }
        let mut out = Vec::new();
        for (t, sort) in args.iter().zip(sorts) {
            if has_vars(t) {
                out.push(ast::Literal {
                    span: t.span,
                    sign: Sign::Positive,
                    atom: ast::Atom::Sort {
                        sort: sort.clone(),
                        arg: Box::new(t.clone()),
                    },
                });
                continue;
            }
            for t in unpool_term(t) {
                let v = rw.eval_ground(&t)?;
                if !self.members.get(sort).is_some_and(|m| m.contains(&v)) {
                    let shown = rw.syms.show(v);
                    rw.diags.push(
                        Diagnostic::error(t.span, format!("'{shown}' is not in sort #{sort}"))
                            .with_snippet(snippet(rw, a.span))
                            .with_note(
                                None,
                                format!("in an argument of {}/{}", a.name, args.len()),
                            ),
                    );
                    return None;
                }
            }
        }
        Some(out)
    }

    /// Typing literals for every atom of a list of literals (sort atoms are checked only for
    /// the sort's existence, by the rewriter).
    fn literals(&self, rw: &mut Rewriter<'_>, lits: &[ast::Literal]) -> Option<Vec<ast::Literal>> {
        let mut out = Vec::new();
        for l in lits {
            if let ast::Atom::Symbolic(a) = &l.atom {
                out.extend(self.typing(rw, a)?);
            }
        }
        Some(out)
    }

    /// Adds the sort atoms of disjunction or choice elements: to the element's condition when
    /// it has one, otherwise to `extra` (the rule body).
    fn head_elements(
        &self,
        rw: &mut Rewriter<'_>,
        es: &mut [ast::ConditionalLiteral],
        extra: &mut Vec<ast::Literal>,
    ) -> Option<()> {
        for e in es.iter_mut() {
            let t = self.literals(rw, std::slice::from_ref(&e.literal))?;
            let c = self.literals(rw, &e.condition)?;
            if e.condition.is_empty() {
                extra.extend(t);
            } else {
                e.condition.extend(t);
                e.condition.extend(c);
            }
        }
        Some(())
    }

    fn rule(&self, rw: &mut Rewriter<'_>, r: &ast::Rule) -> Option<ast::Rule> {
        let mut r = r.clone();
        let mut extra: Vec<ast::Literal> = Vec::new();
        match &mut r.head {
            ast::Head::None => {}
            ast::Head::Disjunction(es) => self.head_elements(rw, es, &mut extra)?,
            ast::Head::Choice(c) => self.head_elements(rw, &mut c.elements, &mut extra)?,
            ast::Head::Aggregate(h) => {
                for e in h.elements.iter_mut() {
                    let t = self.literals(rw, std::slice::from_ref(&e.literal))?;
                    let c = self.literals(rw, &e.condition)?;
                    e.condition.extend(t);
                    e.condition.extend(c);
                }
            }
        }
        for b in r.body.iter_mut() {
            match b {
                ast::BodyLiteral::Literal(l) => {
                    extra.extend(self.literals(rw, std::slice::from_ref(l))?)
                }
                ast::BodyLiteral::Conditional(c) => {
                    let t = self.literals(rw, std::slice::from_ref(&c.literal))?;
                    let u = self.literals(rw, &c.condition)?;
                    c.condition.extend(t);
                    c.condition.extend(u);
                }
                ast::BodyLiteral::Aggregate { aggregate, .. } => {
                    for e in aggregate.elements.iter_mut() {
                        let t = self.literals(rw, &e.condition)?;
                        e.condition.extend(t);
                    }
                    for e in aggregate.set_syntax.iter_mut() {
                        let t = self.literals(rw, std::slice::from_ref(&e.literal))?;
                        let u = self.literals(rw, &e.condition)?;
                        e.condition.extend(t);
                        e.condition.extend(u);
                    }
                }
            }
        }
        r.body
            .extend(extra.into_iter().map(ast::BodyLiteral::Literal));
        Some(r)
    }
}

fn snippet(rw: &Rewriter<'_>, span: Span) -> String {
    match rw.sources {
        Some(s) if (span.file.0 as usize) < s.len() => s.get(span.file).slice(span).to_string(),
        _ => String::new(),
    }
}

/// Lowers a SPARC program to the clingo dialect: registers the sorts (as facts of `#s/1` in
/// `rw.out.sort_facts`) and returns the typed statements, display items turned into `#show`.
pub fn lower(rw: &mut Rewriter<'_>, program: &ast::Program) -> ast::Program {
    let mut typing = Typing::default();
    let mut statements = Vec::new();
    let mut displays: Vec<(Span, ast::Literal)> = Vec::new();
    for st in &program.statements {
        match &st.kind {
            StatementKind::SortDef(d) => {
                if let Some(set) = typing.eval(rw, &d.expr) {
                    typing
                        .members
                        .insert(d.name.clone(), set.iter().copied().collect());
                    typing.sorts.insert(d.name.clone(), set);
                    rw.sorts.push(format!("#{}", d.name));
                }
            }
            StatementKind::PredicateDecl(p) => {
                for s in &p.sorts {
                    if !typing.sorts.contains_key(s) {
                        rw.diags.push(
                            Diagnostic::error(st.span, format!("undefined sort #{s}"))
                                .with_snippet(snippet(rw, st.span)),
                        );
                    }
                }
                typing.decls.insert(p.name.clone(), p.sorts.clone());
            }
            StatementKind::Section(_) => {}
            StatementKind::Display(l) => displays.push((st.span, (**l).clone())),
            StatementKind::Rule(r) => {
                if let Some(r) = typing.rule(rw, r) {
                    statements.push(ast::Statement {
                        span: st.span,
                        kind: StatementKind::Rule(r),
                    });
                }
            }
            _ => statements.push(st.clone()),
        }
    }
    // Sort memberships, in definition order.
    let mut names: Vec<&String> = typing.sorts.keys().collect();
    names.sort_by_key(|n| rw.sorts.iter().position(|s| &s[1..] == n.as_str()));
    for name in names {
        let pred = rw.pred(&format!("#{name}"), 1, false);
        for &v in &typing.sorts[name] {
            rw.out.sort_facts.push((pred, v));
        }
    }
    // display: `p.` shows the predicate, a pattern shows the atoms matching it.
    for (span, l) in displays {
        match &l.atom {
            ast::Atom::Symbolic(a) if a.args.iter().all(|list| list.is_empty()) => {
                let arity = typing.decls.get(&a.name).map_or(0, |d| d.len()) as u32;
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Signature(ast::Signature {
                        negated: a.negated,
                        name: a.name.clone(),
                        arity,
                    }))),
                });
            }
            ast::Atom::Symbolic(a) => {
                let term = ast::Term {
                    span: a.span,
                    kind: TermKind::Function {
                        name: a.name.clone(),
                        args: a.args.clone(),
                        trailing_comma: false,
                    },
                };
                let term = if a.negated {
                    ast::Term {
                        span: a.span,
                        kind: TermKind::Unary {
                            op: ast::UnaryOp::Minus,
                            arg: Box::new(term),
                        },
                    }
                } else {
                    term
                };
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Term {
                        term,
                        body: vec![ast::BodyLiteral::Literal(l.clone())],
                    })),
                });
            }
            ast::Atom::Sort { sort, arg } => {
                let term = ast::Term {
                    span: l.span,
                    kind: TermKind::Function {
                        name: format!("#{sort}"),
                        args: vec![vec![(**arg).clone()]],
                        trailing_comma: false,
                    },
                };
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Term {
                        term,
                        body: vec![ast::BodyLiteral::Literal(l.clone())],
                    })),
                });
            }
            _ => {}
        }
    }
    // Without a display section everything is shown.
    if program
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Section(ast::Section::Display)))
    {
        rw.out.show.restricted = true;
    }
    ast::Program {
        dialect: ast::Dialect::Clingo,
        statements,
    }
}
