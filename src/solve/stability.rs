//! The stability check of non-head-cycle-free programs, component by component and on partial
//! assignments (issue 31). An assignment `M` whose atoms are supported and free of the unfounded
//! sets the source-pointer propagator (`unfounded`) detects is an answer set exactly when no
//! nonempty set `U` of true atoms is unfounded in the disjunctive sense (Leone, Rullo, Scarcello
//! 1997): every rule with a head atom in `U` has a false body, a positive body atom in `U`, or a
//! true head atom outside `U`. If such a `U` exists, its part in a lowest strongly connected
//! component of the positive dependency graph that it meets is unfounded as well, and in a
//! head-cycle-free component the propagator already finds it (its supports there are shifted:
//! body and the other head atoms false, exact because no rule has two head atoms in one such
//! component). So only the *non-HCF components* (a disjunctive rule with two head atoms in
//! them) need this check, each with its own rules, atoms outside it fixed by `M` (Koch, Leone,
//! Pfeifer 2003; clasp checks components likewise).
//!
//! The check of a component `C` looks for a nonempty `U` among its atoms that are not false,
//! as `Y = N \ U` (`N` those atoms) satisfying, for every rule with a head atom in `U`, its
//! reduct, in a fresh engine with one variable per atom of `N`. Unassigned literals are read
//! the way that constrains `Y` most (a body literal as true; only a true head atom satisfies a
//! rule), so a `U` found is unfounded in every extension of the assignment, and a check that
//! finds none is final once every literal the component's rules mention is assigned. `U` is
//! learnt as loop nogoods, `not p` or one of the literals (all false now) that kept each rule
//! with a head atom in `U` from supporting it (Drescher et al., KR 2008), through the engine's
//! loop-set learning: a true atom of `U` makes a conflict (the search backjumps instead of
//! restarting), unassigned ones are propagated false. `Y` is grown to a maximal model first,
//! so `U` is minimal and its nogoods short.
//!
//! Scheduling: per component a counter of unassigned relevant variables (atoms and every
//! literal of its rules) and a dirty flag follow the trail (`propagate` scans what was
//! assigned since its last call, `undo` what backtracking removes). At a propagation fixpoint
//! every dirty component is checked: a partial check while some relevant variable is open,
//! a full one (which marks it verified until one of them is unassigned) when none is.
//! Backtracking alone never makes an unfounded set appear, so it leaves the flag alone.
//!
//! Invariants:
//! - `counted[v]` is set exactly for the relevant variables that are assigned and were scanned;
//!   each component's counter is its relevant variables minus the counted ones.
//! - `verified` implies the component's relevant variables are all assigned and the check found
//!   no unfounded set; undoing any of them clears it. So with every component verified the
//!   assignment is an answer set (given the propagator's unfounded-freeness and the completion).
//! - Every nogood learnt holds in every answer set (the loop-nogood argument, with unassigned
//!   literals never taken as reasons) and is violated by the current assignment. A rule the
//!   argument cannot read (a negative weight in a weight body) makes the nogood the negation of
//!   the component's assigned relevant literals, which is sound for the same reason.
//! - Nogoods stay valid in later multi-shot steps: a component's atoms have all their rules in
//!   one step (clingo's redefinition rule), and the structure is rebuilt when cycles change.

use super::engine::{Engine, SearchResult};
use super::lit::Lit;
use super::unfounded::LoopSet;

/// The body of a rule of a non-HCF component.
#[derive(Clone, Debug)]
pub enum StabilityBody {
    /// A conjunction: positive atoms of the component (local indices) and the other literals.
    Normal {
        /// Positive body atoms in the component.
        internal: Vec<u32>,
        /// Literals fixed by the assignment (negative literals, atoms of other components).
        fixed: Vec<Lit>,
    },
    /// A weight body: literals with weights and, for a positive atom of the component, its
    /// local index.
    Weight {
        /// The lower bound.
        lower: i64,
        /// Weighted literals.
        lits: Vec<(Lit, i64, Option<u32>)>,
    },
}

