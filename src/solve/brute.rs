//! A brute-force reference solver, for tests only: it enumerates every candidate set of atoms,
//! keeps the stable models (by [`check`](super::check)), then applies the CR semantics and
//! optimization. Exponential by design; the solver's property tests compare against it.
//!
//! Semantics, in this order:
//! 1. Stable models of the program (its CR rules are ordinary choice-guarded rules, see
//!    `ground::program`).
//! 2. CR rules (when `cr_rules` is non-empty), over the *applied set* of each model (its true
//!    application atoms): `CrMode::Cardinality` keeps the models whose applied set has minimal
//!    size; `CrMode::Subset` keeps the models whose applied set is subset-minimal among all
//!    applied sets, does not contain two rules ordered by the transitive closure of `prefers`,
//!    and is not dominated by another such set (Y dominates X when some rule of Y is preferred
//!    to some rule of X).
//! 3. Optimization (when `optimize`): the models whose costs (one per priority, highest first)
//!    are lexicographically minimal.
//! 4. Each answer set is reported once with its application atoms projected away: models equal
//!    up to application atoms are merged, keeping the lexicographically smallest applied set.
//!
//! Invariant: only atoms that occur in a rule head or as a non-released external are
//! enumerated (no other atom can be true in a stable model); more than
//! [`MAX_CANDIDATE_ATOMS`] of them is API misuse and panics.

use crate::ground::program::{Atom, ExternalValue, GroundProgram, Lit, Weight};

use super::check::{check_assignment, external_values};
use super::config::CrMode;
use super::solver::transitive_closure;

/// The largest number of candidate atoms the brute-force solver accepts.
pub const MAX_CANDIDATE_ATOMS: usize = 22;

/// What the brute-force solver computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct BruteConfig {
    /// Semantics of CR rules.
    pub cr_mode: CrMode,
    /// Keep only optimal models (otherwise all answer sets, with their costs).
    pub optimize: bool,
}

/// One answer set found by brute force.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct BruteModel {
    /// True atoms, sorted, application atoms of CR rules excluded.
    pub atoms: Vec<Atom>,
    /// True application atoms of CR rules, sorted (the smallest such set among merged models).
    pub applied: Vec<Atom>,
    /// Costs, one per distinct minimize priority, highest priority first.
    pub costs: Vec<Weight>,
}

/// All stable models of `program`, each sorted, in increasing order.
pub fn stable_models(program: &GroundProgram) -> Vec<Vec<Atom>> {
    let n = program.num_atoms as usize;
    let mut can_be_true = vec![false; n + 1];
    for rule in &program.rules {
        for &h in rule.head {
            assert!(
                h as usize <= n,
                "rule head atom {h} is above num_atoms = {n}"
            );
            can_be_true[h as usize] = true;
        }
    }
    for (a, v) in external_values(program) {
        assert!(
            a as usize <= n,
            "external atom {a} is above num_atoms = {n}"
        );
        if v != ExternalValue::Release {
            can_be_true[a as usize] = true;
        }
    }
    let candidates: Vec<Atom> = (1..=n as Atom)
        .filter(|&a| can_be_true[a as usize])
        .collect();
    assert!(
        candidates.len() <= MAX_CANDIDATE_ATOMS,
        "brute force handles at most {MAX_CANDIDATE_ATOMS} atoms that can be true, this program has {}",
        candidates.len()
    );
    let mut models = Vec::new();
    let mut truth = vec![false; n + 1];
    for mask in 0u64..(1u64 << candidates.len()) {
        for (i, &a) in candidates.iter().enumerate() {
            truth[a as usize] = mask >> i & 1 == 1;
        }
        if check_assignment(program, &truth).is_ok() {
            models.push(
                candidates
                    .iter()
                    .copied()
                    .filter(|&a| truth[a as usize])
                    .collect(),
            );
        }
    }
    models.sort();
    models
}

/// The costs of a model (sorted true atoms): for each distinct minimize priority, highest
/// first, the sum of the weights of the true literals.
pub fn costs(program: &GroundProgram, atoms: &[Atom]) -> Vec<Weight> {
    let mut priorities: Vec<Weight> = program.minimize.iter().map(|m| m.priority).collect();
    priorities.sort_unstable_by(|a, b| b.cmp(a));
    priorities.dedup();
    let holds = |l: Lit| atoms.binary_search(&l.unsigned_abs()).is_ok() == (l > 0);
    priorities
        .iter()
        .map(|&p| {
            let statements = program.minimize.iter().filter(|m| m.priority == p);
            statements
                .flat_map(|m| &m.lits)
                .filter(|(l, _)| holds(*l))
                .map(|&(_, w)| w)
                .sum()
        })
        .collect()
}

