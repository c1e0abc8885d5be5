//! The engine's variables: made (`new_var`, `new_body_var`), or recycled from the free list
//! that level-0 simplification fills, reserved in bulk (`reserve_vars`), kept from decisions
//! (`set_decidable`) and retired (`retire_vars`).
//!
//! Invariant: a variable `alloc_var` hands out is unassigned, in no watch list, and has every
//! per-variable vector's entry at its initial value (as a brand-new variable's), so a recycled
//! variable cannot be told from a new one.

use super::*;

impl Engine {
    /// Reserves room for `additional` more variables in every per-variable (and per-literal)
    /// vector, so that translating a large program grows each vector once: grown by doubling,
    /// the abandoned smaller copies stay in the allocator's heap and count in the peak memory.
    pub fn reserve_vars(&mut self, additional: usize) {
        self.asg.values.reserve(2 * additional);
        self.asg.level.reserve(additional);
        self.asg.reason.reserve(additional);
        self.asg.stored_slot.reserve(additional);
        self.heur.phase.reserve(additional);
        self.heur.activity.reserve(additional);
        self.heur.heap_pos.reserve(additional);
        self.heur.decidable.reserve(additional);
        self.an.seen.reserve(additional);
        self.wc.weight_slot.reserve(additional);
        self.uf.uf_relevant.reserve(additional);
        self.db.watches.reserve(2 * additional);
        self.heur.heap.reserve(additional);
    }

    /// Creates a new variable, decidable by default; a variable freed by `retire_vars` is
    /// reused when there is one. It gets the next shared id (`share`); variables made for one
    /// call only come from [`Engine::new_private_var`].
    pub fn new_var(&mut self) -> Var {
        let v = self.alloc_var();
        self.share_numbering(v, true);
        v
    }

    /// A new or recycled variable, without a shared id yet.
    pub(super) fn alloc_var(&mut self) -> Var {
        if let Some(v) = self.pool.free_vars.pop() {
            let i = v.index();
            debug_assert!(self.asg.values[v.positive().code()] == 0);
            debug_assert!(self.db.watches[v.positive().code()].is_empty());
            debug_assert!(self.db.watches[v.negative().code()].is_empty());
            self.pool.retired[i] = false;
            self.asg.level[i] = 0;
            self.asg.reason[i] = Reason::Decision;
            self.heur.phase[i] = self.settings.default_phase;
            self.heur.phase_saved[i] = false;
            self.heur.occ[i] = 0;
            self.an.seen[i] = 0;
            self.uf.uf_relevant[i] = false;
            self.heur.activity[i] = 0.0;
            self.heur.decidable[i] = true;
            if self.heur.heap_pos[i] == NO_SLOT {
                self.heap_insert(v);
            } else {
                self.heap_down(self.heur.heap_pos[i] as usize);
            }
            return v;
        }
        let v = Var::new(self.asg.level.len());
        self.pool.retired.push(false);
        self.asg.values.push(0);
        self.asg.values.push(0);
        self.asg.level.push(0);
        self.asg.reason.push(Reason::Decision);
        self.asg.stored_slot.push(NO_SLOT);
        self.heur.phase.push(self.settings.default_phase);
        self.heur.phase_saved.push(false);
        self.heur.occ.push(0);
        self.heur.activity.push(0.0);
        self.heur.heap_pos.push(NO_SLOT);
        self.heur.decidable.push(true);
        self.an.seen.push(0);
        self.wc.weight_slot.push(NO_SLOT);
        self.uf.uf_relevant.push(false);
        self.db.watches.push(Vec::new());
        self.db.watches.push(Vec::new());
        self.heap_insert(v);
        v
    }

    /// Creates a new variable standing for a rule body (or another conjunction); its initial
    /// phase is `body_phase`.
    pub fn new_body_var(&mut self) -> Var {
        let v = self.new_var();
        self.heur.phase[v.index()] = self.settings.body_phase;
        v
    }

    /// Excludes a variable from decisions (its value is always implied).
    pub fn set_decidable(&mut self, v: Var, decidable: bool) {
        self.heur.decidable[v.index()] = decidable;
        if decidable {
            self.heap_insert(v);
        }
    }

    /// Retires variables that nothing will mention again (the guard of a finished call and
    /// the auxiliary variables of its constraints, whose weight constraints the caller removed).
    /// They stop being decided at once; the next level-0 simplification deletes every clause
    /// that mentions one, learnt clauses included, drops their level-0 assignments, and makes
    /// them free for `new_var`. Sound because each such variable either only occurs negated
    /// in clauses that hold for one call (a guard, false from now on), or was defined by a
    /// constraint the caller removed (a definition extends the program conservatively, so what
    /// was learnt without mentioning the variable stays a consequence of the rest).
    pub fn retire_vars(&mut self, vars: &[Var]) {
        for &v in vars {
            if !self.pool.retired[v.index()] {
                self.pool.retired[v.index()] = true;
                self.heur.decidable[v.index()] = false;
                self.unshare(v);
                self.pool.dead_vars.push(v);
            }
        }
    }
}
