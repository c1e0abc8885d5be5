//! The solver's strategies over the search primitives: plain enumeration, lexicographic
//! branch-and-bound optimization (clasp's "opt") and brave/cautious consequences.
//!
//! Invariants: the last model of an optimization is reported optimal only once the bound below
//! it is unsatisfiable; for consequences each model reports the current estimate and the next
//! model must change it (a clause on the call's guard), so the last one reported is the answer.

use super::*;
use hashbrown::HashMap;

impl Solver {
    // ------------------------------------------------------------------ strategies

    pub(super) fn run_main(&mut self, call: &mut Call<'_>, assume: &[Lit], guard: Lit) {
        let dedup = !self.cr_lits.is_empty();
        match self.config.enum_mode {
            EnumMode::Brave | EnumMode::Cautious => self.run_consequences(call, assume, guard),
            EnumMode::Auto => {
                let optimize =
                    !self.tr.minimize.is_empty() && self.config.opt_mode != OptMode::Ignore;
                match self.config.opt_mode.clone() {
                    OptMode::Opt if optimize => {
                        self.run_opt_strategy(call, assume, dedup);
                    }
                    OptMode::OptN if optimize => {
                        call.unlimited = true;
                        let proven = self.run_opt_strategy(call, assume, dedup);
                        call.unlimited = false;
                        if proven && !call.done {
                            if let Some(best) = self.best.clone() {
                                let g = self.new_guard();
                                self.add_cost_bound(g, &best, true);
                                let mut a2 = assume.to_vec();
                                a2.push(g);
                                call.optimum = false;
                                call.phase_count = 0;
                                call.seen.clear();
                                let ok = self.run_enumerate(call, &a2, g, dedup, true);
                                call.optimum = ok;
                                self.retire(g);
                            }
                        }
                    }
                    OptMode::Enum(bound) if optimize && !bound.is_empty() => {
                        let g = self.new_guard();
                        self.add_cost_bound(g, &bound, true);
                        let mut a2 = assume.to_vec();
                        a2.push(g);
                        self.run_enumerate(call, &a2, g, dedup, false);
                        self.retire(g);
                    }
                    _ => {
                        self.run_enumerate(call, assume, guard, dedup, false);
                    }
                }
            }
        }
    }

    /// Finds an optimum with the configured strategy, reporting improving models; returns true
    /// when the optimum was proven.
    fn run_opt_strategy(&mut self, call: &mut Call<'_>, assume: &[Lit], dedup: bool) -> bool {
        match self.config.opt_strategy {
            OptStrategy::Bb => self.run_optimize(call, assume, dedup, true),
            OptStrategy::Usc => self.run_core_guided(call, assume, dedup, true),
        }
    }

    /// Enumerates answer sets; returns true when the space was exhausted.
    pub(super) fn run_enumerate(
        &mut self,
        call: &mut Call<'_>,
        assume: &[Lit],
        guard: Lit,
        dedup: bool,
        optimal: bool,
    ) -> bool {
        let projection = self.projection();
        let mut resume = false;
        loop {
            match self.next_from(assume, std::mem::take(&mut resume)) {
                Next::Exhausted => {
                    call.exhausted = true;
                    return true;
                }
                Next::Stopped => {
                    call.stopped = true;
                    return false;
                }
                Next::Model => {
                    // A model reached without a decision beyond the assumptions (one level
                    // each) is the only one: the space is exhausted even if the model limit
                    // stops the enumeration here, as clasp reports it.
                    let unique = self.engine.decision_level() as usize <= assume.len();
                    let go = self.report(call, optimal, dedup);
                    if !go {
                        // The next call starts over from level 0, with the model's values as
                        // the saved phases. No clause blocks the model: the call's guard retires
                        // it anyway, and adding it would first flip the last decision, which
                        // the backtrack would then save as that variable's phase (a later
                        // step's call then starts its search off the model it should extend).
                        // The phases are saved explicitly: the backtrack saves them only when
                        // it crosses more than `save_progress` levels (160 under tweety's).
                        self.engine.save_model_phases();
                        self.engine.backtrack(0);
                        if unique {
                            call.exhausted = true;
                        }
                        return unique;
                    }
                    let resumable = self.block(guard, &projection);
                    resume = resumable;
                }
            }
        }
    }

