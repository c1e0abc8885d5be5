//! The tree ensemble, candidate axioms and the vote (docs/domain.md 5.6-5.8).
//!
//! Per tree: a fresh seeded split with 5% of the samples held out; branch selection over the
//! held-out samples' paths (purity > 0.98, support > 0.02, majority class 1); candidates are
//! the non-empty subsets of a path's tests, each test a literal whose polarity follows the
//! held-out sample (1: the feature, 0: its complement); validation on the held-out samples
//! (`occ / (occ + neg + 1e-4) >= 0.98`); over-specification removal; generalization (shared
//! tests of two candidates); validation and removal once more. Across trees: candidates are
//! rendered as axioms, compared up to variable renaming, and kept by the vote (causal laws in at
//! least 40% of the trees, executability conditions at the maximum count, ties kept).
//!
//! Invariants: the result is a function of (table, features, seed); trees run in parallel with
//! rayon, each with its own generator forked from the seed by tree index, and the vote sorts its
//! tallies, so the thread count never changes the outcome.

use std::collections::{BTreeMap, BTreeSet};

use rayon::prelude::*;

use super::cart::{CartParams, Table, Test, Tree};
use super::term::{Axiom, AxiomKind, Literal};
use crate::base::rng::SplitMix64;

/// Ensemble parameters (defaults: docs/domain.md 5.6-5.8).
#[derive(Clone, Debug, PartialEq)]
pub struct EnsembleParams {
    /// Number of trees.
    pub trees: usize,
    /// Share of the samples held out per tree.
    pub held_out: f64,
    /// A selected leaf's purity must exceed this.
    pub min_purity: f64,
    /// A selected leaf's share of the root's samples must exceed this.
    pub min_support: f64,
    /// A candidate survives validation with `occ / (occ + neg + 1e-4)` at least this.
    pub min_precision: f64,
    /// Causal laws need this share of the trees.
    pub causal_vote: f64,
    /// Paths longer than this contribute only their first tests (2^k - 1 subsets).
    pub max_path_tests: usize,
    /// The trees' parameters.
    pub cart: CartParams,
}

impl Default for EnsembleParams {
    fn default() -> Self {
        EnsembleParams {
            trees: 100,
            held_out: 0.05,
            min_purity: 0.98,
            min_support: 0.02,
            min_precision: 0.98,
            causal_vote: 0.4,
            max_path_tests: 12,
            cart: CartParams::default(),
        }
    }
}

/// A candidate: a set of tests (feature, value), sorted.
pub type Candidate = Vec<Test>;

/// What one tree produced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TreeResult {
    /// The surviving candidates with their held-out `occ` counts.
    pub candidates: Vec<(Candidate, u32)>,
    /// The number of nodes of the tree.
    pub nodes: usize,
}

/// What the axiom under construction is, besides its body.
#[derive(Clone, Debug, PartialEq)]
pub struct Target {
    /// Causal law (with head) or executability condition.
    pub kind: AxiomKind,
    /// The lifted action.
    pub action: Literal,
}

/// The vote's outcome.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Learned {
    /// The kept axioms in canonical form, each with the number of trees that produced it.
    pub kept: Vec<(Axiom, usize)>,
    /// Every axiom produced by some tree, canonical, with its count (sorted by count, then
    /// axiom).
    pub tally: Vec<(Axiom, usize)>,
    /// Trees that produced no candidate.
    pub empty_trees: usize,
}

/// `occ` and `neg` of a candidate on the samples `on`.
fn counts(table: &Table, on: &[u32], cand: &[Test]) -> (u32, u32) {
    let (mut occ, mut neg) = (0, 0);
    for &s in on {
        let row = &table.rows[s as usize];
        if cand.iter().all(|t| row[t.feature] == t.value) {
            if table.labels[s as usize] {
                occ += 1;
            } else {
                neg += 1;
            }
        }
    }
    (occ, neg)
}

/// Validation (5.7 step 3) then over-specification removal (step 4).
fn validate_and_prune(
    table: &Table,
    held: &[u32],
    cands: BTreeSet<Candidate>,
    params: &EnsembleParams,
) -> Vec<(Candidate, u32)> {
    let valid: Vec<(Candidate, u32)> = cands
        .into_iter()
        .filter_map(|c| {
            let (occ, neg) = counts(table, held, &c);
            let precision = occ as f64 / (occ as f64 + neg as f64 + 1e-4);
            (precision >= params.min_precision).then_some((c, occ))
        })
        .collect();
    // X goes if it strictly contains some valid Y (same label: all candidates are class 1;
    // equal tests on shared features: Y's tests are a subset of X's) with occ(X) <= occ(Y).
    valid
        .iter()
        .filter(|(x, occ_x)| {
            !valid.iter().any(|(y, occ_y)| {
                y.len() < x.len() && y.iter().all(|t| x.contains(t)) && occ_x <= occ_y
            })
        })
        .cloned()
        .collect()
}

