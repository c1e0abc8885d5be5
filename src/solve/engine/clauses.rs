//! The clause store: long clauses in one arena with a three-word header, binary clauses only
//! in the watch lists, adding clauses at level 0 and during search, and native weight
//! constraints (adding, removing and recycling their slots).
//!
//! Invariants: the first two literals of every long clause are its watched literals; a clause
//! added during search is ordered first (true, unassigned, then false by decreasing level) and
//! an asserting one backjumps to the level where it became unit, so its watches are valid on
//! the current trail.

use super::*;

impl Engine {
    // ---------------------------------------------------------------- clauses

    pub(super) fn clause_len(&self, cref: ClauseRef) -> usize {
        self.db.arena[cref as usize] as usize
    }

    pub(super) fn clause_lit(&self, cref: ClauseRef, i: usize) -> Lit {
        Lit::from_code(self.db.arena[cref as usize + HEADER + i])
    }

    pub(super) fn clause_flags(&self, cref: ClauseRef) -> u32 {
        self.db.arena[cref as usize + 1]
    }

    pub(super) fn alloc_clause(&mut self, lits: &[Lit], learnt: bool, lbd: u32) -> ClauseRef {
        let cref = self.db.arena.len() as u32;
        self.db.arena.push(lits.len() as u32);
        self.db
            .arena
            .push(if learnt { FLAG_LEARNT } else { 0 } | (lbd.min(1 << 20) << 2));
        self.db.arena.push(match self.settings.deletion {
            Deletion::Sorted => 0f32.to_bits(),
            // As clasp: a new clause counts one use per restart so far, so that new clauses
            // outrank old ones whose counts were halved.
            Deletion::Basic => (1 + self.stats.num_restarts).min(MAX_USES as u64) as u32,
        });
        self.db.arena.extend(lits.iter().map(|l| l.code() as u32));
        self.db.watches[(lits[0]).code()].push(Watch {
            cref,
            other: lits[1],
        });
        self.db.watches[(lits[1]).code()].push(Watch {
            cref,
            other: lits[0],
        });
        if learnt {
            self.db.learnts.push(cref);
        }
        cref
    }

    /// Watches the binary clause `a ∨ b` inline (no arena entry): each literal's list holds
    /// the other.
    pub(super) fn watch_binary(&mut self, a: Lit, b: Lit) {
        self.db.watches[a.code()].push(Watch {
            cref: u32::MAX,
            other: b,
        });
        self.db.watches[b.code()].push(Watch {
            cref: u32::MAX,
            other: a,
        });
    }

    pub(super) fn attach(&mut self, lits: &[Lit], learnt: bool, lbd: u32) -> Reason {
        if lits.len() == 2 {
            self.watch_binary(lits[0], lits[1]);
            Reason::Binary(lits[1])
        } else {
            Reason::Long(self.alloc_clause(lits, learnt, lbd))
        }
    }

    /// Adds a clause at decision level 0 (backtracking there first). Returns false when the
    /// engine became inconsistent.
    ///
    /// A clause with a true literal (at level 0) is dropped before anything is copied: most
    /// clauses of a program whose atoms are mostly facts are, and translating such a program
    /// is mostly this test. The others are simplified in `clause_buf` (false literals dropped,
    /// sorted, repeats dropped, tautologies dropped), so adding a clause allocates nothing but
    /// its place in the arena.
    #[inline]
    pub fn add_clause(&mut self, lits: &[Lit]) -> bool {
        if self.asg.trail_lim.is_empty()
            && !self.inconsistent
            && lits.iter().any(|&l| self.val(l) == 1)
        {
            return true;
        }
        self.add_clause_at_level0(lits)
    }

    /// [`Engine::add_clause`] past its test for a true literal at level 0.
    fn add_clause_at_level0(&mut self, lits: &[Lit]) -> bool {
        self.backtrack(0);
        if self.inconsistent {
            return false;
        }
        if lits.iter().any(|&l| self.val(l) == 1) {
            return true;
        }
        let mut c = std::mem::take(&mut self.db.clause_buf);
        c.clear();
        c.extend(lits.iter().copied().filter(|&l| self.val(l) == 0));
        c.sort_unstable();
        c.dedup();
        // With no literal true, both literals of a complementary pair are unassigned.
        let tautology = c.windows(2).any(|w| w[0] == !w[1]);
        let ok = if tautology {
            true
        } else {
            self.stats.num_clauses += 1;
            match c.len() {
                0 => {
                    self.inconsistent = true;
                    false
                }
                1 => {
                    self.assign(c[0], Reason::Decision);
                    if self.propagate().is_some() {
                        self.inconsistent = true;
                        false
                    } else {
                        true
                    }
                }
                _ => {
                    self.attach(&c, false, 0);
                    true
                }
            }
        };
        c.clear();
        self.db.clause_buf = c;
        ok
    }

