//! Clark completion with body variables (AIJ 2012, section 3): every rule body gets a literal
//! (a conjunction of two or more literals a body variable of its own, looked up by its sorted
//! literal codes; a weight body a native weight constraint), each rule gives its clauses and
//! supports, with disjunctive heads shifted into per-atom supports, and `complete` adds each
//! atom's completion clause.
//!
//! Invariants:
//! - For a rule `H :- B`, `B` gets one literal shared by all rules with the same body. A
//!   disjunctive rule with head atoms `h1..hn` gives `hi` the support `B and not hj (j != i)`
//!   (shifting); a choice rule gives each head atom the support `B`.
//! - Completion: an atom that is not external implies the disjunction of its supports;
//!   supports and bodies imply heads through the rule clauses. External atoms get theirs when a
//!   later step defines them (`Solver::add_program`) or releases them.
//! - A conjunction in `conj` has the clauses `b -> l` for each of its literals and
//!   `lits -> b`; the scratch buffers `key_buf` and `lits_buf` are empty between calls.

use super::Translation;
use crate::ground::program::{BodyRef, HeadKind, RuleRef};
use crate::solve::engine::Engine;
use crate::solve::lit::Lit;
use smallvec::SmallVec;
use std::hash::BuildHasher;

impl Translation {
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

    /// Makes the existing literal `x` stand for the conjunction of `lits` (clauses
    /// `x -> l` and `lits -> x`), unless that conjunction already has a literal, is a single
    /// literal, or mentions `x`'s variable; then nothing happens and the rule clauses keep the
    /// equivalence.
    pub(super) fn define_conjunction(&mut self, e: &mut Engine, lits: &[i32], x: Lit) {
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
