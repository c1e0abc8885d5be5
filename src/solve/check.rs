//! An independent stable-model checker: given a ground program and a candidate set of true
//! atoms, decide whether the candidate is a stable model, and explain why not.
//!
//! It shares no code with the search (only the `GroundProgram` type), so it can vouch for every
//! model the solver reports (`--check`, and the solver's tests).
//!
//! Semantics (Gelfond-Lifschitz reduct, extended to choice rules and weight bodies as in
//! lparse/clasp, Simons, Niemelä, Soininen 2002): X is a stable model of P iff X is a model of P
//! and X is a minimal model of the reduct P^X, where
//! - a rule whose normal body has a negative literal `not a` with `a` in X is removed, and the
//!   remaining negative literals are dropped;
//! - a weight body `lower { l1 = w1, .. }` keeps its positive literals and its bound decreases by
//!   the weights of the negative literals true in X (so it is monotone in the positive part);
//! - a choice rule `{h1..hn} :- B` becomes `hi :- B^X` for each `hi` in X;
//! - a disjunctive rule keeps its head; constraints never matter for minimality (X satisfies
//!   them, so no subset of X violates their reduct).
//!
//! Edge directives (statement 8) are acyclicity constraints, as in clasp: the edges whose
//! conditions hold must not form a cycle. Heuristics, projections and outputs do not matter.
//!
//! Externals (statement 5): `Free` ones are free choices (as `{a}.`); `True` and `False` ones are
//! free choices that the candidate must also assign as given; `Release`d ones are ordinary atoms.
//! The last external statement for an atom wins. As in clasp, an external statement on an atom
//! that occurs in some rule head is ignored: the rules define the atom (`#external a. a :- b.`
//! has the answer sets of `a :- b.`). Assumptions must hold in the candidate.
//!
//! Algorithm: (1) every rule is checked to be satisfied by X; (2) the least model L of the
//! reduct, with each disjunctive head cut to its atoms in X, is computed with counters in linear
//! time, and X must equal L when every applicable disjunction has at most one true head atom
//! (head-cycle-free reasoning: a subset of X satisfies such a rule iff it satisfies `h :- B+`);
//! (3) otherwise a branching fixpoint looks for a model of the reduct strictly inside X
//! (exponential only in the number of disjunctions with several true head atoms).
//!
//! Invariant: `check` never panics on any program and candidate (atoms out of range are a
//! `Violation`), and never reports a stable model as a violation.

use thiserror::Error;

use crate::ground::program::{Atom, BodyRef, ExternalValue, GroundProgram, HeadKind, Lit};

/// Why a candidate is not a stable model.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum Violation {
    /// The candidate names an atom outside `1..=num_atoms`.
    #[error("atom {0} is not an atom of the program")]
    UnknownAtom(Atom),
    /// A disjunctive rule's body holds but none of its head atoms does (for a constraint: its
    /// body holds). Choice rules are always satisfied.
    #[error("rule {rule} is violated: its body holds but its head does not")]
    RuleViolated {
        /// Index into `GroundProgram::rules`.
        rule: usize,
    },
    /// An external atom with a fixed value has the other value in the candidate.
    #[error("external atom {atom} must be {value:?}")]
    ExternalValue {
        /// The atom.
        atom: Atom,
        /// Its fixed value.
        value: ExternalValue,
    },
    /// An assumption (aspif statement 6) is false in the candidate.
    #[error("assumption {0} does not hold")]
    Assumption(Lit),
    /// The edges (aspif statement 8) whose conditions hold form a cycle through this node.
    #[error("the edges whose conditions hold form a cycle through node {node}")]
    Cycle {
        /// A node on the cycle.
        node: i32,
    },
    /// True atoms that the reduct does not derive (unfounded: no well-founded support).
    #[error("atoms {atoms:?} are true but unsupported (not in the least model of the reduct)")]
    Unsupported {
        /// The unsupported atoms, sorted.
        atoms: Vec<Atom>,
    },
    /// A model of the reduct strictly inside the candidate exists (disjunctive programs).
    #[error("not minimal: {smaller:?} is a smaller model of the reduct")]
    NotMinimal {
        /// The smaller model, sorted.
        smaller: Vec<Atom>,
    },
}

