//! Instantiation: grounds rewritten statements bottom-up over the statement dependency graph.
//!
//! Algorithm (Kaminski, Schaub, TPLP 2022, simplified): ground facts first, then the strongly
//! connected components of the statement dependency graph (a statement depends on every
//! statement heading an atom that unifies with one it reads, as in gringo: `p(a)` does not
//! depend on the rules for `p(b)`) in topological order, each split, as gringo does,
//! into the components of its positive dependencies (a statement read only under `not` inside
//! its component is grounded after the reader, whose literal stays); inside a recursive part,
//! semi-naive evaluation grounds each rule once per combination that uses at least one atom new
//! in the last round, the rounds after the first in gringo's queue order. Components with an
//! aggregate or conditional literal over one of their own predicates are instead grounded
//! naively to a fixpoint, keeping only the last round's rules (aggregate instances must see
//! every element). Joins use per-predicate indexes on the bound argument positions, built
//! lazily and extended as atoms arrive. The graph search, the split and the queue follow
//! gringo's (`Dependency::analyze`, `Graph::tarjan`, `Queue::process`), so the rules come out
//! in gringo's order: the atom numbering, hence the solver's initial variable order, follows.
//!
//! Invariants:
//! - Grounder atoms ([`GroundAtom`]) are `1..=atoms.len()`; an atom is *in the domain* once some rule instance
//!   can derive it; `fact` atoms are certainly true, and they never lose that status.
//! - A predicate is *complete* once every statement heading it is grounded; readers come after
//!   (or in the same component, where `not` literals on it stay).
//! - A positive body literal only matches atoms in the domain; a fact matched positively is
//!   removed from the ground body; `not a` with `a` a fact kills the instance, and `not a` with
//!   `a` of a complete predicate outside the domain is removed.
//! - Ground rules are over grounder atoms (as plain numbers); `simplify` renumbers them for
//!   aspif.
//!
//! Files: `mod` (the grounder's state, atoms, rule store), `provenance` (origins, dead
//! instances), `join` (candidates, indexes, joins, body order), `conditional` (conditional
//! body literals and the helper atoms for negations), `aggregate` (aggregate elements and
//! guards, saturation), `emit` (ground rules from a body's solutions), `schedule` (component
//! order, semi-naive and naive rounds, warnings), `call` (external function calls `@f(...)`
//! through the grounding context), `theory` (theory atoms: elements, one atom per ground
//! theory atom).

mod aggregate;
mod call;
mod conditional;
mod emit;
mod join;
mod provenance;
mod schedule;
pub mod theory;

pub use call::Calls;
pub use join::cmp_holds;

use hashbrown::HashMap;
use hashbrown::HashTable;
use smallvec::SmallVec;
use std::hash::BuildHasher;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span, WarningKind};
use crate::syntax::ast::{AggregateFunction, CmpOp, Sign};

use super::program::{
    AuxKind, Bindings, Body, BodyRef, DeadReason, DeadRule, ExternalValue, HeadKind,
    HeuristicModifier, Lit, Origin, RemovedLit, Rule, RuleOrigin, RuleRef, Rules, Weight,
};
use super::rewrite::{
    lit_vars, Compiled, HeadGate, NAgg, NAtom, NCondLit, NHead, NKind, NLit, NStmt, PredId,
};
use super::symbol::{SymData, SymId, Symbols};
use super::term::{Binding, NTerm, TermVars, VarList, VarSet};
use crate::base::intern::Sym;

/// A grounder atom: the grounder's own number for an atom, counted from 1 in order of creation
/// over a whole multi-shot session (`Grounder::atoms[a.index()]` is what is known about it).
/// It is not the aspif numbering of the ground program (`ground::program::Atom`, which
/// `simplify` gives the atoms that remain, and which the solver and `control::GroundAtom` use);
/// `ground::program::GAtom` is this numbering as provenance exposes it, a plain `u32`. The rule
/// store over grounder atoms (`Grounder::rules`) and the directives' literals hold these
/// numbers as plain atoms and literals: [`GroundAtom::get`] and [`GroundAtom::lit`] make them,
/// [`GroundAtom::new`] and [`GroundAtom::of_lit`] read them.
#[repr(transparent)]
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub(crate) struct GroundAtom(u32);

