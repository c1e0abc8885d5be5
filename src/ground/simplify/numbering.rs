//! The aspif numbering of the output: atoms numbered in order of first occurrence in the
//! output rules, heads before bodies, normal bodies ordered as gringo prints them. The
//! numbering is the solver's initial variable order, so it follows gringo's to make search on
//! our ground program behave as on gringo's.
//!
//! Invariant: numbers are `1..=next`, given once each, and `atom_syms`/`atom_gatoms` are
//! indexed by number minus one.

use super::scope::Scope;
use super::{shown_pred, Status};
use crate::ground::instantiate::{AtomInfo, GroundAtom, Grounder};
use crate::ground::program::{Atom, BodyRef, HeadKind, Lit, Minimize, Rules, Weight};
use crate::ground::symbol::SymId;

/// The aspif numbering, made as the output rules are written (gringo's: atoms in order of
/// first occurrence, each rule's heads before its body), and the scratch vectors that write
/// each rule renumbered, so the rules are not passed over again to number and renumber them.
pub(super) struct Numbering {
    /// The aspif number of each grounder atom (0: none yet).
    pub(super) number: Vec<u32>,
    /// The last number given.
    pub(super) next: u32,
    /// The symbol of each numbered atom, by number.
    pub(super) atom_syms: Vec<Option<SymId>>,
    /// The grounder atom of each numbered atom, by number.
    pub(super) atom_gatoms: Vec<GroundAtom>,
    /// Scratch: the head, body and weight body of a rule being written, renumbered.
    head: Vec<Atom>,
    lits: Vec<Lit>,
    wlits: Vec<(Lit, Weight)>,
}

impl Numbering {
    /// A numbering of grounder atoms `1..=n` in `number` (all 0, grown to `n + 1`), with room
    /// for `fresh` numbered atoms (the atoms this grounding added: most of them get a number).
    pub(super) fn new(mut number: Vec<u32>, n: usize, fresh: usize) -> Numbering {
        number.resize(n + 1, 0);
        Numbering {
            number,
            next: 0,
            atom_syms: Vec::with_capacity(fresh),
            atom_gatoms: Vec::with_capacity(fresh),
            head: Vec::new(),
            lits: Vec::new(),
            wlits: Vec::new(),
        }
    }

    /// The number of grounder atom `a`, given now if it has none.
    pub(super) fn assign(&mut self, a: usize, atoms: &[AtomInfo]) -> u32 {
        if a >= self.number.len() {
            self.number.resize(a + 1, 0);
        }
        if self.number[a] == 0 {
            self.next += 1;
            self.number[a] = self.next;
            self.atom_syms.push(atoms[a - 1].sym);
            self.atom_gatoms.push(GroundAtom::new(a as u32));
        }
        self.number[a]
    }

    fn assign_lit(&mut self, l: Lit, atoms: &[AtomInfo]) -> Lit {
        let m = self.assign(l.unsigned_abs() as usize, atoms) as Lit;
        if l < 0 {
            -m
        } else {
            m
        }
    }

    /// Numbers the atoms of a rule over grounder atoms and appends it, renumbered, to `rules`.
    pub(super) fn push(
        &mut self,
        rules: &mut Rules,
        kind: HeadKind,
        head: &[u32],
        body: BodyRef<'_>,
        atoms: &[AtomInfo],
    ) {
        let mut h = std::mem::take(&mut self.head);
        h.clear();
        for &a in head {
            h.push(self.assign(a as usize, atoms));
        }
        match body {
            BodyRef::Normal(ls) => {
                let mut b = std::mem::take(&mut self.lits);
                b.clear();
                for &l in ls {
                    b.push(self.assign_lit(l, atoms));
                }
                rules.push_parts(kind, &h, BodyRef::Normal(&b));
                self.lits = b;
            }
            BodyRef::Weight { lower, lits } => {
                let mut b = std::mem::take(&mut self.wlits);
                b.clear();
                for &(l, w) in lits {
                    b.push((self.assign_lit(l, atoms), w));
                }
                rules.push_parts(kind, &h, BodyRef::Weight { lower, lits: &b });
                self.wlits = b;
            }
        }
        self.head = h;
    }
}

