//! Translation of a ground program into the engine's constraints: Clark completion with body
//! variables (AIJ 2012, section 3), shifting of disjunctive heads into per-atom supports, native
//! weight constraints for weight bodies, and the positive dependency graph that decides which
//! atoms need unfounded-set propagation and whether the program is head-cycle-free.
//!
//! Invariants:
//! - Every atom `1..=num_atoms` has a solver literal (`atom_lit`); index 0 holds the constant
//!   true literal.
//! - For a rule `H :- B`, `B` gets one literal shared by all rules with the same body. A
//!   disjunctive rule with head atoms `h1..hn` gives `hi` the support `B and not hj (j != i)`
//!   (shifting); a choice rule gives each head atom the support `B`.
//! - Completion: an atom that is not a free external implies the disjunction of its supports;
//!   supports and bodies imply heads through the rule clauses.
//! - A program is head-cycle-free when no disjunctive rule has two head atoms in one strongly
//!   connected component of the positive dependency graph; only then are answer sets exactly
//!   the supported, unfounded-free assignments. Otherwise `non_hcf` is set and the caller checks
//!   minimality of each candidate.

use super::engine::Engine;
use super::lit::Lit;
use super::unfounded::{Support, SupportBody, Unfounded};
use crate::ground::program::{Body, ExternalValue, GroundProgram, HeadKind, Rule};
use hashbrown::{DefaultHashBuilder, HashMap, HashTable};
use smallvec::SmallVec;
use std::hash::BuildHasher;

/// The supports of one atom as (support literal, rule index); most atoms have one or two, held
/// inline without a heap allocation.
pub type AtomSupports = SmallVec<[(Lit, u32); 2]>;

/// The link between a ground program and the engine's variables.
#[derive(Clone, Debug, Default)]
pub struct Translation {
    /// Per atom (index 0: constant true): its literal.
    pub atom_lit: Vec<Lit>,
    /// Per atom: supports as (support literal, rule index).
    pub supports: Vec<AtomSupports>,
    /// Per rule: the literal of its body.
    pub rule_body: Vec<Lit>,
    /// Per atom: free (an external that is not false), so no completion clause.
    pub free: Vec<bool>,
    /// Per output statement: the literal of its condition.
    pub output_lits: Vec<Lit>,
    /// Minimize levels, highest priority first: (priority, weighted literals).
    pub minimize: Vec<(i64, Vec<(Lit, i64)>)>,
    /// Literals assumed for every solve call (aspif assumptions and true externals).
    pub assumptions: Vec<Lit>,
    /// True when some disjunctive rule has two head atoms in one positive cycle.
    pub non_hcf: bool,
    /// Guard of the current incremental step, attached to loop nogoods (see `unfounded`).
    pub loop_guard: Option<Lit>,
    /// Conjunctions already given a literal: (start, length, literal), the key (sorted literal
    /// codes) being `conj_keys[start..start + length]`. One flat key array instead of a `Vec`
    /// per key keeps a body at 12 bytes in the table plus its codes.
    conj: HashTable<(u32, u32, Lit)>,
    /// The keys of `conj`, one after another.
    conj_keys: Vec<u32>,
    /// Hasher of the keys of `conj`.
    conj_hasher: DefaultHashBuilder,
    /// Weight bodies already given a literal, keyed by bound and sorted (code, weight) pairs.
    weights: HashMap<(i64, Vec<(u32, i64)>), Lit>,
}

/// The largest atom mentioned anywhere in the program (the declared count may be too small).
pub fn max_atom(p: &GroundProgram) -> u32 {
    let mut m = p.num_atoms;
    let lit_atom = |l: i32| l.unsigned_abs();
    for r in &p.rules {
        m = m.max(r.head.iter().copied().max().unwrap_or(0));
        match &r.body {
            Body::Normal(ls) => m = m.max(ls.iter().map(|&l| lit_atom(l)).max().unwrap_or(0)),
            Body::Weight { lits, .. } => {
                m = m.max(lits.iter().map(|&(l, _)| lit_atom(l)).max().unwrap_or(0))
            }
        }
    }
    for mz in &p.minimize {
        m = m.max(mz.lits.iter().map(|&(l, _)| lit_atom(l)).max().unwrap_or(0));
    }
    for o in &p.outputs {
        m = m.max(o.condition.iter().map(|&l| lit_atom(l)).max().unwrap_or(0));
    }
    for &(a, _) in &p.externals {
        m = m.max(a);
    }
    for &l in &p.assumptions {
        m = m.max(lit_atom(l));
    }
    for &a in &p.projections {
        m = m.max(a);
    }
    for c in &p.cr_rules {
        m = m.max(c.appl);
    }
    m
}