impl GroundAtom {
    /// Grounder atom number `n` (`1..`).
    #[inline]
    pub(crate) const fn new(n: u32) -> GroundAtom {
        GroundAtom(n)
    }

    /// The atom of a literal over grounder atoms (either sign).
    #[inline]
    pub(crate) const fn of_lit(l: Lit) -> GroundAtom {
        GroundAtom(l.unsigned_abs())
    }

    /// Its number (`1..`), as rules over grounder atoms store it.
    #[inline]
    pub(crate) const fn get(self) -> u32 {
        self.0
    }

    /// Its index in the atom table (`Grounder::atoms`): the number minus one.
    #[inline]
    pub(crate) const fn index(self) -> usize {
        self.0 as usize - 1
    }

    /// Its positive literal.
    #[inline]
    pub(crate) const fn lit(self) -> Lit {
        self.0 as Lit
    }
}

/// Why grounding stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopReason {
    /// The configured size limit was exceeded.
    SizeLimit,
    /// The deadline passed.
    Deadline,
    /// An error was reported that ends the grounding (a failed external function call).
    Error,
}

/// What is known about one atom.
#[derive(Clone, Copy, Debug)]
pub struct AtomInfo {
    /// The atom as a symbol (`p(1)`); `None` for auxiliary atoms.
    pub sym: Option<SymId>,
    /// Its predicate (`u32::MAX` for auxiliary atoms).
    pub pred: PredId,
    /// Certainly true.
    pub fact: bool,
    /// Derivable by some ground rule (or external).
    pub in_domain: bool,
    /// Position in the predicate's domain list.
    pub dom_pos: u32,
}

/// Index of a predicate's atoms on a set of bound argument positions.
struct Index {
    /// The bound positions (bit `i` for argument `i`).
    mask: u64,
    /// Atoms `[0, upto)` of the domain list are indexed.
    upto: usize,
    /// The number of bound positions: the length of a key.
    width: usize,
    /// The groups, hashed by their keys ([`values_hash`]).
    table: HashTable<u32>,
    /// The key of each group (the values at the bound positions), one after another.
    keys: Vec<SymId>,
    /// Domain positions of each key, increasing (append-only).
    groups: Vec<Vec<u32>>,
}

impl Index {
    /// An empty index on the positions of `mask`.
    fn new(mask: u64) -> Index {
        Index {
            mask,
            upto: 0,
            width: mask.count_ones() as usize,
            table: HashTable::new(),
            keys: Vec::new(),
            groups: Vec::new(),
        }
    }

    /// The group of `key`, if there is one.
    fn find(&self, key: &[SymId]) -> Option<u32> {
        let w = self.width;
        let keys = &self.keys;
        self.table
            .find(values_hash(key), |&g| {
                &keys[g as usize * w..(g as usize + 1) * w] == key
            })
            .copied()
    }

    /// The group of `key`, added (empty) if new.
    fn group(&mut self, key: &[SymId]) -> u32 {
        if let Some(g) = self.find(key) {
            return g;
        }
        let g = self.groups.len() as u32;
        self.keys.extend_from_slice(key);
        self.groups.push(Vec::new());
        let (keys, w) = (&self.keys, self.width);
        self.table.insert_unique(values_hash(key), g, |&x| {
            values_hash(&keys[x as usize * w..(x as usize + 1) * w])
        });
        g
    }
}

/// The atoms of one predicate.
#[derive(Default)]
struct Domain {
    /// Atoms in derivation order.
    atoms: Vec<GroundAtom>,
    /// Indexes, one per bound-position mask (few per predicate, found by linear search).
    indexes: Vec<Index>,
    /// All rules that can derive the predicate have been grounded.
    complete: bool,
    /// Semi-naive: positions below `old` were seen by every rule in all combinations.
    old: u32,
    /// Semi-naive: positions in `[old, delta)` are new in this round.
    delta: u32,
}

/// A position range in a domain list.
type Range = (u32, u32);

/// Domain positions to try for a literal.
enum Candidates {
    /// Every position in `[lo, hi)`.
    Range(u32, u32),
    /// At most one position.
    One(Option<u32>),
    /// `groups[group][lo..hi]` of the predicate's index number `index`.
    Group {
        /// Index number in the domain.
        index: u32,
        /// Group in the index.
        group: u32,
        /// First entry.
        lo: u32,
        /// One past the last entry.
        hi: u32,
    },
}

