//! Unfounded-set propagation for non-tight programs (Gebser, Kaufmann, Schaub, "Conflict-driven
//! answer set solving: from theory to practice", AIJ 2012, section 5).
//!
//! At every propagation fixpoint we compute the greatest unfounded set among the *cyclic* atoms
//! (those in a non-trivial strongly connected component of the positive dependency graph): a
//! least fixpoint marks an atom founded when one of its supports is not false and every cyclic
//! atom of the support's positive body is already founded (for weight bodies: the founded or
//! non-cyclic, non-false literals reach the bound). Non-false cyclic atoms left unfounded form a
//! set `U`; for each `a` in `U` we return the loop nogood `a -> external supports of U`, written
//! as a clause whose other literals are all false, so it propagates `not a`.
//!
//! Invariants: the check runs only when unit propagation is at a fixpoint, so a support literal
//! that is not false has no false positive body atom; every support literal of an external
//! support of `U` is therefore false (the argument of AIJ 2012, Proposition 5.3). For
//! non-head-cycle-free programs supports use the rule body only (a weaker but sound nogood);
//! minimality is then checked separately.
//!
//! This is a source-pointer-free variant: simpler to trust, linear in the cyclic part per
//! fixpoint.

use super::engine::Engine;
use super::lit::Lit;

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
    /// A conjunction: local indices of its positive cyclic atoms.
    Normal(Vec<u32>),
    /// A weight body: literals with positive weights and the local index of the literal's atom
    /// when it is a positive cyclic atom.
    Weight {
        /// The lower bound.
        bound: u64,
        /// Weighted literals.
        lits: Vec<(Lit, u64, Option<u32>)>,
    },
}

/// The unfounded-set propagator's program view.
#[derive(Clone, Debug, Default)]
pub struct Unfounded {
    /// Literal of each cyclic atom (local index).
    pub atom_lit: Vec<Lit>,
    /// Per cyclic atom: indices of its supports.
    pub supports_of: Vec<Vec<u32>>,
    /// Per cyclic atom: supports whose body has it as a positive cyclic atom.
    pub occurs: Vec<Vec<u32>>,
    /// All supports of cyclic atoms.
    pub supports: Vec<Support>,
    /// Scratch: per atom, founded flag.
    founded: Vec<bool>,
    /// Scratch: per support, count of unfounded positive cyclic atoms.
    count: Vec<u32>,
}

