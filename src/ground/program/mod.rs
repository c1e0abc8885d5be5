//! The ground program: aspif's statements held in memory, plus what aspif cannot say
//! (consistency-restoring rules, provenance for explanations).
//!
//! Invariants:
//! - Atoms are numbered `1..=num_atoms` as in aspif; a literal is `+a` (the atom) or `-a` (its
//!   default negation), never 0.
//! - Consistency-restoring (CR) rules are ground as ordinary rules guarded by an *application
//!   atom*: `r: h :+ b.` becomes `{appl_r}.` and `h :- b, appl_r.`; `cr_rules` lists the
//!   application atoms. Written as aspif, they also become a `#minimize` over the application
//!   atoms at a priority above every user priority (so clasp alone computes the default,
//!   cardinality-minimal semantics) and `10 lucent-cr ...` comment lines that let Lucent's aspif
//!   reader recover `cr_rules` and `prefers`.
//! - `provenance`, when not empty, has the origins of each rule of `rules` (see [`Provenance`]).
//!
//! Files: `mod` (the statements and the whole program), `store` (the flat rule store
//! [`Rules`]), `provenance` (origins, atom records and dead rules for explanations), `theory`
//! (ground theory atoms).

mod provenance;
mod store;
mod theory;

pub use provenance::{
    AtomRecord, AtomStatus, AuxKind, Bindings, DeadReason, DeadRule, GAtom, Origin, Provenance,
    RemovedLit, RuleOrigin,
};
pub use store::{Rules, RulesIter};
pub use theory::{is_operator, TheoryAtom, TheoryElement, TheoryTerm};

/// An atom of a ground program: the aspif numbering, `1..=num_atoms` (what `simplify` gives
/// the atoms that remain, in gringo's order; the solver's variables and `control::AtomId` are
/// this numbering). The grounder's own numbering is another ([`GAtom`]), though its rule store
/// holds those numbers in this plain form until `simplify` renumbers them.
pub type Atom = u32;
/// An aspif literal: positive atom or default-negated atom; never 0.
pub type Lit = i32;
/// A weight or bound.
pub type Weight = i64;

/// The head of a rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HeadKind {
    /// At least one head atom is true if the body holds (a constraint when the head is empty).
    Disjunction,
    /// Any subset of the head atoms may be true if the body holds.
    Choice,
}

/// The body of a rule.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Body {
    /// A conjunction of literals.
    Normal(Vec<Lit>),
    /// Holds when the sum of the weights of the true literals is at least `lower`.
    Weight {
        /// The lower bound.
        lower: Weight,
        /// Literals with their weights.
        lits: Vec<(Lit, Weight)>,
    },
}

/// A ground rule (aspif statement 1).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Rule {
    /// Disjunctive or choice head.
    pub head_kind: HeadKind,
    /// Head atoms.
    pub head: Vec<Atom>,
    /// The body.
    pub body: Body,
}

impl Rule {
    /// `head_1 | ... | head_n :- body.` (a constraint when `head` is empty).
    pub fn normal(head: &[Atom], body: &[Lit]) -> Rule {
        Rule {
            head_kind: HeadKind::Disjunction,
            head: head.to_vec(),
            body: Body::Normal(body.to_vec()),
        }
    }

    /// `{head_1; ...; head_n} :- body.`
    pub fn choice(head: &[Atom], body: &[Lit]) -> Rule {
        Rule {
            head_kind: HeadKind::Choice,
            head: head.to_vec(),
            body: Body::Normal(body.to_vec()),
        }
    }
}

impl Rule {
    /// The rule as a view (the form [`Rules`] hands out).
    pub fn as_ref(&self) -> RuleRef<'_> {
        RuleRef {
            head_kind: self.head_kind,
            head: &self.head,
            body: self.body.as_ref(),
        }
    }
}