/// Grounding limits, as values.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    /// Maximum number of ground rules plus atoms.
    pub max_size: Option<usize>,
    /// Stop after this instant (checked every few thousand rules).
    pub deadline: Option<std::time::Instant>,
}

/// A minimize element key: priority, weight, tuple.
type MinKey = (i32, i32, Vec<SymId>);

/// The grounder's state.
pub struct Grounder<'a> {
    /// Symbols.
    pub syms: Symbols,
    /// Atom table, by grounder atom ([`GroundAtom::index`]: number minus one).
    pub atoms: Vec<AtomInfo>,
    /// Grounder atom number of each predicate-atom symbol, by symbol id (0: none).
    sym_atom: Vec<u32>,
    /// Domains, by predicate.
    domains: Vec<Domain>,
    /// Ground rules over grounder atoms (plain numbers, [`GroundAtom::get`]), stored flat (a program may ground to millions).
    pub rules: Rules,
    /// Provenance records (when provenance is on): origins, dead instances, the statement and
    /// auxiliary being grounded.
    pub prov: ProvRecords,
    /// Deduplication of `rules`.
    rule_set: HashTable<u32>,
    /// Hash of each rule in `rules` (so that growing `rule_set` does not rehash rules).
    rule_hashes: Vec<u64>,
    /// Diagnostics.
    pub diags: &'a mut Diagnostics,
    /// Sources for snippets.
    sources: Option<&'a SourceMap>,
    /// Record origins.
    pub provenance: bool,
    /// Limits.
    limits: Limits,
    /// Set when grounding must stop.
    pub stopped: Option<StopReason>,
    /// Spans of undefined operations already reported.
    reported: hashbrown::HashSet<Span>,
    /// `not not a` auxiliaries, by atom.
    notnot: HashMap<GroundAtom, GroundAtom>,
    /// CR application atoms by (statement, ground global values).
    cr_appl: HashMap<(u32, Vec<SymId>), GroundAtom>,
    /// The directives besides rules: CR rules, minimize elements, shows, projections,
    /// externals, heuristics and edges.
    pub directives: Directives,
    /// Rules emitted since the last deadline check.
    since_check: u32,
    /// Grounding a component naively: derived atoms are not marked as facts, since a later
    /// round may withdraw the rule that derived them.
    naive: bool,
    /// The address of the body literal a semi-naive round reads over the last round's new
    /// atoms (0: none). Where no argument of it is bound, its candidates are walked from the
    /// newest atom to the oldest, as gringo walks a full index over new atoms; so the rules
    /// come out in gringo's order. The address is only compared, never followed.
    new_lit: usize,
    /// Computing a naive component's domain: aggregates over its predicates are assumed true.
    optimistic: bool,
    /// Multi-shot: atoms `1..=old_atoms` existed before this grounding (0 for one-shot).
    pub old_atoms: usize,
    /// Multi-shot: old atoms (at most `old_atoms`) this grounding put into their domain or
    /// made facts without a rule (the simplification visits them, `simplify::scope`).
    pub touched: Vec<GroundAtom>,
    /// Predicates some statement of this or an earlier grounding heads (or `#defined`).
    defined: Vec<bool>,
    /// Vectors reused from one statement to the next.
    scratch: Scratch,
    /// The grounding context's functions, for `@f(...)`.
    calls: Option<&'a mut (dyn Calls + 'a)>,
    /// The values of the calls made so far.
    call_cache: call::CallCache,
}

/// What the grounder records for provenance (when provenance is on; empty otherwise).
#[derive(Default)]
pub struct ProvRecords {
    /// Origins parallel to `rules` (when provenance is on): the first instance of each rule.
    pub origins: Vec<Origin>,
    /// Further origins of rules that several instances ground to (when provenance is on).
    pub more_origins: HashMap<u32, Vec<Origin>>,
    /// Provenance: the statement being grounded.
    stmt: ProvStmt,
    /// Provenance: the auxiliary being built (its kind and the bindings when it started).
    aux: Option<(AuxKind, Bindings)>,
    /// Provenance: instances dropped during instantiation because a fact among their heads
    /// satisfies them (`simplify` keeps those with a head atom that ends up false).
    pub dead: Vec<DeadRule>,
    /// Provenance: the origins of each minimize element's conditions, parallel to `minimize`.
    pub minimize_origins: HashMap<MinKey, Vec<Vec<Origin>>>,
}