impl Translation {
    /// The literal of an aspif literal.
    pub fn lit(&self, l: i32) -> Lit {
        let a = self.atom_lit[l.unsigned_abs() as usize];
        if l < 0 {
            !a
        } else {
            a
        }
    }

    /// The constant true literal.
    pub fn true_lit(&self) -> Lit {
        self.atom_lit[0]
    }

    /// A literal equivalent to the conjunction of `lits`.
    pub fn conjunction(&mut self, e: &mut Engine, lits: &[Lit]) -> Lit {
        self.conjunction_as(e, lits, true)
    }

    /// The literal of the conjunction of `lits`, where `to_lits` says whether the clauses
    /// `b -> l` are needed. Without them the literal only follows from its literals
    /// (`l1 and .. and lk -> b`), which is all an integrity constraint needs: its body literal is
    /// made false at once, so `b -> l` would be satisfied at level 0 from then on (and dropped by
    /// the engine's level-0 simplification before the search; the search is the same either
    /// way), and a later rule with the same body shares the false literal.
    fn conjunction_as(&mut self, e: &mut Engine, lits: &[Lit], to_lits: bool) -> Lit {
        let mut key: Vec<u32> = lits.iter().map(|l| l.code() as u32).collect();
        key.sort_unstable();
        key.dedup();
        if key.is_empty() {
            return self.true_lit();
        }
        if key.len() == 1 {
            return Lit::from_code(key[0]);
        }
        let hash = self.conj_hasher.hash_one(&key[..]);
        let keys = &self.conj_keys;
        let same = |&(start, len, _): &(u32, u32, Lit)| {
            keys[start as usize..(start + len) as usize] == key[..]
        };
        if let Some(&(_, _, b)) = self.conj.find(hash, same) {
            return b;
        }
        let b = e.new_body_var().positive();
        let mut big = vec![b];
        for &c in &key {
            let l = Lit::from_code(c);
            if to_lits {
                e.add_clause(&[!b, l]);
            }
            big.push(!l);
        }
        e.add_clause(&big);
        let start = self.conj_keys.len() as u32;
        self.conj_keys.extend_from_slice(&key);
        let (keys, hasher) = (&self.conj_keys, &self.conj_hasher);
        self.conj
            .insert_unique(hash, (start, key.len() as u32, b), |&(s, n, _)| {
                hasher.hash_one(&keys[s as usize..(s + n) as usize])
            });
        b
    }

    /// The literal of a rule body; `constraint` when the rule is an integrity constraint (its
    /// body literal is made false right after).
    fn body_lit(&mut self, e: &mut Engine, body: &Body, constraint: bool) -> Lit {
        match body {
            Body::Normal(ls) => {
                let lits: Vec<Lit> = ls.iter().map(|&l| self.lit(l)).collect();
                self.conjunction_as(e, &lits, !constraint)
            }
            Body::Weight { lower, lits } => {
                let mut key: Vec<(u32, i64)> = lits
                    .iter()
                    .map(|&(l, w)| (self.lit(l).code() as u32, w))
                    .collect();
                key.sort_unstable();
                if let Some(&b) = self.weights.get(&(*lower, key.clone())) {
                    return b;
                }
                let b = e.new_body_var().positive();
                let wl: Vec<(Lit, i64)> =
                    key.iter().map(|&(c, w)| (Lit::from_code(c), w)).collect();
                e.add_weight(b, &wl, *lower);
                self.weights.insert((*lower, key), b);
                b
            }
        }
    }

