//! CR-Prolog semantics: cardinality-minimal applied CR rules (the default) and crmodels2's
//! subset-minimal semantics with `prefer/2`.
//!
//! Invariants: an answer set is compared with others on its non-CR atoms (projection); a
//! reported answer set applies a minimal set of CR rules under the chosen semantics.

use super::*;

impl Solver {
    /// Default CR semantics: find the minimal number of applied CR rules, then solve among the
    /// answer sets applying exactly that many.
    ///
    /// Shortcut: when one model is asked for (`--models=1`, plain enumeration, no
    /// optimization) and the first phase finds an answer set applying no CR rule, that answer
    /// set is CR-minimal (no answer set applies fewer than 0) and is reported at once, from
    /// the first phase's assignment and before any guard is retired (retiring backtracks).
    pub(super) fn run_cr_cardinality(&mut self, call: &mut Call<'_>, assume: &[Lit], guard: Lit) {
        let cr: Vec<(Lit, i64)> = self.cr_lits.iter().map(|&l| (l, 1)).collect();
        let mut best: Option<i64> = None;
        let mut bound_guard: Option<Lit> = None;
        let one_plain_model = self.config.models == 1
            && self.config.enum_mode == EnumMode::Auto
            && (self.tr.minimize.is_empty() || self.config.opt_mode == OptMode::Ignore);
        loop {
            let mut a = assume.to_vec();
            if let Some(g) = bound_guard {
                a.push(g);
            }
            match self.next(&a) {
                Next::Exhausted => break,
                Next::Stopped => {
                    call.stopped = true;
                    if let Some(g) = bound_guard {
                        self.retire(g);
                    }
                    return;
                }
                Next::Model => {
                    let k = cr
                        .iter()
                        .filter(|&&(l, _)| self.engine.value(l) == Some(true))
                        .count() as i64;
                    if k == 0 && one_plain_model {
                        // Forced by propagation under the call's own assumptions: the only
                        // answer set, as `run_enumerate` reports it.
                        let unique = bound_guard.is_none()
                            && self.engine.decision_level() as usize <= assume.len();
                        self.report(call, false, true);
                        self.engine.backtrack(0);
                        if let Some(g) = bound_guard {
                            self.retire(g);
                        }
                        if unique {
                            call.exhausted = true;
                        }
                        return;
                    }
                    best = Some(k);
                    if let Some(g) = bound_guard {
                        self.retire(g);
                    }
                    if k == 0 {
                        bound_guard = None;
                        break;
                    }
                    let g = self.new_guard();
                    let neg: Vec<(Lit, i64)> = cr.iter().map(|&(l, _)| (l, -1)).collect();
                    // guard -> count <= k - 1.
                    let b = self.aux_weight(g, &neg, -(k - 1));
                    self.engine.add_clause(&[!g, b]);
                    bound_guard = Some(g);
                }
            }
        }
        if let Some(g) = bound_guard {
            self.retire(g);
        }
        let Some(k) = best else {
            call.exhausted = true;
            return;
        };
        // guard -> count <= k, for the rest of this call.
        self.engine.backtrack(0);
        let neg: Vec<(Lit, i64)> = cr.iter().map(|&(l, _)| (l, -1)).collect();
        let b = self.aux_weight(guard, &neg, -k);
        self.engine.add_clause(&[!guard, b]);
        self.run_main(call, assume, guard);
    }

