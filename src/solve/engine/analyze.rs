//! Conflict analysis: first-UIP learning with recursive clause minimisation, the LBD of
//! learnt clauses (computed at learning, lowered when a clause propagates), and the final
//! analysis of a failed assumption (the assumptions it rests on, `Engine::failed_assumptions`).
//!
//! Invariants: analysis never looks at level-0 assignments; the learnt clause has its asserting
//! literal first and a literal of the backjump level second.

use super::*;

impl Engine {
    /// Fills `failed` when assumption `a` is found false at decision level
    /// `<= assumptions.len()`: walks the implication graph of `!a` back to the assumption
    /// decisions it rests on (every decision at these levels is an assumption).
    pub(super) fn analyze_final(&mut self, a: Lit) {
        self.an.failed.clear();
        self.an.failed.push(a);
        let v0 = a.var();
        if self.asg.level[v0.index()] == 0 {
            return;
        }
        let Some(&start) = self.asg.trail_lim.first() else {
            return;
        };
        let mut marked: Vec<Var> = vec![v0];
        self.an.seen[v0.index()] = 1;
        let mut reason = Vec::new();
        for i in (start..self.asg.trail.len()).rev() {
            let x = self.asg.trail[i];
            let v = x.var();
            if self.an.seen[v.index()] == 0 {
                continue;
            }
            if matches!(self.asg.reason[v.index()], Reason::Decision) {
                // An assumption (`!a` itself when both `a` and `!a` were assumed).
                self.an.failed.push(x);
                continue;
            }
            reason.clear();
            self.reason_lits(v, &mut reason);
            for &q in &reason {
                let w = q.var();
                if self.an.seen[w.index()] == 0 && self.asg.level[w.index()] > 0 {
                    self.an.seen[w.index()] = 1;
                    marked.push(w);
                }
            }
        }
        for v in marked {
            self.an.seen[v.index()] = 0;
        }
    }

    // ---------------------------------------------------------------- analysis

    /// First-UIP analysis of `self.an.conflict`; leaves the learnt clause in `self.an.learnt`
    /// (asserting literal first, a literal of the backjump level second) and returns the
    /// backjump level. Works in reused buffers: no allocation per conflict once they are warm.
    pub(super) fn analyze(&mut self) -> u32 {
        let current = self.decision_level();
        let mut learnt = std::mem::take(&mut self.an.learnt);
        learnt.clear();
        learnt.push(Lit::from_code(0));
        let mut counter = 0usize;
        let mut index = self.asg.trail.len();
        let mut clause = std::mem::take(&mut self.an.conflict);
        let mut to_clear = std::mem::take(&mut self.an.to_clear);
        to_clear.clear();
        let mut p: Option<Lit> = None;
        loop {
            for &q in &clause {
                if Some(q) == p.map(|x| !x) || Some(q) == p {
                    continue;
                }
                let v = q.var();
                if self.an.seen[v.index()] == 0 && self.asg.level[v.index()] > 0 {
                    self.an.seen[v.index()] = 1;
                    to_clear.push(v);
                    self.bump_var(v);
                    if self.asg.level[v.index()] >= current {
                        counter += 1;
                    } else {
                        learnt.push(q);
                    }
                }
            }
            // Next literal of the current level on the trail.
            loop {
                index -= 1;
                if self.an.seen[self.asg.trail[index].var().index()] != 0 {
                    break;
                }
            }
            let pl = self.asg.trail[index];
            p = Some(pl);
            counter -= 1;
            if counter == 0 {
                learnt[0] = !pl;
                break;
            }
            clause.clear();
            match self.asg.reason[pl.var().index()] {
                Reason::Long(cref) => {
                    self.bump_clause(cref);
                    self.update_lbd(cref, pl);
                }
                Reason::Loop(id) => self.bump_loop(id),
                _ => {}
            }
            // The implied literal itself is not added, and the filter above skips it.
            self.reason_lits(pl.var(), &mut clause);
        }
        self.an.conflict = clause;
        // Recursive minimisation: drop literals implied by the others.
        let mut abstract_levels = 0u64;
        for &l in &learnt[1..] {
            abstract_levels |= 1u64 << (self.asg.level[l.var().index()] & 63);
        }
        let mut kept = 1;
        for k in 1..learnt.len() {
            let l = learnt[k];
            if matches!(self.asg.reason[l.var().index()], Reason::Decision)
                || !self.redundant(l, abstract_levels, &mut to_clear)
            {
                learnt[kept] = l;
                kept += 1;
            }
        }
        learnt.truncate(kept);
        for &l in &learnt {
            let v = l.var();
            self.heur.occ[v.index()] += if l.is_neg() { -1 } else { 1 };
        }
        for &v in &to_clear {
            self.an.seen[v.index()] = 0;
        }
        self.an.to_clear = to_clear;
        // Put a literal of the highest remaining level second.
        let mut bt = 0;
        if learnt.len() > 1 {
            let mut best = 1;
            for k in 2..learnt.len() {
                if self.asg.level[learnt[k].var().index()]
                    > self.asg.level[learnt[best].var().index()]
                {
                    best = k;
                }
            }
            learnt.swap(1, best);
            bt = self.asg.level[learnt[1].var().index()];
        }
        self.an.learnt = learnt;
        bt
    }

