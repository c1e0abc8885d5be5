//! Theory atoms renumbered for aspif: each ground theory atom with its terms as
//! [`TheoryTerm`]s, its elements' conditions without their decided literals (an element whose
//! condition is false is dropped), and its atom made free (an external of value free) when no
//! rule heads it, as clasp treats a theory atom without rules.
//!
//! Invariant: every theory atom has an aspif number (`numbering` gives one to those no rule
//! names); the writers print the free ones as theory atoms, not as externals.

use super::directives::cond_map;
use super::Status;
use crate::ground::instantiate::Grounder;
use crate::ground::program::{ExternalValue, GroundProgram, TheoryAtom, TheoryElement, TheoryTerm};
use crate::ground::symbol::{SymData, SymId, Symbols};

/// The theory term a ground symbol of the rewriting's encoding stands for (see
/// `rewrite::theory`).
pub fn theory_term(syms: &Symbols, id: SymId) -> TheoryTerm {
    match syms.get(id) {
        SymData::Num(n) => TheoryTerm::Number(n),
        SymData::Inf => TheoryTerm::Symbol("#inf".into()),
        SymData::Sup => TheoryTerm::Symbol("#sup".into()),
        SymData::Str(_) => TheoryTerm::Symbol(syms.show(id)),
        SymData::Fun { name, neg, .. } => {
            let name = syms.names.resolve(name);
            let args: Vec<TheoryTerm> = syms
                .args(id)
                .iter()
                .map(|&a| theory_term(syms, a))
                .collect();
            let sign = if neg { "-" } else { "" };
            match name {
                "" => TheoryTerm::Tuple(args),
                "{}" => TheoryTerm::Set(args),
                "[]" => TheoryTerm::List(args),
                _ if args.is_empty() => TheoryTerm::Symbol(format!("{sign}{name}")),
                _ => TheoryTerm::Function(format!("{sign}{name}"), args),
            }
        }
    }
}

/// Sets `out.theory_atoms` from the grounder's, and makes the unheaded ones free externals.
pub(super) fn theory_atoms(
    g: &Grounder<'_>,
    status: &[Status],
    number: &[u32],
    out: &mut GroundProgram,
) {
    for t in &g.directives.theory.atoms {
        let mut elements: Vec<TheoryElement> = Vec::new();
        for (terms, cond) in &t.elems {
            let Some(condition) = cond_map(cond, status, number) else {
                continue;
            };
            let e = TheoryElement {
                terms: terms.iter().map(|&s| theory_term(&g.syms, s)).collect(),
                condition,
            };
            if !elements.contains(&e) {
                elements.push(e);
            }
        }
        out.theory_atoms.push(TheoryAtom {
            atom: t.atom.map_or(0, |a| number[a.get() as usize]),
            term: theory_term(&g.syms, t.name),
            elements,
            guard: t.guard.map(|(op, s)| {
                (
                    g.syms.names.resolve(op).to_string(),
                    theory_term(&g.syms, s),
                )
            }),
        });
    }
    for a in out.free_theory_atoms() {
        if !out.externals.iter().any(|&(b, _)| b == a) {
            out.externals.push((a, ExternalValue::Free));
        }
    }
}
