//! Propagation to fixpoint: two-watched-literal unit propagation over binary and long clauses
//! (with blocker literals), native weight constraints with explanations stored per variable,
//! and, at every fixpoint, the unfounded-set propagator, the stability check of
//! non-head-cycle-free components (`solve::stability`) and then an external propagator
//! (`external`).
//!
//! Invariants: when a long clause is the reason of an assignment, the implied literal is at
//! position 0; on conflict the falsified clause is left in `Analysis::conflict`.

use super::*;

impl Engine {
    // ---------------------------------------------------------------- propagation

    /// Unit propagation to fixpoint, including weight constraints and unfounded sets. Returns
    /// `Some(())` on conflict, with the falsified clause in `self.an.conflict`.
    pub fn propagate(&mut self) -> Option<()> {
        loop {
            if self.propagate_units() {
                return Some(());
            }
            if self.uf.unfounded.is_some() {
                let start = self.uf.uf_clean_upto.min(self.asg.trail.len());
                if !self.uf.uf_dirty
                    && !self.asg.trail[start..]
                        .iter()
                        .any(|l| self.uf.uf_relevant[l.var().index()])
                {
                    self.uf.uf_clean_upto = self.asg.trail.len();
                } else {
                    let mut uf = self.uf.unfounded.take().expect("checked above");
                    let sets = uf.check(self, start);
                    self.uf.unfounded = Some(uf);
                    // The propagator has seen everything up to here; the nogoods' own
                    // assignments (and a backjump they may cause) start the next segment.
                    self.uf.uf_clean_upto = self.asg.trail.len();
                    self.uf.uf_dirty = false;
                    if !sets.is_empty() {
                        for set in sets {
                            if self.add_loop_set(&set.atoms, &set.ext) {
                                return Some(());
                            }
                        }
                        continue;
                    }
                }
            }
            if let Some(mut st) = self.uf.stability.take() {
                let sets = st.propagate(self);
                self.uf.stability = Some(st);
                if !sets.is_empty() {
                    for set in sets {
                        if self.add_loop_set(&set.atoms, &set.ext) {
                            return Some(());
                        }
                    }
                    continue;
                }
            }
            self.ext.as_ref()?;
            match self.propagate_external() {
                external::Step::Quiet => return None,
                external::Step::Changed => continue,
                external::Step::Conflict => return Some(()),
            }
        }
    }

    /// Clause and weight propagation; returns true on conflict.
    #[inline(never)]
    pub(super) fn propagate_units(&mut self) -> bool {
        while self.asg.qhead < self.asg.trail.len() {
            let p = self.asg.trail[self.asg.qhead];
            self.asg.qhead += 1;
            self.stats.propagations += 1;
            // The watch lists of the next few literals: their headers were prefetched when
            // they were assigned; now start loading the lists themselves.
            let end = self.asg.trail.len().min(self.asg.qhead + PREFETCH_AHEAD);
            let mut k = self.asg.pf_head.max(self.asg.qhead);
            while k < end {
                prefetch(self.db.watches[(!self.asg.trail[k]).code()].as_ptr());
                k += 1;
            }
            self.asg.pf_head = k;
            let slot = self.wc.weight_slot[p.var().index()];
            if slot == NO_SLOT {
                if self.propagate_clauses(p) {
                    return true;
                }
                continue;
            }
            // Count `p` in its weight constraints now: backtracking undoes every processed
            // position, even when a clause conflict stops this iteration early.
            let slot = slot as usize;
            for k in 0..self.wc.weight_watch[slot].len() {
                let w = self.wc.weight_watch[slot][k];
                let c = &mut self.wc.weights[w.id as usize];
                if w.lit == p {
                    c.sum_true += w.weight;
                } else {
                    c.sum_false += w.weight;
                }
            }
            if self.propagate_clauses(p) {
                return true;
            }
            let wl = std::mem::take(&mut self.wc.weight_watch[slot]);
            let mut wconflict = false;
            for w in &wl {
                if self.weight_may_propagate(w.id as usize) && self.propagate_weight(w.id as usize)
                {
                    wconflict = true;
                    break;
                }
            }
            self.wc.weight_watch[slot] = wl;
            if wconflict {
                return true;
            }
        }
        false
    }

