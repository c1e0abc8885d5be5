//! The learnt-clause database and level-0 simplification: reduction (Glucose's order or
//! clasp's basic policy), garbage collection of the arena, removal of clauses satisfied at
//! level 0, and freeing of retired variables.
//!
//! Invariants: a clause that is the reason of an assignment (locked) is never deleted; after
//! `simplify` no clause mentions a retired variable and every level-0 assignment has
//! `Reason::Decision`.

use super::*;

impl Engine {
    // ---------------------------------------------------------------- learnt clause database

    pub(super) fn locked(&self, cref: ClauseRef) -> bool {
        let l = self.clause_lit(cref, 0);
        self.val(l) == 1 && self.asg.reason[l.var().index()] == Reason::Long(cref)
    }

    pub(super) fn reduce_db(&mut self) {
        // Loop formulas first: the passes over the watch lists below drop their watches.
        self.reduce_loops();
        match self.settings.deletion {
            Deletion::Sorted => self.reduce_sorted(),
            Deletion::Basic => self.reduce_basic(),
        }
        if self.db.wasted * 4 > self.db.arena.len() {
            self.collect_garbage();
        } else {
            // Propagation never looks at deleted clauses: drop their watches now.
            let (arena, loops) = (&self.db.arena, &self.db.loops);
            for ws in self.db.watches.iter_mut() {
                ws.retain(|w| {
                    w.cref == u32::MAX
                        || if is_loop_watch(w.cref) {
                            loops.is_live(w.cref & !loops::LOOP_TAG)
                        } else {
                            arena[w.cref as usize + 1] & FLAG_DELETED == 0
                        }
                })
            }
        }
    }

    pub(super) fn delete_learnt(&mut self, c: ClauseRef) {
        self.db.arena[c as usize + 1] |= FLAG_DELETED;
        self.db.wasted += HEADER + self.clause_len(c);
    }

    /// `Deletion::Basic` (clasp's linear reduction): oldest first, keeps reasons, glue
    /// clauses (LBD <= 2), clauses of at most three literals and clauses used more than 1.5
    /// times the average; the uses of every kept clause are halved.
    pub(super) fn reduce_basic(&mut self) {
        let mut learnts = std::mem::take(&mut self.db.learnts);
        // Clauses of at most three literals live outside the database in clasp: they are
        // neither counted nor deleted.
        let (mut n, mut sum) = (0u64, 0u64);
        for &c in &learnts {
            if self.clause_len(c) > 3 {
                n += 1;
                sum += self.db.arena[c as usize + 2] as u64;
            }
        }
        let mut to_remove = n / 2;
        let avg = if n == 0 { 0.0 } else { sum as f64 / n as f64 };
        let mut active = avg * 1.5;
        if active > MAX_USES as f64 {
            active = (MAX_USES as f64 + avg) / 2.0;
        }
        learnts.retain(|&c| {
            let uses = self.db.arena[c as usize + 2];
            if self.clause_len(c) <= 3 {
                return true;
            }
            let keep = to_remove == 0
                || self.clause_flags(c) >> 2 <= 2
                || uses as f64 > active
                || self.locked(c);
            if keep {
                self.db.arena[c as usize + 2] = uses >> 1;
            } else {
                self.delete_learnt(c);
                to_remove -= 1;
            }
            keep
        });
        self.db.learnts = learnts;
    }

    /// `Deletion::Sorted`: deletes the worst half by LBD, then activity.
    pub(super) fn reduce_sorted(&mut self) {
        let mut cands: Vec<(u32, f32, ClauseRef)> = self
            .db
            .learnts
            .iter()
            .map(|&c| {
                (
                    self.clause_flags(c) >> 2,
                    f32::from_bits(self.db.arena[c as usize + 2]),
                    c,
                )
            })
            .collect();
        sort_worst_first(&mut cands);
        let target = cands.len() / 2;
        let mut removed = 0;
        let mut keep = Vec::with_capacity(cands.len());
        for (lbd, _, c) in cands {
            if removed < target && lbd > 2 && !self.locked(c) {
                self.delete_learnt(c);
                removed += 1;
            } else {
                keep.push(c);
            }
        }
        self.db.learnts = keep;
    }

