//! CR-Prolog output: the ground CR rules whose application atom is still possible, with their
//! labels, and the `prefer(l1, l2)` facts between labels turned into pairs of application
//! atoms.
//!
//! Invariants: a CR rule whose application atom is unnumbered or decided is dropped; the
//! `prefer` facts of earlier groundings come first, so a later grounding of a multi-shot
//! session pairs them with its own CR rules; only the fresh `prefer` facts are returned, to be
//! remembered for later groundings.

use super::scope::Scope;
use super::Status;
use crate::ground::instantiate::{GroundAtom, Grounder};
use crate::ground::program::{CrRule, GroundProgram, Prefer};
use crate::ground::symbol::SymData;

/// Sets the CR rules of `out` (those whose application atom is possible) and the `prefer`
/// pairs between their labels, from the `prefer(l1, l2)` facts of `prefer_before` and the
/// fresh facts (among the atoms of `scope`); returns the fresh ones.
pub(super) fn cr_rules(
    g: &Grounder<'_>,
    scope: &Scope,
    status: &[Status],
    number: &[u32],
    prefer_before: &[GroundAtom],
    frozen: &dyn Fn(usize) -> bool,
    out: &mut GroundProgram,
) -> Vec<GroundAtom> {
    for (a, label) in &g.directives.cr_rules {
        if number[a.get() as usize] != 0 && status[a.index()] == Status::Unknown {
            out.cr_rules.push(CrRule {
                appl: number[a.get() as usize],
                label: label.clone(),
            });
        }
    }
    // prefer(l1, l2) facts between labels of CR rules (those of earlier groundings first).
    let mut prefer_atoms = Vec::new();
    let prefer_name = g.syms.names.get("prefer");
    let fresh = (scope.atoms.iter().map(|&a| a as usize))
        .filter(|&a| !frozen(a) && status[a - 1] == Status::Fact);
    for a in prefer_before.iter().map(|&a| a.get() as usize).chain(fresh) {
        let info = g.atoms[a - 1];
        let Some(sym) = info.sym else { continue };
        if status[a - 1] != Status::Fact {
            continue;
        }
        let args = g.syms.args(sym);
        let prefer = match g.syms.get(sym) {
            SymData::Fun {
                name, neg: false, ..
            } => Some(name) == prefer_name,
            _ => false,
        };
        if args.len() != 2 || !prefer {
            continue;
        }
        if !frozen(a) {
            prefer_atoms.push(GroundAtom::new(a as u32));
        }
        let (l1, l2) = (g.syms.show(args[0]), g.syms.show(args[1]));
        for better in out.cr_rules.iter().filter(|c| c.label == l1) {
            for worse in out.cr_rules.iter().filter(|c| c.label == l2) {
                out.prefers.push(Prefer {
                    better: better.appl,
                    worse: worse.appl,
                });
            }
        }
    }
    prefer_atoms
}