/// The directives a grounding collects besides its rules, over grounder atoms (`simplify`
/// renumbers them for aspif).
#[derive(Default)]
pub struct Directives {
    /// Ground CR rules: application atom and label.
    pub cr_rules: Vec<(GroundAtom, String)>,
    /// Minimize elements: key to alternative conditions.
    pub minimize: HashMap<MinKey, Vec<Vec<Lit>>>,
    /// Insertion order of minimize keys.
    pub minimize_order: Vec<MinKey>,
    /// `#show t : body` instances, with the index of their statement.
    pub shows: Vec<(SymId, Vec<Lit>, u32)>,
    /// Projected atoms.
    pub projections: Vec<GroundAtom>,
    /// Externals.
    pub externals: Vec<(GroundAtom, ExternalValue)>,
    /// Heuristics over grounder atoms (plain numbers).
    pub heuristics: Vec<super::program::Heuristic>,
    /// Edges.
    pub edges: Vec<super::program::Edge>,
    /// Node numbers of `#edge` terms.
    edge_nodes: HashMap<SymId, i32>,
    /// Theory atoms.
    pub theory: theory::TheoryStore,
}

/// Vectors the grounding of a statement reuses from the previous one instead of allocating
/// its own (a small program's statements ground to a few rules each, so the allocations
/// would be a good part of their cost).
#[derive(Default)]
struct Scratch {
    /// `join_order`: the variables bound so far.
    bound: VarSet,
    /// `join_order`: the variables aggregates bind.
    reserved: VarSet,
    /// `join_order`: the literals placed so far.
    placed: Vec<bool>,
    /// `join_order`: the variables a literal binds.
    newly: VarSet,
    /// `join_order`: the variables of the body's terms.
    term_vars: TermVars,
    /// `join_order`: the first term of each literal in `term_vars`.
    first_term: Vec<usize>,
    /// The join order of the statement.
    order: Vec<usize>,
    /// The join state of the statement (taken while it is grounded).
    ctx: Option<Ctx>,
}

/// What a [`Grounder`] keeps between the groundings of one multi-shot session (see
/// `ground::incremental`): the atoms, their symbol index, and the predicate domains with their
/// indexes, so that a later grounding joins against them instead of rebuilding them.
#[derive(Default)]
pub struct State {
    atoms: Vec<AtomInfo>,
    sym_atom: Vec<u32>,
    domains: Vec<Domain>,
    defined: Vec<bool>,
}

impl State {
    /// The predicate of grounder atom `a` (`None` for an auxiliary atom or one out of range).
    pub fn pred(&self, a: GroundAtom) -> Option<PredId> {
        let info = self.atoms.get((a.get() as usize).wrapping_sub(1))?;
        (info.pred != u32::MAX).then_some(info.pred)
    }

    /// Atom `a` is not certainly true after all (its rules were withdrawn).
    pub fn clear_fact(&mut self, a: GroundAtom) {
        if let Some(info) = self.atoms.get_mut((a.get() as usize).wrapping_sub(1)) {
            info.fact = false;
        }
    }
}

/// A join continuation.
type Cont<'k, 'a> = &'k mut dyn FnMut(&mut Grounder<'a>, &mut Ctx);

/// The statement being grounded, for provenance.
#[derive(Default)]
struct ProvStmt {
    /// Its index.
    stmt: u32,
    /// Set when the statement is itself part of another's translation.
    aux: Option<AuxKind>,
    /// Its variable names (`None` for the rewriting's own variables).
    names: Vec<Option<Sym>>,
    /// Its head atoms, when its head is a plain disjunction or choice of atoms (so that an
    /// instance whose body fails can still name the atoms it would have derived).
    head: Option<Vec<NAtom>>,
}

/// Per-statement join state.
struct Ctx {
    /// Variable values.
    binding: Binding,
    /// Ground body literals so far.
    body: Vec<Lit>,
}

/// A ground conditional disjunction element: its literals (sign and atom) and its condition.
type ElemInstance = (Vec<(Sign, GroundAtom)>, Vec<Lit>);

