//! Translation of a ground program into the engine's constraints: Clark completion with body
//! variables (AIJ 2012, section 3), shifting of disjunctive heads into per-atom supports, native
//! weight constraints for weight bodies, and the positive dependency graph that decides which
//! atoms need unfounded-set propagation and whether the program is head-cycle-free.
//!
//! With `Config::eq`, before translation, atoms equivalent by completion to a literal (`a :- l.`
//! as their only rule) or to a conjunctive body (`a :- B.` as their only rule) are merged with
//! it, as clasp's `--eq` preprocessing does for these cases (`equivalences`): fewer variables,
//! and the heuristic scores one variable instead of two that always agree.
//!
//! Invariants:
//! - Every atom `1..=num_atoms` has a solver literal (`atom_lit`); index 0 holds the constant
//!   true literal. Merged atoms share a literal (possibly negated) with another atom, the true
//!   literal or their body; every rule still gets its clauses, so the completion holds over the
//!   merged literals. Cyclic atoms (positive loops) always have a variable of their own, and no
//!   merging happens for external atoms, disjunctive programs, atoms added by later steps, or
//!   onto an atom that depends positively on an external (a later step could close a cycle
//!   through it).
//! - For a rule `H :- B`, `B` gets one literal shared by all rules with the same body. A
//!   disjunctive rule with head atoms `h1..hn` gives `hi` the support `B and not hj (j != i)`
//!   (shifting); a choice rule gives each head atom the support `B`.
//! - Completion: an atom that is not external implies the disjunction of its supports;
//!   supports and bodies imply heads through the rule clauses. External atoms get theirs when a
//!   later step defines them (`Solver::add_program`) or releases them.
//! - `comp`/`cyclic` hold the strongly connected components of the positive dependency graph
//!   of every step so far; `update_cycles` extends them step by step.
//! - A program is head-cycle-free when no disjunctive rule has two head atoms in one strongly
//!   connected component of the positive dependency graph; only then are answer sets exactly
//!   the supported, unfounded-free assignments. Otherwise `non_hcf` is set and the caller checks
//!   minimality of each candidate.

use super::engine::Engine;
use super::lit::Lit;
use super::unfounded::{Support, SupportBody, Unfounded};
use crate::ground::program::{BodyRef, ExternalValue, GroundProgram, HeadKind, RuleRef};
use hashbrown::{DefaultHashBuilder, HashMap, HashTable};
use smallvec::SmallVec;
use std::hash::BuildHasher;

/// The supports of one atom as (support literal, rule index); most atoms have one or two, held
/// inline without a heap allocation.
pub type AtomSupports = SmallVec<[(Lit, u32); 2]>;

/// The link between a ground program and the engine's variables.
#[derive(Clone, Debug, Default)]
pub struct Translation {
    /// Per atom (index 0: constant true): its literal.
    pub atom_lit: Vec<Lit>,
    /// Per atom: supports as (support literal, rule index).
    pub supports: Vec<AtomSupports>,
    /// Per rule: the literal of its body.
    pub rule_body: Vec<Lit>,
    /// Per atom: an external atom (declared, not released, without rules), so no completion
    /// clause: its value comes from `ext_value` through the assumptions of each call.
    pub free: Vec<bool>,
    /// Per atom: the value of an external atom (meaningful where `free` is set).
    pub ext_value: Vec<ExternalValue>,
    /// The external atoms, in the order they were declared (may hold atoms that stopped
    /// being external; `free` decides).
    pub ext_atoms: Vec<u32>,
    /// The program's own assumptions (aspif statement 6).
    pub prog_assumptions: Vec<Lit>,
    /// Per output statement: the literal of its condition.
    pub output_lits: Vec<Lit>,
    /// Minimize levels, highest priority first: (priority, weighted literals).
    pub minimize: Vec<(i64, Vec<(Lit, i64)>)>,
    /// Literals assumed for every solve call: the program's assumptions, true externals and
    /// the negations of false externals (`refresh_assumptions`).
    pub assumptions: Vec<Lit>,
    /// True when some disjunctive rule has two head atoms in one positive cycle.
    pub non_hcf: bool,
    /// Per atom: its strongly connected component in the positive dependency graph.
    pub comp: Vec<u32>,
    /// Per atom: on a positive cycle.
    pub cyclic: Vec<bool>,
    /// The cyclic atoms, in the order they became cyclic.
    pub cyclic_atoms: Vec<u32>,
    /// Next unused component number.
    next_comp: u32,
    /// Per atom: occurs positively in the body of a rule with a non-empty head (so that it
    /// has a positive dependency pointing at it).
    pub pos_occ: Vec<bool>,
    /// Indices of the disjunctive rules with two or more head atoms.
    disj_rules: Vec<u32>,
    /// Conjunctions already given a literal: (start, length, literal), the key (sorted literal
    /// codes) being `conj_keys[start..start + length]`. One flat key array instead of a `Vec`
    /// per key keeps a body at 12 bytes in the table plus its codes.
    conj: HashTable<(u32, u32, Lit)>,
    /// The keys of `conj`, one after another.
    conj_keys: Vec<u32>,
    /// Hasher of the keys of `conj`.
    conj_hasher: DefaultHashBuilder,
    /// Weight bodies already given a literal, keyed by bound and sorted (code, weight) pairs.
    weights: HashMap<(i64, Vec<(u32, i64)>), Lit>,
    /// Scratch space for a conjunction's key, reused so that translating a rule allocates
    /// nothing (empty between calls).
    key_buf: Vec<u32>,
    /// Scratch space for a clause or a list of literals, reused likewise.
    lits_buf: Vec<Lit>,
}

