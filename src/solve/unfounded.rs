//! Unfounded-set propagation with source pointers for non-tight programs (Gebser, Kaufmann,
//! Schaub, "Conflict-driven answer set solving: from theory to practice", AIJ 2012, section 5,
//! algorithm `UnfoundedSet`; clasp's `DefaultUnfoundedCheck` follows the same idea).
//!
//! Every *cyclic* atom (in a non-trivial strongly connected component of the positive dependency
//! graph) keeps a *source pointer*: one of its supports whose body was, when chosen, not false
//! and whose positive atoms of the same component all had sources themselves (for a weight body:
//! the non-false literals outside the component plus the sourced atoms inside reached the bound).
//! Source pointers are never undone on backtracking: backtracking only makes literals less
//! false, so a valid source stays valid.
//!
//! At a propagation fixpoint the check looks only at what changed since the previous check (the
//! trail segment the engine passes in):
//! 1. atoms whose source became invalid (its literal, or for a weight source any of its
//!    literals, became false) and that are not false themselves form the set `S`;
//! 2. `S` is closed under "my source's body contains an atom of `S` of my component";
//! 3. support is propagated forward inside `S` (least fixpoint): an atom of `S` with a support
//!    that is not false and has no same-component positive atom still in `S` gets that support
//!    as its new source and leaves `S`;
//! 4. what remains of `S` is unfounded. Split by component, each part `U` is returned with its
//!    external supports `EB(U)` (all false): the engine learns the loop nogoods
//!    `{a} ∪ EB(U)` for every `a` in `U`, as one shared loop formula (`engine::loops`) when
//!    that is smaller, so it propagates `not a` for every atom of `U`.
//!
//! Invariants:
//! - The source graph (atom -> same-component atoms its source counted) is acyclic: a source is
//!   only chosen among atoms outside `S`, and `S` is closed under dependence, so no chosen source
//!   can depend on the atom it is chosen for. A weight source counts only the atoms that were
//!   sourced and non-false when it was chosen, and any later loss among its literals or atoms
//!   invalidates it (step 1/2), so what it counted stays true of it.
//! - After a check, every non-false cyclic atom has a valid source, except the atoms the check
//!   just returned nogoods for. Hence, with all propagation at a fixpoint, the assignment is
//!   unfounded-free (AIJ 2012, Theorem 5.4).
//! - The trail segment of one check lies at one decision level, so an atom that was false (and
//!   skipped) when its source was invalidated is unassigned again only after that invalidation
//!   was undone as well.
//! - Atoms that never had a source (before the first check) sit in `no_source` and are tried at
//!   every check until they get one or are false at level 0.
//! - Loop nogoods stay valid in later steps of a multi-shot program: the rules of an atom are
//!   all given in one step, so the external supports of a set of defined atoms never change.
//! - In a component where a disjunctive rule has two head atoms (not head-cycle-free) supports
//!   use the rule body only (a weaker but sound nogood); `stability` checks those components.
//!
//! Cost: a check with no invalidated source touches only the watch lists of the newly false
//! literals. Weight bodies in recursive components are handled natively (no fallback).

use super::engine::Engine;
use super::lit::Lit;

/// Marks an atom without a source pointer.
const NONE: u32 = u32::MAX;

/// Lists of `(support, head)` pairs indexed by a key (an atom or a literal code), stored flat
/// (compressed rows) so that the hot loops read one contiguous slice and never the supports.
#[derive(Clone, Debug, Default)]
struct Lists {
    /// Per key: start of its row in `data`; one extra entry closes the last row.
    start: Vec<u32>,
    /// The rows, concatenated.
    data: Vec<(u32, u32)>,
}

impl Lists {
    /// Builds the rows from `(key, support, head)` triples; duplicates are dropped.
    fn build(keys: usize, mut triples: Vec<(u32, u32, u32)>) -> Lists {
        triples.sort_unstable();
        triples.dedup();
        let mut start = vec![0u32; keys + 1];
        for &(k, _, _) in &triples {
            start[k as usize + 1] += 1;
        }
        for k in 0..keys {
            start[k + 1] += start[k];
        }
        let data = triples.into_iter().map(|(_, s, h)| (s, h)).collect();
        Lists { start, data }
    }

