//! SPARC rules typed by the predicate declarations: every atom is checked against its
//! declaration, every argument with variables gets its typing literal `#s(t)`, and with
//! `#maxint` the variables no atom binds range over `#nat` (the rules are listed in the module
//! above).
//!
//! Invariant: a typed rule has the same head and body as the input rule plus typing literals;
//! a rule with a typing error is reported and left out (`None`), never lowered half-typed.

use super::*;
use crate::base::WarningKind;

fn has_interval(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Interval { .. } => true,
        TermKind::Function { args, .. } => args.iter().flatten().any(has_interval),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => has_interval(arg),
        TermKind::Binary { lhs, rhs, .. } => has_interval(lhs) || has_interval(rhs),
        TermKind::Pool(ts) => ts.iter().any(has_interval),
        _ => false,
    }
}

/// True for a term whose value is computed by arithmetic (`X + 1`, `-X`, `|X|`).
fn is_arithmetic(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Binary { .. } => true,
        TermKind::Unary { arg, .. } => !matches!(arg.kind, TermKind::Function { .. }),
        TermKind::Paren(a) => is_arithmetic(a),
        _ => false,
    }
}

/// The variables of `t`; with `direct`, only those outside arithmetic (the ones a typing
/// literal `#s(t)` binds).
fn term_vars(t: &ast::Term, direct: bool, out: &mut HashSet<String>) {
    match &t.kind {
        TermKind::Variable(v) => {
            out.insert(v.to_string());
        }
        TermKind::Function { args, .. } => {
            for a in args.iter().flatten() {
                term_vars(a, direct, out);
            }
        }
        TermKind::Pool(ts) | TermKind::ScriptCall { args: ts, .. } => {
            for a in ts {
                term_vars(a, direct, out);
            }
        }
        TermKind::Paren(a) => term_vars(a, direct, out),
        TermKind::Unary { arg, .. } if !direct || !is_arithmetic(t) => term_vars(arg, direct, out),
        TermKind::Binary { lhs, rhs, .. } | TermKind::Interval { lo: lhs, hi: rhs } if !direct => {
            term_vars(lhs, direct, out);
            term_vars(rhs, direct, out);
        }
        _ => {}
    }
}

/// All variables of a literal.
fn literal_vars(l: &ast::Literal, out: &mut HashSet<String>) {
    match &l.atom {
        ast::Atom::Symbolic(a) => a
            .args
            .iter()
            .flatten()
            .for_each(|t| term_vars(t, false, out)),
        ast::Atom::Sort { arg, .. } => term_vars(arg, false, out),
        ast::Atom::Comparison { lhs, rhs, .. } => {
            term_vars(lhs, false, out);
            term_vars(rhs, false, out);
        }
        ast::Atom::Boolean(_) => {}
    }
}

/// The variables a literal binds once typed: those outside arithmetic in the arguments of a
/// predicate atom (its typing literal binds them) or of a positive sort atom.
fn bound_vars(l: &ast::Literal, out: &mut HashSet<String>) {
    match &l.atom {
        ast::Atom::Symbolic(a) => a
            .args
            .iter()
            .flatten()
            .for_each(|t| term_vars(t, true, out)),
        ast::Atom::Sort { arg, .. } if l.sign == Sign::Positive => term_vars(arg, true, out),
        _ => {}
    }
}

fn guard_vars(g: &Option<ast::Guard>, out: &mut HashSet<String>) {
    if let Some(g) = g {
        term_vars(&g.term, false, out);
    }
}

/// The variables global to a rule's body: those of its plain literals and aggregate guards
/// (a choice element's other variables are local to it, as in clingo).
fn body_vars(body: &[ast::BodyLiteral]) -> HashSet<String> {
    let mut out = HashSet::new();
    for b in body {
        match b {
            ast::BodyLiteral::Literal(l) => literal_vars(l, &mut out),
            ast::BodyLiteral::Aggregate { aggregate, .. } => {
                guard_vars(&aggregate.lower, &mut out);
                guard_vars(&aggregate.upper, &mut out);
            }
            ast::BodyLiteral::Conditional(_) | ast::BodyLiteral::Theory { .. } => {}
        }
    }
    out
}

pub(super) fn sort_literal(span: Span, sort: &str, arg: ast::Term) -> ast::Literal {
    ast::Literal {
        span,
        sign: Sign::Positive,
        atom: ast::Atom::Sort {
            sort: sort.to_string(),
            arg: Box::new(arg),
        },
    }
}

