//! The decision heuristic: VSIDS activities on a binary heap, clause activities, phase
//! saving and the sign score, random decisions, and the MOMS-like initial activities.
//!
//! Invariants: every unassigned decidable variable is in the heap (assigned ones may be too, and
//! are skipped when popped); activities are rescaled before they overflow.

use super::*;

impl Engine {
    // ---------------------------------------------------------------- heuristic

    pub(super) fn bump_var(&mut self, v: Var) {
        let a = &mut self.heur.activity[v.index()];
        *a += self.heur.var_inc;
        if *a > 1e100 {
            for x in self.heur.activity.iter_mut() {
                *x *= 1e-100;
            }
            self.heur.var_inc *= 1e-100;
        }
        if self.heur.heap_pos[v.index()] != NO_SLOT {
            self.heap_up(self.heur.heap_pos[v.index()] as usize);
        }
    }

    pub(super) fn bump_clause(&mut self, cref: ClauseRef) {
        if self.clause_flags(cref) & FLAG_LEARNT == 0 {
            return;
        }
        let i = cref as usize + 2;
        if self.settings.deletion == Deletion::Basic {
            self.db.arena[i] = (self.db.arena[i] + 1).min(MAX_USES);
            return;
        }
        let a = f32::from_bits(self.db.arena[i]) + self.db.cla_inc as f32;
        self.db.arena[i] = a.to_bits();
        if a > 1e20 {
            self.rescale_clause_activities();
        }
    }

    /// Scales every learnt clause's and loop formula's activity, and the increment, by 1e-20.
    /// Under `Deletion::Basic` the clauses hold use counters, which are left alone.
    pub(super) fn rescale_clause_activities(&mut self) {
        if self.settings.deletion == Deletion::Sorted {
            for &c in &self.db.learnts {
                let k = c as usize + 2;
                self.db.arena[k] = (f32::from_bits(self.db.arena[k]) * 1e-20).to_bits();
            }
        }
        self.rescale_loop_activities();
        self.db.cla_inc *= 1e-20;
    }

    pub(super) fn heap_less(&self, a: Var, b: Var) -> bool {
        self.heur.activity[a.index()] > self.heur.activity[b.index()]
    }

    pub(super) fn heap_insert(&mut self, v: Var) {
        if self.heur.heap_pos[v.index()] != NO_SLOT || !self.heur.decidable[v.index()] {
            return;
        }
        self.heur.heap.push(v);
        let i = self.heur.heap.len() - 1;
        self.heur.heap_pos[v.index()] = i as u32;
        self.heap_up(i);
    }

    pub(super) fn heap_up(&mut self, mut i: usize) {
        let v = self.heur.heap[i];
        while i > 0 {
            let parent = (i - 1) / 2;
            if !self.heap_less(v, self.heur.heap[parent]) {
                break;
            }
            self.heur.heap[i] = self.heur.heap[parent];
            self.heur.heap_pos[self.heur.heap[i].index()] = i as u32;
            i = parent;
        }
        self.heur.heap[i] = v;
        self.heur.heap_pos[v.index()] = i as u32;
    }

    pub(super) fn heap_down(&mut self, mut i: usize) {
        let v = self.heur.heap[i];
        let n = self.heur.heap.len();
        loop {
            let l = 2 * i + 1;
            if l >= n {
                break;
            }
            let r = l + 1;
            let c = if r < n && self.heap_less(self.heur.heap[r], self.heur.heap[l]) {
                r
            } else {
                l
            };
            if !self.heap_less(self.heur.heap[c], v) {
                break;
            }
            self.heur.heap[i] = self.heur.heap[c];
            self.heur.heap_pos[self.heur.heap[i].index()] = i as u32;
            i = c;
        }
        self.heur.heap[i] = v;
        self.heur.heap_pos[v.index()] = i as u32;
    }

    pub(super) fn heap_pop(&mut self) -> Option<Var> {
        if self.heur.heap.is_empty() {
            return None;
        }
        let top = self.heur.heap[0];
        let last = self.heur.heap.pop().expect("non-empty heap");
        self.heur.heap_pos[top.index()] = NO_SLOT;
        if !self.heur.heap.is_empty() {
            self.heur.heap[0] = last;
            self.heur.heap_pos[last.index()] = 0;
            self.heap_down(0);
        }
        Some(top)
    }

