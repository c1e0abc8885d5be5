//! External propagators inside the engine (clingo's propagator interface, `solve::propagator`):
//! the watched literals, the hook's calls at every propagation fixpoint, on backtracking and on
//! total assignments, and the clauses it adds.
//!
//! Scheduling: `propagate` runs clause propagation, then the unfounded-set check, then this
//! step: clauses the hook left waiting are added (`add_clause_in_search`, which backjumps as
//! for a loop nogood), then the trail past `head` is scanned for watched literals, which the
//! hook gets in one `propagate` call; whatever it assigned or added sends propagation round
//! again. With fixpoint checks on, a quiet step ends with the hook's `check_fixpoint`.
//! `search` calls `check_external` where it would answer `Sat`.
//!
//! Invariants:
//! - `notified` holds, in trail order, the watched literals the hook was given that are still
//!   assigned; `backtrack` hands the ones it unassigns to `undo` before clearing them, so the
//!   hook's state follows the trail. `head <= trail.len()` after every backtrack.
//! - While `busy` (a hook call or a `PropagateInit` is running) the hook is never called again:
//!   the propagation step is skipped (its changes are reported later) and nothing backtracks.
//! - A stashed conflict (`stashed`) is in `Analysis::conflict`; the next `propagate` reports
//!   it; a backtrack drops it (the assignment it refuted is gone).

use super::*;
use crate::solve::propagator::{Assignment, Hook, Literal, PropagateControl};
use std::sync::Mutex;

/// The hook shared by the engines of a portfolio.
pub(crate) type SharedHook = Arc<Mutex<dyn Hook>>;

/// Literal translation of a helper engine: user literals name the main engine's variables.
#[derive(Clone, Debug, Default)]
pub(crate) struct LitMap {
    /// Per main-engine variable: this engine's literal for its positive literal.
    pub to_local: Vec<Option<Lit>>,
    /// Per variable of this engine: the user literal of its positive literal (0: none).
    pub to_user: Vec<Literal>,
}

/// The external propagator of one engine.
pub(super) struct External {
    hook: SharedHook,
    thread_id: u32,
    /// Per literal code: watched.
    watched: Vec<bool>,
    /// Trail position up to which watched literals were looked for.
    head: usize,
    /// Watched literals given to the hook and still assigned, with their trail positions.
    notified: Vec<(usize, Lit)>,
    /// Clauses of the hook waiting to be added (they need a backjump, or are conflicting).
    pending: Vec<Vec<Lit>>,
    /// A conflict found inside a hook call waits in `Analysis::conflict`.
    stashed: bool,
    /// A hook call (or an init) runs.
    busy: bool,
    /// `None` on the main engine (user literal `±(v + 1)` is variable `v`).
    map: Option<LitMap>,
    /// The hook's `check_fixpoint` runs at every quiet propagation step.
    fixpoint: bool,
    /// Variables the hook added during this solve call (`external_var`).
    added: Vec<Var>,
    /// The decision levels the current search's assumptions occupy (clingo's root level).
    root: u32,
}

/// What the propagation step did.
pub(super) enum Step {
    /// Nothing new: propagation is at a fixpoint.
    Quiet,
    /// Assignments or clauses were added: propagate again.
    Changed,
    /// A conflict, in `Analysis::conflict`.
    Conflict,
}

impl Engine {
    /// Installs (or removes) the external propagator, called with `thread_id`; the engine
    /// backtracks to level 0 first (undoing for the previous one). Watches start empty.
    pub(crate) fn set_external(&mut self, hook: Option<(SharedHook, u32)>) {
        self.backtrack(0);
        self.ext = hook.map(|(hook, thread_id)| {
            Box::new(External {
                hook,
                thread_id,
                watched: Vec::new(),
                head: 0,
                notified: Vec::new(),
                pending: Vec::new(),
                stashed: false,
                busy: false,
                map: None,
                fixpoint: false,
                added: Vec::new(),
                root: 0,
            })
        });
    }

    /// Sets the literal translation of a helper engine (`None`: this is the main engine).
    pub(crate) fn set_lit_map(&mut self, map: Option<LitMap>) {
        if let Some(e) = self.ext.as_mut() {
            e.map = map;
        }
    }

    /// Marks an init running (no hook calls) or finished.
    pub(crate) fn set_external_busy(&mut self, busy: bool) {
        if let Some(e) = self.ext.as_mut() {
            e.busy = busy;
        }
    }

    /// Calls the hook's `check_fixpoint` at every propagation fixpoint (or stops).
    pub(crate) fn set_fixpoint_checks(&mut self, on: bool) {
        if let Some(e) = self.ext.as_mut() {
            e.fixpoint = on;
        }
    }

    /// A variable for the hook, live until [`Engine::retire_external_vars`]; `None` on a
    /// helper engine (its user literals name the main engine's variables).
    pub(crate) fn external_var(&mut self) -> Option<Var> {
        if self.ext.as_ref().is_none_or(|e| e.map.is_some()) {
            return None;
        }
        let v = self.new_var();
        self.ext.as_mut().expect("checked").added.push(v);
        Some(v)
    }

