//! The whole-program stability check of non-head-cycle-free programs, the fallback of the
//! component checks of `solve::stability` (used when one was cut short by a limit, or a total
//! assignment left a variable it reads open): a candidate `M` (a supported model whose positive
//! loops are founded) is an answer set when no model of the reduct `P^M` lies strictly inside
//! it, which a fresh engine decides (`is_minimal`). When one, `Y`, does, the
//! atoms `U = M \ Y` are unfounded with respect to `M` (`Y` is grown to a maximal one first,
//! so `U` is a minimal such set and touches few rules) (Leone, Rullo, Scarcello 1997, with
//! choice heads and weight bodies as clasp reads them), and `learn_unfounded` adds the loop
//! nogoods of `U` (Drescher et al., "Conflict-driven disjunctive answer set solving", KR 2008):
//! for each atom `p` of `U`, the clause `not p or R1 or ... or Rk`, where the `Ri` are the
//! literals, false in `M`, that kept each rule with a head atom in `U` from supporting `U` from
//! outside: a false body literal, or a head atom of `Y` (true, outside `U`) for a disjunction;
//! a rule with a positive body atom in `U` needs none.
//!
//! Invariants:
//! - Every clause learnt is falsified by `M` (so the search never meets `M` again) and holds
//!   in every answer set: if an answer set `S` made every `Ri` false and `p` true, `U ∩ S`
//!   would be an unfounded set of `S` containing `p`. A weight body's reason is a set of its
//!   false literals whose truth would still leave the sum outside `U` below the bound.
//! - The clauses hold in every later step too: `U`'s atoms are true in `M`, so they have rules
//!   or are free externals (which the check keeps in `Y`, never in `U`), and later steps give
//!   rules to external atoms only.
//! - A rule the argument cannot read (a negative weight in a weight body) makes the check fall
//!   back to blocking `M`'s whole atom assignment, which is sound for the same reason.

use super::*;
use crate::solve::stability::smaller_model;
use crate::solve::stability::Minimality;

impl Solver {
    /// Whether the current total assignment's atoms form a minimal model of the reduct.
    pub(super) fn is_minimal(&mut self) -> Minimality {
        self.minimality_checks += 1;
        let in_m = self.in_model();
        let mut sub = Engine::new();
        sub.limits.deadline = self.engine.limits.deadline;
        sub.limits.interrupt = self.engine.limits.interrupt.clone();
        let vars: Vec<Option<Lit>> = (0..=self.prog.num_atoms as usize)
            .map(|a| {
                if in_m[a] {
                    // Deciding atoms true first finds a large `Y`: a small unfounded set,
                    // whose nogoods are short.
                    let v = sub.new_var();
                    sub.prefer(v, None, Some(true));
                    Some(v.positive())
                } else {
                    None
                }
            })
            .collect();
        let holds = |l: i32| {
            if l > 0 {
                in_m[l as usize]
            } else {
                !in_m[(-l) as usize]
            }
        };
        for r in &self.prog.rules {
            let heads: Vec<Lit> = r.head.iter().filter_map(|&h| vars[h as usize]).collect();
            if r.head.is_empty() {
                continue;
            }
            // The reduct's body over the smaller model Y: positive literals vary, negative
            // ones are fixed by M.
            let mut clause_body: Vec<Lit> = Vec::new();
            match r.body {
                BodyRef::Normal(ls) => {
                    if ls.iter().any(|&l| l < 0 && !holds(l)) {
                        continue;
                    }
                    if ls.iter().any(|&l| l > 0 && !in_m[l as usize]) {
                        continue;
                    }
                    for &l in ls.iter().filter(|&&l| l > 0) {
                        clause_body.push(!vars[l as usize].expect("positive body atom is in M"));
                    }
                }
                BodyRef::Weight { lower, lits } => {
                    let mut fixed = 0i64;
                    let mut var_lits = Vec::new();
                    for &(l, w) in lits {
                        if l < 0 {
                            if holds(l) {
                                fixed += w;
                            }
                        } else if let Some(v) = vars[l as usize] {
                            var_lits.push((v, w));
                        }
                    }
                    let b = sub.new_var().positive();
                    sub.add_weight(b, &var_lits, lower - fixed);
                    clause_body.push(!b);
                }
            }
            match r.head_kind {
                HeadKind::Disjunction => {
                    let mut c = clause_body.clone();
                    c.extend_from_slice(&heads);
                    sub.add_clause(&c);
                }
                HeadKind::Choice => {
                    for &h in &heads {
                        let mut c = clause_body.clone();
                        c.push(h);
                        sub.add_clause(&c);
                    }
                }
            }
        }
        // Free externals keep their value in the reduct check.
        for &(a, _) in &self.prog.externals {
            if self.tr.free[a as usize] {
                if let Some(v) = vars[a as usize] {
                    sub.add_clause(&[v]);
                }
            }
        }
        smaller_model(&mut sub, &vars)
    }

