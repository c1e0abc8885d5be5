//! Final simplification and output: decides which atoms are certainly false (no surviving rule
//! can derive them) by propagation, removes rules that need false atoms and literals that are
//! known, numbers the surviving atoms for aspif as gringo does (first occurrence in the output
//! rules, heads before bodies; normal bodies ordered as gringo prints them), and builds outputs,
//! minimize statements and the other directives. The numbering is the solver's initial variable
//! order, so it follows gringo's to make search on our ground program behave as on gringo's.
//!
//! Rules implemented (each by a worklist step):
//! - an atom that is not external and heads no live rule is false;
//! - a rule with a positive body literal over a false atom, or `not a` with `a` a fact, is dead;
//! - a disjunctive rule with a fact among its heads (other than the fact's own rule) is dead,
//!   and so is a rule whose body contains a literal and its negation;
//! - in kept rules, facts and `not a` with `a` false are removed from bodies.
//!
//! Invariant: the result's atoms are `1..=num_atoms`, every atom occurring anywhere is numbered.
//!
//! Provenance (when on): every output rule keeps the origins of every grounder rule that
//! became it (a second rule for a fact adds its origins to the fact's rule), each extended
//! with the body literals this pass decided; a removed rule with a head atom that ends up
//! false is kept as a `DeadRule` with its reason; the atom table records every grounder
//! atom's symbol, status and aspif number.

use super::instantiate::{AtomId, AtomInfo, Grounder};
use super::program::{
    AtomRecord, AtomStatus, Body, BodyRef, CrRule, DeadReason, DeadRule, GroundProgram, HeadKind,
    Lit, Minimize, Origin, Output, Prefer, Provenance, RemovedLit, Rule, RuleOrigin, Rules, Weight,
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

/// The two passes that build [`Occurrences`]: count, then fill.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Pass {
    Count,
    Fill,
}

/// Body occurrences of atoms `0..=n` in one flat array (compressed rows): the entries of atom
/// `a` are `items[start[a]..start[a + 1]]`, in rule order.
struct Occurrences {
    start: Vec<usize>,
    items: Vec<(u32, i64)>,
}

impl Occurrences {
    fn new(n: usize) -> Occurrences {
        Occurrences {
            start: vec![0; n + 2],
            items: Vec::new(),
        }
    }

    /// Counts (first pass) or places (second pass) one occurrence of `atom`.
    fn add(&mut self, pass: Pass, atom: u32, item: (u32, i64)) {
        let a = atom as usize;
        match pass {
            Pass::Count => self.start[a + 1] += 1,
            Pass::Fill => {
                // During filling, `start[a]` is the next free slot of atom `a`.
                self.items[self.start[a]] = item;
                self.start[a] += 1;
            }
        }
    }

    /// After counting: turns counts into start offsets; after filling: restores them.
    fn end(&mut self, pass: Pass) {
        match pass {
            Pass::Count => {
                for i in 1..self.start.len() {
                    self.start[i] += self.start[i - 1];
                }
                // start[a] is now atom a's first slot, the next free one while filling.
                self.items = vec![(0, 0); *self.start.last().unwrap_or(&0)];
            }
            Pass::Fill => {
                // Each start[a] now holds the end of atom a, which is the start of a + 1.
                self.start.rotate_right(1);
                self.start[0] = 0;
            }
        }
    }

    /// The occurrences of atom `a`.
    fn of(&self, a: usize) -> &[(u32, i64)] {
        &self.items[self.start[a]..self.start[a + 1]]
    }
}

/// The aspif numbering, made as the output rules are written (gringo's: atoms in order of
/// first occurrence, each rule's heads before its body), and the scratch vectors that write
/// each rule renumbered, so the rules are not passed over again to number and renumber them.
struct Numbering {
    /// The aspif number of each grounder atom (0: none yet).
    number: Vec<u32>,
    /// The last number given.
    next: u32,
    /// The symbol of each numbered atom, by number.
    atom_syms: Vec<Option<SymId>>,
    /// The grounder atom of each numbered atom, by number.
    atom_gatoms: Vec<AtomId>,
    /// Scratch: the head, body and weight body of a rule being written.
    head: Vec<AtomId>,
    lits: Vec<Lit>,
    wlits: Vec<(Lit, Weight)>,
}