/// Checks that `true_atoms` (in any order, duplicates allowed) is a stable model of `program`.
pub fn check(program: &GroundProgram, true_atoms: &[Atom]) -> Result<(), Violation> {
    let n = program.num_atoms as usize;
    let mut truth = vec![false; n + 1];
    for &a in true_atoms {
        if a == 0 || a as usize > n {
            return Err(Violation::UnknownAtom(a));
        }
        truth[a as usize] = true;
    }
    check_assignment(program, &truth)
}

/// Like [`check`], with the candidate as a truth vector indexed by atom (index 0 unused, length
/// `num_atoms + 1`).
pub fn check_assignment(program: &GroundProgram, truth: &[bool]) -> Result<(), Violation> {
    assert_eq!(
        truth.len(),
        program.num_atoms as usize + 1,
        "the truth vector must have num_atoms + 1 entries"
    );
    // A program that breaks its own invariant (an atom above `num_atoms`) is checked as if
    // `num_atoms` were large enough, with the extra atoms false, rather than panicking.
    let n = (program.num_atoms as usize).max(largest_atom(program));
    let extended: Vec<bool>;
    let truth = if truth.len() <= n {
        extended = truth
            .iter()
            .copied()
            .chain(std::iter::repeat(false))
            .take(n + 1)
            .collect();
        &extended[..]
    } else {
        truth
    };
    let holds = |l: Lit| {
        let a = l.unsigned_abs() as usize;
        let v = a <= n && truth[a];
        if l > 0 {
            v
        } else {
            !v
        }
    };
    let body_holds = |body: BodyRef<'_>| match body {
        BodyRef::Normal(lits) => lits.iter().all(|&l| holds(l)),
        BodyRef::Weight { lower, lits } => {
            let sum: i128 = lits
                .iter()
                .filter(|(l, _)| holds(*l))
                .map(|&(_, w)| i128::from(w))
                .sum();
            sum >= i128::from(lower)
        }
    };

    // (1) X is a model of P, of the external values and of the assumptions.
    for (i, rule) in program.rules.iter().enumerate() {
        if rule.head_kind == HeadKind::Disjunction
            && body_holds(rule.body)
            && !rule.head.iter().any(|&h| holds(h as Lit))
        {
            return Err(Violation::RuleViolated { rule: i });
        }
    }
    let externals = external_values(program);
    for &(atom, value) in &externals {
        let ok = match value {
            ExternalValue::True => holds(atom as Lit),
            ExternalValue::False => !holds(atom as Lit),
            ExternalValue::Free | ExternalValue::Release => true,
        };
        if !ok {
            return Err(Violation::ExternalValue { atom, value });
        }
    }
    for &l in &program.assumptions {
        if !holds(l) {
            return Err(Violation::Assumption(l));
        }
    }

    let edges: Vec<(i32, i32)> = program
        .edges
        .iter()
        .filter(|e| e.condition.iter().all(|&l| holds(l)))
        .map(|e| (e.from, e.to))
        .collect();
    if let Some(node) = find_cycle(&edges) {
        return Err(Violation::Cycle { node });
    }

    // (2) The reduct, with heads cut to X.
    let mut reduct = Reduct::new(n);
    let mut branching = false;
    for &(atom, value) in &externals {
        if value != ExternalValue::Release && holds(atom as Lit) {
            reduct.add(vec![atom], false, 0, &[]);
        }
    }
    let mut pos: Vec<(Atom, i128)> = Vec::new();
    for rule in &program.rules {
        let heads: Vec<Atom> = rule
            .head
            .iter()
            .copied()
            .filter(|&h| holds(h as Lit))
            .collect();
        if heads.is_empty() {
            continue;
        }
        pos.clear();
        let lower = match rule.body {
            BodyRef::Normal(lits) => {
                if lits.iter().any(|&l| l < 0 && !holds(l)) {
                    continue;
                }
                pos.extend(lits.iter().filter(|&&l| l > 0).map(|&l| (l as Atom, 1)));
                pos.len() as i128
            }
            BodyRef::Weight { lower, lits } => {
                // A negative weight w on l is the weight -w on the complement of l with the
                // bound raised by -w, so that the positive part stays monotone.
                let mut bound = i128::from(lower);
                for &(l, w) in lits {
                    let (l, w) = if w < 0 {
                        bound -= i128::from(w);
                        (-l, -i128::from(w))
                    } else {
                        (l, i128::from(w))
                    };
                    if l < 0 {
                        if holds(l) {
                            bound -= w;
                        }
                    } else {
                        pos.push((l as Atom, w));
                    }
                }
                bound
            }
        };
        let disjunctive = rule.head_kind == HeadKind::Disjunction && heads.len() > 1;
        branching |= disjunctive;
        reduct.add(heads, disjunctive, lower, &pos);
    }

    let least = reduct.least_model();
    let unsupported: Vec<Atom> = (1..=n as Atom)
        .filter(|&a| truth[a as usize] && !least.contains(a))
        .collect();
    if !unsupported.is_empty() {
        return Err(Violation::Unsupported { atoms: unsupported });
    }
    if !branching {
        return Ok(());
    }

    // (3) Search for a model of the reduct strictly inside X.
    let size = truth.iter().filter(|&&t| t).count();
    match reduct.smaller_model(size) {
        Some(smaller) => Err(Violation::NotMinimal { smaller }),
        None => Ok(()),
    }
}

