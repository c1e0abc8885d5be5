//! The search loop: decisions, conflicts, backjumps, restarts (Luby, glucose with blocking),
//! limits and assumptions.
//!
//! Invariants: assumptions occupy decision levels `1..=assumptions.len()`; a model stays on the
//! trail until the next `backtrack` or `add_clause`.

use super::*;

impl Engine {
    // ---------------------------------------------------------------- search

    pub(super) fn luby(mut i: u32) -> u64 {
        // The Luby sequence 1 1 2 1 1 2 4 ... at 0-based index i.
        let mut size = 1u64;
        let mut seq = 0u32;
        while size < i as u64 + 1 {
            seq += 1;
            size = 2 * size + 1;
        }
        let mut x = i as u64;
        while size - 1 != x {
            size = (size - 1) >> 1;
            seq -= 1;
            x %= size;
        }
        let _ = &mut i;
        1u64 << seq
    }

    pub(super) fn should_restart(&mut self, lbd: Option<u32>) -> bool {
        match &mut self.sched.restarts {
            Restarts::Never => false,
            Restarts::Luby { unit, index, left } => {
                if lbd.is_some() {
                    *left = left.saturating_sub(1);
                }
                if *left == 0 {
                    *index += 1;
                    *left = Engine::luby(*index) * *unit as u64;
                    return true;
                }
                false
            }
            Restarts::Glucose {
                fast,
                slow,
                since,
                trail,
            } => {
                if let Some(l) = lbd {
                    let l = l as f64;
                    *fast += (l - *fast) / 32.0;
                    *slow += (l - *slow) / 10000.0f64.min(self.stats.conflicts as f64 + 1.0);
                    *since += 1;
                    let t = self.an.conflict_trail as f64;
                    if self.settings.restart_blocking
                        && self.stats.conflicts > 10000
                        && t > 1.4 * *trail
                    {
                        *since = 0;
                    }
                    *trail += (t - *trail) / 5000.0f64.min(self.stats.conflicts as f64 + 1.0);
                }
                if *since >= 50 && *fast > 1.25 * *slow {
                    *since = 0;
                    return true;
                }
                false
            }
        }
    }

    pub(super) fn limit_reached(&mut self) -> bool {
        if let Some(flag) = &self.limits.portfolio_stop {
            if flag.load(Ordering::Relaxed) {
                return true;
            }
        }
        if let Some(flag) = &self.limits.interrupt {
            if flag.load(Ordering::Relaxed) {
                self.limits.interrupted = true;
                return true;
            }
        }
        if let Some(g) = &self.limits.bound_gen {
            if g.load(Ordering::Relaxed) != self.limits.bound_seen {
                self.limits.bound_news = true;
                return true;
            }
        }
        if let Some(d) = self.limits.deadline {
            if Instant::now() >= d {
                return true;
            }
        }
        self.limits.conflict_hit = self
            .limits
            .conflict_limit
            .is_some_and(|n| self.stats.conflicts >= n);
        self.limits.conflict_hit
    }

    /// Switches to clasp's phase handling for the rest of the search call
    /// (`Engine::phase_switch`).
    fn switch_phases(&mut self) {
        self.heur.phase_switched =
            Some((self.settings.save_progress, self.settings.sign_from_learnts));
        self.stats.phase_switches += 1;
        self.settings.save_progress = PHASE_SWITCH_PROGRESS;
        self.settings.sign_from_learnts = true;
        self.heur.phase_saved.iter_mut().for_each(|s| *s = false);
    }

    /// Saves the phase of every variable as the assignment on the trail (a model) has it,
    /// whatever `save_progress` says. Called when a call ends on a model: a later call
    /// without new clauses or other assumptions then decides as this model does and meets no
    /// conflict, so it finds the same model (the promise of `control::Control::solve`). Not
    /// called between the models of one enumeration: starting next to the last model made
    /// projected enumerations (the planner's) wade through its many neighbours with the same
    /// projection.
    pub fn save_model_phases(&mut self) {
        for i in 0..self.asg.trail.len() {
            self.save_phase(self.asg.trail[i]);
        }
    }

    /// Searches for a total assignment extending `assumptions`. On `Sat` the assignment stays
    /// on the trail until the next `backtrack`/`add_clause`.
    pub fn search(&mut self, assumptions: &[Lit]) -> SearchResult {
        self.search_from(assumptions, false)
    }