/// A rule with a head atom in a non-HCF component.
#[derive(Clone, Debug)]
pub struct StabilityRule {
    /// A choice rule (each head atom on its own); otherwise a disjunction.
    pub choice: bool,
    /// Head atoms in the component (local indices).
    pub heads: Vec<u32>,
    /// Head atoms outside the component (their literals).
    pub other_heads: Vec<Lit>,
    /// The literal of the whole body (false: the rule is out).
    pub body_lit: Lit,
    /// The body.
    pub body: StabilityBody,
}

/// One non-HCF strongly connected component: its atoms' literals and its rules.
#[derive(Clone, Debug)]
pub struct StabilityComponent {
    /// Per local atom: its literal.
    pub atoms: Vec<Lit>,
    /// The rules with a head atom in the component.
    pub rules: Vec<StabilityRule>,
}

/// A component and its scheduling state.
#[derive(Clone, Debug)]
struct Comp {
    spec: StabilityComponent,
    /// Unassigned relevant variables (atoms included).
    open_rel: u32,
    /// A relevant variable was assigned since the component's last check.
    dirty: bool,
    /// A full check found no unfounded set for the current values.
    verified: bool,
}

/// What a component's check found.
enum Found {
    /// No unfounded set.
    Nothing,
    /// An unfounded set: its loop nogoods.
    Set(LoopSet),
    /// A limit stopped the check.
    Stopped,
}

/// The stability checker: the non-HCF components and their scheduling state.
#[derive(Clone, Debug)]
pub struct Stability {
    comps: Vec<Comp>,
    /// Per variable (compressed rows): the components it is relevant to.
    rel_start: Vec<u32>,
    rel: Vec<u32>,
    /// Per variable: assigned, scanned and subtracted from the counters.
    counted: Vec<bool>,
    /// Trail position up to which assignments were scanned.
    head: usize,
    /// Components that became dirty, to check at the next fixpoint.
    ready: Vec<u32>,
    /// Statistics: component checks run.
    pub checks: u64,
    /// Statistics: checks that found an unfounded set.
    pub found: u64,
}

impl Stability {
    /// The checker over `comps`; nothing is counted until the first `propagate`.
    pub fn new(comps: Vec<StabilityComponent>) -> Stability {
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for (c, comp) in comps.iter().enumerate() {
            let c = c as u32;
            let mut vars: Vec<u32> = comp.atoms.iter().map(|l| l.var().index() as u32).collect();
            for r in &comp.rules {
                vars.extend(r.other_heads.iter().map(|l| l.var().index() as u32));
                match &r.body {
                    StabilityBody::Normal { fixed, .. } => {
                        vars.extend(fixed.iter().map(|l| l.var().index() as u32));
                    }
                    StabilityBody::Weight { lits, .. } => {
                        vars.extend(lits.iter().map(|(l, _, _)| l.var().index() as u32));
                    }
                }
            }
            vars.sort_unstable();
            vars.dedup();
            pairs.extend(vars.into_iter().map(|v| (v, c)));
        }
        pairs.sort_unstable();
        let num_vars = pairs.last().map_or(0, |p| p.0 as usize + 1);
        let mut rel_start = vec![0u32; num_vars + 1];
        for &(v, _) in &pairs {
            rel_start[v as usize + 1] += 1;
        }
        for v in 0..num_vars {
            rel_start[v + 1] += rel_start[v];
        }
        let mut comps: Vec<Comp> = comps
            .into_iter()
            .map(|spec| Comp {
                spec,
                open_rel: 0,
                dirty: false,
                verified: false,
            })
            .collect();
        for &(_, c) in &pairs {
            comps[c as usize].open_rel += 1;
        }
        Stability {
            comps,
            rel: pairs.into_iter().map(|(_, c)| c).collect(),
            rel_start,
            counted: vec![false; num_vars],
            head: 0,
            ready: Vec::new(),
            checks: 0,
            found: 0,
        }
    }

    /// The relevance entries of variable index `v`.
    fn rel_range(&self, v: usize) -> std::ops::Range<usize> {
        if v + 1 >= self.rel_start.len() {
            return 0..0;
        }
        self.rel_start[v] as usize..self.rel_start[v + 1] as usize
    }