    /// Translates the whole program into a fresh engine.
    pub fn build(p: &GroundProgram, e: &mut Engine) -> Translation {
        let n = max_atom(p) as usize;
        let mut t = Translation::default();
        // One variable per atom and, at most, about one per rule body (shifted disjunctions
        // and output conditions may add a few more).
        e.reserve_vars(n + 1 + p.rules.len());
        let truth = e.new_var();
        e.add_clause(&[truth.positive()]);
        t.atom_lit.push(truth.positive());
        for _ in 0..n {
            let v = e.new_var();
            t.atom_lit.push(v.positive());
        }
        t.supports = vec![AtomSupports::new(); n + 1];
        t.free = vec![false; n + 1];
        t.set_externals(p);
        for (i, r) in p.rules.iter().enumerate() {
            t.add_rule(e, i, r);
        }
        for a in 1..=n {
            t.complete(e, a);
        }
        for o in &p.outputs {
            let lits: Vec<Lit> = o.condition.iter().map(|&l| t.lit(l)).collect();
            let c = t.conjunction(e, &lits);
            t.output_lits.push(c);
        }
        let mut prios: Vec<i64> = p.minimize.iter().map(|m| m.priority).collect();
        prios.sort_unstable_by(|a, b| b.cmp(a));
        prios.dedup();
        for pr in prios {
            let mut lits = Vec::new();
            for m in p.minimize.iter().filter(|m| m.priority == pr) {
                for &(l, w) in &m.lits {
                    lits.push((t.lit(l), w));
                }
            }
            t.minimize.push((pr, lits));
        }
        t.install_unfounded(p, e);
        t
    }

    /// Sets `free` and `assumptions` from the external statements and assumptions of `p`: the
    /// last statement on an atom gives its value (as `check::external_values`), free and true
    /// externals are free, true ones assumed; every other atom is not free. The caller drops
    /// external statements on atoms that have rules (they are ordinary atoms then).
    pub fn set_externals(&mut self, p: &GroundProgram) {
        self.free.iter_mut().for_each(|f| *f = false);
        self.assumptions.clear();
        let mut last: HashMap<u32, ExternalValue> = HashMap::new();
        for &(a, v) in &p.externals {
            last.insert(a, v);
        }
        let mut assumed = hashbrown::HashSet::new();
        for &(a, _) in &p.externals {
            let v = last[&a];
            match v {
                ExternalValue::Free => self.free[a as usize] = true,
                ExternalValue::True => {
                    self.free[a as usize] = true;
                    if assumed.insert(a) {
                        self.assumptions.push(self.atom_lit[a as usize]);
                    }
                }
                ExternalValue::False | ExternalValue::Release => {}
            }
        }
        for &l in &p.assumptions {
            let x = self.lit(l);
            self.assumptions.push(x);
        }
    }

    /// Adds the clauses of one rule (its body, its head clause and its supports).
    pub fn add_rule(&mut self, e: &mut Engine, index: usize, r: &Rule) {
        let constraint = r.head_kind == HeadKind::Disjunction && r.head.is_empty();
        let b = self.body_lit(e, &r.body, constraint);
        self.rule_body.push(b);
        debug_assert_eq!(self.rule_body.len(), index + 1);
        let mut head: Vec<u32> = r.head.clone();
        head.sort_unstable();
        head.dedup();
        match r.head_kind {
            HeadKind::Choice => {
                for &h in &head {
                    self.supports[h as usize].push((b, index as u32));
                }
            }
            HeadKind::Disjunction => {
                let mut c = vec![!b];
                c.extend(head.iter().map(|&h| self.atom_lit[h as usize]));
                e.add_clause(&c);
                if head.len() == 1 {
                    self.supports[head[0] as usize].push((b, index as u32));
                } else {
                    for &h in &head {
                        let mut conj = vec![b];
                        conj.extend(
                            head.iter()
                                .filter(|&&o| o != h)
                                .map(|&o| !self.atom_lit[o as usize]),
                        );
                        let s = self.conjunction(e, &conj);
                        self.supports[h as usize].push((s, index as u32));
                    }
                }
            }
        }
    }

    /// Adds the completion clause of atom `a`: true only if some support holds.
    pub fn complete(&mut self, e: &mut Engine, a: usize) {
        if self.free[a] {
            return;
        }
        let mut c = vec![!self.atom_lit[a]];
        c.extend(self.supports[a].iter().map(|&(s, _)| s));
        e.add_clause(&c);
    }