/// One ground literal of a conditional disjunction element: its sign, the index of its
/// non-ground literal in the element's conjunction, and the atom.
type ElemLit = (Sign, usize, SymId);

/// The instances of a conditional disjunction element that form one element: their key (the
/// values of the local variables shared by condition and literals), their conditions and the
/// union of their literals.
type ElemGroup = (Vec<SymId>, Vec<Vec<Lit>>, Vec<ElemLit>);

/// A ground instance of a conditional body literal's condition: its literals, and the
/// alternatives of the literal (`None` when none can hold, an empty list when one certainly
/// does).
type CondInstance = (Vec<Lit>, Option<Vec<Vec<Lit>>>);

/// The distinct tuples of an aggregate's ground elements, in order of first occurrence, stored
/// one after another; `table` holds their indexes, hashed by tuple.
#[derive(Default)]
struct ElemTuples {
    /// The tuples' values, one tuple after another.
    values: Vec<SymId>,
    /// Where each tuple ends in `values`.
    ends: Vec<usize>,
    /// Indexes of the tuples.
    table: HashTable<u32>,
    /// Hasher of `table`.
    hasher: hashbrown::DefaultHashBuilder,
}

impl ElemTuples {
    /// Tuple `i`.
    fn get(&self, i: usize) -> &[SymId] {
        let start = if i == 0 { 0 } else { self.ends[i - 1] };
        &self.values[start..self.ends[i]]
    }

    /// The index of tuple `t`, added at the end if new.
    fn index(&mut self, t: &[SymId]) -> usize {
        let hash = self.hasher.hash_one(t);
        let ElemTuples {
            values,
            ends,
            table,
            hasher,
        } = self;
        let get = |i: u32| {
            let i = i as usize;
            let start = if i == 0 { 0 } else { ends[i - 1] };
            &values[start..ends[i]]
        };
        if let Some(&i) = table.find(hash, |&i| get(i) == t) {
            return i as usize;
        }
        let i = ends.len();
        values.extend_from_slice(t);
        ends.push(values.len());
        let (values, ends) = (&*values, &*ends);
        table.insert_unique(hash, i as u32, |&j| {
            let j = j as usize;
            let start = if j == 0 { 0 } else { ends[j - 1] };
            hasher.hash_one(&values[start..ends[j]])
        });
        i
    }
}

/// The value of an aggregate atom under a guard, over ground elements.
enum Truth {
    /// Certainly true.
    True,
    /// Certainly false.
    False,
    /// True exactly when all these literals are.
    Lits(Vec<Lit>),
}