    /// After a solve call: the hook's variables retire (`Engine::retire_vars`).
    pub(crate) fn retire_external_vars(&mut self) {
        let added = match self.ext.as_mut() {
            Some(e) if !e.added.is_empty() => std::mem::take(&mut e.added),
            _ => return,
        };
        self.backtrack(0);
        self.retire_vars(&added);
    }

    /// This engine's literal of a user literal, `None` when it names no variable here.
    pub(crate) fn user_to_local(&self, l: Literal) -> Option<Lit> {
        if l == 0 {
            return None;
        }
        let v = l.unsigned_abs() as usize - 1;
        let pos = match self.ext.as_ref().and_then(|e| e.map.as_ref()) {
            None => (v < self.num_vars()).then(|| Var::new(v).positive())?,
            Some(m) => (*m.to_local.get(v)?)?,
        };
        Some(if l < 0 { !pos } else { pos })
    }

    /// How many variables user literals name (the main engine's count).
    pub(crate) fn user_vars(&self) -> usize {
        match self.ext.as_ref().and_then(|e| e.map.as_ref()) {
            None => self.num_vars(),
            Some(m) => m.to_local.len(),
        }
    }

    /// The user literal of `l` (0 when a helper's variable has none).
    pub(crate) fn user_lit(&self, l: Lit) -> Literal {
        let pos = match self.ext.as_ref().and_then(|e| e.map.as_ref()) {
            None => l.var().index() as Literal + 1,
            Some(m) => m.to_user.get(l.var().index()).copied().unwrap_or(0),
        };
        if l.is_neg() {
            -pos
        } else {
            pos
        }
    }

    /// The thread id the hook is called with.
    pub(crate) fn external_thread(&self) -> u32 {
        self.ext.as_ref().map_or(0, |e| e.thread_id)
    }

    /// The decision levels the assumptions of the running search occupy (at most the
    /// current decision level): clingo's root level.
    pub(crate) fn external_root(&self) -> u32 {
        self.ext
            .as_ref()
            .map_or(0, |e| e.root.min(self.decision_level()))
    }

    /// Records the assumption levels of a search starting (see `external_root`).
    pub(super) fn set_external_root(&mut self, assumptions: usize) {
        if let Some(e) = self.ext.as_mut() {
            e.root = u32::try_from(assumptions).unwrap_or(u32::MAX);
        }
    }

    /// Whether a conflict of the hook waits for analysis.
    pub(crate) fn external_conflict(&self) -> bool {
        self.ext
            .as_ref()
            .is_some_and(|e| e.stashed || !e.pending.is_empty())
    }

    /// Whether every decidable variable is assigned.
    pub(crate) fn is_total(&self) -> bool {
        (0..self.num_vars())
            .all(|v| !self.heur.decidable[v] || self.asg.values[Var::new(v).positive().code()] != 0)
    }

    /// Watches (or stops watching) `l` for the hook.
    pub(crate) fn watch_external(&mut self, l: Lit, on: bool) {
        let Some(e) = self.ext.as_mut() else {
            return;
        };
        if e.watched.len() <= l.code() {
            e.watched.resize(l.code() + 1, false);
        }
        e.watched[l.code()] = on;
        // A literal already true past the scan is reported by the next scan; one before it
        // was true before the watch existed, as in clingo (no retroactive call).
    }

    /// Whether `l` is watched.
    pub(crate) fn is_watched_external(&self, l: Lit) -> bool {
        self.ext
            .as_ref()
            .is_some_and(|e| e.watched.get(l.code()).copied().unwrap_or(false))
    }

    /// A clause from the hook (`PropagateControl::add_clause`); see `solve::propagator`.
    pub(crate) fn external_clause(&mut self, mut lits: Vec<Lit>) -> bool {
        if self.external_conflict() {
            return false;
        }
        lits.sort_unstable();
        lits.dedup();
        if lits.windows(2).any(|w| w[0] == !w[1]) {
            return true;
        }
        let dl = self.decision_level();
        let trues = lits.iter().filter(|&&l| self.val(l) == 1).count();
        let free = lits.iter().filter(|&&l| self.val(l) == 0).count();
        let max_false = lits
            .iter()
            .filter(|&&l| self.val(l) == -1)
            .map(|l| self.asg.level[l.var().index()])
            .max()
            .unwrap_or(0);
        let attach_now = if lits.len() == 1 {
            self.val(lits[0]) == 1 && self.level_of(lits[0]) == 0
        } else {
            trues > 0 || free >= 2 || (free == 1 && max_false == dl)
        };
        if lits.len() == 1 && attach_now {
            return true;
        }
        if attach_now {
            let conflicting = self.add_clause_in_search(&mut lits, true);
            debug_assert!(!conflicting, "an attachable clause does not conflict");
            return true;
        }
        if let Some(e) = self.ext.as_mut() {
            e.pending.push(lits);
        }
        false
    }

