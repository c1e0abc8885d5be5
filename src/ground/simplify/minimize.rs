//! Minimize statements: the grounder's elements (a key of priority, weight and tuple, with
//! alternative conditions) simplified by the atoms' status and gathered into one statement
//! per priority, highest first. An element with several alternatives (or one of several
//! literals) gets an auxiliary atom, defined by one rule per alternative; a certain element a
//! fact atom, since clasp needs a literal.
//!
//! Invariants: elements keep the grounder's key order; a priority whose every element was
//! simplified away but that gringo would keep (it keeps contradictory conditions and the atoms
//! only contradictory rules derive) stays as an empty statement, so the answer is an optimum
//! of 0 as clingo's. The literals are over grounder atoms; `finish_after` renumbers them.

use super::propagate::contradictory_lits;
use super::rules::removed_lit;
use super::{new_aux, truth, Status, Written};
use crate::ground::instantiate::Grounder;
use crate::ground::program::{BodyRef, HeadKind, Lit, Minimize, Origin, RemovedLit};

/// The minimize statements of `g`, over grounder atoms; the rules of their auxiliary atoms are
/// written to `w`. `gringo_status`: what gringo would still find possible, when it differs
/// from `status`.
pub(super) fn minimize(
    g: &mut Grounder<'_>,
    status: &mut Vec<Status>,
    gringo_status: Option<&[Status]>,
    w: &mut Written,
) -> Vec<Minimize> {
    let prov = g.provenance;
    let mut removed: Vec<RemovedLit> = Vec::new();
    // Minimize statements: one per priority, highest first.
    let mut minimize: Vec<Minimize> = Vec::new();
    let keys = std::mem::take(&mut g.directives.minimize_order);
    let mut elements: Vec<(i32, i32, Lit)> = Vec::new();
    // Priorities whose every element Lucent simplified away but gringo would keep (a condition
    // holding a literal and its negation, or an atom only a contradictory rule derives): they
    // stay as empty statements, so the answer is an optimum of 0 as clingo's.
    let mut empty_prios: Vec<i32> = Vec::new();
    for key in keys {
        let conds = g.directives.minimize.get(&key).cloned().unwrap_or_default();
        let gstatus = gringo_status.unwrap_or(&status[..]);
        let gringo_keeps = conds
            .iter()
            .any(|c| c.iter().all(|&l| truth(l, gstatus) != Some(false)));
        let mut cond_origins = g.prov.minimize_origins.remove(&key).unwrap_or_default();
        let mut alts: Vec<Vec<Lit>> = Vec::new();
        // With provenance: the origins of each alternative, and of the certain ones.
        let mut alt_origins: Vec<Vec<Origin>> = Vec::new();
        let mut certain_origins: Vec<Origin> = Vec::new();
        let mut certain = false;
        for (ci, c) in conds.into_iter().enumerate() {
            let mut out = Vec::new();
            let mut ok = !contradictory_lits(&c);
            removed.clear();
            for l in c {
                match truth(l, status) {
                    Some(true) if prov => removed.push(removed_lit(l)),
                    Some(true) => {}
                    Some(false) => ok = false,
                    None => out.push(l),
                }
            }
            if ok {
                certain |= out.is_empty();
                if prov {
                    let mut os = cond_origins
                        .get_mut(ci)
                        .map(std::mem::take)
                        .unwrap_or_default();
                    for o in &mut os {
                        o.removed.extend_from_slice(&removed);
                    }
                    if out.is_empty() {
                        certain_origins.extend(os.iter().cloned());
                    }
                    alt_origins.push(os);
                }
                alts.push(out);
            }
        }
        if alts.is_empty() {
            if gringo_keeps {
                empty_prios.push(key.0);
            }
            continue;
        }
        let lit = element_lit(
            g,
            status,
            w,
            certain,
            alts,
            &mut alt_origins,
            &mut certain_origins,
        );
        elements.push((key.0, key.1, lit));
    }
    let mut prios: Vec<i32> = elements.iter().map(|e| e.0).collect();
    prios.extend(empty_prios);
    prios.sort_unstable_by(|a, b| b.cmp(a));
    prios.dedup();
    for p in prios {
        minimize.push(Minimize {
            priority: p as i64,
            lits: elements
                .iter()
                .filter(|e| e.0 == p)
                .map(|e| (e.2, e.1 as i64))
                .collect(),
        });
    }
    minimize
}

/// The literal of an element with the (non-empty) alternative conditions `alts`: a fact atom
/// when it is `certain`, its one literal, or an auxiliary atom with a rule per alternative
/// (written to `w`, with the origins of `alt_origins` or `certain_origins`).
fn element_lit(
    g: &mut Grounder<'_>,
    status: &mut Vec<Status>,
    w: &mut Written,
    certain: bool,
    alts: Vec<Vec<Lit>>,
    alt_origins: &mut [Vec<Origin>],
    certain_origins: &mut Vec<Origin>,
) -> Lit {
    let prov = g.provenance;
    let lit = if certain {
        None
    } else if alts.len() == 1 && alts[0].len() == 1 {
        Some(alts[0][0])
    } else {
        let a = new_aux(g, status);
        for (i, alt) in alts.into_iter().enumerate() {
            w.numbering.push(
                &mut w.rules,
                HeadKind::Disjunction,
                &[a.get()],
                BodyRef::Normal(&alt),
                &g.atoms,
            );
            if prov {
                w.origins.push_rule(std::mem::take(&mut alt_origins[i]));
            }
        }
        Some(a.lit())
    };
    match lit {
        Some(l) => l,
        None => {
            // A certain element: its weight is always counted; clasp needs a literal, so use
            // a fact atom.
            let a = new_aux(g, status);
            status[a.index()] = Status::Fact;
            w.numbering.push(
                &mut w.rules,
                HeadKind::Disjunction,
                &[a.get()],
                BodyRef::Normal(&[]),
                &g.atoms,
            );
            if prov {
                w.origins.push_rule(std::mem::take(certain_origins));
            }
            a.lit()
        }
    }
}
