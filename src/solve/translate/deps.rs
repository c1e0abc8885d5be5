//! The positive dependency graph of a program: its strongly connected components decide which
//! atoms are cyclic (and so need unfounded-set propagation, installed here as the engine's
//! `Unfounded` propagator) and whether the program is head-cycle-free. `update_cycles` extends
//! the components step by step in multi-shot solving.
//!
//! Invariants:
//! - `comp`/`cyclic` hold the strongly connected components of the positive dependency graph
//!   of every step so far; `cyclic_atoms` lists the cyclic atoms and `next_comp` is above
//!   every component number in use.
//! - A program is head-cycle-free when no disjunctive rule has two head atoms in one strongly
//!   connected component of the positive dependency graph; only then are answer sets exactly
//!   the supported, unfounded-free assignments. Otherwise `non_hcf` is set, the components
//!   with a head cycle get the stability check (`solve::stability`, installed here with the
//!   propagator), and only their atoms' supports are the rule bodies alone.

use super::graph::{scc, Graph};
use super::Translation;
use crate::ground::program::HeadKind;
use crate::ground::program::{BodyRef, GroundProgram, RuleRef};
use crate::solve::engine::Engine;
use crate::solve::stability::{Stability, StabilityBody, StabilityComponent, StabilityRule};
use crate::solve::unfounded::{Support, SupportBody, Unfounded};
use hashbrown::HashMap;
use smallvec::SmallVec;

impl Translation {
    /// Computes strongly connected components of the positive dependency graph, decides
    /// head-cycle-freeness and installs the unfounded-set propagator if there are cycles; `known`: the components of `p`'s positive dependency graph over
    /// `self.atom_lit.len()` atoms, when already known.
    pub(super) fn install_unfounded_with(
        &mut self,
        p: &GroundProgram,
        e: &mut Engine,
        known: Option<Cycles>,
    ) {
        let n = self.atom_lit.len();
        let Cycles { comp, cyclic } = known.unwrap_or_else(|| Cycles::of(p, n, |_, _| {}));
        debug_assert_eq!(comp.len(), n);
        self.next_comp = comp.iter().copied().max().map_or(0, |c| c + 1);
        self.cyclic_atoms = (0..n as u32).filter(|&a| cyclic[a as usize]).collect();
        self.comp = comp;
        self.cyclic = cyclic;
        self.rebuild_unfounded(p, e);
    }