    /// Per atom (index 0 unused), whether the current assignment makes it true.
    fn in_model(&self) -> Vec<bool> {
        let mut in_m = vec![false; self.prog.num_atoms as usize + 1];
        for a in self.true_atoms() {
            in_m[a as usize] = true;
        }
        in_m
    }

    /// Excludes the current candidate, whose reduct has the smaller model `in_y`, by the loop
    /// nogoods of the unfounded set `M \ Y` (see the module documentation).
    pub(super) fn learn_unfounded(&mut self, in_y: &[bool]) {
        let in_m = self.in_model();
        let in_u: Vec<bool> = in_m.iter().zip(in_y).map(|(&m, &y)| m && !y).collect();
        let reasons = self.unfounded_reasons(&in_m, &in_u);
        let Some(mut reasons) = reasons else {
            // Blocks this atom assignment for good.
            let block: Vec<Lit> = (1..=self.prog.num_atoms as usize)
                .map(|a| {
                    let l = self.tr.atom_lit[a];
                    if in_m[a] {
                        !l
                    } else {
                        l
                    }
                })
                .collect();
            self.engine.add_clause(&block);
            return;
        };
        reasons.sort_unstable();
        reasons.dedup();
        let mut clause: Vec<Lit> = Vec::with_capacity(reasons.len() + 1);
        for p in (1..in_u.len()).filter(|&p| in_u[p]) {
            clause.clear();
            clause.push(!self.tr.atom_lit[p]);
            clause.extend_from_slice(&reasons);
            self.engine.add_clause(&clause);
        }
    }

    /// The literals (all false in `M`) that keep every rule with a head atom in `U` from
    /// supporting `U` from outside; `None` when some rule has no such reason the argument
    /// covers.
    fn unfounded_reasons(&self, in_m: &[bool], in_u: &[bool]) -> Option<Vec<Lit>> {
        let holds = |l: i32| in_m[l.unsigned_abs() as usize] == (l > 0);
        let internal = |l: i32| l > 0 && in_u[l as usize];
        let mut reasons: Vec<Lit> = Vec::new();
        for r in &self.prog.rules {
            if !r.head.iter().any(|&h| in_u[h as usize]) {
                continue;
            }
            // A head atom outside U that is true (in Y) satisfies a disjunction's reduct.
            let other_head = || {
                if r.head_kind != HeadKind::Disjunction {
                    return None;
                }
                r.head
                    .iter()
                    .find(|&&h| in_m[h as usize] && !in_u[h as usize])
                    .map(|&h| !self.tr.atom_lit[h as usize])
            };
            match r.body {
                BodyRef::Normal(ls) => {
                    if ls.iter().any(|&l| internal(l)) {
                        continue;
                    }
                    if let Some(&l) = ls.iter().find(|&&l| !holds(l)) {
                        reasons.push(self.tr.lit(l));
                    } else {
                        reasons.push(other_head()?);
                    }
                }
                BodyRef::Weight { lower, lits } => {
                    if lits.iter().any(|&(_, w)| w < 0) {
                        return None;
                    }
                    let outside = |&&(l, _): &&(i32, i64)| !internal(l);
                    let sum: i64 = lits
                        .iter()
                        .filter(outside)
                        .filter(|&&(l, _)| holds(l))
                        .map(|&(_, w)| w)
                        .sum();
                    if sum >= lower {
                        reasons.push(other_head()?);
                        continue;
                    }
                    // The false literals, lightest first, may turn true as long as the sum
                    // stays below the bound; the rest are the reason.
                    let mut false_lits: Vec<(i32, i64)> = lits
                        .iter()
                        .filter(outside)
                        .filter(|&&(l, _)| !holds(l))
                        .copied()
                        .collect();
                    false_lits.sort_unstable_by_key(|&(_, w)| w);
                    let mut slack = lower - 1 - sum;
                    for (l, w) in false_lits {
                        if w <= slack {
                            slack -= w;
                        } else {
                            reasons.push(self.tr.lit(l));
                        }
                    }
                }
            }
        }
        Some(reasons)
    }
}
