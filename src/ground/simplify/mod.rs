//! Final simplification and output: removes the rules that need false atoms and the literals
//! that are known, numbers the surviving atoms for aspif as gringo does, and builds outputs,
//! minimize statements and the other directives. One technique per submodule:
//! - `complement`: the constraints `:- a, -a.` of classical negation, added first;
//! - `propagate`: which atoms are certainly false and which rules are dead (worklist);
//! - `rules`: the surviving rules simplified by the atoms' status and written: in kept rules,
//!   facts and `not a` with `a` false are removed from bodies; satisfied and false heads are
//!   dropped;
//! - `minimize`: minimize statements, one per priority, with auxiliary atoms for elements of
//!   several alternatives;
//! - `numbering`: the aspif numbering, made as the output rules are written, then the atoms
//!   only minimize statements, externals and outputs need;
//! - `provenance`: the origins of the output rules, the atom table and the dead rules;
//! - `outputs`: shown atoms, facts and `#show` terms;
//! - `directives`: externals, projections, heuristics and edges;
//! - `cr`: CR rules and the `prefer` pairs between them;
//! - `theory`: theory atoms, their elements' conditions, free ones as externals;
//! - `scope`: the atoms a grounding visits, and the arrays a session keeps between groundings.
//!
//! This module runs them in that order ([`finish_after`]).
//!
//! Invariant: the result's atoms are `1..=num_atoms`, every atom occurring anywhere is numbered.
//!
//! Provenance (when on): every output rule keeps the origins of every grounder rule that
//! became it (a second rule for a fact adds its origins to the fact's rule), each extended
//! with the body literals this pass decided; a removed rule with a head atom that ends up
//! false is kept as a `DeadRule` with its reason; the atom table records every grounder
//! atom's symbol, status and aspif number.

mod complement;
mod cr;
mod directives;
mod minimize;
mod numbering;
mod outputs;
mod propagate;
mod provenance;
mod rules;
mod scope;
mod theory;

use complement::add_classical_constraints;
use numbering::{number_remaining, Numbering};
use propagate::propagate;
use rules::simplify_rules;
use scope::Scope;
pub use scope::Scratch;

use super::instantiate::{GroundAtom, Grounder};
use super::program::{
    DeadReason, DeadRule, GroundProgram, Lit, Minimize, Origin, Provenance, Rules,
};
use super::rewrite::Compiled;
use super::symbol::SymId;

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

/// What [`finish_after`] produces besides the program.
pub struct Finished {
    /// The aspif program.
    pub program: GroundProgram,
    /// Symbol of each aspif atom (`atom_syms[a - 1]`), `None` for auxiliary atoms. (Names are
    /// rendered only when asked for: `Grounding::atom_name`.)
    pub atom_syms: Vec<Option<SymId>>,
    /// Symbol of every fact atom (also those simplified away from bodies).
    pub fact_syms: Vec<SymId>,
    /// The grounder atom of each fact of `fact_syms`.
    pub fact_atoms: Vec<GroundAtom>,
    /// The grounder atom of each aspif atom (`atom_gatoms[a - 1]`).
    pub atom_gatoms: Vec<GroundAtom>,
    /// The `prefer(l1, l2)` facts among the atoms this call decided (multi-shot: later calls
    /// pair them with their own CR rules).
    pub prefer_atoms: Vec<GroundAtom>,
}

/// Multi-shot ([`finish_after`]): the atom has an aspif number from an earlier grounding.
pub const NUMBERED: u8 = 1;
/// Multi-shot ([`finish_after`]): an earlier grounding reported the atom as a fact.
pub const KNOWN_FACT: u8 = 2;

