//! The classification experiment (scene understanding): accuracy, precision and recall of
//! stability and occlusion on held-apart test scenes, for training sets of growing size, for
//! the four systems of `vision::classify`; the learning of the removed state constraints over
//! independent runs, scored as H1 scores the action axioms; and which constraints of KB_full
//! decide the labels at all (each removed in turn).
//!
//! Setup: reasoning starts from KB_full without ST1, D1 and OC2 (the constraints that decide
//! the labels); the system with learned constraints learns them back from its training set.
//! Training scenes are seeds `base..base+max(sizes)` (a size-n set is the first n), test scenes
//! seeds from `base + 1_000_000`; presets alternate (real, simulated).
//!
//! Invariants: the result is a function of the configuration except for the timings (keys
//! ending in `seconds`); nothing here reads or writes files (`cli` does).

use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::interval::{self, Interval};
use crate::base::rng::SplitMix64;
use crate::learn::score::{self, Counts};
use crate::learn::term::Axiom;
use crate::vision::classify::{
    self, asked, reason_all, truth, Classifier, Reasoned, System, TrainConfig,
};
use crate::vision::constraints::{self, Label};
use crate::vision::dataset::{self, DatasetConfig, LabelledScene};
use crate::vision::reason::{Knowledge, DECIDING};

/// The labels removed from KB_full for the learning systems.
pub const REMOVED: [&str; 3] = ["ST1", "D1", "OC2"];

/// What to run.
#[derive(Clone, Debug)]
pub struct ClassifyConfig {
    /// Training-set sizes in scenes.
    pub sizes: Vec<usize>,
    /// Test scenes.
    pub test_scenes: usize,
    /// Independent learning runs for the constraint-learning score.
    pub runs: usize,
    /// Training scenes per learning run (a seeded subset of the largest training set).
    pub run_scenes: usize,
    /// The base seed.
    pub seed: u64,
    /// How scenes are made.
    pub dataset: DatasetConfig,
    /// How classifiers are trained.
    pub train: TrainConfig,
}

impl Default for ClassifyConfig {
    fn default() -> Self {
        ClassifyConfig {
            sizes: vec![50, 100, 200, 500, 1000],
            test_scenes: 300,
            runs: 20,
            run_scenes: 200,
            seed: 0,
            dataset: classification_dataset(),
            train: TrainConfig::default(),
        }
    }
}

/// The dataset of classification: perception from one image misses relations (10% of the true
/// relations are not perceived) but does not invent them; a confusion of positional relations
/// (a swapped `on`) makes the whole scene contradict the relation algebra (SR5 with SR6), and
/// the robot's planning loop filters those by looking again, which a single image cannot.
pub fn classification_dataset() -> DatasetConfig {
    let mut d = DatasetConfig::default();
    d.error.relation_error = 0.1;
    d.error.substitute_share = 0.0;
    d
}

/// Scores of one system, label and training size.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Row {
    /// The system's key.
    pub system: String,
    /// Training scenes.
    pub train_scenes: usize,
    /// `stability` or `occlusion`.
    pub label: String,
    /// Test examples.
    pub examples: usize,
    /// Fraction correct.
    pub accuracy: f64,
    /// Precision of the positive class (unstable, occluded).
    pub precision: f64,
    /// Recall of the positive class.
    pub recall: f64,
    /// 95% intervals of accuracy, precision and recall: the percentile bootstrap over the test
    /// scenes (`experiment::interval`, fixed seed), each resample's counts summed; `None` in
    /// results written before.
    #[serde(default)]
    pub intervals: [Option<Interval>; 3],
    /// Fraction of test examples decided by reasoning.
    pub by_reasoning: f64,
    /// Training examples given to the network.
    pub cnn_examples: usize,
    /// Training time of the system (both labels), seconds.
    pub train_seconds: f64,
}