    /// Visits the watch list of `!p` after `p` became true: binary clauses assign or conflict
    /// directly, long clauses are skipped when their blocker is true, else get a new watch or
    /// assign their other watched literal. Returns true on conflict (in `self.an.conflict`).
    pub(super) fn propagate_clauses(&mut self, p: Lit) -> bool {
        let false_lit = !p;
        let false_code = false_lit.code() as u32;
        let dl = self.asg.trail_lim.len() as u32;
        let mut ws = std::mem::take(&mut self.db.watches[false_lit.code()]);
        // Disjoint borrows of the fields the loop touches, so that assignments do not force
        // the compiler to reload every vector through `self`.
        let Engine {
            asg:
                Assignment {
                    values,
                    level,
                    reason,
                    trail,
                    ..
                },
            db: ClauseDb { arena, watches, .. },
            an: Analysis {
                conflict: conflict_lits,
                ..
            },
            ..
        } = self;
        let n = ws.len();
        let mut i = 0;
        let mut j = 0;
        let mut conflict = false;
        let mut loop_watches = false;
        while i < n {
            // Start loading the clause of the watch `CLAUSE_AHEAD` entries on, unless its
            // blocker is true (then its clause will not be read): the header load is the
            // main cache miss of propagation, and it now overlaps with this watch's work.
            if let Some(a) = ws.get(i + CLAUSE_AHEAD) {
                if a.cref & LOOP_TAG == 0 && values[a.other.code()] != 1 {
                    prefetch(arena.as_ptr().wrapping_add(a.cref as usize));
                }
            }
            let w = ws[i];
            i += 1;
            let bv = values[w.other.code()];
            if bv == 1 {
                ws[j] = w;
                j += 1;
                continue;
            }
            if w.cref == u32::MAX {
                ws[j] = w;
                j += 1;
                if bv == 0 {
                    let l = w.other;
                    values[l.code()] = 1;
                    values[(!l).code()] = -1;
                    level[l.var().index()] = dl;
                    reason[l.var().index()] = Reason::Binary(false_lit);
                    trail.push(l);
                    prefetch(watches.as_ptr().wrapping_add((!l).code()));
                } else {
                    conflict_lits.clear();
                    conflict_lits.push(w.other);
                    conflict_lits.push(false_lit);
                    conflict = true;
                    break;
                }
                continue;
            }
            if is_loop_watch(w.cref) {
                // Loop formulas are visited after the clauses (`propagate_loops`).
                ws[j] = w;
                j += 1;
                loop_watches = true;
                continue;
            }
            let cref = w.cref;
            debug_assert!(
                arena[cref as usize + 1] & FLAG_DELETED == 0,
                "watches of deleted clauses are removed"
            );
            let len = arena[cref as usize] as usize;
            let base = cref as usize + HEADER;
            let c = &mut arena[base..base + len];
            // Make sure the false literal is at position 1.
            if c[0] == false_code {
                c.swap(0, 1);
            }
            let first = Lit::from_code(c[0]);
            let fv = values[first.code()];
            if first != w.other && fv == 1 {
                ws[j] = Watch { cref, other: first };
                j += 1;
                continue;
            }
            let mut found = 0;
            for k in 2..len {
                if values[c[k] as usize] != -1 {
                    found = k;
                    break;
                }
            }
            if found != 0 {
                c.swap(1, found);
                watches[c[1] as usize].push(Watch { cref, other: first });
                continue;
            }
            ws[j] = Watch { cref, other: first };
            j += 1;
            if fv == -1 {
                conflict_lits.clear();
                conflict_lits.extend(c.iter().map(|&x| Lit::from_code(x)));
                conflict = true;
                break;
            }
            values[first.code()] = 1;
            values[(!first).code()] = -1;
            level[first.var().index()] = dl;
            reason[first.var().index()] = Reason::Long(cref);
            trail.push(first);
            prefetch(watches.as_ptr().wrapping_add((!first).code()));
        }
        keep_unvisited(&mut ws, i, j);
        // No watch of `false_lit` was added during the loop: new watches go to non-false
        // literals only.
        debug_assert!(self.db.watches[false_lit.code()].is_empty());
        self.db.watches[false_lit.code()] = ws;
        if loop_watches && !conflict {
            return self.propagate_loops(false_lit);
        }
        conflict
    }