    /// Branch and bound; returns true when the optimum was proven. Reports improving models
    /// when `report` is set, otherwise remembers the best one in `call.seen`-independent state.
    pub(super) fn run_optimize(
        &mut self,
        call: &mut Call<'_>,
        assume: &[Lit],
        dedup: bool,
        report: bool,
    ) -> bool {
        let mut bound_guard = BoundGuard::default();
        let mut found = false;
        let mut resume = false;
        loop {
            // Portfolio: a better bound another thread found (`portfolio`).
            if self.adopt_bound(&mut bound_guard) {
                found = true;
                resume = false;
            }
            let mut a = assume.to_vec();
            if let Some(g) = bound_guard.guard {
                a.push(g);
            }
            match self.next_from(&a, std::mem::take(&mut resume)) {
                Next::Exhausted => {
                    if let Some(g) = bound_guard.guard {
                        self.retire(g);
                    }
                    if found {
                        call.optimum = true;
                        call.exhausted = true;
                    } else {
                        call.exhausted = true;
                    }
                    return found;
                }
                Next::Stopped if self.engine.limits.bound_news => {}
                Next::Stopped => {
                    call.stopped = true;
                    if let Some(g) = bound_guard.guard {
                        self.retire(g);
                    }
                    return false;
                }
                Next::Model => {
                    found = true;
                    let costs = self.costs();
                    self.best = Some(costs.clone());
                    if report && !self.report(call, false, dedup) {
                        if let Some(g) = bound_guard.guard {
                            self.retire(g);
                        }
                        return false;
                    }
                    resume = self.tighten_bound(&mut bound_guard, &costs, true);
                }
            }
        }
    }

    /// Makes `bg` the guard of `costs <lex bound`. When its constraint can say that with a new
    /// bound (one weight constraint over all levels, see `combined_cost`), the bound is raised
    /// in place: the clauses learnt under the old bound follow from the new one and stay.
    /// Otherwise a fresh guard with a fresh constraint replaces the old one, which is retired
    /// with what was learnt from it. With `resuming`, on the total assignment of a model whose
    /// costs are `bound`, an in-place raise backtracks only as far as the new bound needs;
    /// returns true when the search may go on from the assignment left (`next_from`).
    pub(super) fn tighten_bound(
        &mut self,
        bg: &mut BoundGuard,
        bound: &[i64],
        resuming: bool,
    ) -> bool {
        let Some(c) = self.combined_cost(bound) else {
            let g = self.new_guard();
            self.add_cost_bound(g, bound, false);
            if let Some(old) = bg.guard.replace(g) {
                self.retire(old);
            }
            bg.raisable = false;
            return false;
        };
        // costs < bound  <=>  -cost >= 1 - c.
        let at_least = 1 - c;
        if bg.raisable {
            if let Some(g) = bg.guard {
                let raised = if resuming {
                    self.engine.raise_weight_bound_resuming(g, at_least)
                } else {
                    self.engine.raise_weight_bound(g, at_least)
                };
                if raised {
                    return resuming;
                }
                // Not raisable after all when its constraint only fixed `g` false: then `g`
                // is false at level 0 and the next search fails on it.
                if self.engine.value(g) == Some(false) {
                    return false;
                }
            }
        }
        let g = self.new_guard();
        let neg: Vec<(Lit, i64)> = self.combined_lits().iter().map(|&(l, w)| (l, -w)).collect();
        self.engine.add_weight_implication(g, &neg, at_least);
        self.scope(g).weights.push(g);
        if let Some(old) = bg.guard.replace(g) {
            self.retire(old);
        }
        bg.raisable = true;
        false
    }

    /// The multipliers that fold the cost levels into one sum ordered as the levels are,
    /// lexicographically: a level's multiplier exceeds the range of every sum the levels
    /// below it can take. None when the folded sums might leave +-2^62.
    fn level_multipliers(&self) -> Option<Vec<i128>> {
        let levels = &self.tr.minimize;
        let mut mult = vec![0i128; levels.len()];
        let mut m: i128 = 1;
        let mut extent: i128 = 0;
        for (i, (_, lits)) in levels.iter().enumerate().rev() {
            let lo: i128 = lits.iter().map(|&(_, w)| (w as i128).min(0)).sum();
            let hi: i128 = lits.iter().map(|&(_, w)| (w as i128).max(0)).sum();
            mult[i] = m;
            extent = extent.checked_add((hi - lo).checked_mul(m)?)?;
            if extent >= 1 << 62 {
                return None;
            }
            m = m.checked_mul(hi - lo + 1)?;
        }
        Some(mult)
    }

