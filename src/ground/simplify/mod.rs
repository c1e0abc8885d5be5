//! Final simplification and output: removes the rules that need false atoms and the literals
//! that are known, numbers the surviving atoms for aspif as gringo does, and builds outputs,
//! minimize statements and the other directives. One technique per submodule:
//! - `complement`: the constraints `:- a, -a.` of classical negation, added first;
//! - `propagate`: which atoms are certainly false and which rules are dead (worklist);
//! - `numbering`: the aspif numbering, made as the output rules are written.
//!
//! This module applies their results: in kept rules, facts and `not a` with `a` false are
//! removed from bodies; satisfied and false heads are dropped.
//!
//! Invariant: the result's atoms are `1..=num_atoms`, every atom occurring anywhere is numbered.
//!
//! Provenance (when on): every output rule keeps the origins of every grounder rule that
//! became it (a second rule for a fact adds its origins to the fact's rule), each extended
//! with the body literals this pass decided; a removed rule with a head atom that ends up
//! false is kept as a `DeadRule` with its reason; the atom table records every grounder
//! atom's symbol, status and aspif number.

mod complement;
mod numbering;
mod propagate;

use complement::add_classical_constraints;
use numbering::{gringo_body_order, Numbering};
use propagate::{contradictory_lits, propagate};

use super::instantiate::{AtomId, Grounder};
use super::program::{
    AtomRecord, AtomStatus, BodyRef, CrRule, DeadReason, DeadRule, GroundProgram, HeadKind, Lit,
    Minimize, Origin, Output, Prefer, Provenance, RemovedLit, RuleOrigin, Rules, Weight,
};
use super::rewrite::Compiled;
use super::symbol::{SymData, SymId};

/// Truth status of an atom after propagation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Certainly true.
    Fact,
    /// Certainly false.
    False,
    /// Neither.
    Unknown,
}

/// What [`finish`] produces besides the program.
pub struct Finished {
    /// The aspif program.
    pub program: GroundProgram,
    /// Symbol of each aspif atom (`atom_syms[a - 1]`), `None` for auxiliary atoms. (Names are
    /// rendered only when asked for: `Grounding::atom_name`.)
    pub atom_syms: Vec<Option<SymId>>,
    /// Symbol of every fact atom (also those simplified away from bodies).
    pub fact_syms: Vec<SymId>,
    /// The grounder atom of each fact of `fact_syms`.
    pub fact_atoms: Vec<AtomId>,
    /// The grounder atom of each aspif atom (`atom_gatoms[a - 1]`).
    pub atom_gatoms: Vec<AtomId>,
    /// The `prefer(l1, l2)` facts among the atoms this call decided (multi-shot: later calls
    /// pair them with their own CR rules).
    pub prefer_atoms: Vec<AtomId>,
}

/// Multi-shot ([`finish_after`]): the atom has an aspif number from an earlier grounding.
pub const NUMBERED: u8 = 1;
/// Multi-shot ([`finish_after`]): an earlier grounding reported the atom as a fact.
pub const KNOWN_FACT: u8 = 2;

/// Adds `:- a, -a.` for complementary atoms, then simplifies and numbers.
pub fn finish(g: &mut Grounder<'_>, prog: &Compiled) -> Finished {
    finish_after(g, prog, &[], &[])
}

