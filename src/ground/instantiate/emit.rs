//! Emitting: the ground statement for one solution of a body (rules, choices, disjunctions
//! with conditional elements, minimize, show, external, heuristic, projection, CR rules).
//!
//! Invariant: ground rules are over grounder atoms ([`GroundAtom`]); a head atom that gets a rule enters its
//! predicate's domain.

use super::*;

impl Grounder<'_> {
    /// Produces the ground statement for one solution of the body.
    pub(super) fn emit(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        match &stmt.kind {
            NKind::Rule | NKind::Cr(_) => self.emit_rule(stmt, ctx),
            NKind::Theory => self.emit_theory(stmt, ctx),
            NKind::Minimize {
                weight,
                priority,
                terms,
                maximize,
            } => {
                let (Some(w), Some(p)) = (
                    self.eval(weight, &ctx.binding),
                    self.eval(priority, &ctx.binding),
                ) else {
                    return;
                };
                let mut ts = Vec::new();
                for t in terms {
                    let Some(v) = self.eval(t, &ctx.binding) else {
                        return;
                    };
                    ts.push(v);
                }
                let (Some(wn), Some(pn)) = (self.syms.num(w), self.syms.num(p)) else {
                    let span = stmt.span;
                    self.undefined(span);
                    return;
                };
                let wn = if *maximize { wn.wrapping_neg() } else { wn };
                let key = (pn, wn, ts);
                let body = ctx.body.clone();
                let origin = self.provenance.then(|| Origin {
                    rule: RuleOrigin::Auxiliary {
                        of_stmt: stmt.stmt,
                        kind: AuxKind::Minimize,
                        bindings: self.bindings(&ctx.binding),
                    },
                    removed: self.origin(stmt, ctx).removed,
                });
                let v = match self.directives.minimize.get_mut(&key) {
                    Some(v) => v,
                    None => {
                        self.directives.minimize_order.push(key.clone());
                        self.directives.minimize.entry(key.clone()).or_default()
                    }
                };
                let i = match v.iter().position(|c| *c == body) {
                    Some(i) => i,
                    None => {
                        v.push(body);
                        v.len() - 1
                    }
                };
                if let Some(o) = origin {
                    let os = self.prov.minimize_origins.entry(key).or_default();
                    if os.len() <= i {
                        os.resize(i + 1, Vec::new());
                    }
                    if !os[i].contains(&o) {
                        os[i].push(o);
                    }
                }
            }
            NKind::Show(t) => {
                let Some(v) = self.eval(t, &ctx.binding) else {
                    return;
                };
                self.directives.shows.push((v, ctx.body.clone(), stmt.stmt));
            }
            NKind::Project(a) => {
                let Some(s) = self.atom_sym(a, &ctx.binding) else {
                    return;
                };
                if let Some(id) = self.find_atom(s) {
                    if !self.directives.projections.contains(&id) {
                        self.directives.projections.push(id);
                    }
                }
            }
            NKind::External(a, value) => {
                let Some(s) = self.atom_sym(a, &ctx.binding) else {
                    return;
                };
                let Some(v) = self.eval(value, &ctx.binding) else {
                    return;
                };
                // Any other value leaves the instance out, as clingo 5.8.3 does, silently.
                let value = match self.syms.get(v) {
                    SymData::Fun {
                        name,
                        len: 0,
                        neg: false,
                        ..
                    } => match self.syms.names.resolve(name) {
                        "true" => ExternalValue::True,
                        "false" => ExternalValue::False,
                        "free" => ExternalValue::Free,
                        "release" => ExternalValue::Release,
                        _ => return,
                    },
                    _ => return,
                };
                let id = self.atom_of(s, a.pred);
                if self.info(id).fact {
                    return;
                }
                self.derive(id);
                if !self.directives.externals.iter().any(|(x, _)| *x == id) {
                    self.directives.externals.push((id, value));
                }
            }
            NKind::Heuristic {
                atom,
                weight,
                priority,
                modifier,
            } => {
                let Some(s) = self.atom_sym(atom, &ctx.binding) else {
                    return;
                };
                let Some(id) = self.find_atom(s) else { return };
                let (Some(w), Some(p), Some(m)) = (
                    self.eval(weight, &ctx.binding),
                    self.eval(priority, &ctx.binding),
                    self.eval(modifier, &ctx.binding),
                ) else {
                    return;
                };
                let modifier = match self.syms.get(m) {
                    SymData::Fun {
                        name,
                        len: 0,
                        neg: false,
                        ..
                    } => match self.syms.names.resolve(name) {
                        "level" => HeuristicModifier::Level,
                        "sign" => HeuristicModifier::Sign,
                        "factor" => HeuristicModifier::Factor,
                        "init" => HeuristicModifier::Init,
                        "true" => HeuristicModifier::True,
                        "false" => HeuristicModifier::False,
                        _ => return,
                    },
                    _ => return,
                };
                let (Some(w), Some(p)) = (self.syms.num(w), self.syms.num(p)) else {
                    return;
                };
                self.directives
                    .heuristics
                    .push(crate::ground::program::Heuristic {
                        modifier,
                        atom: id.get(),
                        bias: w,
                        priority: p.max(0) as u32,
                        // The atom's own literal only ranged over its domain (see the rewrite).
                        condition: ctx
                            .body
                            .iter()
                            .copied()
                            .filter(|&l| l != id.lit())
                            .collect(),
                    });
            }
            NKind::Edge(u, v) => {
                let (Some(u), Some(v)) = (self.eval(u, &ctx.binding), self.eval(v, &ctx.binding))
                else {
                    return;
                };
                let n = self.directives.edge_nodes.len() as i32;
                let from = *self.directives.edge_nodes.entry(u).or_insert(n);
                let n = self.directives.edge_nodes.len() as i32;
                let to = *self.directives.edge_nodes.entry(v).or_insert(n);
                self.directives.edges.push(crate::ground::program::Edge {
                    from,
                    to,
                    condition: ctx.body.clone(),
                });
            }
        }
    }

    /// Emits the rules of one instance of a rule statement; auxiliary rules of its head
    /// (element atoms, conditions) are recorded as [`AuxKind::Element`] (provenance).
    pub(super) fn emit_rule(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        let saved = self.enter_aux(AuxKind::Element, &ctx.binding);
        self.emit_rule_inner(stmt, ctx);
        self.leave_aux(saved);
    }

    pub(super) fn emit_rule_inner(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        // Grounder atom numbers, as the rule store holds them. Most heads have a few atoms: no
        // allocation for them.
        let mut head: SmallVec<[u32; 8]> = SmallVec::new();
        let mut extra_choices: Vec<(GroundAtom, Vec<Lit>)> = Vec::new();
        let mut elems: Vec<ElemInstance> = Vec::new();
        let is_choice = matches!(stmt.head, NHead::Choice(_));
        // The tuples of a gated choice's elements (see `HeadGate`); `None` when one cannot be
        // read, and the instance is then not gated.
        let gate = stmt.gate.as_deref();
        let mut gate_tuples: Option<Vec<Vec<SymId>>> = gate.map(|_| Vec::new());
        match &stmt.head {
            NHead::None => {}
            NHead::Disj(es) | NHead::Choice(es) => {
                // An undefined head atom (`p(a+0)`) drops its element from a choice, and the
                // whole rule from a disjunction, conditional elements included (clingo 5.8).
                for (i, e) in es.iter().enumerate() {
                    if !e.conj.is_empty() {
                        gate_tuples = None;
                        if !self.conj_elems(e, ctx, &mut elems) {
                            return;
                        }
                        continue;
                    }
                    if e.cond.is_empty() {
                        match self.atom_sym(&e.atom, &ctx.binding) {
                            Some(s) => {
                                self.push_gate_tuple(&mut gate_tuples, gate, i, s, &ctx.binding);
                                head.push(self.atom_of(s, e.atom.pred).get())
                            }
                            None if is_choice => {}
                            None => return,
                        }
                        continue;
                    }
                    let blen = ctx.body.len();
                    let mut found: Vec<(SymId, Vec<Lit>)> = Vec::new();
                    let mut undefined = false;
                    self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| match g
                        .atom_sym(&e.atom, &ctx.binding)
                    {
                        Some(s) => {
                            g.push_gate_tuple(&mut gate_tuples, gate, i, s, &ctx.binding);
                            found.push((s, ctx.body[blen..].to_vec()))
                        }
                        None => undefined = true,
                    });
                    ctx.body.truncate(blen);
                    if undefined && !is_choice {
                        return;
                    }
                    for (s, c) in found {
                        let a = self.atom_of(s, e.atom.pred);
                        if c.is_empty() {
                            head.push(a.get());
                        } else if is_choice {
                            extra_choices.push((a, c));
                        } else {
                            let span = e.atom.span;
                            if !self.reported.contains(&span) {
                                self.reported.insert(span);
                                let d = Diagnostic::error(
                                    span,
                                    "unsupported: a condition in a disjunctive head that facts do not decide",
                                )
                                .with_snippet(self.snippet(span));
                                self.diags.push(d);
                            }
                            return;
                        }
                    }
                }
            }
        }
        if let (Some(gate), Some(tuples)) = (gate, gate_tuples) {
            if !self.gate_reachable(gate, tuples, &ctx.binding) {
                return;
            }
        }
        head.dedup();
        if let NKind::Cr(label) = &stmt.kind {
            // r: h :+ b.  ==  {appl_r}.  h :- b, appl_r.
            let key: Vec<SymId> = stmt
                .globals
                .iter()
                .filter_map(|&v| ctx.binding.get(v))
                .collect();
            let appl = match self.cr_appl.get(&(stmt.stmt, key.clone())) {
                Some(&a) => a,
                None => match self.new_cr_appl(stmt, label.as_ref(), key, ctx) {
                    Some(a) => a,
                    None => return,
                },
            };
            ctx.body.push(appl.lit());
        }
        if is_choice {
            for &(a, ref c) in &extra_choices {
                self.derive(a);
                let mut body = ctx.body.clone();
                body.extend(c.iter().copied());
                self.add_rule(
                    Rule {
                        head_kind: HeadKind::Choice,
                        head: vec![a.get()],
                        body: Body::Normal(body),
                    },
                    |g| g.origin(stmt, ctx),
                );
            }
            let facts = (self.provenance && !self.naive).then(|| head.to_vec());
            head.retain(|&mut a| !self.info(GroundAtom::new(a)).fact);
            if head.is_empty() {
                // A choice among facts: satisfied (with provenance, kept as removed).
                if let Some((f, facts)) = facts.and_then(|h| Some((*h.first()?, h))) {
                    let origin = self.origin(stmt, ctx);
                    self.prov.dead.push(DeadRule {
                        head: facts,
                        origins: vec![origin],
                        why: DeadReason::HeadFact(f),
                    });
                }
                return;
            }
            for &a in &head {
                self.derive(GroundAtom::new(a));
            }
            self.add_rule_ref(
                RuleRef {
                    head_kind: HeadKind::Choice,
                    head: &head,
                    body: BodyRef::Normal(&ctx.body),
                },
                |g| g.origin(stmt, ctx),
            );
            return;
        }
        // A disjunction with a true atom is satisfied. (With provenance, an instance that
        // grounds to a fact's own rule is one more origin of that rule.)
        if let Some(&f) = head.iter().find(|&&a| self.info(GroundAtom::new(a)).fact) {
            // The other head atoms still enter their domains, as in gringo: `#project p/1.`
            // then matches p(1) of `p(1) ; r(1,3). r(1,3).`, and clingo 5.8 projects onto it
            // (see `simplify::numbering::number_remaining`).
            for &a in &head {
                self.derive(GroundAtom::new(a));
            }
            if head.len() == 1 && ctx.body.is_empty() {
                self.attach_origin(Rule::normal(&[f], &[]), |g| g.origin(stmt, ctx));
            } else if self.provenance && !self.naive {
                let origin = self.origin(stmt, ctx);
                self.prov.dead.push(DeadRule {
                    head: head.to_vec(),
                    origins: vec![origin],
                    why: DeadReason::HeadFact(f),
                });
            }
            return;
        }
        for el in elems {
            match el {
                (lits, cond)
                    if cond.is_empty() && lits.len() == 1 && lits[0].0 == Sign::Positive =>
                {
                    head.push(lits[0].1.get())
                }
                (lits, cond) => head.push(self.elem_atom(&lits, &cond).get()),
            }
        }
        head.dedup();
        for &a in &head {
            self.derive(GroundAtom::new(a));
        }
        if head.len() == 1 && ctx.body.is_empty() && !self.naive {
            self.atoms[GroundAtom::new(head[0]).index()].fact = true;
        }
        self.add_rule_ref(
            RuleRef {
                head_kind: HeadKind::Disjunction,
                head: &head,
                body: BodyRef::Normal(&ctx.body),
            },
            |g| g.origin(stmt, ctx),
        );
    }

    /// Adds to `tuples` (while collecting a gated choice's, `Some`) the tuple of element `i`
    /// whose atom is `atom`, when its terms are defined.
    fn push_gate_tuple(
        &mut self,
        tuples: &mut Option<Vec<Vec<SymId>>>,
        gate: Option<&HeadGate>,
        i: usize,
        atom: SymId,
        binding: &Binding,
    ) {
        if let (Some(ts), Some(gate)) = (tuples, gate) {
            if let Some(t) = self.gate_tuple(gate, i, atom, binding) {
                ts.push(t);
            }
        }
    }

    /// The tuple of element `i` of a gated choice whose atom is `atom` (its atom for a choice
    /// rule, its terms for a head aggregate); `None` when a term is undefined.
    fn gate_tuple(
        &mut self,
        gate: &HeadGate,
        i: usize,
        atom: SymId,
        binding: &Binding,
    ) -> Option<Vec<SymId>> {
        match &gate.tuples {
            None => Some(vec![atom]),
            Some(ts) => ts.get(i)?.iter().map(|t| self.eval(t, binding)).collect(),
        }
    }

    /// Whether the elements grounded so far (`tuples`, repeats counted once) can reach the
    /// bounds of a gated choice: some value between their least and greatest count or sum
    /// satisfies every guard (gringo grounds the atoms of a head aggregate only then). A guard
    /// that is not an integer leaves the instance ungated.
    fn gate_reachable(
        &mut self,
        gate: &HeadGate,
        mut tuples: Vec<Vec<SymId>>,
        b: &Binding,
    ) -> bool {
        tuples.sort_unstable();
        tuples.dedup();
        let (mut lo, mut hi) = (0i64, 0i64);
        for t in &tuples {
            let w = if gate.sum {
                // A weight that is not an integer drops its element (as in a body `#sum`).
                match t.first().and_then(|&w| self.syms.num(w)) {
                    Some(w) => w as i64,
                    None => continue,
                }
            } else {
                1
            };
            if w < 0 {
                lo += w;
            } else {
                hi += w;
            }
        }
        for (op, term) in &gate.guards {
            let Some(k) = self.eval(term, b).and_then(|v| self.syms.num(v)) else {
                return true;
            };
            let k = k as i64;
            match op {
                CmpOp::Lt => hi = hi.min(k - 1),
                CmpOp::Le => hi = hi.min(k),
                CmpOp::Gt => lo = lo.max(k + 1),
                CmpOp::Ge => lo = lo.max(k),
                CmpOp::Eq => {
                    lo = lo.max(k);
                    hi = hi.min(k);
                }
                CmpOp::Ne => {
                    if lo == k && hi == k {
                        return false;
                    }
                }
            }
        }
        lo <= hi
    }

    /// A new application atom for the instance of CR rule `stmt` with the global values `key`:
    /// `{appl}.` is added and the rule recorded with its label (`label` evaluated, or `r<stmt>`
    /// with the named global values); `None` when the label is undefined.
    fn new_cr_appl(
        &mut self,
        stmt: &NStmt,
        label: Option<&NTerm>,
        key: Vec<SymId>,
        ctx: &Ctx,
    ) -> Option<GroundAtom> {
        let text = match label {
            Some(t) => {
                let v = self.eval(t, &ctx.binding)?;
                self.syms.show(v)
            }
            None => {
                let mut s = format!("r{}", stmt.stmt);
                let named: Vec<String> = stmt
                    .globals
                    .iter()
                    .filter(|&&v| {
                        !self
                            .syms
                            .names
                            .resolve(stmt.var_names[v as usize])
                            .starts_with('#')
                    })
                    .filter_map(|&v| ctx.binding.get(v))
                    .map(|v| self.syms.show(v))
                    .collect();
                if !named.is_empty() {
                    s.push('(');
                    s.push_str(&named.join(","));
                    s.push(')');
                }
                s
            }
        };
        let a = self.aux();
        self.cr_appl.insert((stmt.stmt, key), a);
        self.directives.cr_rules.push((a, text));
        self.add_rule(
            Rule {
                head_kind: HeadKind::Choice,
                head: vec![a.get()],
                body: Body::Normal(Vec::new()),
            },
            |g| Origin {
                rule: RuleOrigin::Auxiliary {
                    of_stmt: stmt.stmt,
                    kind: AuxKind::CrApplication,
                    bindings: g.bindings(&ctx.binding),
                },
                removed: Vec::new(),
            },
        );
        Some(a)
    }

    /// Grounds the instances of a conditional disjunction element (`l : c` with gringo's
    /// reading) into `out`, simplified over what is known; false when one of them is certainly
    /// true, so the whole disjunction is satisfied.
    pub(super) fn conj_elems(
        &mut self,
        e: &NCondLit,
        ctx: &mut Ctx,
        out: &mut Vec<ElemInstance>,
    ) -> bool {
        // As gringo does, instances of the condition that agree on the local variables shared
        // by the condition and the literals form one element: its condition is their
        // disjunction, its literals their union.
        let mut cond_vars = VarList::new();
        e.cond.iter().for_each(|l| lit_vars(l, &mut cond_vars));
        let mut head_vars = VarList::new();
        for l in &e.conj {
            l.atom.args.iter().for_each(|t| t.vars(&mut head_vars));
            l.expand.iter().for_each(|x| lit_vars(x, &mut head_vars));
        }
        let mut key_vars: Vec<u32> = cond_vars
            .into_iter()
            .filter(|v| head_vars.contains(v) && ctx.binding.get(*v).is_none())
            .collect();
        key_vars.sort_unstable();
        key_vars.dedup();
        let blen = ctx.body.len();
        // Per group: its key, the conditions of its instances, and its literals.
        let mut groups: Vec<ElemGroup> = Vec::new();
        self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
            let key: Vec<SymId> = key_vars
                .iter()
                .filter_map(|&v| ctx.binding.get(v))
                .collect();
            let gi = match groups.iter().position(|(k, _, _)| *k == key) {
                Some(gi) => gi,
                None => {
                    groups.push((key, Vec::new(), Vec::new()));
                    groups.len() - 1
                }
            };
            let cond = ctx.body[blen..].to_vec();
            if !groups[gi].1.contains(&cond) {
                groups[gi].1.push(cond);
            }
            for (i, l) in e.conj.iter().enumerate() {
                g.join(ctx, &l.expand, 0, &[], &mut |g, ctx| {
                    // An undefined instance is left out of the conjunction.
                    if let Some(s) = g.atom_sym(&l.atom, &ctx.binding) {
                        if !groups[gi].2.contains(&(l.sign, i, s)) {
                            groups[gi].2.push((l.sign, i, s));
                        }
                    }
                });
            }
        });
        ctx.body.truncate(blen);
        'group: for (_, conds, lits) in groups {
            let mut ground: Vec<(Sign, GroundAtom)> = Vec::new();
            for (sign, i, s) in lits {
                let pred = e.conj[i].atom.pred;
                let existing = self.find_atom(s);
                let (fact, never) = existing.map_or((false, true), |a| {
                    (self.info(a).fact, !self.info(a).in_domain)
                });
                let never = never && self.domains[pred as usize].complete;
                match sign {
                    Sign::Positive if fact => {}
                    Sign::Positive => ground.push((sign, self.atom_of(s, pred))),
                    Sign::Not if fact => continue 'group,
                    Sign::NotNot if never => continue 'group,
                    Sign::Not if never => {}
                    Sign::NotNot if fact => {}
                    _ => ground.push((sign, self.atom_of(s, pred))),
                }
            }
            let cond = if conds.iter().any(|c| c.is_empty()) {
                Vec::new()
            } else if conds.len() == 1 {
                conds.into_iter().next().expect("one condition")
            } else {
                vec![self.disjunction_lit(&conds)]
            };
            if ground.is_empty() && cond.is_empty() {
                return false;
            }
            out.push((ground, cond));
        }
        true
    }

    /// The auxiliary atom `e` of a conditional disjunction element instance with literals
    /// `lits` and condition `cond` (gringo's translation): `e :- lits, cond.`; `a :- e, cond.`
    /// for each positive `a`; `:- e, cond, a.` for `not a` and `:- e, cond, not a.` for
    /// `not not a`; `:- e, not c.` for each condition literal `c`.
    pub(super) fn elem_atom(&mut self, lits: &[(Sign, GroundAtom)], cond: &[Lit]) -> GroundAtom {
        let e = self.aux();
        let mut body: Vec<Lit> = Vec::with_capacity(lits.len() + cond.len());
        for &(sign, a) in lits {
            body.push(match sign {
                Sign::Positive => a.lit(),
                Sign::Not => -a.lit(),
                Sign::NotNot => -self.not_aux(a).lit(),
            });
        }
        body.extend_from_slice(cond);
        // Repeated body literals are left out, as gringo does (clasp 3.3.5 mishandles some).
        let dedup = |v: &mut Vec<Lit>| {
            let mut seen = Vec::with_capacity(v.len());
            v.retain(|l| {
                let new = !seen.contains(l);
                seen.push(*l);
                new
            });
        };
        dedup(&mut body);
        self.add_aux_rule(Rule::normal(&[e.get()], &body), AuxKind::Element);
        let mut guard = vec![e.lit()];
        guard.extend_from_slice(cond);
        dedup(&mut guard);
        for &(sign, a) in lits {
            let mut b = guard.clone();
            match sign {
                Sign::Positive => {
                    self.derive(a);
                    self.add_aux_rule(Rule::normal(&[a.get()], &b), AuxKind::Element);
                }
                Sign::Not | Sign::NotNot => {
                    let l = if sign == Sign::Not { a.lit() } else { -a.lit() };
                    if !b.contains(&l) {
                        b.push(l);
                    }
                    self.add_aux_rule(Rule::normal(&[], &b), AuxKind::Element);
                }
            }
        }
        for &c in cond {
            self.add_aux_rule(Rule::normal(&[], &[e.lit(), -c]), AuxKind::Element);
        }
        e
    }
}