    /// Whether the counters allow a propagation or conflict of the constraint (cheap test).
    pub(super) fn weight_may_propagate(&self, id: usize) -> bool {
        let c = &self.wc.weights[id];
        let max = c.total - c.sum_false;
        if max < c.bound || (c.sum_true >= c.bound && !c.implication) {
            return true;
        }
        match self.val(c.head) {
            1 => max.saturating_sub(c.max_weight) < c.bound,
            -1 => !c.implication && c.sum_true + c.max_weight >= c.bound,
            _ => false,
        }
    }

    /// Evaluates one weight constraint; returns true on conflict. Decisions use the counters
    /// (which lag behind the values only for assignments not yet processed, and only in the
    /// safe direction: fewer true and false literals), so every inference is sound; the
    /// remaining ones happen when the lagging assignments are processed. Literals are sorted by
    /// decreasing weight, so the scans stop at the first literal too light to matter.
    pub(super) fn propagate_weight(&mut self, id: usize) -> bool {
        let c = &self.wc.weights[id];
        let head = c.head;
        let bound = c.bound;
        let sum_true = c.sum_true;
        let max = c.total - c.sum_false;
        let hv = self.val(head);
        let implication = c.implication;
        if sum_true >= bound {
            if implication {
                return false;
            }
            match hv {
                1 => {}
                0 => self.assign_weight_implied(head, None, id, true),
                _ => {
                    let mut r = std::mem::take(&mut self.an.conflict);
                    r.clear();
                    r.push(head);
                    self.weight_lits(id, true, &mut r);
                    self.an.conflict = r;
                    return true;
                }
            }
            return false;
        }
        if max < bound {
            match hv {
                -1 => {}
                0 => self.assign_weight_implied(!head, None, id, false),
                _ => {
                    let mut r = std::mem::take(&mut self.an.conflict);
                    r.clear();
                    r.push(!head);
                    self.weight_lits(id, false, &mut r);
                    self.an.conflict = r;
                    return true;
                }
            }
            return false;
        }
        if hv == 1 {
            // Every unassigned literal whose loss would drop the maximum below the bound must
            // hold: weight > max - bound. The explanation (the false literals) does not change
            // while these literals become true.
            self.imply_heavy(id, max - bound, true, !head);
        } else if hv == -1 && !implication {
            // Every unassigned literal that would reach the bound must be false:
            // weight >= bound - sum_true (at least 1: `sum_true < bound` here). The explanation
            // (the true literals) does not change while these literals become false.
            self.imply_heavy(id, bound - sum_true - 1, false, head);
        }
        false
    }

    /// Assigns each unassigned literal of constraint `id` heavier than `limit` (true when
    /// `positive`, else false), with `extra` in its explanation. Literals are sorted by
    /// decreasing weight, so the scan stops at the first one of weight `limit` or less; it
    /// starts past the prefix found assigned earlier in this epoch and records the new prefix.
    fn imply_heavy(&mut self, id: usize, limit: u64, positive: bool, extra: Lit) {
        let mut first = None;
        let start = self.weight_scan_start(id);
        let mut prefix = start;
        for k in start..self.wc.weights[id].lits.len() {
            let (l, w) = self.wc.weights[id].lits[k];
            if w <= limit {
                break;
            }
            if self.val(l) == 0 {
                let implied = if positive { l } else { !l };
                first =
                    Some(self.assign_weight_implied_as(implied, first, id, Some(extra), !positive));
            }
            if k == prefix && self.val(l) != 0 {
                prefix += 1;
            }
        }
        self.wc.weights[id].scan_from = prefix as u32;
    }