    /// The row range of `key` (empty for keys beyond the table).
    fn range(&self, key: usize) -> std::ops::Range<usize> {
        if key + 1 >= self.start.len() {
            return 0..0;
        }
        self.start[key] as usize..self.start[key + 1] as usize
    }
}

/// One way for a cyclic atom to be supported.
#[derive(Clone, Debug)]
pub struct Support {
    /// Local index of the supported atom.
    pub head: u32,
    /// The literal that is true when the support holds.
    pub lit: Lit,
    /// The support's body.
    pub body: SupportBody,
}

/// The body of a support, as far as foundedness is concerned.
#[derive(Clone, Debug)]
pub enum SupportBody {
    /// A conjunction: local indices of its positive cyclic atoms (`Unfounded::new` keeps those
    /// of the head's component).
    Normal(Vec<u32>),
    /// A weight body: literals with positive weights and the local index of the literal's atom
    /// when it is a positive cyclic atom (`Unfounded::new` keeps it only in the head's
    /// component).
    Weight {
        /// The lower bound.
        bound: u64,
        /// Weighted literals.
        lits: Vec<(Lit, u64, Option<u32>)>,
    },
}

/// An unfounded set `U` of one component and its external supports: every atom of `U` must be
/// false unless one of `ext` is true (the loop nogoods `{a} ∪ EB(U)` for each `a` in `U`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoopSet {
    /// The atoms of `U` (positive literals), none of them false.
    pub atoms: Vec<Lit>,
    /// One false literal per external support, sorted and without repetitions.
    pub ext: Vec<Lit>,
}

/// The unfounded-set propagator's program view and its source pointers.
#[derive(Clone, Debug, Default)]
pub struct Unfounded {
    /// Literal of each cyclic atom (local index).
    pub atom_lit: Vec<Lit>,
    /// Per cyclic atom: its strongly connected component.
    pub component: Vec<u32>,
    /// Per cyclic atom: indices of its supports.
    pub supports_of: Vec<Vec<u32>>,
    /// Per cyclic atom: supports (with their heads) of atoms of its component whose body has
    /// it as a positive atom (each support once).
    occurs: Lists,
    /// All supports of cyclic atoms.
    pub supports: Vec<Support>,
    /// Per literal code: supports whose validity is lost when that literal becomes false (the
    /// support literal; for weight bodies also every weighted literal).
    watch: Lists,
    /// Per atom: its source (a support index), or `NONE`.
    source: Vec<u32>,
    /// Atoms that never had a source.
    no_source: Vec<u32>,
    /// Scratch: per atom, membership in `S`.
    in_s: Vec<bool>,
    /// Scratch: per support, count of positive same-component atoms in `S`.
    count: Vec<u32>,
    /// Scratch: the atoms put in `S` by the current check.
    s_list: Vec<u32>,
    /// Scratch: atoms that got a source and whose dependents must be rechecked.
    queue: Vec<u32>,
    /// Statistics: checks that found an invalidated source.
    pub checks: u64,
}

