//! Learning the state constraints that scene understanding lacks, with the learner's machinery
//! (`learn::lift`, `learn::ensemble`, `learn::strength`): the labelled examples that reasoning
//! classifies wrongly, or cannot classify, start a learning episode for that label; the
//! examples of the label that the current knowledge does not already decide become samples,
//! described by the answer set's literals about the example's objects; the trees' branches
//! become candidate constraints that are lifted, validated, merged and voted as in the action
//! learner, and kept ones join the knowledge with a strength.
//!
//! Two labels, each with its constraint's head (class 1 is "the head holds"):
//! - stability, one sample per object standing on another: head `-stable(O1)`, class 1 when the
//!   object moved in the physics test; relevant literals: those of the answer set that mention
//!   the object only (one hop, as in the action learner), among the perceived relations with
//!   the objects of its region of interest, its size and surface, and its support-derived
//!   fluents (`small_base`, `irreg_below`, `tower_height`);
//! - occlusion, one sample per ordered pair (A, B) of objects in view: head
//!   `-partially_occluded(O1, O2)`, class 1 when B hides less than the occluder threshold of A;
//!   relevant literals: the relations between A and B and the two objects' sizes and surfaces.
//!
//! The targets, for scoring as H1 scores the action axioms (strict and relaxed, docs/domain.md
//! 5.10): ST1 `-stable(O1) if irreg_below(O1)`, D1 (as the constraint its default states)
//! `-stable(O1) if small_base(O1)` and OC2 `-partially_occluded(O1, O2) if
//! -relation(behind, O1, O2)`.
//!
//! Invariants: the learned axioms are a function of (examples, parameters, seed); samples are
//! taken in the examples' order after a seeded shuffle and cap, so a run does not depend on the
//! thread count.

use crate::base::rng::SplitMix64;
use crate::learn::cart::Table;
use crate::learn::ensemble::{self, EnsembleParams, Target};
use crate::learn::lift::{Algebra, Lifter, Signature};
use crate::learn::term::{Axiom, AxiomKind, Literal, RELATION};

/// The label a constraint decides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Label {
    /// `stable(A)`.
    Stability,
    /// `partially_occluded(A, B)`, and through OC1 `occluded(A)`.
    Occlusion,
}

impl Label {
    /// Both labels.
    pub const ALL: [Label; 2] = [Label::Stability, Label::Occlusion];

    /// The label's name.
    pub fn name(self) -> &'static str {
        match self {
            Label::Stability => "stability",
            Label::Occlusion => "occlusion",
        }
    }

    /// The head of the constraints learned for the label, lifted.
    pub fn head(self) -> Literal {
        match self {
            Label::Stability => Literal::new("stable", vec![o(1)]).with_sign(false),
            Label::Occlusion => {
                Literal::new("partially_occluded", vec![o(1), o(2)]).with_sign(false)
            }
        }
    }
}

fn o(i: u32) -> crate::learn::term::Term {
    crate::learn::term::o(i)
}

/// One labelled example: the ground subject (`stable(a)`, `partially_occluded(a, b)`), the
/// relevant literals, and whether the constraint's head holds.
#[derive(Clone, Debug, PartialEq)]
pub struct Example {
    /// The ground subject, positive.
    pub subject: Literal,
    /// The relevant literals of the answer set.
    pub relevant: Vec<Literal>,
    /// True when the head (`-stable(a)`, `-partially_occluded(a, b)`) holds physically.
    pub class: bool,
}

/// The literals of `state` whose entities are all among `objects` (with `table`) and mention
/// `subject_objects[0]` (stability) or only the subject's objects (occlusion).
pub fn relevant(label: Label, state: &[Literal], subject: &[&str], roi: &[&str]) -> Vec<Literal> {
    state
        .iter()
        .filter(|l| l.positive)
        .filter(|l| {
            !matches!(
                l.name.as_str(),
                "stable" | "partially_occluded" | "occluded"
            )
        })
        .filter(|l| {
            let ents: Vec<&str> = l
                .entity_positions()
                .filter_map(|i| match &l.args[i] {
                    crate::learn::term::Term::Const(c) => Some(c.as_str()),
                    crate::learn::term::Term::Var(_) => None,
                })
                .collect();
            match label {
                Label::Stability => {
                    ents.contains(&subject[0])
                        && ents.iter().all(|e| roi.contains(e) || *e == "table")
                }
                Label::Occlusion => {
                    ents.iter().any(|e| subject.contains(e))
                        && ents.iter().all(|e| subject.contains(e))
                }
            }
        })
        .cloned()
        .collect()
}