/// The largest atom mentioned anywhere in the program (the declared count may be too small).
pub fn max_atom(p: &GroundProgram) -> u32 {
    let mut m = p.num_atoms.max(p.rules.max_atom());
    let lit_atom = |l: i32| l.unsigned_abs();
    for mz in &p.minimize {
        m = m.max(mz.lits.iter().map(|&(l, _)| lit_atom(l)).max().unwrap_or(0));
    }
    for o in &p.outputs {
        m = m.max(o.condition.iter().map(|&l| lit_atom(l)).max().unwrap_or(0));
    }
    for &(a, _) in &p.externals {
        m = m.max(a);
    }
    for &l in &p.assumptions {
        m = m.max(lit_atom(l));
    }
    for &a in &p.projections {
        m = m.max(a);
    }
    for c in &p.cr_rules {
        m = m.max(c.appl);
    }
    m
}

impl Translation {
    /// The literal of an aspif literal.
    pub fn lit(&self, l: i32) -> Lit {
        let a = self.atom_lit[l.unsigned_abs() as usize];
        if l < 0 {
            !a
        } else {
            a
        }
    }

    /// The constant true literal.
    pub fn true_lit(&self) -> Lit {
        self.atom_lit[0]
    }

    /// A literal equivalent to the conjunction of `lits`.
    pub fn conjunction(&mut self, e: &mut Engine, lits: &[Lit]) -> Lit {
        let mut key = std::mem::take(&mut self.key_buf);
        conj_key(&mut key, lits.iter().copied());
        let b = self.conjunction_of_key(e, &key);
        key.clear();
        self.key_buf = key;
        b
    }

    /// `conjunction` for the key `key` (sorted codes without repeats).
    fn conjunction_of_key(&mut self, e: &mut Engine, key: &[u32]) -> Lit {
        match self.lookup_conj(key) {
            ConjLookup::Known(b) => b,
            ConjLookup::New(hash) => {
                let b = e.new_body_var().positive();
                self.insert_conj(e, key, hash, b);
                b
            }
        }
    }

    /// The literal that already stands for the conjunction `key` (sorted codes without
    /// repeats; the true literal when it is empty, the literal itself when it has one), or the
    /// key's hash for a new entry.
    fn lookup_conj(&self, key: &[u32]) -> ConjLookup {
        if key.is_empty() {
            return ConjLookup::Known(self.true_lit());
        }
        if key.len() == 1 {
            return ConjLookup::Known(Lit::from_code(key[0]));
        }
        let hash = self.conj_hasher.hash_one(key);
        match self.find_conj(hash, key) {
            Some(b) => ConjLookup::Known(b),
            None => ConjLookup::New(hash),
        }
    }

    /// The body literal of an integrity constraint `:- lits.`, which the caller makes false.
    /// A body of two or more literals that no earlier rule has becomes the clause
    /// `not l1 or .. or not lk` directly, as clasp writes it, and the answer is the false
    /// literal: a variable of its own would only be false at level 0 (with the level-0
    /// simplification leaving the same clause), yet cost its per-variable arrays, which on
    /// programs made mostly of constraints (stable marriage, queens) was most of the memory.
    /// A later rule with the same body gets a body variable of its own.
    fn constraint_body(&mut self, e: &mut Engine, key: &[u32]) -> Lit {
        match self.lookup_conj(key) {
            ConjLookup::Known(b) => b,
            ConjLookup::New(_) => {
                let mut clause = std::mem::take(&mut self.lits_buf);
                clause.extend(key.iter().map(|&c| !Lit::from_code(c)));
                e.add_clause(&clause);
                clause.clear();
                self.lits_buf = clause;
                !self.true_lit()
            }
        }
    }

    /// The literal already standing for the conjunction `key` (sorted codes), if any.
    fn find_conj(&self, hash: u64, key: &[u32]) -> Option<Lit> {
        let keys = &self.conj_keys;
        self.conj
            .find(hash, |&(start, len, _)| {
                keys[start as usize..(start + len) as usize] == *key
            })
            .map(|&(_, _, b)| b)
    }

