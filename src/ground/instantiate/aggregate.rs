//! Body aggregates: their elements are grounded, their guards turned into literals (weight
//! rules for sums, saturation for non-monotone comparisons over atoms still being grounded,
//! after Alviano, Faber, Gebser, TPLP 2015), and the values an aggregate can take for
//! assignments.
//!
//! Invariant: an aggregate over atoms of its own component keeps its positive dependency on
//! them (complements of element atoms are saturated atoms, not default negations).

use super::*;

impl<'a> Grounder<'a> {
    /// Grounds the elements of an aggregate and continues with each way it can hold; its
    /// auxiliary rules are recorded as the aggregate's (provenance).
    pub(super) fn aggregate(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        self.in_aux(
            AuxKind::Aggregate,
            ctx,
            &mut |g, ctx, k| g.aggregate_inner(ctx, agg, k),
            k,
        );
    }

    /// Runs `f` (a construct that calls its continuation `k`) inside the auxiliary construct
    /// `kind` for provenance, leaving it while `k` runs (the rest of the body is the
    /// statement's own).
    pub(super) fn in_aux(
        &mut self,
        kind: AuxKind,
        ctx: &mut Ctx,
        f: &mut dyn FnMut(&mut Self, &mut Ctx, Cont<'_, 'a>),
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        let Some(outer) = self.enter_aux(kind, &ctx.binding) else {
            return f(self, ctx, k);
        };
        let mut other = outer;
        f(self, ctx, &mut |g: &mut Self, ctx: &mut Ctx| {
            std::mem::swap(&mut g.prov.aux, &mut other);
            k(g, ctx);
            std::mem::swap(&mut g.prov.aux, &mut other);
        });
        self.prov.aux = other;
    }

