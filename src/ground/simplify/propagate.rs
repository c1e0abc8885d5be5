//! Propagation of false atoms: decides which atoms are certainly false (no surviving rule can
//! derive them) and which rules are dead, by a worklist over the body occurrences of atoms.
//!
//! Rules implemented:
//! - an atom that is not kept (external, or frozen by an earlier grounding) and heads no live
//!   rule is false;
//! - a rule with a positive body literal over a false atom, or `not a` with `a` a fact, is dead
//!   (a weight body loses the literal's weight and dies once its bound is out of reach);
//! - a disjunctive rule with a fact among its heads (other than the fact's own rule) is dead,
//!   and so is a rule whose body contains a literal and its negation;
//! - the single head of a live normal rule whose body literals are all true (positive ones
//!   over facts, negative ones over false atoms) is a fact, unless kept.
//!
//! The last rule makes the decided atoms a fixpoint whatever the order of the rules: a rule
//! `p :- not q.` grounded before `q`'s only rule `q :- not r.` (with `r` false) is dead here,
//! and `p` false, instead of `p` staying possible with no rule left to derive it.
//!
//! Invariant: each rule is killed at most once and each atom decided (made false or a fact) at
//! most once, so each body occurrence is visited at most once and the pass is linear in the
//! size of the rules.

use super::scope::Scope;
use super::Status;
use crate::ground::instantiate::{GroundAtom, Grounder};
use crate::ground::program::{BodyRef, DeadReason, HeadKind, Lit, Rules};

/// The two passes that build [`Occurrences`]: count, then fill.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Pass {
    Count,
    Fill,
}

/// Body occurrences of atoms by local index `0..n` (see [`Scope`]) in one flat array
/// (compressed rows): the entries of atom `i` are `items[start[i]..start[i + 1]]`, in rule
/// order.
struct Occurrences {
    start: Vec<usize>,
    items: Vec<(u32, i64)>,
}

impl Occurrences {
    fn new(n: usize) -> Occurrences {
        Occurrences {
            start: vec![0; n + 1],
            items: Vec::new(),
        }
    }

    /// Counts (first pass) or places (second pass) one occurrence of the atom of local index
    /// `a`.
    fn add(&mut self, pass: Pass, a: usize, item: (u32, i64)) {
        match pass {
            Pass::Count => self.start[a + 1] += 1,
            Pass::Fill => {
                // During filling, `start[a]` is the next free slot of atom `a`.
                self.items[self.start[a]] = item;
                self.start[a] += 1;
            }
        }
    }

    /// After counting: turns counts into start offsets; after filling: restores them.
    fn end(&mut self, pass: Pass) {
        match pass {
            Pass::Count => {
                for i in 1..self.start.len() {
                    self.start[i] += self.start[i - 1];
                }
                // start[a] is now atom a's first slot, the next free one while filling.
                self.items = vec![(0, 0); *self.start.last().unwrap_or(&0)];
            }
            Pass::Fill => {
                // Each start[a] now holds the end of atom a, which is the start of a + 1.
                self.start.rotate_right(1);
                self.start[0] = 0;
            }
        }
    }

    /// The occurrences of atom `a`.
    fn of(&self, a: usize) -> &[(u32, i64)] {
        &self.items[self.start[a]..self.start[a + 1]]
    }
}

/// Whether a normal body contains a literal and its negation (it can never hold). Only short
/// bodies are checked (quadratic scan, no allocation); missing a long one is only less simple.
pub(super) fn contradictory(body: BodyRef<'_>) -> bool {
    match body {
        BodyRef::Normal(lits) => contradictory_lits(lits),
        BodyRef::Weight { .. } => false,
    }
}

/// [`contradictory`] for a conjunction of literals.
pub(super) fn contradictory_lits(lits: &[Lit]) -> bool {
    lits.len() <= 16
        && lits
            .iter()
            .enumerate()
            .any(|(i, &l)| lits[i + 1..].contains(&-l))
}