/// Parameters of a learning episode.
#[derive(Clone, Debug, PartialEq)]
pub struct ConstraintParams {
    /// The ensemble's parameters (docs/domain.md 5.6-5.8 defaults).
    pub ensemble: EnsembleParams,
    /// At most this many samples per episode (a seeded subset), to bound the trees' cost.
    pub max_samples: usize,
    /// Class balance (as docs/domain.md 5.4 balances the action learner's datasets): the majority
    /// class keeps at most this many samples per sample of the minority class. Without it a
    /// rare class (an object hidden by a given other object) makes almost every leaf pure,
    /// and any literal passes as a constraint.
    pub max_ratio: usize,
    /// A kept constraint must decide at least this many class-1 samples that the constraints
    /// with more votes do not. Measured over the 20 learning runs of `lucent experiment
    /// classify --sizes 1000 --test 10` (200-scene subsets): strict precision 89.6% at 5, 96.8%
    /// at 10, 98.4% at 20, recall 100% throughout; the removed constraints decide hundreds.
    pub min_new: usize,
}

impl Default for ConstraintParams {
    fn default() -> Self {
        ConstraintParams {
            // Each tree validates on half of its samples (the action learner holds out 5%,
            // docs/domain.md 5.6): with a rare class, a literal that merely correlates with the
            // majority (`-has_size(O1, large)`: a large object is seldom hidden) passes the
            // 0.98 precision test on a handful of held-out samples by luck, and on a few
            // hundred it does not. Measured over 10 runs of 200 scenes: strict precision
            // 63.8% at 5%, 88.2% at 25%, 100% at 50%, recall 100% throughout.
            ensemble: EnsembleParams {
                held_out: 0.5,
                ..EnsembleParams::default()
            },
            max_samples: 1500,
            max_ratio: 10,
            min_new: 10,
        }
    }
}

/// What one learning episode produced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Episode {
    /// The samples used.
    pub samples: usize,
    /// Of them, with class 1.
    pub positives: usize,
    /// The kept constraints with their votes.
    pub kept: Vec<(Axiom, usize)>,
}

/// Learns the constraints of `label` from `examples`.
pub fn learn(label: Label, examples: &[Example], params: &ConstraintParams, seed: u64) -> Episode {
    let mut rng = SplitMix64::new(seed);
    let mut order: Vec<usize> = (0..examples.len()).collect();
    rng.shuffle_modulo(&mut order);
    let ones = order.iter().filter(|&&i| examples[i].class).count();
    let zeros = order.len() - ones;
    let (cap_one, cap_zero) = (
        (zeros * params.max_ratio).max(1),
        (ones * params.max_ratio).max(1),
    );
    let (mut kept_one, mut kept_zero) = (0, 0);
    order.retain(|&i| {
        let (kept, cap) = if examples[i].class {
            (&mut kept_one, cap_one)
        } else {
            (&mut kept_zero, cap_zero)
        };
        *kept += 1;
        *kept <= cap
    });
    order.truncate(params.max_samples);
    order.sort_unstable();
    let mut lifter = Lifter::new(
        Signature {
            robots: vec![crate::sim::ROBOT.to_string()],
        },
        Algebra::ra(),
    );
    let lifted: Vec<_> = order
        .iter()
        .map(|&i| {
            let e = &examples[i];
            lifter.lift(&[], &e.subject, &e.relevant)
        })
        .collect();
    let width = lifter.features.len();
    let rows: Vec<Vec<bool>> = lifted
        .iter()
        .map(|l| {
            let mut row = vec![false; width];
            for &f in &l.features {
                row[f] = true;
            }
            row
        })
        .collect();
    let labels: Vec<bool> = order.iter().map(|&i| examples[i].class).collect();
    let positives = labels.iter().filter(|&&c| c).count();
    let mut episode = Episode {
        samples: labels.len(),
        positives,
        kept: Vec::new(),
    };
    if positives == 0 || positives == labels.len() {
        return episode;
    }
    let Some(subject) = lifted.first().map(|l| l.action.clone()) else {
        return episode;
    };
    let target = Target {
        kind: AxiomKind::Constraint { head: label.head() },
        action: subject,
    };
    let table = Table::new(rows, labels);
    let learned = ensemble::learn(
        &table,
        &lifter.features,
        &target,
        &params.ensemble,
        rng.next_u64(),
    );
    episode.kept = cover(learned.kept, &table, &lifter.features, params.min_new);
    episode
}

