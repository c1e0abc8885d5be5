//! The rules pass: each rule that propagation left alive is simplified and written numbered
//! (see `numbering`): facts and `not a` with `a` false leave normal bodies (a weight body loses
//! the weight of its true literals, and dies when its bound is out of reach), satisfied and
//! false heads are dropped, and a second rule for a fact adds its origins to the fact's rule.
//!
//! Invariants: the rules come out in the grounder's order (the numbering follows it); a fact
//! gets one output rule `a.`, whose index is recorded so later rules for it are folded into it;
//! with provenance, every output rule keeps the origins of every grounder rule that became it,
//! and a removed rule with a false head atom (or a fact among its heads) is buried as a
//! `DeadRule` with its reason.

use super::numbering::{gringo_body_order, Numbering};
use super::scope::Scope;
use super::{fact_among, truth, Status, Written};
use crate::ground::instantiate::Grounder;
use crate::ground::program::{
    BodyRef, DeadReason, DeadRule, HeadKind, Lit, Origin, Provenance, RemovedLit, RuleOrigin,
    Rules, Weight,
};

/// The removed-literal record of a decided literal `l`.
#[inline]
pub(super) fn removed_lit(l: Lit) -> RemovedLit {
    RemovedLit {
        positive: l > 0,
        atom: l.unsigned_abs(),
    }
}

/// Simplifies and writes the rules of `g` that are not `dead` (`why`: the reason of each dead
/// one, with provenance), numbering their atoms as they come; a fact's rule marks it a fact
/// in `status`. `external` atoms keep their heads; `fresh` is the room the numbering reserves,
/// `number` its array (all 0; the session's, see [`Scope`], which holds every atom the rules
/// name).
#[allow(clippy::too_many_arguments)]
pub(super) fn simplify_rules(
    g: &mut Grounder<'_>,
    scope: &Scope,
    status: &mut [Status],
    external: &[bool],
    dead: &[bool],
    why: &[Option<DeadReason>],
    fresh: usize,
    number: Vec<u32>,
) -> Written {
    let n = g.atoms.len();
    let prov = g.provenance;
    // Simplify the surviving rules.
    // Stored flat (`Rules`): the program outlives grounding and is held beside the solver.
    // They are written numbered for aspif as they come (see `Numbering`).
    // The output is at most the ground rules (a few constraints on complementary atoms
    // aside): room for them at once instead of growing step by step.
    let mut rules = Rules::new();
    rules.reserve_like(&g.rules);
    let mut numbering = Numbering::new(number, n, fresh);
    // With provenance: the origins of each output rule, and the removed rules that headed a
    // false atom.
    let mut origins = Provenance::new();
    // Origins of second rules for facts, added to the fact's rule at the end.
    let mut late: Vec<(u32, Origin)> = Vec::new();
    let mut dead_rules: Vec<DeadRule> = std::mem::take(&mut g.prov.dead);
    let mut g_origins = std::mem::take(&mut g.prov.origins);
    let mut g_more = std::mem::take(&mut g.prov.more_origins);
    let mut take_origins = |ri: usize| -> Vec<Origin> {
        let mut os = vec![std::mem::replace(
            &mut g_origins[ri],
            Origin {
                rule: RuleOrigin::Complement,
                removed: Vec::new(),
            },
        )];
        os.extend(g_more.remove(&(ri as u32)).unwrap_or_default());
        os
    };
    let mut removed: Vec<RemovedLit> = Vec::new();
    // The output rule `a.` of each fact atom `a`, by local index (u32::MAX: none yet).
    let mut fact_rule = vec![u32::MAX; scope.len()];
    // The rules are moved out (the grounder's copy is not used after this); each surviving
    // rule is simplified in the scratch vectors and copied to `rules`.
    let old = std::mem::take(&mut g.rules);
    let mut head: Vec<u32> = Vec::new();
    let mut lits: Vec<Lit> = Vec::new();
    let mut ordered: Vec<Lit> = Vec::new();
    let mut wlits: Vec<(Lit, Weight)> = Vec::new();
    // Records a removed rule that headed a false atom, or that a fact among its heads
    // satisfied (provenance: every rule instance keeps its origin).
    let mut bury = |ri: usize,
                    head: &[u32],
                    reason: DeadReason,
                    status: &[Status],
                    take: &mut dyn FnMut(usize) -> Vec<Origin>| {
        if prov
            && (matches!(reason, DeadReason::HeadFact(_))
                || head
                    .iter()
                    .any(|&h| status[h as usize - 1] == Status::False))
        {
            dead_rules.push(DeadRule {
                head: head.to_vec(),
                origins: take(ri),
                why: reason,
            });
        }
    };
    for (ri, r) in old.iter().enumerate() {
        if dead[ri] {
            if let Some(&Some(reason)) = why.get(ri) {
                bury(ri, r.head, reason, status, &mut take_origins);
            }
            continue;
        }
        lits.clear();
        wlits.clear();
        removed.clear();
        let body = match simplify_body(
            r.body,
            status,
            prov,
            &mut lits,
            &mut ordered,
            &mut wlits,
            &mut removed,
        ) {
            Ok(body) => body,
            Err(reason) => {
                bury(ri, r.head, reason, status, &mut take_origins);
                continue;
            }
        };
        head.clear();
        head.extend_from_slice(r.head);
        if r.head_kind == HeadKind::Disjunction {
            if let Some(f) = fact_among(&head, status) {
                if !(head.len() == 1 && body.is_empty_normal()) {
                    bury(
                        ri,
                        r.head,
                        DeadReason::HeadFact(f),
                        status,
                        &mut take_origins,
                    );
                    continue;
                }
            }
            head.retain(|&h| status[h as usize - 1] != Status::False || external[h as usize]);
        } else {
            head.retain(|&h| status[h as usize - 1] == Status::Unknown || external[h as usize]);
            if head.is_empty() {
                // A choice among facts (and false atoms): kept as satisfied by a fact.
                if let Some(f) = fact_among(r.head, status) {
                    bury(
                        ri,
                        r.head,
                        DeadReason::HeadFact(f),
                        status,
                        &mut take_origins,
                    );
                }
                continue;
            }
        }
        let with_removed = |mut os: Vec<Origin>, removed: &[RemovedLit]| {
            for o in &mut os {
                o.removed.extend_from_slice(removed);
            }
            os
        };
        if r.head_kind == HeadKind::Disjunction && head.len() == 1 && body.is_empty_normal() {
            let h = head[0] as usize;
            let hi = scope.index(h);
            if fact_rule[hi] != u32::MAX {
                // A second rule for a fact: its origins are more origins of the fact's rule.
                if prov {
                    let os = with_removed(take_origins(ri), &removed);
                    late.extend(os.into_iter().map(|o| (fact_rule[hi], o)));
                }
                continue;
            }
            fact_rule[hi] = rules.len() as u32;
            status[h - 1] = Status::Fact;
        }
        numbering.push(&mut rules, r.head_kind, &head, body, &g.atoms);
        if prov {
            origins.push_rule(with_removed(take_origins(ri), &removed));
        }
    }
    drop(g_origins);
    drop(g_more);
    drop(old);
    Written {
        rules,
        numbering,
        origins,
        late,
        dead_rules,
    }
}

