//! Core-guided optimization (clasp's `--opt-strategy=usc`) with OLL relaxation, one priority
//! level at a time, highest first.
//!
//! A level's cost literals become *soft* literals: `(l, w)` costs `w` when `l` is true (a
//! negative weight `w` on `l` is the constant `w` plus `-w` on `!l`). Each search assumes every
//! soft literal false. A refutation names an unsatisfiable core among them (the failed
//! assumptions); with `m` the least weight in the core, the level's lower bound rises by `m`,
//! every weight of the core drops by `m`, and OLL adds the soft literal `sum(core) >= 2` of
//! weight `m`; when the output `sum(C) >= k` of an earlier core is in a core, `sum(C) >= k + 1`
//! is added with that core's `m`. Soft literals are assumed in strata of decreasing weight
//! (clasp's stratification): a model under a partial stratum is an upper bound, reported when it
//! improves on the last model reported, and lowers the stratum.
//!
//! Each core raises a lower bound, which the observer set by
//! [`Solver::set_lower_bound_observer`] is told (clingo's `on_unsat`): the optima of the levels
//! done, then the current level's bound, highest priority first. Branch and bound proves no
//! bound on the way, so it tells nothing, as clasp's model-guided search.
//!
//! Invariants:
//! - `lower` is a proven lower bound of the level's cost under the higher levels' optima, and
//!   the level's cost of every assignment is `lower + sum(weight of true soft literals)` (OLL's
//!   reformulation): so a model under all soft assumptions, or any model of cost `lower`, is
//!   optimal for the level.
//! - A finished level is fixed by the hard constraint `cost <= optimum`; cardinality outputs and
//!   the level bounds live in one guard's scope and are retired with it, so nothing outlives the
//!   call but learnt clauses.
//! - Reported models improve lexicographically, so the last one reported has the optimum costs
//!   (`Solver::best`), which `OptN` then enumerates as branch and bound's optimum.
//! - In a portfolio (`portfolio`), a cost vector another thread found bounds a level from above
//!   when it meets the optima of the levels above (as this thread's own models do); a search
//!   stopped by such news is resumed, never reported as a stop. When another thread's costs
//!   close the last level, `best` holds those costs (that thread passed the model on).

use super::*;
use hashbrown::HashMap;

/// Told each lower bound of the costs that core-guided optimization proves, highest priority
/// first (only the levels done and the current one), from the thread that solves.
pub type LowerBoundObserver = std::sync::Arc<std::sync::Mutex<dyn FnMut(&[i64]) + Send>>;

/// A soft literal of the level being optimized.
struct Soft {
    /// True costs `weight`; assumed false.
    lit: Lit,
    /// What is left of its weight (0: no longer assumed).
    weight: i64,
    /// When `lit` is the output `sum(cards[c]) >= k`: `(c, k)`.
    card: Option<(usize, usize)>,
}

/// The soft literals of one level and OLL's cardinality constraints over them.
#[derive(Default)]
struct Level {
    softs: Vec<Soft>,
    /// Soft index of each soft literal.
    index: HashMap<Lit, usize>,
    /// The literals of each core, in the order the cores were found.
    cards: Vec<Vec<Lit>>,
    /// Soft index of each cardinality output `(card, k)` made so far.
    outputs: HashMap<(usize, usize), usize>,
    /// Proven lower bound of the level's cost.
    lower: i64,
}

impl Level {
    /// The level's soft literals from its cost literals; the constant part goes to `lower`.
    fn new(lits: &[(Lit, i64)]) -> Level {
        let mut level = Level::default();
        for &(l, w) in lits {
            let (l, w) = if w < 0 {
                level.lower += w;
                (!l, -w)
            } else {
                (l, w)
            };
            if w != 0 {
                level.add_soft(l, w, None);
            }
        }
        level
    }