/// Adds `:- a, -a.` for complementary atoms, then simplifies and numbers; for a later grounding of a multi-shot session, `before[a]` holds the flags
/// ([`NUMBERED`], [`KNOWN_FACT`]) of grounder atom `a` from earlier groundings (missing: 0), and
/// `prefer_before` the `prefer` facts they decided. A numbered atom is *frozen*: earlier
/// groundings gave it its number and rules, so it is never made false here (it is possible or a
/// fact), it gets a number only when it occurs, and it is neither output nor reported as a fact
/// again (unless it became one). Only the atoms of the grounding's [`Scope`] are visited (its
/// own and the older ones it names), with the arrays `scratch` keeps between groundings, so the
/// work follows what this grounding added.
pub fn finish_after(
    g: &mut Grounder<'_>,
    prog: &Compiled,
    before: &[u8],
    prefer_before: &[GroundAtom],
    scratch: &mut Scratch,
) -> Finished {
    let frozen = |a: usize| Scope::frozen(before, a);
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
    // Older atoms of predicates shown now and not before (or the reverse) may be output now:
    // every atom is visited then, as with provenance (its atom table lists them all).
    let all = g.provenance || scratch.shown.iter().zip(&shown).any(|(a, b)| a != b);
    let scope = Scope::build(g, prefer_before, all, scratch.take_loc());
    add_classical_constraints(g, prog, &scope, &frozen);
    // The constraints may name older atoms outside the scope: built again.
    let scope = Scope::build(g, prefer_before, all, scope.release());
    let n = g.atoms.len();
    let Decided {
        mut status,
        external,
        dead,
        why,
        gringo_status,
    } = decide(g, &scope, scratch, &frozen);
    let fresh = n.saturating_sub(before.len().saturating_sub(1));
    let number = std::mem::take(&mut scratch.number);
    let mut w = simplify_rules(
        g,
        &scope,
        &mut status,
        &external,
        &dead,
        &why,
        fresh,
        number,
    );
    let minimize = minimize::minimize(g, &mut status, gringo_status.as_deref(), &mut w);
    let mut scope = scope;
    scope.extend(g.atoms.len());
    number_remaining(
        &mut w.numbering,
        g,
        &scope,
        &status,
        &minimize,
        &shown,
        !before.is_empty(),
        &frozen,
    );
    let n = g.atoms.len();
    let Written {
        mut rules,
        numbering,
        origins,
        late,
        dead_rules,
    } = w;
    let Numbering {
        mut number,
        next,
        atom_syms,
        atom_gatoms,
        ..
    } = numbering;
    number.resize(n + 1, 0);
    let mut out = GroundProgram::new();
    out.num_atoms = next;
    rules.shrink_to_fit();
    out.rules = rules;
    if g.provenance {
        out.provenance = provenance::provenance(g, &status, &number, origins, late, dead_rules);
    }
    out.minimize = minimize
        .into_iter()
        .map(|m| Minimize {
            priority: m.priority,
            lits: m
                .lits
                .into_iter()
                .map(|(l, w)| (map_lit(&number, l), w))
                .collect(),
        })
        .collect();
    let (fact_syms, fact_atoms) = outputs::shown_atoms(
        g,
        &scope,
        &status,
        &number,
        before,
        &shown,
        &frozen,
        &prog.domain_rank,
        &mut out.outputs,
    );
    outputs::show_terms(g, &status, &number, &mut out.outputs);
    // In clingo's order (`Output::order`); stable: equal keys keep the order made.
    if out.outputs.windows(2).any(|w| w[0].order > w[1].order) {
        out.outputs.sort_by_key(|o| o.order);
    }
    directives::directives(g, &status, &number, &mut out);
    theory::theory_atoms(g, &status, &number, &mut out);
    let prefer_atoms = cr::cr_rules(
        g,
        &scope,
        &status,
        &number,
        prefer_before,
        &frozen,
        &mut out,
    );
    // The session's arrays, cleared for the next grounding.
    for &a in &atom_gatoms {
        number[a.get() as usize] = 0;
    }
    scratch.number = number;
    let mut external = external;
    for &(a, _) in &g.directives.externals {
        external[a.get() as usize] = false;
    }
    for a in g.directives.theory.atoms.iter().filter_map(|t| t.atom) {
        external[a.get() as usize] = false;
    }
    scratch.external = external;
    scratch.status = status;
    scratch.shown = shown;
    scratch.put_loc(scope.release());
    Finished {
        program: out,
        atom_syms,
        fact_syms,
        fact_atoms,
        atom_gatoms,
        prefer_atoms,
    }
}

/// What propagation decided before the rules are written.
struct Decided {
    /// The status of each grounder atom (index `a - 1`).
    status: Vec<Status>,
    /// External atoms (index `a`): their heads are kept.
    external: Vec<bool>,
    /// The dead rules, by index.
    dead: Vec<bool>,
    /// With provenance: why each dead rule died.
    why: Vec<Option<DeadReason>>,
    /// What gringo would still find possible, when it differs (see [`decide`]).
    gringo_status: Option<Vec<Status>>,
}