    /// Adds a clause that the current (total) assignment falsifies, such as the clause blocking
    /// an enumerated model's decisions, without leaving the search: backtracks only to the
    /// second-highest level of its literals, where the clause is unit and implies its
    /// highest-level literal's complement, so that `search_from(.., true)` goes on from there
    /// (clasp's enumeration likewise backtracks instead of starting over; starting each model
    /// from level 0 made 10-queens' 724 models cost 3x clasp's choices). Falls back to
    /// [`Engine::add_clause`] (level 0) when the clause is not of that shape. Returns false when
    /// the problem became inconsistent.
    pub fn add_clause_resuming(&mut self, lits: &[Lit]) -> bool {
        let mut c: Vec<Lit> = lits.to_vec();
        c.sort();
        c.dedup();
        let all_false = c.iter().all(|&l| self.val(l) == -1);
        let distinct = c.windows(2).all(|w| w[0] != !w[1]);
        if !all_false || !distinct || c.len() < 2 || self.decision_level() == 0 {
            return self.add_clause(lits);
        }
        c.sort_by_key(|&l| std::cmp::Reverse(self.asg.level[l.var().index()]));
        let top = self.asg.level[c[0].var().index()];
        let second = self.asg.level[c[1].var().index()];
        if top == second || second == 0 {
            return self.add_clause(lits);
        }
        self.backtrack(second);
        self.stats.num_clauses += 1;
        // Now c[0] is unassigned and the rest false: the clause is asserting, never conflicting.
        let conflicting = self.add_clause_in_search(&mut c, false);
        debug_assert!(!conflicting);
        true
    }

    /// Adds a clause while a search is in progress (loop nogoods): watches are chosen so that
    /// the clause is propagating or conflicting as appropriate. Returns true when the clause is
    /// conflicting under the current assignment (the conflict is then in `self.an.conflict`).
    pub(super) fn add_clause_in_search(&mut self, lits: &mut [Lit], learnt: bool) -> bool {
        // Order: true literals first, then unassigned, then false by decreasing level.
        lits.sort_by_key(|&l| {
            let v = self.val(l);
            match v {
                1 => 0u64,
                0 => 1,
                _ => 2 + (u32::MAX - self.asg.level[l.var().index()]) as u64,
            }
        });
        if lits.is_empty() {
            self.an.conflict.clear();
            return true;
        }
        if lits.len() == 1 {
            // A unit clause: it holds at level 0; assign it there through a restart.
            let l = lits[0];
            if self.level_of(l) == 0 && self.val(l) == 1 {
                return false;
            }
            if self.val(l) == -1 && self.level_of(l) == 0 {
                self.an.conflict.clear();
                self.an.conflict.push(l);
                return true;
            }
            self.backtrack(0);
            self.assign(l, Reason::Decision);
            return false;
        }
        if self.val(lits[0]) == 0 && self.val(lits[1]) == -1 {
            // Asserting: imply lits[0] at the level where the clause became unit, so the
            // implication survives backtracking above that level (the watches stay valid).
            let level = self.asg.level[lits[1].var().index()];
            if level < self.decision_level() {
                self.backtrack(level);
            }
        }
        let reason = self.attach(lits, learnt, lits.len() as u32);
        let (v0, v1) = (self.val(lits[0]), self.val(lits[1]));
        if v0 == -1 {
            self.an.conflict.clear();
            self.an.conflict.extend_from_slice(lits);
            return true;
        }
        if v0 == 0 && v1 == -1 {
            let r = match reason {
                Reason::Binary(_) => Reason::Binary(lits[1]),
                other => other,
            };
            self.assign(lits[0], r);
        }
        false
    }