/// The answer sets of `program` under `config` (see the module documentation), sorted.
pub fn answer_sets(program: &GroundProgram, config: BruteConfig) -> Vec<BruteModel> {
    let mut appl: Vec<Atom> = program.cr_rules.iter().map(|c| c.appl).collect();
    appl.sort_unstable();
    let applied_of = |atoms: &[Atom]| {
        atoms
            .iter()
            .copied()
            .filter(|a| appl.binary_search(a).is_ok())
            .collect()
    };
    let mut models: Vec<(Vec<Atom>, Vec<Atom>)> = stable_models(program)
        .into_iter()
        .map(|m| (applied_of(&m), m))
        .collect();

    if !appl.is_empty() {
        let keep = match config.cr_mode {
            CrMode::Cardinality => {
                let best = models.iter().map(|(x, _)| x.len()).min().unwrap_or(0);
                models
                    .iter()
                    .map(|(x, _)| x.len() == best)
                    .collect::<Vec<_>>()
            }
            CrMode::Subset => {
                let preferred = preference_closure(program);
                let sets: Vec<&Vec<Atom>> = models.iter().map(|(x, _)| x).collect();
                let is_candidate = |x: &Vec<Atom>| {
                    !sets.iter().any(|y| y.len() < x.len() && is_subset(y, x))
                        && !x.iter().any(|&a| x.iter().any(|&b| preferred(a, b)))
                };
                let candidates: Vec<&Vec<Atom>> =
                    sets.iter().copied().filter(|x| is_candidate(x)).collect();
                let dominated = |x: &Vec<Atom>| {
                    candidates
                        .iter()
                        .any(|y| y.iter().any(|&b| x.iter().any(|&w| preferred(b, w))))
                };
                sets.iter()
                    .map(|x| is_candidate(x) && !dominated(x))
                    .collect()
            }
        };
        let mut keep = keep.into_iter();
        models.retain(|_| keep.next().unwrap_or(false));
    }

    let mut result: Vec<BruteModel> = models
        .into_iter()
        .map(|(applied, atoms)| {
            let costs = costs(program, &atoms);
            let atoms = atoms
                .into_iter()
                .filter(|a| appl.binary_search(a).is_err())
                .collect();
            BruteModel {
                atoms,
                applied,
                costs,
            }
        })
        .collect();
    if config.optimize {
        if let Some(best) = result.iter().map(|m| m.costs.clone()).min() {
            result.retain(|m| m.costs == best);
        }
    }
    // Merge models equal up to application atoms, keeping the smallest applied set.
    result.sort_by(|a, b| {
        a.atoms
            .cmp(&b.atoms)
            .then_with(|| a.applied.cmp(&b.applied))
    });
    result.dedup_by(|later, first| later.atoms == first.atoms);
    result.sort();
    result
}

/// `preferred(a, b)`: the CR rule with application atom `a` is preferred to `b`, by the
/// transitive closure of `program.prefers`.
fn preference_closure(program: &GroundProgram) -> impl Fn(Atom, Atom) -> bool {
    let mut atoms: Vec<Atom> = program
        .prefers
        .iter()
        .flat_map(|p| [p.better, p.worse])
        .collect();
    atoms.sort_unstable();
    atoms.dedup();
    let k = atoms.len();
    let index = |a: Atom| atoms.binary_search(&a).ok();
    let reach = transitive_closure(
        k,
        program
            .prefers
            .iter()
            .filter_map(|p| Some((index(p.better)?, index(p.worse)?))),
    );
    move |a, b| match (atoms.binary_search(&a), atoms.binary_search(&b)) {
        (Ok(i), Ok(j)) => reach[i * k + j],
        _ => false,
    }
}

/// Whether sorted `small` is a subset of sorted `big`.
fn is_subset(small: &[Atom], big: &[Atom]) -> bool {
    small.iter().all(|a| big.binary_search(a).is_ok())
}
