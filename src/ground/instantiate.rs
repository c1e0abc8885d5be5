//! Instantiation: grounds rewritten statements bottom-up over the statement dependency graph.
//!
//! Algorithm (Kaminski, Schaub, TPLP 2022, simplified): ground facts first, then the strongly
//! connected components of the statement dependency graph (a statement depends on every
//! statement heading a predicate it reads) in topological order, each split, as gringo does,
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
//! - Internal atom ids are `1..=atoms.len()`; an atom is *in the domain* once some rule instance
//!   can derive it; `fact` atoms are certainly true, and they never lose that status.
//! - A predicate is *complete* once every statement heading it is grounded; readers come after
//!   (or in the same component, where `not` literals on it stay).
//! - A positive body literal only matches atoms in the domain; a fact matched positively is
//!   removed from the ground body; `not a` with `a` a fact kills the instance, and `not a` with
//!   `a` of a complete predicate outside the domain is removed.
//! - Ground rules use internal ids; `simplify` renumbers them for aspif.

use hashbrown::HashMap;
use hashbrown::HashTable;
use smallvec::SmallVec;
use std::hash::BuildHasher;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span, WarningKind};
use crate::syntax::ast::{AggregateFunction, CmpOp, Sign};

use super::program::{
    AuxKind, Bindings, Body, DeadReason, DeadRule, ExternalValue, HeadKind, HeuristicModifier, Lit,
    Origin, RemovedLit, Rule, RuleOrigin, Rules, Weight,
};
use super::rewrite::{
    lit_vars, Compiled, NAgg, NAtom, NCondLit, NHead, NKind, NLit, NStmt, PredId,
};
use super::symbol::{SymData, SymId, Symbols};
use super::term::{Binding, NTerm};
use crate::base::intern::Sym;

/// Internal atom id, `1..`.
pub type AtomId = u32;

/// Why grounding stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StopReason {
    /// The configured size limit was exceeded.
    SizeLimit,
    /// The deadline passed.
    Deadline,
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
    /// Key: the values at the bound positions; value: its group in `groups`.
    map: HashMap<SmallVec<[SymId; 4]>, u32>,
    /// Domain positions of each key, increasing (append-only).
    groups: Vec<Vec<u32>>,
}

/// The atoms of one predicate.
#[derive(Default)]
struct Domain {
    /// Atoms in derivation order.
    atoms: Vec<AtomId>,
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
    /// Atom table, index `id - 1`.
    pub atoms: Vec<AtomInfo>,
    /// Atom of each predicate-atom symbol, by symbol id (0: none).
    sym_atom: Vec<AtomId>,
    /// Domains, by predicate.
    domains: Vec<Domain>,
    /// Ground rules over internal ids, stored flat (a program may ground to millions).
    pub rules: Rules,
    /// Origins parallel to `rules` (when provenance is on): the first instance of each rule.
    pub origins: Vec<Origin>,
    /// Further origins of rules that several instances ground to (when provenance is on).
    pub more_origins: HashMap<u32, Vec<Origin>>,
    /// Provenance: the statement being grounded.
    prov_stmt: ProvStmt,
    /// Provenance: the auxiliary being built (its kind and the bindings when it started).
    prov_aux: Option<(AuxKind, Bindings)>,
    /// Provenance: instances dropped during instantiation because a fact among their heads
    /// satisfies them (`simplify` keeps those with a head atom that ends up false).
    pub dead: Vec<DeadRule>,
    /// Provenance: the origins of each minimize element's conditions, parallel to `minimize`.
    pub minimize_origins: HashMap<MinKey, Vec<Vec<Origin>>>,
    /// Deduplication of `rules`.
    rule_set: HashTable<u32>,
    /// Hash of each rule in `rules` (so that growing `rule_set` does not rehash rules).
    rule_hashes: Vec<u64>,
    /// Hasher for `rule_set`.
    hasher: hashbrown::DefaultHashBuilder,
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
    notnot: HashMap<AtomId, AtomId>,
    /// CR application atoms by (statement, ground global values).
    cr_appl: HashMap<(u32, Vec<SymId>), AtomId>,
    /// Ground CR rules: application atom and label.
    pub cr_rules: Vec<(AtomId, String)>,
    /// Minimize elements: key to alternative conditions.
    pub minimize: HashMap<MinKey, Vec<Vec<Lit>>>,
    /// Insertion order of minimize keys.
    pub minimize_order: Vec<MinKey>,
    /// `#show t : body` instances.
    pub shows: Vec<(SymId, Vec<Lit>)>,
    /// Projected atoms.
    pub projections: Vec<AtomId>,
    /// Externals.
    pub externals: Vec<(AtomId, ExternalValue)>,
    /// Heuristics with internal atom ids.
    pub heuristics: Vec<super::program::Heuristic>,
    /// Edges.
    pub edges: Vec<super::program::Edge>,
    /// Node numbers of `#edge` terms.
    edge_nodes: HashMap<SymId, i32>,
    /// Rules emitted since the last deadline check.
    since_check: u32,
    /// Grounding a component naively: derived atoms are not marked as facts, since a later
    /// round may withdraw the rule that derived them.
    naive: bool,
    /// Computing a naive component's domain: aggregates over its predicates are assumed true.
    optimistic: bool,
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
type ElemInstance = (Vec<(Sign, AtomId)>, Vec<Lit>);

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
    /// A grounder over `syms` (which holds the symbols of the compiled program).
    pub fn new(
        syms: Symbols,
        num_preds: usize,
        diags: &'a mut Diagnostics,
        sources: Option<&'a SourceMap>,
        provenance: bool,
        limits: Limits,
    ) -> Grounder<'a> {
        let mut domains = Vec::with_capacity(num_preds);
        domains.resize_with(num_preds, Domain::default);
        Grounder {
            syms,
            atoms: Vec::new(),
            sym_atom: Vec::new(),
            domains,
            rules: Rules::new(),
            origins: Vec::new(),
            more_origins: HashMap::new(),
            prov_stmt: ProvStmt::default(),
            prov_aux: None,
            minimize_origins: HashMap::new(),
            dead: Vec::new(),
            rule_set: HashTable::new(),
            rule_hashes: Vec::new(),
            hasher: hashbrown::DefaultHashBuilder::default(),
            diags,
            sources,
            provenance,
            limits,
            stopped: None,
            reported: hashbrown::HashSet::new(),
            notnot: HashMap::new(),
            cr_appl: HashMap::new(),
            cr_rules: Vec::new(),
            minimize: HashMap::new(),
            minimize_order: Vec::new(),
            shows: Vec::new(),
            projections: Vec::new(),
            externals: Vec::new(),
            heuristics: Vec::new(),
            edges: Vec::new(),
            edge_nodes: HashMap::new(),
            since_check: 0,
            naive: false,
            optimistic: false,
        }
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
    pub fn aux(&mut self) -> AtomId {
        self.atoms.push(AtomInfo {
            sym: None,
            pred: u32::MAX,
            fact: false,
            in_domain: true,
            dom_pos: 0,
        });
        self.atoms.len() as AtomId
    }

    /// The atom of a predicate-atom symbol, created outside the domain if new.
    pub fn atom_of(&mut self, sym: SymId, pred: PredId) -> AtomId {
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
        let id = self.atoms.len() as AtomId;
        let i = sym.0 as usize;
        if i >= self.sym_atom.len() {
            self.sym_atom.resize((i + 1).max(self.syms.len()), 0);
        }
        self.sym_atom[i] = id;
        id
    }

    /// The atom of a symbol, if it exists.
    pub fn find_atom(&self, sym: SymId) -> Option<AtomId> {
        match self.sym_atom.get(sym.0 as usize) {
            Some(&a) if a != 0 => Some(a),
            _ => None,
        }
    }

    fn info(&self, a: AtomId) -> &AtomInfo {
        &self.atoms[a as usize - 1]
    }