/// [`finish`] for a later grounding of a multi-shot session: `before[a]` holds the flags
/// ([`NUMBERED`], [`KNOWN_FACT`]) of grounder atom `a` from earlier groundings (missing: 0), and
/// `prefer_before` the `prefer` facts they decided. A numbered atom is *frozen*: earlier
/// groundings gave it its number and rules, so it is never made false here (it is possible or a
/// fact), it gets a number only when it occurs, and it is neither output nor reported as a fact
/// again (unless it became one). Only the atoms that are not frozen are visited for outputs,
/// facts and complementary pairs, so the work follows what this grounding added.
pub fn finish_after(
    g: &mut Grounder<'_>,
    prog: &Compiled,
    before: &[u8],
    prefer_before: &[AtomId],
) -> Finished {
    let frozen = |a: usize| before.get(a).is_some_and(|&f| f & NUMBERED != 0);
    add_classical_constraints(g, prog, &frozen);
    let n = g.atoms.len();
    let mut status = initial_status(g);
    let mut external = vec![false; n + 1];
    for &(a, _) in &g.externals {
        external[a as usize] = true;
    }
    // What propagation may not make false: externals and frozen atoms.
    let keep: Vec<bool> = if before.is_empty() {
        external.clone()
    } else {
        (0..=n).map(|a| external[a] || frozen(a)).collect()
    };
    // With provenance: why each dead rule died.
    let prov = g.provenance;
    let mut why: Vec<Option<DeadReason>> = Vec::new();
    let (dead, killed_contradictory) =
        propagate(g, &keep, &mut status, true, prov.then_some(&mut why));
    // What gringo would still find possible: it keeps rules with contradictory bodies, so atoms
    // only they derive stay in its minimize statements (clingo then reports an optimum of 0
    // where a dropped statement would make the answer plain SATISFIABLE).
    let gringo_status: Option<Vec<Status>> = (killed_contradictory && !g.minimize_order.is_empty())
        .then(|| {
            let mut st = initial_status(g);
            propagate(g, &keep, &mut st, false, None);
            st
        });
    let truth = |l: Lit, status: &[Status]| -> Option<bool> {
        let s = status[l.unsigned_abs() as usize - 1];
        match (l > 0, s) {
            (_, Status::Unknown) => None,
            (true, Status::Fact) | (false, Status::False) => Some(true),
            _ => Some(false),
        }
    };
    // Simplify the surviving rules.
    // Stored flat (`Rules`): the program outlives grounding and is held beside the solver.
    // They are written numbered for aspif as they come (see `Numbering`).
    // The output is at most the ground rules (a few constraints on complementary atoms
    // aside): room for them at once instead of growing step by step.
    let mut rules = Rules::new();
    rules.reserve_like(&g.rules);
    let mut numbering = Numbering::new(n, n.saturating_sub(before.len().saturating_sub(1)));
    // With provenance: the origins of each output rule, and the removed rules that headed a
    // false atom.
    let mut origins = Provenance::new();
    // Origins of second rules for facts, added to the fact's rule at the end.
    let mut late: Vec<(u32, Origin)> = Vec::new();
    let mut dead_rules: Vec<DeadRule> = std::mem::take(&mut g.dead);
    let mut g_origins = std::mem::take(&mut g.origins);
    let mut g_more = std::mem::take(&mut g.more_origins);
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
    // The output rule `a.` of each fact atom `a` (u32::MAX: none yet).
    let mut fact_rule = vec![u32::MAX; n + 1];
    // The rules are moved out (the grounder's copy is not used after this); each surviving
    // rule is simplified in the scratch vectors and copied to `rules`.
    let old = std::mem::take(&mut g.rules);
    let mut head: Vec<AtomId> = Vec::new();
    let mut lits: Vec<Lit> = Vec::new();
    let mut ordered: Vec<Lit> = Vec::new();
    let mut wlits: Vec<(Lit, Weight)> = Vec::new();
    // Records a removed rule that headed a false atom, or that a fact among its heads
    // satisfied (provenance: every rule instance keeps its origin).
    let mut bury = |ri: usize,
                    head: &[AtomId],
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
    let removed_lit = |l: Lit| RemovedLit {
        positive: l > 0,
        atom: l.unsigned_abs(),
    };
    for (ri, r) in old.iter().enumerate() {
        if dead[ri] {
            if let Some(&Some(reason)) = why.get(ri) {
                bury(ri, r.head, reason, &status, &mut take_origins);
            }
            continue;
        }
        lits.clear();
        wlits.clear();
        removed.clear();
        let body = match r.body {
            BodyRef::Normal(ls) => {
                let mut failed = None;
                for &l in ls {
                    match truth(l, &status) {
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
                    let reason = DeadReason::Literal {
                        positive: l > 0,
                        atom: l.unsigned_abs(),
                    };
                    bury(ri, r.head, reason, &status, &mut take_origins);
                    continue;
                }
                gringo_body_order(&lits, &mut ordered);
                BodyRef::Normal(&ordered)
            }
            BodyRef::Weight { lower, lits: ls } => {
                let mut lower = lower;
                for &(l, w) in ls {
                    match truth(l, &status) {
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
                    bury(
                        ri,
                        r.head,
                        DeadReason::Unreachable,
                        &status,
                        &mut take_origins,
                    );
                    continue;
                } else {
                    BodyRef::Weight {
                        lower,
                        lits: &wlits,
                    }
                }
            }
        };
        head.clear();
        head.extend_from_slice(r.head);
        if r.head_kind == HeadKind::Disjunction {
            if let Some(f) = fact_among(&head, &status) {
                if !(head.len() == 1 && body.is_empty_normal()) {
                    bury(
                        ri,
                        r.head,
                        DeadReason::HeadFact(f),
                        &status,
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
                if let Some(f) = fact_among(r.head, &status) {
                    bury(
                        ri,
                        r.head,
                        DeadReason::HeadFact(f),
                        &status,
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
            if fact_rule[h] != u32::MAX {
                // A second rule for a fact: its origins are more origins of the fact's rule.
                if prov {
                    let os = with_removed(take_origins(ri), &removed);
                    late.extend(os.into_iter().map(|o| (fact_rule[h], o)));
                }
                continue;
            }
            fact_rule[h] = rules.len() as u32;
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
    // Minimize statements: one per priority, highest first.
    let mut minimize: Vec<Minimize> = Vec::new();
    let keys = std::mem::take(&mut g.minimize_order);
    let mut elements: Vec<(i32, i32, Lit)> = Vec::new();
    // Priorities whose every element Lucent simplified away but gringo would keep (a condition
    // holding a literal and its negation, or an atom only a contradictory rule derives): they
    // stay as empty statements, so the answer is an optimum of 0 as clingo's.
    let mut empty_prios: Vec<i32> = Vec::new();
    for key in keys {
        let conds = g.minimize.get(&key).cloned().unwrap_or_default();
        let gstatus = gringo_status.as_deref().unwrap_or(&status);
        let gringo_keeps = conds
            .iter()
            .any(|c| c.iter().all(|&l| truth(l, gstatus) != Some(false)));
        let mut cond_origins = g.minimize_origins.remove(&key).unwrap_or_default();
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
                match truth(l, &status) {
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
        let lit = if certain {
            None
        } else if alts.len() == 1 && alts[0].len() == 1 {
            Some(alts[0][0])
        } else {
            let a = new_aux(g, &mut status);
            for (i, alt) in alts.into_iter().enumerate() {
                numbering.push(
                    &mut rules,
                    HeadKind::Disjunction,
                    &[a],
                    BodyRef::Normal(&alt),
                    &g.atoms,
                );
                if prov {
                    origins.push_rule(std::mem::take(&mut alt_origins[i]));
                }
            }
            Some(a as Lit)
        };
        let lit = match lit {
            Some(l) => l,
            None => {
                // A certain element: its weight is always counted; clasp needs a literal, so use
                // a fact atom.
                let a = new_aux(g, &mut status);
                status[a as usize - 1] = Status::Fact;
                numbering.push(
                    &mut rules,
                    HeadKind::Disjunction,
                    &[a],
                    BodyRef::Normal(&[]),
                    &g.atoms,
                );
                if prov {
                    origins.push_rule(std::mem::take(&mut certain_origins));
                }
                a as Lit
            }
        };
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
    // Which atoms get a number: every atom that occurs (those of the rules have theirs), and
    // shown atoms.
    let n = g.atoms.len();
    let mut used = vec![false; n + 1];
    let use_lit = |l: Lit, used: &mut Vec<bool>| used[l.unsigned_abs() as usize] = true;
    for m in &minimize {
        m.lits.iter().for_each(|&(l, _)| use_lit(l, &mut used));
    }
    for &(a, _) in &g.externals {
        used[a as usize] = true;
    }
    // Shown atoms: the predicates shown, decided once per predicate.
    let shown: Vec<bool> = prog
        .preds
        .iter()
        .map(|p| {
            // Auxiliary predicates of the rewriting (`#proj...`) are never shown.
            !g.syms.names.resolve(p.name).starts_with('#')
                && (!prog.show.restricted || prog.show.signatures.contains(p))
        })
        .collect();
    let shown_pred =
        |_: &Grounder<'_>, pred: u32| -> bool { pred != u32::MAX && shown[pred as usize] };
    for a in 1..=n {
        if frozen(a) {
            continue;
        }
        let info = g.atoms[a - 1];
        if info.sym.is_some()
            && status[a - 1] != Status::False
            && info.in_domain
            && shown_pred(g, info.pred)
        {
            used[a] = true;
        }
    }
    // Frozen atoms in conditions of shows, heuristics and edges, and projected ones, are
    // possible (a later part may show an atom of an earlier one).
    if !before.is_empty() {
        let mut mark = |l: Lit| {
            let a = l.unsigned_abs() as usize;
            if frozen(a) {
                used[a] = true;
            }
        };
        for (_, cond) in &g.shows {
            cond.iter().for_each(|&l| mark(l));
        }
        for h in &g.heuristics {
            mark(h.atom as Lit);
            h.condition.iter().for_each(|&l| mark(l));
        }
        for e in &g.edges {
            e.condition.iter().for_each(|&l| mark(l));
        }
        for &a in &g.projections {
            mark(a as Lit);
        }
    }
    // Numbering as gringo's output does it: atoms in order of first occurrence in the rules
    // (each rule's heads before its body; given as the rules were written), then those only in
    // minimize statements, externals and shown atoms, in creation order. The solver's initial
    // variable order follows it.
    for (a, _) in used.iter().enumerate().filter(|&(_, &u)| u) {
        numbering.assign(a, &g.atoms);
    }
    let Numbering {
        mut number,
        next,
        atom_syms,
        atom_gatoms,
        ..
    } = numbering;
    number.resize(n + 1, 0);
    let number = number;
    let map_lit = |l: Lit| -> Lit {
        let a = number[l.unsigned_abs() as usize] as Lit;
        if l > 0 {
            a
        } else {
            -a
        }
    };
    let mut out = GroundProgram::new();
    out.num_atoms = next;
    rules.shrink_to_fit();
    out.rules = rules;
    if prov {
        let mut p = origins;
        p.add_origins(late);
        p.set_atoms(
            g.atoms
                .iter()
                .enumerate()
                .map(|(i, info)| AtomRecord {
                    sym: info.sym.map(|s| s.0),
                    status: match status[i] {
                        Status::Fact => AtomStatus::Fact,
                        Status::False => AtomStatus::False,
                        Status::Unknown => AtomStatus::Possible,
                    },
                    aspif: number[i + 1],
                })
                .collect(),
        );
        // Instances dropped during instantiation are kept only when they headed a false atom
        // (or were satisfied by a fact among their heads) and the literal that stopped them is
        // still decided that way (one that failed in an early round of a recursive component
        // may have been derived later).
        dead_rules.retain(|d| {
            let decided = match d.why {
                DeadReason::Literal { positive, atom } => {
                    status[atom as usize - 1]
                        == if positive {
                            Status::False
                        } else {
                            Status::Fact
                        }
                }
                DeadReason::HeadFact(f) => status[f as usize - 1] == Status::Fact,
                DeadReason::Contradictory | DeadReason::Unreachable => true,
            };
            decided
                && (matches!(d.why, DeadReason::HeadFact(_))
                    || d.head
                        .iter()
                        .any(|&h| status[h as usize - 1] == Status::False))
        });
        p.dead = dead_rules;
        out.provenance = p;
    }
    out.minimize = minimize
        .into_iter()
        .map(|m| Minimize {
            priority: m.priority,
            lits: m.lits.into_iter().map(|(l, w)| (map_lit(l), w)).collect(),
        })
        .collect();
    // Outputs: shown atoms, facts with an empty condition.
    let mut fact_syms = Vec::new();
    let mut fact_atoms = Vec::new();
    for a in 1..=n {
        let info = g.atoms[a - 1];
        let Some(sym) = info.sym else { continue };
        if frozen(a) {
            // Output earlier; a fact only when it became one now.
            if status[a - 1] == Status::Fact && before[a] & KNOWN_FACT == 0 {
                fact_syms.push(sym);
                fact_atoms.push(a as AtomId);
            }
            continue;
        }
        if status[a - 1] == Status::Fact {
            fact_syms.push(sym);
            fact_atoms.push(a as AtomId);
        }
        if info.in_domain && status[a - 1] != Status::False && shown_pred(g, info.pred) {
            let condition = if status[a - 1] == Status::Fact {
                Vec::new()
            } else {
                vec![number[a] as Lit]
            };
            out.outputs.push(Output {
                symbol: g.syms.show(sym),
                condition,
            });
        }
    }
    let shows = std::mem::take(&mut g.shows);
    let mut seen: hashbrown::HashSet<(SymId, Vec<Lit>)> = hashbrown::HashSet::new();
    for (sym, cond) in shows {
        let mut c = Vec::new();
        let mut ok = true;
        for l in cond {
            match truth(l, &status) {
                Some(true) => {}
                Some(false) => ok = false,
                None => {
                    // An atom left out of the numbering occurs in no rule, so it is false:
                    // `not a` holds and drops out of the condition, `a` fails it.
                    if number[l.unsigned_abs() as usize] == 0 {
                        ok &= l < 0;
                    } else {
                        c.push(map_lit(l))
                    }
                }
            }
        }
        if ok && seen.insert((sym, c.clone())) {
            out.outputs.push(Output {
                symbol: g.syms.show(sym),
                condition: c,
            });
        }
    }
    let cond_map = |cond: &[Lit], status: &[Status]| -> Option<Vec<Lit>> {
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
                        c.push(map_lit(l))
                    }
                }
            }
        }
        Some(c)
    };
    out.externals = g
        .externals
        .iter()
        .map(|&(a, v)| (number[a as usize], v))
        .collect();
    out.projections = g
        .projections
        .iter()
        .filter(|&&a| number[a as usize] != 0)
        .map(|&a| number[a as usize])
        .collect();
    for h in &g.heuristics {
        if number[h.atom as usize] == 0 {
            continue;
        }
        if let Some(condition) = cond_map(&h.condition, &status) {
            let mut h2 = h.clone();
            h2.atom = number[h.atom as usize];
            h2.condition = condition;
            out.heuristics.push(h2);
        }
    }
    for e in &g.edges {
        if let Some(condition) = cond_map(&e.condition, &status) {
            let mut e2 = e.clone();
            e2.condition = condition;
            out.edges.push(e2);
        }
    }
    for (a, label) in &g.cr_rules {
        if number[*a as usize] != 0 && status[*a as usize - 1] == Status::Unknown {
            out.cr_rules.push(CrRule {
                appl: number[*a as usize],
                label: label.clone(),
            });
        }
    }
    // prefer(l1, l2) facts between labels of CR rules (those of earlier groundings first).
    let mut prefer_atoms = Vec::new();
    let prefer_name = g.syms.names.get("prefer");
    let fresh = (1..=n).filter(|&a| !frozen(a) && status[a - 1] == Status::Fact);
    for a in prefer_before.iter().map(|&a| a as usize).chain(fresh) {
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
            prefer_atoms.push(a as AtomId);
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
    Finished {
        program: out,
        atom_syms,
        fact_syms,
        fact_atoms,
        atom_gatoms,
        prefer_atoms,
    }
}

/// The first atom of `head` known to be a fact.
fn fact_among(head: &[AtomId], status: &[Status]) -> Option<AtomId> {
    head.iter()
        .copied()
        .find(|&h| status[h as usize - 1] == Status::Fact)
}

/// Each grounder atom's status before propagation: facts known, every other atom unknown.
fn initial_status(g: &Grounder<'_>) -> Vec<Status> {
    g.atoms
        .iter()
        .map(|a| {
            if a.fact {
                Status::Fact
            } else {
                Status::Unknown
            }
        })
        .collect()
}

fn new_aux(g: &mut Grounder<'_>, status: &mut Vec<Status>) -> AtomId {
    let a = g.aux();
    status.push(Status::Unknown);
    a
}