    /// Backtracking removes `undone` from the trail, which starts at position `start`.
    pub fn undo(&mut self, undone: &[Lit], start: usize) {
        for &l in undone {
            let v = l.var().index();
            if v >= self.counted.len() || !self.counted[v] {
                continue;
            }
            self.counted[v] = false;
            for k in self.rel_range(v) {
                let comp = &mut self.comps[self.rel[k] as usize];
                comp.verified = false;
                comp.open_rel += 1;
            }
        }
        self.head = self.head.min(start);
    }

    /// The trail was rewritten (level-0 compaction): rescan it from the start.
    pub fn rescan(&mut self) {
        self.head = 0;
    }

    /// Whether every component passed a full check for the current assignment.
    pub fn all_verified(&self) -> bool {
        self.comps.iter().all(|c| c.verified)
    }

    /// At a propagation fixpoint: counts what was assigned since the last call and checks the
    /// components that became dirty. Returns the unfounded sets found (their atoms not false,
    /// their external literals false), at most one per call.
    pub fn propagate(&mut self, e: &Engine) -> Vec<LoopSet> {
        let trail = e.trail();
        for l in &trail[self.head.min(trail.len())..] {
            let v = l.var().index();
            if v >= self.counted.len() || self.counted[v] {
                continue;
            }
            self.counted[v] = true;
            for k in self.rel_range(v) {
                let c = self.rel[k];
                let comp = &mut self.comps[c as usize];
                comp.open_rel -= 1;
                if !comp.dirty {
                    comp.dirty = true;
                    self.ready.push(c);
                }
            }
        }
        self.head = trail.len();
        while let Some(c) = self.ready.pop() {
            let comp = &mut self.comps[c as usize];
            if !comp.dirty || comp.verified {
                comp.dirty = false;
                continue;
            }
            comp.dirty = false;
            let full = comp.open_rel == 0;
            self.checks += 1;
            match check(&self.comps[c as usize].spec, e) {
                Found::Nothing => self.comps[c as usize].verified = full,
                Found::Set(set) => {
                    self.found += 1;
                    return vec![set];
                }
                Found::Stopped => {}
            }
        }
        Vec::new()
    }
}