    /// Makes `b` stand for the conjunction `key` (sorted codes, at least two, hashed to `hash`):
    /// the clause `key -> b`, the clauses `b -> l`, and the table entry.
    fn insert_conj(&mut self, e: &mut Engine, key: &[u32], hash: u64, b: Lit) {
        let mut big = std::mem::take(&mut self.lits_buf);
        big.push(b);
        for &c in key {
            let l = Lit::from_code(c);
            e.add_clause(&[!b, l]);
            big.push(!l);
        }
        e.add_clause(&big);
        big.clear();
        self.lits_buf = big;
        let start = self.conj_keys.len() as u32;
        self.conj_keys.extend_from_slice(key);
        let (keys, hasher) = (&self.conj_keys, &self.conj_hasher);
        self.conj
            .insert_unique(hash, (start, key.len() as u32, b), |&(s, n, _)| {
                hasher.hash_one(&keys[s as usize..(s + n) as usize])
            });
    }

    /// The literal of a rule body; `constraint` when the rule is an integrity constraint (its
    /// body literal is made false right after).
    fn body_lit(&mut self, e: &mut Engine, body: BodyRef<'_>, constraint: bool) -> Lit {
        match body {
            // What `lookup_conj` answers for keys of no or one literal, without a key.
            BodyRef::Normal([]) => self.true_lit(),
            BodyRef::Normal(&[l]) => self.lit(l),
            BodyRef::Normal(ls) => {
                let mut key = std::mem::take(&mut self.key_buf);
                conj_key(&mut key, ls.iter().map(|&l| self.lit(l)));
                let b = if constraint {
                    self.constraint_body(e, &key)
                } else {
                    self.conjunction_of_key(e, &key)
                };
                key.clear();
                self.key_buf = key;
                b
            }
            BodyRef::Weight { lower, lits } => {
                let mut key: Vec<(u32, i64)> = lits
                    .iter()
                    .map(|&(l, w)| (self.lit(l).code() as u32, w))
                    .collect();
                key.sort_unstable();
                // Merged atoms can make a literal occur twice: one entry with the summed weight.
                key.dedup_by(|b, a| {
                    if a.0 == b.0 {
                        a.1 = a.1.saturating_add(b.1);
                        true
                    } else {
                        false
                    }
                });
                if let Some(&b) = self.weights.get(&(lower, key.clone())) {
                    return b;
                }
                let b = e.new_body_var().positive();
                let wl: Vec<(Lit, i64)> =
                    key.iter().map(|&(c, w)| (Lit::from_code(c), w)).collect();
                e.add_weight(b, &wl, lower);
                self.weights.insert((lower, key), b);
                b
            }
        }
    }

    /// Translates the whole program into a fresh engine, without merging equivalent atoms.
    pub fn build(p: &GroundProgram, e: &mut Engine) -> Translation {
        Translation::build_with(p, e, false)
    }

    /// Translates the whole program into a fresh engine; `eq` turns the merging of equivalent
    /// atoms and bodies on (clasp `--eq`).
    pub fn build_with(p: &GroundProgram, e: &mut Engine, eq: bool) -> Translation {
        let n = max_atom(p) as usize;
        let mut t = Translation::default();
        // One variable per atom and, at most, about one per rule body (shifted disjunctions
        // and output conditions may add a few more).
        e.reserve_vars(n + 1 + p.rules.len());
        let truth = e.new_var();
        e.add_clause(&[truth.positive()]);
        t.atom_lit.push(truth.positive());
        // With merging, the components of the positive dependency graph are needed before
        // translation; they are computed once and given to `install_unfounded_with`.
        let (cycles, eqs) = if eq {
            let mut heads = HeadRules::new(n + 1);
            let c = Cycles::of(p, n + 1, |i, r| heads.add(i, r));
            let free = external_free(p, n);
            let reach = reaches_external(p, n, &free);
            let eqs = equivalences(n, &free, &reach, &c.comp, &heads);
            (Some(c), eqs)
        } else {
            (None, vec![Equiv::None; n + 1])
        };
        // Atoms with a variable of their own first, in atom order; then the aliases.
        let mut lit = vec![None; n + 1];
        lit[0] = Some(truth.positive());
        for a in 1..=n {
            match eqs[a] {
                Equiv::Lit(_) => {}
                // The atom stands for a body: tried true first, as bodies are.
                Equiv::Body(_) => lit[a] = Some(e.new_body_var().positive()),
                Equiv::None => lit[a] = Some(e.new_var().positive()),
            }
        }
        resolve_aliases(&eqs, &mut lit, e);
        t.atom_lit = lit
            .into_iter()
            .map(|l| l.expect("every atom has a literal after alias resolution"))
            .collect();
        t.supports = std::iter::repeat_with(AtomSupports::new)
            .take(n + 1)
            .collect();
        t.free = vec![false; n + 1];
        t.ext_value = vec![ExternalValue::Free; n + 1];
        t.pos_occ = vec![false; n + 1];
        t.set_externals(p);
        // An atom whose only rule is `a :- B` (B of two or more literals) stands for B itself.
        for (a, q) in eqs.iter().enumerate() {
            if let Equiv::Body(ri) = *q {
                if let BodyRef::Normal(ls) = p.rules.get(ri).body {
                    t.define_conjunction(e, ls, t.atom_lit[a]);
                }
            }
        }
        for (i, r) in p.rules.iter().enumerate() {
            t.add_rule(e, i, r);
        }
        for a in 1..=n {
            t.complete(e, a);
        }
        for o in &p.outputs {
            let lits: Vec<Lit> = o.condition.iter().map(|&l| t.lit(l)).collect();
            let c = t.conjunction(e, &lits);
            t.output_lits.push(c);
        }
        let mut prios: Vec<i64> = p.minimize.iter().map(|m| m.priority).collect();
        prios.sort_unstable_by(|a, b| b.cmp(a));
        prios.dedup();
        for pr in prios {
            let mut lits = Vec::new();
            for m in p.minimize.iter().filter(|m| m.priority == pr) {
                for &(l, w) in &m.lits {
                    lits.push((t.lit(l), w));
                }
            }
            t.minimize.push((pr, lits));
        }
        t.install_unfounded_with(p, e, cycles);
        t
    }

