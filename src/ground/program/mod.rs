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

/// Where one rule of a [`Rules`] store ends in each of the store's arrays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Ends {
    /// End in `heads`, with [`CHOICE`] set for a choice rule.
    head: usize,
    /// End in `lits` (normal bodies).
    lit: usize,
    /// End in `wlits` (weight bodies).
    wlit: usize,
}

/// The flag in `Ends::head` that marks a choice rule.
const CHOICE: usize = 1 << (usize::BITS - 1);

/// The rules of a ground program, stored flat: the heads of all rules one after another in one
/// array, normal bodies in a second and weight bodies in a third, plus one record of three
/// ends per rule. A rule costs 24 bytes plus 4 per head atom and body literal (16 per weight
/// literal), without an allocation of its own: a `Vec<Rule>` costs 64 bytes per rule plus a
/// heap block per non-empty head and body, several times more for the millions of small
/// constraints some programs ground to.
///
/// Invariants: `ends` is non-decreasing in each component (with [`CHOICE`] masked off); rule
/// `i` spans from the ends of rule `i - 1` (0 for the first) to its own; a weight body starts
/// with one entry `(0, lower)` holding its bound (no literal is 0), so a rule has a weight body
/// exactly when its `wlits` range is not empty, and then its `lits` range is empty. Equal rule
/// sequences have equal stores.
#[derive(Clone, Default, PartialEq, Eq)]
pub struct Rules {
    heads: Vec<Atom>,
    lits: Vec<Lit>,
    wlits: Vec<(Lit, Weight)>,
    ends: Vec<Ends>,
}

impl Rules {
    /// No rules.
    pub fn new() -> Rules {
        Rules::default()
    }

    /// The number of rules.
    pub fn len(&self) -> usize {
        self.ends.len()
    }

    /// Whether there are no rules.
    pub fn is_empty(&self) -> bool {
        self.ends.is_empty()
    }

    fn last_ends(&self) -> Ends {
        self.ends.last().map_or(Ends::default(), |e| Ends {
            head: e.head & !CHOICE,
            ..*e
        })
    }

    /// Makes room for `rules` more rules with `heads` head atoms and `lits` body literals in
    /// all, so that a store whose size is known roughly does not grow step by step.
    pub fn reserve(&mut self, rules: usize, heads: usize, lits: usize) {
        self.ends.reserve(rules);
        self.heads.reserve(heads);
        self.lits.reserve(lits);
    }

    /// Makes room for as many more rules, head atoms and literals as `other` holds (for a
    /// store that is written from `other`, such as the simplified program from the ground one).
    pub fn reserve_like(&mut self, other: &Rules) {
        self.reserve(other.ends.len(), other.heads.len(), other.lits.len());
        self.wlits.reserve(other.wlits.len());
    }

    /// Appends a rule.
    pub fn push_parts(&mut self, head_kind: HeadKind, head: &[Atom], body: BodyRef<'_>) {
        self.heads.extend_from_slice(head);
        match body {
            BodyRef::Normal(lits) => self.lits.extend_from_slice(lits),
            BodyRef::Weight { lower, lits } => {
                self.wlits.push((0, lower));
                self.wlits.extend_from_slice(lits);
            }
        }
        let choice = if head_kind == HeadKind::Choice {
            CHOICE
        } else {
            0
        };
        self.ends.push(Ends {
            head: self.heads.len() | choice,
            lit: self.lits.len(),
            wlit: self.wlits.len(),
        });
    }

    /// Appends a rule given as a view.
    pub fn push_ref(&mut self, rule: RuleRef<'_>) {
        self.push_parts(rule.head_kind, rule.head, rule.body);
    }

    /// Appends an owned rule (its vectors are copied in and dropped).
    pub fn push(&mut self, rule: Rule) {
        self.push_ref(rule.as_ref());
    }