    /// Puts an atom into its predicate's domain.
    fn derive(&mut self, a: AtomId) {
        let info = self.atoms[a as usize - 1];
        if info.in_domain || info.pred == u32::MAX {
            return;
        }
        let d = &mut self.domains[info.pred as usize];
        let pos = d.atoms.len() as u32;
        d.atoms.push(a);
        let i = &mut self.atoms[a as usize - 1];
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

    /// Frees the rule deduplication table once instantiation is over (simplification does
    /// not add rules through [`Grounder::add_rule`]); large programs need the memory.
    pub fn release_dedup(&mut self) {
        self.rule_set = HashTable::new();
        self.rule_hashes = Vec::new();
    }

    /// Adds a ground rule unless an equal one exists; returns whether it was added. With
    /// provenance, `origin` is recorded for the rule, also when it existed already.
    fn add_rule(&mut self, rule: Rule, origin: impl FnOnce(&mut Self) -> Origin) -> bool {
        assert_eq!(
            self.rule_hashes.len(),
            self.rules.len(),
            "add_rule after release_dedup"
        );
        let rule = rule.as_ref();
        let hash = self.hasher.hash_one(rule);
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
            self.origins.push(o);
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
        if self.origins[i as usize] == o {
            return;
        }
        let more = self.more_origins.entry(i).or_default();
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
        let hash = self.hasher.hash_one(rule);
        let rules = &self.rules;
        if let Some(&i) = self.rule_set.find(hash, |&i| rules.get(i as usize) == rule) {
            let o = origin(self);
            self.add_origin(i, o);
        }
    }

    /// Adds an auxiliary rule of the statement being grounded, recorded as an auxiliary of
    /// `kind` unless a construct (aggregate, condition, ...) or the statement says otherwise.
    fn add_aux_rule(&mut self, rule: Rule, kind: AuxKind) -> bool {
        self.add_rule(rule, |g| g.aux_origin(kind))
    }

    fn aux_origin(&self, kind: AuxKind) -> Origin {
        let (kind, bindings) = match &self.prov_aux {
            Some((k, b)) => (self.prov_stmt.aux.unwrap_or(*k), b.clone()),
            None => (self.prov_stmt.aux.unwrap_or(kind), Vec::new()),
        };
        Origin {
            rule: RuleOrigin::Auxiliary {
                of_stmt: self.prov_stmt.stmt,
                kind,
                bindings,
            },
            removed: Vec::new(),
        }
    }

    /// The bindings of the statement being grounded under `b` (provenance).
    fn bindings(&self, b: &Binding) -> Bindings {
        self.prov_stmt
            .names
            .iter()
            .enumerate()
            .filter_map(|(v, name)| {
                let name = (*name)?;
                b.get(v as u32).map(|s| (name.0, s.0))
            })
            .collect()
    }

    /// Enters an auxiliary construct of `kind` (provenance on and none entered yet): returns
    /// what to restore with [`Grounder::leave_aux`].
    fn enter_aux(&mut self, kind: AuxKind, b: &Binding) -> Option<Option<(AuxKind, Bindings)>> {
        if !self.provenance || self.prov_aux.is_some() {
            return None;
        }
        let bindings = self.bindings(b);
        Some(self.prov_aux.replace((kind, bindings)))
    }

    fn leave_aux(&mut self, saved: Option<Option<(AuxKind, Bindings)>>) {
        if let Some(s) = saved {
            self.prov_aux = s;
        }
    }

    /// Provenance: an instance of the statement being grounded failed at the body literal
    /// `sym` (`positive`: `sym` cannot be derived; else `not sym` with `sym` a fact). When the
    /// statement's head atoms are known under the bindings so far, the instance is recorded
    /// as a dead rule of those atoms (kept by `simplify` if one ends up false and the literal
    /// is still decided that way). Only the statement's own body counts, not the conditions
    /// of its aggregates; naive components (rounds repeated) record nothing.
    fn blocked(&mut self, ctx: &Ctx, positive: bool, sym: SymId, pred: PredId) {
        if self.prov_aux.is_some() || self.naive || self.optimistic {
            return;
        }
        let Some(atoms) = self.prov_stmt.head.take() else {
            return;
        };
        let mut head = Vec::with_capacity(atoms.len());
        for a in &atoms {
            let mut vals: SmallVec<[SymId; 8]> = SmallVec::new();
            for t in &a.args {
                match t.bound_by_binding(&ctx.binding) {
                    true => match t.eval(&mut self.syms, &ctx.binding) {
                        Ok(v) => vals.push(v),
                        Err(_) => break,
                    },
                    false => break,
                }
            }
            if vals.len() != a.args.len() {
                break;
            }
            let s = self.syms.fun(a.name, a.neg, &vals);
            head.push(self.atom_of(s, a.pred));
        }
        let complete = head.len() == atoms.len();
        self.prov_stmt.head = Some(atoms);
        if !complete || head.is_empty() {
            return;
        }
        let atom = self.atom_of(sym, pred);
        let bindings = self.bindings(&ctx.binding);
        let stmt = self.prov_stmt.stmt;
        let rule = match self.prov_stmt.aux {
            None => RuleOrigin::Statement { stmt, bindings },
            Some(kind) => RuleOrigin::Auxiliary {
                of_stmt: stmt,
                kind,
                bindings,
            },
        };
        self.dead.push(DeadRule {
            head,
            origins: vec![Origin {
                rule,
                removed: Vec::new(),
            }],
            why: DeadReason::Literal { positive, atom },
        });
    }

    /// The origin of an instance of `stmt` (its own rule) under the join state `ctx`: the
    /// statement (or, for a statement the rewriting made, the auxiliary of its kind), the
    /// bindings, and the body literals decided by grounding: a positive literal (or `not not
    /// a`) whose atom is a fact, `not a` whose atom cannot be derived.
    fn origin(&mut self, stmt: &NStmt, ctx: &Ctx) -> Origin {
        let bindings = self.bindings(&ctx.binding);
        let rule = match stmt.aux {
            None => RuleOrigin::Statement {
                stmt: stmt.stmt,
                bindings,
            },
            Some(kind) => RuleOrigin::Auxiliary {
                of_stmt: stmt.stmt,
                kind,
                bindings,
            },
        };
        let mut removed = Vec::new();
        for l in &stmt.body {
            let NLit::Pred { sign, atom } = l else {
                continue;
            };
            let Some(sym) = self.atom_sym(atom, &ctx.binding) else {
                continue;
            };
            match sign {
                Sign::Positive | Sign::NotNot => {
                    if let Some(a) = self.find_atom(sym).filter(|&a| self.info(a).fact) {
                        removed.push(RemovedLit {
                            positive: true,
                            atom: a,
                        });
                    }
                }
                Sign::Not => {
                    let kept = self
                        .find_atom(sym)
                        .is_some_and(|a| ctx.body.contains(&-(a as Lit)));
                    if !kept {
                        let a = self.atom_of(sym, atom.pred);
                        removed.push(RemovedLit {
                            positive: false,
                            atom: a,
                        });
                    }
                }
            }
        }
        Origin { rule, removed }
    }

    fn lookup_range(&self, pred: PredId, range: Option<Range>) -> Range {
        range.unwrap_or((0, self.domains[pred as usize].atoms.len() as u32))
    }

    /// Candidate domain positions in `range` for `atom` under the binding.
    fn candidates(&mut self, atom: &NAtom, b: &Binding, range: Range) -> Option<Candidates> {
        let mut mask = 0u64;
        let mut key: SmallVec<[SymId; 4]> = SmallVec::new();
        for (i, t) in atom.args.iter().enumerate() {
            if i < 64 && t.bound_by_binding(b) {
                let v = match t.eval(&mut self.syms, b) {
                    Ok(v) => v,
                    Err(span) => {
                        self.undefined(span);
                        return None;
                    }
                };
                mask |= 1 << i;
                key.push(v);
            }
        }
        if mask == 0 {
            return Some(Candidates::Range(range.0, range.1));
        }
        if key.len() == atom.args.len() {
            // Every argument is known: look the atom up directly (an atom whose symbol was
            // never created does not exist).
            let found = self
                .syms
                .find_fun(atom.name, atom.neg, &key)
                .and_then(|sym| self.find_atom(sym))
                .map(|a| *self.info(a))
                .filter(|info| info.in_domain && info.dom_pos >= range.0 && info.dom_pos < range.1)
                .map(|info| info.dom_pos);
            return Some(Candidates::One(found));
        }
        let slot = self.index(atom.pred, mask);
        let d = &mut self.domains[atom.pred as usize];
        let idx = &mut d.indexes[slot];
        let Some(&group) = idx.map.get(&key) else {
            return Some(Candidates::One(None));
        };
        let list = &idx.groups[group as usize];
        let lo = if range.0 == 0 {
            0
        } else {
            list.partition_point(|&p| p < range.0)
        };
        let hi = if range.1 as usize >= d.atoms.len() {
            list.len()
        } else {
            list.partition_point(|&p| p < range.1)
        };
        Some(Candidates::Group {
            index: slot as u32,
            group,
            lo: lo as u32,
            hi: hi as u32,
        })
    }

    /// The number of the index of `pred` on the positions of `mask`, created if needed and
    /// extended to every atom of the domain.
    fn index(&mut self, pred: PredId, mask: u64) -> usize {
        let d = &mut self.domains[pred as usize];
        let slot = match d.indexes.iter().position(|x| x.mask == mask) {
            Some(i) => i,
            None => {
                d.indexes.push(Index {
                    mask,
                    upto: 0,
                    map: HashMap::new(),
                    groups: Vec::new(),
                });
                d.indexes.len() - 1
            }
        };
        let idx = &mut d.indexes[slot];
        // Extend the index to the atoms derived since it was last used.
        while idx.upto < d.atoms.len() {
            let a = d.atoms[idx.upto];
            let sym = self.atoms[a as usize - 1]
                .sym
                .expect("predicate atom has a symbol");
            let args = self.syms.args(sym);
            let k: SmallVec<[SymId; 4]> = (0..args.len())
                .filter(|&i| i < 64 && mask & (1 << i) != 0)
                .map(|i| args[i])
                .collect();
            let groups = &mut idx.groups;
            let g = *idx.map.entry(k).or_insert_with(|| {
                groups.push(Vec::new());
                groups.len() as u32 - 1
            });
            idx.groups[g as usize].push(idx.upto as u32);
            idx.upto += 1;
        }
        slot
    }

    /// Grounds `lits[i..]` and calls `k` for every solution.
    fn join(
        &mut self,
        ctx: &mut Ctx,
        lits: &[NLit],
        i: usize,
        ranges: &[Option<Range>],
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        if self.stopped.is_some() {
            return;
        }
        let Some(lit) = lits.get(i) else {
            k(self, ctx);
            return;
        };
        let mark = ctx.binding.mark();
        let blen = ctx.body.len();
        match lit {
            NLit::Bool(true) => self.join(ctx, lits, i + 1, ranges, k),
            NLit::Bool(false) => {}
            NLit::Pred {
                sign: Sign::Positive,
                atom,
            } => {
                let range = self.lookup_range(atom.pred, ranges.get(i).copied().flatten());
                let Some(cands) = self.candidates(atom, &ctx.binding, range) else {
                    return;
                };
                let (lo, hi) = match cands {
                    Candidates::Range(lo, hi) => (lo, hi),
                    Candidates::One(None) => {
                        // With provenance, a fully bound atom that does not exist stops an
                        // instance: record it (not when a semi-naive range hid the atom).
                        if self.provenance
                            && self.prov_aux.is_none()
                            && ranges.get(i).copied().flatten().is_none()
                            && atom.args.iter().all(|t| t.bound_by_binding(&ctx.binding))
                        {
                            if let Some(sym) = self.atom_sym(atom, &ctx.binding) {
                                self.blocked(ctx, true, sym, atom.pred);
                            }
                        }
                        return;
                    }
                    Candidates::One(Some(p)) => (p, p + 1),
                    Candidates::Group { lo, hi, .. } => (lo, hi),
                };
                for j in lo..hi {
                    let d = &self.domains[atom.pred as usize];
                    let pos = match cands {
                        Candidates::Group { index, group, .. } => {
                            d.indexes[index as usize].groups[group as usize][j as usize]
                        }
                        _ => j,
                    };
                    let a = d.atoms[pos as usize];
                    let sym = self.info(a).sym.expect("predicate atom has a symbol");
                    let mut ok = true;
                    for (j, t) in atom.args.iter().enumerate() {
                        let s = self.syms.args(sym)[j];
                        if !t.matches(&mut self.syms, s, &mut ctx.binding) {
                            ok = false;
                            break;
                        }
                    }
                    if ok {
                        if !self.info(a).fact {
                            ctx.body.push(a as Lit);
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                    ctx.body.truncate(blen);
                    if self.stopped.is_some() {
                        return;
                    }
                }
            }
            NLit::Pred { sign, atom } => {
                let Some(sym) = self.atom_sym(atom, &ctx.binding) else {
                    return;
                };
                let complete = self.domains[atom.pred as usize].complete;
                let existing = self.find_atom(sym);
                let (in_domain, fact) = existing.map_or((false, false), |a| {
                    (self.info(a).in_domain, self.info(a).fact)
                });
                match sign {
                    Sign::Not => {
                        // not a: true when a cannot be derived, false when a is a fact.
                        if fact {
                            if self.provenance {
                                self.blocked(ctx, false, sym, atom.pred);
                            }
                            return;
                        }
                        if !complete || in_domain {
                            let a = self.atom_of(sym, atom.pred);
                            ctx.body.push(-(a as Lit));
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    _ => {
                        // not not a: false when a cannot be derived, true when a is a fact.
                        if complete && !in_domain {
                            if self.provenance {
                                self.blocked(ctx, true, sym, atom.pred);
                            }
                            return;
                        }
                        if !fact {
                            let a = self.atom_of(sym, atom.pred);
                            let saved = self.enter_aux(AuxKind::DoubleNegation, &ctx.binding);
                            let d = self.not_aux(a);
                            self.leave_aux(saved);
                            ctx.body.push(-(d as Lit));
                        }
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                }
                ctx.body.truncate(blen);
            }
            NLit::Cmp { op, lhs, rhs } => {
                let lb = lhs.bound_by_binding(&ctx.binding);
                let rb = rhs.bound_by_binding(&ctx.binding);
                if lb && rb {
                    // Integer arithmetic is compared without creating symbols; anything else
                    // (and undefined operations, which warn) goes the general way.
                    let holds = match (
                        lhs.eval_int(&self.syms, &ctx.binding),
                        rhs.eval_int(&self.syms, &ctx.binding),
                    ) {
                        (Some(l), Some(r)) => cmp_ints(*op, l, r),
                        _ => {
                            let (Some(l), Some(r)) =
                                (self.eval(lhs, &ctx.binding), self.eval(rhs, &ctx.binding))
                            else {
                                return;
                            };
                            cmp_holds(&self.syms, *op, l, r)
                        }
                    };
                    if holds {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                } else {
                    // X = t binds the unbound side.
                    let (pat, val) = if rb { (lhs, rhs) } else { (rhs, lhs) };
                    let Some(v) = self.eval(val, &ctx.binding) else {
                        return;
                    };
                    if pat.matches(&mut self.syms, v, &mut ctx.binding) {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                }
            }
            NLit::Interval { pat, lo, hi } => {
                let (Some(l), Some(h)) = (self.eval(lo, &ctx.binding), self.eval(hi, &ctx.binding))
                else {
                    return;
                };
                let (Some(l), Some(h)) = (self.syms.num(l), self.syms.num(h)) else {
                    return;
                };
                for v in l..=h {
                    let s = self.syms.int(v);
                    if pat.matches(&mut self.syms, s, &mut ctx.binding) {
                        self.join(ctx, lits, i + 1, ranges, k);
                    }
                    ctx.binding.undo(mark);
                    if self.stopped.is_some() {
                        return;
                    }
                }
            }
            NLit::Agg(agg)
                if self.optimistic && agg.binder.is_none() && self.reads_incomplete(agg) =>
            {
                // Computing the domain of a component with recursive aggregates: assume the
                // aggregate can hold, so no atom is missed; the final round evaluates it.
                self.join(ctx, lits, i + 1, ranges, k);
            }
            NLit::Agg(agg) if agg.elems.len() == 1 && agg.elems[0].lit.is_some() => {
                self.conditional(ctx, agg, &mut |g, ctx| g.join(ctx, lits, i + 1, ranges, k));
                ctx.binding.undo(mark);
                ctx.body.truncate(blen);
            }
            NLit::Agg(agg) => {
                self.aggregate(ctx, agg, &mut |g, ctx| g.join(ctx, lits, i + 1, ranges, k));
                ctx.binding.undo(mark);
                ctx.body.truncate(blen);
            }
        }
    }

    fn atom_sym(&mut self, atom: &NAtom, b: &Binding) -> Option<SymId> {
        let mut vals: SmallVec<[SymId; 8]> = SmallVec::new();
        for t in &atom.args {
            vals.push(self.eval(t, b)?);
        }
        Some(self.syms.fun(atom.name, atom.neg, &vals))
    }

    /// `d :- not a.`, so that `not d` stands for `not not a`.
    fn not_aux(&mut self, a: AtomId) -> AtomId {
        if let Some(&d) = self.notnot.get(&a) {
            return d;
        }
        let d = self.aux();
        self.notnot.insert(a, d);
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![d],
                body: Body::Normal(vec![-(a as Lit)]),
            },
            AuxKind::DoubleNegation,
        );
        d
    }

    /// Defines an auxiliary atom true exactly when one of `alternatives` (conjunctions) holds;
    /// a single one-literal alternative is returned as is.
    fn disjunction_lit(&mut self, alternatives: &[Vec<Lit>]) -> Lit {
        if alternatives.len() == 1 && alternatives[0].len() == 1 {
            return alternatives[0][0];
        }
        let a = self.aux();
        for alt in alternatives {
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head: vec![a],
                    body: Body::Normal(alt.clone()),
                },
                AuxKind::Aggregate,
            );
        }
        if alternatives.iter().any(|c| c.is_empty()) {
            self.atoms[a as usize - 1].fact = true;
        }
        a as Lit
    }

    /// True when an element condition of `agg` reads a predicate still being grounded.
    fn reads_incomplete(&self, agg: &NAgg) -> bool {
        let mut preds = Vec::new();
        for e in &agg.elems {
            e.cond.iter().for_each(|l| lit_preds(l, &mut preds));
            e.lit_lits().for_each(|l| lit_preds(l, &mut preds));
        }
        preds.iter().any(|&p| !self.domains[p as usize].complete)
    }

    /// The default negation of a literal: `not a` for `a`, and for `not a` an atom standing
    /// for `not not a` (never collapsed to `a`, which would add a positive dependency).
    fn negate_lit(&mut self, l: Lit) -> Lit {
        if l > 0 {
            -l
        } else {
            -(self.not_aux((-l) as AtomId) as Lit)
        }
    }

    /// `not (c1, ..., cn)` as one literal.
    fn not_conj(&mut self, c: &[Lit]) -> Lit {
        if c.len() == 1 && c[0] > 0 {
            return -c[0];
        }
        let a = self.aux();
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![a],
                body: Body::Normal(c.to_vec()),
            },
            AuxKind::Condition,
        );
        -(a as Lit)
    }

    /// A conditional body literal `l : c`: for each instance of `c`, some instance of `l` must
    /// hold (`l`'s pools, intervals and local variables give alternatives). An instance with a
    /// certain condition contributes `l` itself (positively, as gringo keeps it); otherwise an
    /// auxiliary atom `x :- l.  x :- not c.` stands for `c -> l`.
    fn conditional(&mut self, ctx: &mut Ctx, agg: &NAgg, k: &mut dyn FnMut(&mut Self, &mut Ctx)) {
        self.in_aux(
            AuxKind::Condition,
            ctx,
            &mut |g, ctx, k| g.conditional_inner(ctx, agg, k),
            k,
        );
    }

    fn conditional_inner(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        let e = &agg.elems[0];
        let alts = e.lit.as_deref().expect("conditional literal");
        let blen = ctx.body.len();
        // Per condition instance: its literals, and the alternatives of `l` (None when none
        // can hold, an empty alternative when one certainly holds).
        let mut found: Vec<CondInstance> = Vec::new();
        self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
            let cond = ctx.body[blen..].to_vec();
            let b2 = ctx.body.len();
            let mut sols: Vec<Vec<Lit>> = Vec::new();
            for alt in alts {
                g.join(ctx, alt, 0, &[], &mut |_, ctx| {
                    let s = ctx.body[b2..].to_vec();
                    if !sols.contains(&s) {
                        sols.push(s);
                    }
                });
            }
            ctx.body.truncate(b2);
            let sol = if sols.iter().any(|s| s.is_empty()) {
                Some(Vec::new())
            } else if sols.is_empty() {
                None
            } else {
                Some(sols)
            };
            found.push((cond, sol));
        });
        ctx.body.truncate(blen);
        let mut lits = Vec::new();
        for (cond, sol) in found {
            match (cond.is_empty(), sol) {
                (_, Some(s)) if s.is_empty() => {}
                (true, None) => return,
                (true, Some(s)) if s.len() == 1 => lits.extend(s.into_iter().flatten()),
                (true, Some(s)) => lits.push(self.disjunction_lit(&s)),
                (false, None) => lits.push(self.not_conj(&cond)),
                (false, Some(s)) => {
                    // x :- l.  x :- not c.  and x | k :- not not l, with k :- c and c_i :- k
                    // for the positive c_i (gringo's encoding: c -> l keeps c in the reduct
                    // when c depends on x).
                    let nc = self.not_conj(&cond);
                    let x = self.aux();
                    for body in s.iter().cloned().chain([vec![nc]]) {
                        self.add_aux_rule(Rule::normal(&[x], &body), AuxKind::Condition);
                    }
                    let k = if cond.len() == 1 && cond[0] > 0 {
                        Some(cond[0] as AtomId)
                    } else if cond.iter().any(|&c| c > 0) {
                        let k = self.aux();
                        self.add_aux_rule(Rule::normal(&[k], &cond), AuxKind::Condition);
                        for &c in cond.iter().filter(|&&c| c > 0) {
                            self.add_aux_rule(
                                Rule::normal(&[c as AtomId], &[k as Lit]),
                                AuxKind::Condition,
                            );
                        }
                        Some(k)
                    } else {
                        None
                    };
                    if let Some(k) = k {
                        let t = self.disjunction_lit(&s);
                        let nt = self.negate_lit(t);
                        let nnt = self.negate_lit(nt);
                        self.add_aux_rule(Rule::normal(&[x, k], &[nnt]), AuxKind::Condition);
                    }
                    lits.push(x as Lit);
                }
            }
        }
        ctx.body.extend(lits);
        k(self, ctx);
        ctx.body.truncate(blen);
    }

