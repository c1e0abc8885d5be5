//! Rules: each pool alternative of a rule becomes a statement; choice bounds and head
//! aggregates become an unbounded choice plus a constraint on a body aggregate; `finish`
//! plans the body (the safety check) and records the statement.
//!
//! Invariant: an unsafe statement is reported (gringo's `unsafe variables in:`) and not
//! produced.

use super::pool::*;
use super::*;

impl Rewriter<'_> {
    pub(super) fn rule(&mut self, index: u32, span: Span, r: &ast::Rule) {
        // Most rules have no pools: no copy then.
        if pool_free_rule(r) {
            self.rule_instance(index, span, &r.head, &r.body, &r.kind);
            return;
        }
        // Unfold pools of the head and body into separate rules.
        let heads: Vec<ast::Head> = match &r.head {
            // A plain element's alternatives are separate rules; an element written with a
            // colon keeps its literal's pools (a conjunction, see `head_elem`) and its
            // condition's alternatives become further elements of the same disjunction.
            ast::Head::Disjunction(elems) => product(
                elems
                    .iter()
                    .map(|e| {
                        if e.has_colon {
                            vec![unpool_condition(e)]
                        } else {
                            unpool_cond(e).into_iter().map(|c| vec![c]).collect()
                        }
                    })
                    .collect(),
            )
            .into_iter()
            .map(|es: Vec<Vec<ast::ConditionalLiteral>>| ast::Head::Disjunction(es.concat()))
            .collect(),
            // Alternatives of the guards are separate rules (each bound must hold).
            ast::Head::Choice(c) => {
                let mut c = c.clone();
                c.elements = c.elements.iter().flat_map(unpool_cond).collect();
                let mut out = Vec::new();
                for lower in unpool_guard(&c.lower) {
                    for upper in unpool_guard(&c.upper) {
                        let mut c = c.clone();
                        c.lower = lower.clone();
                        c.upper = upper;
                        out.push(ast::Head::Choice(c));
                    }
                }
                out
            }
            ast::Head::Aggregate(h) => {
                let mut h = h.clone();
                h.elements = h
                    .elements
                    .iter()
                    .flat_map(|e| {
                        unpool_list(&e.terms)
                            .into_iter()
                            .map(|terms| ast::HeadAggregateElement { terms, ..e.clone() })
                            .collect::<Vec<_>>()
                    })
                    .collect();
                let mut out = Vec::new();
                for lower in unpool_guard(&h.lower) {
                    for upper in unpool_guard(&h.upper) {
                        let mut h = h.clone();
                        h.lower = lower.clone();
                        h.upper = upper;
                        out.push(ast::Head::Aggregate(h));
                    }
                }
                out
            }
            h => vec![h.clone()],
        };
        for head in &heads {
            for body in unpool_body(&r.body) {
                self.rule_instance(index, span, head, &body, &r.kind);
            }
        }
    }

    pub(super) fn rule_instance(
        &mut self,
        index: u32,
        span: Span,
        head: &ast::Head,
        body: &[ast::BodyLiteral],
        kind: &ast::RuleKind,
    ) {
        let mut vars = Vars::default();
        // The body's literals, and a few interval binders and guard checks (a fact's stays
        // unallocated).
        let mut out = if body.is_empty() {
            Vec::new()
        } else {
            Vec::with_capacity(body.len() + 2)
        };
        let mut extra = Vec::new();
        let kind = match kind {
            ast::RuleKind::Normal => NKind::Rule,
            ast::RuleKind::ConsistencyRestoring { label } => match label {
                None => NKind::Cr(None),
                Some(l) => {
                    let ls = unpool_term(l);
                    let Some(t) = self.term(&ls[0], &mut vars, &mut extra) else {
                        return;
                    };
                    NKind::Cr(Some(t))
                }
            },
        };
        let head_ast = head;
        let mut kind = kind;
        // The gate of a bounded choice or head aggregate: `Some(None)` for a choice rule's.
        let mut gate_tuples: Option<Option<Vec<Vec<NTerm>>>> = None;
        let head = match head {
            ast::Head::None => NHead::None,
            ast::Head::Theory(a) => {
                if !matches!(kind, NKind::Rule) {
                    self.unsupported(span, "a theory atom in the head of a CR rule");
                    return;
                }
                let pos = if body.is_empty() {
                    theory::Position::Alone
                } else {
                    theory::Position::Head
                };
                let Some(lit) = self.theory_atom(Sign::Positive, a, pos, &mut vars, &mut extra)
                else {
                    return;
                };
                kind = NKind::Theory;
                // Placed after the body (see `finish`): the body binds its global variables.
                extra.push(lit);
                NHead::None
            }
            ast::Head::Disjunction(elems) => {
                // `#false` alone is a constraint; `#true` alone makes the rule void.
                if elems.len() == 1 && elems[0].condition.is_empty() {
                    match elems[0].literal.atom {
                        ast::Atom::Boolean(false) if elems[0].literal.sign == Sign::Positive => {
                            return self.rule_instance(
                                index,
                                span,
                                &ast::Head::None,
                                body,
                                &ast::RuleKind::Normal,
                            );
                        }
                        ast::Atom::Boolean(_) => {
                            self.unsupported(elems[0].span, "this head literal");
                            return;
                        }
                        _ => {}
                    }
                }
                // h | not a :- B.  ==  h :- B, not not a.   (and `not not a` moves as `not a`);
                // likewise a comparison: h | X < 3 :- B.  ==  h :- B, not X < 3.
                let moves = |e: &ast::ConditionalLiteral| {
                    !e.has_colon
                        && (e.literal.sign != Sign::Positive
                            || matches!(e.literal.atom, ast::Atom::Comparison { .. }))
                };
                if elems.iter().any(moves) {
                    let mut keep = Vec::new();
                    let mut nbody = body.to_vec();
                    for e in elems {
                        if moves(e) {
                            let mut l = e.literal.clone();
                            l.sign = negate_sign(l.sign);
                            nbody.push(ast::BodyLiteral::Literal(l));
                        } else {
                            keep.push(e.clone());
                        }
                    }
                    let head = if keep.is_empty() {
                        ast::Head::None
                    } else {
                        ast::Head::Disjunction(keep)
                    };
                    let kind = match &kind {
                        NKind::Cr(_) => {
                            return self.unsupported(span, "default negation in CR rule heads")
                        }
                        _ => ast::RuleKind::Normal,
                    };
                    return self.rule_instance(index, span, &head, &nbody, &kind);
                }
                let mut es = Vec::new();
                for e in elems {
                    // An element with a colon whose literal is false (`#false`, `not #true`) never
                    // holds; gringo reads a comparison there the same way.
                    if e.has_colon
                        && match &e.literal.atom {
                            ast::Atom::Boolean(b) => *b == (e.literal.sign == Sign::Not),
                            ast::Atom::Comparison { .. } => true,
                            _ => false,
                        }
                    {
                        continue;
                    }
                    let e = if e.has_colon {
                        self.disj_elem(e, &mut vars)
                    } else {
                        self.head_elem(e, &mut vars, &mut extra)
                    };
                    let Some(e) = e else {
                        return;
                    };
                    es.push(e);
                }
                NHead::Disj(es)
            }
            ast::Head::Choice(c) => {
                let mut es = Vec::new();
                let before = extra.len();
                for e in &c.elements {
                    let Some(e) = self.head_elem(e, &mut vars, &mut extra) else {
                        return;
                    };
                    es.push(e);
                }
                if lower_upper(&c.lower, &c.upper) {
                    // An interval in a head atom (`2 { p(1..4) } 2.`) is bound in the body, so
                    // each instance holds one of the elements: no gate then.
                    if extra.len() == before {
                        gate_tuples = Some(None);
                    }
                    // l { e } u :- B.  ==  { e } :- B.  and  :- B, not l #count{ e } u.
                    let agg = ast::BodyAggregate {
                        span: c.span,
                        function: AggregateFunction::Count,
                        lower: c.lower.clone(),
                        elements: Vec::new(),
                        set_syntax: c.elements.iter().flat_map(unpool_cond).collect(),
                        upper: c.upper.clone(),
                    };
                    self.bound_check(index, span, body, agg);
                }
                NHead::Choice(es)
            }
            ast::Head::Aggregate(h) => {
                match self.aggregate_head(index, span, body, h, &mut vars, &mut extra) {
                    Some((head, tuples)) => {
                        gate_tuples = tuples.map(Some);
                        head
                    }
                    None => return,
                }
            }
        };
        if self.body(body, &mut vars, &mut out).is_none() {
            return;
        }
        // A choice whose bounds are undefined (say `X+1` with X=a) is dropped with them: the
        // bounds are evaluated in its body as `t = t`.
        let (guards, sum): (Vec<(&ast::Guard, bool)>, bool) = match head_ast {
            ast::Head::Choice(c) => (bounds(&c.lower, &c.upper), false),
            ast::Head::Aggregate(h) => (
                bounds(&h.lower, &h.upper),
                matches!(
                    h.function,
                    AggregateFunction::Sum | AggregateFunction::SumPlus
                ),
            ),
            _ => (Vec::new(), false),
        };
        let mut gate_guards = Vec::new();
        for (g, left) in guards {
            if let Some(t) = self.term(&g.term, &mut vars, &mut extra) {
                let op = if left { flip_cmp(g.op) } else { g.op };
                gate_guards.push((op, t.clone()));
                if !matches!(t, NTerm::Sym(_)) {
                    out.push(NLit::Cmp {
                        op: CmpOp::Eq,
                        lhs: t.clone(),
                        rhs: t,
                    });
                }
            }
        }
        self.gate = gate_tuples.map(|tuples| HeadGate {
            sum,
            guards: gate_guards,
            tuples,
        });
        out.append(&mut extra);
        self.finish(index, span, head, out, kind, vars);
    }

    /// The head of a head aggregate instance, with the constraint that checks its bounds, and
    /// the tuple of each head element when the aggregate is a `#count` or `#sum` with bounds
    /// and every tuple term is a plain term (see [`HeadGate`]); `None`: an element is
    /// undefined, and the rule instance is dropped.
    fn aggregate_head(
        &mut self,
        index: u32,
        span: Span,
        body: &[ast::BodyLiteral],
        h: &ast::HeadAggregate,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<(NHead, Option<Vec<Vec<NTerm>>>)> {
        let gated = lower_upper(&h.lower, &h.upper)
            && matches!(
                h.function,
                AggregateFunction::Count | AggregateFunction::Sum | AggregateFunction::SumPlus
            );
        let mut tuples = gated.then(Vec::new);
        let before = extra.len();
        // l #f { w,t : a : c } u :- B.  ==  { a : c } :- B.  and
        // :- B, not l #f { w,t : a, c } u.
        // The tuple alone identifies an element, as in clingo 5.8: `2 #count { 1: p; 1: q }.`
        // has no answer set (both atoms true still count the one tuple `1`).
        let mut es = Vec::new();
        let mut elements = Vec::new();
        for e in &h.elements {
            let ce = ast::ConditionalLiteral {
                span: e.span,
                literal: e.literal.clone(),
                condition: e.condition.clone(),
                has_colon: !e.condition.is_empty(),
            };
            for ce in unpool_cond(&ce) {
                let mut n = self.head_elem(&ce, vars, extra)?;
                if !self.tuple_checks(h.function, &e.terms, vars, &mut n.cond) {
                    continue;
                }
                if let Some(ts) = &mut tuples {
                    let mut scratch = Vec::new();
                    let lowered: Option<Vec<NTerm>> = e
                        .terms
                        .iter()
                        .map(|t| self.term(t, vars, &mut scratch))
                        .collect();
                    match lowered {
                        // An interval in a tuple binds a variable of its own: no gate.
                        Some(lowered) if scratch.is_empty() => ts.push(lowered),
                        _ => tuples = None,
                    }
                }
                es.push(n);
                let mut condition = vec![ce.literal.clone()];
                condition.extend(ce.condition.iter().cloned());
                elements.push(ast::BodyAggregateElement {
                    span: e.span,
                    terms: e.terms.clone(),
                    condition,
                });
            }
        }
        if lower_upper(&h.lower, &h.upper) {
            let agg = ast::BodyAggregate {
                span: h.span,
                function: h.function,
                lower: h.lower.clone(),
                elements,
                set_syntax: Vec::new(),
                upper: h.upper.clone(),
            };
            self.bound_check(index, span, body, agg);
        }
        if extra.len() != before {
            // An interval in a head atom is bound in the body: no gate (see `rule_instance`).
            tuples = None;
        }
        Some((NHead::Choice(es), tuples))
    }

    /// Emits the constraint `:- B, not AGG.` that checks a choice or head aggregate's bounds,
    /// its rule instances attributed to the rule as `AuxKind::Bound`.
    fn bound_check(
        &mut self,
        index: u32,
        span: Span,
        body: &[ast::BodyLiteral],
        agg: ast::BodyAggregate,
    ) {
        let mut cbody = body.to_vec();
        cbody.push(ast::BodyLiteral::Aggregate {
            sign: Sign::Not,
            aggregate: Box::new(agg),
        });
        let role = self.aux_role.replace(AuxKind::Bound);
        self.rule_instance(
            index,
            span,
            &ast::Head::None,
            &cbody,
            &ast::RuleKind::Normal,
        );
        self.aux_role = role;
    }

    /// Plans the body and element conditions, checks safety, and records the statement.
    pub(super) fn finish(
        &mut self,
        index: u32,
        span: Span,
        mut head: NHead,
        body: Vec<NLit>,
        kind: NKind,
        vars: Vars,
    ) {
        let n = vars.names.len();
        // Global variables: those outside aggregate elements and head conditions.
        // Per variable slot: global, and bound by the body (on the stack for up to 32 slots).
        let mut global: Flags = smallvec::smallvec![false; n];
        let mut buf = VarList::new();
        let mut mark = |t: &NTerm, g: &mut [bool]| {
            buf.clear();
            t.vars(&mut buf);
            for &v in &buf {
                g[v as usize] = true;
            }
        };
        let mut vs = VarList::new();
        for l in &body {
            match l {
                NLit::Agg(a) => a.guards.iter().for_each(|(_, t)| mark(t, &mut global)),
                other => {
                    vs.clear();
                    lit_vars(other, &mut vs);
                    for &v in &vs {
                        global[v as usize] = true;
                    }
                }
            }
        }
        match &head {
            NHead::Disj(es) | NHead::Choice(es) => {
                for e in es.iter().filter(|e| e.cond.is_empty() && e.conj.is_empty()) {
                    e.atom.args.iter().for_each(|t| mark(t, &mut global));
                }
            }
            NHead::None => {}
        }
        match &kind {
            NKind::Rule | NKind::Cr(None) | NKind::Theory => {}
            NKind::Cr(Some(t)) | NKind::Show(t) => mark(t, &mut global),
            NKind::Minimize {
                weight,
                priority,
                terms,
                ..
            } => {
                mark(weight, &mut global);
                mark(priority, &mut global);
                terms.iter().for_each(|t| mark(t, &mut global));
            }
            NKind::Project(a) => a.args.iter().for_each(|t| mark(t, &mut global)),
            NKind::External(a, value) => {
                a.args.iter().for_each(|t| mark(t, &mut global));
                mark(value, &mut global);
            }
            NKind::Heuristic {
                atom,
                weight,
                priority,
                modifier,
            } => {
                atom.args.iter().for_each(|t| mark(t, &mut global));
                mark(weight, &mut global);
                mark(priority, &mut global);
                mark(modifier, &mut global);
            }
            NKind::Edge(u, v) => {
                mark(u, &mut global);
                mark(v, &mut global);
            }
        }
        // Global variables occurring only in elements of several aggregates are still local to
        // each; a variable is global iff marked above.
        let mut bound: Flags = smallvec::smallvec![false; n];
        let mut unsafe_vars: Vec<u32> = Vec::new();
        let body = plan(body, &mut bound, &global, &mut unsafe_vars);
        for (v, g) in global.iter().enumerate() {
            if *g && !bound[v] && !unsafe_vars.contains(&(v as u32)) {
                unsafe_vars.push(v as u32);
            }
        }
        match &mut head {
            NHead::Disj(es) | NHead::Choice(es) => {
                for e in es.iter_mut() {
                    let mut b = bound.clone();
                    let cond = std::mem::take(&mut e.cond);
                    e.cond = plan(cond, &mut b, &global, &mut unsafe_vars);
                    let mut vs = VarList::new();
                    if e.conj.is_empty() {
                        e.atom.args.iter().for_each(|t| t.vars(&mut vs));
                    }
                    for l in &mut e.conj {
                        let mut bl = b.clone();
                        let expand = std::mem::take(&mut l.expand);
                        l.expand = plan(expand, &mut bl, &global, &mut unsafe_vars);
                        let mut lv = VarList::new();
                        l.atom.args.iter().for_each(|t| t.vars(&mut lv));
                        vs.extend(lv.into_iter().filter(|&v| !bl[v as usize]));
                    }
                    for v in vs {
                        if !b[v as usize] && !unsafe_vars.contains(&v) {
                            unsafe_vars.push(v);
                        }
                    }
                }
            }
            NHead::None => {}
        }
        if !unsafe_vars.is_empty() {
            unsafe_vars.sort_by_key(|&v| (vars.spans[v as usize].start, v));
            let mut d =
                Diagnostic::error(span, "unsafe variables in").with_snippet(self.snippet(span));
            for v in unsafe_vars {
                let name = self.syms.names.resolve(vars.names[v as usize]);
                let shown = if name.starts_with("#Anon") {
                    "_".to_string()
                } else {
                    name.to_string()
                };
                d = d.with_note(Some(vars.spans[v as usize]), format!("'{shown}' is unsafe"));
            }
            self.diags.push(d);
            return;
        }
        let var_names = vars.names;
        let globals = (0..n as u32).filter(|&v| global[v as usize]).collect();
        self.out.stmts.push(NStmt {
            stmt: index,
            span,
            head,
            body,
            kind,
            num_vars: n as u32,
            var_names,
            globals,
            aux: self.aux_role,
            gate: self.gate.take().map(Box::new),
        });
    }
}