/// The learning runs' score against the removed constraints.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq, Default)]
pub struct LearningScore {
    /// Runs.
    pub runs: usize,
    /// Strict counts summed over runs.
    pub strict: (usize, usize, usize),
    /// Relaxed counts summed over runs.
    pub relaxed: (usize, usize, usize),
    /// Strict precision and recall, percent.
    pub strict_pr: (f64, f64),
    /// Relaxed precision and recall, percent.
    pub relaxed_pr: (f64, f64),
    /// 95% intervals of strict P, strict R, relaxed P, relaxed R: the bootstrap over the runs,
    /// each resample's counts summed (as H1's); `None` in results written before.
    #[serde(default)]
    pub intervals: [Option<Interval>; 4],
    /// Every constraint learned in some run, with the number of runs that learned it.
    pub learned: Vec<(String, usize)>,
}

/// Reasoning alone with one constraint removed from KB_full.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct Removal {
    /// The removed label (`none` for KB_full).
    pub removed: String,
    /// Per label: accuracy over the decided examples, fraction decided, decisions changed
    /// against KB_full.
    pub stability: (f64, f64, usize),
    /// The same for occlusion.
    pub occlusion: (f64, f64, usize),
}

/// The experiment's result.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct ClassifyResult {
    /// Training sizes.
    pub sizes: Vec<usize>,
    /// Test scenes.
    pub test_scenes: usize,
    /// Per system, label and size.
    pub rows: Vec<Row>,
    /// The learning runs.
    pub learning: LearningScore,
    /// The removal check.
    pub removals: Vec<Removal>,
    /// Test class balance: fraction unstable of stacked objects, fraction occluded.
    pub balance: (f64, f64),
    /// Per label, the least training size at which the CNN alone reaches the accuracy of
    /// reasoning + CNN + learned at 200 scenes (`None`: not within the sizes run).
    pub cnn_match: Vec<(String, Option<usize>)>,
    /// Seconds to generate the scenes.
    pub dataset_seconds: f64,
    /// Seconds of the whole experiment.
    pub seconds: f64,
}

fn slot(label: Label) -> usize {
    match label {
        Label::Stability => 0,
        Label::Occlusion => 1,
    }
}

/// One test scene's decisions: examples, right, tp, fp, fn, decided by reasoning.
type SceneCounts = [usize; 6];

/// Accuracy, precision and recall of summed scene counts (0 when undefined).
fn rates(counts: &[&SceneCounts]) -> [f64; 3] {
    let mut t = [0usize; 6];
    for c in counts {
        for (a, b) in t.iter_mut().zip(c.iter()) {
            *a += b;
        }
    }
    let ratio = |a: usize, b: usize| if b == 0 { 0.0 } else { a as f64 / b as f64 };
    [
        ratio(t[1], t[0]),
        ratio(t[2], t[2] + t[3]),
        ratio(t[2], t[2] + t[4]),
    ]
}

/// Scores of one classifier on the test scenes.
struct Scores {
    examples: usize,
    /// Accuracy, precision, recall.
    rates: [f64; 3],
    /// Their 95% intervals over the test scenes.
    intervals: [Option<Interval>; 3],
    by_reasoning: f64,
}