    /// Computes strongly connected components of the positive dependency graph, decides
    /// head-cycle-freeness and installs the unfounded-set propagator if there are cycles.
    pub fn install_unfounded(&mut self, p: &GroundProgram, e: &mut Engine) {
        let n = self.atom_lit.len();
        let mut edges: Vec<Vec<u32>> = vec![Vec::new(); n];
        for r in &p.rules {
            let pos: Vec<u32> = match &r.body {
                Body::Normal(ls) => ls.iter().filter(|&&l| l > 0).map(|&l| l as u32).collect(),
                Body::Weight { lits, .. } => lits
                    .iter()
                    .filter(|&&(l, w)| l > 0 && w > 0)
                    .map(|&(l, _)| l as u32)
                    .collect(),
            };
            for &h in &r.head {
                edges[h as usize].extend_from_slice(&pos);
            }
        }
        let comp = scc(&edges);
        let mut size = vec![0u32; n];
        for &c in &comp {
            size[c as usize] += 1;
        }
        let cyclic: Vec<bool> = (0..n)
            .map(|a| {
                a > 0 && (size[comp[a] as usize] > 1 || edges[a].iter().any(|&b| b as usize == a))
            })
            .collect();
        self.non_hcf = p.rules.iter().any(|r| {
            r.head_kind == HeadKind::Disjunction
                && r.head.iter().enumerate().any(|(i, &h)| {
                    cyclic[h as usize]
                        && r.head[i + 1..]
                            .iter()
                            .any(|&g| g != h && comp[g as usize] == comp[h as usize])
                })
        });
        let mut local = vec![u32::MAX; n];
        let mut atom_lits = Vec::new();
        let mut components = Vec::new();
        for a in 0..n {
            if cyclic[a] && !self.free[a] {
                local[a] = atom_lits.len() as u32;
                atom_lits.push(self.atom_lit[a]);
                components.push(comp[a]);
            }
        }
        if atom_lits.is_empty() {
            e.set_unfounded(None);
            return;
        }
        let mut sups = Vec::new();
        for a in 0..n {
            if local[a] == u32::MAX {
                continue;
            }
            for &(s, ri) in &self.supports[a] {
                let ri = ri as usize;
                let r = &p.rules[ri];
                // Non-HCF programs use the rule body as support (see the module comment).
                let lit = if self.non_hcf { self.rule_body[ri] } else { s };
                let body = match &r.body {
                    Body::Normal(ls) => SupportBody::Normal(
                        ls.iter()
                            .filter(|&&l| l > 0 && local[l as usize] != u32::MAX)
                            .map(|&l| local[l as usize])
                            .collect(),
                    ),
                    Body::Weight { lower, lits } => {
                        let mut bound = *lower as i128;
                        let mut wl = Vec::new();
                        for &(l, w) in lits {
                            if w > 0 {
                                let at = if l > 0 && local[l as usize] != u32::MAX {
                                    Some(local[l as usize])
                                } else {
                                    None
                                };
                                wl.push((self.lit(l), w as u64, at));
                            } else if w < 0 {
                                bound -= w as i128;
                                wl.push((!self.lit(l), (-(w as i128)) as u64, None));
                            }
                        }
                        SupportBody::Weight {
                            bound: bound.max(0) as u64,
                            lits: wl,
                        }
                    }
                };
                sups.push(Support {
                    head: local[a],
                    lit,
                    body,
                });
            }
        }
        let mut uf = Unfounded::new(atom_lits, components, sups);
        uf.guard = self.loop_guard;
        e.set_unfounded(Some(uf));
    }
}

/// Tarjan's strongly connected components, iteratively; returns the component of each node.
pub fn scc(edges: &[Vec<u32>]) -> Vec<u32> {
    let n = edges.len();
    let mut index = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut on_stack = vec![false; n];
    let mut comp = vec![u32::MAX; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut next = 0u32;
    let mut ncomp = 0u32;
    for root in 0..n {
        if index[root] != u32::MAX {
            continue;
        }
        let mut call: Vec<(u32, usize)> = vec![(root as u32, 0)];
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root as u32);
        on_stack[root] = true;
        while let Some(&mut (v, ref mut k)) = call.last_mut() {
            let v = v as usize;
            if *k < edges[v].len() {
                let w = edges[v][*k] as usize;
                *k += 1;
                if index[w] == u32::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w as u32);
                    on_stack[w] = true;
                    call.push((w as u32, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
            } else {
                call.pop();
                if let Some(&(u, _)) = call.last() {
                    low[u as usize] = low[u as usize].min(low[v]);
                }
                if low[v] == index[v] {
                    loop {
                        let w = stack.pop().expect("Tarjan stack holds the component") as usize;
                        on_stack[w] = false;
                        comp[w] = ncomp;
                        if w == v {
                            break;
                        }
                    }
                    ncomp += 1;
                }
            }
        }
    }
    comp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scc_finds_cycles() {
        // 0 -> 1 -> 2 -> 1, 3 alone.
        let edges = vec![vec![1], vec![2], vec![1], vec![]];
        let c = scc(&edges);
        assert_eq!(c[1], c[2]);
        assert_ne!(c[0], c[1]);
        assert_ne!(c[3], c[1]);
    }
}