impl Body {
    /// The body as a view.
    pub fn as_ref(&self) -> BodyRef<'_> {
        match self {
            Body::Normal(lits) => BodyRef::Normal(lits),
            Body::Weight { lower, lits } => BodyRef::Weight {
                lower: *lower,
                lits,
            },
        }
    }
}

/// A rule body borrowed from a [`Rules`] store (or from a [`Body`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BodyRef<'a> {
    /// A conjunction of literals.
    Normal(&'a [Lit]),
    /// Holds when the sum of the weights of the true literals is at least `lower`.
    Weight {
        /// The lower bound.
        lower: Weight,
        /// Literals with their weights.
        lits: &'a [(Lit, Weight)],
    },
}

impl BodyRef<'_> {
    /// An owned copy.
    pub fn to_body(self) -> Body {
        match self {
            BodyRef::Normal(lits) => Body::Normal(lits.to_vec()),
            BodyRef::Weight { lower, lits } => Body::Weight {
                lower,
                lits: lits.to_vec(),
            },
        }
    }

    /// `true` for an empty conjunction (a fact's body).
    pub fn is_empty_normal(self) -> bool {
        matches!(self, BodyRef::Normal([]))
    }
}

/// A rule borrowed from a [`Rules`] store (or from a [`Rule`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RuleRef<'a> {
    /// Disjunctive or choice head.
    pub head_kind: HeadKind,
    /// Head atoms.
    pub head: &'a [Atom],
    /// The body.
    pub body: BodyRef<'a>,
}

impl RuleRef<'_> {
    /// An owned copy.
    pub fn to_rule(self) -> Rule {
        Rule {
            head_kind: self.head_kind,
            head: self.head.to_vec(),
            body: self.body.to_body(),
        }
    }
}

/// A minimize statement (aspif statement 2): minimize the sum of weights of true literals.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Minimize {
    /// Higher priorities are more important.
    pub priority: Weight,
    /// Literals with their weights.
    pub lits: Vec<(Lit, Weight)>,
}

/// An output statement (aspif statement 4): `symbol` is shown when all of `condition` hold.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Output {
    /// The text shown, e.g. `p(1,"a")`.
    pub symbol: String,
    /// Literals that must all be true.
    pub condition: Vec<Lit>,
    /// Where a model lists the symbol, as clingo lists it: the solver keeps its outputs
    /// ordered by this key, equal keys in the order added. The grounder gives a shown atom
    /// its predicate's domain rank and its atom number ([`Output::atom_order`]) and a `#show`
    /// term a key after every atom's ([`Output::term_order`]); outputs from elsewhere (aspif,
    /// the backend) take [`Output::LAST`].
    pub order: u64,
}

impl Output {
    /// The key of outputs with no place of their own: after the others, in the order added.
    pub const LAST: u64 = u64::MAX;

    /// An output without a place of its own ([`Output::LAST`]).
    pub fn new(symbol: String, condition: Vec<Lit>) -> Output {
        Output {
            symbol,
            condition,
            order: Output::LAST,
        }
    }

    /// The key of a shown atom: its predicate's domain rank, then its grounder atom number.
    pub fn atom_order(rank: u32, atom: u32) -> u64 {
        ((rank as u64) << 32) | atom as u64
    }

    /// The key of a `#show` term of statement `stmt`: after the atoms, later statements first
    /// (as clingo lists them).
    pub fn term_order(stmt: u32) -> u64 {
        (1u64 << 63) | (u32::MAX - stmt) as u64
    }
}

/// Truth value of an external atom (aspif statement 5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ExternalValue {
    /// Free to be true or false.
    Free,
    /// Assumed true.
    True,
    /// Assumed false.
    False,
    /// No longer external.
    Release,
}

/// Heuristic modifiers (aspif statement 7).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum HeuristicModifier {
    /// `level`
    Level,
    /// `sign`
    Sign,
    /// `factor`
    Factor,
    /// `init`
    Init,
    /// `true`
    True,
    /// `false`
    False,
}

