//! Binary CART decision trees over binary features and binary labels (docs/domain.md 5.6).
//!
//! The trees of the axiom learner: the entropy criterion, `min_samples_split = 15`,
//! `min_samples_leaf = 5`, no depth limit, and ties between equally good splits broken by a
//! seeded generator (scikit-learn breaks them by a random feature order; we draw uniformly among
//! the tied features, which is the same distribution).
//!
//! Invariants: a tree is a function of (samples, labels, parameters, seed) alone; nodes are
//! stored flat with the root at index 0 and every child after its parent; every split leaves at
//! least `min_samples_leaf` samples on each side and lowers the weighted entropy by more than
//! `min_gain` (scikit-learn also accepts splits that gain nothing; such a split leaves both
//! children with the parent's class ratio and only lengthens the paths the learner turns into
//! candidate axioms, so we stop there).

use crate::base::rng::SplitMix64;

/// Tree-growing parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct CartParams {
    /// A node with fewer samples is a leaf.
    pub min_samples_split: usize,
    /// Each side of a split keeps at least this many samples.
    pub min_samples_leaf: usize,
    /// A split must lower the weighted entropy by more than this.
    pub min_gain: f64,
    /// Two weighted entropies closer than this are a tie.
    pub tie_tolerance: f64,
}

impl Default for CartParams {
    fn default() -> Self {
        CartParams {
            min_samples_split: 15,
            min_samples_leaf: 5,
            min_gain: 1e-9,
            tie_tolerance: 1e-12,
        }
    }
}

/// A training table: one row of binary features per sample and one binary label.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Table {
    /// `rows[s][f]` is feature `f` of sample `s`; every row has `num_features` entries.
    pub rows: Vec<Vec<bool>>,
    /// `labels[s]` is the label of sample `s` (true = class 1).
    pub labels: Vec<bool>,
    /// The number of feature columns.
    pub num_features: usize,
}

impl Table {
    /// A table from rows and labels; panics if the lengths disagree.
    pub fn new(rows: Vec<Vec<bool>>, labels: Vec<bool>) -> Table {
        assert_eq!(rows.len(), labels.len(), "one label per row");
        let num_features = rows.first().map_or(0, Vec::len);
        assert!(
            rows.iter().all(|r| r.len() == num_features),
            "rows of equal length"
        );
        Table {
            rows,
            labels,
            num_features,
        }
    }

    /// A table from strings of `0`/`1` characters (tests and examples).
    pub fn from_bits(rows: &[(&str, bool)]) -> Table {
        Table::new(
            rows.iter()
                .map(|(bits, _)| bits.bytes().map(|b| b == b'1').collect())
                .collect(),
            rows.iter().map(|&(_, label)| label).collect(),
        )
    }
}

/// Index of a node in [`Tree::nodes`].
pub type NodeId = u32;

/// What a node does.
#[derive(Clone, Debug, PartialEq)]
pub enum NodeKind {
    /// A leaf.
    Leaf,
    /// A test on one feature: samples with value 0 go to `if_false`, with 1 to `if_true`.
    Split {
        /// The tested feature.
        feature: usize,
        /// The child for feature value 0.
        if_false: NodeId,
        /// The child for feature value 1.
        if_true: NodeId,
    },
}

/// One node of a tree, with the training samples that reached it.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// Number of training samples at this node.
    pub samples: u32,
    /// How many of them have label 1.
    pub positives: u32,
    /// Leaf or split.
    pub kind: NodeKind,
}

impl Node {
    /// The majority class (ties go to class 0, as scikit-learn's argmax does).
    pub fn majority(&self) -> bool {
        2 * self.positives > self.samples
    }

    /// The majority class's share of the node's samples.
    pub fn purity(&self) -> f64 {
        let major = self.positives.max(self.samples - self.positives);
        major as f64 / self.samples.max(1) as f64
    }
}

/// One test on a decision path: the feature and the value the sample had.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Test {
    /// The tested feature.
    pub feature: usize,
    /// The value that led down this path.
    pub value: bool,
}

/// A fitted tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Tree {
    /// The nodes, root first, children after parents.
    pub nodes: Vec<Node>,
}

/// The entropy in bits of a two-class node with `positives` of `samples` in class 1.
///
/// `H = -p log2 p - (1-p) log2 (1-p)`, 0 for a pure or empty node.
pub fn entropy(positives: u32, samples: u32) -> f64 {
    if samples == 0 || positives == 0 || positives == samples {
        return 0.0;
    }
    let p = positives as f64 / samples as f64;
    -(p * p.log2()) - (1.0 - p) * (1.0 - p).log2()
}

