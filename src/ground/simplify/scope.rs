//! The atoms one grounding visits, and the arrays a multi-shot session keeps between its
//! groundings so that simplifying a later part costs what the part adds, not what was grounded
//! before.
//!
//! A later grounding of a session visits its *scope*: the atoms it created (above
//! `old_atoms`) and the older atoms its rules, directives and `prefer` facts name, or whose
//! domain or fact flag it changed (`Grounder::touched`). An older atom outside the scope keeps
//! what the full passes would find for it again: frozen (possible or a fact), or false and
//! unnumbered, or a fact reported before; no rule of this grounding names it, so nothing here
//! can change it. The first grounding, a one-shot one, one with provenance (its atom table
//! lists every atom) and one whose shown predicates changed visit every atom.
//!
//! Invariants: `atoms` is sorted and without repeats (the passes keep the creation order of the
//! full ones); in a partial scope `loc[a]` is atom `a`'s index in `atoms` plus one and 0 for
//! every other atom ([`Scope::release`] clears it again); the arrays of [`Scratch`] are all
//! zero (false, unnumbered) between groundings except `status`, whose entries outside a scope
//! are never read.

use super::{Status, NUMBERED};
use crate::ground::instantiate::{GroundAtom, Grounder};
use crate::ground::program::{BodyRef, Lit};

/// Arrays over every grounder atom, kept by a multi-shot session between its groundings
/// (allocated and cleared once instead of once per grounding).
#[derive(Default)]
pub struct Scratch {
    /// [`Scope`]'s local index of each atom (0: outside the scope).
    loc: Vec<u32>,
    /// The status of each atom (meaningful inside the scope only).
    pub(super) status: Vec<Status>,
    /// External atoms (all false between groundings).
    pub(super) external: Vec<bool>,
    /// The aspif number of each atom (all 0 between groundings).
    pub(super) number: Vec<u32>,
    /// The shown predicates of the last grounding.
    pub(super) shown: Vec<bool>,
}

/// The atoms a grounding visits, in creation order, with each one's local index.
pub(super) struct Scope {
    /// Every atom (indexes are atom numbers minus one, no `loc` array).
    all: bool,
    /// The atoms visited, sorted.
    pub(super) atoms: Vec<u32>,
    /// Local index plus one of each atom (partial scope only).
    loc: Vec<u32>,
}

impl Scope {
    /// The scope of grounding `g`: every atom when `all` (or when nothing is old), else the
    /// fresh atoms and the old ones named by its rules, its directives and `prefer_before`,
    /// and those it touched. `loc` is the session's array (all zero).
    pub(super) fn build(
        g: &Grounder<'_>,
        prefer_before: &[GroundAtom],
        all: bool,
        loc: Vec<u32>,
    ) -> Scope {
        let n = g.atoms.len();
        if all || g.old_atoms == 0 {
            return Scope {
                all: true,
                atoms: (1..=n as u32).collect(),
                loc,
            };
        }
        let old = g.old_atoms as u32;
        let mut loc = loc;
        loc.resize(n + 1, 0);
        let mut atoms: Vec<u32> = Vec::new();
        let mut add = |a: u32| {
            if a <= old && loc[a as usize] == 0 {
                loc[a as usize] = 1;
                atoms.push(a);
            }
        };
        for r in g.rules.iter() {
            r.head.iter().for_each(|&h| add(h));
            match r.body {
                BodyRef::Normal(ls) => ls.iter().for_each(|&l| add(l.unsigned_abs())),
                BodyRef::Weight { lits, .. } => {
                    lits.iter().for_each(|&(l, _)| add(l.unsigned_abs()))
                }
            }
        }
        let d = &g.directives;
        let mut add_lits = |ls: &[Lit]| ls.iter().for_each(|&l| add(l.unsigned_abs()));
        for conds in d.minimize.values() {
            conds.iter().for_each(|c| add_lits(c));
        }
        for (_, cond, _) in &d.shows {
            add_lits(cond);
        }
        for h in &d.heuristics {
            add_lits(&[h.atom as Lit]);
            add_lits(&h.condition);
        }
        for e in &d.edges {
            add_lits(&e.condition);
        }
        for t in &d.theory.atoms {
            t.elems.iter().for_each(|(_, c)| add_lits(c));
            if let Some(a) = t.atom {
                add_lits(&[a.lit()]);
            }
        }
        let named = d.cr_rules.iter().map(|(a, _)| a);
        let named = named
            .chain(&d.projections)
            .chain(d.externals.iter().map(|(a, _)| a));
        for &a in named.chain(prefer_before).chain(&g.touched) {
            add(a.get());
        }
        atoms.sort_unstable();
        atoms.extend(old + 1..=n as u32);
        for (i, &a) in atoms.iter().enumerate() {
            loc[a as usize] = i as u32 + 1;
        }
        Scope {
            all: false,
            atoms,
            loc,
        }
    }

    /// The number of atoms visited.
    pub(super) fn len(&self) -> usize {
        self.atoms.len()
    }

    /// Whether atom `a` is in the scope.
    #[inline]
    pub(super) fn contains(&self, a: usize) -> bool {
        self.all || self.loc.get(a).is_some_and(|&i| i != 0)
    }

    /// The local index of atom `a` (in the scope: every atom a rule or directive names is).
    #[inline]
    pub(super) fn index(&self, a: usize) -> usize {
        if self.all {
            a - 1
        } else {
            self.loc[a] as usize - 1
        }
    }

    /// Adds the atoms made since the scope was built (auxiliary atoms of minimize statements);
    /// `n` is the number of atoms now.
    pub(super) fn extend(&mut self, n: usize) {
        let last = self.atoms.last().copied().unwrap_or(0);
        for a in last + 1..=n as u32 {
            self.atoms.push(a);
            if !self.all {
                self.loc.resize(n + 1, 0);
                self.loc[a as usize] = self.atoms.len() as u32;
            }
        }
    }

    /// Whether a session's earlier grounding numbered atom `a` (`before`: the session's
    /// flags).
    #[inline]
    pub(super) fn frozen(before: &[u8], a: usize) -> bool {
        before.get(a).is_some_and(|&f| f & NUMBERED != 0)
    }

    /// The session's `loc` array, cleared.
    pub(super) fn release(mut self) -> Vec<u32> {
        if !self.all {
            for &a in &self.atoms {
                self.loc[a as usize] = 0;
            }
        }
        self.loc
    }
}

impl Scratch {
    /// Takes the `loc` array out for a [`Scope`].
    pub(super) fn take_loc(&mut self) -> Vec<u32> {
        std::mem::take(&mut self.loc)
    }

    /// Gives back the `loc` array of a released [`Scope`].
    pub(super) fn put_loc(&mut self, loc: Vec<u32>) {
        self.loc = loc;
    }
}