    /// Rule `i` (panics when `i >= len()`, as slice indexing does).
    #[inline]
    pub fn get(&self, i: usize) -> RuleRef<'_> {
        let start = if i == 0 {
            Ends::default()
        } else {
            let e = self.ends[i - 1];
            Ends {
                head: e.head & !CHOICE,
                ..e
            }
        };
        self.view(start, self.ends[i])
    }

    #[inline]
    fn view(&self, start: Ends, end: Ends) -> RuleRef<'_> {
        let head_kind = if end.head & CHOICE != 0 {
            HeadKind::Choice
        } else {
            HeadKind::Disjunction
        };
        let body = if end.wlit > start.wlit {
            let w = &self.wlits[start.wlit..end.wlit];
            BodyRef::Weight {
                lower: w[0].1,
                lits: &w[1..],
            }
        } else {
            BodyRef::Normal(&self.lits[start.lit..end.lit])
        };
        RuleRef {
            head_kind,
            head: &self.heads[start.head..end.head & !CHOICE],
            body,
        }
    }

    /// The rules in order.
    #[inline]
    pub fn iter(&self) -> RulesIter<'_> {
        RulesIter {
            rules: self,
            next: 0,
            start: Ends::default(),
        }
    }

    /// Owned copies of the rules.
    pub fn to_vec(&self) -> Vec<Rule> {
        self.iter().map(RuleRef::to_rule).collect()
    }

    /// Keeps the first `n` rules.
    pub fn truncate(&mut self, n: usize) {
        if n >= self.len() {
            return;
        }
        self.ends.truncate(n);
        let e = self.last_ends();
        self.heads.truncate(e.head);
        self.lits.truncate(e.lit);
        self.wlits.truncate(e.wlit);
    }

    /// The largest atom in any head or body literal (0 without rules): one pass over the
    /// flat arrays, not a view per rule.
    pub fn max_atom(&self) -> Atom {
        let heads = self.heads.iter().copied().max().unwrap_or(0);
        let lits = self
            .lits
            .iter()
            .map(|l| l.unsigned_abs())
            .max()
            .unwrap_or(0);
        // The `(0, lower)` entries count as atom 0.
        let wlits = self
            .wlits
            .iter()
            .map(|(l, _)| l.unsigned_abs())
            .max()
            .unwrap_or(0);
        heads.max(lits).max(wlits)
    }

    /// Releases spare capacity.
    pub fn shrink_to_fit(&mut self) {
        self.heads.shrink_to_fit();
        self.lits.shrink_to_fit();
        self.wlits.shrink_to_fit();
        self.ends.shrink_to_fit();
    }

    /// Renumbers every atom of every rule by `f`; a body literal keeps its sign.
    pub fn map_atoms(&mut self, f: &mut dyn FnMut(Atom) -> Atom) {
        self.for_each_head_atom(&mut |a| *a = f(*a));
        self.for_each_body_lit(&mut |l| {
            let m = f(l.unsigned_abs()) as Lit;
            *l = if *l < 0 { -m } else { m };
        });
    }

    /// Calls `f` on every body literal (weights kept), in place.
    fn for_each_body_lit(&mut self, f: &mut dyn FnMut(&mut Lit)) {
        self.lits.iter_mut().for_each(&mut *f);
        // The `(0, lower)` entries are bounds, not literals.
        self.wlits
            .iter_mut()
            .filter(|(l, _)| *l != 0)
            .for_each(|(l, _)| f(l));
    }

    /// Calls `f` on every head atom, in place.
    fn for_each_head_atom(&mut self, f: &mut dyn FnMut(&mut Atom)) {
        self.heads.iter_mut().for_each(f);
    }
}

impl std::fmt::Debug for Rules {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_list().entries(self.iter()).finish()
    }
}

impl PartialEq<Vec<Rule>> for Rules {
    fn eq(&self, other: &Vec<Rule>) -> bool {
        self.len() == other.len() && self.iter().zip(other).all(|(a, b)| a == b.as_ref())
    }
}

impl From<Vec<Rule>> for Rules {
    fn from(rules: Vec<Rule>) -> Rules {
        rules.iter().map(Rule::as_ref).collect()
    }
}

impl<'a> FromIterator<RuleRef<'a>> for Rules {
    fn from_iter<I: IntoIterator<Item = RuleRef<'a>>>(iter: I) -> Rules {
        let mut rules = Rules::new();
        rules.extend(iter);
        rules
    }
}

impl<'a> Extend<RuleRef<'a>> for Rules {
    fn extend<I: IntoIterator<Item = RuleRef<'a>>>(&mut self, iter: I) {
        for r in iter {
            self.push_ref(r);
        }
    }
}

impl Extend<Rule> for Rules {
    fn extend<I: IntoIterator<Item = Rule>>(&mut self, iter: I) {
        for r in iter {
            self.push(r);
        }
    }
}

impl<'a> Extend<&'a Rule> for Rules {
    fn extend<I: IntoIterator<Item = &'a Rule>>(&mut self, iter: I) {
        for r in iter {
            self.push_ref(r.as_ref());
        }
    }
}