/// The body `body` without its decided literals: a normal body in gringo's order in
/// `ordered` (built in `lits`), a weight body in `wlits` with its bound lowered by the weight
/// of its true literals; with provenance, the true literals go to `removed`. `Err`: the body
/// cannot hold (a false literal, or a bound out of reach), with the reason.
#[inline]
fn simplify_body<'s>(
    body: BodyRef<'_>,
    status: &[Status],
    prov: bool,
    lits: &mut Vec<Lit>,
    ordered: &'s mut Vec<Lit>,
    wlits: &'s mut Vec<(Lit, Weight)>,
    removed: &mut Vec<RemovedLit>,
) -> Result<BodyRef<'s>, DeadReason> {
    Ok(match body {
        BodyRef::Normal(ls) => {
            let mut failed = None;
            for &l in ls {
                match truth(l, status) {
                    Some(true) if prov => removed.push(removed_lit(l)),
                    Some(true) => {}
                    Some(false) => {
                        failed = Some(l);
                        break;
                    }
                    None => lits.push(l),
                }
            }
            if let Some(l) = failed {
                return Err(DeadReason::Literal {
                    positive: l > 0,
                    atom: l.unsigned_abs(),
                });
            }
            gringo_body_order(lits, ordered);
            BodyRef::Normal(ordered)
        }
        BodyRef::Weight { lower, lits: ls } => {
            let mut lower = lower;
            for &(l, w) in ls {
                match truth(l, status) {
                    Some(true) => {
                        lower -= w;
                        if prov {
                            removed.push(removed_lit(l));
                        }
                    }
                    Some(false) => {}
                    None => wlits.push((l, w)),
                }
            }
            if lower <= 0 {
                BodyRef::Normal(&[])
            } else if wlits.iter().map(|&(_, w)| w).sum::<i64>() < lower {
                return Err(DeadReason::Unreachable);
            } else {
                BodyRef::Weight { lower, lits: wlits }
            }
        }
    })
}