/// A heuristic directive (aspif statement 7).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Heuristic {
    /// The modifier.
    pub modifier: HeuristicModifier,
    /// The atom it applies to.
    pub atom: Atom,
    /// Its value.
    pub bias: i32,
    /// Its priority.
    pub priority: u32,
    /// When it applies.
    pub condition: Vec<Lit>,
}

/// An edge directive (aspif statement 8).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Edge {
    /// Source node.
    pub from: i32,
    /// Target node.
    pub to: i32,
    /// When the edge exists.
    pub condition: Vec<Lit>,
}

/// A ground consistency-restoring rule, represented by its application atom.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct CrRule {
    /// The choice atom that is true exactly when the rule is applied.
    pub appl: Atom,
    /// The rule's ground label (or a generated name such as `r3(1,2)`), used in reports.
    pub label: String,
}

/// `prefer(l1, l2)`: applying the rule labelled `better` is preferred to applying `worse`
/// (`--cr=subset` only).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Prefer {
    /// Application atom of the preferred rule.
    pub better: Atom,
    /// Application atom of the less preferred rule.
    pub worse: Atom,
}

/// A whole ground program.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GroundProgram {
    /// Largest atom number used.
    pub num_atoms: u32,
    /// Rules, in emission order.
    pub rules: Rules,
    /// Minimize statements.
    pub minimize: Vec<Minimize>,
    /// Projection atoms (`#project`); empty means no projection.
    pub projections: Vec<Atom>,
    /// Output statements.
    pub outputs: Vec<Output>,
    /// External atoms with their values.
    pub externals: Vec<(Atom, ExternalValue)>,
    /// Assumptions (aspif statement 6).
    pub assumptions: Vec<Lit>,
    /// Heuristic directives.
    pub heuristics: Vec<Heuristic>,
    /// Edge directives.
    pub edges: Vec<Edge>,
    /// Theory statements read from aspif, kept verbatim (aspif statement 9).
    pub theory: Vec<String>,
    /// Theory atoms of a grounding (see [`TheoryAtom`]).
    pub theory_atoms: Vec<TheoryAtom>,
    /// Consistency-restoring rules.
    pub cr_rules: Vec<CrRule>,
    /// Preferences between CR rules.
    pub prefers: Vec<Prefer>,
    /// Provenance of the rules and atoms (empty unless grounded with provenance on).
    pub provenance: Provenance,
}

impl GroundProgram {
    /// An empty program.
    pub fn new() -> GroundProgram {
        GroundProgram::default()
    }

    /// Allocates a fresh atom.
    pub fn new_atom(&mut self) -> Atom {
        self.num_atoms += 1;
        self.num_atoms
    }

    /// Renumbers the atoms densely when they are sparse: aspif from elsewhere may name atom
    /// 2147483647 in a program of three atoms, and the solver's per-atom arrays are sized by
    /// the largest atom. Atoms keep their order; atoms no statement mentions (which no rule
    /// defines, so they are false and shown by nothing) disappear. Returns, when it renumbered,
    /// the old number of each new atom (index 0 unused); `None` when the numbering was already
    /// dense enough (at most twice the atoms used, plus 1024) and nothing changed.
    ///
    /// Theory statements are kept verbatim, with their old numbers: renumber only a program
    /// that is solved, not one written back as aspif.
    pub fn compact_atoms(&mut self) -> Option<Vec<Atom>> {
        let mut used: Vec<Atom> = Vec::new();
        let mut max = self.num_atoms;
        self.for_each_atom(&mut |a| {
            used.push(*a);
            max = max.max(*a);
        });
        used.sort_unstable();
        used.dedup();
        if u64::from(max) <= 2 * used.len() as u64 + 1024 {
            return None;
        }
        let new_of = |a: Atom| -> Atom {
            let k = used.binary_search(&a).expect("every atom was collected");
            k as Atom + 1
        };
        self.for_each_atom(&mut |a| *a = new_of(*a));
        self.num_atoms = used.len() as Atom;
        let mut old = Vec::with_capacity(used.len() + 1);
        old.push(0);
        old.extend_from_slice(&used);
        Some(old)
    }