impl<'a> Grounder<'a> {
    /// A grounder that continues `state` (the atoms and domains of earlier groundings; their
    /// predicates keep their ids, new ones are numbered after them), over `syms`, the table
    /// those groundings used. Rules, directives and provenance start empty.
    #[allow(clippy::too_many_arguments)]
    pub fn resume(
        state: State,
        syms: Symbols,
        num_preds: usize,
        diags: &'a mut Diagnostics,
        sources: Option<&'a SourceMap>,
        provenance: bool,
        limits: Limits,
    ) -> Grounder<'a> {
        let mut domains = state.domains;
        domains.resize_with(num_preds.max(domains.len()), Domain::default);
        let old_atoms = state.atoms.len();
        Grounder {
            syms,
            atoms: state.atoms,
            sym_atom: state.sym_atom,
            domains,
            rules: Rules::new(),
            prov: ProvRecords::default(),
            rule_set: HashTable::new(),
            rule_hashes: Vec::new(),
            diags,
            sources,
            provenance,
            limits,
            stopped: None,
            reported: hashbrown::HashSet::new(),
            notnot: HashMap::new(),
            cr_appl: HashMap::new(),
            directives: Directives::default(),
            since_check: 0,
            naive: false,
            new_lit: 0,
            optimistic: false,
            old_atoms,
            touched: Vec::new(),
            defined: state.defined,
            scratch: Scratch::default(),
            calls: None,
            call_cache: call::CallCache::new(),
        }
    }

    /// The state to continue from at the next grounding (the grounder's atoms, domains and
    /// indexes move out; its symbols stay in `syms`).
    pub fn suspend(&mut self) -> State {
        State {
            atoms: std::mem::take(&mut self.atoms),
            sym_atom: std::mem::take(&mut self.sym_atom),
            domains: std::mem::take(&mut self.domains),
            defined: std::mem::take(&mut self.defined),
        }
    }

    /// Marks atom `a` true for good (a later grounding removes it from bodies).
    pub fn set_fact(&mut self, a: GroundAtom) {
        self.atoms[a.index()].fact = true;
    }

    /// Puts atom `a` into its predicate's domain (an atom a later grounding must be able to
    /// match).
    pub fn put_in_domain(&mut self, a: GroundAtom) {
        self.derive(a);
    }

    fn snippet(&self, span: Span) -> String {
        match self.sources {
            Some(s) if (span.file.0 as usize) < s.len() => s.get(span.file).slice(span).to_string(),
            _ => String::new(),
        }
    }

    fn undefined(&mut self, span: Span) {
        if self.reported.insert(span) {
            let d =
                Diagnostic::warning(WarningKind::OperationUndefined, span, "operation undefined");
            let s = self.snippet(span);
            self.diags
                .push(if s.is_empty() { d } else { d.with_snippet(s) });
        }
    }

    fn eval(&mut self, t: &NTerm, b: &Binding) -> Option<SymId> {
        match t.eval(&mut self.syms, b) {
            Ok(v) => Some(v),
            Err(span) => {
                self.undefined(span);
                None
            }
        }
    }

    /// A fresh auxiliary atom.
    pub fn aux(&mut self) -> GroundAtom {
        self.atoms.push(AtomInfo {
            sym: None,
            pred: u32::MAX,
            fact: false,
            in_domain: true,
            dom_pos: 0,
        });
        GroundAtom::new(self.atoms.len() as u32)
    }

    /// The atom of a predicate-atom symbol, created outside the domain if new.
    pub fn atom_of(&mut self, sym: SymId, pred: PredId) -> GroundAtom {
        if let Some(a) = self.find_atom(sym) {
            return a;
        }
        self.atoms.push(AtomInfo {
            sym: Some(sym),
            pred,
            fact: false,
            in_domain: false,
            dom_pos: 0,
        });
        let id = GroundAtom::new(self.atoms.len() as u32);
        let i = sym.0 as usize;
        if i >= self.sym_atom.len() {
            self.sym_atom.resize((i + 1).max(self.syms.len()), 0);
        }
        self.sym_atom[i] = id.get();
        id
    }

    /// The atom of a symbol, if it exists.
    pub fn find_atom(&self, sym: SymId) -> Option<GroundAtom> {
        match self.sym_atom.get(sym.0 as usize) {
            Some(&a) if a != 0 => Some(GroundAtom::new(a)),
            _ => None,
        }
    }

    fn info(&self, a: GroundAtom) -> &AtomInfo {
        &self.atoms[a.index()]
    }

    /// Puts an atom into its predicate's domain.
    fn derive(&mut self, a: GroundAtom) {
        let info = self.atoms[a.index()];
        if info.in_domain || info.pred == u32::MAX {
            return;
        }
        if a.index() < self.old_atoms {
            self.touched.push(a);
        }
        let d = &mut self.domains[info.pred as usize];
        let pos = d.atoms.len() as u32;
        d.atoms.push(a);
        let i = &mut self.atoms[a.index()];
        i.in_domain = true;
        i.dom_pos = pos;
        self.check_size();
    }

    fn check_size(&mut self) {
        if let Some(max) = self.limits.max_size {
            if self.rules.len() + self.atoms.len() > max {
                self.stopped = Some(StopReason::SizeLimit);
            }
        }
    }

    /// Makes room for `n` ground rules (and as many atoms) before instantiation, so that a
    /// small program's tables do not rehash as they grow from empty.
    pub fn reserve(&mut self, n: usize) {
        let hashes = &self.rule_hashes;
        self.rule_set.reserve(n, |&i| hashes[i as usize]);
        self.rule_hashes.reserve(n);
        self.atoms.reserve(n);
        // About two body literals per rule.
        self.rules.reserve(n, n, 2 * n);
    }

    /// Frees the rule deduplication table once instantiation is over (simplification does
    /// not add rules through [`Grounder::add_rule`]); large programs need the memory.
    pub fn release_dedup(&mut self) {
        self.rule_set = HashTable::new();
        self.rule_hashes = Vec::new();
    }

    /// Adds a ground rule unless an equal one exists; returns whether it was added. With
    /// provenance, `origin` is recorded for the rule, also when it existed already.
    fn add_rule(&mut self, rule: Rule, origin: impl FnOnce(&mut Self) -> Origin) -> bool {
        self.add_rule_ref(rule.as_ref(), origin)
    }

    /// [`Grounder::add_rule`] for a rule given by slices (no owned copy is made unless the
    /// rule is new, and then only into the rule store).
    fn add_rule_ref(
        &mut self,
        rule: RuleRef<'_>,
        origin: impl FnOnce(&mut Self) -> Origin,
    ) -> bool {
        assert_eq!(
            self.rule_hashes.len(),
            self.rules.len(),
            "add_rule after release_dedup"
        );
        let hash = rule_hash(rule);
        let rules = &self.rules;
        if let Some(&i) = self.rule_set.find(hash, |&i| rules.get(i as usize) == rule) {
            if self.provenance {
                let o = origin(self);
                self.add_origin(i, o);
            }
            return false;
        }
        let idx = self.rules.len() as u32;
        self.rules.push_ref(rule);
        self.rule_hashes.push(hash);
        if self.provenance {
            let o = origin(self);
            self.prov.origins.push(o);
        }
        let hashes = &self.rule_hashes;
        self.rule_set
            .insert_unique(hash, idx, |&i| hashes[i as usize]);
        self.check_size();
        self.since_check += 1;
        if self.since_check >= 4096 {
            self.since_check = 0;
            if let Some(d) = self.limits.deadline {
                if std::time::Instant::now() >= d {
                    self.stopped = Some(StopReason::Deadline);
                }
            }
        }
        true
    }

    /// Records one more origin for rule `i` (unless it has that origin already).
    fn add_origin(&mut self, i: u32, o: Origin) {
        if self.prov.origins[i as usize] == o {
            return;
        }
        let more = self.prov.more_origins.entry(i).or_default();
        if !more.contains(&o) {
            more.push(o);
        }
    }

    /// With provenance: records `origin` for an existing rule equal to `rule`, if there is one
    /// (an instance satisfied by a fact that grounds to that fact's rule).
    fn attach_origin(&mut self, rule: Rule, origin: impl FnOnce(&mut Self) -> Origin) {
        if !self.provenance {
            return;
        }
        let rule = rule.as_ref();
        let hash = rule_hash(rule);
        let rules = &self.rules;
        if let Some(&i) = self.rule_set.find(hash, |&i| rules.get(i as usize) == rule) {
            let o = origin(self);
            self.add_origin(i, o);
        }
    }
}

