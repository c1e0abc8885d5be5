//! Joins: candidate domain positions for a body literal, per-predicate indexes on bound
//! argument positions, the recursive join over a body, the greedy body order, and the
//! grounding of one statement over the ranges of its semi-naive literals.
//!
//! Invariants: an index covers every atom of its predicate's domain before it is read (it is
//! extended lazily); a positive literal only matches atoms in the domain, inside the range the
//! semi-naive round gives it.

use super::*;

impl<'a> Grounder<'a> {
    pub(super) fn lookup_range(&self, pred: PredId, range: Option<Range>) -> Range {
        range.unwrap_or((0, self.domains[pred as usize].atoms.len() as u32))
    }

    /// Candidate domain positions in `range` for `atom` under the binding.
    pub(super) fn candidates(
        &mut self,
        atom: &NAtom,
        b: &Binding,
        range: Range,
    ) -> Option<Candidates> {
        let mut mask = 0u64;
        let mut key: SmallVec<[SymId; 4]> = SmallVec::new();
        for (i, t) in atom.args.iter().enumerate().take(64) {
            // Constants and variables (most arguments) without a call.
            let v = match t {
                NTerm::Sym(s) => *s,
                NTerm::Var(v) => match b.get(*v) {
                    Some(s) => s,
                    None => continue,
                },
                _ if !t.bound_by(b) => continue,
                _ => match t.eval(&mut self.syms, b) {
                    Ok(v) => v,
                    Err(span) => {
                        self.undefined(span);
                        return None;
                    }
                },
            };
            mask |= 1 << i;
            key.push(v);
        }
        if mask == 0 {
            return Some(Candidates::Range(range.0, range.1));
        }
        if key.len() == atom.args.len() {
            // Every argument is known: look the atom up directly (an atom whose symbol was
            // never created does not exist).
            let found = self
                .syms
                .find_fun(atom.name, atom.neg, &key)
                .and_then(|sym| self.find_atom(sym))
                .map(|a| *self.info(a))
                .filter(|info| info.in_domain && info.dom_pos >= range.0 && info.dom_pos < range.1)
                .map(|info| info.dom_pos);
            return Some(Candidates::One(found));
        }
        let slot = self.index(atom.pred, mask);
        let d = &mut self.domains[atom.pred as usize];
        let idx = &mut d.indexes[slot];
        let Some(group) = idx.find(&key) else {
            return Some(Candidates::One(None));
        };
        let list = &idx.groups[group as usize];
        let lo = if range.0 == 0 {
            0
        } else {
            list.partition_point(|&p| p < range.0)
        };
        let hi = if range.1 as usize >= d.atoms.len() {
            list.len()
        } else {
            list.partition_point(|&p| p < range.1)
        };
        Some(Candidates::Group {
            index: slot as u32,
            group,
            lo: lo as u32,
            hi: hi as u32,
        })
    }

    /// The number of the index of `pred` on the positions of `mask`, created if needed and
    /// extended to every atom of the domain.
    pub(super) fn index(&mut self, pred: PredId, mask: u64) -> usize {
        let d = &mut self.domains[pred as usize];
        let slot = match d.indexes.iter().position(|x| x.mask == mask) {
            Some(i) => i,
            None => {
                d.indexes.push(Index::new(mask));
                d.indexes.len() - 1
            }
        };
        let idx = &mut d.indexes[slot];
        // Extend the index to the atoms derived since it was last used.
        while idx.upto < d.atoms.len() {
            let a = d.atoms[idx.upto];
            let sym = self.atoms[a.index()]
                .sym
                .expect("predicate atom has a symbol");
            let args = self.syms.args(sym);
            let k: SmallVec<[SymId; 4]> = (0..args.len())
                .filter(|&i| i < 64 && mask & (1 << i) != 0)
                .map(|i| args[i])
                .collect();
            let g = idx.group(&k);
            idx.groups[g as usize].push(idx.upto as u32);
            idx.upto += 1;
        }
        slot
    }

