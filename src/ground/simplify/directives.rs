//! The directives besides rules, outputs and minimize statements, renumbered for aspif:
//! externals, projected atoms, heuristics and edges (their conditions with the decided
//! literals removed).
//!
//! Invariants: a heuristic or edge whose condition is false is dropped (an unnumbered atom
//! occurs in no rule, so it is false, as for shows); so is a heuristic on an unnumbered atom.

use super::{map_lit, truth, Status};
use crate::ground::instantiate::Grounder;
use crate::ground::program::{GroundProgram, Lit};

/// `cond` without its true literals, renumbered; `None` when one is false.
pub(super) fn cond_map(cond: &[Lit], status: &[Status], number: &[u32]) -> Option<Vec<Lit>> {
    let mut c = Vec::new();
    for &l in cond {
        match truth(l, status) {
            Some(true) => {}
            Some(false) => return None,
            None => {
                // As for shows: an unnumbered atom is false.
                if number[l.unsigned_abs() as usize] == 0 {
                    if l > 0 {
                        return None;
                    }
                } else {
                    c.push(map_lit(number, l))
                }
            }
        }
    }
    Some(c)
}

/// Sets the externals, projections, heuristics and edges of `out` from those of `g`.
pub(super) fn directives(
    g: &Grounder<'_>,
    status: &[Status],
    number: &[u32],
    out: &mut GroundProgram,
) {
    out.externals = g
        .directives
        .externals
        .iter()
        .map(|&(a, v)| (number[a.get() as usize], v))
        .collect();
    out.projections = g
        .directives
        .projections
        .iter()
        .filter(|&&a| number[a.get() as usize] != 0)
        .map(|&a| number[a.get() as usize])
        .collect();
    for h in &g.directives.heuristics {
        if number[h.atom as usize] == 0 {
            continue;
        }
        if let Some(condition) = cond_map(&h.condition, status, number) {
            let mut h2 = h.clone();
            h2.atom = number[h.atom as usize];
            h2.condition = condition;
            out.heuristics.push(h2);
        }
    }
    for e in &g.directives.edges {
        if let Some(condition) = cond_map(&e.condition, status, number) {
            let mut e2 = e.clone();
            e2.condition = condition;
            out.edges.push(e2);
        }
    }
}