/// The false atoms by propagation from `status` (facts known, everything else unknown): marks
/// them in `status` and returns which rules are dead, and whether a rule was killed because its
/// body holds a literal and its negation (only with `kill_contradictory`; gringo keeps such
/// rules, so their heads stay possible for gringo). Atoms with `keep(a)` are never made false.
/// Only the atoms of `scope` are visited (every atom the rules name is in it).
///
/// With `why`, records there why each dead rule died (provenance).
pub(super) fn propagate(
    g: &Grounder<'_>,
    scope: &Scope,
    keep: &dyn Fn(usize) -> bool,
    status: &mut [Status],
    kill_contradictory: bool,
    why: Option<&mut Vec<Option<DeadReason>>>,
) -> (Vec<bool>, bool) {
    let mut no_why = Vec::new();
    let why = match why {
        Some(w) => {
            *w = vec![None; g.rules.len()];
            w
        }
        None => &mut no_why,
    };
    let n = scope.len();
    let mut killed_contradictory = false;
    // By local index.
    let mut head_count = vec![0u32; n];
    // Occurrences in bodies: (rule, weight); weight 0 marks a normal body.
    let mut pos_occ = Occurrences::new(n);
    let mut neg_occ = Occurrences::new(n);
    // For weight bodies: the weight still reachable minus the bound; below 0 the rule is dead.
    let mut slack: Vec<i64> = vec![0; g.rules.len()];
    // For each normal body: how many of its literals are not yet known to hold.
    let mut pending: Vec<u32> = vec![u32::MAX; g.rules.len()];
    // A disjunctive rule with a fact among its heads is satisfied in every model and, by
    // minimality, supports none of its other heads: it is dead from the start (as in gringo),
    // so atoms only it could derive become false. The fact's own rule `a.` is kept. So is a
    // rule whose body holds `a` and `not a` (a weak constraint `:~ r, not r.` costs nothing).
    // Found in the counting pass, killed once the head counts are complete.
    let mut dead_at_start: Vec<(u32, DeadReason)> = Vec::new();
    for pass in [Pass::Count, Pass::Fill] {
        for (ri, r) in g.rules.iter().enumerate() {
            if pass == Pass::Count {
                for &h in r.head {
                    head_count[scope.index(h as usize)] += 1;
                }
                match r.body {
                    BodyRef::Weight { lower, lits } => {
                        slack[ri] = lits.iter().map(|&(_, w)| w).sum::<i64>() - lower;
                    }
                    BodyRef::Normal(lits) => pending[ri] = lits.len() as u32,
                }
                let fact_head = r
                    .head
                    .iter()
                    .copied()
                    .find(|&h| status[h as usize - 1] == Status::Fact);
                let satisfied_head = r.head_kind == HeadKind::Disjunction
                    && fact_head.is_some()
                    && !(r.head.len() == 1 && r.body.is_empty_normal());
                let contra = kill_contradictory && contradictory(r.body);
                killed_contradictory |= contra;
                if satisfied_head || contra {
                    let reason = match fact_head {
                        Some(h) if satisfied_head => DeadReason::HeadFact(h),
                        _ => DeadReason::Contradictory,
                    };
                    dead_at_start.push((ri as u32, reason));
                }
            }
            match r.body {
                BodyRef::Normal(lits) => {
                    for &l in lits {
                        let occ = if l > 0 { &mut pos_occ } else { &mut neg_occ };
                        occ.add(pass, scope.index(l.unsigned_abs() as usize), (ri as u32, 0));
                    }
                }
                BodyRef::Weight { lits, .. } => {
                    for &(l, w) in lits {
                        let occ = if l > 0 { &mut pos_occ } else { &mut neg_occ };
                        let i = scope.index(l.unsigned_abs() as usize);
                        occ.add(pass, i, (ri as u32, w.max(1)));
                    }
                }
            }
        }
        pos_occ.end(pass);
        neg_occ.end(pass);
    }
    let mut p = Propagation {
        rules: &g.rules,
        scope,
        keep,
        status,
        why,
        dead: vec![false; g.rules.len()],
        head_count,
        slack,
        pending,
        work: Vec::new(),
        facts: Vec::new(),
    };
    for &a in &scope.atoms {
        p.falsify_if_unsupported(a as usize);
    }
    for (ri, reason) in dead_at_start {
        p.kill(ri as usize, reason);
    }
    // The facts known from the start, and the heads of rules with empty bodies.
    for &a in &scope.atoms {
        if p.status[a as usize - 1] == Status::Fact {
            p.facts.push(GroundAtom::new(a));
        }
    }
    for ri in 0..g.rules.len() {
        if p.pending[ri] == 0 {
            p.body_holds(ri);
        }
    }
    loop {
        // A false atom: rules with `a` lose that literal and `not a` holds; a fact: the reverse.
        let (a, fact) = if let Some(a) = p.work.pop() {
            (a, false)
        } else if let Some(a) = p.facts.pop() {
            (a, true)
        } else {
            break;
        };
        let i = scope.index(a.get() as usize);
        let (lost, held) = if fact {
            (&neg_occ, &pos_occ)
        } else {
            (&pos_occ, &neg_occ)
        };
        for &(ri, w) in lost.of(i) {
            p.lose(ri as usize, w, !fact, a);
        }
        for &(ri, w) in held.of(i) {
            if w == 0 {
                p.literal_holds(ri as usize);
            }
        }
    }
    (p.dead, killed_contradictory)
}