    /// Where `propagate_weight`'s scans of constraint `id` start: past the prefix of its
    /// literals already found assigned in this epoch (0 in a new epoch).
    #[inline]
    fn weight_scan_start(&mut self, id: usize) -> usize {
        let epoch = self.wc.epoch;
        let c = &mut self.wc.weights[id];
        if c.scan_epoch != epoch {
            c.scan_epoch = epoch;
            c.scan_from = 0;
        }
        c.scan_from as usize
    }

    /// Appends the currently false literals of constraint `id` to `out`, or, when `of_true`,
    /// the negations of its currently true literals (both are false literals).
    pub(super) fn weight_lits(&self, id: usize, of_true: bool, out: &mut Vec<Lit>) {
        let want: i8 = if of_true { 1 } else { -1 };
        for &(l, _) in &self.wc.weights[id].lits {
            if self.asg.values[l.code()] == want {
                out.push(if of_true { !l } else { l });
            }
        }
    }

    /// The explanation slot of `l`'s variable (made on first use) and its buffer, taken out
    /// and holding `l` alone; the caller completes it and puts it back.
    #[inline]
    fn explanation_buffer(&mut self, l: Lit) -> (usize, Vec<Lit>) {
        let v = l.var().index();
        if self.asg.stored_slot[v] == NO_SLOT {
            self.asg.stored_slot[v] = self.asg.stored.len() as u32;
            self.asg.stored.push(Vec::new());
        }
        let slot = self.asg.stored_slot[v] as usize;
        let mut r = std::mem::take(&mut self.asg.stored[slot]);
        r.clear();
        r.push(l);
        (slot, r)
    }

    /// Assigns `l` with a stored explanation: `l`, then `extra` if given, then the literals of
    /// `weight_lits(id, of_true)`. Reuses the variable's explanation buffer.
    pub(super) fn assign_weight_implied(
        &mut self,
        l: Lit,
        extra: Option<Lit>,
        id: usize,
        of_true: bool,
    ) {
        let (slot, mut r) = self.explanation_buffer(l);
        r.extend(extra);
        self.weight_lits(id, of_true, &mut r);
        self.asg.stored[slot] = r;
        self.assign(l, Reason::Stored);
    }

    /// [`Engine::assign_weight_implied`] for the literals one evaluation of constraint `id`
    /// implies together, whose explanations differ only in the implied literal: the first
    /// (`like` None) collects it, the later ones copy it from the first's buffer (`like`, the
    /// returned slot). Returns the explanation's slot.
    fn assign_weight_implied_as(
        &mut self,
        l: Lit,
        like: Option<usize>,
        id: usize,
        extra: Option<Lit>,
        of_true: bool,
    ) -> usize {
        let Some(src) = like else {
            self.assign_weight_implied(l, extra, id, of_true);
            return self.asg.stored_slot[l.var().index()] as usize;
        };
        let (slot, mut r) = self.explanation_buffer(l);
        r.extend_from_slice(&self.asg.stored[src][1..]);
        self.asg.stored[slot] = r;
        self.assign(l, Reason::Stored);
        src
    }

    /// Appends the false literals of the reason of `v` (excluding `v` itself) to `out`.
    pub(super) fn reason_lits(&self, v: Var, out: &mut Vec<Lit>) {
        match self.asg.reason[v.index()] {
            Reason::Decision => {}
            Reason::Binary(l) => out.push(l),
            Reason::Long(cref) => {
                // The implied literal is at position 0 of its reason (module invariant).
                let c = cref as usize;
                let lits = &self.db.arena[c + HEADER..c + HEADER + self.db.arena[c] as usize];
                debug_assert_eq!(Lit::from_code(lits[0]).var(), v);
                out.extend(lits[1..].iter().map(|&x| Lit::from_code(x)));
            }
            Reason::Stored => out.extend(
                self.asg.stored[self.asg.stored_slot[v.index()] as usize]
                    .iter()
                    .copied()
                    .filter(|l| l.var() != v),
            ),
            Reason::Loop(id) => self.loop_reason_lits(id, v, out),
        }
    }
}