    /// Adds a native weight constraint `head <-> sum(w * l) >= bound` at level 0. Weights may be
    /// negative; they are normalised by negating their literals.
    pub fn add_weight(&mut self, head: Lit, lits: &[(Lit, i64)], bound: i64) -> bool {
        self.add_weight_constraint(head, lits, bound, false)
    }

    /// Adds the native weight constraint `head -> sum(w * l) >= bound` (one direction only) at
    /// level 0, whose bound `raise_weight_bound` may raise later.
    pub fn add_weight_implication(&mut self, head: Lit, lits: &[(Lit, i64)], bound: i64) -> bool {
        self.add_weight_constraint(head, lits, bound, true)
    }

    fn add_weight_constraint(
        &mut self,
        head: Lit,
        lits: &[(Lit, i64)],
        bound: i64,
        implication: bool,
    ) -> bool {
        self.backtrack(0);
        let given = bound as i128;
        let mut bound = bound as i128;
        let mut norm: Vec<(Lit, u64)> = Vec::new();
        for &(l, w) in lits {
            if w > 0 {
                norm.push((l, w as u64));
            } else if w < 0 {
                // w * l = w - w * (not l), so move -w to the other side.
                bound -= w as i128;
                norm.push((!l, (-(w as i128)) as u64));
            }
        }
        let shift = bound - given;
        if bound <= 0 && !implication {
            return self.add_clause(&[head]);
        }
        let total: i128 = norm.iter().map(|&(_, w)| w as i128).sum();
        if total < bound {
            return self.add_clause(&[!head]);
        }
        let bound = bound.max(0) as u64;
        norm.sort_by_key(|x| std::cmp::Reverse(x.1));
        if self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        let id = match self.wc.free_weights.last() {
            Some(&id) => id,
            None => self.wc.weights.len() as u32,
        };
        let (mut sum_true, mut sum_false) = (0u64, 0u64);
        for &(l, w) in &norm {
            let slot = self.weight_slot_of(l.var());
            self.wc.weight_watch[slot].push(WeightWatch {
                id,
                lit: l,
                weight: w,
            });
            match self.val(l) {
                1 => sum_true += w,
                -1 => sum_false += w,
                _ => {}
            }
        }
        let slot = self.weight_slot_of(head.var());
        self.wc.weight_watch[slot].push(WeightWatch {
            id,
            lit: head,
            weight: 0,
        });
        let total = norm.iter().map(|&(_, w)| w).sum();
        let max_weight = norm.iter().map(|&(_, w)| w).max().unwrap_or(0);
        let c = WeightConstraint {
            sum_true,
            sum_false,
            total,
            max_weight,
            head,
            implication,
            shift,
            lits: norm,
            bound,
            removed: false,
            scan_from: 0,
            scan_epoch: 0,
        };
        if id as usize == self.wc.weights.len() {
            self.wc.weights.push(c);
        } else {
            self.wc.free_weights.pop();
            self.wc.weights[id as usize] = c;
        }
        self.stats.num_clauses += 1;
        if self.propagate_weight(id as usize) || self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        true
    }

    /// The index in `weight_watch` of `v`'s occurrence list, made on first use.
    pub(super) fn weight_slot_of(&mut self, v: Var) -> usize {
        if self.wc.weight_slot[v.index()] == NO_SLOT {
            self.wc.weight_slot[v.index()] = self.wc.weight_watch.len() as u32;
            self.wc.weight_watch.push(Vec::new());
        }
        self.wc.weight_slot[v.index()] as usize
    }

    /// Detaches the weight constraint whose literal is `head` (if `add_weight` made one), at
    /// level 0. Its head variable becomes unconstrained by it; clauses learnt with its help
    /// stay valid for every assignment of the other variables (the constraint only defined
    /// `head`), so callers may retire auxiliary bounds this way once nothing reads `head`.
    pub fn remove_weight(&mut self, head: Lit) {
        self.backtrack(0);
        let Some(id) = self.weight_id(head) else {
            return;
        };
        self.wc.free_weights.push(id as u32);
        let c = &mut self.wc.weights[id];
        c.removed = true;
        let lits = std::mem::take(&mut c.lits);
        let idu = id as u32;
        for v in lits.iter().map(|&(l, _)| l.var()).chain([head.var()]) {
            // The slot stays (possibly with an empty list): propagation then finds nothing.
            let slot = self.wc.weight_slot[v.index()];
            if slot != NO_SLOT {
                self.wc.weight_watch[slot as usize].retain(|w| w.id != idu);
            }
        }
    }