    /// Moves the live clauses to the front of the arena, in order, and redirects the watch
    /// lists, reasons and learnt references. In place, so that the peak memory holds one
    /// arena, not the old one and a growing copy: a first pass writes each live clause's new
    /// position into its activity word (keeping the activities aside), the references are
    /// redirected through that word, and a second pass moves the clauses and puts the
    /// activities back.
    pub(super) fn collect_garbage(&mut self) {
        let mut activities = Vec::with_capacity(self.db.learnts.len());
        let (mut pos, mut to) = (0usize, 0usize);
        while pos < self.db.arena.len() {
            let len = self.db.arena[pos] as usize;
            if self.db.arena[pos + 1] & FLAG_DELETED == 0 {
                activities.push(self.db.arena[pos + 2]);
                self.db.arena[pos + 2] = to as u32;
                to += HEADER + len;
            }
            pos += HEADER + len;
        }
        let (arena, loops) = (&self.db.arena, &self.db.loops);
        let live = |c: u32| arena[c as usize + 1] & FLAG_DELETED == 0;
        for ws in self.db.watches.iter_mut() {
            ws.retain_mut(|w| {
                if w.cref == u32::MAX {
                    true
                } else if is_loop_watch(w.cref) {
                    loops.is_live(w.cref & !loops::LOOP_TAG)
                } else if live(w.cref) {
                    w.cref = arena[w.cref as usize + 2];
                    true
                } else {
                    false
                }
            });
        }
        // Only assigned variables have meaningful reasons; an unassigned one may hold a stale
        // reference that is not a clause start any more, so it is cleared, never followed.
        for (v, r) in self.asg.reason.iter_mut().enumerate() {
            if let Reason::Long(c) = r {
                if self.asg.values[2 * v] != 0 && live(*c) {
                    *c = arena[*c as usize + 2];
                } else {
                    *r = Reason::Decision;
                }
            }
        }
        for c in self.db.learnts.iter_mut() {
            debug_assert!(live(*c), "learnt references are live");
            *c = arena[*c as usize + 2];
        }
        let (mut pos, mut to) = (0usize, 0usize);
        let mut live_index = 0;
        while pos < self.db.arena.len() {
            let len = self.db.arena[pos] as usize;
            if self.db.arena[pos + 1] & FLAG_DELETED == 0 {
                self.db.arena.copy_within(pos..pos + HEADER + len, to);
                self.db.arena[to + 2] = activities[live_index];
                live_index += 1;
                to += HEADER + len;
            }
            pos += HEADER + len;
        }
        self.db.arena.truncate(to);
        self.db.wasted = 0;
    }

    // ---------------------------------------------------------------- level-0 simplification

