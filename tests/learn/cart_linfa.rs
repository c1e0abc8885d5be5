//! `learn::cart` against linfa-trees on the same data: at every node of our tree, linfa fitted on
//! that node's samples (depth 1) makes the same decision: it splits where we split, on a feature
//! whose weighted entropy equals our best within f32 precision (a tie), and stays a leaf where we
//! stay a leaf.
//!
//! Why per node, not one whole linfa tree: linfa-trees 0.8.1 (src/decision_trees/algorithm.rs,
//! the split loop of `TreeNode::fit`) evaluates a split of a column only at the position where
//! the value changes in the *whole* sorted column; for a binary feature, below the root that row
//! is often outside the node, so linfa never considers the split there. Fitting on each node's
//! samples alone avoids that and still compares every split decision.

use linfa::prelude::*;
use linfa_trees::{DecisionTree, SplitQuality};
use lucent::base::rng::SplitMix64;
use lucent::learn::cart::{best_splits, split_entropy, CartParams, NodeKind, Table, Tree};
use ndarray::{Array1, Array2};

/// A random table: `n` samples, 10 features with varied densities, features 8 and 9 copies of 0
/// and 1 (exact ties), and a noisy label `(x0 and not x3) or x5`.
fn random_table(seed: u64, n: usize) -> Table {
    let mut rng = SplitMix64::new(seed);
    let density = [0.5, 0.3, 0.7, 0.4, 0.2, 0.25, 0.6, 0.9];
    let mut rows = Vec::new();
    let mut labels = Vec::new();
    for _ in 0..n {
        let mut row: Vec<bool> = density.iter().map(|&p| rng.chance(p)).collect();
        row.push(row[0]);
        row.push(row[1]);
        let truth = (row[0] && !row[3]) || row[5];
        labels.push(if rng.chance(0.08) { !truth } else { truth });
        rows.push(row);
    }
    Table::new(rows, labels)
}

/// linfa's decision at the root for these samples: `Some(feature)` if it splits.
fn linfa_root(table: &Table, samples: &[u32], min_gain: f64) -> Option<usize> {
    let records = Array2::from_shape_fn((samples.len(), table.num_features), |(i, f)| {
        table.rows[samples[i] as usize][f] as u8 as f64
    });
    let targets: Array1<usize> = samples
        .iter()
        .map(|&s| table.labels[s as usize] as usize)
        .collect();
    let dataset = Dataset::new(records, targets);
    let model = DecisionTree::params()
        .split_quality(SplitQuality::Entropy)
        .min_weight_split(15.0)
        .min_weight_leaf(5.0)
        .min_impurity_decrease(min_gain)
        .max_depth(Some(1))
        .fit(&dataset)
        .expect("linfa fits");
    // After pruning a depth-1 split whose children predict the same class, linfa's root is
    // marked a leaf but keeps its split feature and impurity decrease; an unsplit root has 0.
    let (feature, _, decrease) = model.root_node().split();
    (decrease > 0.0).then_some(feature)
}

#[test]
fn same_splits_as_linfa_up_to_ties() {
    let params = CartParams {
        // linfa computes entropies in f32; a split that gains nothing can show a gain of about
        // 1e-7 there, so both sides use linfa's default threshold.
        min_gain: 1e-5,
        ..CartParams::default()
    };
    let mut nodes_checked = 0;
    let mut splits_checked = 0;
    for seed in 0..40 {
        let n = 60 + (seed as usize % 5) * 30;
        let table = random_table(seed, n);
        let all: Vec<u32> = (0..n as u32).collect();
        let tree = Tree::fit(&table, &all, &params, seed);
        let per_node = tree.samples_per_node(&table, &all);
        for (id, node) in tree.nodes.iter().enumerate() {
            let samples = &per_node[id];
            assert_eq!(samples.len() as u32, node.samples);
            let theirs = linfa_root(&table, samples, params.min_gain);
            match node.kind {
                NodeKind::Split { feature, .. } => {
                    let theirs = theirs
                        .unwrap_or_else(|| panic!("seed {seed} node {id}: linfa does not split"));
                    let (best, tied) = best_splits(&table, samples, &params).unwrap();
                    assert!(tied.contains(&feature));
                    let their_score =
                        split_entropy(&table, samples, theirs, 5).expect("admissible");
                    assert!(
                        (their_score - best).abs() < 1e-5,
                        "seed {seed} node {id}: linfa splits on {theirs} ({their_score}), best {tied:?} ({best})"
                    );
                    splits_checked += 1;
                }
                NodeKind::Leaf => {
                    assert_eq!(theirs, None, "seed {seed} node {id}: linfa splits a leaf")
                }
            }
            nodes_checked += 1;
        }
    }
    assert!(
        splits_checked > 100,
        "{splits_checked} splits in {nodes_checked} nodes"
    );
}