    /// Makes the existing literal `x` stand for the conjunction of `lits` (clauses
    /// `x -> l` and `lits -> x`), unless that conjunction already has a literal, is a single
    /// literal, or mentions `x`'s variable; then nothing happens and the rule clauses keep the
    /// equivalence.
    fn define_conjunction(&mut self, e: &mut Engine, lits: &[i32], x: Lit) {
        let mut key = std::mem::take(&mut self.key_buf);
        conj_key(&mut key, lits.iter().map(|&l| self.lit(l)));
        if key.len() >= 2 && key.iter().all(|&c| Lit::from_code(c).var() != x.var()) {
            let hash = self.conj_hasher.hash_one(&key[..]);
            if self.find_conj(hash, &key).is_none() {
                self.insert_conj(e, &key, hash, x);
            }
        }
        key.clear();
        self.key_buf = key;
    }

    /// Sets `free`, `ext_value` and the assumptions from the external statements and
    /// assumptions of `p`: the last statement on an atom gives its value (as
    /// `check::external_values`); `Release` makes the atom an ordinary one (false without
    /// rules). The caller drops external statements on atoms that have rules (they are
    /// ordinary atoms then).
    pub fn set_externals(&mut self, p: &GroundProgram) {
        for &a in &self.ext_atoms {
            self.free[a as usize] = false;
        }
        self.ext_atoms.clear();
        for &(a, v) in &p.externals {
            self.set_external(a, v);
        }
        self.prog_assumptions = p.assumptions.iter().map(|&l| self.lit(l)).collect();
        self.refresh_assumptions();
    }

    /// Makes `a` an external atom with value `v` (`Release`: an ordinary atom again; the caller
    /// completes it). Call `refresh_assumptions` afterwards.
    pub fn set_external(&mut self, a: u32, v: ExternalValue) {
        let au = a as usize;
        if v == ExternalValue::Release {
            self.free[au] = false;
            return;
        }
        if !self.free[au] {
            self.free[au] = true;
            self.ext_atoms.push(a);
        }
        self.ext_value[au] = v;
    }

    /// Recomputes `assumptions`: the program's assumptions, then each true external and the
    /// negation of each false one. Drops atoms that stopped being external from `ext_atoms`.
    pub fn refresh_assumptions(&mut self) {
        let free = &self.free;
        let mut seen = hashbrown::HashSet::new();
        self.ext_atoms
            .retain(|&a| free[a as usize] && seen.insert(a));
        self.assumptions.clear();
        self.assumptions.extend_from_slice(&self.prog_assumptions);
        for &a in &self.ext_atoms {
            let l = self.atom_lit[a as usize];
            match self.ext_value[a as usize] {
                ExternalValue::True => self.assumptions.push(l),
                ExternalValue::False => self.assumptions.push(!l),
                ExternalValue::Free | ExternalValue::Release => {}
            }
        }
    }

    /// Makes room for atoms up to `n` (each gets a fresh variable).
    pub fn grow_atoms(&mut self, e: &mut Engine, n: usize) {
        while self.atom_lit.len() <= n {
            self.atom_lit.push(e.new_var().positive());
            self.supports.push(AtomSupports::new());
            self.free.push(false);
            self.ext_value.push(ExternalValue::Free);
            self.pos_occ.push(false);
            self.comp.push(self.next_comp);
            self.next_comp += 1;
            self.cyclic.push(false);
        }
    }

