//! SPARC sorted programs (Balai, Gelfond, Zhang): sort definitions are evaluated to sets of
//! ground terms, predicate declarations type every argument position, and the program is
//! lowered to the clingo dialect the rest of the grounder understands.
//!
//! Rules implemented (SPARC's manual, iensen/sparc `User_Manual`):
//! - `#maxint = N.` bounds arithmetic: the built-in sort `#nat` is `0..N` (a program without
//!   `#maxint` has no `#nat`);
//! - a sort is the set its expression denotes: `{a, f(b)}` its elements, `lo..hi` the integers
//!   between (ends may be `#const` names; `hi < lo` is an error), `id1..id2` the identifiers
//!   `s` with `id1 <= s <= id2` and `|id1| <= |s| <= |id2|` over letters, digits and `_`
//!   (by character code; at most 100,000 of them), `[id][1..3]` the constants made by
//!   concatenating one choice per part (`id1`, `id2`, `id3`), `f(#s1, #s2)` every `f(x, y)`
//!   with `x` in `#s1` and `y` in `#s2` and, with variables `f(#s1(X), #s2(Y)) : c`, those
//!   satisfying the condition `c` (comparisons joined by `and`, `or`, `not(...)`), `+` union,
//!   `-` difference, `*` intersection, `#s` a sort defined earlier;
//! - errors: a sort defined twice, an empty sort, a predicate declared twice, an undefined
//!   sort, a record condition over variables it does not name, a concatenation of anything
//!   but identifiers and natural numbers, a range mixing an integer and an identifier;
//! - a sort `#s` becomes facts `#s(x)` of a hidden predicate;
//! - every atom `p(t1, ..., tn)` of a rule must match the declaration `p(#s1, ..., #sn)`: an
//!   undeclared predicate, a wrong arity, a ground argument (intervals expanded) outside its
//!   sort, an argument no element of the sort has the shape of (`g(X)` for a sort without
//!   `g`), or arithmetic in an argument whose sort has no numbers is an error at the atom;
//!   an argument with variables gets the typing literal `#si(ti)`, so every variable ranges
//!   over the sort of the positions it occupies. The typing literal goes to the rule body,
//!   except for an element of a choice or head aggregate, or a condition, whose own (local)
//!   variables it types: there it joins the element's condition (`1{has(X,C)}1 :- #r(X).`
//!   chooses one `C` of `has`'s second sort for each `X`);
//! - with `#maxint`, a variable that no atom argument binds outside arithmetic (it occurs
//!   only in comparisons or under `+ - * / \`) ranges over `#nat`;
//! - every declared predicate is `#defined` (SPARC programs get no "atom does not occur in
//!   any rule head" warnings for them);
//! - the `display` section becomes `#show` statements: `p.` shows every `p` atom, `-p.` every
//!   `-p` literal, a pattern `p(X, a).` the atoms matching it, `#s.` the sort's atoms; without
//!   a display section every atom is shown.

use hashbrown::{HashMap, HashSet};

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{
    self, CmpOp, RecordCondition, Sign, SortExpr, SortExprKind, StatementKind, TermKind,
};

use super::rewrite::{unpool_term, Rewriter};
use super::symbol::{SymData, SymId, Symbols};

/// Most elements an identifier range, or the interval expansion of one argument, may have
/// (SPARC's own sort capacity).
const MAX_GENERATED: usize = 100_000;

/// The characters of identifiers, in character-code order.
const ID_CHARS: &[u8] = b"0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ_abcdefghijklmnopqrstuvwxyz";