impl Unfounded {
    /// Builds the propagator; `supports` must refer to atoms `0..atom_lit.len()` and
    /// `component` gives each atom's strongly connected component. Positive atoms of other
    /// components are dropped from the bodies: they are founded or unfounded on their own.
    pub fn new(atom_lit: Vec<Lit>, component: Vec<u32>, mut supports: Vec<Support>) -> Unfounded {
        let n = atom_lit.len();
        assert_eq!(component.len(), n, "one component per cyclic atom");
        for s in supports.iter_mut() {
            let c = component[s.head as usize];
            match &mut s.body {
                SupportBody::Normal(pos) => {
                    pos.retain(|&p| component[p as usize] == c);
                    pos.sort_unstable();
                    pos.dedup();
                }
                SupportBody::Weight { lits, .. } => {
                    for (_, _, at) in lits.iter_mut() {
                        if at.is_some_and(|a| component[a as usize] != c) {
                            *at = None;
                        }
                    }
                }
            }
        }
        let mut supports_of = vec![Vec::new(); n];
        let mut occurs = Vec::new();
        let mut watch = Vec::new();
        let mut max_code = 0usize;
        for (i, s) in supports.iter().enumerate() {
            let (i, h) = (i as u32, s.head);
            supports_of[h as usize].push(i);
            max_code = max_code.max(s.lit.code());
            watch.push((s.lit.code() as u32, i, h));
            match &s.body {
                SupportBody::Normal(pos) => {
                    for &p in pos {
                        occurs.push((p, i, h));
                    }
                }
                SupportBody::Weight { lits, .. } => {
                    for &(l, _, a) in lits {
                        max_code = max_code.max(l.code());
                        watch.push((l.code() as u32, i, h));
                        if let Some(a) = a {
                            occurs.push((a, i, h));
                        }
                    }
                }
            }
        }
        let occurs = Lists::build(n, occurs);
        let watch = Lists::build(max_code + 1, watch);
        let count = vec![0; supports.len()];
        Unfounded {
            atom_lit,
            component,
            supports_of,
            occurs,
            supports,
            watch,
            source: vec![NONE; n],
            no_source: (0..n as u32).collect(),
            in_s: vec![false; n],
            count,
            s_list: Vec::new(),
            queue: Vec::new(),
            checks: 0,
        }
    }

    /// Variables whose value can make a support fail: support literals and weight-body
    /// literals.
    pub fn relevant_vars(&self) -> Vec<super::lit::Var> {
        let mut v = Vec::new();
        for s in &self.supports {
            v.push(s.lit.var());
            if let SupportBody::Weight { lits, .. } = &s.body {
                v.extend(lits.iter().map(|(l, _, _)| l.var()));
            }
        }
        v.sort_unstable();
        v.dedup();
        v
    }

    fn is_false(e: &Engine, l: Lit) -> bool {
        e.value(l) == Some(false)
    }

    /// Puts atom `a` into `S` unless it is there already or false.
    fn enter(&mut self, e: &Engine, a: u32) {
        let au = a as usize;
        if !self.in_s[au] && !Self::is_false(e, self.atom_lit[au]) {
            self.in_s[au] = true;
            self.s_list.push(a);
        }
    }

    /// Whether support `si` can be (re)chosen as a source now: its literal is not false and it
    /// does not depend on an atom of `S`.
    fn eligible(&self, e: &Engine, si: usize) -> bool {
        let s = &self.supports[si];
        if Self::is_false(e, s.lit) {
            return false;
        }
        match &s.body {
            SupportBody::Normal(_) => self.count[si] == 0,
            SupportBody::Weight { bound, lits } => {
                let mut sum = 0u64;
                for &(l, w, at) in lits {
                    if Self::is_false(e, l) || at.is_some_and(|a| self.in_s[a as usize]) {
                        continue;
                    }
                    sum += w;
                    if sum >= *bound {
                        return true;
                    }
                }
                *bound == 0
            }
        }
    }

    /// Makes `si` the source of its head, which leaves `S`; dependents are rechecked later.
    fn take_source(&mut self, si: usize) {
        let h = self.supports[si].head;
        self.source[h as usize] = si as u32;
        self.in_s[h as usize] = false;
        self.queue.push(h);
    }