    /// Adds the clauses of one rule (its body, its head clause and its supports).
    pub fn add_rule(&mut self, e: &mut Engine, index: usize, r: RuleRef<'_>) {
        if let (HeadKind::Disjunction, &[h], BodyRef::Normal([])) = (r.head_kind, r.head, r.body) {
            // A fact (most rules of many programs): the body is the true literal, the rule
            // clause `h` (satisfied when `h` was merged with the true literal).
            let b = self.true_lit();
            self.rule_body.push(b);
            e.add_clause(&[!b, self.atom_lit[h as usize]]);
            self.supports[h as usize].push((b, index as u32));
            return;
        }
        let constraint = r.head_kind == HeadKind::Disjunction && r.head.is_empty();
        if !r.head.is_empty() {
            match r.body {
                BodyRef::Normal(ls) => {
                    for &l in ls.iter().filter(|&&l| l > 0) {
                        self.pos_occ[l as usize] = true;
                    }
                }
                BodyRef::Weight { lits, .. } => {
                    for &(l, w) in lits.iter().filter(|&&(l, w)| l > 0 && w > 0) {
                        let _ = w;
                        self.pos_occ[l as usize] = true;
                    }
                }
            }
            if r.head_kind == HeadKind::Disjunction && r.head.len() > 1 {
                self.disj_rules.push(index as u32);
            }
        }
        let b = self.body_lit(e, r.body, constraint);
        self.rule_body.push(b);
        debug_assert_eq!(self.rule_body.len(), index + 1);
        // Integrity constraints and normal rules (most rules) directly; the general case
        // below gives them the same clauses and supports.
        if r.head_kind == HeadKind::Disjunction && r.head.len() <= 1 {
            match *r.head {
                [] => {
                    e.add_clause(&[!b]);
                }
                [h] => {
                    e.add_clause(&[!b, self.atom_lit[h as usize]]);
                    self.supports[h as usize].push((b, index as u32));
                }
                _ => unreachable!("at most one head atom"),
            }
            return;
        }
        let mut head: SmallVec<[u32; 4]> = SmallVec::from_slice(r.head);
        head.sort_unstable();
        head.dedup();
        match r.head_kind {
            HeadKind::Choice => {
                for &h in &head {
                    self.supports[h as usize].push((b, index as u32));
                }
            }
            HeadKind::Disjunction => {
                let mut c = std::mem::take(&mut self.lits_buf);
                c.push(!b);
                c.extend(head.iter().map(|&h| self.atom_lit[h as usize]));
                e.add_clause(&c);
                c.clear();
                self.lits_buf = c;
                if head.len() == 1 {
                    self.supports[head[0] as usize].push((b, index as u32));
                } else {
                    for &h in &head {
                        let mut conj = vec![b];
                        conj.extend(
                            head.iter()
                                .filter(|&&o| o != h)
                                .map(|&o| !self.atom_lit[o as usize]),
                        );
                        let s = self.conjunction(e, &conj);
                        self.supports[h as usize].push((s, index as u32));
                    }
                }
            }
        }
    }

    /// Adds the completion clause of atom `a`: true only if some support holds.
    pub fn complete(&mut self, e: &mut Engine, a: usize) {
        if self.free[a] {
            return;
        }
        // Satisfied at level 0 (a fact's atom and its fact's true body): nothing to add.
        if e.true_at_level0(!self.atom_lit[a])
            || self.supports[a].iter().any(|&(s, _)| e.true_at_level0(s))
        {
            return;
        }
        let mut c = std::mem::take(&mut self.lits_buf);
        c.push(!self.atom_lit[a]);
        c.extend(self.supports[a].iter().map(|&(s, _)| s));
        e.add_clause(&c);
        c.clear();
        self.lits_buf = c;
    }

    /// Computes strongly connected components of the positive dependency graph, decides
    /// head-cycle-freeness and installs the unfounded-set propagator if there are cycles.
    pub fn install_unfounded(&mut self, p: &GroundProgram, e: &mut Engine) {
        self.install_unfounded_with(p, e, None);
    }

    /// `install_unfounded` with the components of `p`'s positive dependency graph over
    /// `self.atom_lit.len()` atoms, when already known.
    fn install_unfounded_with(&mut self, p: &GroundProgram, e: &mut Engine, known: Option<Cycles>) {
        let n = self.atom_lit.len();
        let Cycles { comp, cyclic } = known.unwrap_or_else(|| Cycles::of(p, n, |_, _| {}));
        debug_assert_eq!(comp.len(), n);
        self.next_comp = comp.iter().copied().max().map_or(0, |c| c + 1);
        self.cyclic_atoms = (0..n as u32).filter(|&a| cyclic[a as usize]).collect();
        self.comp = comp;
        self.cyclic = cyclic;
        self.rebuild_unfounded(p, e);
    }