    pub(super) fn next_random(&mut self) -> u64 {
        // xorshift64*.
        self.heur.rng ^= self.heur.rng >> 12;
        self.heur.rng ^= self.heur.rng << 25;
        self.heur.rng ^= self.heur.rng >> 27;
        self.heur.rng.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// Remembers the polarity of `l` as its variable's phase (phase saving).
    #[inline]
    pub(super) fn save_phase(&mut self, l: Lit) {
        let i = l.var().index();
        self.heur.phase[i] = !l.is_neg();
        self.heur.phase_saved[i] = true;
    }

    /// The sign to decide `v` with: its saved phase, else (with `sign_from_learnts`) the
    /// polarity occurring more often in learnt clauses, else its initial sign.
    pub(super) fn decision_sign(&self, v: Var) -> bool {
        let i = v.index();
        match self.heur.dom_sign.get(i) {
            Some(1) => return true,
            Some(-1) => return false,
            _ => {}
        }
        if self.settings.sign_from_learnts && !self.heur.phase_saved[i] && self.heur.occ[i] != 0 {
            return self.heur.occ[i] > 0;
        }
        self.heur.phase[i]
    }

    /// Decides each of `lits` true when it is decided on (the sign of its variable set as
    /// [`Engine::prefer`] sets it), returning the signs replaced, for
    /// [`Engine::restore_signs`].
    pub(crate) fn push_signs(&mut self, lits: impl IntoIterator<Item = Lit>) -> Vec<(Var, i8)> {
        let mut saved = Vec::new();
        for l in lits {
            let v = l.var();
            if self.heur.dom_sign.len() <= v.index() {
                self.heur.dom_sign.resize(v.index() + 1, 0);
            }
            saved.push((v, self.heur.dom_sign[v.index()]));
            self.heur.dom_sign[v.index()] = if l.is_neg() { -1 } else { 1 };
        }
        saved
    }

    /// Undoes [`Engine::push_signs`] (in reverse, so a variable pushed twice gets its first
    /// sign back).
    pub(crate) fn restore_signs(&mut self, saved: Vec<(Var, i8)>) {
        for (v, s) in saved.into_iter().rev() {
            self.heur.dom_sign[v.index()] = s;
        }
    }

    /// A domain preference (clingo's `#heuristic` under `--heuristic=domain`): decide `v`
    /// with `sign` (when given), and before every variable of a lower level (when `level` is
    /// positive; the default level is 0).
    pub fn prefer(&mut self, v: Var, level: Option<i32>, sign: Option<bool>) {
        if let Some(s) = sign {
            if self.heur.dom_sign.len() <= v.index() {
                self.heur.dom_sign.resize(v.index() + 1, 0);
            }
            self.heur.dom_sign[v.index()] = if s { 1 } else { -1 };
        }
        if let Some(l) = level {
            self.heur.dom_order.retain(|&(_, x)| x != v);
            if l > 0 {
                self.heur.dom_order.push((l, v));
                // Stable: equal levels keep the order the statements gave.
                self.heur
                    .dom_order
                    .sort_by_key(|&(l, _)| std::cmp::Reverse(l));
            }
        }
    }

    pub(super) fn pick_branch(&mut self) -> Option<Lit> {
        for k in 0..self.heur.dom_order.len() {
            let v = self.heur.dom_order[k].1;
            if self.val(v.positive()) == 0 && self.heur.decidable[v.index()] {
                return Some(Lit::new(v, self.decision_sign(v)));
            }
        }
        if self.settings.random_permille > 0
            && !self.heur.heap.is_empty()
            && self.next_random() % 1000 < self.settings.random_permille as u64
        {
            let k = (self.next_random() % self.heur.heap.len() as u64) as usize;
            let v = self.heur.heap[k];
            if self.val(v.positive()) == 0 && self.heur.decidable[v.index()] {
                return Some(Lit::new(v, self.decision_sign(v)));
            }
        }
        while let Some(v) = self.heap_pop() {
            if self.val(v.positive()) == 0 && self.heur.decidable[v.index()] {
                return Some(Lit::new(v, self.decision_sign(v)));
            }
        }
        None
    }

    /// Seeds the VSIDS activities with a MOMS-like score (clasp `--init-moms`): variables
    /// occurring often in both polarities in short clauses come first. Scores are scaled into
    /// [0, 1], below one conflict bump, so learning takes over at the first conflict.
    pub(super) fn seed_activities(&mut self) {
        let n = self.num_vars();
        let mut occ = vec![0u64; 2 * n];
        for (code, ws) in self.db.watches.iter().enumerate() {
            // Each binary clause appears in two lists; count it once per literal.
            occ[code] += ws.iter().filter(|w| w.cref == u32::MAX).count() as u64;
        }
        let mut pos = 0usize;
        while pos < self.db.arena.len() {
            let len = self.db.arena[pos] as usize;
            if self.db.arena[pos + 1] & (FLAG_DELETED | FLAG_LEARNT) == 0 {
                for &c in &self.db.arena[pos + HEADER..pos + HEADER + len] {
                    occ[c as usize] += 1;
                }
            }
            pos += HEADER + len;
        }
        let score: Vec<f64> = (0..n)
            .map(|v| {
                let (p, q) = (occ[2 * v], occ[2 * v + 1]);
                ((p * q) as f64) * 1024.0 + (p + q) as f64
            })
            .collect();
        let max = score.iter().copied().fold(0.0f64, f64::max);
        if max <= 0.0 {
            return;
        }
        for (v, s) in score.into_iter().enumerate() {
            self.heur.activity[v] = s / max;
        }
        let vars: Vec<Var> = self.heur.heap.clone();
        self.heur.heap.clear();
        for v in vars {
            self.heur.heap_pos[v.index()] = NO_SLOT;
        }
        for v in 0..n {
            self.heap_insert(Var::new(v));
        }
    }
}