    /// Processes the assignments `trail[start..]` made since the previous check and returns
    /// the unfounded sets found, one per component (empty when every non-false cyclic atom
    /// still has a valid source). Must be called at a unit-propagation fixpoint.
    #[inline(never)]
    pub fn check(&mut self, e: &Engine, start: usize) -> Vec<LoopSet> {
        debug_assert!(self.s_list.is_empty() && self.queue.is_empty());
        // 1. Sources invalidated by newly false literals.
        let trail = e.trail();
        for &t in &trail[start.min(trail.len())..] {
            for k in self.watch.range((!t).code()) {
                let (si, h) = self.watch.data[k];
                if self.source[h as usize] == si {
                    self.enter(e, h);
                }
            }
        }
        // Atoms that never had a source; those false at level 0 stay false.
        if !self.no_source.is_empty() {
            let mut list = std::mem::take(&mut self.no_source);
            list.retain(|&a| {
                let l = self.atom_lit[a as usize];
                self.source[a as usize] == NONE && !(Self::is_false(e, l) && e.level_of(l) == 0)
            });
            for &a in &list {
                self.enter(e, a);
            }
            self.no_source = list;
        }
        if self.s_list.is_empty() {
            return Vec::new();
        }
        self.checks += 1;
        // 2. Close `S` under dependence of sources.
        let mut i = 0;
        while i < self.s_list.len() {
            let x = self.s_list[i] as usize;
            i += 1;
            for k in self.occurs.range(x) {
                let (si, h) = self.occurs.data[k];
                if self.source[h as usize] == si {
                    self.enter(e, h);
                }
            }
        }
        // 3. Forward propagation of support inside `S`.
        for i in 0..self.s_list.len() {
            let x = self.s_list[i] as usize;
            for k in self.occurs.range(x) {
                self.count[self.occurs.data[k].0 as usize] += 1;
            }
        }
        for i in 0..self.s_list.len() {
            let p = self.s_list[i] as usize;
            if !self.in_s[p] {
                continue;
            }
            for k in 0..self.supports_of[p].len() {
                let si = self.supports_of[p][k] as usize;
                if self.eligible(e, si) {
                    self.take_source(si);
                    break;
                }
            }
            while let Some(x) = self.queue.pop() {
                for k in self.occurs.range(x as usize) {
                    let (si, h) = self.occurs.data[k];
                    let (si, h) = (si as usize, h as usize);
                    self.count[si] -= 1;
                    if self.in_s[h] && self.eligible(e, si) {
                        self.take_source(si);
                    }
                }
            }
        }
        for i in 0..self.s_list.len() {
            let x = self.s_list[i] as usize;
            for k in self.occurs.range(x) {
                self.count[self.occurs.data[k].0 as usize] = 0;
            }
        }
        // 4. What is left is unfounded; one loop set per component.
        let mut unfounded: Vec<u32> = self
            .s_list
            .iter()
            .copied()
            .filter(|&a| self.in_s[a as usize])
            .collect();
        let mut sets = Vec::new();
        if !unfounded.is_empty() {
            unfounded.sort_unstable_by_key(|&a| (self.component[a as usize], a));
            for part in unfounded
                .chunk_by(|a, b| self.component[*a as usize] == self.component[*b as usize])
            {
                let mut ext = self.external(e, part);
                ext.sort_unstable();
                ext.dedup();
                let atoms = part.iter().map(|&a| self.atom_lit[a as usize]).collect();
                sets.push(LoopSet { atoms, ext });
            }
        }
        for &a in &self.s_list {
            self.in_s[a as usize] = false;
        }
        self.s_list.clear();
        sets
    }

    /// The external supports of `part` (atoms of one component, all in `S`), each as a false
    /// literal whose truth would let some support of `part` hold without `part`.
    fn external(&self, e: &Engine, part: &[u32]) -> Vec<Lit> {
        let mut ext: Vec<Lit> = Vec::new();
        for &a in part {
            for &si in &self.supports_of[a as usize] {
                let s = &self.supports[si as usize];
                match &s.body {
                    SupportBody::Normal(pos) => {
                        if pos.iter().all(|&p| !self.in_s[p as usize]) {
                            debug_assert!(Self::is_false(e, s.lit));
                            ext.push(s.lit);
                        }
                    }
                    SupportBody::Weight { bound, lits } => {
                        let outside: u64 = lits
                            .iter()
                            .filter(|&&(_, _, at)| at.is_none_or(|x| !self.in_s[x as usize]))
                            .map(|&(_, w, _)| w)
                            .sum();
                        if outside < *bound {
                            continue;
                        }
                        if Self::is_false(e, s.lit) {
                            ext.push(s.lit);
                        } else {
                            // The body cannot reach its bound without the part unless one of
                            // these currently false literals becomes true.
                            for &(l, _, at) in lits {
                                if at.is_none_or(|x| !self.in_s[x as usize]) && Self::is_false(e, l)
                                {
                                    ext.push(l);
                                }
                            }
                        }
                    }
                }
            }
        }
        ext.sort_unstable();
        ext.dedup();
        ext
    }
}