    /// Grounds the elements of an aggregate and continues with each way it can hold; its
    /// auxiliary rules are recorded as the aggregate's (provenance).
    fn aggregate(&mut self, ctx: &mut Ctx, agg: &NAgg, k: &mut dyn FnMut(&mut Self, &mut Ctx)) {
        self.in_aux(
            AuxKind::Aggregate,
            ctx,
            &mut |g, ctx, k| g.aggregate_inner(ctx, agg, k),
            k,
        );
    }

    /// Runs `f` (a construct that calls its continuation `k`) inside the auxiliary construct
    /// `kind` for provenance, leaving it while `k` runs (the rest of the body is the
    /// statement's own).
    fn in_aux(
        &mut self,
        kind: AuxKind,
        ctx: &mut Ctx,
        f: &mut dyn FnMut(&mut Self, &mut Ctx, Cont<'_, 'a>),
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        let Some(outer) = self.enter_aux(kind, &ctx.binding) else {
            return f(self, ctx, k);
        };
        let mut other = outer;
        f(self, ctx, &mut |g: &mut Self, ctx: &mut Ctx| {
            std::mem::swap(&mut g.prov_aux, &mut other);
            k(g, ctx);
            std::mem::swap(&mut g.prov_aux, &mut other);
        });
        self.prov_aux = other;
    }

