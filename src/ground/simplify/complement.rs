//! Classical negation: the constraint `:- a, -a.` for every atom `-a` whose complement was
//! derived, added to the grounder's rules before simplification (with its origin when
//! provenance is on; complements that are facts are recorded as removed literals).
//!
//! Invariant (multi-shot): a grounding adds constraints only for the pairs with an atom of its
//! scope that is not frozen (new to it), so a pair gets its constraint once.

use super::scope::Scope;
use crate::ground::instantiate::{GroundAtom, Grounder};
use crate::ground::program::{Body, HeadKind, Origin, RemovedLit, Rule, RuleOrigin};
use crate::ground::rewrite::Compiled;
use crate::ground::symbol::SymData;

/// `:- a, -a.` for every atom `-a` whose complement can be derived (multi-shot: for the pairs
/// with an atom of `scope` that is not `frozen`, the others had theirs in an earlier
/// grounding).
pub(super) fn add_classical_constraints(
    g: &mut Grounder<'_>,
    prog: &Compiled,
    scope: &Scope,
    frozen: &dyn Fn(usize) -> bool,
) {
    // The atoms visited here (their pairs are found from either side).
    let visited = |a: usize| !frozen(a) && scope.contains(a);
    let mut extra = Vec::new();
    let mut removed = Vec::new();
    // Multi-shot: positive predicates with a classically negated twin, whose new atoms may
    // complete a pair with a frozen negative atom.
    let twins: Vec<bool> = if g.old_atoms == 0 {
        Vec::new()
    } else {
        let negs: hashbrown::HashSet<(crate::base::intern::Sym, u32)> = prog
            .preds
            .iter()
            .filter(|p| p.neg)
            .map(|p| (p.name, p.arity))
            .collect();
        prog.preds
            .iter()
            .map(|p| !p.neg && negs.contains(&(p.name, p.arity)))
            .collect()
    };
    for &x in &scope.atoms {
        let x = x as usize;
        if frozen(x) {
            continue;
        }
        let info = g.atoms[x - 1];
        let Some(sym) = info.sym else { continue };
        if !info.in_domain {
            continue;
        }
        let SymData::Fun { neg, .. } = g.syms.get(sym) else {
            continue;
        };
        if !neg && !twins.get(info.pred as usize).copied().unwrap_or(false) {
            continue;
        }
        // (A complement never created has no atom.)
        let Some(other) = g.syms.find_flip_sign(sym) else {
            continue;
        };
        let Some(y) = g.find_atom(other) else {
            continue;
        };
        // From the positive side only the pairs whose negative atom is not visited (the
        // others are found from their negative side).
        if !neg && visited(y.get() as usize) {
            continue;
        }
        let (a, b) = if neg {
            (x, y)
        } else {
            (y.get() as usize, GroundAtom::new(x as u32))
        };
        if !g.atoms[b.index()].in_domain || !g.atoms[a - 1].in_domain {
            continue;
        }
        let mut body = Vec::new();
        let mut facts = Vec::new();
        for x in [b, GroundAtom::new(a as u32)] {
            if !g.atoms[x.index()].fact {
                body.push(x.lit());
            } else {
                facts.push(RemovedLit {
                    positive: true,
                    atom: x.get(),
                });
            }
        }
        extra.push(body);
        removed.push(facts);
    }
    for (body, removed) in extra.into_iter().zip(removed) {
        g.rules.push(Rule {
            head_kind: HeadKind::Disjunction,
            head: Vec::new(),
            body: Body::Normal(body),
        });
        if g.provenance {
            g.prov.origins.push(Origin {
                rule: RuleOrigin::Complement,
                removed,
            });
        }
    }
}