    /// Whether `l` (false, in the learnt clause) is implied by other literals of the clause.
    pub(super) fn redundant(
        &mut self,
        l: Lit,
        abstract_levels: u64,
        to_clear: &mut Vec<Var>,
    ) -> bool {
        let mut stack = std::mem::take(&mut self.an.min_stack);
        let mut buf = std::mem::take(&mut self.an.min_buf);
        stack.clear();
        stack.push(l);
        let top = to_clear.len();
        let mut result = true;
        'outer: while let Some(q) = stack.pop() {
            buf.clear();
            if self.settings.deletion == Deletion::Basic {
                // clasp counts a use of a clause in minimisation as in resolution.
                if let Reason::Long(cref) = self.asg.reason[q.var().index()] {
                    self.bump_clause(cref);
                }
            }
            self.reason_lits(q.var(), &mut buf);
            for &r in &buf {
                let v = r.var();
                if self.an.seen[v.index()] != 0 || self.asg.level[v.index()] == 0 {
                    continue;
                }
                let decision = matches!(self.asg.reason[v.index()], Reason::Decision);
                if !decision && (abstract_levels >> (self.asg.level[v.index()] & 63)) & 1 == 1 {
                    self.an.seen[v.index()] = 1;
                    to_clear.push(v);
                    stack.push(r);
                } else {
                    for w in to_clear.drain(top..) {
                        self.an.seen[w.index()] = 0;
                    }
                    result = false;
                    break 'outer;
                }
            }
        }
        self.an.min_stack = stack;
        self.an.min_buf = buf;
        result
    }

    /// Lowers the stored LBD of a learnt clause met in analysis when its literals now span
    /// fewer levels (clasp `--update-lbd=less`), so reductions keep clauses that became good.
    /// Under `Deletion::Basic` the levels are counted over the reason literals only (without
    /// the implied literal `implied`), as clasp does.
    pub(super) fn update_lbd(&mut self, cref: ClauseRef, implied: Lit) {
        let flags = self.clause_flags(cref);
        let old = flags >> 2;
        if flags & FLAG_LEARNT == 0 || old <= 2 {
            return;
        }
        self.an.lbd_stamp += 1;
        let stamp = self.an.lbd_stamp;
        let len = self.clause_len(cref);
        let mut n = 0;
        let skip_implied = self.settings.deletion == Deletion::Basic;
        for k in 0..len {
            let l = self.clause_lit(cref, k);
            if skip_implied && l == implied {
                continue;
            }
            if self.first_at_level(l, stamp) {
                n += 1;
                if n >= old {
                    return;
                }
            }
        }
        self.db.arena[cref as usize + 1] = (flags & 3) | (n << 2);
    }

    /// Whether `l` is the first literal of its decision level met under `stamp` (marks the
    /// level as met).
    #[inline]
    fn first_at_level(&mut self, l: Lit, stamp: u64) -> bool {
        let lv = self.asg.level[l.var().index()] as usize;
        if lv >= self.an.level_seen.len() {
            self.an.level_seen.resize(lv + 1, 0);
        }
        let first = self.an.level_seen[lv] != stamp;
        self.an.level_seen[lv] = stamp;
        first
    }

    /// Number of distinct decision levels among `lits` (literal block distance).
    pub(super) fn lbd(&mut self, lits: &[Lit]) -> u32 {
        self.an.lbd_stamp += 1;
        let stamp = self.an.lbd_stamp;
        let mut n = 0;
        for l in lits {
            if self.first_at_level(*l, stamp) {
                n += 1;
            }
        }
        n
    }
}