    fn aggregate_inner(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        // Ground elements: tuple -> alternative conditions (an empty condition is certain).
        // An aggregate may have hundreds of thousands of elements (`#count { X,Y : path(X,Y) }`),
        // so the tuples are kept flat, found through a table of their indexes, and a certain
        // element keeps no conditions.
        let mut tuples = ElemTuples::default();
        let mut conds: Vec<Vec<Vec<Lit>>> = Vec::new();
        let mut certain: Vec<bool> = Vec::new();
        for e in &agg.elems {
            let blen = ctx.body.len();
            let mut t: Vec<SymId> = Vec::with_capacity(e.terms.len());
            self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
                t.clear();
                for term in &e.terms {
                    match g.eval(term, &ctx.binding) {
                        Some(v) => t.push(v),
                        None => return,
                    }
                }
                let i = tuples.index(&t);
                if i == conds.len() {
                    conds.push(Vec::new());
                    certain.push(false);
                }
                let c = &ctx.body[blen..];
                if c.is_empty() {
                    certain[i] = true;
                } else if !certain[i] && !conds[i].iter().any(|x| x.as_slice() == c) {
                    conds[i].push(c.to_vec());
                }
            });
            ctx.body.truncate(blen);
        }
        // Weights: integers for sums and counts, symbols for min/max.
        let mut elems: Vec<(SymId, Vec<Vec<Lit>>)> = Vec::new();
        for (i, c) in conds.into_iter().enumerate() {
            let t = tuples.get(i);
            let w = match agg.func {
                AggregateFunction::Count => self.syms.int(1),
                _ => match t.first() {
                    Some(&w) => w,
                    None => continue,
                },
            };
            if matches!(
                agg.func,
                AggregateFunction::Sum | AggregateFunction::SumPlus
            ) && self.syms.num(w).is_none()
            {
                continue;
            }
            if agg.func == AggregateFunction::SumPlus && self.syms.num(w).is_some_and(|n| n <= 0) {
                continue;
            }
            elems.push((w, if certain[i] { Vec::new() } else { c }));
        }
        // Guard values.
        let mut guards: Vec<(CmpOp, SymId)> = Vec::new();
        for (i, (op, t)) in agg.guards.iter().enumerate() {
            if Some(i) == agg.binder {
                continue;
            }
            let Some(v) = self.eval(t, &ctx.binding) else {
                return;
            };
            guards.push((*op, v));
        }
        let candidates: Vec<Option<SymId>> = match agg.binder {
            None => vec![None],
            Some(_) => self
                .possible_values(agg.func, &elems)
                .into_iter()
                .map(Some)
                .collect(),
        };
        // A positive aggregate over atoms still being grounded may need the translation that
        // keeps Ferraris' semantics when it is not monotone (see `sum_saturated`).
        let recursive = agg.sign == Sign::Positive && self.reads_incomplete(agg);
        let mark = ctx.binding.mark();
        let blen = ctx.body.len();
        for cand in candidates {
            let mut gs = guards.clone();
            if let Some(v) = cand {
                let pat = &agg.guards[agg.binder.expect("binder")].1;
                if !pat.matches(&mut self.syms, v, &mut ctx.binding) {
                    ctx.binding.undo(mark);
                    continue;
                }
                gs.push((CmpOp::Eq, v));
            }
            let mut lits: Vec<Lit> = Vec::new();
            let mut truth = true;
            for (op, v) in gs {
                match self.guard_truth(agg.func, &elems, op, v, recursive) {
                    Truth::True => {}
                    Truth::False => {
                        truth = false;
                        break;
                    }
                    Truth::Lits(l) => lits.extend(l),
                }
            }
            // Apply the default-negation sign.
            let proceed = match agg.sign {
                Sign::Positive => {
                    if truth {
                        ctx.body.extend(lits);
                    }
                    truth
                }
                Sign::Not => {
                    if !truth {
                        true
                    } else if lits.is_empty() {
                        false
                    } else {
                        let a = self.disjunction_lit(&[lits]);
                        let n = self.negate_lit(a);
                        ctx.body.push(n);
                        true
                    }
                }
                Sign::NotNot => {
                    if !truth {
                        false
                    } else if lits.is_empty() {
                        true
                    } else {
                        let a = self.disjunction_lit(&[lits]);
                        let n = self.disjunction_lit(&[vec![-a], vec![-a]]);
                        ctx.body.push(-n);
                        true
                    }
                }
            };
            if proceed {
                k(self, ctx);
            }
            ctx.binding.undo(mark);
            ctx.body.truncate(blen);
            if self.stopped.is_some() {
                return;
            }
        }
    }

    /// The values an aggregate can take (for `X = #agg{...}`).
    fn possible_values(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
    ) -> Vec<SymId> {
        match func {
            AggregateFunction::Min | AggregateFunction::Max => {
                let mut vals: Vec<SymId> = Vec::new();
                let certain: Vec<SymId> = elems
                    .iter()
                    .filter(|e| e.1.is_empty())
                    .map(|e| e.0)
                    .collect();
                let best_certain = certain.iter().copied().reduce(|a, b| {
                    let o = self.syms.compare(a, b);
                    if (func == AggregateFunction::Min) == o.is_le() {
                        a
                    } else {
                        b
                    }
                });
                for (w, _) in elems {
                    if let Some(c) = best_certain {
                        let o = self.syms.compare(*w, c);
                        let better = if func == AggregateFunction::Min {
                            o.is_le()
                        } else {
                            o.is_ge()
                        };
                        if !better {
                            continue;
                        }
                    }
                    if !vals.contains(w) {
                        vals.push(*w);
                    }
                }
                if best_certain.is_none() {
                    vals.push(if func == AggregateFunction::Min {
                        self.syms.sup()
                    } else {
                        self.syms.inf()
                    });
                }
                vals
            }
            _ => {
                // Sums reachable by subsets of the uncertain elements, plus the certain sum.
                let mut base: i64 = 0;
                let mut sums: hashbrown::HashSet<i64> = hashbrown::HashSet::new();
                sums.insert(0);
                for (w, c) in elems {
                    let n = self.syms.num(*w).unwrap_or(0) as i64;
                    if c.is_empty() {
                        base += n;
                    } else {
                        let next: Vec<i64> = sums.iter().map(|s| s + n).collect();
                        sums.extend(next);
                        if sums.len() > 100_000 {
                            self.stopped = Some(StopReason::SizeLimit);
                            return Vec::new();
                        }
                    }
                }
                let mut v: Vec<i64> = sums.into_iter().map(|s| s + base).collect();
                v.sort_unstable();
                v.into_iter()
                    .filter_map(|s| i32::try_from(s).ok())
                    .map(|s| self.syms.int(s))
                    .collect()
            }
        }
    }

    /// When `aggregate op v` holds, as literals.
    fn guard_truth(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
        recursive: bool,
    ) -> Truth {
        match func {
            AggregateFunction::Min | AggregateFunction::Max => {
                if recursive && op == CmpOp::Ne {
                    return self.minmax_saturated(func == AggregateFunction::Max, elems, v);
                }
                self.minmax_truth(func, elems, op, v)
            }
            _ => {
                let Some(k) = self.syms.num(v) else {
                    // An integer compared with a non-integer: fixed by the term order.
                    let zero = self.syms.int(0);
                    return if cmp_holds(&self.syms, op, zero, v) {
                        Truth::True
                    } else {
                        Truth::False
                    };
                };
                let k = k as i64;
                // Over atoms still being grounded, a sum whose uncertain weights are all
                // negative is read as `-sum op' -k` with positive weights, so that `<=` stays
                // the monotone comparison it is (a positive dependency), as gringo does.
                if recursive && self.all_negative(elems) {
                    let flipped: Vec<(SymId, Vec<Vec<Lit>>)> = elems
                        .iter()
                        .map(|(w, c)| {
                            let n = self.syms.num(*w).unwrap_or(0);
                            (self.syms.int(n.wrapping_neg()), c.clone())
                        })
                        .collect();
                    let nk = self.syms.int((-k) as i32);
                    let op = super::rewrite::flip_cmp(op);
                    return self.guard_truth(func, &flipped, op, nk, recursive);
                }
                // `!=` at an end of the possible sums is one-sided: keep it monotone (a
                // positive dependency) rather than the negation of `=`.
                let (lo, hi) = self.sum_range(elems);
                let op = match op {
                    CmpOp::Ne if k < lo || k > hi => return Truth::True,
                    CmpOp::Ne if k == lo => CmpOp::Gt,
                    CmpOp::Ne if k == hi => CmpOp::Lt,
                    op => op,
                };
                if recursive && self.sum_nonmonotone(elems, op, k) {
                    // Each comparison as a disjunction of monotone sums `dir * sum >= bound`;
                    // `=` is the conjunction of two (Ferraris' semantics splits conjunctions).
                    return match op {
                        CmpOp::Ge => self.sum_saturated(elems, &[(1, k)]),
                        CmpOp::Gt => self.sum_saturated(elems, &[(1, k + 1)]),
                        CmpOp::Le => self.sum_saturated(elems, &[(-1, -k)]),
                        CmpOp::Lt => self.sum_saturated(elems, &[(-1, 1 - k)]),
                        CmpOp::Ne => self.sum_saturated(elems, &[(1, k + 1), (-1, 1 - k)]),
                        CmpOp::Eq => {
                            let a = self.sum_saturated(elems, &[(1, k)]);
                            let b = self.sum_saturated(elems, &[(-1, -k)]);
                            conj(a, b)
                        }
                    };
                }
                match op {
                    CmpOp::Ge => self.sum_ge(elems, k),
                    CmpOp::Gt => self.sum_ge(elems, k + 1),
                    CmpOp::Le => {
                        let t = self.sum_ge(elems, k + 1);
                        negate(self, t)
                    }
                    CmpOp::Lt => {
                        let t = self.sum_ge(elems, k);
                        negate(self, t)
                    }
                    CmpOp::Eq => {
                        let a = self.sum_ge(elems, k);
                        let b = self.sum_ge(elems, k + 1);
                        let nb = negate(self, b);
                        conj(a, nb)
                    }
                    CmpOp::Ne => {
                        let a = self.sum_ge(elems, k);
                        let b = self.sum_ge(elems, k + 1);
                        let nb = negate(self, b);
                        let eq = conj(a, nb);
                        negate(self, eq)
                    }
                }
            }
        }
    }

    /// `sum >= k` over weighted elements: true, false, or an auxiliary atom defined by a weight
    /// rule `aux :- k' { l = w, ... }` (negative weights turned into complements).
    fn sum_ge(&mut self, elems: &[(SymId, Vec<Vec<Lit>>)], k: i64) -> Truth {
        let mut bound = k;
        let mut lits: Vec<(Lit, Weight)> = Vec::new();
        let mut max_extra: i64 = 0;
        // Weights of the same literal add up (gringo does the same: `-1:a; 1:a` weighs 0).
        let mut merged: Vec<(Lit, i64)> = Vec::new();
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                bound -= w;
                continue;
            }
            let l = self.disjunction_lit(c);
            match merged.iter_mut().find(|(x, _)| *x == l) {
                Some(e) => e.1 += w,
                None => merged.push((l, w)),
            }
        }
        for (l, w) in merged {
            if w > 0 {
                lits.push((l, w));
                max_extra += w;
            } else if w < 0 {
                // w*l == w + (-w)*(not l)
                bound -= w;
                let nl = self.negate_lit(l);
                lits.push((nl, -w));
                max_extra += -w;
            }
        }
        if bound <= 0 {
            return Truth::True;
        }
        if bound > max_extra {
            return Truth::False;
        }
        let a = self.aux();
        let body = if lits.iter().all(|&(_, w)| w == 1) && bound as usize == lits.len() {
            Body::Normal(lits.iter().map(|&(l, _)| l).collect())
        } else {
            Body::Weight { lower: bound, lits }
        };
        self.add_aux_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![a],
                body,
            },
            AuxKind::Aggregate,
        );
        Truth::Lits(vec![a as Lit])
    }

    /// True when some uncertain weight is negative and none is positive.
    fn all_negative(&self, elems: &[(SymId, Vec<Vec<Lit>>)]) -> bool {
        let signs = |pos: bool| {
            elems.iter().any(|(w, c)| {
                !c.is_empty()
                    && self
                        .syms
                        .num(*w)
                        .is_some_and(|n| if pos { n > 0 } else { n < 0 })
            })
        };
        signs(false) && !signs(true)
    }

    /// The least and the greatest sum the elements can take.
    fn sum_range(&self, elems: &[(SymId, Vec<Vec<Lit>>)]) -> (i64, i64) {
        let (mut lo, mut hi) = (0i64, 0i64);
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                lo += w;
                hi += w;
            } else if w < 0 {
                lo += w;
            } else {
                hi += w;
            }
        }
        (lo, hi)
    }

    /// True when `sum op k` is not monotone in the truth of the elements' literals: the
    /// uncertain weights have both signs, or `op` is `!=` with `k` strictly between the least
    /// and the greatest possible sum (gringo's NONMONOTONE analysis).
    fn sum_nonmonotone(&self, elems: &[(SymId, Vec<Vec<Lit>>)], op: CmpOp, k: i64) -> bool {
        let (lo, hi) = self.sum_range(elems);
        let mixed = elems
            .iter()
            .any(|(w, c)| !c.is_empty() && self.syms.num(*w).is_some_and(|n| n > 0))
            && elems
                .iter()
                .any(|(w, c)| !c.is_empty() && self.syms.num(*w).is_some_and(|n| n < 0));
        mixed || (op == CmpOp::Ne && lo < k && k < hi)
    }

    /// `sum op k` for a non-monotone comparison over atoms still being grounded, as the
    /// disjunction of monotone sums `dir * sum >= bound` (`dir` is 1 or -1), see `saturated`.
    fn sum_saturated(
        &mut self,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        disjuncts: &[(i64, i64)],
    ) -> Truth {
        let mut certain: i64 = 0;
        let mut merged: Vec<(Lit, i64)> = Vec::new();
        for (w, c) in elems {
            let w = self.syms.num(*w).unwrap_or(0) as i64;
            if c.is_empty() {
                certain += w;
                continue;
            }
            let l = self.disjunction_lit(c);
            match merged.iter_mut().find(|(x, _)| *x == l) {
                Some(e) => e.1 += w,
                None => merged.push((l, w)),
            }
        }
        merged.retain(|&(_, w)| w != 0);
        let parts: Vec<(Vec<(Lit, i64)>, i64)> = disjuncts
            .iter()
            .map(|&(dir, k)| {
                let lits = merged.iter().map(|&(l, w)| (l, dir * w)).collect();
                (lits, k - dir * certain)
            })
            .collect();
        self.saturated(parts)
    }

    /// An atom `A` for a disjunction of weighted sums `sum_i w_i * l_i >= bound` over element
    /// literals some of which are still being grounded, with Ferraris' semantics however the
    /// weights are signed (Alviano, Faber, Gebser: "Rewriting recursive aggregates in answer
    /// set programming: back to monotonicity", TPLP 2015; gringo translates so too). A literal
    /// `l` weighing `-w < 0` counts as its complement with weight `w` (the bound grows by `w`),
    /// which makes every disjunct monotone; the complement of an atom of the current component
    /// is an atom `c` saturated on `A`, so that `A` keeps its positive dependency on `l`:
    ///   c :- not l.   c :- A.   c | l :- not not A.
    /// Other complements are default negations. Then `A :- bound' { lits = weights }` for each
    /// disjunct that can hold; `True` when one always holds, `False` when none can.
    fn saturated(&mut self, disjuncts: Vec<(Vec<(Lit, i64)>, i64)>) -> Truth {
        let mut live: Vec<(Vec<(Lit, i64)>, i64)> = Vec::new();
        for (lits, k) in disjuncts {
            let lits: Vec<(Lit, i64)> = lits.into_iter().filter(|&(_, w)| w != 0).collect();
            let bound = k - lits
                .iter()
                .filter(|&&(_, w)| w < 0)
                .map(|&(_, w)| w)
                .sum::<i64>();
            let max: i64 = lits.iter().map(|&(_, w)| w.abs()).sum();
            if bound <= 0 {
                return Truth::True;
            }
            if bound <= max {
                live.push((lits, bound));
            }
        }
        if live.is_empty() {
            return Truth::False;
        }
        let a = self.aux();
        let mut complements: Vec<(Lit, Lit)> = Vec::new();
        for (lits, bound) in live {
            let mut body: Vec<(Lit, Weight)> = Vec::new();
            for (l, w) in lits {
                if w > 0 {
                    body.push((l, w));
                    continue;
                }
                let c = match complements.iter().find(|(x, _)| *x == l) {
                    Some(&(_, c)) => c,
                    None => {
                        let c = self.complement(l, a);
                        complements.push((l, c));
                        c
                    }
                };
                body.push((c, -w));
            }
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head: vec![a],
                    body: Body::Weight {
                        lower: bound,
                        lits: body,
                    },
                },
                AuxKind::Aggregate,
            );
        }
        Truth::Lits(vec![a as Lit])
    }

    /// The complement of an element literal `l` inside the saturated atom `a` (see
    /// `saturated`).
    fn complement(&mut self, l: Lit, a: AtomId) -> Lit {
        let recursive = l > 0 && {
            let p = self.info(l as AtomId).pred;
            p == u32::MAX || !self.domains[p as usize].complete
        };
        if !recursive {
            return self.negate_lit(l);
        }
        let c = self.aux();
        let not_a = self.not_aux(a);
        for (head, body) in [
            (vec![c], vec![-l]),
            (vec![c], vec![a as Lit]),
            (vec![c, l as AtomId], vec![-(not_a as Lit)]),
        ] {
            self.add_aux_rule(
                Rule {
                    head_kind: HeadKind::Disjunction,
                    head,
                    body: Body::Normal(body),
                },
                AuxKind::Aggregate,
            );
        }
        c as Lit
    }

    /// `#max != v` over atoms still being grounded (not monotone), with Ferraris' semantics:
    /// the maximum is above `v` (some element above `v` holds) or below it (no element at or
    /// above `v` holds): `#count{above} >= 1` or `-#count{at v} >= 0`, see `saturated`.
    /// `#min` is the mirror image.
    fn minmax_saturated(
        &mut self,
        is_max: bool,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        v: SymId,
    ) -> Truth {
        let mut beyond: Vec<(Lit, i64)> = Vec::new();
        let mut at: Vec<(Lit, i64)> = Vec::new();
        let mut at_certain = false;
        for (w, c) in elems {
            let o = self.syms.compare(*w, v);
            let past = if is_max { o.is_gt() } else { o.is_lt() };
            if past {
                if c.is_empty() {
                    return Truth::True;
                }
                let l = self.disjunction_lit(c);
                beyond.push((l, 1));
            } else if o.is_eq() {
                if c.is_empty() {
                    at_certain = true;
                    continue;
                }
                let l = self.disjunction_lit(c);
                at.push((l, -1));
            }
        }
        let mut parts = vec![(beyond, 1)];
        if !at_certain {
            parts.push((at, 0));
        }
        self.saturated(parts)
    }

    /// `#min`/`#max` compared with `v`. With `m` the extremum (`#inf` for an empty `#max`,
    /// `#sup` for an empty `#min`): `max >= v` iff some weight is `>= v` (or `v` is `#inf`),
    /// `max <= v` iff not `max > v`; `#min` is the mirror image.
    fn minmax_truth(
        &mut self,
        func: AggregateFunction,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
    ) -> Truth {
        let is_max = func == AggregateFunction::Max;
        match op {
            CmpOp::Eq => {
                let a = self.minmax_dir(is_max, elems, CmpOp::Ge, v);
                let b = self.minmax_dir(is_max, elems, CmpOp::Le, v);
                conj(a, b)
            }
            CmpOp::Ne => {
                let a = self.minmax_dir(is_max, elems, CmpOp::Ge, v);
                let b = self.minmax_dir(is_max, elems, CmpOp::Le, v);
                let eq = conj(a, b);
                negate(self, eq)
            }
            op => self.minmax_dir(is_max, elems, op, v),
        }
    }

    fn minmax_dir(
        &mut self,
        is_max: bool,
        elems: &[(SymId, Vec<Vec<Lit>>)],
        op: CmpOp,
        v: SymId,
    ) -> Truth {
        let toward = if is_max {
            matches!(op, CmpOp::Ge | CmpOp::Gt)
        } else {
            matches!(op, CmpOp::Le | CmpOp::Lt)
        };
        if !toward {
            let complement = super::rewrite::negate_cmp(op);
            let t = self.minmax_dir(is_max, elems, complement, v);
            return negate(self, t);
        }
        let empty = if is_max {
            self.syms.inf()
        } else {
            self.syms.sup()
        };
        if cmp_holds(&self.syms, op, empty, v) {
            return Truth::True;
        }
        let mut alts: Vec<Vec<Lit>> = Vec::new();
        for (w, c) in elems {
            if cmp_holds(&self.syms, op, *w, v) {
                if c.is_empty() {
                    return Truth::True;
                }
                alts.extend(c.iter().cloned());
            }
        }
        if alts.is_empty() {
            Truth::False
        } else {
            Truth::Lits(vec![self.disjunction_lit(&alts)])
        }
    }

    /// Grounds one statement with the given ranges for its body literals.
    fn ground_stmt(&mut self, stmt: &NStmt, ranges: &[Option<Range>]) {
        if self.provenance {
            let names = &self.syms.names;
            let head = match (&stmt.kind, &stmt.head) {
                (NKind::Rule | NKind::Cr(_), NHead::Disj(es) | NHead::Choice(es))
                    if es.iter().all(|e| e.cond.is_empty() && e.conj.is_empty()) =>
                {
                    Some(es.iter().map(|e| e.atom.clone()).collect())
                }
                _ => None,
            };
            self.prov_stmt = ProvStmt {
                stmt: stmt.stmt,
                aux: stmt.aux,
                names: stmt
                    .var_names
                    .iter()
                    .map(|&n| (!names.resolve(n).starts_with('#')).then_some(n))
                    .collect(),
                head,
            };
        }
        let mut ctx = Ctx {
            binding: Binding::new(stmt.num_vars as usize),
            body: Vec::new(),
        };
        let order = self.join_order(stmt, ranges);
        if order.iter().enumerate().all(|(i, &j)| i == j) {
            self.join(&mut ctx, &stmt.body, 0, ranges, &mut |g, ctx| {
                g.emit(stmt, ctx)
            });
            return;
        }
        let body: Vec<NLit> = order.iter().map(|&j| stmt.body[j].clone()).collect();
        let ranges: Vec<Option<Range>> = order
            .iter()
            .map(|&j| ranges.get(j).copied().flatten())
            .collect();
        self.join(&mut ctx, &body, 0, &ranges, &mut |g, ctx| g.emit(stmt, ctx));
    }

    /// The order in which to join the body literals of `stmt`, given the ranges of its
    /// semi-naive literals: greedily, the evaluable literal expected to yield the fewest
    /// matches under the current domains (gringo orders bodies by such estimates too).
    /// Tests and bound comparisons come first, then assignments, then positive atoms by
    /// estimated matches: the domain's size in range divided by the number of distinct values
    /// on the bound positions (read from the index on those positions).
    ///
    /// Evaluability follows the planner's rules (`rewrite::plan`); an aggregate keeps every
    /// literal the planner put before it in front of it (so its global variables are bound as
    /// planned), and the variable an aggregate binds is bound by it alone.
    fn join_order(&mut self, stmt: &NStmt, ranges: &[Option<Range>]) -> Vec<usize> {
        let lits = &stmt.body;
        let n = lits.len();
        if n <= 1 {
            return (0..n).collect();
        }
        let mut bound = vec![false; stmt.num_vars as usize];
        // Variables bound by aggregates (as planned).
        let mut reserved = vec![false; stmt.num_vars as usize];
        for l in lits {
            if let NLit::Agg(a) = l {
                if let Some(NTerm::Var(v)) = a.binder.map(|i| &a.guards[i].1) {
                    reserved[*v as usize] = true;
                }
            }
        }
        let mut placed = vec![false; n];
        let mut order = Vec::with_capacity(n);
        let mut newly: Vec<u32> = Vec::new();
        while order.len() < n {
            let mut best: Option<(f64, usize)> = None;
            for (i, l) in lits.iter().enumerate() {
                if placed[i] {
                    continue;
                }
                newly.clear();
                let cost = match l {
                    NLit::Bool(_) => Some(0.0),
                    NLit::Pred { sign, atom } if *sign != Sign::Positive => {
                        atom.args.iter().all(|t| t.bound_by(&bound)).then_some(0.0)
                    }
                    NLit::Pred { atom, .. } => {
                        if atom.args.iter().all(|t| t.binds(&bound, &mut newly)) {
                            let range =
                                self.lookup_range(atom.pred, ranges.get(i).copied().flatten());
                            let size = range.1.saturating_sub(range.0) as f64;
                            let mut mask = 0u64;
                            for (k, t) in atom.args.iter().enumerate() {
                                if k < 64 && t.bound_by(&bound) {
                                    mask |= 1 << k;
                                }
                            }
                            Some(if newly.is_empty() {
                                size.min(0.5)
                            } else if mask == 0 {
                                size
                            } else {
                                let slot = self.index(atom.pred, mask);
                                let keys = self.domains[atom.pred as usize].indexes[slot].map.len();
                                size / keys.max(1) as f64
                            })
                        } else {
                            None
                        }
                    }
                    NLit::Cmp { op, lhs, rhs } => {
                        let (lb, rb) = (lhs.bound_by(&bound), rhs.bound_by(&bound));
                        if lb && rb {
                            Some(0.0)
                        } else if *op == CmpOp::Eq
                            && ((rb && lhs.binds(&bound, &mut newly))
                                || (lb && rhs.binds(&bound, &mut newly)))
                        {
                            Some(1.0)
                        } else {
                            None
                        }
                    }
                    NLit::Interval { pat, lo, hi } => {
                        if lo.bound_by(&bound)
                            && hi.bound_by(&bound)
                            && pat.binds(&bound, &mut newly)
                        {
                            Some(match (lo, hi) {
                                (NTerm::Sym(a), NTerm::Sym(b)) => {
                                    match (self.syms.num(*a), self.syms.num(*b)) {
                                        (Some(a), Some(b)) => (b as f64 - a as f64 + 1.0).max(0.0),
                                        _ => 0.0,
                                    }
                                }
                                _ => 100.0,
                            })
                        } else {
                            None
                        }
                    }
                    NLit::Agg(a) => {
                        if placed[..i].iter().all(|&p| p) {
                            if let Some(NTerm::Var(v)) = a.binder.map(|k| &a.guards[k].1) {
                                newly.push(*v);
                            }
                            Some(1.5)
                        } else {
                            None
                        }
                    }
                };
                let Some(cost) = cost else { continue };
                if !matches!(l, NLit::Agg(_)) && newly.iter().any(|&v| reserved[v as usize]) {
                    continue;
                }
                if best.is_none_or(|(c, _)| cost < c) {
                    best = Some((cost, i));
                }
            }
            let Some((_, i)) = best else {
                // Not expected (the planned order is evaluable): keep the rest as planned.
                order.extend((0..n).filter(|&j| !placed[j]));
                return order;
            };
            placed[i] = true;
            order.push(i);
            newly.clear();
            lit_binds(&lits[i], &bound, &mut newly);
            for &v in &newly {
                bound[v as usize] = true;
            }
        }
        order
    }

    /// Produces the ground statement for one solution of the body.
    fn emit(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        match &stmt.kind {
            NKind::Rule | NKind::Cr(_) => self.emit_rule(stmt, ctx),
            NKind::Minimize {
                weight,
                priority,
                terms,
                maximize,
            } => {
                let (Some(w), Some(p)) = (
                    self.eval(weight, &ctx.binding),
                    self.eval(priority, &ctx.binding),
                ) else {
                    return;
                };
                let mut ts = Vec::new();
                for t in terms {
                    let Some(v) = self.eval(t, &ctx.binding) else {
                        return;
                    };
                    ts.push(v);
                }
                let (Some(wn), Some(pn)) = (self.syms.num(w), self.syms.num(p)) else {
                    let span = stmt.span;
                    self.undefined(span);
                    return;
                };
                let wn = if *maximize { wn.wrapping_neg() } else { wn };
                let key = (pn, wn, ts);
                let body = ctx.body.clone();
                let origin = self.provenance.then(|| Origin {
                    rule: RuleOrigin::Auxiliary {
                        of_stmt: stmt.stmt,
                        kind: AuxKind::Minimize,
                        bindings: self.bindings(&ctx.binding),
                    },
                    removed: self.origin(stmt, ctx).removed,
                });
                let v = match self.minimize.get_mut(&key) {
                    Some(v) => v,
                    None => {
                        self.minimize_order.push(key.clone());
                        self.minimize.entry(key.clone()).or_default()
                    }
                };
                let i = match v.iter().position(|c| *c == body) {
                    Some(i) => i,
                    None => {
                        v.push(body);
                        v.len() - 1
                    }
                };
                if let Some(o) = origin {
                    let os = self.minimize_origins.entry(key).or_default();
                    if os.len() <= i {
                        os.resize(i + 1, Vec::new());
                    }
                    if !os[i].contains(&o) {
                        os[i].push(o);
                    }
                }
            }
            NKind::Show(t) => {
                let Some(v) = self.eval(t, &ctx.binding) else {
                    return;
                };
                self.shows.push((v, ctx.body.clone()));
            }
            NKind::Project(a) => {
                let Some(s) = self.atom_sym(a, &ctx.binding) else {
                    return;
                };
                if let Some(id) = self.find_atom(s) {
                    if !self.projections.contains(&id) {
                        self.projections.push(id);
                    }
                }
            }
            NKind::External(a, value) => {
                let Some(s) = self.atom_sym(a, &ctx.binding) else {
                    return;
                };
                let Some(v) = self.eval(value, &ctx.binding) else {
                    return;
                };
                // Any other value leaves the instance out, as clingo 5.8.3 does, silently.
                let value = match self.syms.get(v) {
                    SymData::Fun {
                        name,
                        len: 0,
                        neg: false,
                        ..
                    } => match self.syms.names.resolve(name) {
                        "true" => ExternalValue::True,
                        "false" => ExternalValue::False,
                        "free" => ExternalValue::Free,
                        "release" => ExternalValue::Release,
                        _ => return,
                    },
                    _ => return,
                };
                let id = self.atom_of(s, a.pred);
                if self.info(id).fact {
                    return;
                }
                self.derive(id);
                if !self.externals.iter().any(|(x, _)| *x == id) {
                    self.externals.push((id, value));
                }
            }
            NKind::Heuristic {
                atom,
                weight,
                priority,
                modifier,
            } => {
                let Some(s) = self.atom_sym(atom, &ctx.binding) else {
                    return;
                };
                let Some(id) = self.find_atom(s) else { return };
                let (Some(w), Some(p), Some(m)) = (
                    self.eval(weight, &ctx.binding),
                    self.eval(priority, &ctx.binding),
                    self.eval(modifier, &ctx.binding),
                ) else {
                    return;
                };
                let modifier = match self.syms.get(m) {
                    SymData::Fun {
                        name,
                        len: 0,
                        neg: false,
                        ..
                    } => match self.syms.names.resolve(name) {
                        "level" => HeuristicModifier::Level,
                        "sign" => HeuristicModifier::Sign,
                        "factor" => HeuristicModifier::Factor,
                        "init" => HeuristicModifier::Init,
                        "true" => HeuristicModifier::True,
                        "false" => HeuristicModifier::False,
                        _ => return,
                    },
                    _ => return,
                };
                let (Some(w), Some(p)) = (self.syms.num(w), self.syms.num(p)) else {
                    return;
                };
                self.heuristics.push(super::program::Heuristic {
                    modifier,
                    atom: id,
                    bias: w,
                    priority: p.max(0) as u32,
                    condition: ctx.body.clone(),
                });
            }
            NKind::Edge(u, v) => {
                let (Some(u), Some(v)) = (self.eval(u, &ctx.binding), self.eval(v, &ctx.binding))
                else {
                    return;
                };
                let n = self.edge_nodes.len() as i32;
                let from = *self.edge_nodes.entry(u).or_insert(n);
                let n = self.edge_nodes.len() as i32;
                let to = *self.edge_nodes.entry(v).or_insert(n);
                self.edges.push(super::program::Edge {
                    from,
                    to,
                    condition: ctx.body.clone(),
                });
            }
        }
    }

    /// Emits the rules of one instance of a rule statement; auxiliary rules of its head
    /// (element atoms, conditions) are recorded as [`AuxKind::Element`] (provenance).
    fn emit_rule(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        let saved = self.enter_aux(AuxKind::Element, &ctx.binding);
        self.emit_rule_inner(stmt, ctx);
        self.leave_aux(saved);
    }

    fn emit_rule_inner(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        let mut head: Vec<AtomId> = Vec::new();
        let mut extra_choices: Vec<(AtomId, Vec<Lit>)> = Vec::new();
        let mut elems: Vec<ElemInstance> = Vec::new();
        let is_choice = matches!(stmt.head, NHead::Choice(_));
        match &stmt.head {
            NHead::None => {}
            NHead::Disj(es) | NHead::Choice(es) => {
                // An undefined head atom (`p(a+0)`) drops its element from a choice, and the
                // whole rule from a disjunction, conditional elements included (clingo 5.8).
                for e in es {
                    if !e.conj.is_empty() {
                        if !self.conj_elems(e, ctx, &mut elems) {
                            return;
                        }
                        continue;
                    }
                    if e.cond.is_empty() {
                        match self.atom_sym(&e.atom, &ctx.binding) {
                            Some(s) => head.push(self.atom_of(s, e.atom.pred)),
                            None if is_choice => {}
                            None => return,
                        }
                        continue;
                    }
                    let blen = ctx.body.len();
                    let mut found: Vec<(SymId, Vec<Lit>)> = Vec::new();
                    let mut undefined = false;
                    self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| match g
                        .atom_sym(&e.atom, &ctx.binding)
                    {
                        Some(s) => found.push((s, ctx.body[blen..].to_vec())),
                        None => undefined = true,
                    });
                    ctx.body.truncate(blen);
                    if undefined && !is_choice {
                        return;
                    }
                    for (s, c) in found {
                        let a = self.atom_of(s, e.atom.pred);
                        if c.is_empty() {
                            head.push(a);
                        } else if is_choice {
                            extra_choices.push((a, c));
                        } else {
                            let span = e.atom.span;
                            if !self.reported.contains(&span) {
                                self.reported.insert(span);
                                let d = Diagnostic::error(
                                    span,
                                    "unsupported: a condition in a disjunctive head that facts do not decide",
                                )
                                .with_snippet(self.snippet(span));
                                self.diags.push(d);
                            }
                            return;
                        }
                    }
                }
            }
        }
        head.dedup();
        if let NKind::Cr(label) = &stmt.kind {
            // r: h :+ b.  ==  {appl_r}.  h :- b, appl_r.
            let key: Vec<SymId> = stmt
                .globals
                .iter()
                .filter_map(|&v| ctx.binding.get(v))
                .collect();
            let appl = match self.cr_appl.get(&(stmt.stmt, key.clone())) {
                Some(&a) => a,
                None => {
                    let text = match label {
                        Some(t) => match self.eval(t, &ctx.binding) {
                            Some(v) => self.syms.show(v),
                            None => return,
                        },
                        None => {
                            let mut s = format!("r{}", stmt.stmt);
                            let named: Vec<String> = stmt
                                .globals
                                .iter()
                                .filter(|&&v| {
                                    !self
                                        .syms
                                        .names
                                        .resolve(stmt.var_names[v as usize])
                                        .starts_with('#')
                                })
                                .filter_map(|&v| ctx.binding.get(v))
                                .map(|v| self.syms.show(v))
                                .collect();
                            if !named.is_empty() {
                                s.push('(');
                                s.push_str(&named.join(","));
                                s.push(')');
                            }
                            s
                        }
                    };
                    let a = self.aux();
                    self.cr_appl.insert((stmt.stmt, key), a);
                    self.cr_rules.push((a, text));
                    self.add_rule(
                        Rule {
                            head_kind: HeadKind::Choice,
                            head: vec![a],
                            body: Body::Normal(Vec::new()),
                        },
                        |g| Origin {
                            rule: RuleOrigin::Auxiliary {
                                of_stmt: stmt.stmt,
                                kind: AuxKind::CrApplication,
                                bindings: g.bindings(&ctx.binding),
                            },
                            removed: Vec::new(),
                        },
                    );
                    a
                }
            };
            ctx.body.push(appl as Lit);
        }
        if is_choice {
            for &(a, ref c) in &extra_choices {
                self.derive(a);
                let mut body = ctx.body.clone();
                body.extend(c.iter().copied());
                self.add_rule(
                    Rule {
                        head_kind: HeadKind::Choice,
                        head: vec![a],
                        body: Body::Normal(body),
                    },
                    |g| g.origin(stmt, ctx),
                );
            }
            let facts = (self.provenance && !self.naive).then(|| head.clone());
            head.retain(|&a| !self.info(a).fact);
            if head.is_empty() {
                // A choice among facts: satisfied (with provenance, kept as removed).
                if let Some((f, facts)) = facts.and_then(|h| Some((*h.first()?, h))) {
                    let origin = self.origin(stmt, ctx);
                    self.dead.push(DeadRule {
                        head: facts,
                        origins: vec![origin],
                        why: DeadReason::HeadFact(f),
                    });
                }
                return;
            }
            for &a in &head {
                self.derive(a);
            }
            self.add_rule(
                Rule {
                    head_kind: HeadKind::Choice,
                    head,
                    body: Body::Normal(ctx.body.clone()),
                },
                |g| g.origin(stmt, ctx),
            );
            return;
        }
        // A disjunction with a true atom is satisfied. (With provenance, an instance that
        // grounds to a fact's own rule is one more origin of that rule.)
        if let Some(&f) = head.iter().find(|&&a| self.info(a).fact) {
            if head.len() == 1 && ctx.body.is_empty() {
                self.attach_origin(Rule::normal(&[f], &[]), |g| g.origin(stmt, ctx));
            } else if self.provenance && !self.naive {
                let origin = self.origin(stmt, ctx);
                self.dead.push(DeadRule {
                    head,
                    origins: vec![origin],
                    why: DeadReason::HeadFact(f),
                });
            }
            return;
        }
        for el in elems {
            match el {
                (lits, cond)
                    if cond.is_empty() && lits.len() == 1 && lits[0].0 == Sign::Positive =>
                {
                    head.push(lits[0].1)
                }
                (lits, cond) => head.push(self.elem_atom(&lits, &cond)),
            }
        }
        head.dedup();
        for &a in &head {
            self.derive(a);
        }
        if head.len() == 1 && ctx.body.is_empty() && !self.naive {
            self.atoms[head[0] as usize - 1].fact = true;
        }
        self.add_rule(
            Rule {
                head_kind: HeadKind::Disjunction,
                head,
                body: Body::Normal(ctx.body.clone()),
            },
            |g| g.origin(stmt, ctx),
        );
    }

    /// Grounds the instances of a conditional disjunction element (`l : c` with gringo's
    /// reading) into `out`, simplified over what is known; false when one of them is certainly
    /// true, so the whole disjunction is satisfied.
    fn conj_elems(&mut self, e: &NCondLit, ctx: &mut Ctx, out: &mut Vec<ElemInstance>) -> bool {
        // As gringo does, instances of the condition that agree on the local variables shared
        // by the condition and the literals form one element: its condition is their
        // disjunction, its literals their union.
        let mut cond_vars = Vec::new();
        e.cond.iter().for_each(|l| lit_vars(l, &mut cond_vars));
        let mut head_vars = Vec::new();
        for l in &e.conj {
            l.atom.args.iter().for_each(|t| t.vars(&mut head_vars));
            l.expand.iter().for_each(|x| lit_vars(x, &mut head_vars));
        }
        let mut key_vars: Vec<u32> = cond_vars
            .into_iter()
            .filter(|v| head_vars.contains(v) && ctx.binding.get(*v).is_none())
            .collect();
        key_vars.sort_unstable();
        key_vars.dedup();
        let blen = ctx.body.len();
        // Per group: its key, the conditions of its instances, and its literals.
        let mut groups: Vec<ElemGroup> = Vec::new();
        self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
            let key: Vec<SymId> = key_vars
                .iter()
                .filter_map(|&v| ctx.binding.get(v))
                .collect();
            let gi = match groups.iter().position(|(k, _, _)| *k == key) {
                Some(gi) => gi,
                None => {
                    groups.push((key, Vec::new(), Vec::new()));
                    groups.len() - 1
                }
            };
            let cond = ctx.body[blen..].to_vec();
            if !groups[gi].1.contains(&cond) {
                groups[gi].1.push(cond);
            }
            for (i, l) in e.conj.iter().enumerate() {
                g.join(ctx, &l.expand, 0, &[], &mut |g, ctx| {
                    // An undefined instance is left out of the conjunction.
                    if let Some(s) = g.atom_sym(&l.atom, &ctx.binding) {
                        if !groups[gi].2.contains(&(l.sign, i, s)) {
                            groups[gi].2.push((l.sign, i, s));
                        }
                    }
                });
            }
        });
        ctx.body.truncate(blen);
        'group: for (_, conds, lits) in groups {
            let mut ground: Vec<(Sign, AtomId)> = Vec::new();
            for (sign, i, s) in lits {
                let pred = e.conj[i].atom.pred;
                let existing = self.find_atom(s);
                let (fact, never) = existing.map_or((false, true), |a| {
                    (self.info(a).fact, !self.info(a).in_domain)
                });
                let never = never && self.domains[pred as usize].complete;
                match sign {
                    Sign::Positive if fact => {}
                    Sign::Positive => ground.push((sign, self.atom_of(s, pred))),
                    Sign::Not if fact => continue 'group,
                    Sign::NotNot if never => continue 'group,
                    Sign::Not if never => {}
                    Sign::NotNot if fact => {}
                    _ => ground.push((sign, self.atom_of(s, pred))),
                }
            }
            let cond = if conds.iter().any(|c| c.is_empty()) {
                Vec::new()
            } else if conds.len() == 1 {
                conds.into_iter().next().expect("one condition")
            } else {
                vec![self.disjunction_lit(&conds)]
            };
            if ground.is_empty() && cond.is_empty() {
                return false;
            }
            out.push((ground, cond));
        }
        true
    }

    /// The auxiliary atom `e` of a conditional disjunction element instance with literals
    /// `lits` and condition `cond` (gringo's translation): `e :- lits, cond.`; `a :- e, cond.`
    /// for each positive `a`; `:- e, cond, a.` for `not a` and `:- e, cond, not a.` for
    /// `not not a`; `:- e, not c.` for each condition literal `c`.
    fn elem_atom(&mut self, lits: &[(Sign, AtomId)], cond: &[Lit]) -> AtomId {
        let e = self.aux();
        let mut body: Vec<Lit> = Vec::with_capacity(lits.len() + cond.len());
        for &(sign, a) in lits {
            body.push(match sign {
                Sign::Positive => a as Lit,
                Sign::Not => -(a as Lit),
                Sign::NotNot => -(self.not_aux(a) as Lit),
            });
        }
        body.extend_from_slice(cond);
        // Repeated body literals are left out, as gringo does (clasp 3.3.5 mishandles some).
        let dedup = |v: &mut Vec<Lit>| {
            let mut seen = Vec::with_capacity(v.len());
            v.retain(|l| {
                let new = !seen.contains(l);
                seen.push(*l);
                new
            });
        };
        dedup(&mut body);
        self.add_aux_rule(Rule::normal(&[e], &body), AuxKind::Element);
        let mut guard = vec![e as Lit];
        guard.extend_from_slice(cond);
        dedup(&mut guard);
        for &(sign, a) in lits {
            let mut b = guard.clone();
            match sign {
                Sign::Positive => {
                    self.derive(a);
                    self.add_aux_rule(Rule::normal(&[a], &b), AuxKind::Element);
                }
                Sign::Not | Sign::NotNot => {
                    let l = if sign == Sign::Not {
                        a as Lit
                    } else {
                        -(a as Lit)
                    };
                    if !b.contains(&l) {
                        b.push(l);
                    }
                    self.add_aux_rule(Rule::normal(&[], &b), AuxKind::Element);
                }
            }
        }
        for &c in cond {
            self.add_aux_rule(Rule::normal(&[], &[e as Lit, -c]), AuxKind::Element);
        }
        e
    }

    /// Grounds the whole compiled program.
    pub fn run(&mut self, prog: &Compiled) {
        let n = prog.preds.len();
        // Head predicates of each statement, and the predicates each statement reads.
        let mut heads: Vec<Vec<PredId>> = Vec::with_capacity(prog.stmts.len());
        let mut reads: Vec<Vec<PredId>> = Vec::with_capacity(prog.stmts.len());
        // What each statement reads other than under default negation.
        let mut pos_reads: Vec<Vec<PredId>> = Vec::with_capacity(prog.stmts.len());
        for s in &prog.stmts {
            let h = stmt_heads(s);
            // In gringo's order of the body (positive literals last to first, then the negative
            // ones), which decides the order of its depth-first search.
            let negative =
                |l: &NLit| matches!(l, NLit::Pred { sign, .. } if *sign != Sign::Positive);
            let mut pr = Vec::new();
            for l in s.body.iter().rev().filter(|l| !negative(l)) {
                lit_preds(l, &mut pr);
            }
            let mut r = pr.clone();
            for l in s.body.iter().filter(|l| negative(l)) {
                lit_preds(l, &mut r);
            }
            if let NHead::Disj(es) | NHead::Choice(es) = &s.head {
                for e in es {
                    for l in &e.cond {
                        lit_preds(l, &mut r);
                        lit_preds(l, &mut pr);
                    }
                    for l in e.conj.iter().filter(|l| l.sign != Sign::Positive) {
                        r.push(l.atom.pred);
                    }
                }
            }
            heads.push(h);
            reads.push(r);
            pos_reads.push(pr);
        }
        self.warn_undefined(prog, &heads);
        // SPARC sorts: facts of their hidden predicates.
        for &(pred, v) in &prog.sort_facts {
            let name = prog.preds[pred as usize].name;
            let sym = self.syms.fun(name, false, &[v]);
            let a = self.atom_of(sym, pred);
            self.derive(a);
            self.atoms[a as usize - 1].fact = true;
        }
        // Statement dependency graph, as gringo's (Dependency::analyze): a statement depends on
        // every statement heading a predicate it reads. Ground facts are no nodes (gringo keeps
        // them apart and outputs them first); they are grounded before everything.
        let mut providers: Vec<Vec<u32>> = vec![Vec::new(); n];
        let mut nodes: Vec<usize> = Vec::new();
        let mut node_of = vec![u32::MAX; prog.stmts.len()];
        for (si, s) in prog.stmts.iter().enumerate() {
            if !is_ground_fact(s) {
                node_of[si] = nodes.len() as u32;
                nodes.push(si);
            }
            for &p in &heads[si] {
                providers[p as usize].push(si as u32);
            }
        }
        // Statements still to ground per predicate: a predicate is complete once all are done.
        let mut pending: Vec<u32> = providers.iter().map(|v| v.len() as u32).collect();
        for (d, &left) in self.domains.iter_mut().zip(&pending) {
            if left == 0 {
                d.complete = true;
            }
        }
        let finished = |g: &mut Self, si: usize, pending: &mut Vec<u32>| {
            for &p in &heads[si] {
                pending[p as usize] -= 1;
                if pending[p as usize] == 0 {
                    g.domains[p as usize].complete = true;
                }
            }
        };
        for (si, s) in prog.stmts.iter().enumerate() {
            if node_of[si] == u32::MAX {
                if self.stopped.is_some() {
                    return;
                }
                self.ground_stmt(s, &[]);
                finished(self, si, &mut pending);
            }
        }
        let edges_of = |reads: &[Vec<PredId>], keep: &dyn Fn(usize) -> bool| -> Vec<Vec<u32>> {
            nodes
                .iter()
                .map(|&si| {
                    let mut e = Vec::new();
                    for &p in &reads[si] {
                        for &t in &providers[p as usize] {
                            let t = node_of[t as usize];
                            if t != u32::MAX && keep(t as usize) {
                                e.push(t);
                            }
                        }
                    }
                    e
                })
                .collect()
        };
        let edges = edges_of(&reads, &|_| true);
        let pos_edges = edges_of(&pos_reads, &|_| true);
        let comps = positive_split(gringo_tarjan(&edges), &pos_edges);
        let mut comp_mark = vec![usize::MAX; n];
        for (ci, comp) in comps.iter().enumerate() {
            if self.stopped.is_some() {
                break;
            }
            let stmts: Vec<&NStmt> = comp
                .iter()
                .map(|&v| &prog.stmts[nodes[v as usize]])
                .collect();
            let mut preds: Vec<PredId> = Vec::new();
            for &v in comp {
                for &p in &heads[nodes[v as usize]] {
                    if comp_mark[p as usize] != ci {
                        comp_mark[p as usize] = ci;
                        preds.push(p);
                    }
                }
            }
            let in_comp = |p: PredId| comp_mark[p as usize] == ci;
            let naive = stmts
                .iter()
                .any(|s| s.body.iter().any(|l| nested_reads(l, &in_comp)))
                || stmts.iter().any(|s| match &s.head {
                    NHead::Disj(es) | NHead::Choice(es) => es.iter().any(|e| {
                        let mut r = Vec::new();
                        e.cond.iter().for_each(|l| lit_preds(l, &mut r));
                        r.into_iter().any(in_comp)
                    }),
                    NHead::None => false,
                });
            let recursive = stmts.iter().any(|s| {
                s.body
                    .iter()
                    .any(|l| matches!(l, NLit::Pred { sign: Sign::Positive, atom } if in_comp(atom.pred)))
            });
            if naive {
                self.naive = true;
                self.ground_naive(&stmts, &preds);
                self.naive = false;
            } else if recursive {
                self.ground_seminaive(&stmts, &preds, &in_comp);
            } else {
                for s in &stmts {
                    self.ground_stmt(s, &[]);
                }
            }
            for &v in comp {
                finished(self, nodes[v as usize], &mut pending);
            }
        }
    }

    /// Grounds a component with recursive aggregates: first its domain, by rounds in which
    /// such aggregates are assumed true (each round's rules are discarded), until no atom is
    /// added; then one final round with the aggregates evaluated over the complete domain.
    fn ground_naive(&mut self, stmts: &[&NStmt], comp: &[PredId]) {
        self.optimistic = true;
        loop {
            let rules_start = self.rules.len();
            let cr_start = self.cr_rules.len();
            let size_before: usize = comp
                .iter()
                .map(|&p| self.domains[p as usize].atoms.len())
                .sum();
            for s in stmts {
                self.ground_stmt(s, &[]);
            }
            let size_after: usize = comp
                .iter()
                .map(|&p| self.domains[p as usize].atoms.len())
                .sum();
            self.forget_rules_from(rules_start);
            for (a, _) in self.cr_rules.drain(cr_start..) {
                self.cr_appl.retain(|_, v| *v != a);
            }
            if self.stopped.is_some() || size_after == size_before {
                break;
            }
        }
        self.optimistic = false;
        for s in stmts {
            self.ground_stmt(s, &[]);
        }
    }

    fn forget_rules_from(&mut self, start: usize) {
        while self.rule_hashes.len() > start {
            let hash = self.rule_hashes.pop().expect("len > start");
            let idx = self.rule_hashes.len() as u32;
            if let Ok(e) = self.rule_set.find_entry(hash, |&i| i == idx) {
                e.remove();
            }
            if self.provenance {
                self.origins.pop();
            }
        }
        if self.provenance {
            self.more_origins.retain(|&i, _| (i as usize) < start);
        }
        self.rules.truncate(start);
        // Their defining rules may be gone; fresh auxiliaries are made next round.
        self.notnot.clear();
    }

    fn ground_seminaive(
        &mut self,
        stmts: &[&NStmt],
        comp: &[PredId],
        in_comp: &dyn Fn(PredId) -> bool,
    ) {
        // Round 0: everything over what is known.
        for &p in comp {
            let d = &mut self.domains[p as usize];
            d.old = 0;
            d.delta = d.atoms.len() as u32;
        }
        for s in stmts {
            let ranges: Vec<Option<Range>> = s
                .body
                .iter()
                .map(|l| match l {
                    NLit::Pred {
                        sign: Sign::Positive,
                        atom,
                    } if in_comp(atom.pred) => Some((0, self.domains[atom.pred as usize].delta)),
                    _ => None,
                })
                .collect();
            self.ground_stmt(s, &ranges);
        }
        // Later rounds follow gringo's queue of instantiators (Queue::process): an instantiator
        // is a statement with one recursive literal over the last round's new atoms (earlier
        // recursive literals over older atoms, later ones over all). After a round, the
        // statements of that round, in order, enqueue the instantiators reading what they head
        // whose literal has new atoms, in the order the instantiators were registered. Only
        // the order of the output rules (hence the atom numbering) depends on this order.
        let rec: Vec<Vec<usize>> = stmts
            .iter()
            .map(|s| {
                s.body
                    .iter()
                    .enumerate()
                    .filter(|(_, l)| matches!(l, NLit::Pred { sign: Sign::Positive, atom } if in_comp(atom.pred)))
                    .map(|(i, _)| i)
                    .collect()
            })
            .collect();
        let heads: Vec<Vec<PredId>> = stmts.iter().map(|s| stmt_heads(s)).collect();
        let rec_pred = |t: usize, jj: usize| -> PredId {
            match &stmts[t].body[rec[t][jj]] {
                NLit::Pred { atom, .. } => atom.pred,
                _ => unreachable!("recursive literals are predicate literals"),
            }
        };
        // deps[s]: the instantiators (statement, recursive literal) reading a predicate that
        // statement s heads, in registration order.
        let mut deps: Vec<Vec<(usize, usize)>> = vec![Vec::new(); stmts.len()];
        for (t, r) in rec.iter().enumerate() {
            for jj in 0..r.len() {
                let p = rec_pred(t, jj);
                for (s, h) in heads.iter().enumerate() {
                    if h.contains(&p) {
                        deps[s].push((t, jj));
                    }
                }
            }
        }
        let offset: Vec<usize> = rec
            .iter()
            .scan(0usize, |acc, r| {
                let o = *acc;
                *acc += r.len();
                Some(o)
            })
            .collect();
        let mut enqueued =
            vec![false; offset.last().map_or(0, |&o| o) + rec.last().map_or(0, |r| r.len())];
        // The statements whose heads propagate after the current round, in order.
        let mut current: Vec<usize> = (0..stmts.len()).collect();
        loop {
            let mut any = false;
            for &p in comp {
                let d = &mut self.domains[p as usize];
                d.old = d.delta;
                d.delta = d.atoms.len() as u32;
                any |= d.delta > d.old;
            }
            if !any || self.stopped.is_some() {
                return;
            }
            let mut queue: Vec<(usize, usize)> = Vec::new();
            for &s in &current {
                for &(t, jj) in &deps[s] {
                    let d = &self.domains[rec_pred(t, jj) as usize];
                    if !enqueued[offset[t] + jj] && d.delta > d.old {
                        enqueued[offset[t] + jj] = true;
                        queue.push((t, jj));
                    }
                }
            }
            current.clear();
            for &(t, jj) in &queue {
                enqueued[offset[t] + jj] = false;
                current.push(t);
                let s = stmts[t];
                let mut ranges: Vec<Option<Range>> = vec![None; s.body.len()];
                let mut empty = false;
                for (kk, &i) in rec[t].iter().enumerate() {
                    let NLit::Pred { atom, .. } = &s.body[i] else {
                        continue;
                    };
                    let d = &self.domains[atom.pred as usize];
                    let r = match kk.cmp(&jj) {
                        std::cmp::Ordering::Less => (0, d.old),
                        std::cmp::Ordering::Equal => (d.old, d.delta),
                        std::cmp::Ordering::Greater => (0, d.delta),
                    };
                    empty |= r.0 >= r.1;
                    ranges[i] = Some(r);
                }
                if !empty {
                    self.ground_stmt(s, &ranges);
                }
            }
        }
    }

    /// gringo's `atom does not occur in any rule head` for positive body atoms of predicates
    /// that nothing defines.
    fn warn_undefined(&mut self, prog: &Compiled, heads: &[Vec<PredId>]) {
        let mut defined = vec![false; prog.preds.len()];
        for h in heads {
            for &p in h {
                defined[p as usize] = true;
            }
        }
        for &p in &prog.defined {
            defined[p as usize] = true;
        }
        let mut seen: hashbrown::HashSet<Span> = hashbrown::HashSet::new();
        for s in &prog.stmts {
            let mut atoms: Vec<&NAtom> = Vec::new();
            for l in &s.body {
                positive_atoms(l, &mut atoms);
            }
            if let NHead::Disj(es) | NHead::Choice(es) = &s.head {
                for e in es {
                    e.cond.iter().for_each(|l| positive_atoms(l, &mut atoms));
                }
            }
            for a in atoms {
                if !a.sort && !defined[a.pred as usize] && seen.insert(a.span) {
                    let d = Diagnostic::warning(
                        WarningKind::AtomUndefined,
                        a.span,
                        "atom does not occur in any rule head",
                    );
                    let snip = self.snippet(a.span);
                    self.diags.push(if snip.is_empty() {
                        d
                    } else {
                        d.with_snippet(snip)
                    });
                }
            }
        }
    }
}