    /// The folded cost (`level_multipliers`) of the level costs `costs`, which must give every
    /// level; None when the levels do not fold.
    fn combined_cost(&self, costs: &[i64]) -> Option<i64> {
        if costs.len() != self.tr.minimize.len() || costs.is_empty() {
            return None;
        }
        let mult = self.level_multipliers()?;
        let c: i128 = costs.iter().zip(&mult).map(|(&c, &m)| c as i128 * m).sum();
        i64::try_from(c).ok()
    }

    /// The literals of all levels with their folded weights (`level_multipliers`), one entry
    /// per literal.
    fn combined_lits(&self) -> Vec<(Lit, i64)> {
        let mult = self.level_multipliers().expect("the levels fold");
        let mut acc: HashMap<Lit, i128> = HashMap::new();
        let mut order = Vec::new();
        for ((_, lits), &m) in self.tr.minimize.iter().zip(&mult) {
            for &(l, w) in lits {
                let e = acc.entry(l).or_insert_with(|| {
                    order.push(l);
                    0
                });
                *e += w as i128 * m;
            }
        }
        order
            .into_iter()
            .filter_map(|l| {
                let w = acc[&l];
                (w != 0).then_some((l, w as i64))
            })
            .collect()
    }

    pub(super) fn run_consequences(&mut self, call: &mut Call<'_>, assume: &[Lit], guard: Lit) {
        let brave = self.config.enum_mode == EnumMode::Brave;
        let n = self.tr.output_lits.len();
        let mut current: Option<Vec<bool>> = None;
        let mut current_atoms: Option<Vec<u32>> = None;
        // As clasp: brave consequences decide the shown atoms true first (each model adds as
        // many as it can), cautious ones false (each model removes as many), so the first
        // approximation is already close and `-n 1` gives clingo's.
        let signs =
            self.engine.push_signs(
                self.tr
                    .output_lits
                    .iter()
                    .map(|&l| if brave { l } else { !l }),
            );
        loop {
            match self.next(assume) {
                Next::Exhausted => {
                    call.exhausted = true;
                    break;
                }
                Next::Stopped => {
                    call.stopped = true;
                    break;
                }
                Next::Model => {
                    let truth: Vec<bool> = self
                        .tr
                        .output_lits
                        .iter()
                        .map(|&l| self.engine.value(l) == Some(true))
                        .collect();
                    let cur = match current.take() {
                        None => truth,
                        Some(c) => (0..n)
                            .map(|i| {
                                if brave {
                                    c[i] || truth[i]
                                } else {
                                    c[i] && truth[i]
                                }
                            })
                            .collect(),
                    };
                    let mut m = self.model(call.count + 1, false, call.with_support);
                    m.symbols.clear();
                    let mut shown: HashSet<&str> = HashSet::new();
                    for (i, o) in self.prog.outputs.iter().enumerate() {
                        if cur[i] && shown.insert(o.symbol.as_str()) {
                            m.symbols.push(o.symbol.clone());
                        }
                    }
                    // The model is the consequences so far, as clasp reports them: its true
                    // atoms are the union (brave) or intersection (cautious) of the answer
                    // sets' (both lists sorted).
                    let atoms = match current_atoms.take() {
                        None => m.atoms.clone(),
                        Some(c) if brave => {
                            let mut u: Vec<u32> = c.iter().chain(&m.atoms).copied().collect();
                            u.sort_unstable();
                            u.dedup();
                            u
                        }
                        Some(c) => c
                            .into_iter()
                            .filter(|a| m.atoms.binary_search(a).is_ok())
                            .collect(),
                    };
                    m.atoms.clone_from(&atoms);
                    current_atoms = Some(atoms);
                    call.note_model();
                    if !(call.sink)(&m, &self.prog) {
                        call.done = true;
                        break;
                    }
                    // `-n N`: N approximations, as clasp (`clingo -e cautious 1` prints one).
                    if self.config.models > 0 && call.count >= self.config.models {
                        call.done = true;
                        break;
                    }
                    let mut c = vec![!guard];
                    for (&l, &now) in self.tr.output_lits.iter().zip(&cur) {
                        if brave && !now {
                            c.push(l);
                        } else if !brave && now {
                            c.push(!l);
                        }
                    }
                    current = Some(cur);
                    self.engine.add_clause(&c);
                }
            }
        }
        self.engine.restore_signs(signs);
    }
}

/// The guard of the current bound of a branch-and-bound search.
#[derive(Default)]
pub(super) struct BoundGuard {
    pub(super) guard: Option<Lit>,
    /// The guard's constraint is one `add_weight_implication` over the folded levels.
    pub(super) raisable: bool,
}