/// Scores a trained classifier on reasoned test scenes; the intervals resample the scenes (the
/// examples of one image are not independent).
fn evaluate(c: &Classifier, test: &[Reasoned<'_>], label: Label) -> Scores {
    let scenes: Vec<SceneCounts> = test
        .par_iter()
        .map(|r| {
            asked(label, r.scene)
                .map(|o| {
                    let d = c.decide(label, Some(&r.reasoning), o);
                    let positive = |v: bool| match label {
                        Label::Stability => !v,
                        Label::Occlusion => v,
                    };
                    (
                        positive(d.value),
                        positive(truth(label, o)),
                        d.source == classify::Source::Reasoning,
                    )
                })
                .fold([0usize; 6], |mut n, (p, t, r)| {
                    n[0] += 1;
                    n[1] += usize::from(p == t);
                    n[2] += usize::from(p && t);
                    n[3] += usize::from(p && !t);
                    n[4] += usize::from(!p && t);
                    n[5] += usize::from(r);
                    n
                })
        })
        .collect();
    let all: Vec<&SceneCounts> = scenes.iter().collect();
    let n: usize = scenes.iter().map(|c| c[0]).sum();
    let reasoned: usize = scenes.iter().map(|c| c[5]).sum();
    let ci = |k: usize| interval::bootstrap(&scenes, |sample| Some(rates(sample)[k]));
    Scores {
        examples: n,
        rates: rates(&all),
        intervals: [ci(0), ci(1), ci(2)],
        by_reasoning: if n == 0 {
            0.0
        } else {
            reasoned as f64 / n as f64
        },
    }
}

/// How many scenes [`run`] generates (training and test): the length of its progress.
pub fn scene_count(config: &ClassifyConfig) -> usize {
    config.sizes.iter().copied().max().unwrap_or(0) + config.test_scenes
}

/// Runs the experiment; `progress` hears a line per stage, `scene_done` each generated scene
/// ([`scene_count`] in all).
pub fn run(
    config: &ClassifyConfig,
    progress: &dyn Fn(&str),
    scene_done: &(dyn Fn() + Sync),
) -> Result<ClassifyResult, String> {
    let start = Instant::now();
    let max = config.sizes.iter().copied().max().unwrap_or(0);
    let base = config.seed.wrapping_mul(10_000_000);
    let train_scenes = dataset::generate_with(&config.dataset, base..base + max as u64, scene_done);
    let test_base = base + 1_000_000;
    let test_scenes = dataset::generate_with(
        &config.dataset,
        test_base..test_base + config.test_scenes as u64,
        scene_done,
    );
    let dataset_seconds = start.elapsed().as_secs_f64();
    progress(&format!(
        "scenes: {} training, {} test, {dataset_seconds:.1} s",
        train_scenes.len(),
        test_scenes.len()
    ));
    let incomplete = Knowledge::kb_full().without(&REMOVED);
    let err = |e: crate::vision::reason::ReasonError| e.to_string();
    let train_reasoned = reason_all(&incomplete, &train_scenes).map_err(err)?;
    let test_reasoned = reason_all(&incomplete, &test_scenes).map_err(err)?;
    progress("reasoning over the scenes done");
    let mut rows = Vec::new();
    for &size in &config.sizes {
        let train = &train_reasoned[..size.min(train_reasoned.len())];
        for system in System::ALL {
            let t0 = Instant::now();
            let c = Classifier::train(system, &incomplete, train, &config.train).map_err(err)?;
            let secs = t0.elapsed().as_secs_f64();
            let relearned;
            let test: &[Reasoned<'_>] = if c.learned.is_empty() {
                &test_reasoned
            } else {
                relearned = reason_all(&c.knowledge, &test_scenes).map_err(err)?;
                &relearned
            };
            for label in Label::ALL {
                let sc = evaluate(&c, test, label);
                let [accuracy, precision, recall] = sc.rates;
                rows.push(Row {
                    system: system.key().into(),
                    train_scenes: size,
                    label: label.name().into(),
                    examples: sc.examples,
                    accuracy,
                    precision,
                    recall,
                    intervals: sc.intervals,
                    by_reasoning: sc.by_reasoning,
                    cnn_examples: c.trained_on[slot(label)],
                    train_seconds: secs,
                });
            }
            progress(&format!(
                "{} scenes, {}: stability {:.3}, occlusion {:.3} ({secs:.1} s)",
                size,
                system.name(),
                rows[rows.len() - 2].accuracy,
                rows[rows.len() - 1].accuracy
            ));
        }
    }
    let learning = learning_runs(config, &train_reasoned);
    progress(&format!(
        "learning runs: strict P {:.1} R {:.1}",
        learning.strict_pr.0, learning.strict_pr.1
    ));
    let removals = removal_check(&test_scenes).map_err(err)?;
    let balance = balance(&test_scenes);
    let cnn_match = Label::ALL
        .iter()
        .map(|&label| {
            let goal = rows.iter().find(|r| {
                r.system == System::ReasoningCnnLearned.key()
                    && r.label == label.name()
                    && r.train_scenes == 200
            });
            let found = goal.and_then(|g| {
                rows.iter()
                    .filter(|r| r.system == System::CnnAlone.key() && r.label == label.name())
                    .filter(|r| r.accuracy >= g.accuracy)
                    .map(|r| r.train_scenes)
                    .min()
            });
            (label.name().to_string(), found)
        })
        .collect();
    Ok(ClassifyResult {
        sizes: config.sizes.clone(),
        test_scenes: test_scenes.len(),
        rows,
        learning,
        removals,
        balance,
        cnn_match,
        dataset_seconds,
        seconds: start.elapsed().as_secs_f64(),
    })
}

fn balance(scenes: &[LabelledScene]) -> (f64, f64) {
    let (mut st, mut stn, mut oc, mut ocn) = (0, 0, 0, 0);
    for s in scenes {
        for o in &s.objects {
            if o.stacked {
                stn += 1;
                st += usize::from(!o.labels.stable);
            }
            ocn += 1;
            oc += usize::from(o.labels.occluded);
        }
    }
    (st as f64 / stn.max(1) as f64, oc as f64 / ocn.max(1) as f64)
}

/// Independent learning runs: each learns from a seeded subset of the training scenes.
fn learning_runs(config: &ClassifyConfig, train: &[Reasoned<'_>]) -> LearningScore {
    let targets: Vec<Axiom> = constraints::targets().into_iter().map(|(_, a)| a).collect();
    let per_run: Vec<Vec<Axiom>> = (0..config.runs)
        .into_par_iter()
        .map(|run| {
            let mut rng = SplitMix64::new(config.seed).fork(1000 + run as u64);
            let mut idx: Vec<usize> = (0..train.len()).collect();
            rng.shuffle_modulo(&mut idx);
            idx.truncate(config.run_scenes.min(train.len()));
            idx.sort_unstable();
            let subset: Vec<Reasoned<'_>> = idx.iter().map(|&i| train[i].clone()).collect();
            let mut found = Vec::new();
            for label in Label::ALL {
                let examples = classify::learning_examples(label, &subset);
                let ep =
                    constraints::learn(label, &examples, &config.train.constraints, rng.next_u64());
                found.extend(ep.kept.into_iter().map(|(a, _)| a));
            }
            found
        })
        .collect();
    let (mut strict, mut relaxed) = (Counts::default(), Counts::default());
    let mut tally: std::collections::BTreeMap<String, usize> = Default::default();
    let mut per_run_counts = Vec::new();
    for found in &per_run {
        let (st, re) = (
            score::strict(found, &targets),
            score::relaxed(found, &targets),
        );
        per_run_counts.push((st, re));
        strict.add(st);
        relaxed.add(re);
        for a in found {
            *tally.entry(a.to_ald()).or_default() += 1;
        }
    }
    let mut learned: Vec<(String, usize)> = tally.into_iter().collect();
    learned.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let ci = |relaxed: bool, recall: bool| {
        interval::bootstrap(&per_run_counts, |sample| {
            let mut c = Counts::default();
            for (st, re) in sample {
                c.add(if relaxed { *re } else { *st });
            }
            Some(if recall { c.recall() } else { c.precision() })
        })
    };
    LearningScore {
        intervals: [
            ci(false, false),
            ci(false, true),
            ci(true, false),
            ci(true, true),
        ],
        runs: config.runs,
        strict: (strict.tp, strict.fp, strict.fn_),
        relaxed: (relaxed.tp, relaxed.fp, relaxed.fn_),
        strict_pr: (strict.precision(), strict.recall()),
        relaxed_pr: (relaxed.precision(), relaxed.recall()),
        learned,
    }
}

/// Reasoning alone over the test scenes with KB_full and with each deciding constraint
/// removed in turn.
fn removal_check(
    test: &[LabelledScene],
) -> Result<Vec<Removal>, crate::vision::reason::ReasonError> {
    let full = reason_all(&Knowledge::kb_full(), test)?;
    let mut out = Vec::new();
    for removed in std::iter::once("none").chain(DECIDING) {
        let k = if removed == "none" {
            Knowledge::kb_full()
        } else {
            Knowledge::kb_full().without(&[removed])
        };
        let r = if removed == "none" {
            full.clone()
        } else {
            reason_all(&k, test)?
        };
        let stats = |label: Label| {
            let (mut decided, mut right, mut n, mut changed) = (0, 0, 0, 0);
            for (a, b) in r.iter().zip(&full) {
                for o in asked(label, a.scene) {
                    n += 1;
                    let d = classify::reasoned(label, &a.reasoning, &o.name);
                    let f = classify::reasoned(label, &b.reasoning, &o.name);
                    changed += usize::from(d != f);
                    if let Some(v) = d {
                        decided += 1;
                        right += usize::from(v == truth(label, o));
                    }
                }
            }
            (
                right as f64 / decided.max(1) as f64,
                decided as f64 / n.max(1) as f64,
                changed,
            )
        };
        out.push(Removal {
            removed: removed.to_string(),
            stability: stats(Label::Stability),
            occlusion: stats(Label::Occlusion),
        });
    }
    Ok(out)
}

/// The paper's claims beside ours, as markdown.
pub fn markdown(r: &ClassifyResult) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let _ = writeln!(s, "## Scene understanding: stability and occlusion\n");
    let _ = writeln!(
        s,
        "{} test scenes; {:.0}% of stacked objects unstable, {:.0}% of objects occluded. \
         Reasoning starts from KB_full without {}; the last system learns them back from its \
         training set. Each figure is followed by its 95% interval in brackets: the percentile \
         bootstrap over the test scenes (an image's objects are not independent), 2000 \
         resamples with a fixed seed (src/experiment/interval.rs); the plots draw the accuracy's \
         interval as a whisker.\n",
        r.test_scenes,
        100.0 * r.balance.0,
        100.0 * r.balance.1,
        REMOVED.join(", ")
    );
    for label in Label::ALL {
        let _ = writeln!(
            s,
            "### {} accuracy (precision / recall of the positive class)\n",
            label.name()
        );
        let _ = write!(s, "| system |");
        for n in &r.sizes {
            let _ = write!(s, " {n} scenes |");
        }
        let _ = writeln!(s, " training time at {} |", r.sizes.last().unwrap_or(&0));
        let _ = writeln!(s, "|---|{}---|", "---|".repeat(r.sizes.len()));
        for system in System::ALL {
            let _ = write!(s, "| {} |", system.name());
            let mut last_time = 0.0;
            for n in &r.sizes {
                match r.rows.iter().find(|x| {
                    x.system == system.key() && x.label == label.name() && x.train_scenes == *n
                }) {
                    Some(x) => {
                        last_time = x.train_seconds;
                        let [a, p, r] = x.intervals;
                        let _ = write!(
                            s,
                            " {} ({} / {}) |",
                            interval::cell(Some(x.accuracy), a, 3),
                            interval::cell(Some(x.precision), p, 2),
                            interval::cell(Some(x.recall), r, 2)
                        );
                    }
                    None => {
                        let _ = write!(s, " n/a |");
                    }
                }
            }
            let _ = writeln!(s, " {last_time:.1} s |");
        }
        let _ = writeln!(s);
    }
    let l = &r.learning;
    let _ = writeln!(
        s,
        "### Learning the removed constraints back ({} runs; intervals: bootstrap over the runs)\n\n| | TP | FP | FN | Precision % | Recall % |\n|---|---|---|---|---|---|\n| Strict | {} | {} | {} | {} | {} |\n| Relaxed | {} | {} | {} | {} | {} |\n",
        l.runs, l.strict.0, l.strict.1, l.strict.2,
        interval::cell(Some(l.strict_pr.0), l.intervals[0], 1),
        interval::cell(Some(l.strict_pr.1), l.intervals[1], 1),
        l.relaxed.0, l.relaxed.1, l.relaxed.2,
        interval::cell(Some(l.relaxed_pr.0), l.intervals[2], 1),
        interval::cell(Some(l.relaxed_pr.1), l.intervals[3], 1)
    );
    let _ = writeln!(s, "Learned (runs that learned it):\n");
    for (a, n) in &l.learned {
        let _ = writeln!(s, "- `{a}`: {n}");
    }
    let _ = writeln!(
        s,
        "\n### Which constraints decide the labels (reasoning alone, KB_full with one removed)\n\n| removed | stability: accuracy of decided / decided / changed | occlusion: accuracy of decided / decided / changed |\n|---|---|---|"
    );
    for m in &r.removals {
        let _ = writeln!(
            s,
            "| {} | {:.3} / {:.3} / {} | {:.3} / {:.3} / {} |",
            m.removed,
            m.stability.0,
            m.stability.1,
            m.stability.2,
            m.occlusion.0,
            m.occlusion.1,
            m.occlusion.2
        );
    }
    let _ = writeln!(s, "\n### Sample complexity\n");
    for (label, n) in &r.cnn_match {
        let _ = writeln!(
            s,
            "- {label}: the CNN alone {}",
            match n {
                Some(n) => format!(
                    "reaches the accuracy of reasoning + CNN + learned at 200 scenes with {n} training scenes"
                ),
                None => format!(
                    "does not reach the accuracy of reasoning + CNN + learned at 200 scenes within {} training scenes",
                    r.sizes.iter().max().unwrap_or(&0)
                ),
            }
        );
    }
    let _ = writeln!(
        s,
        "\nThe paper's claim: reasoning guides learning, so the network needs far fewer examples and the combination is more reliable than a deep network alone.\n\nScenes generated in {:.1} s; the whole experiment took {:.1} s.",
        r.dataset_seconds, r.seconds
    );
    s
}

/// One SVG per label: accuracy against training-set size, one bar per system.
pub fn plots(r: &ClassifyResult) -> Vec<(String, String)> {
    Label::ALL
        .iter()
        .map(|&label| {
            let groups = r
                .sizes
                .iter()
                .map(|n| {
                    let values = System::ALL
                        .iter()
                        .map(|sys| {
                            r.rows
                                .iter()
                                .find(|x| {
                                    x.system == sys.key()
                                        && x.label == label.name()
                                        && x.train_scenes == *n
                                })
                                .map(|x| x.accuracy)
                        })
                        .collect();
                    (format!("{n} scenes"), values)
                })
                .collect();
            let errors = r
                .sizes
                .iter()
                .map(|n| {
                    System::ALL
                        .iter()
                        .map(|sys| {
                            r.rows
                                .iter()
                                .find(|x| {
                                    x.system == sys.key()
                                        && x.label == label.name()
                                        && x.train_scenes == *n
                                })
                                .and_then(|x| x.intervals[0])
                        })
                        .collect()
                })
                .collect();
            let bars = super::svg::Bars {
                title: format!("{} accuracy against training-set size", label.name()),
                series: System::ALL.iter().map(|s| s.name().to_string()).collect(),
                groups,
                errors,
                y_max: 1.0,
            };
            (
                format!("classify_{}.svg", label.name()),
                super::svg::bar_chart(&bars),
            )
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rates_sum_the_scenes_counts() {
        // Scene a: 4 examples, 3 right, tp 1, fp 1, fn 0; scene b: 2 examples, 1 right, tp 0,
        // fp 0, fn 1. Summed: 4 right of 6, precision 1/2, recall 1/2.
        let a: SceneCounts = [4, 3, 1, 1, 0, 2];
        let b: SceneCounts = [2, 1, 0, 0, 1, 0];
        assert_eq!(rates(&[&a, &b]), [4.0 / 6.0, 0.5, 0.5]);
        // No positive predicted or present: precision and recall are 0, not NaN.
        let c: SceneCounts = [3, 3, 0, 0, 0, 0];
        assert_eq!(rates(&[&c]), [1.0, 0.0, 0.0]);
        // The bootstrap over scenes: a resample of a alone or b alone spans the interval.
        let i = interval::bootstrap(&[a, b], |s| Some(rates(s)[0])).unwrap();
        assert!(i.lo <= 0.5 && i.hi >= 0.75, "{i:?}");
    }
}