fn positive_atoms<'x>(l: &'x NLit, out: &mut Vec<&'x NAtom>) {
    match l {
        NLit::Pred { atom, .. } => out.push(atom),
        NLit::Agg(a) => {
            for e in &a.elems {
                e.cond.iter().for_each(|c| positive_atoms(c, out));
                e.lit_lits().for_each(|l| positive_atoms(l, out));
            }
        }
        _ => {}
    }
}

/// `a op b` on integers (clingo orders integers numerically).
fn cmp_ints(op: CmpOp, a: i32, b: i32) -> bool {
    match op {
        CmpOp::Eq => a == b,
        CmpOp::Ne => a != b,
        CmpOp::Lt => a < b,
        CmpOp::Le => a <= b,
        CmpOp::Gt => a > b,
        CmpOp::Ge => a >= b,
    }
}

/// `t1 op t2` in clingo's term order.
pub fn cmp_holds(syms: &Symbols, op: CmpOp, a: SymId, b: SymId) -> bool {
    // Symbols are hash-consed: equality is identity.
    match op {
        CmpOp::Eq => return a == b,
        CmpOp::Ne => return a != b,
        _ => {}
    }
    let o = syms.compare(a, b);
    match op {
        CmpOp::Eq => o.is_eq(),
        CmpOp::Ne => o.is_ne(),
        CmpOp::Lt => o.is_lt(),
        CmpOp::Le => o.is_le(),
        CmpOp::Gt => o.is_gt(),
        CmpOp::Ge => o.is_ge(),
    }
}