    pub(super) fn aggregate_inner(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        // Ground elements: tuple -> alternative conditions (an empty condition is certain).
        // An aggregate may have hundreds of thousands of elements (`#count { X,Y : path(X,Y) }`),
        // so the tuples are kept flat, found through a table of their indexes, and a certain
        // element keeps no conditions.
        let mut tuples = ElemTuples::default();
        let mut conds: Vec<Vec<Vec<Lit>>> = Vec::new();
        let mut certain: Vec<bool> = Vec::new();
        for e in &agg.elems {
            let blen = ctx.body.len();
            let mut t: Vec<SymId> = Vec::with_capacity(e.terms.len());
            self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
                t.clear();
                for term in &e.terms {
                    match g.eval(term, &ctx.binding) {
                        Some(v) => t.push(v),
                        None => return,
                    }
                }
                let i = tuples.index(&t);
                if i == conds.len() {
                    conds.push(Vec::new());
                    certain.push(false);
                }
                let c = &ctx.body[blen..];
                if c.is_empty() {
                    certain[i] = true;
                } else if !certain[i] && !conds[i].iter().any(|x| x.as_slice() == c) {
                    conds[i].push(c.to_vec());
                }
            });
            ctx.body.truncate(blen);
        }
        // Weights: integers for sums and counts, symbols for min/max.
        let mut elems: Vec<(SymId, Vec<Vec<Lit>>)> = Vec::new();
        for (i, c) in conds.into_iter().enumerate() {
            let t = tuples.get(i);
            let w = match agg.func {
                AggregateFunction::Count => self.syms.int(1),
                _ => match t.first() {
                    Some(&w) => w,
                    None => continue,
                },
            };
            if matches!(
                agg.func,
                AggregateFunction::Sum | AggregateFunction::SumPlus
            ) && self.syms.num(w).is_none()
            {
                continue;
            }
            if agg.func == AggregateFunction::SumPlus && self.syms.num(w).is_some_and(|n| n <= 0) {
                continue;
            }
            elems.push((w, if certain[i] { Vec::new() } else { c }));
        }
        // Guard values.
        let mut guards: Vec<(CmpOp, SymId)> = Vec::new();
        for (i, (op, t)) in agg.guards.iter().enumerate() {
            if Some(i) == agg.binder {
                continue;
            }
            let Some(v) = self.eval(t, &ctx.binding) else {
                return;
            };
            guards.push((*op, v));
        }
        let candidates: Vec<Option<SymId>> = match agg.binder {
            None => vec![None],
            Some(_) => self
                .possible_values(agg.func, &elems)
                .into_iter()
                .map(Some)
                .collect(),
        };
        // A positive aggregate over atoms still being grounded may need the translation that
        // keeps Ferraris' semantics when it is not monotone (see `sum_saturated`): when one of
        // its ground elements reads such an atom, as gringo decides (an element of a recursive
        // predicate that grounds to no atom leaves the aggregate over earlier atoms only).
        let recursive = agg.sign == Sign::Positive
            && self.reads_incomplete(agg)
            && elems.iter().flat_map(|(_, c)| c).flatten().any(|&l| {
                let p = self.info(GroundAtom::of_lit(l)).pred;
                p == u32::MAX || !self.domains[p as usize].complete
            });
        let mark = ctx.binding.mark();
        let blen = ctx.body.len();
        for cand in candidates {
            let mut gs = guards.clone();
            if let Some(v) = cand {
                let pat = &agg.guards[agg.binder.expect("binder")].1;
                if !pat.matches(&mut self.syms, v, &mut ctx.binding) {
                    ctx.binding.undo(mark);
                    continue;
                }
                gs.push((CmpOp::Eq, v));
            }
            let mut lits: Vec<Lit> = Vec::new();
            let mut truth = true;
            for (op, v) in gs {
                match self.guard_truth(agg.func, &elems, op, v, recursive) {
                    Truth::True => {}
                    Truth::False => {
                        truth = false;
                        break;
                    }
                    Truth::Lits(l) => lits.extend(l),
                }
            }
            // Apply the default-negation sign.
            let proceed = match agg.sign {
                Sign::Positive => {
                    if truth {
                        ctx.body.extend(lits);
                    }
                    truth
                }
                Sign::Not => {
                    if !truth {
                        true
                    } else if lits.is_empty() {
                        false
                    } else {
                        let a = self.disjunction_lit(&[lits]);
                        let n = self.negate_lit(a);
                        ctx.body.push(n);
                        true
                    }
                }
                Sign::NotNot => {
                    if !truth {
                        false
                    } else if lits.is_empty() {
                        true
                    } else {
                        let a = self.disjunction_lit(&[lits]);
                        let n = self.disjunction_lit(&[vec![-a], vec![-a]]);
                        ctx.body.push(-n);
                        true
                    }
                }
            };
            if proceed {
                k(self, ctx);
            }
            ctx.binding.undo(mark);
            ctx.body.truncate(blen);
            if self.stopped.is_some() {
                return;
            }
        }
    }

    /// The values an aggregate can take (for `X = #agg{...}`).
    pub(super) fn possible_values(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
    ) -> Vec<SymId> {
        match func {
            AggregateFunction::Min | AggregateFunction::Max => {
                let mut vals: Vec<SymId> = Vec::new();
                let certain: Vec<SymId> = elems
                    .iter()
                    .filter(|e| e.1.is_empty())
                    .map(|e| e.0)
                    .collect();
                let best_certain = certain.iter().copied().reduce(|a, b| {
                    let o = self.syms.compare(a, b);
                    if (func == AggregateFunction::Min) == o.is_le() {
                        a
                    } else {
                        b
                    }
                });
                for (w, _) in elems {
                    if let Some(c) = best_certain {
                        let o = self.syms.compare(*w, c);
                        let better = if func == AggregateFunction::Min {
                            o.is_le()
                        } else {
                            o.is_ge()
                        };
                        if !better {
                            continue;
                        }
                    }
                    if !vals.contains(w) {
                        vals.push(*w);
                    }
                }
                if best_certain.is_none() {
                    vals.push(if func == AggregateFunction::Min {
                        self.syms.sup()
                    } else {
                        self.syms.inf()
                    });
                }
                vals
            }
            _ => {
                // Sums reachable by subsets of the uncertain elements, plus the certain sum.
                let mut base: i64 = 0;
                let mut sums: hashbrown::HashSet<i64> = hashbrown::HashSet::new();
                sums.insert(0);
                for (w, c) in elems {
                    let n = self.syms.num(*w).unwrap_or(0) as i64;
                    if c.is_empty() {
                        base += n;
                    } else {
                        let next: Vec<i64> = sums.iter().map(|s| s + n).collect();
                        sums.extend(next);
                        if sums.len() > 100_000 {
                            self.stopped = Some(StopReason::SizeLimit);
                            return Vec::new();
                        }
                    }
                }
                let mut v: Vec<i64> = sums.into_iter().map(|s| s + base).collect();
                v.sort_unstable();
                v.into_iter()
                    .filter_map(|s| i32::try_from(s).ok())
                    .map(|s| self.syms.int(s))
                    .collect()
            }
        }
    }

    /// When `aggregate op v` holds, as literals.
    pub(super) fn guard_truth(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
        recursive: bool,
    ) -> Truth {
        match func {
            AggregateFunction::Min | AggregateFunction::Max => {
                if recursive && op == CmpOp::Ne {
                    return self.minmax_saturated(func == AggregateFunction::Max, elems, v);
                }
                self.minmax_truth(func, elems, op, v)
            }
            _ => {
                let Some(k) = self.syms.num(v) else {
                    // An integer compared with a non-integer: fixed by the term order.
                    let zero = self.syms.int(0);
                    return if cmp_holds(&self.syms, op, zero, v) {
                        Truth::True
                    } else {
                        Truth::False
                    };
                };
                let k = k as i64;
                // Over atoms still being grounded, a sum whose uncertain weights are all
                // negative is read as `-sum op' -k` with positive weights, so that `<=` stays
                // the monotone comparison it is (a positive dependency), as gringo does.
                if recursive && self.all_negative(elems) {
                    let flipped: Vec<(SymId, Vec<Vec<Lit>>)> = elems
                        .iter()
                        .map(|(w, c)| {
                            let n = self.syms.num(*w).unwrap_or(0);
                            (self.syms.int(n.wrapping_neg()), c.clone())
                        })
                        .collect();
                    let nk = self.syms.int((-k) as i32);
                    let op = crate::ground::rewrite::flip_cmp(op);
                    return self.guard_truth(func, &flipped, op, nk, recursive);
                }
                // `!=` at an end of the possible sums is one-sided: keep it monotone (a
                // positive dependency) rather than the negation of `=`.
                let (lo, hi) = self.sum_range(elems);
                let op = match op {
                    CmpOp::Ne if k < lo || k > hi => return Truth::True,
                    CmpOp::Ne if k == lo => CmpOp::Gt,
                    CmpOp::Ne if k == hi => CmpOp::Lt,
                    op => op,
                };
                if recursive && self.sum_nonmonotone(elems, op, k) {
                    // Each comparison as a disjunction of monotone sums `dir * sum >= bound`;
                    // `=` is the conjunction of two (Ferraris' semantics splits conjunctions).
                    return match op {
                        CmpOp::Ge => self.sum_saturated(elems, &[(1, k)]),
                        CmpOp::Gt => self.sum_saturated(elems, &[(1, k + 1)]),
                        CmpOp::Le => self.sum_saturated(elems, &[(-1, -k)]),
                        CmpOp::Lt => self.sum_saturated(elems, &[(-1, 1 - k)]),
                        CmpOp::Ne => self.sum_saturated(elems, &[(1, k + 1), (-1, 1 - k)]),
                        CmpOp::Eq => {
                            let a = self.sum_saturated(elems, &[(1, k)]);
                            let b = self.sum_saturated(elems, &[(-1, -k)]);
                            conj(a, b)
                        }
                    };
                }
                match op {
                    CmpOp::Ge => self.sum_ge(elems, k),
                    CmpOp::Gt => self.sum_ge(elems, k + 1),
                    CmpOp::Le => {
                        let t = self.sum_ge(elems, k + 1);
                        negate(self, t)
                    }
                    CmpOp::Lt => {
                        let t = self.sum_ge(elems, k);
                        negate(self, t)
                    }
                    CmpOp::Eq => {
                        let a = self.sum_ge(elems, k);
                        let b = self.sum_ge(elems, k + 1);
                        let nb = negate(self, b);
                        conj(a, nb)
                    }
                    CmpOp::Ne => {
                        let a = self.sum_ge(elems, k);
                        let b = self.sum_ge(elems, k + 1);
                        let nb = negate(self, b);
                        let eq = conj(a, nb);
                        negate(self, eq)
                    }
                }
            }
        }
    }

    /// `sum >= k` over weighted elements: true, false, or an auxiliary atom defined by a weight
    /// rule `aux :- k' { l = w, ... }` (negative weights turned into complements).
    pub(super) fn sum_ge(&mut self, elems: &[(SymId, Vec<Vec<Lit>>)], k: i64) -> Truth {
        let mut bound = k;
        let mut lits: Vec<(Lit, Weight)> = Vec::new();
        let mut max_extra: i64 = 0;
        // Weights of the same literal add up (gringo does the same: `-1:a; 1:a` weighs 0).
        let mut merged: Vec<(Lit, i64)> = Vec::new();
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                bound -= w;
                continue;
            }
            let l = self.disjunction_lit(c);
            match merged.iter_mut().find(|(x, _)| *x == l) {
                Some(e) => e.1 += w,
                None => merged.push((l, w)),
            }
        }
        for (l, w) in merged {
            if w > 0 {
                lits.push((l, w));
                max_extra += w;
            } else if w < 0 {
                // w*l == w + (-w)*(not l)
                bound -= w;
                let nl = self.negate_lit(l);
                lits.push((nl, -w));
                max_extra += -w;
            }
        }
        if bound <= 0 {
            return Truth::True;
        }
        if bound > max_extra {
            return Truth::False;
        }
        let a = self.aux();
        let body = if lits.iter().all(|&(_, w)| w == 1) && bound as usize == lits.len() {
            Body::Normal(lits.iter().map(|&(l, _)| l).collect())
        } else {
            Body::Weight { lower: bound, lits }
        };
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![a.get()],
                body,
            },
            AuxKind::Aggregate,
        );
        Truth::Lits(vec![a.lit()])
    }

    /// True when some uncertain weight is negative and none is positive.
    pub(super) fn all_negative(&self, elems: &[(SymId, Vec<Vec<Lit>>)]) -> bool {
        let signs = |pos: bool| {
            elems.iter().any(|(w, c)| {
                !c.is_empty()
                    && self
                        .syms
                        .num(*w)
                        .is_some_and(|n| if pos { n > 0 } else { n < 0 })
            })
        };
        signs(false) && !signs(true)
    }

    /// The least and the greatest sum the elements can take.
    pub(super) fn sum_range(&self, elems: &[(SymId, Vec<Vec<Lit>>)]) -> (i64, i64) {
        let (mut lo, mut hi) = (0i64, 0i64);
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                lo += w;
                hi += w;
            } else if w < 0 {
                lo += w;
            } else {
                hi += w;
            }
        }
        (lo, hi)
    }

    /// True when `sum op k` is not monotone in the truth of the elements' literals: the
    /// uncertain weights have both signs, or `op` is `!=` with `k` strictly between the least
    /// and the greatest possible sum (gringo's NONMONOTONE analysis).
    pub(super) fn sum_nonmonotone(
        &self,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        k: i64,
    ) -> bool {
        let (lo, hi) = self.sum_range(elems);
        let mixed = elems
            .iter()
            .any(|(w, c)| !c.is_empty() && self.syms.num(*w).is_some_and(|n| n > 0))
            && elems
                .iter()
                .any(|(w, c)| !c.is_empty() && self.syms.num(*w).is_some_and(|n| n < 0));
        mixed || (op == CmpOp::Ne && lo < k && k < hi)
    }

    /// `sum op k` for a non-monotone comparison over atoms still being grounded, as the
    /// disjunction of monotone sums `dir * sum >= bound` (`dir` is 1 or -1), see `saturated`.
    pub(super) fn sum_saturated(
        &mut self,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        disjuncts: &[(i64, i64)],
    ) -> Truth {
        let mut certain: i64 = 0;
        let mut merged: Vec<(Lit, i64)> = Vec::new();
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                certain += w;
                continue;
            }
            let l = self.equivalent_lit(c);
            match merged.iter_mut().find(|(x, _)| *x == l) {
                Some(e) => e.1 += w,
                None => merged.push((l, w)),
            }
        }
        merged.retain(|&(_, w)| w != 0);
        let parts: Vec<(Vec<(Lit, i64)>, i64)> = disjuncts
            .iter()
            .map(|&(dir, k)| {
                let lits = merged.iter().map(|&(l, w)| (l, dir * w)).collect();
                (lits, k - dir * certain)
            })
            .collect();
        self.saturated(parts)
    }

    /// An atom `A` for a disjunction of weighted sums `sum_i w_i * l_i >= bound` over element
    /// literals some of which are still being grounded, with Ferraris' semantics however the
    /// weights are signed (Alviano, Faber, Gebser: "Rewriting recursive aggregates in answer
    /// set programming: back to monotonicity", TPLP 2015; gringo translates so too). A literal
    /// `l` weighing `-w < 0` counts as its complement with weight `w` (the bound grows by `w`),
    /// which makes every disjunct monotone; the complement of an atom is an atom `c` saturated
    /// on `A`, so that `A` keeps its positive dependency on `l` (see `complement`):
    ///   c :- not l.   c :- A.   c | l :- not not A.
    /// The complement of `not l` is `l`. Then `A :- bound' { lits = weights }` for each
    /// disjunct that can hold; `True` when one always holds, `False` when none can.
    pub(super) fn saturated(&mut self, disjuncts: Vec<(Vec<(Lit, i64)>, i64)>) -> Truth {
        let mut live: Vec<(Vec<(Lit, i64)>, i64)> = Vec::new();
        for (lits, k) in disjuncts {
            let lits: Vec<(Lit, i64)> = lits.into_iter().filter(|&(_, w)| w != 0).collect();
            let bound = k - lits
                .iter()
                .filter(|&&(_, w)| w < 0)
                .map(|&(_, w)| w)
                .sum::<i64>();
            let max: i64 = lits.iter().map(|&(_, w)| w.abs()).sum();
            if bound <= 0 {
                return Truth::True;
            }
            if bound <= max {
                live.push((lits, bound));
            }
        }
        if live.is_empty() {
            return Truth::False;
        }
        let a = self.aux();
        let mut complements: Vec<(Lit, Lit)> = Vec::new();
        for (lits, bound) in live {
            let mut body: Vec<(Lit, Weight)> = Vec::new();
            for (l, w) in lits {
                if w > 0 {
                    body.push((l, w));
                    continue;
                }
                let c = match complements.iter().find(|(x, _)| *x == l) {
                    Some(&(_, c)) => c,
                    None => {
                        let c = self.complement(l, a);
                        complements.push((l, c));
                        c
                    }
                };
                body.push((c, -w));
            }
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head: vec![a.get()],
                    body: Body::Weight {
                        lower: bound,
                        lits: body,
                    },
                },
                AuxKind::Aggregate,
            );
        }
        Truth::Lits(vec![a.lit()])
    }

    /// The complement of an element literal `l` inside the saturated atom `a` (see
    /// `saturated`). Every positive element atom is saturated, not only those of the current
    /// component, as gringo does: the two agree on normal atoms (the saturating disjunction
    /// never supports `l`, `c :- A.` satisfies it first), and an external atom so put in a rule
    /// head is defined by a rule and loses its external value, as it does in clingo.
    pub(super) fn complement(&mut self, l: Lit, a: GroundAtom) -> Lit {
        if l < 0 {
            return self.negate_lit(l);
        }
        let c = self.aux();
        let not_a = self.not_aux(a);
        for (head, body) in [
            (vec![c.get()], vec![-l]),
            (vec![c.get()], vec![a.lit()]),
            (vec![c.get(), l as u32], vec![-not_a.lit()]),
        ] {
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head,
                    body: Body::Normal(body),
                },
                AuxKind::Aggregate,
            );
        }
        c.lit()
    }

    /// `#max != v` over atoms still being grounded (not monotone), with Ferraris' semantics:
    /// the maximum is above `v` (some element above `v` holds) or below it (no element at or
    /// above `v` holds): `#count{above} >= 1` or `-#count{at v} >= 0`, see `saturated`.
    /// `#min` is the mirror image.
    pub(super) fn minmax_saturated(
        &mut self,
        is_max: bool,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        v: SymId,
    ) -> Truth {
        let mut beyond: Vec<(Lit, i64)> = Vec::new();
        let mut at: Vec<(Lit, i64)> = Vec::new();
        let mut at_certain = false;
        for (w, c) in elems {
            let o = self.syms.compare(*w, v);
            let past = if is_max { o.is_gt() } else { o.is_lt() };
            if past {
                if c.is_empty() {
                    return Truth::True;
                }
                let l = self.equivalent_lit(c);
                beyond.push((l, 1));
            } else if o.is_eq() {
                if c.is_empty() {
                    at_certain = true;
                    continue;
                }
                let l = self.equivalent_lit(c);
                at.push((l, -1));
            }
        }
        let mut parts = vec![(beyond, 1)];
        if !at_certain {
            parts.push((at, 0));
        }
        self.saturated(parts)
    }

    /// `#min`/`#max` compared with `v`. With `m` the extremum (`#inf` for an empty `#max`,
    /// `#sup` for an empty `#min`): `max >= v` iff some weight is `>= v` (or `v` is `#inf`),
    /// `max <= v` iff not `max > v`; `#min` is the mirror image.
    pub(super) fn minmax_truth(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
    ) -> Truth {
        let is_max = func == AggregateFunction::Max;
        match op {
            CmpOp::Eq => {
                let a = self.minmax_dir(is_max, elems, CmpOp::Ge, v);
                let b = self.minmax_dir(is_max, elems, CmpOp::Le, v);
                conj(a, b)
            }
            CmpOp::Ne => {
                let a = self.minmax_dir(is_max, elems, CmpOp::Ge, v);
                let b = self.minmax_dir(is_max, elems, CmpOp::Le, v);
                let eq = conj(a, b);
                negate(self, eq)
            }
            op => self.minmax_dir(is_max, elems, op, v),
        }
    }

    pub(super) fn minmax_dir(
        &mut self,
        is_max: bool,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
    ) -> Truth {
        let toward = if is_max {
            matches!(op, CmpOp::Ge | CmpOp::Gt)
        } else {
            matches!(op, CmpOp::Le | CmpOp::Lt)
        };
        if !toward {
            let complement = crate::ground::rewrite::negate_cmp(op);
            let t = self.minmax_dir(is_max, elems, complement, v);
            return negate(self, t);
        }
        let empty = if is_max {
            self.syms.inf()
        } else {
            self.syms.sup()
        };
        if cmp_holds(&self.syms, op, empty, v) {
            return Truth::True;
        }
        let mut alts: Vec<Vec<Lit>> = Vec::new();
        for (w, c) in elems {
            if cmp_holds(&self.syms, op, *w, v) {
                if c.is_empty() {
                    return Truth::True;
                }
                alts.extend(c.iter().cloned());
            }
        }
        if alts.is_empty() {
            Truth::False
        } else {
            Truth::Lits(vec![self.disjunction_lit(&alts)])
        }
    }
}

pub(super) fn negate(g: &mut Grounder<'_>, t: Truth) -> Truth {
    match t {
        Truth::True => Truth::False,
        Truth::False => Truth::True,
        Truth::Lits(l) => {
            let a = g.disjunction_lit(&[l]);
            Truth::Lits(vec![g.negate_lit(a)])
        }
    }
}

pub(super) fn conj(a: Truth, b: Truth) -> Truth {
    match (a, b) {
        (Truth::False, _) | (_, Truth::False) => Truth::False,
        (Truth::True, x) | (x, Truth::True) => x,
        (Truth::Lits(mut x), Truth::Lits(y)) => {
            x.extend(y);
            Truth::Lits(x)
        }
    }
}