    /// The live weight constraint whose head is `head`, found through the head's occurrence
    /// (weight 0, which no body literal has).
    fn weight_id(&self, head: Lit) -> Option<usize> {
        let slot = self.wc.weight_slot[head.var().index()];
        if slot == NO_SLOT {
            return None;
        }
        self.wc.weight_watch[slot as usize]
            .iter()
            .find(|w| w.weight == 0 && w.lit == head && !self.wc.weights[w.id as usize].removed)
            .map(|w| w.id as usize)
    }

    /// Raises the bound of the implication `head -> sum(w * l) >= bound` that
    /// `add_weight_implication` made to `bound` (a lower bound leaves it as it is), at level
    /// 0. Every clause learnt with the old bound's help still follows from the new one, so
    /// nothing learnt is dropped. Returns false when the engine became inconsistent; false
    /// too, with nothing changed, when `head` has no such constraint (`add_weight_implication`
    /// then only fixed `head` false, or it was removed).
    pub fn raise_weight_bound(&mut self, head: Lit, bound: i64) -> bool {
        self.backtrack(0);
        let id = match self.lift_bound(head, bound) {
            Ok(id) => id,
            Err(unchanged) => return unchanged,
        };
        if self.propagate_weight(id) || self.propagate().is_some() {
            self.inconsistent = true;
            return false;
        }
        true
    }

    /// Sets the bound of `head`'s implication constraint (see `raise_weight_bound`) to `bound`
    /// when that is higher: `Ok` with the constraint's index when raised, `Err(true)` when the
    /// bound already was as high, `Err(false)` when `head` has no implication constraint.
    fn lift_bound(&mut self, head: Lit, bound: i64) -> Result<usize, bool> {
        let id = self.weight_id(head).ok_or(false)?;
        let c = &mut self.wc.weights[id];
        if !c.implication {
            return Err(false);
        }
        let new = bound as i128 + c.shift;
        if new <= c.bound as i128 {
            return Err(true);
        }
        // Above the total the constraint only says `!head`; the bound stays representable.
        c.bound = new.min(c.total as i128 + 1) as u64;
        Ok(id)
    }

    /// [`Engine::raise_weight_bound`] on the total assignment of a model, without leaving the
    /// search: backtracks only to the level below the lowest one at which the new bound is
    /// violated and evaluates the constraint there, so that `search_from(.., true)` goes on
    /// from that assignment (what the constraint implies lower down, it implies at that level:
    /// sound, and conflict analysis copes with it). Returns false as `raise_weight_bound` does.
    pub fn raise_weight_bound_resuming(&mut self, head: Lit, bound: i64) -> bool {
        if self.decision_level() == 0 {
            return self.raise_weight_bound(head, bound);
        }
        let id = match self.lift_bound(head, bound) {
            Ok(id) => id,
            Err(unchanged) => return unchanged,
        };
        // The false literals by level: the bound is violated from the level where the sum of
        // their weights exceeds `total - bound`.
        let c = &self.wc.weights[id];
        let room = c.total - c.bound.min(c.total);
        let mut false_at: Vec<(u32, u64)> = c
            .lits
            .iter()
            .filter(|&&(l, _)| self.val(l) == -1)
            .map(|&(l, w)| (self.asg.level[l.var().index()], w))
            .collect();
        false_at.sort_unstable();
        let mut sum = 0u64;
        let mut violated = None;
        for &(level, w) in &false_at {
            sum += w;
            if sum > room {
                violated = Some(level);
                break;
            }
        }
        let Some(level) = violated else {
            // Not violated by this assignment (not a model's, then): start over at level 0.
            self.backtrack(0);
            if self.propagate_weight(id) || self.propagate().is_some() {
                self.inconsistent = true;
                return false;
            }
            return true;
        };
        let target = level.saturating_sub(1);
        self.backtrack(target);
        if target == 0 {
            if self.propagate_weight(id) || self.propagate().is_some() {
                self.inconsistent = true;
                return false;
            }
            return true;
        }
        // Not violated at `target`: the evaluation implies literals at most.
        let conflict = self.propagate_weight(id);
        debug_assert!(!conflict);
        true
    }
}