/// Looks for an unfounded set among the true atoms of `comp` (see the module documentation).
fn check(comp: &StabilityComponent, e: &Engine) -> Found {
    let n = comp.atoms.len();
    let val: Vec<Option<bool>> = comp.atoms.iter().map(|&l| e.value(l)).collect();
    let in_t: Vec<bool> = val.iter().map(|&v| v == Some(true)).collect();
    // `U` may hold unassigned atoms too (its nogoods then make them false).
    let in_n: Vec<bool> = val.iter().map(|&v| v != Some(false)).collect();
    if !in_n.iter().any(|&t| t) {
        return Found::Nothing;
    }
    let mut sub = Engine::new();
    sub.limits.deadline = e.limits.deadline;
    sub.limits.interrupt = e.limits.interrupt.clone();
    let vars: Vec<Option<Lit>> = (0..n)
        .map(|i| {
            in_n[i].then(|| {
                // Deciding atoms true first finds a large `Y`: a small unfounded set.
                let v = sub.new_var();
                sub.prefer(v, None, Some(true));
                v.positive()
            })
        })
        .collect();
    let value = |l: Lit| e.value(l);
    for r in &comp.rules {
        if value(r.body_lit) == Some(false) {
            continue;
        }
        let heads: Vec<Lit> = r.heads.iter().filter_map(|&h| vars[h as usize]).collect();
        if heads.is_empty() {
            continue;
        }
        if !r.choice && r.other_heads.iter().any(|&h| value(h) == Some(true)) {
            continue;
        }
        let mut clause: Vec<Lit> = Vec::new();
        match &r.body {
            StabilityBody::Normal { internal, fixed } => {
                if fixed.iter().any(|&l| value(l) == Some(false)) {
                    continue;
                }
                if internal
                    .iter()
                    .any(|&a| value(comp.atoms[a as usize]) == Some(false))
                {
                    continue;
                }
                clause.extend(
                    internal
                        .iter()
                        .filter_map(|&a| vars[a as usize].map(|v| !v)),
                );
            }
            StabilityBody::Weight { lower, lits } => {
                let mut fixed = 0i64;
                let mut var_lits = Vec::new();
                for &(l, w, at) in lits {
                    if let Some(v) = at.and_then(|a| vars[a as usize]) {
                        var_lits.push((v, w));
                        continue;
                    }
                    match value(l) {
                        Some(true) => fixed += w,
                        Some(false) => {}
                        // The reading that satisfies the body most easily.
                        None => fixed += w.max(0),
                    }
                }
                if var_lits.is_empty() {
                    if fixed < *lower {
                        continue;
                    }
                } else {
                    let b = sub.new_var().positive();
                    sub.add_weight(b, &var_lits, lower - fixed);
                    clause.push(!b);
                }
            }
        }
        if r.choice {
            for &h in &heads {
                let mut c = clause.clone();
                c.push(h);
                sub.add_clause(&c);
            }
        } else {
            // Only a true head atom in `Y` satisfies the rule for an atom of `U`; an
            // unassigned one in `U` needs a true one in `Y` as well.
            let true_heads: Vec<Lit> = r
                .heads
                .iter()
                .filter(|&&h| in_t[h as usize])
                .filter_map(|&h| vars[h as usize])
                .collect();
            for &h in r
                .heads
                .iter()
                .filter(|&&h| in_n[h as usize] && !in_t[h as usize])
            {
                let mut c = clause.clone();
                c.extend_from_slice(&true_heads);
                c.extend(vars[h as usize]);
                sub.add_clause(&c);
            }
            if !true_heads.is_empty() {
                clause.extend_from_slice(&true_heads);
                sub.add_clause(&clause);
            }
        }
    }
    let in_y = match smaller_model(&mut sub, &vars) {
        Minimality::Minimal => return Found::Nothing,
        Minimality::Smaller(in_y) => in_y,
        Minimality::Stopped => return Found::Stopped,
    };
    let in_u: Vec<bool> = in_n.iter().zip(&in_y).map(|(&t, &y)| t && !y).collect();
    let (atoms, mut ext) = match reasons(comp, e, &in_u) {
        Some(ext) => {
            let atoms = (0..n).filter(|&i| in_u[i]).map(|i| comp.atoms[i]);
            (atoms.collect(), ext)
        }
        None => {
            // The fallback blocks the assignment, which only a true atom of `U` refutes.
            let Some(t) = (0..n).find(|&i| in_u[i] && in_t[i]) else {
                return Found::Nothing;
            };
            (vec![comp.atoms[t]], block(comp, e))
        }
    };
    ext.sort_unstable();
    ext.dedup();
    Found::Set(LoopSet { atoms, ext })
}

/// What a search for a model of a reduct smaller than the candidate found.
pub(crate) enum Minimality {
    /// No model of the reduct strictly inside the candidate.
    Minimal,
    /// A smaller model of the reduct: per variable of `vars`, whether it is in it.
    Smaller(Vec<bool>),
    /// A limit (deadline, interrupt) stopped the check.
    Stopped,
}

/// Searches the reduct `sub`, whose candidate atoms are `vars` (`None`: not in the candidate),
/// for a model that leaves out at least one of them, and grows it to a maximal one inside the
/// candidate (each round keeps the model and adds an atom): a minimal unfounded set touches few
/// rules, so its nogoods are short. Used by the per-component check here and by the whole-model
/// check of `solver::minimal`.
pub(crate) fn smaller_model(sub: &mut Engine, vars: &[Option<Lit>]) -> Minimality {
    let strict: Vec<Lit> = vars.iter().flatten().map(|&l| !l).collect();
    if !sub.add_clause(&strict) {
        return Minimality::Minimal;
    }
    match sub.search(&[]) {
        SearchResult::Sat => {}
        SearchResult::Unsat => return Minimality::Minimal,
        SearchResult::Unknown => return Minimality::Stopped,
    }
    let mut in_y: Vec<bool> = vars
        .iter()
        .map(|v| v.is_some_and(|v| sub.value(v) == Some(true)))
        .collect();
    loop {
        let keep: Vec<Lit> = vars
            .iter()
            .zip(&in_y)
            .filter_map(|(v, &y)| v.filter(|_| y))
            .collect();
        let grow: Vec<Lit> = vars
            .iter()
            .zip(&in_y)
            .filter_map(|(v, &y)| v.filter(|_| !y))
            .collect();
        if !sub.add_clause(&grow) {
            break;
        }
        match sub.search(&keep) {
            SearchResult::Sat => {
                for (y, v) in in_y.iter_mut().zip(vars) {
                    *y = v.is_some_and(|v| sub.value(v) == Some(true));
                }
            }
            SearchResult::Unsat => break,
            SearchResult::Unknown => return Minimality::Stopped,
        }
    }
    Minimality::Smaller(in_y)
}

