//! Merging of equivalent atoms before translation (`Config::eq`): atoms equivalent by
//! completion to a literal (`a :- l.` as their only rule) or to a conjunctive body (`a :- B.` as
//! their only rule) are merged with it, as clasp's `--eq` preprocessing does for these cases
//! (`equivalences`): fewer variables, and the heuristic scores one variable instead of two that
//! always agree.
//!
//! Invariants:
//! - A merged atom shares a literal (possibly negated) with another atom, the true literal or
//!   its body; every rule still gets its clauses, so the completion holds over the merged
//!   literals.
//! - Cyclic atoms (positive loops) always have a variable of their own, and no merging happens
//!   for external atoms, disjunctive programs, atoms added by later steps, or onto an atom that
//!   depends positively on an external (a later step could close a cycle through it).

use crate::ground::program::{BodyRef, ExternalValue, GroundProgram, HeadKind, RuleRef};
use crate::solve::engine::Engine;
use crate::solve::lit::Lit;

/// What an atom is known to be equivalent to before translation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Equiv {
    /// Nothing: the atom gets a variable of its own.
    None,
    /// The aspif literal given (0: the constant true): the atom's only rule is `a :- l.` (or
    /// the fact `a.`), so completion makes `a <-> l`, and the atom shares `l`'s literal.
    Lit(i32),
    /// The atom's only rule, this one, is `a :- B.` with `B` a conjunction of two or more
    /// literals: `a <-> B`, and `B` gets the atom's variable.
    Body(usize),
}

/// Finds atoms equivalent to a literal or to a rule body by their completion (clasp's `--eq`
/// for the simplest and most frequent case): the atom is not free, has exactly one rule, that
/// rule is a normal rule with a single head atom and a conjunctive body. Not done for programs
/// with disjunctive heads (the shifted supports and the minimality check keep the plain
/// translation). An alias `a :- b.` to a positive atom of `a`'s own strongly connected
/// component would merge a loop into one variable and lose its unfoundedness, so it is left
/// out; such an atom is cyclic, every other alias target is outside the alias's component,
/// so aliased atoms are never cyclic and every cyclic atom keeps a variable of its own.
/// `comp` gives the component of each atom `0..=n` in the positive dependency graph, `heads`
/// the rules of each atom.
pub(super) fn equivalences(
    n: usize,
    free: &[bool],
    reach: &[bool],
    comp: &[u32],
    heads: &HeadRules,
) -> Vec<Equiv> {
    let mut out = vec![Equiv::None; n + 1];
    if heads.disjunctive {
        return out;
    }
    for a in 1..=n {
        if heads.count[a] != 1 || free[a] {
            continue;
        }
        out[a] = match heads.shape[a] {
            Shape::Other => continue,
            Shape::Fact => Equiv::Lit(0),
            Shape::Lit(l) => {
                let b = l.unsigned_abs() as usize;
                if free[b] || (l > 0 && (comp[b] == comp[a] || reach[b])) {
                    continue;
                }
                Equiv::Lit(l)
            }
            Shape::Body => Equiv::Body(heads.rule[a] as usize),
        };
    }
    out
}

/// The shape of the last rule of an atom, as far as `equivalences` needs it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Shape {
    /// Anything but a normal rule with one head atom and a conjunctive body.
    Other,
    /// `a.`
    Fact,
    /// `a :- l.`
    Lit(i32),
    /// `a :- B.`, `B` of two or more literals.
    Body,
}

/// Per atom, its rules as far as `equivalences` needs them; filled by one `add` per rule (in
/// the pass over the rules that `positive_edges` makes anyway), so that `equivalences` needs
/// no second look at the rules.
pub(super) struct HeadRules {
    /// Per atom: the number of rules with it in the head, counted up to 2.
    count: Vec<u8>,
    /// Per atom: the last rule with it in the head.
    rule: Vec<u32>,
    /// Per atom: the shape of that rule.
    shape: Vec<Shape>,
    /// Whether some rule is a disjunction of two or more atoms.
    disjunctive: bool,
}