    /// Updates the components after a step whose rules (those from index `first_rule` on)
    /// gave rules to the atoms `defined` (new atoms, or externals until now), and reinstalls
    /// the unfounded-set propagator when some atom became cyclic. Atoms defined in earlier
    /// steps keep their rules, so every new positive cycle goes through `defined`: when no
    /// defined atom occurred positively in an earlier rule body (`pos_occ_before`), no earlier
    /// atom reaches one and the new cycles lie among `defined`, found by Tarjan's algorithm
    /// on the new rules alone; otherwise the components of the whole program are recomputed.
    pub fn update_cycles(
        &mut self,
        p: &GroundProgram,
        e: &mut Engine,
        defined: &[u32],
        first_rule: usize,
        pos_occ_before: bool,
    ) {
        if pos_occ_before {
            let n = self.atom_lit.len();
            let before = self.cyclic_atoms.len();
            let c = Cycles::of(p, n, |_, _| {});
            let changed = c.cyclic != self.cyclic || before > 0;
            self.next_comp = c.comp.iter().copied().max().map_or(0, |c| c + 1);
            self.cyclic_atoms = (0..n as u32).filter(|&a| c.cyclic[a as usize]).collect();
            self.comp = c.comp;
            self.cyclic = c.cyclic;
            if changed {
                self.rebuild_unfounded(p, e);
            }
            return;
        }
        let local: HashMap<u32, u32> = defined
            .iter()
            .enumerate()
            .map(|(i, &a)| (a, i as u32))
            .collect();
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); defined.len()];
        for ri in first_rule..p.rules.len() {
            let r = p.rules.get(ri);
            if r.head.is_empty() {
                continue;
            }
            let mut targets: SmallVec<[u32; 8]> = SmallVec::new();
            match r.body {
                BodyRef::Normal(ls) => targets.extend(
                    ls.iter()
                        .filter(|&&l| l > 0)
                        .filter_map(|&l| local.get(&(l as u32)).copied()),
                ),
                BodyRef::Weight { lits, .. } => targets.extend(
                    lits.iter()
                        .filter(|&&(l, w)| l > 0 && w > 0)
                        .filter_map(|&(l, _)| local.get(&(l as u32)).copied()),
                ),
            }
            if targets.is_empty() {
                continue;
            }
            for &h in r.head {
                if let Some(&hl) = local.get(&h) {
                    lists[hl as usize].extend_from_slice(&targets);
                }
            }
        }
        if lists.iter().all(|l| l.is_empty()) {
            return;
        }
        let g = Graph::from_lists(&lists);
        let comp = scc(&g);
        let mut size: HashMap<u32, u32> = HashMap::new();
        for &c in &comp {
            *size.entry(c).or_default() += 1;
        }
        let mut any = false;
        for (i, &a) in defined.iter().enumerate() {
            let c = comp[i];
            let cyc = size[&c] > 1 || g.succ(i).contains(&(i as u32));
            self.comp[a as usize] = self.next_comp + c;
            if cyc {
                self.cyclic[a as usize] = true;
                self.cyclic_atoms.push(a);
                any = true;
            }
        }
        self.next_comp += size.len() as u32;
        if any {
            self.rebuild_unfounded(p, e);
        }
    }

    /// Decides head-cycle-freeness and (re)installs the unfounded-set propagator over the
    /// cyclic atoms (none installed when there are none). Work proportional to the cyclic
    /// atoms, their supports and the disjunctive rules.
    fn rebuild_unfounded(&mut self, p: &GroundProgram, e: &mut Engine) {
        // The components where some disjunctive rule has two head atoms: only their atoms
        // need the stability check, and only their supports are the rule bodies alone.
        let mut non_hcf_comps: Vec<u32> = Vec::new();
        {
            let (comp, cyclic) = (&self.comp, &self.cyclic);
            for &ri in &self.disj_rules {
                let r = p.rules.get(ri as usize);
                for (i, &h) in r.head.iter().enumerate() {
                    if cyclic[h as usize]
                        && r.head[i + 1..]
                            .iter()
                            .any(|&g| g != h && comp[g as usize] == comp[h as usize])
                    {
                        non_hcf_comps.push(comp[h as usize]);
                    }
                }
            }
        }
        non_hcf_comps.sort_unstable();
        non_hcf_comps.dedup();
        self.non_hcf = !non_hcf_comps.is_empty();
        let in_non_hcf = |c: u32| non_hcf_comps.binary_search(&c).is_ok();
        e.set_stability(
            self.stability_components(p, &non_hcf_comps)
                .map(Stability::new),
        );
        let mut local: HashMap<u32, u32> = HashMap::new();
        let mut atom_lits = Vec::new();
        let mut components = Vec::new();
        let mut atoms: Vec<u32> = self
            .cyclic_atoms
            .iter()
            .copied()
            .filter(|&a| !self.free[a as usize])
            .collect();
        atoms.sort_unstable();
        for &a in &atoms {
            local.insert(a, atom_lits.len() as u32);
            atom_lits.push(self.atom_lit[a as usize]);
            components.push(self.comp[a as usize]);
        }
        if atom_lits.is_empty() {
            if e.has_unfounded() {
                e.set_unfounded(None);
            }
            return;
        }
        let loc = |l: i32| -> Option<u32> {
            if l > 0 {
                local.get(&(l as u32)).copied()
            } else {
                None
            }
        };
        let mut sups = Vec::new();
        for &a in &atoms {
            for &(s, ri) in &self.supports[a as usize] {
                let ri = ri as usize;
                let r = p.rules.get(ri);
                // Non-HCF components use the rule body as support (see the module comment).
                let lit = if in_non_hcf(self.comp[a as usize]) {
                    self.rule_body[ri]
                } else {
                    s
                };
                let body = match r.body {
                    BodyRef::Normal(ls) => {
                        SupportBody::Normal(ls.iter().filter_map(|&l| loc(l)).collect())
                    }
                    BodyRef::Weight { lower, lits } => {
                        let mut bound = lower as i128;
                        let mut wl = Vec::new();
                        for &(l, w) in lits {
                            if w > 0 {
                                wl.push((self.lit(l), w as u64, loc(l)));
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
                    head: local[&a],
                    lit,
                    body,
                });
            }
        }
        let uf = Unfounded::new(atom_lits, components, sups);
        e.set_unfounded(Some(uf));
    }

    /// The rules and atoms of the non-HCF components `comps` (sorted) for the stability
    /// check; `None` when there are none.
    fn stability_components(
        &self,
        p: &GroundProgram,
        comps: &[u32],
    ) -> Option<Vec<StabilityComponent>> {
        if comps.is_empty() {
            return None;
        }
        let index = |a: u32| comps.binary_search(&self.comp[a as usize]).ok();
        // Per atom of a non-HCF component: (component position, local index).
        let mut local: HashMap<u32, (usize, u32)> = HashMap::new();
        let mut atoms: Vec<Vec<u32>> = vec![Vec::new(); comps.len()];
        let mut cyc: Vec<u32> = self
            .cyclic_atoms
            .iter()
            .copied()
            .filter(|&a| !self.free[a as usize])
            .collect();
        cyc.sort_unstable();
        for a in cyc {
            if let Some(k) = index(a) {
                local.insert(a, (k, atoms[k].len() as u32));
                atoms[k].push(a);
            }
        }
        let mut out = Vec::with_capacity(comps.len());
        for (k, list) in atoms.iter().enumerate() {
            let mut rules: Vec<u32> = list
                .iter()
                .flat_map(|&a| self.supports[a as usize].iter().map(|&(_, ri)| ri))
                .collect();
            rules.sort_unstable();
            rules.dedup();
            let inside = |a: u32| local.get(&a).filter(|&&(c, _)| c == k).map(|&(_, i)| i);
            let rules = rules
                .into_iter()
                .map(|ri| {
                    let r = p.rules.get(ri as usize);
                    let mut heads: Vec<u32> = r.head.iter().filter_map(|&h| inside(h)).collect();
                    heads.sort_unstable();
                    heads.dedup();
                    let other_heads = r
                        .head
                        .iter()
                        .filter(|&&h| inside(h).is_none())
                        .map(|&h| self.atom_lit[h as usize])
                        .collect();
                    let body = match r.body {
                        BodyRef::Normal(ls) => {
                            let mut internal = Vec::new();
                            let mut fixed = Vec::new();
                            for &l in ls {
                                match inside(l.unsigned_abs()).filter(|_| l > 0) {
                                    Some(i) => internal.push(i),
                                    None => fixed.push(self.lit(l)),
                                }
                            }
                            StabilityBody::Normal { internal, fixed }
                        }
                        BodyRef::Weight { lower, lits } => StabilityBody::Weight {
                            lower,
                            lits: lits
                                .iter()
                                .filter(|&&(_, w)| w != 0)
                                .map(|&(l, w)| {
                                    let at = inside(l.unsigned_abs()).filter(|_| l > 0 && w > 0);
                                    (self.lit(l), w, at)
                                })
                                .collect(),
                        },
                    };
                    StabilityRule {
                        choice: r.head_kind == HeadKind::Choice,
                        heads,
                        other_heads,
                        body_lit: self.rule_body[ri as usize],
                        body,
                    }
                })
                .collect();
            let atoms = list.iter().map(|&a| self.atom_lit[a as usize]).collect();
            out.push(StabilityComponent { atoms, rules });
        }
        Some(out)
    }
}

/// The strongly connected components of the positive dependency graph.
pub(super) struct Cycles {
    /// Per atom: its component.
    pub(super) comp: Vec<u32>,
    /// Per atom: on a positive cycle (its component has two or more atoms, or a self-loop);
    /// index 0 (the constant true) never is.
    pub(super) cyclic: Vec<bool>,
}

impl Cycles {
    /// The components of `p`'s positive dependency graph over atoms `0..n`; `visit` sees
    /// every rule and its index on the way. The graph is freed on return: it is as large as
    /// the program's positive dependencies.
    pub(super) fn of(
        p: &GroundProgram,
        n: usize,
        visit: impl FnMut(usize, &RuleRef<'_>),
    ) -> Cycles {
        let edges = positive_edges(p, n, visit);
        let comp = scc(&edges);
        let mut size = vec![0u32; n];
        for &c in &comp {
            size[c as usize] += 1;
        }
        let cyclic = (0..n)
            .map(|a| {
                a > 0
                    && (size[comp[a] as usize] > 1
                        || edges.succ(a).iter().any(|&b| b as usize == a))
            })
            .collect();
        Cycles { comp, cyclic }
    }
}

/// The positive dependency graph: per atom, the atoms of positive body literals (positive
/// weights) of its rules. `visit` sees every rule and its index, in the first of the two
/// passes over the rules.
fn positive_edges(
    p: &GroundProgram,
    n: usize,
    mut visit: impl FnMut(usize, &RuleRef<'_>),
) -> Graph {
    let positive = |r: &RuleRef<'_>| -> usize {
        if r.head.is_empty() {
            // Integrity constraints (most rules of some programs) give no edge.
            return 0;
        }
        match r.body {
            BodyRef::Normal(ls) => ls.iter().filter(|&&l| l > 0).count(),
            BodyRef::Weight { lits, .. } => lits.iter().filter(|&&(l, w)| l > 0 && w > 0).count(),
        }
    };
    // Two passes (count, then fill) into one flat array: a `Vec` per atom cost 24 bytes of
    // header per atom even for the many atoms without edges.
    // The second pass visits only the rules with edges, noted in the first.
    let mut first = vec![0usize; n + 1];
    let mut with_edges: Vec<u32> = Vec::new();
    for (i, r) in p.rules.iter().enumerate() {
        visit(i, &r);
        let k = positive(&r);
        if k > 0 {
            with_edges.push(i as u32);
            for &h in r.head {
                first[h as usize + 1] += k;
            }
        }
    }
    for a in 0..n {
        first[a + 1] += first[a];
    }
    let mut fill = first.clone();
    let mut targets = vec![0u32; first[n]];
    for &i in &with_edges {
        let r = p.rules.get(i as usize);
        for &h in r.head {
            let at = &mut fill[h as usize];
            let mut put = |b: u32| {
                targets[*at] = b;
                *at += 1;
            };
            match r.body {
                BodyRef::Normal(ls) => ls.iter().filter(|&&l| l > 0).for_each(|&l| put(l as u32)),
                BodyRef::Weight { lits, .. } => lits
                    .iter()
                    .filter(|&&(l, w)| l > 0 && w > 0)
                    .for_each(|&(l, _)| put(l as u32)),
            }
        }
    }
    Graph { first, targets }
}
