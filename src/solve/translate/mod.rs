//! Translation of a ground program into the engine's constraints: the [`Translation`] that links
//! atoms, rule bodies, outputs and minimize statements to engine literals, the whole-program
//! `build`, and the bookkeeping of externals and assumptions across steps. The techniques live
//! in submodules, one each: `completion` (Clark completion with body variables, shifting of
//! disjunctive heads, native weight constraints for weight bodies), `merge` (atoms equivalent
//! by completion merged before translation, clasp's `--eq`), `deps` (the positive dependency
//! graph: which atoms need unfounded-set propagation and whether the program is
//! head-cycle-free) and `graph` (Tarjan's strongly connected components).
//!
//! Invariants:
//! - Every atom `1..=num_atoms` has a solver literal (`atom_lit`); index 0 holds the constant
//!   true literal. Merged atoms (`merge`) share a literal (possibly negated) with another atom,
//!   the true literal or their body; every rule still gets its clauses (`completion`), so the
//!   completion holds over the merged literals.
//! - The per-atom vectors (`atom_lit`, `supports`, `free`, `ext_value`, `pos_occ`, and after
//!   `deps` has run `comp` and `cyclic`) have one entry per atom, index 0 included;
//!   `grow_atoms` extends them together.
//! - `assumptions` is the program's assumptions followed by the true externals and the
//!   negations of the false ones (`refresh_assumptions`); `free` decides which atoms of
//!   `ext_atoms` are still external.

mod completion;
mod deps;
mod graph;
mod merge;

use super::engine::Engine;
use super::lit::Lit;
use crate::ground::program::{BodyRef, ExternalValue, GroundProgram};
use deps::Cycles;
use hashbrown::{DefaultHashBuilder, HashMap, HashTable};
use merge::{equivalences, external_free, reaches_external, resolve_aliases, Equiv, HeadRules};
use smallvec::SmallVec;

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
}
