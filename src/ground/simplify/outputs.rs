//! Outputs and facts: every shown atom that is not false is output (unconditionally when it is
//! a fact, else under its own aspif literal), every fact atom is reported as a fact, and each
//! `#show t : body` instance is output under its condition with the decided literals removed.
//!
//! Invariants (multi-shot): a frozen atom was output by an earlier grounding, so it is not
//! output again, and it is reported as a fact only when it became one now; an atom left out of
//! the numbering occurs in no rule, so it is false in a `#show` condition; equal `#show`
//! outputs (same symbol, same condition) are output once.

use super::scope::Scope;
use super::{map_lit, shown_pred, truth, Status, KNOWN_FACT};
use crate::ground::instantiate::{GroundAtom, Grounder};
use crate::ground::program::{Lit, Output};
use crate::ground::rewrite::UNRANKED;
use crate::ground::symbol::SymId;

/// Appends the outputs of the shown atoms (`shown`, by predicate) to `outputs` and returns the
/// symbol and grounder atom of each fact; `number` is the aspif numbering, `before` the flags
/// of earlier groundings, `ranks` the predicates' domain ranks (the outputs' keys). Only the atoms of `scope` are visited: an older atom outside it was
/// output, or reported as a fact, by the grounding that decided it.
#[allow(clippy::too_many_arguments)]
pub(super) fn shown_atoms(
    g: &Grounder<'_>,
    scope: &Scope,
    status: &[Status],
    number: &[u32],
    before: &[u8],
    shown: &[bool],
    frozen: &dyn Fn(usize) -> bool,
    ranks: &[u32],
    outputs: &mut Vec<Output>,
) -> (Vec<SymId>, Vec<GroundAtom>) {
    // Outputs: shown atoms, facts with an empty condition.
    let mut fact_syms = Vec::new();
    let mut fact_atoms = Vec::new();
    for &a in &scope.atoms {
        let a = a as usize;
        let info = g.atoms[a - 1];
        let Some(sym) = info.sym else { continue };
        if frozen(a) {
            // Output earlier; a fact only when it became one now.
            if status[a - 1] == Status::Fact && before[a] & KNOWN_FACT == 0 {
                fact_syms.push(sym);
                fact_atoms.push(GroundAtom::new(a as u32));
            }
            continue;
        }
        if status[a - 1] == Status::Fact {
            fact_syms.push(sym);
            fact_atoms.push(GroundAtom::new(a as u32));
        }
        if info.in_domain && status[a - 1] != Status::False && shown_pred(shown, info.pred) {
            let condition = if status[a - 1] == Status::Fact {
                Vec::new()
            } else {
                vec![number[a] as Lit]
            };
            let rank = ranks.get(info.pred as usize).copied().unwrap_or(UNRANKED);
            outputs.push(Output {
                symbol: g.syms.show(sym),
                condition,
                order: Output::atom_order(rank, a as u32),
            });
        }
    }
    (fact_syms, fact_atoms)
}

/// Appends the outputs of the `#show t : body` instances of `g` (taken) to `outputs`.
pub(super) fn show_terms(
    g: &mut Grounder<'_>,
    status: &[Status],
    number: &[u32],
    outputs: &mut Vec<Output>,
) {
    let shows = std::mem::take(&mut g.directives.shows);
    let mut seen: hashbrown::HashSet<(SymId, Vec<Lit>)> = hashbrown::HashSet::new();
    for (sym, cond, stmt) in shows {
        let mut c = Vec::new();
        let mut ok = true;
        for l in cond {
            match truth(l, status) {
                Some(true) => {}
                Some(false) => ok = false,
                None => {
                    // An atom left out of the numbering occurs in no rule, so it is false:
                    // `not a` holds and drops out of the condition, `a` fails it.
                    if number[l.unsigned_abs() as usize] == 0 {
                        ok &= l < 0;
                    } else {
                        c.push(map_lit(number, l))
                    }
                }
            }
        }
        if ok && seen.insert((sym, c.clone())) {
            outputs.push(Output {
                symbol: g.syms.show(sym),
                condition: c,
                order: Output::term_order(stmt),
            });
        }
    }
}
