//! Well-founded supports of an answer set, computed bottom-up (the proofs of `lucent explain
//! --why` on any program): every true atom gets the rule instance that first founded it, in the
//! order a least-fixpoint computation over the model's true rule bodies reaches the atoms, and
//! a proof tree is read off those supports.
//!
//! How: the atoms of the ground program and the grounder's own facts are numbered densely
//! (an aspif atom `a` is `a`; a grounder fact with no aspif atom is `aspif count + g`). Each rule
//! instance (a ground rule with one provenance origin) whose head is true and whose body holds in
//! the model waits for its positive body atoms, counted; the atoms are founded level by level
//! (a bucket queue), so an atom's level is the least height of a proof of it, and its support is
//! an instance of that height. The work is linear in the size of the ground program.
//!
//! Invariants: a support's positive body atoms all have smaller levels than its head (so the
//! proof tree built from supports is acyclic, no literal repeats on a path, and each literal is
//! one node, shared where proofs meet); a tree is only returned when every node's rule instance
//! comes from `ProgramOracle::instance`, so `tree::recheck` checks it as any other tree. Atoms
//! this does not found (bodies with weight constraints, which it does not count) get `None`,
//! and the caller falls back to the search of `explain::build`.

use std::collections::HashMap;

use super::build::classify;
use super::oracle::{ProgramOracle, Source};
use super::tree::{BodyLiteral, Node, NodeId, ProofTree, RuleInstance, MAX_BRANCHES};
use crate::control::Symbol;
use crate::ground::program::{AtomStatus, AuxKind, BodyRef, GAtom, RuleOrigin};

/// No level yet.
const UNFOUNDED: u32 = u32::MAX;
/// The support of a grounder fact that has no rule in the ground program.
const BARE_FACT: u32 = u32::MAX;

/// The id of grounder atom `g`: its aspif atom, else a slot of its own after the aspif atoms.
fn g_id(o: &ProgramOracle, aspif_slots: usize, g: GAtom) -> usize {
    match o.ctl.program().provenance.atom(g) {
        Some(r) if r.aspif != 0 => r.aspif as usize,
        _ => aspif_slots + g as usize,
    }
}

/// The founding level and support of every atom of one answer set.
pub(super) struct Supports {
    /// Number of aspif atom slots (`atom_term.len()`): grounder-only atoms start here.
    aspif_slots: usize,
    /// Level per atom id, [`UNFOUNDED`] when not founded.
    level: Vec<u32>,
    /// The founding instance per atom id (index into `source`), or [`BARE_FACT`].
    chosen: Vec<u32>,
    /// Each instance's ground rule and origin.
    source: Vec<(u32, u32)>,
}