/// One tree's candidates (5.7), trained on all samples but `held`.
pub fn tree_candidates(
    table: &Table,
    train: &[u32],
    held: &[u32],
    params: &EnsembleParams,
    seed: u64,
) -> TreeResult {
    let tree = Tree::fit(table, train, &params.cart, seed);
    let root = tree.root().samples.max(1) as f64;
    let mut cands: BTreeSet<Candidate> = BTreeSet::new();
    let mut paths: BTreeSet<Vec<Test>> = BTreeSet::new();
    for &s in held {
        let (tests, leaf) = tree.path(&table.rows[s as usize]);
        let leaf = &tree.nodes[leaf as usize];
        let selected = leaf.purity() > params.min_purity
            && leaf.samples as f64 / root > params.min_support
            && leaf.majority();
        if selected {
            paths.insert(tests);
        }
    }
    for path in paths {
        let k = path.len().min(params.max_path_tests);
        for mask in 1u32..(1u32 << k) {
            let mut cand: Candidate = (0..k)
                .filter(|i| mask & (1 << i) != 0)
                .map(|i| path[i])
                .collect();
            cand.sort();
            cands.insert(cand);
        }
    }
    let mut kept = validate_and_prune(table, held, cands, params);
    // Generalization (step 5): the shared tests of two candidates, then steps 3-4 once more.
    let mut all: BTreeSet<Candidate> = kept.iter().map(|(c, _)| c.clone()).collect();
    for (i, (a, _)) in kept.iter().enumerate() {
        for (b, _) in &kept[i + 1..] {
            let shared: Candidate = a.iter().filter(|t| b.contains(t)).copied().collect();
            if !shared.is_empty() {
                all.insert(shared);
            }
        }
    }
    if all.len() > kept.len() {
        kept = validate_and_prune(table, held, all, params);
    }
    TreeResult {
        candidates: kept,
        nodes: tree.nodes.len(),
    }
}

/// The held-out split of tree `t`: a fresh shuffle, the first `ceil(held_out * n)` held out
/// (at least 1 when there are 2 or more samples).
pub fn split(n: usize, held_out: f64, rng: &mut SplitMix64) -> (Vec<u32>, Vec<u32>) {
    let mut idx: Vec<u32> = (0..n as u32).collect();
    rng.shuffle(&mut idx);
    let h = if n < 2 {
        0
    } else {
        ((held_out * n as f64).round() as usize).clamp(1, n - 1)
    };
    let held = idx[..h].to_vec();
    let train = idx[h..].to_vec();
    (train, held)
}

/// A candidate's body literals: test value 1 gives the feature, 0 its complement.
pub fn body_of(cand: &[Test], features: &[Literal]) -> Vec<Literal> {
    cand.iter()
        .map(|t| {
            let f = &features[t.feature];
            if t.value {
                f.clone()
            } else {
                f.complement()
            }
        })
        .collect()
}

/// Runs the ensemble on a table whose columns are `features` and votes (5.8).
pub fn learn(
    table: &Table,
    features: &[Literal],
    target: &Target,
    params: &EnsembleParams,
    seed: u64,
) -> Learned {
    let base = SplitMix64::new(seed);
    let results: Vec<TreeResult> = (0..params.trees)
        .into_par_iter()
        .map(|t| {
            let mut rng = base.fork(t as u64);
            let (train, held) = split(table.labels.len(), params.held_out, &mut rng);
            tree_candidates(table, &train, &held, params, rng.next_u64())
        })
        .collect();
    let mut tally: BTreeMap<Axiom, usize> = BTreeMap::new();
    let mut empty_trees = 0;
    for r in &results {
        if r.candidates.is_empty() {
            empty_trees += 1;
        }
        let axioms: BTreeSet<Axiom> = r
            .candidates
            .iter()
            .map(|(c, _)| {
                Axiom::new(
                    target.kind.clone(),
                    target.action.clone(),
                    body_of(c, features),
                )
                .canonical()
            })
            .collect();
        for a in axioms {
            *tally.entry(a).or_insert(0) += 1;
        }
    }
    let mut tally: Vec<(Axiom, usize)> = tally.into_iter().collect();
    tally.sort_by(|(a, ca), (b, cb)| cb.cmp(ca).then(a.cmp(b)));
    let kept: Vec<(Axiom, usize)> = match &target.kind {
        AxiomKind::Causal { .. } => {
            if tally.is_empty() {
                // No tree yields a candidate: the unconditional law.
                let law =
                    Axiom::new(target.kind.clone(), target.action.clone(), Vec::new()).canonical();
                vec![(law, params.trees)]
            } else {
                let need = (params.causal_vote * params.trees as f64).ceil() as usize;
                tally.iter().filter(|(_, c)| *c >= need).cloned().collect()
            }
        }
        AxiomKind::Constraint { .. } => {
            // State constraints are voted as causal laws are, without an unconditional
            // fallback: a constraint with no condition would say its head of everything.
            let need = (params.causal_vote * params.trees as f64).ceil() as usize;
            tally.iter().filter(|(_, c)| *c >= need).cloned().collect()
        }
        AxiomKind::Executability => {
            let max = tally.first().map_or(0, |(_, c)| *c);
            tally
                .iter()
                .filter(|(_, c)| *c == max && max > 0)
                .cloned()
                .collect()
        }
    };
    Learned {
        kept,
        tally,
        empty_trees,
    }
}

