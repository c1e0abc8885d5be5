//! Shared loop formulas: one learnt constraint per unfounded set `U` instead of one loop nogood
//! `{a} ∪ EB(U)` per atom `a` of `U` (the idea of clasp's `--loops=shared`; the watching scheme
//! below is our own). On labyrinth an unfounded set has some 20 atoms and some 500 external
//! bodies, so the clauses repeated the external part 20 times.
//!
//! A formula stores the external literals `B` (the external bodies, all false when it is
//! learnt) and then the atoms `A`. It stands for the clauses `¬a ∨ B1 ∨ ... ∨ Bk` for every
//! `a` in `A`, that is the disjunction `B1 ∨ ... ∨ Bk ∨ X` with `X = ¬a1 ∧ ... ∧ ¬an`, and is
//! watched as such:
//! - two external literals, at positions 0 and 1, are watched like a clause's (in the watch
//!   list of the literal, visited when it becomes false), with a blocker;
//! - every atom is watched in the list of `¬a` (visited when `a` becomes true: `X` is false);
//!   these watches never move.
//!
//! Propagation: when no external literal but the other watched one is left non-false, either
//! that one is false too (every atom gets false, reason: `B`; a true atom is a conflict) or it
//! is unassigned and some atom is true (it gets true, reason: `B` minus itself plus `¬a` for
//! the true atom `a`, remembered in `act`). When an atom becomes true and a watched external
//! literal is false, the external literals are counted: one non-false left is implied, none is
//! a conflict.
//!
//! Invariants:
//! - External literals and atoms share no variable (otherwise the set is learnt as clauses).
//! - A false watched external literal whose event was processed has every unwatched external
//!   literal false, assigned no later, or some external literal true at a level no higher
//!   (the two-watched-literal invariant, blockers included). An atom's event never relies on
//!   it: it counts the external literals itself.
//! - `act` is only written when an external literal is implied, which needs every other one
//!   false; so while that literal is true its reason's atom stays the one recorded.
//! - Formulas are learnt constraints: counted with the learnt clauses (as the clauses they
//!   stand for), reduced with them by LBD and activity, never deleted while they are the reason
//!   of an assignment. Ids are slots, stable until deletion; deleted slots are reused only
//!   after their watches were dropped (`reduce_db` drops them in the same call).
//! - Level-0 simplification drops every non-binary watch; `simplify_loops` then shrinks each
//!   formula (false external literals and false atoms removed, satisfied formulas deleted,
//!   one external literal left: binary clauses) and watches it again.

use super::{Engine, Reason, Watch};
use crate::solve::lit::Lit;

/// Marks a watch-list entry whose `cref` is a loop formula id (`u32::MAX` stays a binary
/// clause; clause arena offsets stay below this bit).
pub(super) const LOOP_TAG: u32 = 1 << 31;

/// Whether a watch entry belongs to a loop formula.
#[inline(always)]
pub(super) fn is_loop_watch(cref: u32) -> bool {
    cref != u32::MAX && cref & LOOP_TAG != 0
}

/// One shared loop formula.
#[derive(Clone, Debug, Default)]
struct LoopFormula {
    /// The external literals (`nb` of them, watched at 0 and 1), then the atoms.
    lits: Box<[Lit]>,
    /// Number of external literals.
    nb: u32,
    /// Index among the atoms of the true atom behind the last implied external literal.
    act: u32,
    /// Literal block distance, as for learnt clauses (the clauses' length when learnt).
    lbd: u32,
    /// Activity, bumped like a learnt clause's when it is a reason in conflict analysis.
    activity: f32,
    /// False once deleted (the slot is free).
    live: bool,
}

impl LoopFormula {
    fn ext(&self) -> &[Lit] {
        &self.lits[..self.nb as usize]
    }

    fn atoms(&self) -> &[Lit] {
        &self.lits[self.nb as usize..]
    }
}

/// The store of loop formulas.
#[derive(Clone, Debug, Default)]
pub(super) struct Loops {
    items: Vec<LoopFormula>,
    /// Free slots.
    free: Vec<u32>,
    /// Clauses the live formulas stand for (the sum of their atom counts).
    pub(super) clauses: usize,
    /// Live formulas.
    pub(super) live: usize,
}

impl Loops {
    /// Whether formula `id` is live (its watches are valid).
    pub(super) fn is_live(&self, id: u32) -> bool {
        self.items[id as usize].live
    }

    fn insert(&mut self, f: LoopFormula) -> u32 {
        self.clauses += f.lits.len() - f.nb as usize;
        self.live += 1;
        match self.free.pop() {
            Some(id) => {
                self.items[id as usize] = f;
                id
            }
            None => {
                self.items.push(f);
                assert!(
                    self.items.len() < LOOP_TAG as usize,
                    "loop formula ids fit 31 bits"
                );
                (self.items.len() - 1) as u32
            }
        }
    }