    /// `--cr=subset`: first every set-inclusion-minimal set of applied CR rules, then the
    /// preference filter of CR-Prolog (drop sets containing two rules ordered by the transitive
    /// closure of `prefer`, then sets dominated by a remaining one: `Y` dominates `X` when a rule
    /// of `Y` is preferred to a rule of `X`), then the answer sets applying exactly one of the
    /// kept sets.
    pub(super) fn run_cr_subset(&mut self, call: &mut Call<'_>, assume: &[Lit], guard: Lit) {
        let k = self.cr_lits.len();
        let mut minimal: Vec<Vec<bool>> = Vec::new();
        let phase = self.new_guard();
        let mut a0 = assume.to_vec();
        a0.push(phase);
        loop {
            match self.next(&a0) {
                Next::Exhausted => break,
                Next::Stopped => {
                    call.stopped = true;
                    self.retire(phase);
                    return;
                }
                Next::Model => {}
            }
            let mut applied: Vec<bool> = self
                .cr_lits
                .iter()
                .map(|&l| self.engine.value(l) == Some(true))
                .collect();
            // Shrink the applied set until no answer set applies a strict subset.
            loop {
                let g = self.new_guard();
                let mut c = vec![!g];
                let mut a = a0.clone();
                a.push(g);
                for (i, &l) in self.cr_lits.iter().enumerate() {
                    if applied[i] {
                        c.push(!l);
                    } else {
                        a.push(!l);
                    }
                }
                self.engine.add_clause(&c);
                let r = self.next(&a);
                if let Next::Model = r {
                    applied = self
                        .cr_lits
                        .iter()
                        .map(|&l| self.engine.value(l) == Some(true))
                        .collect();
                }
                self.retire(g);
                match r {
                    Next::Model => {}
                    Next::Exhausted => break,
                    Next::Stopped => {
                        call.stopped = true;
                        self.retire(phase);
                        return;
                    }
                }
            }
            // No later set may contain this minimal one.
            let mut c = vec![!phase];
            c.extend(
                self.cr_lits
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| applied[*i])
                    .map(|(_, &l)| !l),
            );
            self.engine.add_clause(&c);
            minimal.push(applied);
        }
        self.retire(phase);
        let pref = self.preference_closure();
        let candidates: Vec<&Vec<bool>> = minimal
            .iter()
            .filter(|x| !(0..k).any(|i| x[i] && (0..k).any(|j| x[j] && pref[i * k + j])))
            .collect();
        let kept: Vec<&Vec<bool>> = candidates
            .iter()
            .copied()
            .filter(|x| {
                !candidates
                    .iter()
                    .any(|y| (0..k).any(|b| y[b] && (0..k).any(|w| x[w] && pref[b * k + w])))
            })
            .collect();
        if kept.is_empty() {
            call.exhausted = true;
            return;
        }
        // guard -> the applied set is one of the kept sets.
        let mut big = vec![!guard];
        for x in kept {
            let conj: Vec<Lit> = self
                .cr_lits
                .iter()
                .enumerate()
                .map(|(i, &l)| if x[i] { l } else { !l })
                .collect();
            let c = self.aux_conjunction(guard, &conj);
            big.push(c);
        }
        self.engine.add_clause(&big);
        self.run_main(call, assume, guard);
    }

    /// `pref[i * k + j]`: CR rule `i` is preferred to CR rule `j` (transitive closure).
    pub(super) fn preference_closure(&self) -> Vec<bool> {
        let k = self.cr_lits.len();
        let index = |a: u32| self.prog.cr_rules.iter().position(|c| c.appl == a);
        transitive_closure(
            k,
            self.prog
                .prefers
                .iter()
                .filter_map(|p| Some((index(p.better)?, index(p.worse)?))),
        )
    }
}

/// The transitive closure of the relation `edges` over `0..k`, as a `k * k` matrix in row
/// order (`reach[i * k + j]`: `j` is reachable from `i` in one or more steps; Warshall).
pub(crate) fn transitive_closure(
    k: usize,
    edges: impl IntoIterator<Item = (usize, usize)>,
) -> Vec<bool> {
    let mut reach = vec![false; k * k];
    for (i, j) in edges {
        reach[i * k + j] = true;
    }
    for m in 0..k {
        for i in 0..k {
            if reach[i * k + m] {
                for j in 0..k {
                    if reach[m * k + j] {
                        reach[i * k + j] = true;
                    }
                }
            }
        }
    }
    reach
}