/// Propagates false atoms and dead rules over the rules of `g`, visiting the atoms of `scope`;
/// externals and `frozen` atoms (multi-shot: those of earlier groundings) are never made false.
/// The status and external arrays come from `scratch` (the caller gives them back).
fn decide(
    g: &Grounder<'_>,
    scope: &Scope,
    scratch: &mut Scratch,
    frozen: &dyn Fn(usize) -> bool,
) -> Decided {
    let n = g.atoms.len();
    let mut status = std::mem::take(&mut scratch.status);
    status.resize(n, Status::Unknown);
    for &a in &scope.atoms {
        status[a as usize - 1] = initial_status(g, a as usize);
    }
    let mut external = std::mem::take(&mut scratch.external);
    external.resize(n + 1, false);
    for &(a, _) in &g.directives.externals {
        external[a.get() as usize] = true;
    }
    // Theory atoms are never false by the program either (free without rules).
    for a in g.directives.theory.atoms.iter().filter_map(|t| t.atom) {
        external[a.get() as usize] = true;
    }
    // What propagation may not make false: externals and frozen atoms.
    let keep = |a: usize| external[a] || frozen(a);
    // With provenance: why each dead rule died.
    let prov = g.provenance;
    let mut why: Vec<Option<DeadReason>> = Vec::new();
    let (dead, killed_contradictory) =
        propagate(g, scope, &keep, &mut status, true, prov.then_some(&mut why));
    // What gringo would still find possible: it keeps rules with contradictory bodies, so atoms
    // only they derive stay in its minimize statements (clingo then reports an optimum of 0
    // where a dropped statement would make the answer plain SATISFIABLE).
    let gringo_status: Option<Vec<Status>> =
        (killed_contradictory && !g.directives.minimize_order.is_empty()).then(|| {
            let mut st: Vec<Status> = (1..=n).map(|a| initial_status(g, a)).collect();
            propagate(g, scope, &keep, &mut st, false, None);
            st
        });
    Decided {
        status,
        external,
        dead,
        why,
        gringo_status,
    }
}

/// The output rules written so far, numbered as they come, with their provenance: what the
/// rules pass starts and the minimize pass adds to.
struct Written {
    /// The output rules, over aspif numbers.
    rules: Rules,
    /// The numbering made as they were written.
    numbering: Numbering,
    /// With provenance: the origins of each output rule.
    origins: Provenance,
    /// Origins of second rules for facts, added to the fact's rule at the end.
    late: Vec<(u32, Origin)>,
    /// With provenance: the removed rules that headed a false atom (or that a fact among their
    /// heads satisfied).
    dead_rules: Vec<DeadRule>,
}

/// The truth of literal `l` under `status`: `None` when its atom is undecided.
#[inline]
fn truth(l: Lit, status: &[Status]) -> Option<bool> {
    let s = status[l.unsigned_abs() as usize - 1];
    match (l > 0, s) {
        (_, Status::Unknown) => None,
        (true, Status::Fact) | (false, Status::False) => Some(true),
        _ => Some(false),
    }
}

/// Literal `l` over grounder atoms, renumbered by `number` for aspif.
#[inline]
fn map_lit(number: &[u32], l: Lit) -> Lit {
    let a = number[l.unsigned_abs() as usize] as Lit;
    if l > 0 {
        a
    } else {
        -a
    }
}

/// Whether predicate `pred` is shown (`shown`, by predicate; auxiliary atoms never are).
#[inline]
fn shown_pred(shown: &[bool], pred: u32) -> bool {
    pred != u32::MAX && shown[pred as usize]
}

/// The first atom of `head` (grounder atom numbers, as the rule store holds them) known to be
/// a fact.
fn fact_among(head: &[u32], status: &[Status]) -> Option<u32> {
    head.iter()
        .copied()
        .find(|&h| status[h as usize - 1] == Status::Fact)
}

/// Grounder atom `a`'s status before propagation: a fact known, any other atom unknown.
#[inline]
fn initial_status(g: &Grounder<'_>, a: usize) -> Status {
    if g.atoms[a - 1].fact {
        Status::Fact
    } else {
        Status::Unknown
    }
}

fn new_aux(g: &mut Grounder<'_>, status: &mut Vec<Status>) -> GroundAtom {
    let a = g.aux();
    status.push(Status::Unknown);
    a
}