    fn remove(&mut self, id: u32) {
        let f = &mut self.items[id as usize];
        debug_assert!(f.live);
        self.clauses -= f.lits.len() - f.nb as usize;
        self.live -= 1;
        *f = LoopFormula::default();
        self.free.push(id);
    }
}

/// What a loop watch asks of the watch list being visited.
enum Event {
    Keep(Lit),
    Drop,
    Conflict,
}

impl Engine {
    /// Learns the loop nogoods of an unfounded set `atoms` with external literals `ext`
    /// during search: as one shared formula when that is smaller and safe, else one clause per
    /// atom. Returns true on conflict (in `self.an.conflict`).
    pub(super) fn add_loop_set(&mut self, atoms: &[Lit], ext: &[Lit]) -> bool {
        let n = atoms.len();
        self.stats.loop_nogoods += n as u64;
        let overlap = || atoms.iter().any(|a| ext.iter().any(|l| l.var() == a.var()));
        if !self.settings.shared_loops || n < 2 || ext.len() < 2 || overlap() {
            for &a in atoms {
                let not_a = !a;
                let mut c = Vec::with_capacity(ext.len() + 1);
                c.push(not_a);
                // With merged atoms an external support can be `not a` itself (a support
                // literal shared with `a`'s negation); a clause never repeats a literal.
                c.extend(ext.iter().copied().filter(|&l| l != not_a));
                for &l in &c {
                    self.heur.occ[l.var().index()] += if l.is_neg() { -1 } else { 1 };
                    if self.settings.score_other {
                        self.bump_var(l.var());
                    }
                }
                if self.add_clause_in_search(&mut c, true) {
                    return true;
                }
            }
            return false;
        }
        // The sign score and `--score-other` count the formula as the clauses it stands for.
        for &a in atoms {
            self.heur.occ[a.var().index()] -= 1;
        }
        for &l in ext {
            self.heur.occ[l.var().index()] += if l.is_neg() { -(n as i32) } else { n as i32 };
        }
        if self.settings.score_other {
            for _ in 0..n {
                for &a in atoms {
                    self.bump_var(a.var());
                }
                for &l in ext {
                    self.bump_var(l.var());
                }
            }
        }
        // External literals: true first, then unassigned, then false by decreasing level (the
        // order of `add_clause_in_search`), so that positions 0 and 1 are the ones to watch.
        let mut b = ext.to_vec();
        b.sort_by_key(|&l| match self.val(l) {
            1 => 0u64,
            0 => 1,
            _ => 2 + (u32::MAX - self.asg.level[l.var().index()]) as u64,
        });
        let (v0, v1) = (self.val(b[0]), self.val(b[1]));
        let mut conflict_atom = None;
        if v0 == -1 {
            // Every external literal is false: the formula is unit on the atoms at the level
            // of the latest one. A true atom assigned no later is a conflict; atoms made true
            // later are undone by the backjump.
            let level = self.asg.level[b[0].var().index()];
            conflict_atom = atoms
                .iter()
                .copied()
                .filter(|&a| self.val(a) == 1 && self.asg.level[a.var().index()] <= level)
                .min_by_key(|&a| self.asg.level[a.var().index()]);
            if conflict_atom.is_none() && level < self.decision_level() {
                self.backtrack(level);
            }
        }
        let mut lits = b.clone();
        lits.extend_from_slice(atoms);
        let id = self.db.loops.insert(LoopFormula {
            lits: lits.into_boxed_slice(),
            nb: b.len() as u32,
            act: 0,
            lbd: b.len() as u32 + 1,
            activity: 0.0,
            live: true,
        });
        self.watch_loop(id);
        if let Some(a) = conflict_atom {
            self.an.conflict.clear();
            self.an.conflict.push(!a);
            self.an.conflict.extend_from_slice(&b);
            return true;
        }
        if v0 == -1 {
            for &a in atoms {
                if self.val(a) == 0 {
                    self.assign(!a, Reason::Loop(id));
                }
            }
        } else if v0 == 0 && v1 == -1 {
            if let Some(k) = atoms.iter().position(|&a| self.val(a) == 1) {
                self.db.loops.items[id as usize].act = k as u32;
                self.assign(b[0], Reason::Loop(id));
            }
        }
        false
    }