pub(super) fn variable(span: Span, name: &str) -> ast::Term {
    ast::Term {
        span,
        kind: TermKind::Variable(name.into()),
    }
}

/// The shape of an argument with variables, to check that its sort has an element of it.
enum Pattern {
    /// A variable: any element.
    Any,
    /// Arithmetic: any integer.
    Int,
    /// A ground subterm: that value.
    Value(SymId),
    /// `f(p1, ..., pn)` with the interned name (`None`: no symbol has that name).
    Fun(Option<crate::base::intern::Sym>, Vec<Pattern>),
}

impl Pattern {
    fn matches(&self, syms: &Symbols, v: SymId) -> bool {
        match self {
            Pattern::Any => true,
            Pattern::Int => syms.num(v).is_some(),
            Pattern::Value(x) => *x == v,
            Pattern::Fun(name, args) => match (name, syms.get(v)) {
                (
                    Some(n),
                    SymData::Fun {
                        name: m,
                        neg: false,
                        len,
                        ..
                    },
                ) if *n == m && len as usize == args.len() => args
                    .iter()
                    .zip(syms.args(v))
                    .all(|(p, &x)| p.matches(syms, x)),
                _ => false,
            },
        }
    }
}
impl Typing {
    /// The shape of an argument term (pool-free).
    fn pattern(rw: &mut Rewriter<'_>, t: &ast::Term) -> Option<Pattern> {
        Some(match &t.kind {
            TermKind::Variable(_) | TermKind::Anonymous => Pattern::Any,
            TermKind::Paren(a) => Self::pattern(rw, a)?,
            _ if !has_vars(t) => Pattern::Value(rw.eval_ground(t)?),
            _ if is_arithmetic(t) || matches!(t.kind, TermKind::Interval { .. }) => Pattern::Int,
            TermKind::Function { name, args, .. } if args.len() <= 1 => {
                let mut ps = Vec::new();
                for a in args.iter().flatten() {
                    ps.push(Self::pattern(rw, a)?);
                }
                Pattern::Fun(rw.syms.names.get(name), ps)
            }
            _ => Pattern::Any,
        })
    }

    /// The values of a variable-free argument, intervals expanded; `None` after an error.
    fn ground_values(rw: &mut Rewriter<'_>, t: &ast::Term) -> Option<Vec<SymId>> {
        let mut out = Vec::new();
        for t in unpool_term(t) {
            if has_interval(&t) {
                for t in expand_intervals(rw, &t)? {
                    out.push(rw.eval_ground(&t)?);
                }
            } else {
                out.push(rw.eval_ground(&t)?);
            }
        }
        Some(out)
    }

