//! Conditional body literals (`l : c`) and the helper atoms of negation: `not not a`,
//! negated conjunctions and disjunctions of conjunctions as single literals.
//!
//! Invariant: `not not a` is never collapsed to `a` (that would add a positive dependency).

use super::schedule::lit_preds;
use super::*;

impl Grounder<'_> {
    /// `d :- not a.`, so that `not d` stands for `not not a`.
    pub(super) fn not_aux(&mut self, a: GroundAtom) -> GroundAtom {
        if let Some(&d) = self.notnot.get(&a) {
            return d;
        }
        let d = self.aux();
        self.notnot.insert(a, d);
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![d.get()],
                body: Body::Normal(vec![-a.lit()]),
            },
            AuxKind::DoubleNegation,
        );
        d
    }

    /// Defines an auxiliary atom true exactly when one of `alternatives` (conjunctions) holds;
    /// a single one-literal alternative is returned as is.
    pub(super) fn disjunction_lit(&mut self, alternatives: &[Vec<Lit>]) -> Lit {
        if alternatives.len() == 1 && alternatives[0].len() == 1 {
            return alternatives[0][0];
        }
        let a = self.aux();
        for alt in alternatives {
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head: vec![a.get()],
                    body: Body::Normal(alt.clone()),
                },
                AuxKind::Aggregate,
            );
        }
        if alternatives.iter().any(|c| c.is_empty()) {
            self.atoms[a.index()].fact = true;
        }
        a.lit()
    }

    /// As [`Grounder::disjunction_lit`], for an element of a saturated aggregate (see
    /// `saturated`): the auxiliary atom also implies what defines it, so that the reduct
    /// cannot make it true alone. Each alternative of several literals gets an atom `b` with
    /// `b :- alt.`, `x :- b.` for each atom `x` of `alt`, `:- b, y.` for each `not y`; several
    /// alternatives get an atom `a` with `a :- b_i.` and `b_1 | ... | b_n :- a.` Without that,
    /// the saturation rule `c | b :- not not A.` is satisfied by `b` in the reduct at no cost:
    /// `d(1..3). q(3). 1 #count { X,p : p(X) : d(X) } 2 :- #count { X,1 : p(X), not p(1);
    /// X,3 : q(X); -1 : p(2) } != 2.` lost its answer set {p(2)} (gringo defines its element
    /// atoms in both directions too).
    pub(super) fn equivalent_lit(&mut self, alternatives: &[Vec<Lit>]) -> Lit {
        if alternatives.iter().any(|c| c.is_empty()) {
            return self.disjunction_lit(alternatives);
        }
        if alternatives.len() == 1 && alternatives[0].len() == 1 && alternatives[0][0] > 0 {
            return alternatives[0][0];
        }
        let mut atoms: Vec<u32> = Vec::with_capacity(alternatives.len());
        for alt in alternatives {
            if alt.len() == 1 && alt[0] > 0 {
                atoms.push(alt[0] as u32);
                continue;
            }
            let b = self.aux();
            let mut rules = vec![(vec![b.get()], alt.clone())];
            for &l in alt {
                if l > 0 {
                    rules.push((vec![l as u32], vec![b.lit()]));
                } else {
                    rules.push((Vec::new(), vec![b.lit(), -l]));
                }
            }
            for (head, body) in rules {
                self.add_aux_rule(
                    Rule {
                        head_kind: HeadKind::Disjunction,
                        head,
                        body: Body::Normal(body),
                    },
                    AuxKind::Aggregate,
                );
            }
            atoms.push(b.get());
        }
        if atoms.len() == 1 {
            return atoms[0] as Lit;
        }
        let a = self.aux();
        let mut rules: Vec<(Vec<u32>, Vec<Lit>)> = atoms
            .iter()
            .map(|&b| (vec![a.get()], vec![b as Lit]))
            .collect();
        rules.push((atoms, vec![a.lit()]));
        for (head, body) in rules {
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head,
                    body: Body::Normal(body),
                },
                AuxKind::Aggregate,
            );
        }
        a.lit()
    }

    /// True when an element condition of `agg` reads a predicate still being grounded.
    pub(super) fn reads_incomplete(&self, agg: &NAgg) -> bool {
        let mut preds = Vec::new();
        for e in &agg.elems {
            e.cond.iter().for_each(|l| lit_preds(l, &mut preds));
            e.lit_lits().for_each(|l| lit_preds(l, &mut preds));
        }
        preds.iter().any(|&p| !self.domains[p as usize].complete)
    }

    /// The default negation of a literal: `not a` for `a`, and for `not a` an atom standing
    /// for `not not a` (never collapsed to `a`, which would add a positive dependency).
    pub(super) fn negate_lit(&mut self, l: Lit) -> Lit {
        if l > 0 {
            -l
        } else {
            -self.not_aux(GroundAtom::of_lit(l)).lit()
        }
    }

    /// `not (c1, ..., cn)` as one literal.
    pub(super) fn not_conj(&mut self, c: &[Lit]) -> Lit {
        if c.len() == 1 && c[0] > 0 {
            return -c[0];
        }
        let a = self.aux();
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![a.get()],
                body: Body::Normal(c.to_vec()),
            },
            AuxKind::Condition,
        );
        -a.lit()
    }

    /// A conditional body literal `l : c`: for each instance of `c`, some instance of `l` must
    /// hold (`l`'s pools, intervals and local variables give alternatives). An instance with a
    /// certain condition contributes `l` itself (positively, as gringo keeps it); otherwise an
    /// auxiliary atom `x :- l.  x :- not c.` stands for `c -> l`.
    pub(super) fn conditional(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        self.in_aux(
            AuxKind::Condition,
            ctx,
            &mut |g, ctx, k| g.conditional_inner(ctx, agg, k),
            k,
        );
    }

    pub(super) fn conditional_inner(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        let e = &agg.elems[0];
        let alts = e.lit.as_deref().expect("conditional literal");
        let blen = ctx.body.len();
        // Per condition instance: its literals, and the alternatives of `l` (None when none
        // can hold, an empty alternative when one certainly holds).
        let mut found: Vec<CondInstance> = Vec::new();
        self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
            let cond = ctx.body[blen..].to_vec();
            let b2 = ctx.body.len();
            let mut sols: Vec<Vec<Lit>> = Vec::new();
            for alt in alts {
                g.join(ctx, alt, 0, &[], &mut |_, ctx| {
                    let s = ctx.body[b2..].to_vec();
                    if !sols.contains(&s) {
                        sols.push(s);
                    }
                });
            }
            ctx.body.truncate(b2);
            let sol = if sols.iter().any(|s| s.is_empty()) {
                Some(Vec::new())
            } else if sols.is_empty() {
                None
            } else {
                Some(sols)
            };
            found.push((cond, sol));
        });
        ctx.body.truncate(blen);
        let mut lits = Vec::new();
        for (cond, sol) in found {
            match (cond.is_empty(), sol) {
                (_, Some(s)) if s.is_empty() => {}
                (true, None) => return,
                (true, Some(s)) if s.len() == 1 => lits.extend(s.into_iter().flatten()),
                (true, Some(s)) => lits.push(self.disjunction_lit(&s)),
                (false, None) => lits.push(self.not_conj(&cond)),
                (false, Some(s)) => {
                    // x :- l.  x :- not c.  and x | k :- not not l, with k :- c and c_i :- k
                    // for the positive c_i (gringo's encoding: c -> l keeps c in the reduct
                    // when c depends on x).
                    let nc = self.not_conj(&cond);
                    let x = self.aux();
                    for body in s.iter().cloned().chain([vec![nc]]) {
                        self.add_aux_rule(Rule::normal(&[x.get()], &body), AuxKind::Condition);
                    }
                    let k = if cond.len() == 1 && cond[0] > 0 {
                        Some(GroundAtom::of_lit(cond[0]))
                    } else if cond.iter().any(|&c| c > 0) {
                        let k = self.aux();
                        self.add_aux_rule(Rule::normal(&[k.get()], &cond), AuxKind::Condition);
                        for &c in cond.iter().filter(|&&c| c > 0) {
                            self.add_aux_rule(
                                Rule::normal(&[c as u32], &[k.lit()]),
                                AuxKind::Condition,
                            );
                        }
                        Some(k)
                    } else {
                        None
                    };
                    if let Some(k) = k {
                        let t = self.disjunction_lit(&s);
                        let nt = self.negate_lit(t);
                        let nnt = self.negate_lit(nt);
                        self.add_aux_rule(
                            Rule::normal(&[x.get(), k.get()], &[nnt]),
                            AuxKind::Condition,
                        );
                    }
                    lits.push(x.lit());
                }
            }
        }
        ctx.body.extend(lits);
        k(self, ctx);
        ctx.body.truncate(blen);
    }
}