/// Orders a normal body as gringo prints it, into `out`: the positive literals in reverse
/// order of the rule's body, then the negative ones in order. Only the solver's initial
/// variable order depends on it (atoms are numbered by first occurrence).
pub(super) fn gringo_body_order(lits: &[Lit], out: &mut Vec<Lit>) {
    out.clear();
    out.extend(lits.iter().rev().copied().filter(|&l| l > 0));
    out.extend(lits.iter().copied().filter(|&l| l < 0));
}

/// Numbers the atoms no output rule numbered that still need one: those of the minimize
/// statements, externals, shown atoms that are not false and not `frozen`, and (multi-shot)
/// frozen atoms in conditions of shows, heuristics and edges and projected ones. They come in
/// creation order, after the atoms of the rules, as in gringo's output; the solver's initial
/// variable order follows it. Only the atoms of `scope` are visited (every atom a directive
/// names is in it).
#[allow(clippy::too_many_arguments)]
pub(super) fn number_remaining(
    numbering: &mut Numbering,
    g: &Grounder<'_>,
    scope: &Scope,
    status: &[Status],
    minimize: &[Minimize],
    shown: &[bool],
    multi_shot: bool,
    frozen: &dyn Fn(usize) -> bool,
) {
    // Which atoms get a number: every atom that occurs (those of the rules have theirs), and
    // shown atoms.
    // By local index.
    let mut used = vec![false; scope.len()];
    let use_lit =
        |l: Lit, used: &mut Vec<bool>| used[scope.index(l.unsigned_abs() as usize)] = true;
    for m in minimize {
        m.lits.iter().for_each(|&(l, _)| use_lit(l, &mut used));
    }
    for &(a, _) in &g.directives.externals {
        used[scope.index(a.get() as usize)] = true;
    }
    for a in g.directives.theory.atoms.iter().filter_map(|t| t.atom) {
        used[scope.index(a.get() as usize)] = true;
    }
    for (i, &a) in scope.atoms.iter().enumerate() {
        let a = a as usize;
        if frozen(a) {
            continue;
        }
        let info = g.atoms[a - 1];
        if info.sym.is_some()
            && status[a - 1] != Status::False
            && info.in_domain
            && shown_pred(shown, info.pred)
        {
            used[i] = true;
        }
    }
    // Frozen atoms in conditions of shows, heuristics and edges, and projected ones, are
    // possible (a later part may show an atom of an earlier one).
    if multi_shot {
        let mut mark = |l: Lit| {
            let a = l.unsigned_abs() as usize;
            if frozen(a) {
                used[scope.index(a)] = true;
            }
        };
        for (_, cond, _) in &g.directives.shows {
            cond.iter().for_each(|&l| mark(l));
        }
        for h in &g.directives.heuristics {
            mark(h.atom as Lit);
            h.condition.iter().for_each(|&l| mark(l));
        }
        for e in &g.directives.edges {
            e.condition.iter().for_each(|&l| mark(l));
        }
        for &a in &g.directives.projections {
            mark(a.lit());
        }
    }
    // clingo 5.8 projects onto the atoms `#project` statements matched while grounding, before
    // its simplification: when all of them are simplified away it still projects, onto no
    // atom (`{a}. p(1) ; r(1,3). r(1,3). #project p/1.` has one answer set under `--project`,
    // while `{a}. #project p/1.`, with no `p` atom at all, projects onto the shown atoms and
    // has two). So the first projected atom keeps a number then: an atom without rules, false.
    let numbered = |a: GroundAtom| {
        let i = a.get() as usize;
        used[scope.index(i)] || numbering.number.get(i).is_some_and(|&x| x != 0)
    };
    if let Some(&first) = g.directives.projections.first() {
        if !g.directives.projections.iter().any(|&a| numbered(a)) {
            used[scope.index(first.get() as usize)] = true;
        }
    }
    // Numbering as gringo's output does it: atoms in order of first occurrence in the rules
    // (each rule's heads before its body; given as the rules were written), then those only in
    // minimize statements, externals and shown atoms, in creation order. The solver's initial
    // variable order follows it.
    for (&a, _) in scope.atoms.iter().zip(&used).filter(|&(_, &u)| u) {
        numbering.assign(a as usize, &g.atoms);
    }
}