    /// Adds `w` to the weight of soft literal `l`, making it soft if it is not yet.
    fn add_soft(&mut self, l: Lit, w: i64, card: Option<(usize, usize)>) {
        match self.index.get(&l) {
            Some(&k) => self.softs[k].weight += w,
            None => {
                self.index.insert(l, self.softs.len());
                self.softs.push(Soft {
                    lit: l,
                    weight: w,
                    card,
                });
            }
        }
    }

    /// The highest weight below `stratum` among the soft literals, if any.
    fn next_stratum(&self, stratum: i64) -> Option<i64> {
        self.softs
            .iter()
            .map(|s| s.weight)
            .filter(|&w| w > 0 && w < stratum)
            .max()
    }

    /// The soft literals of a refutation's failed assumptions (sorted, distinct).
    fn core(&self, failed: &[Lit]) -> Vec<usize> {
        let mut core: Vec<usize> = failed
            .iter()
            .filter_map(|&a| self.index.get(&!a).copied())
            .filter(|&k| self.softs[k].weight > 0)
            .collect();
        core.sort_unstable();
        core.dedup();
        core
    }
}

/// How one search under a level's assumptions ended.
enum Step {
    /// A model; `done` when every soft literal was assumed (so it is optimal for the level).
    Model { done: bool },
    /// A core was relaxed.
    Relaxed,
    /// No model at all under the hard assumptions.
    Unsat,
    /// A limit stopped the call.
    Stop,
    /// Another thread of the portfolio found a better model (the search resumes).
    News,
}

/// The cost that `costs` gives the level after `fixed` when it meets their optima, else none
/// (`i64::MAX`).
pub(super) fn level_bound(costs: &[i64], fixed: &[i64]) -> i64 {
    match costs.get(fixed.len()) {
        Some(&c) if costs[..fixed.len()] == *fixed => c,
        _ => i64::MAX,
    }
}

impl Solver {
    /// Sets (or removes) the observer of proven lower bounds (see the module documentation).
    pub fn set_lower_bound_observer(&mut self, observer: Option<LowerBoundObserver>) {
        self.lower_observer = observer;
    }

    /// Tells the observer the bound `fixed ++ [lower]`.
    fn tell_lower(&self, fixed: &[i64], lower: i64) {
        if let Some(o) = &self.lower_observer {
            let mut bound = fixed.to_vec();
            bound.push(lower);
            (o.lock().unwrap_or_else(|p| p.into_inner()))(&bound);
        }
    }

    /// Core-guided optimization; returns true when the optimum was proven (as
    /// [`Solver::run_optimize`], whose contract it shares: improving models are reported when
    /// `report` is set, and `self.best` holds the optimum's costs).
    pub(super) fn run_core_guided(
        &mut self,
        call: &mut Call<'_>,
        assume: &[Lit],
        dedup: bool,
        report: bool,
    ) -> bool {
        let g = self.new_guard();
        let mut base = assume.to_vec();
        base.push(g);
        let mut reported: Option<Vec<i64>> = None;
        // The optima of the levels done so far.
        let mut fixed: Vec<i64> = Vec::new();
        let levels: Vec<Vec<(Lit, i64)>> =
            self.tr.minimize.iter().map(|(_, l)| l.clone()).collect();
        for (i, lits) in levels.iter().enumerate() {
            let mut level = Level::new(lits);
            let mut stratum = level.next_stratum(i64::MAX).unwrap_or(0);
            // The best model so far meets the optima of the levels above (it is the least
            // lexicographically), so its cost here bounds this level from above.
            let mut upper = reported
                .as_ref()
                .map_or(i64::MAX, |r| level_bound(r, &fixed));
            while upper.min(self.shared_level_bound(&fixed)) > level.lower {
                match self.core_step(call, &base, &mut level, stratum) {
                    Step::Model { done } => {
                        let costs = self.costs();
                        upper = upper.min(costs[i]);
                        if done {
                            // Under every soft assumption the cost is the lower bound.
                            upper = level.lower;
                        }
                        if reported.as_ref().is_none_or(|r| costs < *r) {
                            self.best = Some(costs.clone());
                            if report && !self.report(call, false, dedup) {
                                self.retire(g);
                                return false;
                            }
                            reported = Some(costs);
                        }
                        stratum = level.next_stratum(stratum).unwrap_or(0);
                    }
                    Step::Relaxed => self.tell_lower(&fixed, level.lower),
                    Step::News => {}
                    Step::Unsat => {
                        call.exhausted = true;
                        self.retire(g);
                        return false;
                    }
                    Step::Stop => {
                        self.retire(g);
                        return false;
                    }
                }
            }
            // The level's optimum is `lower`: fix it for the lower levels.
            fixed.push(level.lower);
            self.engine.backtrack(0);
            let neg: Vec<(Lit, i64)> = lits.iter().map(|&(l, w)| (l, -w)).collect();
            let b = self.aux_weight(g, &neg, level.lower.saturating_neg());
            self.engine.add_clause(&[!g, b]);
        }
        self.retire(g);
        if reported.as_ref() != Some(&fixed) {
            // Another thread's model closed the last level (module invariants).
            self.best = Some(fixed);
        }
        call.optimum = true;
        call.exhausted = true;
        true
    }