/// The weighted entropy of the children when `samples` (indices into `table`) are split on
/// `feature`, or `None` if a side would hold fewer than `min_leaf` samples.
pub fn split_entropy(
    table: &Table,
    samples: &[u32],
    feature: usize,
    min_leaf: usize,
) -> Option<f64> {
    let (mut n1, mut p1, mut p0) = (0u32, 0u32, 0u32);
    for &s in samples {
        let s = s as usize;
        if table.rows[s][feature] {
            n1 += 1;
            p1 += table.labels[s] as u32;
        } else {
            p0 += table.labels[s] as u32;
        }
    }
    let n = samples.len() as u32;
    let n0 = n - n1;
    if (n0 as usize) < min_leaf || (n1 as usize) < min_leaf {
        return None;
    }
    Some((n0 as f64 * entropy(p0, n0) + n1 as f64 * entropy(p1, n1)) / n as f64)
}

/// The best splits of a sample set: the lowest weighted child entropy and every feature that
/// reaches it (within the tie tolerance), in increasing feature order. `None` if no feature
/// splits the set with enough samples per side.
pub fn best_splits(
    table: &Table,
    samples: &[u32],
    params: &CartParams,
) -> Option<(f64, Vec<usize>)> {
    let mut best: Option<(f64, Vec<usize>)> = None;
    for feature in 0..table.num_features {
        let Some(score) = split_entropy(table, samples, feature, params.min_samples_leaf) else {
            continue;
        };
        match &mut best {
            Some((best_score, tied)) if (score - *best_score).abs() <= params.tie_tolerance => {
                tied.push(feature)
            }
            Some((best_score, _)) if score > *best_score => {}
            _ => best = Some((score, vec![feature])),
        }
    }
    best
}

impl Tree {
    /// Grows a tree on the samples `samples` (indices into `table`, a bootstrap-free subset).
    pub fn fit(table: &Table, samples: &[u32], params: &CartParams, seed: u64) -> Tree {
        let mut rng = SplitMix64::new(seed);
        let mut tree = Tree { nodes: Vec::new() };
        // Each pending entry is (node id, its samples); nodes are pushed before being expanded.
        let mut pending: Vec<(NodeId, Vec<u32>)> = Vec::new();
        tree.push_node(table, samples);
        pending.push((0, samples.to_vec()));
        // Expand in creation order so that node ids (and the generator's draws) follow a
        // breadth-first order independent of the recursion shape.
        let mut cursor = 0;
        while cursor < pending.len() {
            let (id, node_samples) = std::mem::take(&mut pending[cursor]);
            cursor += 1;
            let node = &tree.nodes[id as usize];
            let parent_entropy = entropy(node.positives, node.samples);
            if node_samples.len() < params.min_samples_split || parent_entropy == 0.0 {
                continue;
            }
            let Some((score, tied)) = best_splits(table, &node_samples, params) else {
                continue;
            };
            if parent_entropy - score <= params.min_gain {
                continue;
            }
            let feature = if tied.len() == 1 {
                tied[0]
            } else {
                tied[rng.below(tied.len() as u64) as usize]
            };
            let (ones, zeros): (Vec<u32>, Vec<u32>) = node_samples
                .iter()
                .partition(|&&s| table.rows[s as usize][feature]);
            let if_false = tree.push_node(table, &zeros);
            let if_true = tree.push_node(table, &ones);
            tree.nodes[id as usize].kind = NodeKind::Split {
                feature,
                if_false,
                if_true,
            };
            pending.push((if_false, zeros));
            pending.push((if_true, ones));
        }
        tree
    }

    fn push_node(&mut self, table: &Table, samples: &[u32]) -> NodeId {
        let positives = samples
            .iter()
            .filter(|&&s| table.labels[s as usize])
            .count() as u32;
        self.nodes.push(Node {
            samples: samples.len() as u32,
            positives,
            kind: NodeKind::Leaf,
        });
        (self.nodes.len() - 1) as NodeId
    }

    /// The root.
    pub fn root(&self) -> &Node {
        &self.nodes[0]
    }

    /// The decision path of a feature row: the tests met from the root, and the leaf reached.
    pub fn path(&self, row: &[bool]) -> (Vec<Test>, NodeId) {
        let mut tests = Vec::new();
        let mut id: NodeId = 0;
        while let NodeKind::Split {
            feature,
            if_false,
            if_true,
        } = self.nodes[id as usize].kind
        {
            let value = row[feature];
            tests.push(Test { feature, value });
            id = if value { if_true } else { if_false };
        }
        (tests, id)
    }