impl HeadRules {
    /// No rules yet, for atoms `0..n`.
    pub(super) fn new(n: usize) -> HeadRules {
        HeadRules {
            count: vec![0; n],
            rule: vec![u32::MAX; n],
            shape: vec![Shape::Other; n],
            disjunctive: false,
        }
    }

    /// Records rule `i`, `r`.
    pub(super) fn add(&mut self, i: usize, r: &RuleRef<'_>) {
        if r.head.len() > 1 && r.head_kind == HeadKind::Disjunction {
            self.disjunctive = true;
        }
        let shape = match (r.head_kind, r.head.len(), r.body) {
            (HeadKind::Disjunction, 1, BodyRef::Normal([])) => Shape::Fact,
            (HeadKind::Disjunction, 1, BodyRef::Normal(&[l])) => Shape::Lit(l),
            (HeadKind::Disjunction, 1, BodyRef::Normal(_)) => Shape::Body,
            _ => Shape::Other,
        };
        for &h in r.head {
            let h = h as usize;
            self.count[h] = self.count[h].saturating_add(1).min(2);
            self.rule[h] = i as u32;
            self.shape[h] = shape;
        }
    }
}

/// Per atom: external by the external statements (the last statement on an atom decides, as
/// in `Translation::set_externals`; any value but `Release`).
pub(super) fn external_free(p: &GroundProgram, n: usize) -> Vec<bool> {
    let mut free = vec![false; n + 1];
    for &(a, v) in &p.externals {
        free[a as usize] = v != ExternalValue::Release;
    }
    free
}

/// Per atom: whether a positive path of the dependency graph leads from it to an external
/// atom (`free`). A later step may give such an external rules that close a positive cycle
/// through the atom, so the atom may not share a variable with an atom it depends on.
pub(super) fn reaches_external(p: &GroundProgram, n: usize, free: &[bool]) -> Vec<bool> {
    let mut reach = free.to_vec();
    if !free.iter().any(|&f| f) {
        return reach;
    }
    // Reverse edges (body atom -> head), then a search backwards from the externals.
    let mut rev: Vec<Vec<u32>> = vec![Vec::new(); n + 1];
    for r in p.rules.iter() {
        if r.head.is_empty() {
            continue;
        }
        let mut add = |b: i32| {
            if b > 0 {
                rev[b as usize].extend_from_slice(r.head);
            }
        };
        match r.body {
            BodyRef::Normal(ls) => ls.iter().for_each(|&l| add(l)),
            BodyRef::Weight { lits, .. } => lits
                .iter()
                .filter(|&&(_, w)| w > 0)
                .for_each(|&(l, _)| add(l)),
        }
    }
    let mut stack: Vec<u32> = (0..=n as u32).filter(|&a| free[a as usize]).collect();
    while let Some(x) = stack.pop() {
        for &h in &rev[x as usize] {
            if !reach[h as usize] {
                reach[h as usize] = true;
                stack.push(h);
            }
        }
    }
    reach
}

/// Gives every aliased atom (`Equiv::Lit`) the literal of its target, following chains; an
/// alias cycle (`a :- not b. b :- not a.`) is broken by a fresh variable for one of its atoms,
/// whose rule clauses keep the equivalences.
pub(super) fn resolve_aliases(eqs: &[Equiv], lit: &mut [Option<Lit>], e: &mut Engine) {
    let target = |x: usize| match eqs[x] {
        Equiv::Lit(l) => l,
        _ => unreachable!("only aliases have a target"),
    };
    let mut visiting = vec![false; eqs.len()];
    let mut stack: Vec<usize> = Vec::new();
    for a in 1..eqs.len() {
        if lit[a].is_some() {
            continue;
        }
        stack.clear();
        let mut x = a;
        loop {
            if lit[x].is_some() {
                break;
            }
            if visiting[x] {
                lit[x] = Some(e.new_var().positive());
                break;
            }
            visiting[x] = true;
            stack.push(x);
            x = target(x).unsigned_abs() as usize;
        }
        while let Some(y) = stack.pop() {
            visiting[y] = false;
            if lit[y].is_some() {
                continue;
            }
            let l = target(y);
            let t = lit[l.unsigned_abs() as usize].expect("the chain's end is resolved");
            lit[y] = Some(if l < 0 { !t } else { t });
        }
    }
}