impl Supports {
    /// Computes the supports of the oracle's answer set.
    pub(super) fn new(o: &ProgramOracle) -> Supports {
        let prog = o.ctl.program();
        let prov = &prog.provenance;
        let aspif_slots = o.atom_term.len();
        let n = aspif_slots + prov.atoms.len() + 1;
        let mut truth = vec![false; n];
        for &a in &o.model.atoms {
            if let Some(t) = truth.get_mut(a as usize) {
                *t = true;
            }
        }
        let g_id: Vec<usize> = (1..=prov.atoms.len())
            .map(|g| g_id(o, aspif_slots, g as GAtom))
            .collect();
        let mut level = vec![UNFOUNDED; n];
        let mut chosen = vec![UNFOUNDED; n];
        let mut bare = Vec::new();
        for (i, r) in prov.atoms.iter().enumerate() {
            if r.aspif == 0 && r.status == AtomStatus::Fact {
                truth[g_id[i]] = true;
                bare.push(g_id[i]);
            }
        }
        let cr_atoms: hashbrown::HashSet<u32> = prog.cr_rules.iter().map(|c| c.appl).collect();

        // The instances whose head is true and whose body holds, with their positive atoms.
        let mut source: Vec<(u32, u32)> = Vec::new();
        let mut head: Vec<u32> = Vec::new();
        let mut missing: Vec<u32> = Vec::new();
        let mut watch_pairs: Vec<(u32, u32)> = Vec::new();
        let mut pos: Vec<usize> = Vec::new();
        for (i, r) in prog.rules.iter().enumerate() {
            if r.head.is_empty() {
                continue;
            }
            let BodyRef::Normal(lits) = r.body else {
                continue;
            };
            let appl = o.cr_appl.get(&(i as u32)).copied();
            if appl.is_some_and(|a| !truth[a as usize]) {
                continue;
            }
            pos.clear();
            let mut holds = true;
            for &l in lits {
                let a = l.unsigned_abs();
                if Some(a) == appl && l > 0 {
                    continue;
                }
                let t = truth.get(a as usize).copied().unwrap_or(false);
                if (l > 0) != t {
                    holds = false;
                    break;
                }
                if l > 0 {
                    pos.push(a as usize);
                }
            }
            if !holds {
                continue;
            }
            let origins = prov.origins(i);
            let count = origins.len().max(1);
            for k in 0..count {
                let base = pos.len();
                if let Some(origin) = origins.get(k) {
                    if matches!(
                        origin.rule,
                        RuleOrigin::Auxiliary {
                            kind: AuxKind::CrApplication,
                            ..
                        }
                    ) {
                        continue;
                    }
                    for rl in &origin.removed {
                        if rl.positive {
                            if let Some(&id) = g_id.get((rl.atom as usize).wrapping_sub(1)) {
                                pos.push(id);
                            }
                        }
                    }
                }
                for &h in r.head {
                    if !truth.get(h as usize).copied().unwrap_or(false) || cr_atoms.contains(&h) {
                        continue;
                    }
                    let inst = source.len() as u32;
                    source.push((i as u32, k as u32));
                    head.push(h);
                    missing.push(pos.len() as u32);
                    watch_pairs.extend(pos.iter().map(|&b| (b as u32, inst)));
                }
                pos.truncate(base);
            }
        }
        // Watchers in compressed rows: the instances waiting for each atom.
        let mut start = vec![0u32; n + 1];
        for &(b, _) in &watch_pairs {
            start[b as usize + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut watchers = vec![0u32; watch_pairs.len()];
        for &(b, inst) in &watch_pairs {
            watchers[fill[b as usize] as usize] = inst;
            fill[b as usize] += 1;
        }
        drop(watch_pairs);

        // Found level by level. Instances with no positive body start at level 0; the bare facts are founded at level
        // 0 after them, so an instance they complete waits for level 1.
        let mut buckets: Vec<Vec<u32>> = vec![(0..missing.len() as u32)
            .filter(|&i| missing[i as usize] == 0)
            .collect()];
        let mut found = |id: usize,
                         by: u32,
                         lvl: u32,
                         level: &mut Vec<u32>,
                         buckets: &mut Vec<Vec<u32>>,
                         missing: &mut Vec<u32>| {
            if level[id] != UNFOUNDED {
                return;
            }
            level[id] = lvl;
            chosen[id] = by;
            for &w in &watchers[start[id] as usize..start[id + 1] as usize] {
                missing[w as usize] -= 1;
                if missing[w as usize] == 0 {
                    if buckets.len() <= lvl as usize + 1 {
                        buckets.push(Vec::new());
                    }
                    buckets[lvl as usize + 1].push(w);
                }
            }
        };
        for id in bare {
            found(id, BARE_FACT, 0, &mut level, &mut buckets, &mut missing);
        }
        let mut lvl = 0;
        while lvl < buckets.len() {
            let now = std::mem::take(&mut buckets[lvl]);
            for inst in now {
                let h = head[inst as usize] as usize;
                found(h, inst, lvl as u32, &mut level, &mut buckets, &mut missing);
            }
            lvl += 1;
        }
        Supports {
            aspif_slots,
            level,
            chosen,
            source,
        }
    }

    /// The id of a named atom, if the program has it.
    fn id_of(&self, o: &ProgramOracle, t: &Symbol) -> Option<usize> {
        if let Some(&a) = o.term_atom.get(t) {
            return Some(a as usize);
        }
        let &g = o.term_g.get(t)?;
        Some(g_id(o, self.aspif_slots, g))
    }

    fn founded(&self, id: usize) -> bool {
        self.level.get(id).is_some_and(|&l| l != UNFOUNDED)
    }

    /// The rule instance that founded an atom.
    fn instance(&self, o: &ProgramOracle, id: usize, t: &Symbol) -> Option<RuleInstance> {
        let by = self.chosen[id];
        if by == BARE_FACT {
            use super::tree::Oracle;
            return o
                .rules_for(t)
                .into_iter()
                .find(|r| r.body.iter().all(|b| matches!(b, BodyLiteral::Test(_))));
        }
        let (rule, origin) = self.source[by as usize];
        o.instance(t, Source::Ground { rule, origin })
    }

    /// The proof tree of a true atom from its supports: one node per literal, children before
    /// parents, the path following first children down to a leaf. `None` when the atom (or an
    /// atom of its proof) was not founded here.
    pub(super) fn tree(&self, o: &ProgramOracle, literal: &Symbol) -> Option<ProofTree> {
        let root = self.id_of(o, literal)?;
        if !self.founded(root) {
            return None;
        }
        let mut tree = ProofTree::default();
        let mut done: HashMap<usize, NodeId> = HashMap::new();
        // Iterative post-order: (id, node without children, children, next child to visit).
        type Frame = (usize, Node, Vec<(usize, Symbol)>, usize);
        let open = |id: usize, t: Symbol| -> Option<Frame> {
            let rule = self.instance(o, id, &t)?;
            let kind = classify(&t, &rule);
            let mut kids: Vec<(usize, Symbol)> = Vec::new();
            if !kind.is_leaf_kind() {
                for b in rule.positive() {
                    let c = self.id_of(o, b)?;
                    if !self.founded(c) || self.level[c] >= self.level[id] {
                        return None;
                    }
                    if !kids.iter().any(|(k, _)| *k == c) && kids.len() < MAX_BRANCHES {
                        kids.push((c, b.clone()));
                    }
                }
            }
            Some((id, Node::supported(t, kind, rule), kids, 0))
        };
        let mut stack: Vec<Frame> = vec![open(root, literal.clone())?];
        while let Some(top) = stack.last_mut() {
            if let Some((c, t)) = top.2.get(top.3).cloned() {
                top.3 += 1;
                if !done.contains_key(&c) {
                    stack.push(open(c, t)?);
                }
                continue;
            }
            let (id, mut node, kids, _) = stack.pop().expect("non-empty");
            node.children = kids.iter().map(|(c, _)| done[c]).collect();
            done.insert(id, tree.add(node));
        }
        let r = done[&root];
        tree.roots = vec![r];
        let mut at = r;
        tree.path.push(at);
        while let Some(&c) = tree.node(at).children.first() {
            at = c;
            tree.path.push(at);
        }
        Some(tree)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::SourceMap;
    use crate::control::{Control, ControlConfig, Part, SolveOptions};
    use crate::explain::oracle::Labels;
    use crate::explain::tree::Oracle;
    use crate::syntax::ast::Dialect;

    /// The oracle of `text`'s first answer set.
    fn oracle(text: &str) -> ProgramOracle {
        let mut sources = SourceMap::new();
        let id = sources.add("t.lp", text);
        let parse = crate::syntax::parse(id, text, Dialect::Clingo);
        assert!(parse.diagnostics.is_empty());
        let labels = Labels::from_program(&parse.program, &|s| sources.location(s.span));
        let mut config = ControlConfig::default();
        config.ground.provenance = true;
        let mut ctl = Control::with_sources(config, sources.clone());
        ctl.add_program(parse.program).unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        let mut model = None;
        ctl.solve(&SolveOptions::default(), |m| {
            model = Some(m.raw().clone());
            false
        });
        ProgramOracle::new(ctl, model.unwrap(), labels).unwrap()
    }

    fn sym(s: &str) -> Symbol {
        crate::control::Symbol::parse(s).unwrap()
    }

    /// Every atom is founded above the atoms of its positive body, facts included, so the proof
    /// of `d` runs down through `b` and `a` to the fact `e(1)`.
    #[test]
    fn a_rule_on_facts_is_founded_above_them() {
        let o = oracle("e(1). a :- e(1). {c}. b :- a, not c. d :- b, not c.");
        assert!(!o.holds(&sym("c")), "the first answer set has no c");
        let s = Supports::new(&o);
        let tree = s
            .tree(&o, &sym("d"))
            .expect("a proof of d from the supports");
        let root = &tree.nodes[tree.roots[0].index()];
        assert_eq!(root.literal, sym("d"));
        let b = &tree.nodes[root.children[0].index()];
        assert_eq!(b.literal, sym("b"));
        assert!(b
            .children
            .iter()
            .any(|c| tree.nodes[c.index()].literal == sym("a")));
    }

    /// A chain's proof has one node per literal and its full depth (no depth cap).
    #[test]
    fn a_long_chain_is_proved_in_full() {
        let mut text = String::from("{x}. p(0) :- not x.\n");
        text.push_str("p(N+1) :- p(N), N < 200, not x.\n");
        let o = oracle(&text);
        let s = Supports::new(&o);
        let tree = s.tree(&o, &sym("p(200)")).expect("a proof of p(200)");
        let mut depth = 0;
        let mut n = tree.roots[0];
        while let Some(&c) = tree.nodes[n.index()]
            .children
            .iter()
            .find(|c| tree.nodes[c.index()].literal.to_string().starts_with("p("))
        {
            depth += 1;
            n = c;
        }
        assert_eq!(depth, 200);
    }
}