    /// Unit propagation inside a hook call (`PropagateControl::propagate`): false on conflict
    /// (stashed for the engine).
    pub(crate) fn external_propagate(&mut self) -> bool {
        if self.external_conflict() || self.ext.as_ref().is_some_and(|e| !e.pending.is_empty()) {
            return false;
        }
        if self.propagate_units() {
            if let Some(e) = self.ext.as_mut() {
                e.stashed = true;
            }
            return false;
        }
        true
    }

    /// Adds the waiting clauses; stops at the first conflicting one.
    fn flush_external(&mut self) -> Step {
        let Some(e) = self.ext.as_mut() else {
            return Step::Quiet;
        };
        let pending = std::mem::take(&mut e.pending);
        let mut rest = pending.into_iter();
        while let Some(mut c) = rest.next() {
            if self.add_clause_in_search(&mut c, true) {
                if let Some(e) = self.ext.as_mut() {
                    e.pending.extend(rest);
                }
                return Step::Conflict;
            }
        }
        Step::Changed
    }

    /// The propagation step of the hook (see the module doc).
    pub(super) fn propagate_external(&mut self) -> Step {
        let Some(e) = self.ext.as_mut() else {
            return Step::Quiet;
        };
        if e.busy {
            return Step::Quiet;
        }
        if e.stashed {
            e.stashed = false;
            return Step::Conflict;
        }
        if !e.pending.is_empty() {
            return self.flush_external();
        }
        let len = self.asg.trail.len();
        let start = e.head.min(len);
        e.head = len;
        let mut changes = Vec::new();
        for pos in start..len {
            let l = self.asg.trail[pos];
            if e.watched.get(l.code()).copied().unwrap_or(false) {
                e.notified.push((pos, l));
                changes.push(l);
            }
        }
        let hook = e.hook.clone();
        let fixpoint = e.fixpoint;
        if !changes.is_empty() {
            let user: Vec<Literal> = changes.iter().map(|&l| self.user_lit(l)).collect();
            self.call_hook(|h, ctl| h.propagate(ctl, &user), &hook);
            match self.after_hook(len) {
                Step::Quiet => {}
                step => return step,
            }
        }
        if !fixpoint {
            return Step::Quiet;
        }
        // clingo's check mode `fixpoint`: propagation (the hook's included) is quiet.
        let len = self.asg.trail.len();
        self.call_hook(|h, ctl| h.check_fixpoint(ctl), &hook);
        self.after_hook(len)
    }

    /// At a total assignment: the hook's `check`. True when it changed something (search goes
    /// on), false when the assignment stands.
    pub(super) fn check_external(&mut self) -> bool {
        let Some(e) = self.ext.as_ref() else {
            return false;
        };
        if e.busy {
            return false;
        }
        let hook = e.hook.clone();
        let added = e.added.len();
        let len = self.asg.trail.len();
        self.call_hook(|h, ctl| h.check(ctl), &hook);
        let grown = self.ext.as_ref().is_some_and(|e| e.added.len() != added);
        match self.after_hook(len) {
            // A new variable (`add_literal`) is still to be decided.
            Step::Quiet => grown,
            Step::Changed => true,
            Step::Conflict => {
                // `search` goes round to `propagate`, which reports it.
                if let Some(e) = self.ext.as_mut() {
                    e.stashed = true;
                }
                true
            }
        }
    }

    fn call_hook(
        &mut self,
        f: impl FnOnce(&mut dyn Hook, &mut PropagateControl<'_>),
        hook: &SharedHook,
    ) {
        let mut guard = hook.lock().unwrap_or_else(|p| p.into_inner());
        if let Some(e) = self.ext.as_mut() {
            e.busy = true;
        }
        f(&mut *guard, &mut PropagateControl { engine: self });
        if let Some(e) = self.ext.as_mut() {
            e.busy = false;
        }
    }

    /// What a hook call left: a stashed conflict, waiting clauses, or new assignments.
    fn after_hook(&mut self, len: usize) -> Step {
        let e = self.ext.as_mut().expect("a hook was called");
        if e.stashed {
            e.stashed = false;
            return Step::Conflict;
        }
        if !e.pending.is_empty() {
            return self.flush_external();
        }
        if self.asg.trail.len() != len || self.asg.qhead < self.asg.trail.len() {
            Step::Changed
        } else {
            Step::Quiet
        }
    }

    /// Before `backtrack` unassigns the trail from `start`: the hook's `undo` for the watched
    /// literals it was given there.
    pub(super) fn undo_external(&mut self, start: usize) {
        let Some(e) = self.ext.as_mut() else {
            return;
        };
        e.head = e.head.min(start);
        e.stashed = false;
        let k = e.notified.partition_point(|&(pos, _)| pos < start);
        if k == e.notified.len() {
            return;
        }
        let undone: Vec<Lit> = e.notified.drain(k..).map(|(_, l)| l).collect();
        if e.busy {
            debug_assert!(false, "no backtracking during a hook call");
            return;
        }
        let hook = e.hook.clone();
        let thread_id = e.thread_id;
        let user: Vec<Literal> = undone.iter().map(|&l| self.user_lit(l)).collect();
        let mut guard = hook.lock().unwrap_or_else(|p| p.into_inner());
        guard.undo(thread_id, &Assignment { engine: self }, &user);
    }
}