    /// Removes clauses satisfied at decision level 0 and the literals false there, turning
    /// long clauses that shrink to two literals into binary watches (MiniSat's `simplify`,
    /// clasp's removal of satisfied constraints). Must be called at level 0 after a
    /// conflict-free propagation. Rebuilds the arena and the long-clause watches; every
    /// level-0 assignment gets `Reason::Decision` (analysis never looks at level 0).
    pub(super) fn simplify(&mut self) {
        debug_assert_eq!(self.decision_level(), 0);
        debug_assert_eq!(self.asg.qhead, self.asg.trail.len());
        for &l in &self.asg.trail {
            self.asg.reason[l.var().index()] = Reason::Decision;
        }
        // Binary clauses with an assigned literal are satisfied at level 0 (a false literal
        // forced its partner true).
        // Clauses mentioning a retired variable go too (`retire_vars`).
        for code in 0..self.db.watches.len() {
            if self.asg.values[code] != 0 || self.pool.retired[code >> 1] {
                self.db.watches[code].clear();
                continue;
            }
            let (values, retired) = (&self.asg.values, &self.pool.retired);
            self.db.watches[code].retain(|w| {
                w.cref == u32::MAX && values[w.other.code()] == 0 && !retired[w.other.var().index()]
            });
        }
        // In place (see `collect_garbage`): a clause only shrinks or goes, so the write
        // position never passes the read position, and a clause's literals are read before
        // its new place is written.
        let mut learnts = Vec::with_capacity(self.db.learnts.len());
        let mut lits: Vec<Lit> = Vec::new();
        let (mut pos, mut to) = (0usize, 0usize);
        let end = self.db.arena.len();
        while pos < end {
            let len = self.db.arena[pos] as usize;
            let flags = self.db.arena[pos + 1];
            let activity = self.db.arena[pos + 2];
            let next = pos + HEADER + len;
            if flags & FLAG_DELETED != 0 {
                pos = next;
                continue;
            }
            lits.clear();
            let mut satisfied = false;
            for k in pos + HEADER..next {
                let l = Lit::from_code(self.db.arena[k]);
                if self.pool.retired[l.var().index()] {
                    satisfied = true;
                    break;
                }
                match self.asg.values[l.code()] {
                    1 => {
                        satisfied = true;
                        break;
                    }
                    0 => lits.push(l),
                    _ => {}
                }
            }
            if !satisfied {
                debug_assert!(lits.len() >= 2, "propagation reached a fixpoint");
                if lits.len() == 2 {
                    self.watch_binary(lits[0], lits[1]);
                } else {
                    let cref = to as u32;
                    self.db.arena[to] = lits.len() as u32;
                    self.db.arena[to + 1] = flags;
                    self.db.arena[to + 2] = activity;
                    for (k, l) in lits.iter().enumerate() {
                        self.db.arena[to + HEADER + k] = l.code() as u32;
                    }
                    to += HEADER + lits.len();
                    self.db.watches[lits[0].code()].push(Watch {
                        cref,
                        other: lits[1],
                    });
                    self.db.watches[lits[1].code()].push(Watch {
                        cref,
                        other: lits[0],
                    });
                    if flags & FLAG_LEARNT != 0 {
                        learnts.push(cref);
                    }
                }
            }
            pos = next;
        }
        self.db.arena.truncate(to);
        self.db.learnts = learnts;
        self.db.wasted = 0;
        self.simplify_loops();
        self.free_dead_vars();
        self.sched.simp_assigns = self.asg.trail.len();
        self.sched.simp_props = self.stats.propagations + self.db.arena.len() as u64;
    }

    /// The end of `simplify`, once no clause mentions a retired variable: drops their level-0
    /// assignments (facts derived through them stay: see `retire_vars`) and frees them.
    pub(super) fn free_dead_vars(&mut self) {
        if self.pool.dead_vars.is_empty() {
            return;
        }
        let retired = &self.pool.retired;
        if self.asg.trail.iter().any(|l| retired[l.var().index()]) {
            self.wc.epoch += 1;
            let mut kept = Vec::with_capacity(self.asg.trail.len());
            for &l in &self.asg.trail {
                if self.pool.retired[l.var().index()] {
                    self.asg.values[l.code()] = 0;
                    self.asg.values[(!l).code()] = 0;
                } else {
                    kept.push(l);
                }
            }
            self.asg.trail = kept;
            self.asg.qhead = self.asg.trail.len();
            self.asg.pf_head = self.asg.qhead;
            self.uf.uf_clean_upto = self.uf.uf_clean_upto.min(self.asg.trail.len());
            if let Some(st) = &mut self.uf.stability {
                st.rescan();
            }
        }
        for v in std::mem::take(&mut self.pool.dead_vars) {
            let slot = self.wc.weight_slot[v.index()];
            debug_assert!(
                slot == NO_SLOT || self.wc.weight_watch[slot as usize].is_empty(),
                "a retired variable is in no weight constraint"
            );
            self.pool.free_vars.push(v);
        }
    }

    /// Runs `simplify` when new level-0 facts exist and enough propagation work was done since
    /// the last run to pay for a pass over the arena, or when many variables wait to be freed
    /// (a pass per quarter of the variables retired keeps their number bounded, at a cost per
    /// retired variable of about the clauses per variable).
    pub(super) fn maybe_simplify(&mut self) {
        if self.decision_level() == 0
            && ((self.asg.trail.len() > self.sched.simp_assigns
                && self.stats.propagations >= self.sched.simp_props)
                || self.pool.dead_vars.len() > 256 + self.num_vars() / 4)
        {
            self.simplify();
        }
    }
}

/// Sorts reduction candidates `(lbd, activity, id)` worst first: high LBD, then low activity.
pub(super) fn sort_worst_first<T>(cands: &mut [(u32, f32, T)]) {
    cands.sort_by(|a, b| {
        b.0.cmp(&a.0)
            .then(a.1.partial_cmp(&b.1).unwrap_or(std::cmp::Ordering::Equal))
    });
}