/// The rules of a [`Rules`] store in order.
pub struct RulesIter<'a> {
    rules: &'a Rules,
    next: usize,
    start: Ends,
}

impl<'a> Iterator for RulesIter<'a> {
    type Item = RuleRef<'a>;

    #[inline]
    fn next(&mut self) -> Option<RuleRef<'a>> {
        let end = *self.rules.ends.get(self.next)?;
        let r = self.rules.view(self.start, end);
        self.next += 1;
        self.start = Ends {
            head: end.head & !CHOICE,
            ..end
        };
        Some(r)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let n = self.rules.len() - self.next;
        (n, Some(n))
    }
}

impl ExactSizeIterator for RulesIter<'_> {}

impl<'a> IntoIterator for &'a Rules {
    type Item = RuleRef<'a>;
    type IntoIter = RulesIter<'a>;

    fn into_iter(self) -> RulesIter<'a> {
        self.iter()
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

/// A grounder atom: the grounder's own number for an atom, `1..=Provenance::atoms.len()`.
/// Every atom the grounder created has one, also atoms without an aspif number (facts that no
/// rule body keeps, atoms proved false); [`Provenance::atoms`] says what it is.
pub type GAtom = u32;

/// A variable binding of a rule instance: (variable name, ground term), as ids into the
/// grounder's tables (`Grounding::symbols`: the name is interned in `names`, the term is a
/// symbol id). Variables the rewriting made (names starting with `#`) are left out.
pub type Bindings = Vec<(u32, u32)>;

/// Which part of a statement's translation an auxiliary ground rule belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AuxKind {
    /// A body aggregate: weight rules, the atoms that stand for its comparisons, the atom true
    /// when one of an element's conditions holds (gringo's translation).
    Aggregate,
    /// A conditional body literal `l : c` (`x :- l.  x :- not c.` and its helpers).
    Condition,
    /// A conditional element `l : c` of a disjunctive head (the element atom and its rules).
    Element,
    /// `d :- not a.`: the atom whose negation stands for the body literal `not not a`.
    DoubleNegation,
    /// `{appl}.`: the application atom of a consistency-restoring rule instance.
    CrApplication,
    /// `x :- c.`: an atom true when a `#minimize` element's condition holds (made when the
    /// element has several conditions, or a certain one).
    Minimize,
    /// `:- B, not l #count{...} u.`: the bounds of a choice rule or head aggregate.
    Bound,
    /// `#projN(X) :- p(X,_).`: an anonymous variable projected out of a negated literal.
    Projection,
}

impl AuxKind {
    /// A short English name (`aggregate`, `condition`, ...).
    pub fn name(self) -> &'static str {
        match self {
            AuxKind::Aggregate => "aggregate",
            AuxKind::Condition => "condition",
            AuxKind::Element => "disjunction element",
            AuxKind::DoubleNegation => "double negation",
            AuxKind::CrApplication => "CR application",
            AuxKind::Minimize => "minimize",
            AuxKind::Bound => "bound",
            AuxKind::Projection => "projection",
        }
    }
}

/// What produced a ground rule. Statement ids are indexes of statements of the program given
/// to the grounder (`Grounding::statement_spans` is indexed by them); they are plain numbers
/// that stay valid when statements are added later.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum RuleOrigin {
    /// An instance of statement `stmt` under `bindings`.
    Statement {
        /// The statement.
        stmt: u32,
        /// The instance's variable values.
        bindings: Bindings,
    },
    /// Part of the translation of statement `of_stmt`: `bindings` are the statement's variables
    /// bound when the auxiliary was made (for an aggregate, its global variables so far).
    Auxiliary {
        /// The statement.
        of_stmt: u32,
        /// What the auxiliary stands for.
        kind: AuxKind,
        /// The variable values known when it was made.
        bindings: Bindings,
    },
    /// `:- a, -a.`: no statement; an atom and its classical negation cannot both hold.
    Complement,
}

impl RuleOrigin {
    /// The statement, if any.
    pub fn stmt(&self) -> Option<u32> {
        match self {
            RuleOrigin::Statement { stmt, .. } => Some(*stmt),
            RuleOrigin::Auxiliary { of_stmt, .. } => Some(*of_stmt),
            RuleOrigin::Complement => None,
        }
    }