/// One step of the grounder's hashes: a multiplicative word mix (as the symbol table's).
#[inline]
fn mix(h: u64, w: u64) -> u64 {
    const K: u64 = 0x9e37_79b9_7f4a_7c15;
    (h.rotate_left(23) ^ w).wrapping_mul(K)
}

/// The hash of a list of symbols (an index key).
fn values_hash(vs: &[SymId]) -> u64 {
    let mut h = mix(7, vs.len() as u64);
    for v in vs {
        h = mix(h, v.0 as u64);
    }
    h ^ (h >> 29)
}

/// The hash of a ground rule in the deduplication table: a multiplicative word mix, as the
/// symbol table's (a general hasher writes every atom separately, several times the work).
fn rule_hash(r: RuleRef<'_>) -> u64 {
    let kind = match r.head_kind {
        HeadKind::Disjunction => 1,
        HeadKind::Choice => 2,
    };
    let mut h = mix(kind, r.head.len() as u64);
    for &a in r.head {
        h = mix(h, a as u64);
    }
    match r.body {
        BodyRef::Normal(ls) => {
            h = mix(h, ls.len() as u64);
            for &l in ls {
                h = mix(h, l as u32 as u64);
            }
        }
        BodyRef::Weight { lower, lits } => {
            h = mix(mix(h, u64::MAX - lits.len() as u64), lower as u64);
            for &(l, w) in lits {
                h = mix(mix(h, l as u32 as u64), w as u64);
            }
        }
    }
    h ^ (h >> 29)
}