/// Keeps, in order of votes, the constraints that decide at least `min_new` class-1 samples
/// that no constraint kept before them decides: a constraint whose every conclusion another
/// already draws (`-partially_occluded(O1, O2) if relation(right, O1, O2)` beside OC2: an
/// object to the right is never behind) adds nothing to the knowledge.
fn cover(
    kept: Vec<(Axiom, usize)>,
    table: &Table,
    features: &[Literal],
    min_new: usize,
) -> Vec<(Axiom, usize)> {
    let tests = |a: &Axiom| -> Option<Vec<(usize, bool)>> {
        a.body
            .iter()
            .map(|l| {
                let positive = l.clone().with_sign(true);
                features
                    .iter()
                    .position(|f| *f == positive)
                    .map(|i| (i, l.positive))
            })
            .collect()
    };
    let matches = |t: &[(usize, bool)]| -> Vec<usize> {
        (0..table.labels.len())
            .filter(|&i| table.labels[i] && t.iter().all(|&(f, v)| table.rows[i][f] == v))
            .collect()
    };
    // Votes first; among equal votes, the constraint that decides more samples first.
    let mut ranked: Vec<(Axiom, usize, Option<Vec<usize>>)> = kept
        .into_iter()
        .map(|(a, v)| {
            let m = tests(&a).map(|t| matches(&t));
            (a, v, m)
        })
        .collect();
    ranked.sort_by(|(a, va, ma), (b, vb, mb)| {
        let len = |m: &Option<Vec<usize>>| m.as_ref().map_or(0, Vec::len);
        vb.cmp(va).then(len(mb).cmp(&len(ma))).then(a.cmp(b))
    });
    let mut covered = vec![false; table.labels.len()];
    let mut out = Vec::new();
    for (axiom, votes, matches) in ranked {
        let Some(matches) = matches else {
            out.push((axiom, votes));
            continue;
        };
        let new = matches.iter().filter(|&&i| !covered[i]).count();
        if new >= min_new {
            for i in matches {
                covered[i] = true;
            }
            out.push((axiom, votes));
        }
    }
    out
}

/// The constraints removed from KB_full for the experiment, lifted, with their labels.
pub fn targets() -> Vec<(&'static str, Axiom)> {
    let algebra = Algebra::ra();
    let norm = |a: Axiom| {
        let body = a.body.iter().map(|l| algebra.normalize(l)).collect();
        Axiom::new(a.kind, a.action, body).canonical()
    };
    [
        ("ST1", "-stable(O1) if irreg_below(O1)"),
        ("D1", "-stable(O1) if small_base(O1)"),
        (
            "OC2",
            "-partially_occluded(O1, O2) if -relation(behind, O1, O2)",
        ),
    ]
    .into_iter()
    .map(|(l, t)| {
        (
            l,
            norm(Axiom::parse_ald(t).expect("the targets are well formed")),
        )
    })
    .collect()
}

/// Whether a constraint's head is about `label`.
pub fn label_of(axiom: &Axiom) -> Option<Label> {
    match axiom.head()?.name.as_str() {
        "stable" => Some(Label::Stability),
        "partially_occluded" => Some(Label::Occlusion),
        _ => None,
    }
}

/// True for a relation literal of the learner's vocabulary.
pub fn is_relation(l: &Literal) -> bool {
    l.name == RELATION
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lit(text: &str) -> Literal {
        let (positive, rest) = match text.strip_prefix('-') {
            Some(r) => (false, r),
            None => (true, text),
        };
        let (name, args) = rest.split_once('(').unwrap();
        let args: Vec<&str> = args.trim_end_matches(')').split(',').collect();
        Literal::ground(name, &args).with_sign(positive)
    }

    /// Hand-made samples: an object is unstable exactly when it has an irregular object below;
    /// a second feature (its size) is noise. The trees must find ST1 and nothing else.
    #[test]
    fn learns_st1_from_clean_samples() {
        let mut examples = Vec::new();
        for i in 0..300 {
            let a = format!("x{i}");
            let irregular = i % 3 == 0;
            let mut relevant = vec![lit(&format!(
                "has_size({a},{})",
                if i % 2 == 0 { "small" } else { "large" }
            ))];
            if irregular {
                relevant.push(lit(&format!("irreg_below({a})")));
            }
            relevant.push(lit(&format!("relation(on,{a},y{i})")));
            examples.push(Example {
                subject: lit(&format!("stable({a})")),
                relevant,
                class: irregular,
            });
        }
        let ep = learn(Label::Stability, &examples, &ConstraintParams::default(), 7);
        assert_eq!(ep.samples, 300);
        assert_eq!(ep.positives, 100);
        let kept: Vec<Axiom> = ep.kept.iter().map(|(a, _)| a.clone()).collect();
        let st1 = targets().into_iter().find(|(l, _)| *l == "ST1").unwrap().1;
        assert_eq!(kept, vec![st1]);
    }

    #[test]
    fn targets_print_as_written() {
        let t: Vec<String> = targets().iter().map(|(_, a)| a.to_ald()).collect();
        assert_eq!(
            t,
            vec![
                "-stable(O1) if irreg_below(O1)",
                "-stable(O1) if small_base(O1)",
                "-partially_occluded(O1, O2) if -relation(behind, O1, O2)",
            ]
        );
    }
}