    /// The bindings (empty for `Complement`).
    pub fn bindings(&self) -> &[(u32, u32)] {
        match self {
            RuleOrigin::Statement { bindings, .. } | RuleOrigin::Auxiliary { bindings, .. } => {
                bindings
            }
            RuleOrigin::Complement => &[],
        }
    }
}

/// A body literal that grounding decided and so left out of a ground rule: `a` with `a` a
/// fact (`positive`; also `not not a` with `a` a fact), or `not a` with `a` false.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct RemovedLit {
    /// `a` (true) or `not a` (false).
    pub positive: bool,
    /// The atom.
    pub atom: GAtom,
}

/// One origin of a ground rule: what produced it, and the body literals that grounding
/// decided for this instance (so a proof can show them as leaves).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Origin {
    /// The statement (or auxiliary) and bindings.
    pub rule: RuleOrigin,
    /// Body literals of this instance that hold by grounding alone and are not in the rule.
    pub removed: Vec<RemovedLit>,
}

/// What grounding knows of an atom's truth.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AtomStatus {
    /// True in every answer set (no rule body keeps it).
    Fact,
    /// False in every answer set: no rule instance that can fire derives it.
    False,
    /// Left to the solver.
    Possible,
}

/// An atom the grounder created.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct AtomRecord {
    /// Its symbol (an id into `Grounding::symbols`); `None` for an auxiliary atom.
    pub sym: Option<u32>,
    /// What grounding decided.
    pub status: AtomStatus,
    /// Its aspif atom, 0 when it has none (it occurs in no statement of the program).
    pub aspif: Atom,
}

/// Why a rule instance that could have derived an atom was removed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeadReason {
    /// A body literal cannot hold: `a` with `a` false (`positive`), or `not a` with `a` a fact.
    Literal {
        /// `a` (true) or `not a` (false).
        positive: bool,
        /// The atom.
        atom: GAtom,
    },
    /// A rule with this fact among its heads: satisfied, it supports no other head (and adds
    /// nothing to the fact; a choice whose heads are all facts is dropped the same way).
    HeadFact(GAtom),
    /// The body holds a literal and its complement.
    Contradictory,
    /// A weight body can no longer reach its bound.
    Unreachable,
}

/// A ground rule instance that grounding removed, kept because one of its head atoms ended up
/// false (the rule instances, possibly none, that could have derived a false atom) or because
/// a fact among its heads satisfied it (`DeadReason::HeadFact`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct DeadRule {
    /// Its head atoms.
    pub head: Vec<GAtom>,
    /// Its origins.
    pub origins: Vec<Origin>,
    /// Why it was removed.
    pub why: DeadReason,
}

/// The provenance of a ground program (empty unless `GroundConfig::provenance` is on).
///
/// Invariants: when not empty, `origin_ends` has one entry per rule of the program and is
/// non-decreasing; rule `i`'s origins are `origins[origin_ends[i - 1]..origin_ends[i]]`, and
/// every rule the grounder made has at least one (several when instances ground to the same
/// rule); rules added to a program without provenance have none. `atoms` is
/// indexed by grounder atom minus one; `by_aspif[a]` is the grounder atom of aspif atom `a`
/// (0 when none); `by_sym` is sorted by symbol.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Provenance {
    origin_ends: Vec<u32>,
    origins: Vec<Origin>,
    /// Every atom the grounder created, by grounder atom minus one.
    pub atoms: Vec<AtomRecord>,
    by_aspif: Vec<GAtom>,
    by_sym: Vec<(u32, GAtom)>,
    /// The removed rule instances whose heads hold an atom that ended up false, and those
    /// removed because a fact among their heads satisfies them (`DeadReason::HeadFact`), so
    /// that every rule instance keeps its origin.
    pub dead: Vec<DeadRule>,
}

impl Provenance {
    /// No provenance.
    pub fn new() -> Provenance {
        Provenance::default()
    }

    /// Whether nothing was recorded (provenance off).
    pub fn is_empty(&self) -> bool {
        self.origin_ends.is_empty() && self.atoms.is_empty()
    }

    /// The number of rules with origins.
    pub fn num_rules(&self) -> usize {
        self.origin_ends.len()
    }

    /// Appends the origins of the next rule.
    pub fn push_rule(&mut self, origins: impl IntoIterator<Item = Origin>) {
        self.origins.extend(origins);
        self.origin_ends.push(self.origins.len() as u32);
    }