impl Numbering {
    fn new(n: usize) -> Numbering {
        Numbering {
            number: vec![0; n + 1],
            next: 0,
            atom_syms: Vec::new(),
            atom_gatoms: Vec::new(),
            head: Vec::new(),
            lits: Vec::new(),
            wlits: Vec::new(),
        }
    }

    /// The number of grounder atom `a`, given now if it has none.
    fn assign(&mut self, a: usize, atoms: &[AtomInfo]) -> u32 {
        if a >= self.number.len() {
            self.number.resize(a + 1, 0);
        }
        if self.number[a] == 0 {
            self.next += 1;
            self.number[a] = self.next;
            self.atom_syms.push(atoms[a - 1].sym);
            self.atom_gatoms.push(a as AtomId);
        }
        self.number[a]
    }

    fn assign_lit(&mut self, l: Lit, atoms: &[AtomInfo]) -> Lit {
        let m = self.assign(l.unsigned_abs() as usize, atoms) as Lit;
        if l < 0 {
            -m
        } else {
            m
        }
    }

    /// Numbers the atoms of a rule over grounder atoms and appends it, renumbered, to `rules`.
    fn push(
        &mut self,
        rules: &mut Rules,
        kind: HeadKind,
        head: &[AtomId],
        body: BodyRef<'_>,
        atoms: &[AtomInfo],
    ) {
        let mut h = std::mem::take(&mut self.head);
        h.clear();
        for &a in head {
            h.push(self.assign(a as usize, atoms));
        }
        match body {
            BodyRef::Normal(ls) => {
                let mut b = std::mem::take(&mut self.lits);
                b.clear();
                for &l in ls {
                    b.push(self.assign_lit(l, atoms));
                }
                rules.push_parts(kind, &h, BodyRef::Normal(&b));
                self.lits = b;
            }
            BodyRef::Weight { lower, lits } => {
                let mut b = std::mem::take(&mut self.wlits);
                b.clear();
                for &(l, w) in lits {
                    b.push((self.assign_lit(l, atoms), w));
                }
                rules.push_parts(kind, &h, BodyRef::Weight { lower, lits: &b });
                self.wlits = b;
            }
        }
        self.head = h;
    }
}

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
    let mut status: Vec<Status> = g
        .atoms
        .iter()
        .map(|a| {
            if a.fact {
                Status::Fact
            } else {
                Status::Unknown
            }
        })
        .collect();
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
            let mut st: Vec<Status> = g
                .atoms
                .iter()
                .map(|a| {
                    if a.fact {
                        Status::Fact
                    } else {
                        Status::Unknown
                    }
                })
                .collect();
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
    let mut rules = Rules::new();
    let mut numbering = Numbering::new(n);
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
            if let Some(&f) = head
                .iter()
                .find(|&&h| status[h as usize - 1] == Status::Fact)
            {
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
                if let Some(&f) = r
                    .head
                    .iter()
                    .find(|&&h| status[h as usize - 1] == Status::Fact)
                {
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

/// Orders a normal body as gringo prints it, into `out`: the positive literals in reverse
/// order of the rule's body, then the negative ones in order. Only the solver's initial
/// variable order depends on it (atoms are numbered by first occurrence).
fn gringo_body_order(lits: &[Lit], out: &mut Vec<Lit>) {
    out.clear();
    out.extend(lits.iter().rev().copied().filter(|&l| l > 0));
    out.extend(lits.iter().copied().filter(|&l| l < 0));
}

/// Whether a normal body contains a literal and its negation (it can never hold). Only short
/// bodies are checked (quadratic scan, no allocation); missing a long one is only less simple.
fn contradictory(body: BodyRef<'_>) -> bool {
    match body {
        BodyRef::Normal(lits) => contradictory_lits(lits),
        BodyRef::Weight { .. } => false,
    }
}

/// [`contradictory`] for a conjunction of literals.
fn contradictory_lits(lits: &[Lit]) -> bool {
    lits.len() <= 16
        && lits
            .iter()
            .enumerate()
            .any(|(i, &l)| lits[i + 1..].contains(&-l))
}

/// The false atoms by propagation from `status` (facts known, everything else unknown): marks
/// them in `status` and returns which rules are dead, and whether a rule was killed because its
/// body holds a literal and its negation (only with `kill_contradictory`; gringo keeps such
/// rules, so their heads stay possible for gringo).
///
/// With `why`, records there why each dead rule died (provenance).
fn propagate(
    g: &Grounder<'_>,
    external: &[bool],
    status: &mut [Status],
    kill_contradictory: bool,
    why: Option<&mut Vec<Option<DeadReason>>>,
) -> (Vec<bool>, bool) {
    let mut no_why = Vec::new();
    let why = match why {
        Some(w) => {
            *w = vec![None; g.rules.len()];
            w
        }
        None => &mut no_why,
    };
    let n = g.atoms.len();
    let mut killed_contradictory = false;
    let mut head_count = vec![0u32; n + 1];
    // Occurrences in bodies: (rule, weight); weight 0 marks a normal body.
    let mut pos_occ = Occurrences::new(n);
    let mut neg_occ = Occurrences::new(n);
    // For weight bodies: the weight still reachable minus the bound; below 0 the rule is dead.
    let mut slack: Vec<i64> = vec![0; g.rules.len()];
    // A disjunctive rule with a fact among its heads is satisfied in every model and, by
    // minimality, supports none of its other heads: it is dead from the start (as in gringo),
    // so atoms only it could derive become false. The fact's own rule `a.` is kept. So is a
    // rule whose body holds `a` and `not a` (a weak constraint `:~ r, not r.` costs nothing).
    // Found in the counting pass, killed once the head counts are complete.
    let mut dead_at_start: Vec<(u32, DeadReason)> = Vec::new();
    for pass in [Pass::Count, Pass::Fill] {
        for (ri, r) in g.rules.iter().enumerate() {
            if pass == Pass::Count {
                for &h in r.head {
                    head_count[h as usize] += 1;
                }
                if let BodyRef::Weight { lower, lits } = r.body {
                    slack[ri] = lits.iter().map(|&(_, w)| w).sum::<i64>() - lower;
                }
                let fact_head = r
                    .head
                    .iter()
                    .copied()
                    .find(|&h| status[h as usize - 1] == Status::Fact);
                let satisfied_head = r.head_kind == HeadKind::Disjunction
                    && fact_head.is_some()
                    && !(r.head.len() == 1 && r.body.is_empty_normal());
                let contra = kill_contradictory && contradictory(r.body);
                killed_contradictory |= contra;
                if satisfied_head || contra {
                    let reason = match fact_head {
                        Some(h) if satisfied_head => DeadReason::HeadFact(h),
                        _ => DeadReason::Contradictory,
                    };
                    dead_at_start.push((ri as u32, reason));
                }
            }
            match r.body {
                BodyRef::Normal(lits) => {
                    for &l in lits {
                        let occ = if l > 0 { &mut pos_occ } else { &mut neg_occ };
                        occ.add(pass, l.unsigned_abs(), (ri as u32, 0));
                    }
                }
                BodyRef::Weight { lits, .. } => {
                    for &(l, w) in lits {
                        let occ = if l > 0 { &mut pos_occ } else { &mut neg_occ };
                        occ.add(pass, l.unsigned_abs(), (ri as u32, w.max(1)));
                    }
                }
            }
        }
        pos_occ.end(pass);
        neg_occ.end(pass);
    }
    let mut dead = vec![false; g.rules.len()];
    let mut work: Vec<AtomId> = Vec::new();
    for a in 1..=n {
        if head_count[a] == 0 && !external[a] && status[a - 1] == Status::Unknown {
            status[a - 1] = Status::False;
            work.push(a as AtomId);
        }
    }
    let kill = |ri: usize,
                reason: DeadReason,
                why: &mut Vec<Option<DeadReason>>,
                dead: &mut Vec<bool>,
                head_count: &mut Vec<u32>,
                status: &mut [Status],
                work: &mut Vec<AtomId>,
                rules: &Rules| {
        if dead[ri] {
            return;
        }
        dead[ri] = true;
        if let Some(w) = why.get_mut(ri) {
            *w = Some(reason);
        }
        for &h in rules.get(ri).head {
            head_count[h as usize] -= 1;
            if head_count[h as usize] == 0
                && !external[h as usize]
                && status[h as usize - 1] == Status::Unknown
            {
                status[h as usize - 1] = Status::False;
                work.push(h);
            }
        }
    };
    for (ri, reason) in dead_at_start {
        kill(
            ri as usize,
            reason,
            why,
            &mut dead,
            &mut head_count,
            status,
            &mut work,
            &g.rules,
        );
    }
    // Rules with `not a`, a a fact, are dead from the start.
    for a in 1..=n {
        if status[a - 1] == Status::Fact {
            for &(ri, w) in neg_occ.of(a) {
                // A weight body loses the literal's weight; a normal body dies.
                let reason = if w > 0 {
                    slack[ri as usize] -= w;
                    if slack[ri as usize] >= 0 {
                        continue;
                    }
                    DeadReason::Unreachable
                } else {
                    DeadReason::Literal {
                        positive: false,
                        atom: a as AtomId,
                    }
                };
                kill(
                    ri as usize,
                    reason,
                    why,
                    &mut dead,
                    &mut head_count,
                    status,
                    &mut work,
                    &g.rules,
                );
            }
        }
    }
    while let Some(a) = work.pop() {
        for &(ri, w) in pos_occ.of(a as usize) {
            let reason = if w > 0 {
                slack[ri as usize] -= w;
                if slack[ri as usize] >= 0 {
                    continue;
                }
                DeadReason::Unreachable
            } else {
                DeadReason::Literal {
                    positive: true,
                    atom: a,
                }
            };
            kill(
                ri as usize,
                reason,
                why,
                &mut dead,
                &mut head_count,
                status,
                &mut work,
                &g.rules,
            );
        }
    }
    drop((pos_occ, neg_occ, slack, head_count));
    (dead, killed_contradictory)
}

fn new_aux(g: &mut Grounder<'_>, status: &mut Vec<Status>) -> AtomId {
    let a = g.aux();
    status.push(Status::Unknown);
    a
}

/// `:- a, -a.` for every atom `-a` whose complement can be derived (multi-shot: for the pairs
/// with an atom that is not `frozen`, the others had theirs in an earlier grounding).
fn add_classical_constraints(
    g: &mut Grounder<'_>,
    prog: &Compiled,
    frozen: &dyn Fn(usize) -> bool,
) {
    let n = g.atoms.len();
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
    for x in 1..=n {
        if frozen(x) {
            continue;
        }
        let info = g.atoms[x - 1];
        let Some(sym) = info.sym else { continue };
        if !info.in_domain {
            continue;
        }
        let super::symbol::SymData::Fun { neg, .. } = g.syms.get(sym) else {
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
        // From the positive side only the pairs whose negative atom is frozen (the others
        // are found from their negative side).
        if !neg && !frozen(y as usize) {
            continue;
        }
        let (a, b) = if neg {
            (x, y)
        } else {
            (y as usize, x as AtomId)
        };
        if !g.atoms[b as usize - 1].in_domain || !g.atoms[a - 1].in_domain {
            continue;
        }
        let mut body = Vec::new();
        let mut facts = Vec::new();
        for x in [b, a as AtomId] {
            if !g.atoms[x as usize - 1].fact {
                body.push(x as Lit);
            } else {
                facts.push(RemovedLit {
                    positive: true,
                    atom: x,
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
            g.origins.push(Origin {
                rule: RuleOrigin::Complement,
                removed,
            });
        }
    }
}
