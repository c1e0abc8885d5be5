//! SPARC sort definitions evaluated to sets of ground terms: enumerations, integer and
//! identifier ranges, concatenations, records with conditions, and the set operations
//! `+ - *` (the rules are listed in the module above).
//!
//! Invariants: a sort's elements are distinct and in order of first appearance; no sort
//! expression generates more than `MAX_GENERATED` elements; a sort whose definition failed
//! is reported once and then recorded in `Typing::failed`, so its uses stay silent.

use super::*;

fn push_unique(out: &mut Vec<SymId>, seen: &mut HashSet<SymId>, s: SymId) {
    if seen.insert(s) {
        out.push(s);
    }
}

/// A record condition with its operands resolved: variables by their argument position,
/// constants by value.
enum Cond {
    Cmp(Operand, CmpOp, Operand),
    And(Box<Cond>, Box<Cond>),
    Or(Box<Cond>, Box<Cond>),
    Not(Box<Cond>),
}

enum Operand {
    Arg(usize),
    Value(SymId),
}

impl Cond {
    fn holds(&self, syms: &Symbols, tuple: &[SymId]) -> bool {
        match self {
            Cond::Cmp(a, op, b) => {
                let get = |o: &Operand| match o {
                    Operand::Arg(i) => tuple[*i],
                    Operand::Value(v) => *v,
                };
                let ord = syms.compare(get(a), get(b));
                match op {
                    CmpOp::Eq => ord.is_eq(),
                    CmpOp::Ne => ord.is_ne(),
                    CmpOp::Lt => ord.is_lt(),
                    CmpOp::Le => ord.is_le(),
                    CmpOp::Gt => ord.is_gt(),
                    CmpOp::Ge => ord.is_ge(),
                }
            }
            Cond::And(a, b) => a.holds(syms, tuple) && b.holds(syms, tuple),
            Cond::Or(a, b) => a.holds(syms, tuple) || b.holds(syms, tuple),
            Cond::Not(a) => !a.holds(syms, tuple),
        }
    }
}

/// The identifiers `s` with `lo <= s <= hi` and `|lo| <= |s| <= |hi|` (characters of
/// [`ID_CHARS`], lower-case letters, compared by code); `false` when there are
/// more than [`MAX_GENERATED`].
fn identifier_range(lo: &[u8], hi: &[u8], out: &mut Vec<String>) -> bool {
    fn go(
        lo: &[u8],
        hi: &[u8],
        len: usize,
        tight: (bool, bool),
        buf: &mut Vec<u8>,
        out: &mut Vec<String>,
    ) -> bool {
        let i = buf.len();
        if i == len {
            out.push(String::from_utf8_lossy(buf).into_owned());
            return out.len() <= MAX_GENERATED;
        }
        for &c in ID_CHARS {
            if i == 0 && !c.is_ascii_lowercase() {
                continue;
            }
            // Still equal to `lo` so far: stay at or above it (a longer string with `lo` as a
            // prefix is above it).
            if tight.0 && i < lo.len() && c < lo[i] {
                continue;
            }
            if tight.1 && c > hi[i] {
                break;
            }
            let next = (tight.0 && i < lo.len() && c == lo[i], tight.1 && c == hi[i]);
            buf.push(c);
            if !go(lo, hi, len, next, buf, out) {
                return false;
            }
            buf.pop();
        }
        true
    }
    let mut buf = Vec::with_capacity(hi.len());
    (lo.len()..=hi.len()).all(|len| go(lo, hi, len, (true, true), &mut buf, out))
}

/// The name of a plain constant symbol.
fn constant_name(syms: &Symbols, v: SymId) -> Option<String> {
    match syms.get(v) {
        SymData::Fun {
            name,
            neg: false,
            len: 0,
            ..
        } => {
            let n = syms.names.resolve(name);
            (!n.is_empty()).then(|| n.to_string())
        }
        _ => None,
    }
}

impl Typing {
    /// Records the sort `name` with its elements (`span`: its definition, `None` if built in).
    pub(super) fn define(
        &mut self,
        rw: &mut Rewriter<'_>,
        name: &str,
        set: Vec<SymId>,
        span: Option<Span>,
    ) {
        if set.iter().any(|&v| rw.syms.num(v).is_some()) {
            self.numeric.insert(name.to_string());
        }
        self.members
            .insert(name.to_string(), set.iter().copied().collect());
        self.sorts.insert(name.to_string(), set);
        self.sort_spans.insert(name.to_string(), span);
        rw.sorts.push(format!("#{name}"));
    }