/// The largest atom in the rules and external statements of `program`.
fn largest_atom(program: &GroundProgram) -> usize {
    let mut m = 0;
    for rule in &program.rules {
        m = rule.head.iter().fold(m, |m, &a| m.max(a));
        m = match rule.body {
            BodyRef::Normal(lits) => lits.iter().fold(m, |m, &l| m.max(l.unsigned_abs())),
            BodyRef::Weight { lits, .. } => {
                lits.iter().fold(m, |m, &(l, _)| m.max(l.unsigned_abs()))
            }
        };
    }
    m = program.externals.iter().fold(m, |m, &(a, _)| m.max(a));
    m as usize
}

/// A node on a cycle of the directed graph `edges`, if it has one (iterative depth-first
/// search with three colours).
fn find_cycle(edges: &[(i32, i32)]) -> Option<i32> {
    let mut nodes: Vec<i32> = edges.iter().flat_map(|&(u, v)| [u, v]).collect();
    nodes.sort_unstable();
    nodes.dedup();
    let index = |v: i32| nodes.binary_search(&v).unwrap_or(0);
    let mut succ = vec![Vec::new(); nodes.len()];
    for &(u, v) in edges {
        succ[index(u)].push(index(v));
    }
    // 0 unvisited, 1 on the stack, 2 done.
    let mut colour = vec![0u8; nodes.len()];
    for root in 0..nodes.len() {
        if colour[root] != 0 {
            continue;
        }
        let mut stack = vec![(root, 0usize)];
        colour[root] = 1;
        while let Some(&mut (v, ref mut next)) = stack.last_mut() {
            if let Some(&w) = succ[v].get(*next) {
                *next += 1;
                match colour[w] {
                    0 => {
                        colour[w] = 1;
                        stack.push((w, 0));
                    }
                    1 => return Some(nodes[w]),
                    _ => {}
                }
            } else {
                colour[v] = 2;
                stack.pop();
            }
        }
    }
    None
}

/// The effective value of each external atom without rules (the last statement for an atom
/// wins), in order of first statement.
pub fn external_values(program: &GroundProgram) -> Vec<(Atom, ExternalValue)> {
    let mut defined = std::collections::HashSet::new();
    for rule in &program.rules {
        defined.extend(rule.head.iter().copied());
    }
    let mut values: Vec<(Atom, ExternalValue)> = Vec::new();
    let mut seen = std::collections::HashMap::new();
    for &(atom, value) in program
        .externals
        .iter()
        .filter(|(a, _)| !defined.contains(a))
    {
        match seen.get(&atom) {
            Some(&i) => values[i] = (atom, value),
            None => {
                seen.insert(atom, values.len());
                values.push((atom, value));
            }
        }
    }
    values
}

/// One rule of the reduct: `heads :- lower <= sum of weights of true positive atoms`, or
/// `h1 | .. | hk :- ..` when `disjunctive`.
struct ReductRule {
    heads: Vec<Atom>,
    disjunctive: bool,
    lower: i128,
}

/// The reduct as counters: for each atom, the rules where it occurs positively, with weights.
struct Reduct {
    rules: Vec<ReductRule>,
    occurs: Vec<Vec<(u32, i128)>>,
}

/// A partial fixpoint: the atoms derived so far and each rule's remaining bound.
#[derive(Clone)]
struct State {
    derived: Vec<bool>,
    count: usize,
    remaining: Vec<i128>,
    fired: Vec<bool>,
}

impl State {
    fn new(reduct: &Reduct) -> State {
        State {
            derived: vec![false; reduct.occurs.len()],
            count: 0,
            remaining: reduct.rules.iter().map(|r| r.lower).collect(),
            fired: vec![false; reduct.rules.len()],
        }
    }

