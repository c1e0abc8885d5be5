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
//! - `origins`, when present, is parallel to `rules`: the provenance of each ground rule.

/// An aspif atom, `1..=num_atoms`.
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

/// Where a ground rule came from: the index of its non-ground rule in the parsed program and
/// the substitution that produced it, as ids (the grounder owns the tables they index).
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Origin {
    /// Index of the source rule (statement) in the parsed program.
    pub rule: u32,
    /// Variable bindings, as (variable symbol id, ground term id) pairs.
    pub bindings: Vec<(u32, u32)>,
}

/// A whole ground program.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GroundProgram {
    /// Largest atom number used.
    pub num_atoms: u32,
    /// Rules, in emission order.
    pub rules: Vec<Rule>,
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
    /// Theory statements, kept verbatim (aspif statement 9); Lucent does not interpret them.
    pub theory: Vec<String>,
    /// Consistency-restoring rules.
    pub cr_rules: Vec<CrRule>,
    /// Preferences between CR rules.
    pub prefers: Vec<Prefer>,
    /// Provenance of each rule, parallel to `rules` when non-empty.
    pub origins: Vec<Origin>,
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
}