fn negate(g: &mut Grounder<'_>, t: Truth) -> Truth {
    match t {
        Truth::True => Truth::False,
        Truth::False => Truth::True,
        Truth::Lits(l) => {
            let a = g.disjunction_lit(&[l]);
            Truth::Lits(vec![g.negate_lit(a)])
        }
    }
}

fn conj(a: Truth, b: Truth) -> Truth {
    match (a, b) {
        (Truth::False, _) | (_, Truth::False) => Truth::False,
        (Truth::True, x) | (x, Truth::True) => x,
        (Truth::Lits(mut x), Truth::Lits(y)) => {
            x.extend(y);
            Truth::Lits(x)
        }
    }
}

/// Adds the variables that evaluating `l` with `bound` known binds to `out`.
fn lit_binds(l: &NLit, bound: &[bool], out: &mut Vec<u32>) {
    match l {
        NLit::Pred {
            sign: Sign::Positive,
            atom,
        } => {
            for t in &atom.args {
                t.binds(bound, out);
            }
        }
        NLit::Cmp { lhs, rhs, .. } => {
            if lhs.bound_by(bound) {
                rhs.binds(bound, out);
            } else {
                lhs.binds(bound, out);
            }
        }
        NLit::Interval { pat, .. } => {
            pat.binds(bound, out);
        }
        NLit::Agg(a) => {
            if let Some(NTerm::Var(v)) = a.binder.map(|k| &a.guards[k].1) {
                if !bound[*v as usize] && !out.contains(v) {
                    out.push(*v);
                }
            }
        }
        NLit::Pred { .. } | NLit::Bool(_) => {}
    }
}