    /// [`Engine::search`]; with `resume`, goes on from the current assignment instead of level
    /// 0 (after [`Engine::add_clause_resuming`], with the same assumptions as the search that
    /// made this assignment).
    pub fn search_from(&mut self, assumptions: &[Lit], resume: bool) -> SearchResult {
        self.limits.interrupted = false;
        self.limits.conflict_hit = false;
        self.limits.bound_news = false;
        self.an.failed.clear();
        self.set_external_root(assumptions.len());
        if let Some((save_progress, sign)) = self.heur.phase_switched.take() {
            self.settings.save_progress = save_progress;
            self.settings.sign_from_learnts = sign;
        }
        let switch_at = self
            .settings
            .phase_switch
            .map(|k| self.stats.conflicts.saturating_add(k));
        if self.inconsistent {
            return SearchResult::Unsat;
        }
        if !resume || self.decision_level() == 0 {
            self.backtrack(0);
            if self.propagate().is_some() || !self.exchange() {
                self.inconsistent = true;
                return SearchResult::Unsat;
            }
            self.maybe_simplify();
        }
        if self.settings.init_moms {
            self.settings.init_moms = false;
            self.seed_activities();
        }
        let mut ticks: u64 = 0;
        loop {
            ticks += 1;
            if ticks & 255 == 0 && self.limit_reached() {
                self.backtrack(0);
                return SearchResult::Unknown;
            }
            if self.propagate().is_some() {
                self.stats.conflicts += 1;
                if switch_at == Some(self.stats.conflicts) {
                    self.switch_phases();
                }
                // The conflict may lie entirely below the current level (clauses added during
                // search); move down to its highest level first.
                let max_level = self
                    .an
                    .conflict
                    .iter()
                    .map(|l| self.asg.level[l.var().index()])
                    .max()
                    .unwrap_or(0);
                if max_level == 0 {
                    self.inconsistent = true;
                    self.backtrack(0);
                    return SearchResult::Unsat;
                }
                if max_level < self.decision_level() {
                    self.backtrack(max_level);
                }
                self.an.conflict_trail = self.asg.trail.len();
                let bt = self.analyze();
                let learnt = std::mem::take(&mut self.an.learnt);
                let lbd = self.lbd(&learnt);
                self.export_learnt(&learnt, lbd);
                self.backtrack(bt);
                if learnt.len() == 1 {
                    self.assign(learnt[0], Reason::Decision);
                } else {
                    let r = self.attach(&learnt, true, lbd);
                    let r = match r {
                        Reason::Binary(_) => Reason::Binary(learnt[1]),
                        other => other,
                    };
                    self.assign(learnt[0], r);
                }
                self.an.learnt = learnt;
                self.heur.var_inc /= self.heur.var_decay;
                self.db.cla_inc /= 0.999;
                if self.should_restart(Some(lbd)) {
                    self.stats.num_restarts += 1;
                    self.backtrack(0);
                    if !self.exchange() {
                        return SearchResult::Unsat;
                    }
                }
                continue;
            }
            self.maybe_simplify();
            match self.settings.reduce {
                ReduceSchedule::Size => {
                    // A loop formula counts as the clauses it stands for.
                    let learnts = self.db.learnts.len() + self.db.loops.clauses;
                    if learnts as f64 >= self.sched.max_learnts + self.asg.trail.len() as f64 {
                        self.reduce_db();
                        self.sched.max_learnts *= 1.1;
                    }
                }
                ReduceSchedule::Conflicts { first, inc, repeat } => {
                    if self.sched.next_reduce == 0 {
                        self.sched.next_reduce = self.stats.conflicts + first;
                        self.sched.reduce_len = repeat;
                    }
                    if self.stats.conflicts >= self.sched.next_reduce {
                        self.sched.reductions += 1;
                        self.sched.reduce_idx += 1;
                        if self.sched.reduce_len > 0
                            && self.sched.reduce_idx >= self.sched.reduce_len
                        {
                            self.sched.reduce_idx = 0;
                            self.sched.reduce_len += 1;
                        }
                        self.sched.next_reduce =
                            self.stats.conflicts + first + self.sched.reduce_idx * inc;
                        self.reduce_db();
                    }
                }
            }
            let level = self.decision_level() as usize;
            let next = if level < assumptions.len() {
                let a = assumptions[level];
                match self.val(a) {
                    1 => {
                        // Already true: open an empty level to keep levels aligned.
                        self.asg.trail_lim.push(self.asg.trail.len());
                        continue;
                    }
                    -1 => {
                        self.analyze_final(a);
                        self.backtrack(0);
                        return SearchResult::Unsat;
                    }
                    _ => a,
                }
            } else {
                match self.pick_branch() {
                    Some(l) => l,
                    // A total assignment: an external propagator's `check` may still refute
                    // it (a clause, then conflict analysis) or extend it.
                    None if self.ext.is_some() && self.check_external() => continue,
                    None => return SearchResult::Sat,
                }
            };
            self.stats.decisions += 1;
            self.asg.trail_lim.push(self.asg.trail.len());
            self.assign(next, Reason::Decision);
        }
    }
}
