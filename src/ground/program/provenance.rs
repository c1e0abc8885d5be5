//! Provenance of a ground program, for explanations: what produced each ground rule (its
//! statement, bindings and the body literals grounding decided), every atom the grounder
//! created with its status and aspif number, and the removed rule instances that could have
//! derived a false atom.
//!
//! Invariants: see [`Provenance`]; it is empty unless grounding ran with provenance on, and
//! then has the origins of each rule of the program it belongs to.

use super::Atom;

/// A grounder atom: the grounder's own number for an atom, counted from 1 in order of creation,
/// `1..=Provenance::atoms.len()` (inside the grounder the same numbering is the type
/// `GroundAtom`). Not the aspif numbering of the program ([`Atom`]). Every atom the grounder
/// created has one, also atoms without an aspif number (facts that no rule body keeps, atoms
/// proved false); [`Provenance::atoms`] says what it is.
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