/// Predicates a literal reads (including inside aggregates).
fn lit_preds(l: &NLit, out: &mut Vec<PredId>) {
    match l {
        NLit::Pred { atom, .. } => out.push(atom.pred),
        NLit::Agg(a) => {
            for e in &a.elems {
                e.cond.iter().for_each(|c| lit_preds(c, out));
                e.lit_lits().for_each(|l| lit_preds(l, out));
            }
        }
        _ => {}
    }
}

/// True when an aggregate of `l` reads a predicate of the current component.
/// The predicates a statement derives atoms of (its head atoms, or the external atom).
fn stmt_heads(s: &NStmt) -> Vec<PredId> {
    let mut h = Vec::new();
    match &s.head {
        NHead::Disj(es) | NHead::Choice(es) => {
            for a in es.iter().flat_map(|e| e.derived_atoms()) {
                if !h.contains(&a.pred) {
                    h.push(a.pred)
                }
            }
        }
        NHead::None => {}
    }
    if let NKind::External(a, _) = &s.kind {
        h.push(a.pred);
    }
    h
}

/// Whether a statement is a ground fact (one unconditional head atom, no body, no variables):
/// gringo keeps these out of its dependency graph and outputs them first.
fn is_ground_fact(s: &NStmt) -> bool {
    matches!(s.kind, NKind::Rule)
        && s.body.is_empty()
        && s.num_vars == 0
        && matches!(&s.head, NHead::Disj(es) if es.len() == 1 && es[0].cond.is_empty() && es[0].conj.is_empty())
}