impl Unfounded {
    /// Builds the propagator; `supports` must refer to atoms `0..atom_lit.len()`.
    pub fn new(atom_lit: Vec<Lit>, mut supports: Vec<Support>) -> Unfounded {
        let n = atom_lit.len();
        // Counting requires each positive cyclic atom once per body.
        for s in supports.iter_mut() {
            if let SupportBody::Normal(pos) = &mut s.body {
                pos.sort_unstable();
                pos.dedup();
            }
        }
        let mut supports_of = vec![Vec::new(); n];
        let mut occurs = vec![Vec::new(); n];
        for (i, s) in supports.iter().enumerate() {
            supports_of[s.head as usize].push(i as u32);
            match &s.body {
                SupportBody::Normal(pos) => {
                    for &p in pos {
                        occurs[p as usize].push(i as u32);
                    }
                }
                SupportBody::Weight { lits, .. } => {
                    for &(_, _, a) in lits {
                        if let Some(a) = a {
                            occurs[a as usize].push(i as u32);
                        }
                    }
                }
            }
        }
        for o in occurs.iter_mut() {
            o.sort_unstable();
            o.dedup();
        }
        let count = vec![0; supports.len()];
        Unfounded {
            atom_lit,
            supports_of,
            occurs,
            supports,
            founded: vec![false; n],
            count,
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

    fn weight_founded(&self, e: &Engine, s: &Support) -> bool {
        match &s.body {
            SupportBody::Weight { bound, lits } => {
                if *bound == 0 {
                    return true;
                }
                let mut sum = 0u64;
                for &(l, w, a) in lits {
                    if e.value(l) == Some(false) {
                        continue;
                    }
                    if let Some(a) = a {
                        if !self.founded[a as usize] {
                            continue;
                        }
                    }
                    sum += w;
                    if sum >= *bound {
                        return true;
                    }
                }
                false
            }
            SupportBody::Normal(_) => false,
        }
    }

    /// Computes loop nogoods for the greatest unfounded set under the current assignment; empty
    /// when every non-false cyclic atom is founded.
    #[inline(never)]
    pub fn check(&mut self, e: &Engine) -> Vec<Vec<Lit>> {
        let n = self.atom_lit.len();
        self.founded.clear();
        self.founded.resize(n, false);
        let mut queue: Vec<u32> = Vec::new();
        for (i, s) in self.supports.iter().enumerate() {
            if let SupportBody::Normal(pos) = &s.body {
                self.count[i] = pos.len() as u32;
            }
        }
        for i in 0..self.supports.len() {
            let s = &self.supports[i];
            let h = s.head as usize;
            if self.founded[h]
                || e.value(s.lit) == Some(false)
                || e.value(self.atom_lit[h]) == Some(false)
            {
                continue;
            }
            let ok = match &s.body {
                SupportBody::Normal(_) => self.count[i] == 0,
                SupportBody::Weight { .. } => self.weight_founded(e, s),
            };
            if ok {
                self.founded[h] = true;
                queue.push(h as u32);
            }
        }
        while let Some(x) = queue.pop() {
            for k in 0..self.occurs[x as usize].len() {
                let si = self.occurs[x as usize][k] as usize;
                let h = self.supports[si].head as usize;
                if let SupportBody::Normal(_) = self.supports[si].body {
                    self.count[si] -= 1;
                }
                if self.founded[h] || e.value(self.supports[si].lit) == Some(false) {
                    continue;
                }
                let ok = match &self.supports[si].body {
                    SupportBody::Normal(_) => self.count[si] == 0,
                    SupportBody::Weight { .. } => self.weight_founded(e, &self.supports[si]),
                };
                if ok {
                    self.founded[h] = true;
                    queue.push(h as u32);
                }
            }
        }
        let unfounded: Vec<usize> = (0..n)
            .filter(|&a| !self.founded[a] && e.value(self.atom_lit[a]) != Some(false))
            .collect();
        if unfounded.is_empty() {
            return Vec::new();
        }
        let mut in_u = vec![false; n];
        for &a in &unfounded {
            in_u[a] = true;
        }
        // External supports of U, each as a false literal.
        let mut ext: Vec<Lit> = Vec::new();
        for &a in &unfounded {
            for &si in &self.supports_of[a] {
                let s = &self.supports[si as usize];
                match &s.body {
                    SupportBody::Normal(pos) => {
                        if pos.iter().all(|&p| !in_u[p as usize]) {
                            debug_assert_eq!(e.value(s.lit), Some(false));
                            ext.push(s.lit);
                        }
                    }
                    SupportBody::Weight { bound, lits } => {
                        let outside: u64 = lits
                            .iter()
                            .filter(|&&(_, _, at)| at.is_none_or(|x| !in_u[x as usize]))
                            .map(|&(_, w, _)| w)
                            .sum();
                        if outside < *bound {
                            continue;
                        }
                        if e.value(s.lit) == Some(false) {
                            ext.push(s.lit);
                        } else {
                            // The body cannot reach its bound without U unless one of these
                            // currently false literals becomes true.
                            for &(l, _, at) in lits {
                                if at.is_none_or(|x| !in_u[x as usize]) && e.value(l) == Some(false)
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
        unfounded
            .iter()
            .map(|&a| {
                let mut c = Vec::with_capacity(ext.len() + 1);
                c.push(!self.atom_lit[a]);
                c.extend_from_slice(&ext);
                c
            })
            .collect()
    }
}