    /// Checks an atom against its declaration and returns the typing literals of its
    /// arguments with variables; `None` after reporting an error.
    fn typing(&self, rw: &mut Rewriter<'_>, a: &ast::SymbolicAtom) -> Option<Vec<ast::Literal>> {
        let args: Vec<ast::Term> = a.args.first().cloned().unwrap_or_default();
        let Some(sorts) = self.decls.get(a.name.as_str()) else {
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
        if sorts.iter().any(|s| self.failed.contains(s)) {
            return None;
        }
        let mut out = Vec::new();
        let note = format!("in an argument of {}/{}", a.name, args.len());
        for (t, sort) in args.iter().zip(sorts) {
            if has_vars(t) {
                if is_arithmetic(t) && !self.numeric.contains(sort) {
                    rw.diags.push(
                        Diagnostic::error(
                            t.span,
                            format!(
                                "arithmetic in an argument of sort #{sort}, which has no numbers"
                            ),
                        )
                        .with_snippet(snippet(rw, a.span))
                        .with_note(None, note),
                    );
                    return None;
                }
                for u in unpool_term(t) {
                    let p = Self::pattern(rw, &u)?;
                    if matches!(p, Pattern::Any) {
                        continue;
                    }
                    let elements = self.sorts.get(sort).map_or(&[][..], |v| &v[..]);
                    if !elements.iter().any(|&v| p.matches(rw.syms, v)) {
                        // SPARC accepts the rule with a warning; its typing literal can never
                        // hold, so the rule never applies.
                        let shown = snippet(rw, u.span);
                        rw.diags.push(
                            Diagnostic::warning(
                                WarningKind::Other,
                                u.span,
                                format!("'{shown}' does not belong to sort #{sort}: no element has its form; the literal never holds"),
                            )
                            .with_snippet(snippet(rw, a.span))
                            .with_note(None, note.clone()),
                        );
                    }
                }
                out.push(sort_literal(t.span, sort, t.clone()));
                continue;
            }
            for v in Self::ground_values(rw, t)? {
                if !self.members.get(sort).is_some_and(|m| m.contains(&v)) {
                    let shown = rw.syms.show(v);
                    rw.diags.push(
                        Diagnostic::error(t.span, format!("'{shown}' is not in sort #{sort}"))
                            .with_snippet(snippet(rw, a.span))
                            .with_note(None, note),
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

    /// Adds the sort atoms of disjunction or choice elements. An element with a condition
    /// gets them in its condition. Without one, a disjunction element's go to `extra` (the
    /// rule body); a choice element's go to the body when they type only variables of the
    /// body (`global`), and to the element's condition when they type its local variables.
    fn head_elements(
        &self,
        rw: &mut Rewriter<'_>,
        es: &mut [ast::ConditionalLiteral],
        extra: &mut Vec<ast::Literal>,
        local: Option<&HashSet<String>>,
    ) -> Option<()> {
        for e in es.iter_mut() {
            let t = self.literals(rw, std::slice::from_ref(&e.literal))?;
            let c = self.literals(rw, &e.condition)?;
            if !e.condition.is_empty() {
                e.condition.extend(t);
                e.condition.extend(c);
                continue;
            }
            for lit in t {
                let mut vars = HashSet::new();
                literal_vars(&lit, &mut vars);
                match local {
                    Some(global) if !vars.iter().all(|v| global.contains(v)) => {
                        e.condition.push(lit);
                        e.has_colon = true;
                    }
                    _ => extra.push(lit),
                }
            }
        }
        Some(())
    }

    /// `#nat(V)` for each variable of `vars` not in `bound`, in name order.
    fn nat_literals(
        &self,
        span: Span,
        vars: &HashSet<String>,
        bound: &HashSet<String>,
    ) -> Vec<ast::Literal> {
        if self.maxint.is_none() {
            return Vec::new();
        }
        let mut free: Vec<&String> = vars.iter().filter(|v| !bound.contains(*v)).collect();
        free.sort();
        free.into_iter()
            .map(|v| sort_literal(span, "nat", variable(span, v)))
            .collect()
    }

    pub(super) fn rule(
        &self,
        rw: &mut Rewriter<'_>,
        r: &ast::Rule,
        span: Span,
    ) -> Option<ast::Rule> {
        let mut r = r.clone();
        let mut extra: Vec<ast::Literal> = Vec::new();
        let mut global = body_vars(&r.body);
        match &mut r.head {
            ast::Head::None | ast::Head::Theory(_) => {}
            ast::Head::Disjunction(es) => self.head_elements(rw, es, &mut extra, None)?,
            ast::Head::Choice(c) => {
                guard_vars(&c.lower, &mut global);
                guard_vars(&c.upper, &mut global);
                self.head_elements(rw, &mut c.elements, &mut extra, Some(&global))?
            }
            ast::Head::Aggregate(h) => {
                guard_vars(&h.lower, &mut global);
                guard_vars(&h.upper, &mut global);
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
                ast::BodyLiteral::Theory { .. } => {}
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
                        // Local variables bound by no atom range over #nat.
                        let mut vars = HashSet::new();
                        e.terms.iter().for_each(|t| term_vars(t, false, &mut vars));
                        e.condition.iter().for_each(|l| literal_vars(l, &mut vars));
                        vars.retain(|v| !global.contains(v));
                        let mut bound = HashSet::new();
                        e.condition.iter().for_each(|l| bound_vars(l, &mut bound));
                        let nat = self.nat_literals(e.span, &vars, &bound);
                        e.condition.extend(nat);
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
        // Without #maxint, a variable that occurs only inside an arithmetic argument of a head
        // atom ranges over that argument's sort, as SPARC grounds it: `p(((X-1)/3)*3+(Y+2)/3).`
        // with `p(#num)` and `#num = 1..9` gives p(1)..p(9).
        if self.maxint.is_none() {
            let mut bound = HashSet::new();
            for l in &extra {
                bound_vars(l, &mut bound);
            }
            for b in &r.body {
                if let ast::BodyLiteral::Literal(l) = b {
                    bound_vars(l, &mut bound);
                }
            }
            let mut ranged = Vec::new();
            if let ast::Head::Disjunction(es) = &r.head {
                for e in es.iter().filter(|e| e.condition.is_empty()) {
                    let ast::Atom::Symbolic(a) = &e.literal.atom else {
                        continue;
                    };
                    let Some(sorts) = self.decls.get(a.name.as_str()) else {
                        continue;
                    };
                    let args = a.args.first().map_or(&[][..], |v| &v[..]);
                    for (t, sort) in args.iter().zip(sorts) {
                        if !is_arithmetic(t) || !self.numeric.contains(sort) {
                            continue;
                        }
                        let mut vars = HashSet::new();
                        term_vars(t, false, &mut vars);
                        let mut vars: Vec<String> =
                            vars.into_iter().filter(|v| !bound.contains(v)).collect();
                        vars.sort();
                        for v in vars {
                            bound.insert(v.clone());
                            ranged.push(sort_literal(t.span, sort, variable(t.span, &v)));
                        }
                    }
                }
            }
            extra.extend(ranged);
        }
        // Rule variables bound by no atom range over #nat (with #maxint).
        if self.maxint.is_some() {
            let mut vars = global;
            let mut bound = HashSet::new();
            if let ast::Head::Disjunction(es) = &r.head {
                for e in es.iter().filter(|e| e.condition.is_empty()) {
                    literal_vars(&e.literal, &mut vars);
                }
            }
            for l in &extra {
                bound_vars(l, &mut bound);
            }
            for b in &r.body {
                if let ast::BodyLiteral::Literal(l) = b {
                    bound_vars(l, &mut bound);
                }
            }
            extra.extend(self.nat_literals(span, &vars, &bound));
        }
        r.body
            .extend(extra.into_iter().map(ast::BodyLiteral::Literal));
        Some(r)
    }
}

/// `t` with every interval replaced by each of its integers (for variable-free arguments);
/// `None` after an error.
fn expand_intervals(rw: &mut Rewriter<'_>, t: &ast::Term) -> Option<Vec<ast::Term>> {
    let at = |kind| ast::Term { span: t.span, kind };
    Some(match &t.kind {
        TermKind::Interval { lo, hi } => {
            let (l, h) = (rw.eval_ground(lo)?, rw.eval_ground(hi)?);
            let (Some(l), Some(h)) = (rw.syms.num(l), rw.syms.num(h)) else {
                rw.diags.push(
                    Diagnostic::error(t.span, "an interval needs integer ends")
                        .with_snippet(snippet(rw, t.span)),
                );
                return None;
            };
            if i64::from(h) - i64::from(l) >= MAX_GENERATED as i64 {
                rw.diags.push(
                    Diagnostic::error(
                        t.span,
                        format!("interval {l}..{h} has more than {MAX_GENERATED} integers"),
                    )
                    .with_snippet(snippet(rw, t.span)),
                );
                return None;
            }
            (l..=h).map(|i| at(TermKind::Integer(i.into()))).collect()
        }
        TermKind::Paren(a) => expand_intervals(rw, a)?,
        TermKind::Unary { op, arg } => expand_intervals(rw, arg)?
            .into_iter()
            .map(|a| {
                at(TermKind::Unary {
                    op: *op,
                    arg: Box::new(a),
                })
            })
            .collect(),
        TermKind::Binary { op, lhs, rhs } => {
            let (ls, rs) = (expand_intervals(rw, lhs)?, expand_intervals(rw, rhs)?);
            let mut out = Vec::with_capacity(ls.len() * rs.len());
            for l in &ls {
                for r in &rs {
                    out.push(at(TermKind::Binary {
                        op: *op,
                        lhs: Box::new(l.clone()),
                        rhs: Box::new(r.clone()),
                    }));
                }
            }
            out
        }
        TermKind::Function {
            name,
            args,
            trailing_comma,
        } if args.len() == 1 => {
            let mut lists: Vec<Vec<ast::Term>> = vec![Vec::new()];
            for a in &args[0] {
                let vals = expand_intervals(rw, a)?;
                let mut next = Vec::with_capacity(lists.len() * vals.len());
                for l in &lists {
                    for v in &vals {
                        let mut l = l.clone();
                        l.push(v.clone());
                        next.push(l);
                    }
                }
                if next.len() > MAX_GENERATED {
                    rw.diags.push(
                        Diagnostic::error(
                            t.span,
                            format!(
                                "the intervals of this term make more than {MAX_GENERATED} terms"
                            ),
                        )
                        .with_snippet(snippet(rw, t.span)),
                    );
                    return None;
                }
                lists = next;
            }
            lists
                .into_iter()
                .map(|l| {
                    at(TermKind::Function {
                        name: name.clone(),
                        args: vec![l],
                        trailing_comma: *trailing_comma,
                    })
                })
                .collect()
        }
        _ => vec![t.clone()],
    })
}