    /// Evaluates a sort expression; `None` after reporting an error.
    pub(super) fn eval(&self, rw: &mut Rewriter<'_>, e: &SortExpr) -> Option<Vec<SymId>> {
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
                let (l, h) = (rw.eval_ground(lo)?, rw.eval_ground(hi)?);
                match (rw.syms.num(l), rw.syms.num(h)) {
                    (Some(l), Some(h)) => {
                        if l > h {
                            rw.diags.push(
                                Diagnostic::error(
                                    e.span,
                                    format!("range {l}..{h} is empty: {l} is greater than {h}"),
                                )
                                .with_snippet(snippet(rw, e.span)),
                            );
                            return None;
                        }
                        for i in l..=h {
                            let v = rw.syms.int(i);
                            push_unique(&mut out, &mut seen, v);
                        }
                    }
                    _ => {
                        let names = (constant_name(rw.syms, l), constant_name(rw.syms, h));
                        let (Some(a), Some(b)) = names else {
                            let (l, h) = (rw.syms.show(l), rw.syms.show(h));
                            rw.diags.push(
                                Diagnostic::error(
                                    e.span,
                                    format!(
                                        "range {l}..{h} needs two integers or two \
                                         identifiers as ends"
                                    ),
                                )
                                .with_snippet(snippet(rw, e.span))
                                .with_note(
                                    None,
                                    "an identifier next to an integer is often a #const \
                                     that is not defined",
                                ),
                            );
                            return None;
                        };
                        let problem = if a > b {
                            Some(format!("{a} comes after {b}"))
                        } else if a.len() > b.len() {
                            Some(format!("{a} is longer than {b}"))
                        } else {
                            None
                        };
                        if let Some(problem) = problem {
                            rw.diags.push(
                                Diagnostic::error(
                                    e.span,
                                    format!("identifier range {a}..{b} is empty: {problem}"),
                                )
                                .with_snippet(snippet(rw, e.span)),
                            );
                            return None;
                        }
                        let mut ids = Vec::new();
                        if !identifier_range(a.as_bytes(), b.as_bytes(), &mut ids) {
                            rw.diags.push(
                                Diagnostic::error(
                                    e.span,
                                    format!(
                                        "identifier range {a}..{b} has more than \
                                         {MAX_GENERATED} elements"
                                    ),
                                )
                                .with_snippet(snippet(rw, e.span)),
                            );
                            return None;
                        }
                        for id in ids {
                            let v = rw.syms.fun_str(&id, false, &[]);
                            push_unique(&mut out, &mut seen, v);
                        }
                    }
                }
            }
            SortExprKind::Ref(name) => match self.sorts.get(name) {
                Some(v) => out = v.clone(),
                None => {
                    if !self.failed.contains(name) {
                        rw.diags.push(self.undefined(rw, e.span, name));
                    }
                    return None;
                }
            },
            SortExprKind::Concat(parts) => {
                let mut texts = vec![String::new()];
                for p in parts {
                    let vals = self.eval(rw, p)?;
                    // Only basic sorts (identifiers and integers) concatenate.
                    let basic = |v: SymId| {
                        rw.syms.num(v).is_some_and(|n| n >= 0)
                            || constant_name(rw.syms, v).is_some()
                    };
                    if let Some(&bad) = vals.iter().find(|&&v| !basic(v)) {
                        let shown = rw.syms.show(bad);
                        rw.diags.push(
                            Diagnostic::error(
                                p.span,
                                format!(
                                    "a concatenation joins identifiers and natural numbers, \
                                     not '{shown}'"
                                ),
                            )
                            .with_snippet(snippet(rw, p.span)),
                        );
                        return None;
                    }
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
                let cond = match condition {
                    Some(c) => Some(self.record_condition(rw, args, c, e.span)?),
                    None => None,
                };
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
                    if cond.as_ref().is_none_or(|c| c.holds(rw.syms, &t)) {
                        let v = rw.syms.fun_str(name, false, &t);
                        push_unique(&mut out, &mut seen, v);
                    }
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

    /// The error for a sort name that is not defined.
    pub(super) fn undefined(&self, rw: &Rewriter<'_>, span: Span, name: &str) -> Diagnostic {
        Diagnostic::error(span, format!("undefined sort #{name}")).with_snippet(snippet(rw, span))
    }

    /// Resolves a record condition against the record's variables; `None` after an error.
    fn record_condition(
        &self,
        rw: &mut Rewriter<'_>,
        args: &[(SortExpr, Option<String>)],
        c: &RecordCondition,
        span: Span,
    ) -> Option<Cond> {
        let mut names: Vec<&str> = Vec::new();
        for (_, v) in args {
            if let Some(v) = v {
                if names.contains(&v.as_str()) {
                    rw.diags.push(
                        Diagnostic::error(
                            span,
                            format!("variable {v} names two arguments of the record"),
                        )
                        .with_snippet(snippet(rw, span)),
                    );
                    return None;
                }
                names.push(v);
            }
        }
        let position = |v: &str| args.iter().position(|(_, n)| n.as_deref() == Some(v));
        let mut operand = |rw: &mut Rewriter<'_>, t: &ast::Term| -> Option<Operand> {
            if let TermKind::Variable(v) = &t.kind {
                if let Some(i) = position(v) {
                    return Some(Operand::Arg(i));
                }
                rw.diags.push(
                    Diagnostic::error(
                        t.span,
                        format!("variable {v} is not a variable of the record"),
                    )
                    .with_snippet(snippet(rw, t.span)),
                );
                return None;
            }
            if has_vars(t) {
                rw.diags.push(
                    Diagnostic::error(
                        t.span,
                        "a record condition compares variables and constants only",
                    )
                    .with_snippet(snippet(rw, t.span)),
                );
                return None;
            }
            rw.eval_ground(t).map(Operand::Value)
        };
        fn go(
            rw: &mut Rewriter<'_>,
            c: &RecordCondition,
            operand: &mut dyn FnMut(&mut Rewriter<'_>, &ast::Term) -> Option<Operand>,
        ) -> Option<Cond> {
            Some(match c {
                RecordCondition::Compare { lhs, op, rhs } => {
                    Cond::Cmp(operand(rw, lhs)?, *op, operand(rw, rhs)?)
                }
                RecordCondition::And(a, b) => {
                    Cond::And(Box::new(go(rw, a, operand)?), Box::new(go(rw, b, operand)?))
                }
                RecordCondition::Or(a, b) => {
                    Cond::Or(Box::new(go(rw, a, operand)?), Box::new(go(rw, b, operand)?))
                }
                RecordCondition::Not(a) => Cond::Not(Box::new(go(rw, a, operand)?)),
                RecordCondition::Paren(a) => go(rw, a, operand)?,
            })
        }
        go(rw, c, &mut operand)
    }
}

/// Whether the program names the sort `#name` anywhere: a predicate declaration, a sort
/// definition, a display item or a sort atom of a rule.
pub(super) fn mentions_sort(program: &ast::Program, name: &str) -> bool {
    fn in_expr(e: &SortExpr, name: &str) -> bool {
        match &e.kind {
            SortExprKind::Ref(r) => r == name,
            SortExprKind::Set(_) | SortExprKind::Range(..) => false,
            SortExprKind::Concat(parts) => parts.iter().any(|p| in_expr(p, name)),
            SortExprKind::Record { args, .. } => args.iter().any(|(e, _)| in_expr(e, name)),
            SortExprKind::Union(a, b)
            | SortExprKind::Difference(a, b)
            | SortExprKind::Intersection(a, b) => in_expr(a, name) || in_expr(b, name),
            SortExprKind::Paren(a) => in_expr(a, name),
        }
    }
    let lit = |l: &ast::Literal| matches!(&l.atom, ast::Atom::Sort { sort, .. } if sort == name);
    let cond = |c: &ast::ConditionalLiteral| lit(&c.literal) || c.condition.iter().any(lit);
    let in_rule = |r: &ast::Rule| {
        let head = match &r.head {
            ast::Head::None => false,
            ast::Head::Disjunction(es) => es.iter().any(cond),
            ast::Head::Choice(c) => c.elements.iter().any(cond),
            ast::Head::Aggregate(h) => h
                .elements
                .iter()
                .any(|e| lit(&e.literal) || e.condition.iter().any(lit)),
            ast::Head::Theory(a) => a.elements.iter().any(|e| e.condition.iter().any(lit)),
        };
        head || r.body.iter().any(|b| match b {
            ast::BodyLiteral::Literal(l) => lit(l),
            ast::BodyLiteral::Conditional(c) => cond(c),
            ast::BodyLiteral::Aggregate { aggregate, .. } => {
                aggregate
                    .elements
                    .iter()
                    .any(|e| e.condition.iter().any(lit))
                    || aggregate.set_syntax.iter().any(cond)
            }
            ast::BodyLiteral::Theory { atom, .. } => {
                atom.elements.iter().any(|e| e.condition.iter().any(lit))
            }
        })
    };
    program.statements.iter().any(|st| match &st.kind {
        StatementKind::PredicateDecl(p) => p.sorts.iter().any(|s| s == name),
        StatementKind::SortDef(d) => in_expr(&d.expr, name),
        StatementKind::DisplaySort(s) => s == name,
        StatementKind::Rule(r) => in_rule(r),
        _ => false,
    })
}