    /// Adds the watches of formula `id`: its external literals at 0 and 1, and every atom
    /// but those true at level 0 (they stay true; an atom true above level 0 may be undone and
    /// made true again).
    fn watch_loop(&mut self, id: u32) {
        let cref = LOOP_TAG | id;
        let f = &self.db.loops.items[id as usize];
        let (b0, b1) = (f.lits[0], f.lits[1]);
        self.db.watches[b0.code()].push(Watch { cref, other: b1 });
        self.db.watches[b1.code()].push(Watch { cref, other: b0 });
        for k in f.nb as usize..f.lits.len() {
            let a = f.lits[k];
            if self.asg.values[a.code()] != 1 || self.asg.level[a.var().index()] > 0 {
                self.db.watches[(!a).code()].push(Watch { cref, other: b0 });
            }
        }
    }

    /// Visits the loop-formula watches in the list of `f`, which just became false (called by
    /// `propagate_clauses` when the list has some). Returns true on conflict.
    pub(super) fn propagate_loops(&mut self, f: Lit) -> bool {
        let mut ws = std::mem::take(&mut self.db.watches[f.code()]);
        let n = ws.len();
        let (mut i, mut j) = (0, 0);
        let mut conflict = false;
        while i < n {
            let w = ws[i];
            i += 1;
            if !is_loop_watch(w.cref) || self.val(w.other) == 1 {
                ws[j] = w;
                j += 1;
                continue;
            }
            match self.loop_event(w.cref & !LOOP_TAG, f) {
                Event::Keep(other) => {
                    ws[j] = Watch {
                        cref: w.cref,
                        other,
                    };
                    j += 1;
                }
                Event::Drop => {}
                Event::Conflict => {
                    ws[j] = w;
                    j += 1;
                    conflict = true;
                    break;
                }
            }
        }
        super::keep_unvisited(&mut ws, i, j);
        // New watches went to non-false literals only.
        debug_assert!(self.db.watches[f.code()].is_empty());
        self.db.watches[f.code()] = ws;
        conflict
    }

    /// Handles formula `id` after `f` became false: `f` is a watched external literal or the
    /// negation of one of its atoms.
    fn loop_event(&mut self, id: u32, f: Lit) -> Event {
        let idu = id as usize;
        let mut lits = std::mem::take(&mut self.db.loops.items[idu].lits);
        let nb = self.db.loops.items[idu].nb as usize;
        let event = if lits[0] == f || lits[1] == f {
            self.loop_ext_false(id, &mut lits, nb, f)
        } else {
            self.loop_atom_true(id, &lits, nb, !f)
        };
        self.db.loops.items[idu].lits = lits;
        event
    }

    /// A watched external literal `f` became false.
    fn loop_ext_false(&mut self, id: u32, lits: &mut [Lit], nb: usize, f: Lit) -> Event {
        if lits[0] == f {
            lits.swap(0, 1);
        }
        let other = lits[0];
        if self.val(other) == 1 {
            return Event::Keep(other);
        }
        for k in 2..nb {
            if self.val(lits[k]) != -1 {
                lits.swap(1, k);
                self.db.watches[lits[1].code()].push(Watch {
                    cref: LOOP_TAG | id,
                    other,
                });
                return Event::Drop;
            }
        }
        if self.val(other) == 0 {
            if let Some(k) = lits[nb..].iter().position(|&a| self.val(a) == 1) {
                self.db.loops.items[id as usize].act = k as u32;
                self.assign(other, Reason::Loop(id));
            }
            return Event::Keep(other);
        }
        // Every external literal is false: so is every atom.
        for k in nb..lits.len() {
            let a = lits[k];
            match self.val(a) {
                1 => {
                    self.an.conflict.clear();
                    self.an.conflict.push(!a);
                    self.an.conflict.extend_from_slice(&lits[..nb]);
                    return Event::Conflict;
                }
                0 => self.assign(!a, Reason::Loop(id)),
                _ => {}
            }
        }
        Event::Keep(other)
    }

    /// Atom `a` became true: unless two external literals are still open (or one is true),
    /// the last open one is implied, or there is a conflict.
    fn loop_atom_true(&mut self, id: u32, lits: &[Lit], nb: usize, a: Lit) -> Event {
        let (v0, v1) = (self.val(lits[0]), self.val(lits[1]));
        if v0 == 1 {
            return Event::Keep(lits[0]);
        }
        if v1 == 1 {
            return Event::Keep(lits[1]);
        }
        if v0 == 0 && v1 == 0 {
            return Event::Keep(lits[0]);
        }
        let mut open = None;
        for &l in &lits[..nb] {
            match self.val(l) {
                1 => return Event::Keep(l),
                0 if open.is_some() => return Event::Keep(l),
                0 => open = Some(l),
                _ => {}
            }
        }
        match open {
            Some(l) => {
                let k = lits[nb..]
                    .iter()
                    .position(|&x| x == a)
                    .expect("the watched atom is in its formula");
                self.db.loops.items[id as usize].act = k as u32;
                self.assign(l, Reason::Loop(id));
                Event::Keep(l)
            }
            None => {
                self.an.conflict.clear();
                self.an.conflict.push(!a);
                self.an.conflict.extend_from_slice(&lits[..nb]);
                Event::Conflict
            }
        }
    }