/// The literals (all false now) that keep every rule with a head atom in `U` from supporting
/// `U` from outside; `None` when some rule has no such reason the argument covers.
fn reasons(comp: &StabilityComponent, e: &Engine, in_u: &[bool]) -> Option<Vec<Lit>> {
    let value = |l: Lit| e.value(l);
    let is_false = |l: Lit| value(l) == Some(false);
    let internal = |at: Option<u32>| at.is_some_and(|a| in_u[a as usize]);
    let mut out: Vec<Lit> = Vec::new();
    for r in &comp.rules {
        if !r.heads.iter().any(|&h| in_u[h as usize]) {
            continue;
        }
        if let StabilityBody::Normal { internal: pos, .. } = &r.body {
            if pos.iter().any(|&a| in_u[a as usize]) {
                continue;
            }
        }
        if is_false(r.body_lit) {
            out.push(r.body_lit);
            continue;
        }
        // A true head atom outside `U` satisfies a disjunction's reduct.
        let other_head = || -> Option<Lit> {
            if r.choice {
                return None;
            }
            r.heads
                .iter()
                .find(|&&h| !in_u[h as usize] && value(comp.atoms[h as usize]) == Some(true))
                .map(|&h| !comp.atoms[h as usize])
                .or_else(|| {
                    r.other_heads
                        .iter()
                        .find(|&&h| value(h) == Some(true))
                        .map(|&h| !h)
                })
        };
        match &r.body {
            StabilityBody::Normal {
                internal: pos,
                fixed,
            } => {
                if let Some(&l) = fixed.iter().find(|&&l| is_false(l)) {
                    out.push(l);
                } else if let Some(&a) = pos.iter().find(|&&a| is_false(comp.atoms[a as usize])) {
                    out.push(comp.atoms[a as usize]);
                } else {
                    out.push(other_head()?);
                }
            }
            StabilityBody::Weight { lower, lits } => {
                if lits.iter().any(|&(_, w, _)| w < 0) {
                    return None;
                }
                // Without `U`, unassigned literals counted as true.
                let sum: i64 = lits
                    .iter()
                    .filter(|&&(l, _, at)| !internal(at) && !is_false(l))
                    .map(|&(_, w, _)| w)
                    .sum();
                if sum >= *lower {
                    out.push(other_head()?);
                    continue;
                }
                // The false literals, lightest first, may turn true as long as the sum stays
                // below the bound; the rest are the reason.
                let mut false_lits: Vec<(Lit, i64)> = lits
                    .iter()
                    .filter(|&&(l, _, at)| !internal(at) && is_false(l))
                    .map(|&(l, w, _)| (l, w))
                    .collect();
                false_lits.sort_unstable_by_key(|&(_, w)| w);
                let mut slack = lower - 1 - sum;
                for (l, w) in false_lits {
                    if w <= slack {
                        slack -= w;
                    } else {
                        out.push(l);
                    }
                }
            }
        }
    }
    Some(out)
}

/// The negation of every assigned literal the component's check read: excludes this part of
/// the assignment (the fallback of `reasons`).
fn block(comp: &StabilityComponent, e: &Engine) -> Vec<Lit> {
    let mut lits: Vec<Lit> = comp.atoms.clone();
    for r in &comp.rules {
        lits.push(r.body_lit);
        lits.extend_from_slice(&r.other_heads);
        match &r.body {
            StabilityBody::Normal { fixed, .. } => lits.extend_from_slice(fixed),
            StabilityBody::Weight { lits: wl, .. } => lits.extend(wl.iter().map(|&(l, _, _)| l)),
        }
    }
    lits.into_iter()
        .filter_map(|l| match e.value(l) {
            Some(true) => Some(!l),
            Some(false) => Some(l),
            None => None,
        })
        .collect()
}