    /// Updates the components after a step whose rules (those from index `first_rule` on)
    /// gave rules to the atoms `defined` (new atoms, or externals until now), and reinstalls
    /// the unfounded-set propagator when some atom became cyclic. Atoms defined in earlier
    /// steps keep their rules, so every new positive cycle goes through `defined`: when no
    /// defined atom occurred positively in an earlier rule body (`pos_occ_before`), no earlier
    /// atom reaches one and the new cycles lie among `defined`, found by Tarjan's algorithm
    /// on the new rules alone; otherwise the components of the whole program are recomputed.
    pub fn update_cycles(
        &mut self,
        p: &GroundProgram,
        e: &mut Engine,
        defined: &[u32],
        first_rule: usize,
        pos_occ_before: bool,
    ) {
        if pos_occ_before {
            let n = self.atom_lit.len();
            let before = self.cyclic_atoms.len();
            let c = Cycles::of(p, n, |_, _| {});
            let changed = c.cyclic != self.cyclic || before > 0;
            self.next_comp = c.comp.iter().copied().max().map_or(0, |c| c + 1);
            self.cyclic_atoms = (0..n as u32).filter(|&a| c.cyclic[a as usize]).collect();
            self.comp = c.comp;
            self.cyclic = c.cyclic;
            if changed {
                self.rebuild_unfounded(p, e);
            }
            return;
        }
        let local: HashMap<u32, u32> = defined
            .iter()
            .enumerate()
            .map(|(i, &a)| (a, i as u32))
            .collect();
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); defined.len()];
        for ri in first_rule..p.rules.len() {
            let r = p.rules.get(ri);
            if r.head.is_empty() {
                continue;
            }
            let mut targets: SmallVec<[u32; 8]> = SmallVec::new();
            match r.body {
                BodyRef::Normal(ls) => targets.extend(
                    ls.iter()
                        .filter(|&&l| l > 0)
                        .filter_map(|&l| local.get(&(l as u32)).copied()),
                ),
                BodyRef::Weight { lits, .. } => targets.extend(
                    lits.iter()
                        .filter(|&&(l, w)| l > 0 && w > 0)
                        .filter_map(|&(l, _)| local.get(&(l as u32)).copied()),
                ),
            }
            if targets.is_empty() {
                continue;
            }
            for &h in r.head {
                if let Some(&hl) = local.get(&h) {
                    lists[hl as usize].extend_from_slice(&targets);
                }
            }
        }
        if lists.iter().all(|l| l.is_empty()) {
            return;
        }
        let g = Graph::from_lists(&lists);
        let comp = scc(&g);
        let mut size: HashMap<u32, u32> = HashMap::new();
        for &c in &comp {
            *size.entry(c).or_default() += 1;
        }
        let mut any = false;
        for (i, &a) in defined.iter().enumerate() {
            let c = comp[i];
            let cyc = size[&c] > 1 || g.succ(i).contains(&(i as u32));
            self.comp[a as usize] = self.next_comp + c;
            if cyc {
                self.cyclic[a as usize] = true;
                self.cyclic_atoms.push(a);
                any = true;
            }
        }
        self.next_comp += size.len() as u32;
        if any {
            self.rebuild_unfounded(p, e);
        }
    }

    /// Decides head-cycle-freeness and (re)installs the unfounded-set propagator over the
    /// cyclic atoms (none installed when there are none). Work proportional to the cyclic
    /// atoms, their supports and the disjunctive rules.
    fn rebuild_unfounded(&mut self, p: &GroundProgram, e: &mut Engine) {
        let (comp, cyclic) = (&self.comp, &self.cyclic);
        self.non_hcf = self.disj_rules.iter().any(|&ri| {
            let r = p.rules.get(ri as usize);
            r.head.iter().enumerate().any(|(i, &h)| {
                cyclic[h as usize]
                    && r.head[i + 1..]
                        .iter()
                        .any(|&g| g != h && comp[g as usize] == comp[h as usize])
            })
        });
        let mut local: HashMap<u32, u32> = HashMap::new();
        let mut atom_lits = Vec::new();
        let mut components = Vec::new();
        let mut atoms: Vec<u32> = self
            .cyclic_atoms
            .iter()
            .copied()
            .filter(|&a| !self.free[a as usize])
            .collect();
        atoms.sort_unstable();
        for &a in &atoms {
            local.insert(a, atom_lits.len() as u32);
            atom_lits.push(self.atom_lit[a as usize]);
            components.push(self.comp[a as usize]);
        }
        if atom_lits.is_empty() {
            if e.has_unfounded() {
                e.set_unfounded(None);
            }
            return;
        }
        let loc = |l: i32| -> Option<u32> {
            if l > 0 {
                local.get(&(l as u32)).copied()
            } else {
                None
            }
        };
        let mut sups = Vec::new();
        for &a in &atoms {
            for &(s, ri) in &self.supports[a as usize] {
                let ri = ri as usize;
                let r = p.rules.get(ri);
                // Non-HCF programs use the rule body as support (see the module comment).
                let lit = if self.non_hcf { self.rule_body[ri] } else { s };
                let body = match r.body {
                    BodyRef::Normal(ls) => {
                        SupportBody::Normal(ls.iter().filter_map(|&l| loc(l)).collect())
                    }
                    BodyRef::Weight { lower, lits } => {
                        let mut bound = lower as i128;
                        let mut wl = Vec::new();
                        for &(l, w) in lits {
                            if w > 0 {
                                wl.push((self.lit(l), w as u64, loc(l)));
                            } else if w < 0 {
                                bound -= w as i128;
                                wl.push((!self.lit(l), (-(w as i128)) as u64, None));
                            }
                        }
                        SupportBody::Weight {
                            bound: bound.max(0) as u64,
                            lits: wl,
                        }
                    }
                };
                sups.push(Support {
                    head: local[&a],
                    lit,
                    body,
                });
            }
        }
        let uf = Unfounded::new(atom_lits, components, sups);
        e.set_unfounded(Some(uf));
    }
}