/// The evaluated sorts and predicate declarations of a SPARC program.
#[derive(Default)]
struct Typing {
    /// Elements of each sort (name without `#`), in definition order of first appearance.
    sorts: HashMap<String, Vec<SymId>>,
    /// The same as sets, for membership checks.
    members: HashMap<String, HashSet<SymId>>,
    /// The sorts with at least one integer.
    numeric: HashSet<String>,
    /// Where each sort was defined (`None` for the built-in `#nat`).
    sort_spans: HashMap<String, Option<Span>>,
    /// Argument sorts of each declared predicate.
    decls: HashMap<String, Vec<String>>,
    /// Where each predicate was declared.
    decl_spans: HashMap<String, Span>,
    /// The `#maxint` value, when the program sets one.
    maxint: Option<i32>,
    /// Sorts whose definition had an error (reported once: uses of them stay silent).
    failed: HashSet<String>,
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
            ast::BodyLiteral::Conditional(_) => {}
        }
    }
    out
}

fn sort_literal(span: Span, sort: &str, arg: ast::Term) -> ast::Literal {
    ast::Literal {
        span,
        sign: Sign::Positive,
        atom: ast::Atom::Sort {
            sort: sort.to_string(),
            arg: Box::new(arg),
        },
    }
}

fn variable(span: Span, name: &str) -> ast::Term {
    ast::Term {
        span,
        kind: TermKind::Variable(name.into()),
    }
}