    /// The theory atoms that head no rule: free, as externals are (see [`TheoryAtom`]).
    pub fn free_theory_atoms(&self) -> Vec<Atom> {
        if self.theory_atoms.is_empty() {
            return Vec::new();
        }
        let mut headed = vec![false; self.num_atoms as usize + 1];
        for r in self.rules.iter() {
            for &h in r.head {
                if let Some(x) = headed.get_mut(h as usize) {
                    *x = true;
                }
            }
        }
        self.theory_atoms
            .iter()
            .map(|t| t.atom)
            .filter(|&a| a != 0 && !headed[a as usize])
            .collect()
    }

    /// Calls `f` on every atom occurrence of every statement (theory statements excepted),
    /// literals as their atoms; `f` may change the atom, and a literal keeps its sign.
    fn for_each_atom(&mut self, f: &mut dyn FnMut(&mut Atom)) {
        let mut lit = |l: &mut Lit| {
            let mut a = l.unsigned_abs();
            f(&mut a);
            let m = a as Lit;
            *l = if *l < 0 { -m } else { m };
        };
        self.rules.for_each_body_lit(&mut lit);
        for m in &mut self.minimize {
            m.lits.iter_mut().for_each(|(l, _)| lit(l));
        }
        for o in &mut self.outputs {
            o.condition.iter_mut().for_each(&mut lit);
        }
        self.assumptions.iter_mut().for_each(&mut lit);
        for h in &mut self.heuristics {
            h.condition.iter_mut().for_each(&mut lit);
        }
        for e in &mut self.edges {
            e.condition.iter_mut().for_each(&mut lit);
        }
        for t in &mut self.theory_atoms {
            if t.atom != 0 {
                let mut l = t.atom as Lit;
                lit(&mut l);
                t.atom = l as Atom;
            }
            for e in &mut t.elements {
                e.condition.iter_mut().for_each(&mut lit);
            }
        }
        self.rules.for_each_head_atom(f);
        self.projections.iter_mut().for_each(&mut *f);
        for (a, _) in &mut self.externals {
            f(a);
        }
        for h in &mut self.heuristics {
            f(&mut h.atom);
        }
        for c in &mut self.cr_rules {
            f(&mut c.appl);
        }
        for p in &mut self.prefers {
            f(&mut p.better);
            f(&mut p.worse);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn compact_atoms_renumbers_sparse_atoms_in_order() {
        // {a; b}. c :- a, not b. with a = 9, b = 2147483647, c = 4; every field renumbered.
        let mut p = GroundProgram::new();
        p.rules = vec![
            Rule::choice(&[9, 2147483647], &[]),
            Rule::normal(&[4], &[9, -2147483647]),
        ]
        .into();
        p.num_atoms = 2147483647;
        p.outputs.push(Output::new("b".into(), vec![2147483647]));
        p.minimize.push(Minimize {
            priority: 0,
            lits: vec![(-4, 1)],
        });
        p.cr_rules.push(CrRule {
            appl: 9,
            label: "r".into(),
        });
        let old = p.compact_atoms().expect("sparse atoms are renumbered");
        // Old 4, 9, 2147483647 become 1, 2, 3.
        assert_eq!(old, vec![0, 4, 9, 2147483647]);
        assert_eq!(p.num_atoms, 3);
        assert_eq!(
            p.rules,
            vec![Rule::choice(&[2, 3], &[]), Rule::normal(&[1], &[2, -3])]
        );
        assert_eq!(p.outputs[0].condition, vec![3]);
        assert_eq!(p.minimize[0].lits, vec![(-1, 1)]);
        assert_eq!(p.cr_rules[0].appl, 2);
        // Dense enough now: nothing changes.
        let before = p.clone();
        assert_eq!(p.compact_atoms(), None);
        assert_eq!(p, before);
    }
}