#[cfg(test)]
mod tests {
    use super::super::term::{in_hand, o, r, rel};
    use super::*;

    fn test(feature: usize, value: bool) -> Test {
        Test { feature, value }
    }

    /// Hand-made held-out set: 4 samples over 3 features.
    ///
    /// ```text
    ///  sample f0 f1 f2 label
    ///    0     1  1  0   1
    ///    1     1  0  0   1
    ///    2     0  1  0   0
    ///    3     1  1  1   0
    /// ```
    /// {f0=1}: matches 0, 1, 3: occ 2, neg 1 -> 2/3.0001 < 0.98, deleted.
    /// {f0=1, f2=0}: matches 0, 1: occ 2, neg 0 -> kept.
    /// {f2=0}: matches 0, 1, 2: occ 2, neg 1 -> deleted.
    /// {f0=1, f1=1, f2=0}: matches 0: occ 1, kept by validation, but it strictly contains
    /// {f0=1, f2=0} with occ 1 <= 2: over-specified, deleted.
    #[test]
    fn validation_and_overspecification_by_hand() {
        let table =
            Table::from_bits(&[("110", true), ("100", true), ("010", false), ("111", false)]);
        let held = [0, 1, 2, 3];
        let cands: BTreeSet<Candidate> = [
            vec![test(0, true)],
            vec![test(0, true), test(2, false)],
            vec![test(2, false)],
            vec![test(0, true), test(1, true), test(2, false)],
        ]
        .into_iter()
        .collect();
        assert_eq!(counts(&table, &held, &[test(0, true)]), (2, 1));
        let kept = validate_and_prune(&table, &held, cands, &EnsembleParams::default());
        assert_eq!(kept, vec![(vec![test(0, true), test(2, false)], 2)]);
    }

    #[test]
    fn bodies_take_the_complement_for_value_zero() {
        let features = vec![rel("below", o(1), o(2)), in_hand(false, r(1), o(1))];
        assert_eq!(
            body_of(&[test(0, false), test(1, false)], &features),
            vec![
                rel("below", o(1), o(2)).complement(),
                in_hand(true, r(1), o(1))
            ]
        );
    }

    /// A table where label 1 is exactly feature 0 (E7-like): the ensemble keeps the single
    /// literal `below(O1, O2)`, whatever the thread count.
    #[test]
    fn ensemble_finds_the_exact_condition() {
        let mut rng = SplitMix64::new(3);
        let mut rows = Vec::new();
        let mut labels = Vec::new();
        for _ in 0..100 {
            let row: Vec<bool> = (0..4).map(|_| rng.chance(0.5)).collect();
            labels.push(row[0]);
            rows.push(row);
        }
        let table = Table::new(rows, labels);
        let features = vec![
            rel("below", o(1), o(2)),
            rel("on", o(1), o(3)),
            in_hand(false, r(1), o(4)),
            rel("left", o(1), o(5)),
        ];
        let target = Target {
            kind: AxiomKind::Executability,
            action: Literal::new("pickup", vec![r(1), o(1)]),
        };
        let learned = learn(&table, &features, &target, &EnsembleParams::default(), 11);
        assert_eq!(learned.kept.len(), 1);
        assert_eq!(
            learned.kept[0].0.short(),
            "impossible pickup(R1, O1) if below(O1, O2)"
        );
        let one_thread = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        let again = one_thread
            .install(|| learn(&table, &features, &target, &EnsembleParams::default(), 11));
        assert_eq!(again, learned);
    }

    /// All samples positive: no tree splits, no path has a test, so no candidate: the causal
    /// law is emitted unconditionally.
    #[test]
    fn all_positive_gives_the_unconditional_law() {
        let table = Table::from_bits(&vec![("10", true); 60]);
        let features = vec![in_hand(false, r(1), o(1)), rel("on", o(1), o(2))];
        let target = Target {
            kind: AxiomKind::Causal {
                head: in_hand(true, r(1), o(1)),
            },
            action: Literal::new("pickup", vec![r(1), o(1)]),
        };
        let learned = learn(&table, &features, &target, &EnsembleParams::default(), 5);
        assert_eq!(learned.empty_trees, 100);
        assert_eq!(learned.kept.len(), 1);
        assert_eq!(
            learned.kept[0].0.to_ald(),
            "pickup(R1, O1) causes in_hand(R1, O1)"
        );
    }
}