    /// One search under `base` and the soft literals of weight at least `stratum` assumed
    /// false; a core found is relaxed.
    fn core_step(
        &mut self,
        call: &mut Call<'_>,
        base: &[Lit],
        level: &mut Level,
        stratum: i64,
    ) -> Step {
        let mut a = base.to_vec();
        let all = level
            .softs
            .iter()
            .all(|s| s.weight == 0 || s.weight >= stratum);
        a.extend(
            level
                .softs
                .iter()
                .filter(|s| s.weight > 0 && s.weight >= stratum)
                .map(|s| !s.lit),
        );
        match self.next(&a) {
            Next::Stopped if self.engine.limits.bound_news => Step::News,
            Next::Stopped => {
                call.stopped = true;
                Step::Stop
            }
            Next::Model => Step::Model { done: all },
            Next::Exhausted => {
                let core = level.core(self.engine.failed_assumptions());
                if core.is_empty() {
                    return Step::Unsat;
                }
                self.relax(base[base.len() - 1], level, &core);
                Step::Relaxed
            }
        }
    }

    /// OLL's relaxation of `core` (soft indices) in `level`, its constraints owned by `guard`.
    fn relax(&mut self, guard: Lit, level: &mut Level, core: &[usize]) {
        let m = core
            .iter()
            .map(|&k| level.softs[k].weight)
            .min()
            .expect("a core is not empty");
        level.lower += m;
        for &k in core {
            level.softs[k].weight -= m;
        }
        let lits: Vec<Lit> = core.iter().map(|&k| level.softs[k].lit).collect();
        let next: Vec<(usize, usize)> = core
            .iter()
            .filter_map(|&k| level.softs[k].card)
            .map(|(c, k)| (c, k + 1))
            .filter(|&(c, k)| k <= level.cards[c].len())
            .collect();
        self.engine.backtrack(0);
        if lits.len() > 1 {
            level.cards.push(lits);
            let c = level.cards.len() - 1;
            self.card_output(guard, level, c, 2, m);
        }
        for (c, k) in next {
            self.card_output(guard, level, c, k, m);
        }
    }

    /// Adds `m` to the weight of the soft literal `sum(cards[c]) >= k`, defining it first.
    fn card_output(&mut self, guard: Lit, level: &mut Level, c: usize, k: usize, m: i64) {
        if let Some(&s) = level.outputs.get(&(c, k)) {
            level.softs[s].weight += m;
            return;
        }
        let lits: Vec<(Lit, i64)> = level.cards[c].iter().map(|&l| (l, 1)).collect();
        let out = self.aux_weight(guard, &lits, k as i64);
        level.add_soft(out, m, Some((c, k)));
        let s = level.index[&out];
        level.outputs.insert((c, k), s);
    }
}