fn nested_reads(l: &NLit, in_comp: &dyn Fn(PredId) -> bool) -> bool {
    match l {
        NLit::Agg(_) => {
            let mut r = Vec::new();
            lit_preds(l, &mut r);
            r.into_iter().any(in_comp)
        }
        _ => false,
    }
}

/// Splits each strongly connected component of the statement dependency graph into the
/// components of its positive dependencies, in topological order, as gringo does: a statement
/// read only under default negation by a statement of the same component is grounded after
/// it, which keeps such literals (the predicate is not complete yet) instead of iterating the
/// whole component together. Grounding each part to a fixpoint in this order gives the same
/// rules, in gringo's order. Parts list their statements in gringo's order too.
fn positive_split(comps: Vec<Vec<u32>>, pos_edges: &[Vec<u32>]) -> Vec<Vec<u32>> {
    let mut local = vec![u32::MAX; pos_edges.len()];
    let mut out = Vec::with_capacity(comps.len());
    for comp in comps {
        if comp.len() == 1 {
            out.push(comp);
            continue;
        }
        for (i, &v) in comp.iter().enumerate() {
            local[v as usize] = i as u32;
        }
        let sub: Vec<Vec<u32>> = comp
            .iter()
            .map(|&v| {
                pos_edges[v as usize]
                    .iter()
                    .map(|&w| local[w as usize])
                    .filter(|&w| w != u32::MAX)
                    .collect()
            })
            .collect();
        for part in gringo_tarjan(&sub) {
            out.push(part.into_iter().map(|i| comp[i as usize]).collect());
        }
        for &v in &comp {
            local[v as usize] = u32::MAX;
        }
    }
    out
}

/// Strongly connected components, every component after those it has edges to, computed as
/// gringo's `Graph::tarjan` does so that independent components and the members of one
/// component come in gringo's order: depth-first from the nodes in reverse order (gringo's
/// graph prepends inserted nodes), edges in insertion order, and each component listing its
/// nodes as they leave the trail (last reached first).
pub fn gringo_tarjan(edges: &[Vec<u32>]) -> Vec<Vec<u32>> {
    const NEW: u32 = u32::MAX;
    const DONE: u32 = 0;
    let n = edges.len();
    // NEW, DONE, or the node's current low value (from 2 on, as gringo's).
    let mut visited = vec![NEW; n];
    let mut next_edge = vec![0usize; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut trail: Vec<u32> = Vec::new();
    let mut comps: Vec<Vec<u32>> = Vec::new();
    for root in (0..n).rev() {
        if visited[root] != NEW {
            continue;
        }
        let mut index = 1u32;
        let mut push =
            |x: u32, visited: &mut Vec<u32>, stack: &mut Vec<u32>, trail: &mut Vec<u32>| {
                index += 1;
                visited[x as usize] = index;
                stack.push(x);
                trail.push(x);
            };
        push(root as u32, &mut visited, &mut stack, &mut trail);
        while let Some(&y) = stack.last() {
            let y = y as usize;
            let es = &edges[y];
            while next_edge[y] < es.len() && visited[es[next_edge[y]] as usize] != NEW {
                next_edge[y] += 1;
            }
            if next_edge[y] < es.len() {
                let z = es[next_edge[y]];
                next_edge[y] += 1;
                push(z, &mut visited, &mut stack, &mut trail);
                continue;
            }
            stack.pop();
            let mut root = true;
            for &z in es {
                let vz = visited[z as usize];
                if vz != DONE && vz < visited[y] {
                    root = false;
                    visited[y] = vz;
                }
            }
            if root {
                let mut c = Vec::new();
                loop {
                    let w = trail.pop().expect("scc trail");
                    visited[w as usize] = DONE;
                    c.push(w);
                    if w as usize == y {
                        break;
                    }
                }
                comps.push(c);
            }
        }
    }
    comps
}