/// The state of [`propagate`] once the occurrences are counted: which rules are dead (and
/// why), how many live rules head each atom, the slack of each weight body, how many literals
/// of each normal body are not yet known to hold, and the atoms decided whose occurrences are
/// still to visit (made false in `work`, facts in `facts`).
///
/// Invariant: an atom is made false (and queued) exactly once, when it is unknown, not kept,
/// and no live rule heads it; it is made a fact (and queued) exactly once, when it is unknown,
/// not kept, and heads a live normal rule alone whose body holds. An atom decided one way is
/// never decided the other: a false atom heads no live rule, and a fact's supporting rule
/// stays live (only a false body literal, or a fact among several heads, kills a rule).
struct Propagation<'a> {
    rules: &'a Rules,
    scope: &'a Scope,
    keep: &'a dyn Fn(usize) -> bool,
    status: &'a mut [Status],
    why: &'a mut Vec<Option<DeadReason>>,
    dead: Vec<bool>,
    head_count: Vec<u32>,
    slack: Vec<i64>,
    pending: Vec<u32>,
    work: Vec<GroundAtom>,
    facts: Vec<GroundAtom>,
}

impl Propagation<'_> {
    /// Makes atom `a` false and queues it if nothing can derive it any more.
    fn falsify_if_unsupported(&mut self, a: usize) {
        if self.head_count[self.scope.index(a)] == 0
            && self.status[a - 1] == Status::Unknown
            && !(self.keep)(a)
        {
            self.status[a - 1] = Status::False;
            self.work.push(GroundAtom::new(a as u32));
        }
    }

    /// A literal of the normal body of rule `ri` holds.
    fn literal_holds(&mut self, ri: usize) {
        self.pending[ri] -= 1;
        if self.pending[ri] == 0 {
            self.body_holds(ri);
        }
    }

    /// Every literal of the normal body of rule `ri` holds: a live rule with one disjunctive
    /// head makes it a fact (a choice derives nothing; a constraint is left to the solver).
    fn body_holds(&mut self, ri: usize) {
        if self.dead[ri] {
            return;
        }
        let r = self.rules.get(ri);
        if let (HeadKind::Disjunction, &[h]) = (r.head_kind, r.head) {
            let a = h as usize;
            if self.status[a - 1] == Status::Unknown && !(self.keep)(a) {
                self.status[a - 1] = Status::Fact;
                self.facts.push(GroundAtom::new(h));
            }
        }
    }

    /// Rule `ri` is dead for `reason`: its heads lose a supporting rule.
    fn kill(&mut self, ri: usize, reason: DeadReason) {
        if self.dead[ri] {
            return;
        }
        self.dead[ri] = true;
        if let Some(w) = self.why.get_mut(ri) {
            *w = Some(reason);
        }
        for &h in self.rules.get(ri).head {
            self.head_count[self.scope.index(h as usize)] -= 1;
            self.falsify_if_unsupported(h as usize);
        }
    }

    /// A literal over `atom` (`positive` or `not atom`) in the body of rule `ri` became false,
    /// with weight `w` in a weight body (0: a normal body). A normal body dies; a weight body
    /// loses the weight and dies once its bound is out of reach.
    fn lose(&mut self, ri: usize, w: i64, positive: bool, atom: GroundAtom) {
        let reason = if w > 0 {
            self.slack[ri] -= w;
            if self.slack[ri] >= 0 {
                return;
            }
            DeadReason::Unreachable
        } else {
            DeadReason::Literal {
                positive,
                atom: atom.get(),
            }
        };
        self.kill(ri, reason);
    }
}
