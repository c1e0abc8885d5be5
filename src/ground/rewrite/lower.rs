//! Lowering: pool-free terms, atoms, literals, guards, body aggregates, conditions and head
//! elements to their rewritten forms (`NTerm`, `NLit`, ...); intervals, external function
//! calls `@f(...)` and anonymous variables become fresh variables, ground arithmetic is folded.
//!
//! Invariant: every variable gets a slot of the statement's `Vars`; an interval or a call adds
//! the literal that binds its variable (gringo's script literal for calls).

use super::pool::*;
use super::*;

impl Rewriter<'_> {
    /// Compiles a pool-free term; intervals add binder literals to `extra`.
    pub(super) fn term(
        &mut self,
        t: &ast::Term,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NTerm> {
        Some(match &t.kind {
            // clingo reads an integer literal modulo 2^32 (`2147483648` is `-2147483648`,
            // `0x80000000` too), as its arithmetic wraps: the truncating cast does the same.
            TermKind::Integer(n) => NTerm::Sym(self.syms.int(*n as i32)),
            TermKind::String(s) => NTerm::Sym(self.syms.string(s)),
            TermKind::Constant(c) => match self.consts.get(c.as_str()) {
                Some(&v) => NTerm::Sym(v),
                None => {
                    let name = self.name_id(c);
                    NTerm::Sym(self.syms.fun(name, false, &[]))
                }
            },
            TermKind::Variable(v) => NTerm::Var(vars.slot(self.name_id(v), t.span)),
            TermKind::Anonymous => NTerm::Var(vars.fresh(&mut self.syms.names, "Anon", t.span)),
            TermKind::Infimum => NTerm::Sym(self.syms.inf()),
            TermKind::Supremum => NTerm::Sym(self.syms.sup()),
            TermKind::Function { name, args, .. } => {
                let list: &[ast::Term] = args.first().map_or(&[], Vec::as_slice);
                let mut nargs = Vec::with_capacity(list.len());
                for a in list {
                    nargs.push(self.term(a, vars, extra)?);
                }
                let name_sym = self.name_id(name);
                self.fold_fun(name_sym, false, nargs)
            }
            TermKind::ScriptCall { name, args } => {
                if !self.calls {
                    self.unsupported(
                        t.span,
                        "external function call without a grounding context (lucent runs no \
                         #script; from Rust use Control::ground_with_context, from Python \
                         ground(parts, context=...))",
                    );
                    return None;
                }
                let mut nargs = Vec::with_capacity(args.len());
                for a in args {
                    nargs.push(self.term(a, vars, extra)?);
                }
                let name = self.syms.names.intern(name);
                let v = vars.fresh(&mut self.syms.names, "Call", t.span);
                extra.push(NLit::Call {
                    pat: NTerm::Var(v),
                    name,
                    args: nargs,
                    span: t.span,
                });
                NTerm::Var(v)
            }
            TermKind::Unary { op, arg } => {
                let a = self.term(arg, vars, extra)?;
                match (op, a) {
                    (ast::UnaryOp::Minus, NTerm::Fun { name, neg, args })
                        if !self.syms.names.resolve(name).is_empty() =>
                    {
                        NTerm::Fun {
                            name,
                            neg: !neg,
                            args,
                        }
                    }
                    (op, a) => self.fold(NTerm::Unary {
                        op: *op,
                        arg: Box::new(a),
                        span: t.span,
                    }),
                }
            }
            TermKind::Binary { op, lhs, rhs } => {
                let l = self.term(lhs, vars, extra)?;
                let r = self.term(rhs, vars, extra)?;
                self.fold(NTerm::Binary {
                    op: *op,
                    lhs: Box::new(l),
                    rhs: Box::new(r),
                    span: t.span,
                })
            }
            TermKind::Interval { lo, hi } => {
                let lo = self.term(lo, vars, extra)?;
                let hi = self.term(hi, vars, extra)?;
                let v = vars.fresh(&mut self.syms.names, "Range", t.span);
                extra.push(NLit::Interval {
                    pat: NTerm::Var(v),
                    lo,
                    hi,
                });
                NTerm::Var(v)
            }
            TermKind::Pool(alts) if alts.len() == 1 => self.term(&alts[0], vars, extra)?,
            TermKind::Pool(_) => {
                self.unsupported(t.span, "pool in this position");
                return None;
            }
            TermKind::Paren(inner) => self.term(inner, vars, extra)?,
        })
    }

    pub(super) fn fold_fun(&mut self, name: Sym, neg: bool, args: Vec<NTerm>) -> NTerm {
        if args.iter().all(|a| matches!(a, NTerm::Sym(_))) {
            let vals: Vec<SymId> = args
                .iter()
                .map(|a| match a {
                    NTerm::Sym(s) => *s,
                    _ => unreachable!("checked above"),
                })
                .collect();
            NTerm::Sym(self.syms.fun(name, neg, &vals))
        } else {
            NTerm::Fun { name, neg, args }
        }
    }

    /// Folds ground operations whose value is defined (undefined ones stay, so grounding
    /// reports them where they are used).
    pub(super) fn fold(&mut self, t: NTerm) -> NTerm {
        if t.is_ground() {
            if let Ok(v) = t.eval(self.syms, &crate::ground::term::Binding::new(0)) {
                return NTerm::Sym(v);
            }
        }
        t
    }

    /// The term with the shape of a compiled atom.
    pub(super) fn atom_term(&mut self, a: &NAtom) -> NTerm {
        self.fold_fun(a.name, a.neg, a.args.clone())
    }

    pub(super) fn atom(
        &mut self,
        a: &ast::SymbolicAtom,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NAtom> {
        let list: &[ast::Term] = a.args.first().map_or(&[], Vec::as_slice);
        let mut args = Vec::with_capacity(list.len());
        for t in list {
            args.push(self.term(t, vars, extra)?);
        }
        let name = self.name_id(&a.name);
        let pred = self.pred_of(name, args.len() as u32, a.negated);
        Some(NAtom {
            pred,
            name,
            neg: a.negated,
            args,
            span: a.span,
            sort: false,
        })
    }

    pub(super) fn literal(
        &mut self,
        l: &ast::Literal,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NLit> {
        Some(match &l.atom {
            ast::Atom::Symbolic(a) => NLit::Pred {
                sign: l.sign,
                atom: self.atom(a, vars, extra)?,
            },
            ast::Atom::Comparison { lhs, op, rhs } => {
                let op = if l.sign == Sign::Not {
                    negate_cmp(*op)
                } else {
                    *op
                };
                NLit::Cmp {
                    op,
                    lhs: self.term(lhs, vars, extra)?,
                    rhs: self.term(rhs, vars, extra)?,
                }
            }
            ast::Atom::Boolean(b) => NLit::Bool(if l.sign == Sign::Not { !*b } else { *b }),
            ast::Atom::Sort { sort, arg } => {
                let name = format!("#{sort}");
                if !self.sorts.contains(&name) {
                    self.diags.push(
                        Diagnostic::error(l.span, format!("undefined sort #{sort}"))
                            .with_snippet(self.snippet(l.span)),
                    );
                    return None;
                }
                let t = self.term(arg, vars, extra)?;
                let pred = self.pred(&name, 1, false);
                let atom = NAtom {
                    pred,
                    name: self.syms.names.intern(&name),
                    neg: false,
                    args: vec![t],
                    span: l.span,
                    sort: true,
                };
                NLit::Pred { sign: l.sign, atom }
            }
        })
    }

    /// Compiles a condition (list of literals) into `out`.
    pub(super) fn condition(
        &mut self,
        lits: &[ast::Literal],
        vars: &mut Vars,
        out: &mut Vec<NLit>,
    ) -> Option<()> {
        for l in lits {
            let mut extra = Vec::new();
            let n = self.literal(l, vars, &mut extra)?;
            out.append(&mut extra);
            out.push(n);
        }
        Some(())
    }

    pub(super) fn guard(
        &mut self,
        g: &ast::Guard,
        left: bool,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<(CmpOp, NTerm)> {
        let op = if left { flip_cmp(g.op) } else { g.op };
        Some((op, self.term(&g.term, vars, extra)?))
    }

    pub(super) fn body_aggregate(
        &mut self,
        sign: Sign,
        a: &ast::BodyAggregate,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NLit> {
        let mut guards = Vec::new();
        if let Some(g) = &a.lower {
            guards.push(self.guard(g, true, vars, extra)?);
        }
        if let Some(g) = &a.upper {
            guards.push(self.guard(g, false, vars, extra)?);
        }
        let mut elems = Vec::new();
        for e in &a.elements {
            let mut cond = Vec::new();
            let mut terms = Vec::new();
            for t in &e.terms {
                terms.push(self.term(t, vars, &mut cond)?);
            }
            self.condition(&e.condition, vars, &mut cond)?;
            elems.push(NElem {
                terms,
                cond,
                lit: None,
            });
        }
        for c in &a.set_syntax {
            // `{ l : c }` counts the distinct atoms l (with their conditions).
            let mut cond = Vec::new();
            if !matches!(c.literal.atom, ast::Atom::Symbolic(_)) {
                self.unsupported(c.span, "non-atomic element in a set aggregate");
                return None;
            }
            let mut lits = vec![c.literal.clone()];
            lits.extend(c.condition.iter().cloned());
            self.condition(&lits, vars, &mut cond)?;
            // The tuple is the atom itself, with the variables (and interval variables) of
            // its compiled form.
            let t = cond
                .iter()
                .find_map(|l| match l {
                    NLit::Pred { atom, .. } => Some(self.atom_term(atom)),
                    _ => None,
                })
                .expect("the element literal was compiled");
            elems.push(NElem {
                terms: vec![t],
                cond,
                lit: None,
            });
        }
        Some(NLit::Agg(Box::new(NAgg {
            sign,
            func: a.function,
            guards,
            binder: None,
            elems,
            theory: None,
        })))
    }

    pub(super) fn body(
        &mut self,
        body: &[ast::BodyLiteral],
        vars: &mut Vars,
        out: &mut Vec<NLit>,
    ) -> Option<()> {
        for b in body {
            let mut extra = Vec::new();
            let n = match b {
                ast::BodyLiteral::Literal(l)
                    if l.sign != Sign::Positive && has_anonymous_arg(l) =>
                {
                    let p = self.project(l);
                    self.literal(&p, vars, &mut extra)?
                }
                ast::BodyLiteral::Literal(l) => self.literal(l, vars, &mut extra)?,
                ast::BodyLiteral::Aggregate { sign, aggregate } => {
                    self.body_aggregate(*sign, aggregate, vars, &mut extra)?
                }
                ast::BodyLiteral::Theory { sign, atom } => {
                    self.theory_atom(*sign, atom, theory::Position::Body, vars, &mut extra)?
                }
                ast::BodyLiteral::Conditional(c) => {
                    // l : c holds when every instance of c has l; kept as a guard-less
                    // aggregate with one element that the instantiator treats specially.
                    let mut cond = Vec::new();
                    self.condition(&c.condition, vars, &mut cond)?;
                    let mut alts = Vec::new();
                    for l in unpool_literal(&c.literal) {
                        let mut alt = Vec::new();
                        self.condition(std::slice::from_ref(&l), vars, &mut alt)?;
                        alts.push(alt);
                    }
                    NLit::Agg(Box::new(NAgg {
                        sign: Sign::Positive,
                        func: AggregateFunction::Count,
                        guards: Vec::new(),
                        binder: None,
                        elems: vec![NElem {
                            terms: Vec::new(),
                            cond,
                            lit: Some(alts),
                        }],
                        theory: None,
                    }))
                }
            };
            out.append(&mut extra);
            out.push(n);
        }
        Some(())
    }

    /// `not p(X,_)` is `not #projN(X)` with `#projN(P) :- p(P,_).` (gringo projects anonymous
    /// variables out of negated atoms the same way).
    pub(super) fn project(&mut self, l: &ast::Literal) -> ast::Literal {
        let ast::Atom::Symbolic(a) = &l.atom else {
            return l.clone();
        };
        self.projections += 1;
        let name = format!("#proj{}", self.projections);
        let args: &[ast::Term] = a.args.first().map_or(&[], Vec::as_slice);
        let mut head_args = Vec::new();
        let mut body_args = Vec::new();
        let mut lit_args = Vec::new();
        for (i, t) in args.iter().enumerate() {
            if matches!(t.kind, TermKind::Anonymous) {
                body_args.push(t.clone());
            } else {
                let v = ast::Term {
                    span: t.span,
                    kind: TermKind::Variable(format!("#P{i}").into()),
                };
                head_args.push(v.clone());
                body_args.push(v);
                lit_args.push(t.clone());
            }
        }
        let mk = |name: &str, negated: bool, args: Vec<ast::Term>| ast::SymbolicAtom {
            span: a.span,
            negated,
            name: name.into(),
            args: vec![args],
        };
        let rule = ast::Rule {
            head: ast::Head::Disjunction(vec![ast::ConditionalLiteral {
                span: a.span,
                literal: ast::Literal {
                    span: a.span,
                    sign: Sign::Positive,
                    atom: ast::Atom::Symbolic(mk(&name, false, head_args)),
                },
                condition: Vec::new(),
                has_colon: false,
            }]),
            body: vec![ast::BodyLiteral::Literal(ast::Literal {
                span: l.span,
                sign: Sign::Positive,
                atom: ast::Atom::Symbolic(mk(&a.name, a.negated, body_args)),
            })],
            kind: ast::RuleKind::Normal,
        };
        let (index, span) = self.current;
        let role = self.aux_role.replace(AuxKind::Projection);
        self.rule(index, span, &rule);
        self.aux_role = role;
        self.current = (index, span);
        ast::Literal {
            span: l.span,
            sign: l.sign,
            atom: ast::Atom::Symbolic(mk(&name, false, lit_args)),
        }
    }

    pub(super) fn head_elem(
        &mut self,
        c: &ast::ConditionalLiteral,
        vars: &mut Vars,
        body_extra: &mut Vec<NLit>,
    ) -> Option<NCondLit> {
        let ast::Atom::Symbolic(a) = &c.literal.atom else {
            if let ast::Atom::Boolean(false) = c.literal.atom {
                // `#false` in a head: an empty disjunction element.
                self.unsupported(c.span, "#false in a disjunctive head with other elements");
            } else {
                self.unsupported(c.span, "this head literal");
            }
            return None;
        };
        if c.literal.sign != Sign::Positive {
            self.unsupported(c.span, "default negation in rule heads");
            return None;
        }
        let mut cond = Vec::new();
        let atom = if c.condition.is_empty() {
            self.atom(a, vars, body_extra)?
        } else {
            let at = self.atom(a, vars, &mut cond)?;
            self.condition(&c.condition, vars, &mut cond)?;
            at
        };
        Some(NCondLit {
            atom,
            cond,
            conj: Vec::new(),
        })
    }

    /// A disjunction element written with a colon, `l : c`, read as gringo does: it holds
    /// when `c` and every instance of `l` hold, where `l`'s pools and intervals give the
    /// instances (an undefined instance is left out, so an element without any is `c`).
    pub(super) fn disj_elem(
        &mut self,
        c: &ast::ConditionalLiteral,
        vars: &mut Vars,
    ) -> Option<NCondLit> {
        let mut conj = Vec::new();
        for l in unpool_literal(&c.literal) {
            let ast::Atom::Symbolic(a) = &l.atom else {
                self.unsupported(c.span, "this head literal");
                return None;
            };
            let mut expand = Vec::new();
            let atom = self.atom(a, vars, &mut expand)?;
            conj.push(NHeadLit {
                sign: l.sign,
                atom,
                expand,
            });
        }
        let mut cond = Vec::new();
        self.condition(&c.condition, vars, &mut cond)?;
        Some(NCondLit {
            atom: conj[0].atom.clone(),
            cond,
            conj,
        })
    }

    /// The element `t1,...,tn : a : c` of a head aggregate chooses `a` only for the instances
    /// whose tuple is defined and, for `#sum` and `#sum+`, whose weight `t1` is an integer, as
    /// in clingo. Adds to the element's condition `t = t` for each tuple term with an
    /// operation and `t1+0 = t1+0` for a non-integer sum weight (gringo's own check: clingo
    /// reports `operation undefined: (X+0)`). Returns false when the element can never count.
    pub(super) fn tuple_checks(
        &mut self,
        func: AggregateFunction,
        terms: &[ast::Term],
        vars: &mut Vars,
        cond: &mut Vec<NLit>,
    ) -> bool {
        let sum = matches!(func, AggregateFunction::Sum | AggregateFunction::SumPlus);
        for (i, t) in terms.iter().enumerate() {
            let mut scratch = Vec::new();
            let Some(nt) = self.term(t, vars, &mut scratch) else {
                return false;
            };
            if !scratch.is_empty() {
                // An interval: always defined, and already a number when it is the weight.
                continue;
            }
            let check = if sum && i == 0 {
                match nt {
                    NTerm::Sym(v) if self.syms.num(v).is_some() => continue,
                    NTerm::Sym(_) => return false,
                    NTerm::Var(_)
                    | NTerm::Fun { .. }
                    | NTerm::Unary { .. }
                    | NTerm::Binary { .. } => {
                        let zero = self.syms.int(0);
                        NTerm::Binary {
                            op: ast::BinaryOp::Add,
                            lhs: Box::new(nt),
                            rhs: Box::new(NTerm::Sym(zero)),
                            span: t.span,
                        }
                    }
                }
            } else if nt.has_operation() {
                nt
            } else {
                continue;
            };
            cond.push(NLit::Cmp {
                op: CmpOp::Eq,
                lhs: check.clone(),
                rhs: check,
            });
        }
        true
    }
}

/// True when an argument of the literal's atom is the anonymous variable.
pub(super) fn has_anonymous_arg(l: &ast::Literal) -> bool {
    match &l.atom {
        ast::Atom::Symbolic(a) => a
            .args
            .iter()
            .flatten()
            .any(|t| matches!(t.kind, TermKind::Anonymous)),
        _ => false,
    }
}