    /// Keeps the origins of the first `n` rules, or gives the rules from the last recorded
    /// one up to `n` no origin (rules added without provenance).
    pub fn resize_rules(&mut self, n: usize) {
        if n <= self.origin_ends.len() {
            self.origin_ends.truncate(n);
            let end = self.origin_ends.last().copied().unwrap_or(0);
            self.origins.truncate(end as usize);
        } else {
            let end = self.origins.len() as u32;
            self.origin_ends.resize(n, end);
        }
    }

    /// The origins of rule `i` (empty when `i` has none recorded).
    pub fn origins(&self, i: usize) -> &[Origin] {
        let Some(&end) = self.origin_ends.get(i) else {
            return &[];
        };
        let start = if i == 0 { 0 } else { self.origin_ends[i - 1] };
        &self.origins[start as usize..end as usize]
    }

    /// Adds origins to rules already recorded (`(rule, origin)`), leaving out an origin equal
    /// to one the rule has.
    pub fn add_origins(&mut self, mut extra: Vec<(u32, Origin)>) {
        if extra.is_empty() {
            return;
        }
        extra.sort_by_key(|e| e.0);
        let old_ends = std::mem::take(&mut self.origin_ends);
        let mut old = std::mem::take(&mut self.origins).into_iter();
        let mut extra = extra.into_iter().peekable();
        let mut start = 0;
        for (i, &end) in old_ends.iter().enumerate() {
            let first = self.origins.len();
            self.origins
                .extend(old.by_ref().take((end - start) as usize));
            start = end;
            while let Some((_, o)) = extra.next_if(|e| e.0 as usize == i) {
                if !self.origins[first..].contains(&o) {
                    self.origins.push(o);
                }
            }
            self.origin_ends.push(self.origins.len() as u32);
        }
    }

    /// Sets the atom table (and its lookups by aspif atom and symbol).
    pub fn set_atoms(&mut self, atoms: Vec<AtomRecord>) {
        let max = atoms.iter().map(|r| r.aspif).max().unwrap_or(0);
        self.by_aspif = vec![0; max as usize + 1];
        self.by_sym.clear();
        for (i, r) in atoms.iter().enumerate() {
            let g = i as GAtom + 1;
            if r.aspif != 0 {
                self.by_aspif[r.aspif as usize] = g;
            }
            if let Some(s) = r.sym {
                self.by_sym.push((s, g));
            }
        }
        self.by_sym.sort_unstable();
        self.atoms = atoms;
    }

    /// Grounder atom `g`'s record.
    pub fn atom(&self, g: GAtom) -> Option<&AtomRecord> {
        self.atoms.get((g as usize).wrapping_sub(1))
    }

    /// The grounder atom of aspif atom `a`.
    pub fn of_aspif(&self, a: Atom) -> Option<GAtom> {
        self.by_aspif.get(a as usize).copied().filter(|&g| g != 0)
    }

    /// The grounder atom of a symbol (an id into `Grounding::symbols`); `None` when the
    /// grounder never made that atom (no rule instance mentions it: it is false).
    pub fn of_symbol(&self, sym: u32) -> Option<GAtom> {
        self.by_sym
            .binary_search_by_key(&sym, |&(s, _)| s)
            .ok()
            .map(|i| self.by_sym[i].1)
    }

    /// The removed rule instances that had `g` among their heads. For a false atom these are
    /// all the ground instances that could have derived it; none means that instantiation made
    /// no instance with `g` in its head (every instance's positive body failed to match).
    pub fn dead_rules_for(&self, g: GAtom) -> impl Iterator<Item = &DeadRule> {
        self.dead.iter().filter(move |d| d.head.contains(&g))
    }

    /// Appends `other`'s rule origins after this one's (for rules added to the program later;
    /// atoms and dead rules are replaced by `other`'s when it has any).
    pub fn append(&mut self, other: Provenance) {
        let base = self.origins.len() as u32;
        self.origins.extend(other.origins);
        self.origin_ends
            .extend(other.origin_ends.into_iter().map(|e| e + base));
        if !other.atoms.is_empty() {
            self.atoms = other.atoms;
            self.by_aspif = other.by_aspif;
            self.by_sym = other.by_sym;
        }
        self.dead.extend(other.dead);
    }
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
    /// Theory statements, kept verbatim (aspif statement 9); Lucent does not interpret them.
    pub theory: Vec<String>,
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
        p.outputs.push(Output {
            symbol: "b".into(),
            condition: vec![2147483647],
        });
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