fn push_unique(out: &mut Vec<SymId>, seen: &mut HashSet<SymId>, s: SymId) {
    if seen.insert(s) {
        out.push(s);
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
/// [`ID_CHARS`] compared by code, first character a lower-case letter); `false` when there are
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
    fn define(&mut self, rw: &mut Rewriter<'_>, name: &str, set: Vec<SymId>, span: Option<Span>) {
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
    fn undefined(&self, rw: &Rewriter<'_>, span: Span, name: &str) -> Diagnostic {
        let d = Diagnostic::error(span, format!("undefined sort #{name}"))
            .with_snippet(snippet(rw, span));
        if name == "nat" && self.maxint.is_none() {
            d.with_note(
                None,
                "#nat is the built-in sort 0..N of a program that sets #maxint = N.",
            )
        } else {
            d
        }
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
                        let shown = snippet(rw, u.span);
                        rw.diags.push(
                            Diagnostic::error(
                                u.span,
                                format!("'{shown}' does not belong to sort #{sort}: no element has its form"),
                            )
                            .with_snippet(snippet(rw, a.span))
                            .with_note(None, note),
                        );
                        return None;
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

    fn rule(&self, rw: &mut Rewriter<'_>, r: &ast::Rule, span: Span) -> Option<ast::Rule> {
        let mut r = r.clone();
        let mut extra: Vec<ast::Literal> = Vec::new();
        let mut global = body_vars(&r.body);
        match &mut r.head {
            ast::Head::None => {}
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

fn snippet(rw: &Rewriter<'_>, span: Span) -> String {
    match rw.sources {
        Some(s) if (span.file.0 as usize) < s.len() => s.get(span.file).slice(span).to_string(),
        _ => String::new(),
    }
}

/// Reports a second definition (`verb`: "defined", "declared") of `what`, pointing at the
/// first when it has a place.
fn twice(rw: &mut Rewriter<'_>, span: Span, what: String, verb: &str, first: Option<Span>) {
    let d =
        Diagnostic::error(span, format!("{what} is {verb} twice")).with_snippet(snippet(rw, span));
    rw.diags.push(match first {
        Some(f) => d.with_note(Some(f), format!("first {verb} here")),
        None => d.with_note(None, "#nat is built in: 0..#maxint"),
    });
}

/// Lowers a SPARC program to the clingo dialect: registers the sorts (as facts of `#s/1` in
/// `rw.out.sort_facts`) and returns the typed statements, every declared predicate
/// `#defined`, display items turned into `#show`.
pub fn lower(rw: &mut Rewriter<'_>, program: &ast::Program) -> ast::Program {
    let mut typing = Typing::default();
    let mut statements = Vec::new();
    let mut displays: Vec<(Span, &StatementKind)> = Vec::new();
    let user_nat = program
        .statements
        .iter()
        .any(|s| matches!(&s.kind, StatementKind::SortDef(d) if d.name == "nat"));
    for st in &program.statements {
        match &st.kind {
            StatementKind::MaxInt(t) => {
                let Some(v) = rw.eval_ground(t) else { continue };
                let n = rw.syms.num(v).filter(|&n| n >= 0);
                let Some(n) = n else {
                    rw.diags.push(
                        Diagnostic::error(t.span, "#maxint needs a non-negative integer")
                            .with_snippet(snippet(rw, st.span)),
                    );
                    continue;
                };
                if typing.maxint.is_some() {
                    rw.diags.push(
                        Diagnostic::error(st.span, "#maxint is set twice")
                            .with_snippet(snippet(rw, st.span)),
                    );
                    continue;
                }
                typing.maxint = Some(n);
                if !user_nat {
                    let set: Vec<SymId> = (0..=n).map(|i| rw.syms.int(i)).collect();
                    typing.define(rw, "nat", set, None);
                }
            }
            StatementKind::SortDef(d) => {
                if let Some(first) = typing.sort_spans.get(&d.name) {
                    let first = *first;
                    twice(rw, st.span, format!("sort #{}", d.name), "defined", first);
                    continue;
                }
                match typing.eval(rw, &d.expr) {
                    Some(set) if !set.is_empty() => typing.define(rw, &d.name, set, Some(st.span)),
                    failed => {
                        if failed.is_some() {
                            rw.diags.push(
                                Diagnostic::error(st.span, format!("sort #{} is empty", d.name))
                                    .with_snippet(snippet(rw, st.span)),
                            );
                        }
                        typing.failed.insert(d.name.clone());
                        typing.sort_spans.insert(d.name.clone(), Some(st.span));
                        rw.sorts.push(format!("#{}", d.name));
                    }
                }
            }
            StatementKind::PredicateDecl(p) => {
                if let Some(&first) = typing.decl_spans.get(&p.name) {
                    twice(
                        rw,
                        st.span,
                        format!("predicate {}", p.name),
                        "declared",
                        Some(first),
                    );
                    continue;
                }
                for s in &p.sorts {
                    if !typing.sorts.contains_key(s) && !typing.failed.contains(s) {
                        let d = typing.undefined(rw, st.span, s);
                        rw.diags.push(d);
                    }
                }
                typing.decl_spans.insert(p.name.clone(), st.span);
                typing.decls.insert(p.name.clone(), p.sorts.clone());
            }
            StatementKind::Section(_) => {}
            StatementKind::Display(_) | StatementKind::DisplaySort(_) => {
                displays.push((st.span, &st.kind))
            }
            StatementKind::Rule(r) => {
                if let Some(r) = typing.rule(rw, r, st.span) {
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
    // Declared predicates are defined: no "atom does not occur in any rule head" for them.
    let mut declared: Vec<(&String, &Span)> = typing.decl_spans.iter().collect();
    declared.sort_by_key(|(_, s)| (s.file.0, s.start));
    for (name, &span) in declared {
        for negated in [false, true] {
            statements.push(ast::Statement {
                span,
                kind: StatementKind::Defined(ast::Signature {
                    negated,
                    name: name.clone(),
                    arity: typing.decls[name].len() as u32,
                }),
            });
        }
    }
    // display: `p.` shows the predicate, `#s.` the sort, a pattern the atoms matching it.
    for (span, item) in displays {
        let sort_item;
        let l = match item {
            StatementKind::DisplaySort(sort) => {
                if !typing.sorts.contains_key(sort) {
                    let d = typing.undefined(rw, span, sort);
                    rw.diags.push(d);
                    continue;
                }
                // `#s.` is the pattern `#s(X).`: sort predicates are never shown by name.
                sort_item = sort_literal(span, sort, variable(span, "X"));
                &sort_item
            }
            StatementKind::Display(l) => &**l,
            _ => continue,
        };
        match &l.atom {
            ast::Atom::Symbolic(a) if a.args.iter().all(|list| list.is_empty()) => {
                let arity = typing.decls.get(a.name.as_str()).map_or(0, |d| d.len()) as u32;
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Signature(ast::Signature {
                        negated: a.negated,
                        name: a.name.to_string(),
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
                        name: format!("#{sort}").into(),
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