    fn contains(&self, a: Atom) -> bool {
        self.derived[a as usize]
    }
}

impl Reduct {
    fn new(n: usize) -> Reduct {
        Reduct {
            rules: Vec::new(),
            occurs: vec![Vec::new(); n + 1],
        }
    }

    fn add(&mut self, heads: Vec<Atom>, disjunctive: bool, lower: i128, pos: &[(Atom, i128)]) {
        let id = self.rules.len() as u32;
        for &(a, w) in pos {
            self.occurs[a as usize].push((id, w));
        }
        self.rules.push(ReductRule {
            heads,
            disjunctive,
            lower,
        });
    }

    /// The least model of the reduct with every disjunctive rule deriving all its heads (the
    /// over-approximation of step 2).
    fn least_model(&self) -> State {
        let mut state = State::new(self);
        self.propagate(&mut state, &mut Vec::new(), false);
        state
    }

    /// Runs the fixpoint. Precondition: `state`'s counters are fresh (`State::new`, or reset)
    /// and its `derived` atoms are seeds still to be counted. With `branch`, a disjunctive rule
    /// whose body holds derives nothing and is collected in `open` for a branching decision.
    fn propagate(&self, state: &mut State, open: &mut Vec<u32>, branch: bool) {
        let mut queue: Vec<Atom> = (1..state.derived.len() as Atom)
            .filter(|&a| state.derived[a as usize])
            .collect();
        let fire = |state: &mut State, r: usize, queue: &mut Vec<Atom>, open: &mut Vec<u32>| {
            if std::mem::replace(&mut state.fired[r], true) {
                return;
            }
            let rule = &self.rules[r];
            if branch && rule.disjunctive {
                open.push(r as u32);
                return;
            }
            for &h in &rule.heads {
                if !std::mem::replace(&mut state.derived[h as usize], true) {
                    state.count += 1;
                    queue.push(h);
                }
            }
        };
        for r in 0..self.rules.len() {
            if state.remaining[r] <= 0 {
                fire(state, r, &mut queue, open);
            }
        }
        let mut counted = vec![false; state.derived.len()];
        while let Some(a) = queue.pop() {
            if std::mem::replace(&mut counted[a as usize], true) {
                continue;
            }
            for &(r, w) in &self.occurs[a as usize] {
                let r = r as usize;
                state.remaining[r] -= w;
                if state.remaining[r] <= 0 {
                    fire(state, r, &mut queue, open);
                }
            }
        }
    }

    /// Looks for a model of the reduct with fewer than `size` atoms, branching on which head
    /// atom of each applicable disjunction to derive. Every model of the reduct inside X
    /// contains the result of some branch, and every branch ends in a model of the reduct, so
    /// X is minimal iff every branch ends with all of X.
    fn smaller_model(&self, size: usize) -> Option<Vec<Atom>> {
        let mut root = State::new(self);
        let mut open = Vec::new();
        self.propagate(&mut root, &mut open, true);
        let mut stack = vec![(root, open)];
        while let Some((state, open)) = stack.pop() {
            if state.count >= size {
                continue;
            }
            let pending = open.iter().copied().find(|&r| {
                !self.rules[r as usize]
                    .heads
                    .iter()
                    .any(|&h| state.derived[h as usize])
            });
            let Some(r) = pending else {
                let atoms = (1..state.derived.len() as Atom).filter(|&a| state.derived[a as usize]);
                return Some(atoms.collect());
            };
            for &h in &self.rules[r as usize].heads {
                // Derive h and recount every derived atom from fresh counters.
                let mut next = State::new(self);
                next.derived.clone_from(&state.derived);
                next.count = state.count;
                if !std::mem::replace(&mut next.derived[h as usize], true) {
                    next.count += 1;
                }
                let mut next_open = Vec::new();
                self.propagate(&mut next, &mut next_open, true);
                stack.push((next, next_open));
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::program::Rule;

    #[test]
    fn positive_loop_is_unsupported() {
        // a :- b. b :- a.  The only stable model is {}; {a, b} is a model but unfounded.
        let p = GroundProgram {
            num_atoms: 2,
            rules: vec![Rule::normal(&[1], &[2]), Rule::normal(&[2], &[1])].into(),
            ..Default::default()
        };
        assert_eq!(check(&p, &[]), Ok(()));
        assert_eq!(
            check(&p, &[1, 2]),
            Err(Violation::Unsupported { atoms: vec![1, 2] })
        );
    }
}