/// The strongly connected components of the positive dependency graph.
struct Cycles {
    /// Per atom: its component.
    comp: Vec<u32>,
    /// Per atom: on a positive cycle (its component has two or more atoms, or a self-loop);
    /// index 0 (the constant true) never is.
    cyclic: Vec<bool>,
}

impl Cycles {
    /// The components of `p`'s positive dependency graph over atoms `0..n`; `visit` sees
    /// every rule and its index on the way. The graph is freed on return: it is as large as
    /// the program's positive dependencies.
    fn of(p: &GroundProgram, n: usize, visit: impl FnMut(usize, &RuleRef<'_>)) -> Cycles {
        let edges = positive_edges(p, n, visit);
        let comp = scc(&edges);
        let mut size = vec![0u32; n];
        for &c in &comp {
            size[c as usize] += 1;
        }
        let cyclic = (0..n)
            .map(|a| {
                a > 0
                    && (size[comp[a] as usize] > 1
                        || edges.succ(a).iter().any(|&b| b as usize == a))
            })
            .collect();
        Cycles { comp, cyclic }
    }
}

/// What an atom is known to be equivalent to before translation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Equiv {
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
fn equivalences(
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
struct HeadRules {
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
    fn new(n: usize) -> HeadRules {
        HeadRules {
            count: vec![0; n],
            rule: vec![u32::MAX; n],
            shape: vec![Shape::Other; n],
            disjunctive: false,
        }
    }

    /// Records rule `i`, `r`.
    fn add(&mut self, i: usize, r: &RuleRef<'_>) {
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
fn external_free(p: &GroundProgram, n: usize) -> Vec<bool> {
    let mut free = vec![false; n + 1];
    for &(a, v) in &p.externals {
        free[a as usize] = v != ExternalValue::Release;
    }
    free
}

/// Per atom: whether a positive path of the dependency graph leads from it to an external
/// atom (`free`). A later step may give such an external rules that close a positive cycle
/// through the atom, so the atom may not share a variable with an atom it depends on.
fn reaches_external(p: &GroundProgram, n: usize, free: &[bool]) -> Vec<bool> {
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
fn resolve_aliases(eqs: &[Equiv], lit: &mut [Option<Lit>], e: &mut Engine) {
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

/// The positive dependency graph: per atom, the atoms of positive body literals (positive
/// weights) of its rules. `visit` sees every rule and its index, in the first of the two
/// passes over the rules.
fn positive_edges(
    p: &GroundProgram,
    n: usize,
    mut visit: impl FnMut(usize, &RuleRef<'_>),
) -> Graph {
    let positive = |r: &RuleRef<'_>| -> usize {
        if r.head.is_empty() {
            // Integrity constraints (most rules of some programs) give no edge.
            return 0;
        }
        match r.body {
            BodyRef::Normal(ls) => ls.iter().filter(|&&l| l > 0).count(),
            BodyRef::Weight { lits, .. } => lits.iter().filter(|&&(l, w)| l > 0 && w > 0).count(),
        }
    };
    // Two passes (count, then fill) into one flat array: a `Vec` per atom cost 24 bytes of
    // header per atom even for the many atoms without edges.
    // The second pass visits only the rules with edges, noted in the first.
    let mut first = vec![0usize; n + 1];
    let mut with_edges: Vec<u32> = Vec::new();
    for (i, r) in p.rules.iter().enumerate() {
        visit(i, &r);
        let k = positive(&r);
        if k > 0 {
            with_edges.push(i as u32);
            for &h in r.head {
                first[h as usize + 1] += k;
            }
        }
    }
    for a in 0..n {
        first[a + 1] += first[a];
    }
    let mut fill = first.clone();
    let mut targets = vec![0u32; first[n]];
    for &i in &with_edges {
        let r = p.rules.get(i as usize);
        for &h in r.head {
            let at = &mut fill[h as usize];
            let mut put = |b: u32| {
                targets[*at] = b;
                *at += 1;
            };
            match r.body {
                BodyRef::Normal(ls) => ls.iter().filter(|&&l| l > 0).for_each(|&l| put(l as u32)),
                BodyRef::Weight { lits, .. } => lits
                    .iter()
                    .filter(|&&(l, w)| l > 0 && w > 0)
                    .for_each(|&(l, _)| put(l as u32)),
            }
        }
    }
    Graph { first, targets }
}

/// A directed graph over nodes `0..len()` in compressed form: the successors of `v` are
/// `targets[first[v]..first[v + 1]]`, in the order they were added.
pub struct Graph {
    first: Vec<usize>,
    targets: Vec<u32>,
}

impl Graph {
    /// The graph with the given successor lists.
    pub fn from_lists(lists: &[Vec<u32>]) -> Graph {
        let mut first = vec![0usize];
        let mut targets = Vec::new();
        for l in lists {
            targets.extend_from_slice(l);
            first.push(targets.len());
        }
        Graph { first, targets }
    }

    /// The number of nodes.
    pub fn len(&self) -> usize {
        self.first.len() - 1
    }

    /// Whether the graph has no node.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The successors of `v`.
    pub fn succ(&self, v: usize) -> &[u32] {
        &self.targets[self.first[v]..self.first[v + 1]]
    }
}

/// What `Translation::lookup_conj` found: the conjunction's literal, or the key's hash under
/// which a new one is entered.
enum ConjLookup {
    Known(Lit),
    New(u64),
}

/// Writes into the empty `key` the key of the conjunction of `lits`: their codes, sorted,
/// without repeats.
fn conj_key(key: &mut Vec<u32>, lits: impl Iterator<Item = Lit>) {
    debug_assert!(key.is_empty());
    key.extend(lits.map(|l| l.code() as u32));
    key.sort_unstable();
    key.dedup();
}

/// Tarjan's strongly connected components, iteratively; returns the component of each node.
pub fn scc(edges: &Graph) -> Vec<u32> {
    let n = edges.len();
    let mut index = vec![u32::MAX; n];
    let mut low = vec![0u32; n];
    let mut on_stack = vec![false; n];
    let mut comp = vec![u32::MAX; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut next = 0u32;
    let mut ncomp = 0u32;
    // The depth-first path as (node, next successor to visit); empty between roots.
    let mut call: Vec<(u32, usize)> = Vec::new();
    for root in 0..n {
        if index[root] != u32::MAX {
            continue;
        }
        if edges.succ(root).is_empty() {
            // A root without successors is a component of its own (most atoms of most
            // programs): what the search below would find, in the same order.
            index[root] = next;
            next += 1;
            comp[root] = ncomp;
            ncomp += 1;
            continue;
        }
        call.push((root as u32, 0));
        index[root] = next;
        low[root] = next;
        next += 1;
        stack.push(root as u32);
        on_stack[root] = true;
        while let Some(&mut (v, ref mut k)) = call.last_mut() {
            let v = v as usize;
            let succ = edges.succ(v);
            if *k < succ.len() {
                let w = succ[*k] as usize;
                *k += 1;
                if index[w] == u32::MAX {
                    index[w] = next;
                    low[w] = next;
                    next += 1;
                    stack.push(w as u32);
                    on_stack[w] = true;
                    call.push((w as u32, 0));
                } else if on_stack[w] {
                    low[v] = low[v].min(index[w]);
                }
            } else {
                call.pop();
                if let Some(&(u, _)) = call.last() {
                    low[u as usize] = low[u as usize].min(low[v]);
                }
                if low[v] == index[v] {
                    loop {
                        let w = stack.pop().expect("Tarjan stack holds the component") as usize;
                        on_stack[w] = false;
                        comp[w] = ncomp;
                        if w == v {
                            break;
                        }
                    }
                    ncomp += 1;
                }
            }
        }
    }
    comp
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scc_finds_cycles() {
        // 0 -> 1 -> 2 -> 1, 3 alone.
        let edges = vec![vec![1], vec![2], vec![1], vec![]];
        let c = scc(&Graph::from_lists(&edges));
        assert_eq!(c[1], c[2]);
        assert_ne!(c[0], c[1]);
        assert_ne!(c[3], c[1]);
    }
}