    /// Appends the false literals of the reason of `v`, implied by formula `id`.
    pub(super) fn loop_reason_lits(&self, id: u32, v: crate::solve::lit::Var, out: &mut Vec<Lit>) {
        let f = &self.db.loops.items[id as usize];
        let ext = f.ext();
        if ext.iter().any(|l| l.var() == v) {
            out.extend(ext.iter().copied().filter(|l| l.var() != v));
            out.push(!f.atoms()[f.act as usize]);
        } else {
            out.extend_from_slice(ext);
        }
    }

    /// Bumps the activity of formula `id` (met as a reason in conflict analysis).
    pub(super) fn bump_loop(&mut self, id: u32) {
        let f = &mut self.db.loops.items[id as usize];
        f.activity += self.db.cla_inc as f32;
        if f.activity > 1e20 {
            self.rescale_clause_activities();
        }
    }

    /// Scales the loop formulas' activities like the clauses' (by 1e-20).
    pub(super) fn rescale_loop_activities(&mut self) {
        for f in self.db.loops.items.iter_mut() {
            f.activity *= 1e-20;
        }
    }

    /// Whether formula `id` is the reason of a current assignment.
    fn loop_locked(&self, id: u32) -> bool {
        let f = &self.db.loops.items[id as usize];
        let r = Reason::Loop(id);
        f.ext()
            .iter()
            .any(|&l| self.val(l) == 1 && self.asg.reason[l.var().index()] == r)
            || f.atoms()
                .iter()
                .any(|&a| self.val(a) == -1 && self.asg.reason[a.var().index()] == r)
    }

    /// Deletes about half of the loop formulas, the worst first (high LBD, then low
    /// activity), keeping those of LBD 2 or less and the locked ones, as `reduce_db` does
    /// with learnt clauses. Their watches are dropped by the caller's pass over the lists.
    pub(super) fn reduce_loops(&mut self) {
        let mut cands: Vec<(u32, f32, u32)> = self
            .db
            .loops
            .items
            .iter()
            .enumerate()
            .filter(|(_, f)| f.live)
            .map(|(id, f)| (f.lbd, f.activity, id as u32))
            .collect();
        super::database::sort_worst_first(&mut cands);
        let target = cands.len() / 2;
        let mut removed = 0;
        for (lbd, _, id) in cands {
            if removed >= target {
                break;
            }
            if lbd > 2 && !self.loop_locked(id) {
                self.db.loops.remove(id);
                removed += 1;
            }
        }
    }

    /// Level-0 simplification of the loop formulas, after `simplify` dropped every non-binary
    /// watch: removes false external literals and false atoms, deletes satisfied or empty
    /// formulas, turns one-literal external parts into binary clauses, and watches the rest
    /// again.
    pub(super) fn simplify_loops(&mut self) {
        for id in 0..self.db.loops.items.len() as u32 {
            if !self.db.loops.items[id as usize].live {
                continue;
            }
            let f = std::mem::take(&mut self.db.loops.items[id as usize]);
            let ext: Vec<Lit> = f
                .ext()
                .iter()
                .copied()
                .filter(|&l| self.val(l) != -1)
                .collect();
            let atoms: Vec<Lit> = f
                .atoms()
                .iter()
                .copied()
                .filter(|&a| self.val(a) != -1)
                .collect();
            // A formula mentioning a retired variable goes, as a clause would (`retire_vars`).
            let satisfied = ext.iter().any(|&l| self.val(l) == 1)
                || f.lits.iter().any(|&l| self.pool.retired[l.var().index()]);
            // Put the formula back so that `remove` accounts for it.
            self.db.loops.items[id as usize] = f;
            if satisfied || atoms.is_empty() {
                self.db.loops.remove(id);
                continue;
            }
            debug_assert!(ext.len() >= 2 || atoms.iter().all(|&a| self.val(a) == 0));
            if ext.len() < 2 {
                self.db.loops.remove(id);
                if let Some(&b) = ext.first() {
                    for &a in &atoms {
                        self.watch_binary(!a, b);
                    }
                }
                continue;
            }
            let nb = ext.len() as u32;
            let mut lits = ext;
            lits.extend_from_slice(&atoms);
            let f = &mut self.db.loops.items[id as usize];
            self.db.loops.clauses -= f.lits.len() - f.nb as usize;
            self.db.loops.clauses += lits.len() - nb as usize;
            f.lits = lits.into_boxed_slice();
            f.nb = nb;
            f.act = 0;
            self.watch_loop(id);
        }
    }
}