    /// Grounds `lits[i..]` and calls `k` for every solution.
    pub(super) fn join<L: std::borrow::Borrow<NLit>>(
        &mut self,
        ctx: &mut Ctx,
        lits: &[L],
        i: usize,
        ranges: &[Option<Range>],
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        if self.stopped.is_some() {
            return;
        }
        let Some(lit) = lits.get(i).map(L::borrow) else {
            k(self, ctx);
            return;
        };
        let mark = ctx.binding.mark();
        let blen = ctx.body.len();
        match lit {
            NLit::Bool(true) => self.join(ctx, lits, i + 1, ranges, k),
            NLit::Bool(false) => {}
            NLit::Pred {
                sign: Sign::Positive,
                atom,
            } => {
                let range = self.lookup_range(atom.pred, ranges.get(i).copied().flatten());
                let Some(cands) = self.candidates(atom, &ctx.binding, range) else {
                    return;
                };
                let (lo, hi) = match cands {
                    Candidates::Range(lo, hi) => (lo, hi),
                    Candidates::One(None) => {
                        // With provenance, a fully bound atom that does not exist stops an
                        // instance: record it (not when a semi-naive range hid the atom).
                        if self.provenance
                            && self.prov.aux.is_none()
                            && ranges.get(i).copied().flatten().is_none()
                            && atom.args.iter().all(|t| t.bound_by(&ctx.binding))
                        {
                            if let Some(sym) = self.atom_sym(atom, &ctx.binding) {
                                self.blocked(ctx, true, sym, atom.pred);
                            }
                        }
                        return;
                    }
                    Candidates::One(Some(p)) => (p, p + 1),
                    Candidates::Group { lo, hi, .. } => (lo, hi),
                };
                // gringo's order: new atoms of an unbound literal newest first (`new_lit`).
                let backward = matches!(cands, Candidates::Range(..))
                    && std::ptr::eq(lit, self.new_lit as *const NLit);
                for j in lo..hi {
                    let j = if backward { hi - 1 - (j - lo) } else { j };
                    let d = &self.domains[atom.pred as usize];
                    let pos = match cands {
                        Candidates::Group { index, group, .. } => {
                            d.indexes[index as usize].groups[group as usize][j as usize]
                        }
                        _ => j,
                    };
                    let a = d.atoms[pos as usize];
                    let info = *self.info(a);
                    let sym = info.sym.expect("predicate atom has a symbol");
                    let mut ok = true;
                    for (j, t) in atom.args.iter().enumerate() {
                        let s = self.syms.args(sym)[j];
                        ok = t.matches_arg(&mut self.syms, s, &mut ctx.binding);
                        if !ok {
                            break;
                        }
                    }
                    if ok {
                        if !info.fact {
                            ctx.body.push(a.lit());
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                    ctx.body.truncate(blen);
                    if self.stopped.is_some() {
                        return;
                    }
                }
            }
            NLit::Pred { sign, atom } => {
                let Some(sym) = self.atom_sym(atom, &ctx.binding) else {
                    return;
                };
                let complete = self.domains[atom.pred as usize].complete;
                let existing = self.find_atom(sym);
                let (in_domain, fact) = existing.map_or((false, false), |a| {
                    (self.info(a).in_domain, self.info(a).fact)
                });
                match sign {
                    Sign::Not => {
                        // not a: true when a cannot be derived, false when a is a fact.
                        if fact {
                            if self.provenance {
                                self.blocked(ctx, false, sym, atom.pred);
                            }
                            return;
                        }
                        if !complete || in_domain {
                            let a = self.atom_of(sym, atom.pred);
                            ctx.body.push(-a.lit());
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    _ => {
                        // not not a: false when a cannot be derived, true when a is a fact.
                        if complete && !in_domain {
                            if self.provenance {
                                self.blocked(ctx, true, sym, atom.pred);
                            }
                            return;
                        }
                        if !fact {
                            let a = self.atom_of(sym, atom.pred);
                            let saved = self.enter_aux(AuxKind::DoubleNegation, &ctx.binding);
                            let d = self.not_aux(a);
                            self.leave_aux(saved);
                            ctx.body.push(-d.lit());
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                }
                ctx.body.truncate(blen);
            }
            NLit::Cmp { op, lhs, rhs } => {
                let lb = lhs.bound_by(&ctx.binding);
                let rb = rhs.bound_by(&ctx.binding);
                if lb && rb {
                    // Integer arithmetic is compared without creating symbols; anything else
                    // (and undefined operations, which warn) goes the general way.
                    let holds = match (
                        lhs.eval_int(&self.syms, &ctx.binding),
                        rhs.eval_int(&self.syms, &ctx.binding),
                    ) {
                        (Some(l), Some(r)) => cmp_ints(*op, l, r),
                        _ => {
                            let (Some(l), Some(r)) =
                                (self.eval(lhs, &ctx.binding), self.eval(rhs, &ctx.binding))
                            else {
                                return;
                            };
                            cmp_holds(&self.syms, *op, l, r)
                        }
                    };
                    if holds {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                } else {
                    // X = t binds the unbound side.
                    let (pat, val) = if rb { (lhs, rhs) } else { (rhs, lhs) };
                    let Some(v) = self.eval(val, &ctx.binding) else {
                        return;
                    };
                    if pat.matches(&mut self.syms, v, &mut ctx.binding) {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                }
            }
            NLit::Interval { pat, lo, hi } => {
                let (Some(l), Some(h)) = (self.eval(lo, &ctx.binding), self.eval(hi, &ctx.binding))
                else {
                    return;
                };
                let (Some(l), Some(h)) = (self.syms.num(l), self.syms.num(h)) else {
                    return;
                };
                for v in l..=h {
                    let s = self.syms.int(v);
                    if pat.matches(&mut self.syms, s, &mut ctx.binding) {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                    if self.stopped.is_some() {
                        return;
                    }
                }
            }
            NLit::Call {
                pat,
                name,
                args,
                span,
            } => {
                let Some(values) = self.call(*name, args, *span, &ctx.binding) else {
                    return;
                };
                for s in values {
                    if pat.matches(&mut self.syms, s, &mut ctx.binding) {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                    if self.stopped.is_some() {
                        return;
                    }
                }
            }
            NLit::Agg(agg)
                if self.optimistic
                    && agg.sign != Sign::Positive
                    && agg.binder.is_none()
                    && self.reads_incomplete(agg) =>
            {
                // Computing the domain of a component with recursive aggregates: a negated one
                // is assumed to hold, so no atom is missed (the final round evaluates it). A
                // positive one is evaluated over the atoms found so far, as gringo does: its
                // rule is grounded once the aggregate can hold, so `p :- #count { 1 : p } >= 1.`
                // never makes `p` possible (and a bounded choice whose elements depend on its
                // own atoms stays as small as gringo's; see `HeadGate`).
                self.join(ctx, lits, i + 1, ranges, k);
            }
            NLit::Agg(agg) if agg.theory.is_some() => {
                self.theory(ctx, agg, &mut |g, ctx| g.join(ctx, lits, i + 1, ranges, k));
                ctx.binding.undo(mark);
                ctx.body.truncate(blen);
            }
            NLit::Agg(agg) if agg.elems.len() == 1 && agg.elems[0].lit.is_some() => {
                self.conditional(ctx, agg, &mut |g, ctx| g.join(ctx, lits, i + 1, ranges, k));
                ctx.binding.undo(mark);
                ctx.body.truncate(blen);
            }
            NLit::Agg(agg) => {
                self.aggregate(ctx, agg, &mut |g, ctx| g.join(ctx, lits, i + 1, ranges, k));
                ctx.binding.undo(mark);
                ctx.body.truncate(blen);
            }
        }
    }

    pub(super) fn atom_sym(&mut self, atom: &NAtom, b: &Binding) -> Option<SymId> {
        let mut vals: SmallVec<[SymId; 8]> = SmallVec::new();
        for t in &atom.args {
            // Constants and variables (most arguments) without a call.
            vals.push(match t {
                NTerm::Sym(s) => *s,
                NTerm::Var(v) => b.get(*v).expect("evaluated an unbound variable"),
                _ => self.eval(t, b)?,
            });
        }
        Some(self.syms.fun(atom.name, atom.neg, &vals))
    }
}

impl Grounder<'_> {
    /// Grounds one statement with the given ranges for its body literals.
    pub(super) fn ground_stmt(&mut self, stmt: &NStmt, ranges: &[Option<Range>]) {
        if self.provenance {
            let names = &self.syms.names;
            let head = match (&stmt.kind, &stmt.head) {
                (NKind::Rule | NKind::Cr(_), NHead::Disj(es) | NHead::Choice(es))
                    if es.iter().all(|e| e.cond.is_empty() && e.conj.is_empty()) =>
                {
                    Some(es.iter().map(|e| e.atom.clone()).collect())
                }
                _ => None,
            };
            self.prov.stmt = ProvStmt {
                stmt: stmt.stmt,
                aux: stmt.aux,
                names: stmt
                    .var_names
                    .iter()
                    .map(|&n| (!names.resolve(n).starts_with('#')).then_some(n))
                    .collect(),
                head,
            };
        }
        // The join state and the order's vector are reused from statement to statement.
        let mut ctx = match self.scratch.ctx.take() {
            Some(mut c) => {
                c.binding.reset(stmt.num_vars as usize);
                c.body.clear();
                c
            }
            None => Ctx {
                binding: Binding::new(stmt.num_vars as usize),
                body: Vec::new(),
            },
        };
        let mut order = std::mem::take(&mut self.scratch.order);
        self.join_order(stmt, ranges, &mut order);
        if order.iter().enumerate().all(|(i, &j)| i == j) {
            self.join(&mut ctx, &stmt.body, 0, ranges, &mut |g, ctx| {
                g.emit(stmt, ctx)
            });
        } else {
            let body: Vec<&NLit> = order.iter().map(|&j| &stmt.body[j]).collect();
            let ranges: Vec<Option<Range>> = order
                .iter()
                .map(|&j| ranges.get(j).copied().flatten())
                .collect();
            self.join(&mut ctx, &body, 0, &ranges, &mut |g, ctx| g.emit(stmt, ctx));
        }
        self.scratch.order = order;
        self.scratch.ctx = Some(ctx);
    }

    /// The order in which to join the body literals of `stmt`, given the ranges of its
    /// semi-naive literals: greedily, the evaluable literal expected to yield the fewest
    /// matches under the current domains (gringo orders bodies by such estimates too).
    /// Tests and bound comparisons come first, then assignments, then positive atoms by
    /// estimated matches: the domain's size in range divided by the number of distinct values
    /// on the bound positions (read from the index on those positions).
    ///
    /// Evaluability follows the planner's rules (`rewrite::plan`); an aggregate keeps every
    /// literal the planner put before it in front of it (so its global variables are bound as
    /// planned), and the variable an aggregate binds is bound by it alone.
    ///
    /// The order is written to `order` (cleared first).
    pub(super) fn join_order(
        &mut self,
        stmt: &NStmt,
        ranges: &[Option<Range>],
        order: &mut Vec<usize>,
    ) {
        let lits = &stmt.body;
        let n = lits.len();
        order.clear();
        if n <= 1 {
            order.extend(0..n);
            return;
        }
        // Scratch vectors, taken from the grounder and given back at the end.
        let nv = stmt.num_vars as usize;
        let mut bound = std::mem::take(&mut self.scratch.bound);
        bound.reset(nv);
        // Variables bound by aggregates (as planned).
        let mut reserved = std::mem::take(&mut self.scratch.reserved);
        reserved.reset(nv);
        for l in lits {
            if let NLit::Agg(a) = l {
                if let Some(NTerm::Var(v)) = a.binder.map(|i| &a.guards[i].1) {
                    reserved.insert(*v);
                }
            }
        }
        let mut placed = std::mem::take(&mut self.scratch.placed);
        placed.clear();
        placed.resize(n, false);
        let mut newly = std::mem::take(&mut self.scratch.newly);
        newly.reset(nv);
        // The variables of the terms each literal evaluates, once: term `first[i] + k` is the
        // `k`-th of literal `i` (a predicate's arguments; a comparison's sides; an interval's
        // bounds and pattern).
        let mut tv = std::mem::take(&mut self.scratch.term_vars);
        tv.reset(nv);
        let mut first = std::mem::take(&mut self.scratch.first_term);
        first.clear();
        for l in lits {
            first.push(tv.len());
            match l {
                NLit::Pred { atom, .. } => atom.args.iter().for_each(|t| tv.push(t)),
                NLit::Cmp { lhs, rhs, .. } => {
                    tv.push(lhs);
                    tv.push(rhs);
                }
                NLit::Interval { pat, lo, hi } => {
                    tv.push(lo);
                    tv.push(hi);
                    tv.push(pat);
                }
                NLit::Call { pat, args, .. } => {
                    args.iter().for_each(|t| tv.push(t));
                    tv.push(pat);
                }
                NLit::Bool(_) | NLit::Agg(_) => {}
            }
        }
        while order.len() < n {
            let mut best: Option<(f64, usize)> = None;
            for (i, l) in lits.iter().enumerate() {
                if placed[i] {
                    continue;
                }
                newly.clear();
                let f = first[i];
                let cost = match l {
                    NLit::Bool(_) => Some(0.0),
                    NLit::Pred { sign, atom } if *sign != Sign::Positive => (0..atom.args.len())
                        .all(|k| tv.bound_in(f + k, &bound))
                        .then_some(0.0),
                    NLit::Pred { atom, .. } => {
                        if atom
                            .args
                            .iter()
                            .enumerate()
                            .all(|(k, t)| tv.binds_in(f + k, t, &bound, &mut newly))
                        {
                            let range =
                                self.lookup_range(atom.pred, ranges.get(i).copied().flatten());
                            let size = range.1.saturating_sub(range.0) as f64;
                            let mut mask = 0u64;
                            for k in 0..atom.args.len().min(64) {
                                if tv.bound_in(f + k, &bound) {
                                    mask |= 1 << k;
                                }
                            }
                            Some(if newly.is_empty() {
                                size.min(0.5)
                            } else if mask == 0 {
                                size
                            } else {
                                let slot = self.index(atom.pred, mask);
                                let keys =
                                    self.domains[atom.pred as usize].indexes[slot].groups.len();
                                size / keys.max(1) as f64
                            })
                        } else {
                            None
                        }
                    }
                    NLit::Cmp { op, lhs, rhs } => {
                        let (lb, rb) = (tv.bound_in(f, &bound), tv.bound_in(f + 1, &bound));
                        if lb && rb {
                            Some(0.0)
                        } else if *op == CmpOp::Eq
                            && ((rb && tv.binds_in(f, lhs, &bound, &mut newly))
                                || (lb && tv.binds_in(f + 1, rhs, &bound, &mut newly)))
                        {
                            Some(1.0)
                        } else {
                            None
                        }
                    }
                    NLit::Interval { pat, lo, hi } => {
                        if tv.bound_in(f, &bound)
                            && tv.bound_in(f + 1, &bound)
                            && tv.binds_in(f + 2, pat, &bound, &mut newly)
                        {
                            Some(match (lo, hi) {
                                (NTerm::Sym(a), NTerm::Sym(b)) => {
                                    match (self.syms.num(*a), self.syms.num(*b)) {
                                        (Some(a), Some(b)) => (b as f64 - a as f64 + 1.0).max(0.0),
                                        _ => 0.0,
                                    }
                                }
                                _ => 100.0,
                            })
                        } else {
                            None
                        }
                    }
                    NLit::Call { pat, args, .. } => {
                        let n = args.len();
                        if (0..n).all(|k| tv.bound_in(f + k, &bound))
                            && tv.binds_in(f + n, pat, &bound, &mut newly)
                        {
                            // Most functions return one symbol: an assignment.
                            Some(1.0)
                        } else {
                            None
                        }
                    }
                    NLit::Agg(a) => {
                        if placed[..i].iter().all(|&p| p) {
                            if let Some(NTerm::Var(v)) = a.binder.map(|k| &a.guards[k].1) {
                                newly.insert(*v);
                            }
                            Some(1.5)
                        } else {
                            None
                        }
                    }
                };
                let Some(cost) = cost else { continue };
                if !matches!(l, NLit::Agg(_)) && newly.intersects(&reserved) {
                    continue;
                }
                if best.is_none_or(|(c, _)| cost < c) {
                    best = Some((cost, i));
                }
            }
            let Some((_, i)) = best else {
                // Not expected (the planned order is evaluable): keep the rest as planned.
                order.extend((0..n).filter(|&j| !placed[j]));
                break;
            };
            placed[i] = true;
            order.push(i);
            newly.clear();
            lit_binds(&lits[i], &bound, &mut newly);
            bound.union_with(&newly);
        }
        self.scratch.bound = bound;
        self.scratch.reserved = reserved;
        self.scratch.placed = placed;
        self.scratch.newly = newly;
        self.scratch.term_vars = tv;
        self.scratch.first_term = first;
    }
}

/// `a op b` on integers (clingo orders integers numerically).
pub(super) fn cmp_ints(op: CmpOp, a: i32, b: i32) -> bool {
    match op {
        CmpOp::Eq => a == b,
        CmpOp::Ne => a != b,
        CmpOp::Lt => a < b,
        CmpOp::Le => a <= b,
        CmpOp::Gt => a > b,
        CmpOp::Ge => a >= b,
    }
}

/// `t1 op t2` in clingo's term order.
pub fn cmp_holds(syms: &Symbols, op: CmpOp, a: SymId, b: SymId) -> bool {
    // Symbols are hash-consed: equality is identity.
    match op {
        CmpOp::Eq => return a == b,
        CmpOp::Ne => return a != b,
        _ => {}
    }
    let o = syms.compare(a, b);
    match op {
        CmpOp::Eq => o.is_eq(),
        CmpOp::Ne => o.is_ne(),
        CmpOp::Lt => o.is_lt(),
        CmpOp::Le => o.is_le(),
        CmpOp::Gt => o.is_gt(),
        CmpOp::Ge => o.is_ge(),
    }
}

/// Adds the variables that evaluating `l` with `bound` known binds to `out`.
pub(super) fn lit_binds(l: &NLit, bound: &VarSet, out: &mut VarSet) {
    match l {
        NLit::Pred {
            sign: Sign::Positive,
            atom,
        } => {
            for t in &atom.args {
                t.binds(bound, out);
            }
        }
        NLit::Cmp { lhs, rhs, .. } => {
            if lhs.bound_by(bound) {
                rhs.binds(bound, out);
            } else {
                lhs.binds(bound, out);
            }
        }
        NLit::Interval { pat, .. } | NLit::Call { pat, .. } => {
            pat.binds(bound, out);
        }
        NLit::Agg(a) => {
            if let Some(NTerm::Var(v)) = a.binder.map(|k| &a.guards[k].1) {
                if !bound.contains(*v) {
                    out.insert(*v);
                }
            }
        }
        NLit::Pred { .. } | NLit::Bool(_) => {}
    }
}
