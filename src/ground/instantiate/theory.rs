//! Theory atoms grounded: for one binding of a statement's global variables, each element's
//! condition is joined like an aggregate element's (its undecided literals kept), its terms
//! evaluated, and the ground theory atom (name, distinct elements, guard) looked up or given a
//! fresh auxiliary atom; a body occurrence continues with that atom's literal, a head
//! occurrence (or directive) with the atom noted for `emit`.
//!
//! Invariant: equal ground theory atoms (same name, elements in the same order, guard) share
//! one atom; directives get none.

use super::*;
use crate::ground::rewrite::NTheory;

/// The ground theory atom's elements: terms and condition literals (grounder atoms).
pub type GElems = Vec<(Vec<SymId>, Vec<Lit>)>;

/// One ground theory atom, over grounder atoms.
#[derive(Clone, Debug)]
pub struct GTheory {
    /// Its atom (`None` for a directive).
    pub atom: Option<GroundAtom>,
    /// The name term.
    pub name: SymId,
    /// The elements.
    pub elems: GElems,
    /// Guard operator and term.
    pub guard: Option<(Sym, SymId)>,
}

/// The key of a ground theory atom.
type Key = (SymId, GElems, Option<(Sym, SymId)>, bool);

/// The theory atoms of a grounding.
#[derive(Default)]
pub struct TheoryStore {
    /// The atoms, in order of creation.
    pub atoms: Vec<GTheory>,
    /// Index of each atom by key.
    index: HashMap<Key, usize>,
    /// While a head occurrence's continuation runs: its atom (`Some(None)` for a directive).
    pub(super) head: Option<Option<GroundAtom>>,
}

impl Grounder<'_> {
    /// Grounds the theory atom `agg` stands for and continues with `k`.
    pub(super) fn theory(
        &mut self,
        ctx: &mut Ctx,
        agg: &NAgg,
        k: &mut dyn FnMut(&mut Self, &mut Ctx),
    ) {
        let th: &NTheory = agg.theory.as_deref().expect("a theory aggregate");
        let Some(name) = self.eval(&th.name, &ctx.binding) else {
            return;
        };
        let guard = match &th.guard {
            Some((op, t)) => match self.eval(t, &ctx.binding) {
                Some(v) => Some((*op, v)),
                None => return,
            },
            None => None,
        };
        let mut elems: GElems = Vec::new();
        for e in &agg.elems {
            let blen = ctx.body.len();
            self.join(ctx, &e.cond, 0, &[], &mut |g, ctx| {
                let mut t = Vec::with_capacity(e.terms.len());
                for term in &e.terms {
                    match g.eval(term, &ctx.binding) {
                        Some(v) => t.push(v),
                        None => return,
                    }
                }
                let mut c = ctx.body[blen..].to_vec();
                c.sort_unstable();
                c.dedup();
                if !elems.iter().any(|(t2, c2)| *t2 == t && *c2 == c) {
                    elems.push((t, c));
                }
            });
            ctx.body.truncate(blen);
        }
        let key: Key = (name, elems, guard, th.directive);
        let atom = match self.directives.theory.index.get(&key) {
            Some(&i) => self.directives.theory.atoms[i].atom,
            None => {
                let atom = (!th.directive).then(|| self.aux());
                let (name, elems, guard, _) = key.clone();
                let store = &mut self.directives.theory;
                store.index.insert(key, store.atoms.len());
                store.atoms.push(GTheory {
                    atom,
                    name,
                    elems,
                    guard,
                });
                atom
            }
        };
        if th.head {
            let saved = self.directives.theory.head.replace(atom);
            k(self, ctx);
            self.directives.theory.head = saved;
            return;
        }
        let Some(a) = atom else { return };
        let blen = ctx.body.len();
        ctx.body.push(if agg.sign == Sign::Positive {
            a.lit()
        } else {
            -a.lit()
        });
        k(self, ctx);
        ctx.body.truncate(blen);
    }

    /// `emit` for a theory atom in a head: the rule `atom :- body.` (a directive is recorded
    /// already).
    pub(super) fn emit_theory(&mut self, stmt: &NStmt, ctx: &mut Ctx) {
        let Some(Some(atom)) = self.directives.theory.head else {
            return;
        };
        let head = [atom.get()];
        self.add_rule_ref(
            RuleRef {
                head_kind: HeadKind::Disjunction,
                head: &head,
                body: BodyRef::Normal(&ctx.body),
            },
            |g| g.origin(stmt, ctx),
        );
    }
}