    /// The predicted class of a feature row.
    pub fn predict(&self, row: &[bool]) -> bool {
        let (_, leaf) = self.path(row);
        self.nodes[leaf as usize].majority()
    }

    /// The training samples that reach each node, routed from `samples` (the set the tree was
    /// fitted on, for the fitted counts).
    pub fn samples_per_node(&self, table: &Table, samples: &[u32]) -> Vec<Vec<u32>> {
        let mut per_node = vec![Vec::new(); self.nodes.len()];
        for &s in samples {
            let mut id: NodeId = 0;
            loop {
                per_node[id as usize].push(s);
                match self.nodes[id as usize].kind {
                    NodeKind::Leaf => break,
                    NodeKind::Split {
                        feature,
                        if_false,
                        if_true,
                    } => {
                        id = if table.rows[s as usize][feature] {
                            if_true
                        } else {
                            if_false
                        }
                    }
                }
            }
        }
        per_node
    }

    /// The tested feature of every split node, in node order.
    pub fn split_features(&self) -> Vec<usize> {
        self.nodes
            .iter()
            .filter_map(|n| match n.kind {
                NodeKind::Split { feature, .. } => Some(feature),
                NodeKind::Leaf => None,
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(table: &Table) -> Vec<u32> {
        (0..table.labels.len() as u32).collect()
    }

    #[test]
    fn entropy_by_hand() {
        assert_eq!(entropy(0, 10), 0.0);
        assert_eq!(entropy(10, 10), 0.0);
        assert_eq!(entropy(0, 0), 0.0);
        // p = 1/2: -2 * 0.5 * log2 0.5 = 1.
        assert!((entropy(5, 10) - 1.0).abs() < 1e-12);
        // p = 1/4: -0.25 log2 0.25 - 0.75 log2 0.75 = 0.5 + 0.311278 = 0.811278.
        assert!((entropy(1, 4) - 0.811_278_124_459_132_8).abs() < 1e-12);
        // p = 3/20 and p = 17/20 are symmetric: 0.15*2.736966 + 0.85*0.234465 = 0.609840.
        assert!((entropy(3, 20) - 0.609_840_304_716_400_4).abs() < 1e-12);
        assert!((entropy(17, 20) - entropy(3, 20)).abs() < 1e-15);
    }

    /// 40 samples, 3 features. Feature 0 separates the classes except for four samples, feature
    /// 1 is noise, feature 2 is constant 1 (never splits: one side would be empty).
    ///
    /// ```text
    ///  f0 f1 f2 label  count
    ///   1  0  1   1     12
    ///   1  1  1   1      8
    ///   1  1  1   0      2      f0=1: 22 samples, 20 positive
    ///   0  1  1   0     10
    ///   0  0  1   0      6
    ///   0  0  1   1      2      f0=0: 18 samples, 2 positive
    /// ```
    /// Root: 22 of 40 positive, H(0.55) = 0.992774.
    /// Split on f0: 22/40 * H(10/11) + 18/40 * H(1/9) = 0.55*0.439497 + 0.45*0.503258 = 0.468189.
    /// Split on f1: f1=1 has 20 samples (8 positive), f1=0 has 20 (14 positive):
    /// 0.5*H(0.4) + 0.5*H(0.7) = 0.5*0.970951 + 0.5*0.881291 = 0.926121.
    /// So the root splits on f0. Child f0=1 (22 samples, H(10/11) = 0.439497): on f1, f1=0 has 12
    /// samples all positive and f1=1 has 10 with 8 positive: 10/22*H(0.8) = 0.328149, a gain, so
    /// it splits on f1. Child f0=0 (18 samples, H(1/9) = 0.503258): f1=1 has 10 samples all
    /// negative and f1=0 has 8 with 2 positive: 8/18*H(0.25) = 0.360568, so it splits on f1 too.
    /// The four grandchildren have fewer than 15 samples: leaves.
    fn table_a() -> Table {
        let mut rows = Vec::new();
        for (bits, label, count) in [
            ("101", true, 12),
            ("111", true, 8),
            ("111", false, 2),
            ("011", false, 10),
            ("001", false, 6),
            ("001", true, 2),
        ] {
            for _ in 0..count {
                rows.push((bits, label));
            }
        }
        Table::from_bits(&rows)
    }

    #[test]
    fn split_scores_by_hand() {
        let t = table_a();
        let s = all(&t);
        assert!((entropy(22, 40) - 0.992_774_453_987_808_4).abs() < 1e-12);
        let f0 = split_entropy(&t, &s, 0, 5).unwrap();
        assert!((f0 - 0.468_189).abs() < 1e-6, "{f0}");
        let f1 = split_entropy(&t, &s, 1, 5).unwrap();
        assert!((f1 - 0.926_121).abs() < 1e-6, "{f1}");
        assert_eq!(split_entropy(&t, &s, 2, 5), None);
        let (score, tied) = best_splits(&t, &s, &CartParams::default()).unwrap();
        assert_eq!(tied, vec![0]);
        assert!((score - f0).abs() < 1e-15);
        // With min_samples_leaf 19, f0 (22/18) is not admissible and f1 (20/20) is the only split.
        let params = CartParams {
            min_samples_leaf: 19,
            ..CartParams::default()
        };
        assert_eq!(best_splits(&t, &s, &params).unwrap().1, vec![1]);
    }

    #[test]
    fn tree_by_hand() {
        let t = table_a();
        let tree = Tree::fit(&t, &all(&t), &CartParams::default(), 7);
        // Root (f0), its children (both split on f1), then four leaves.
        assert_eq!(tree.nodes.len(), 7);
        assert_eq!(tree.split_features(), vec![0, 1, 1]);
        let root = tree.root();
        assert_eq!((root.samples, root.positives), (40, 22));
        let (tests, leaf) = tree.path(&[true, true, true]);
        assert_eq!(
            tests,
            vec![
                Test {
                    feature: 0,
                    value: true
                },
                Test {
                    feature: 1,
                    value: true
                }
            ]
        );
        let leaf = &tree.nodes[leaf as usize];
        assert_eq!((leaf.samples, leaf.positives), (10, 8));
        assert!(leaf.majority());
        assert!((leaf.purity() - 0.8).abs() < 1e-15);
        let (tests, leaf) = tree.path(&[false, false, true]);
        assert_eq!(tests.len(), 2);
        let leaf = &tree.nodes[leaf as usize];
        assert_eq!((leaf.samples, leaf.positives), (8, 2));
        assert!(!tree.predict(&[false, false, true]));
        assert!(tree.predict(&[true, false, true]));
    }

    #[test]
    fn min_samples_split_and_pure_nodes_stop() {
        // 14 samples: below min_samples_split, so the root is a leaf even though f0 separates.
        let rows: Vec<(&str, bool)> = (0..14)
            .map(|i| if i < 7 { ("1", true) } else { ("0", false) })
            .collect();
        let t = Table::from_bits(&rows);
        let tree = Tree::fit(&t, &all(&t), &CartParams::default(), 1);
        assert_eq!(tree.nodes.len(), 1);
        // 15 samples with the same split: now the root splits, and the pure children stay leaves.
        let rows: Vec<(&str, bool)> = (0..15)
            .map(|i| if i < 7 { ("1", true) } else { ("0", false) })
            .collect();
        let t = Table::from_bits(&rows);
        let tree = Tree::fit(&t, &all(&t), &CartParams::default(), 1);
        assert_eq!(tree.nodes.len(), 3);
        // A pure root never splits.
        let rows: Vec<(&str, bool)> = (0..30)
            .map(|i| (if i % 2 == 0 { "1" } else { "0" }, true))
            .collect();
        let t = Table::from_bits(&rows);
        assert_eq!(
            Tree::fit(&t, &all(&t), &CartParams::default(), 1)
                .nodes
                .len(),
            1
        );
    }

    /// Two identical columns tie exactly; the seed picks one, both get picked over many seeds,
    /// and the same seed always picks the same one.
    #[test]
    fn ties_are_broken_by_the_seed() {
        let rows: Vec<(&str, bool)> = (0..20)
            .map(|i| if i < 10 { ("11", true) } else { ("00", false) })
            .collect();
        let t = Table::from_bits(&rows);
        let s = all(&t);
        assert_eq!(
            best_splits(&t, &s, &CartParams::default()).unwrap().1,
            vec![0, 1]
        );
        let mut seen = [false; 2];
        for seed in 0..32 {
            let a = Tree::fit(&t, &s, &CartParams::default(), seed);
            let b = Tree::fit(&t, &s, &CartParams::default(), seed);
            assert_eq!(a, b);
            seen[a.split_features()[0]] = true;
        }
        assert_eq!(seen, [true, true]);
    }
}
