//! The robot's scene classifier: reasoning first, the CNN where reasoning cannot decide, and
//! every decision with its source. Four systems are built from the same parts, for the
//! classification experiment and for `lucent classify`:
//!
//! - [`System::CnnAlone`]: the network on every example;
//! - [`System::Reasoning`]: reasoning alone; where it cannot decide, the training set's
//!   majority class (a prior, named as such);
//! - [`System::ReasoningCnn`]: reasoning, and the network (trained only on the training
//!   examples reasoning could not decide or decided wrongly) where it cannot decide;
//! - [`System::ReasoningCnnLearned`]: the same over knowledge extended with the state
//!   constraints learned from reasoning's failures on the training set.
//!
//! Examples: stability is asked of every object that stands on another object (its region of
//! interest: it and its supports); occlusion of every object in view (its region: it and what
//! stands in front of it). The network's output is the probability of the label's positive
//! class: *unstable* for stability, *occluded* for occlusion.
//!
//! Invariants: training is a function of the training scenes and the seed; a trained
//! classifier is a value (knowledge, networks, priors) that classifies any labelled or
//! unlabelled scene without reading files.

use rayon::prelude::*;

use super::cnn::{Cnn, CnnConfig};
use super::constraints::{self, ConstraintParams, Example, Label};
use super::dataset::{LabelledObject, LabelledScene};
use super::reason::{Knowledge, ReasonError, Reasoning, View};
use super::roi::{mirrored, ROI_SIZE};
use crate::learn::term::{Axiom, Literal};

/// The four classifiers of the experiment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum System {
    /// The CNN on every example.
    CnnAlone,
    /// Reasoning, with the majority class where it cannot decide.
    Reasoning,
    /// Reasoning, with the CNN where it cannot decide.
    ReasoningCnn,
    /// Reasoning with learned constraints, with the CNN where it cannot decide.
    ReasoningCnnLearned,
}

impl System {
    /// Every system.
    pub const ALL: [System; 4] = [
        System::CnnAlone,
        System::Reasoning,
        System::ReasoningCnn,
        System::ReasoningCnnLearned,
    ];

    /// The system's name in tables.
    pub fn name(self) -> &'static str {
        match self {
            System::CnnAlone => "CNN alone",
            System::Reasoning => "reasoning",
            System::ReasoningCnn => "reasoning + CNN",
            System::ReasoningCnnLearned => "reasoning + CNN + learned",
        }
    }

    /// A short key for JSON.
    pub fn key(self) -> &'static str {
        match self {
            System::CnnAlone => "cnn",
            System::Reasoning => "reasoning",
            System::ReasoningCnn => "reasoning_cnn",
            System::ReasoningCnnLearned => "reasoning_cnn_learned",
        }
    }
}

/// Where a decision came from.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Source {
    /// The knowledge base decided it.
    Reasoning,
    /// The knowledge base decided it only with these learned constraints.
    Learned(Vec<String>),
    /// The network decided it (reasoning could not).
    Cnn,
    /// Nothing decided it: the training set's majority class.
    Prior,
}

impl Source {
    /// The source in words.
    pub fn words(&self) -> String {
        match self {
            Source::Reasoning => "reasoning".into(),
            Source::Learned(l) => format!("learned constraint {}", l.join(", ")),
            Source::Cnn => "CNN".into(),
            Source::Prior => "prior".into(),
        }
    }
}

/// One decision: the label's value and its source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Decision {
    /// The decided value (`true`: stable, or occluded).
    pub value: bool,
    /// Where it came from.
    pub source: Source,
}

/// Training parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainConfig {
    /// The network (input size, layers, optimizer, steps cap, seed).
    pub cnn: CnnConfig,
    /// Passes over the training examples: steps = epochs x examples / batch, between
    /// `min_steps` and `cnn.steps`.
    pub epochs: usize,
    /// The least number of steps of a training.
    pub min_steps: usize,
    /// Train on each ROI and its mirror image.
    pub mirror: bool,
    /// The constraint learner's parameters.
    pub constraints: ConstraintParams,
    /// The seed of the constraint learner.
    pub seed: u64,
}

impl Default for TrainConfig {
    fn default() -> Self {
        TrainConfig {
            cnn: CnnConfig {
                steps: 400,
                ..CnnConfig::default()
            },
            epochs: 20,
            min_steps: 100,
            // Measured on the occlusion examples KB_full cannot decide (300 test scenes,
            // `measure`): test accuracy 0.789 -> 0.815 at 50 training scenes, 0.815 -> 0.813
            // at 100, 0.849 -> 0.867 at 200.
            mirror: true,
            constraints: ConstraintParams::default(),
            seed: 0,
        }
    }
}

/// A labelled scene with the reasoning over it.
#[derive(Clone, Debug)]
pub struct Reasoned<'a> {
    /// The scene.
    pub scene: &'a LabelledScene,
    /// The classification under some knowledge.
    pub reasoning: Reasoning,
}

/// Reasons over every scene, in parallel, in order.
pub fn reason_all<'a>(
    knowledge: &Knowledge,
    scenes: &'a [LabelledScene],
) -> Result<Vec<Reasoned<'a>>, ReasonError> {
    scenes
        .par_iter()
        .map(|s| {
            let view = View::from_percept(&s.scene, &s.percept);
            Ok(Reasoned {
                scene: s,
                reasoning: knowledge.classify(&view)?,
            })
        })
        .collect()
}

/// The examples of a label in a scene: the objects asked about.
pub fn asked(label: Label, scene: &LabelledScene) -> impl Iterator<Item = &LabelledObject> {
    scene
        .objects
        .iter()
        .filter(move |o| label == Label::Occlusion || o.stacked)
}

/// The true value of a label (`true`: stable / occluded).
pub fn truth(label: Label, o: &LabelledObject) -> bool {
    match label {
        Label::Stability => o.labels.stable,
        Label::Occlusion => o.labels.occluded,
    }
}

/// Reasoning's decision of a label for an object, `None` when it cannot decide.
pub fn reasoned(label: Label, r: &Reasoning, name: &str) -> Option<bool> {
    let b = r.belief(name)?;
    match label {
        Label::Stability => b.stable,
        Label::Occlusion => b.occluded,
    }
}

/// The network's input of a label for an object.
pub fn roi(label: Label, o: &LabelledObject) -> &[f32] {
    match label {
        Label::Stability => &o.stability_roi,
        Label::Occlusion => &o.occlusion_roi,
    }
}

/// The network's target: the positive class (unstable, occluded).
fn positive(label: Label, value: bool) -> bool {
    match label {
        Label::Stability => !value,
        Label::Occlusion => value,
    }
}

/// Trains a network for `label` on `(roi, value)` examples; `None` without examples.
pub fn train_cnn(label: Label, examples: &[(&[f32], bool)], config: &TrainConfig) -> Option<Cnn> {
    if examples.is_empty() {
        return None;
    }
    let mut cnn_config = config.cnn.clone();
    let copies = if config.mirror { 2 } else { 1 };
    let steps = config.epochs * copies * examples.len() / cnn_config.batch.max(1);
    cnn_config.steps = steps.clamp(config.min_steps, config.cnn.steps.max(config.min_steps));
    cnn_config.outputs = 1;
    let mut cnn = Cnn::new(cnn_config);
    let mirrors: Vec<Vec<f32>> = if config.mirror {
        examples
            .iter()
            .map(|(r, _)| mirrored(r, ROI_SIZE))
            .collect()
    } else {
        Vec::new()
    };
    let inputs: Vec<&[f32]> = examples
        .iter()
        .map(|(r, _)| *r)
        .chain(mirrors.iter().map(Vec::as_slice))
        .collect();
    let labels: Vec<Vec<bool>> = examples
        .iter()
        .chain(examples.iter().take(mirrors.len()))
        .map(|(_, v)| vec![positive(label, *v)])
        .collect();
    cnn.train(&inputs, &labels);
    Some(cnn)
}

/// The network's decision (`true`: stable / occluded).
pub fn cnn_decides(label: Label, cnn: &Cnn, input: &[f32]) -> bool {
    let p = cnn.predict(input)[0];
    match label {
        Label::Stability => !p,
        Label::Occlusion => p,
    }
}

/// The constraint learner's examples of a label over reasoned training scenes: every example
/// that the knowledge does not already decide the way the constraint's head would.
pub fn learning_examples(label: Label, reasoned: &[Reasoned<'_>]) -> Vec<Example> {
    let mut out = Vec::new();
    for r in reasoned {
        let state = &r.reasoning.state;
        if state.is_empty() {
            continue;
        }
        let names: Vec<&str> = r.scene.objects.iter().map(|o| o.name.as_str()).collect();
        match label {
            Label::Stability => {
                for o in asked(label, r.scene) {
                    if reasoned_is(label, &r.reasoning, &o.name, false) {
                        continue;
                    }
                    let mut roi: Vec<&str> = o.supports.iter().map(String::as_str).collect();
                    roi.push(&o.name);
                    out.push(Example {
                        subject: Literal::ground("stable", &[&o.name]),
                        relevant: constraints::relevant(label, state, &[&o.name], &roi),
                        class: !o.labels.stable,
                    });
                }
            }
            Label::Occlusion => {
                for o in &r.scene.objects {
                    for &b in &names {
                        if b == o.name || pair_decided(state, &o.name, b) {
                            continue;
                        }
                        let hides = o.labels.occluders.iter().any(|(n, _)| n == b);
                        out.push(Example {
                            subject: Literal::ground("partially_occluded", &[&o.name, b]),
                            relevant: constraints::relevant(label, state, &[&o.name, b], &[]),
                            class: !hides,
                        });
                    }
                }
            }
        }
    }
    out
}

fn reasoned_is(label: Label, r: &Reasoning, name: &str, value: bool) -> bool {
    reasoned(label, r, name) == Some(value)
}

/// Whether the answer set says `partially_occluded(a, b)` either way.
fn pair_decided(state: &[Literal], a: &str, b: &str) -> bool {
    state.iter().any(|l| {
        l.name == "partially_occluded"
            && l.args.len() == 2
            && l.args[0].to_string() == a
            && l.args[1].to_string() == b
    })
}

/// A trained classifier of both labels.
#[derive(Clone, Debug)]
pub struct Classifier {
    /// Which system it is.
    pub system: System,
    /// The knowledge it reasons with (unused by the CNN alone).
    pub knowledge: Knowledge,
    /// Per label, the network (absent when the system has none or nothing to train on).
    pub networks: [Option<Cnn>; 2],
    /// Per label, the training set's majority value.
    pub majority: [bool; 2],
    /// The constraints learned, with their votes.
    pub learned: Vec<(String, Axiom, usize)>,
    /// Training examples per label given to the network.
    pub trained_on: [usize; 2],
}

fn slot(label: Label) -> usize {
    match label {
        Label::Stability => 0,
        Label::Occlusion => 1,
    }
}

impl Classifier {
    /// Trains `system` on `train`, reasoned with `base` (the knowledge before learning).
    pub fn train(
        system: System,
        base: &Knowledge,
        train: &[Reasoned<'_>],
        config: &TrainConfig,
    ) -> Result<Classifier, ReasonError> {
        let mut majority = [false; 2];
        for label in Label::ALL {
            let (mut yes, mut all) = (0usize, 0usize);
            for r in train {
                for o in asked(label, r.scene) {
                    all += 1;
                    yes += usize::from(truth(label, o));
                }
            }
            majority[slot(label)] = 2 * yes > all;
        }
        let mut knowledge = base.clone();
        let mut learned = Vec::new();
        // The examples each CNN trains on (none for reasoning alone).
        let examples = if system == System::ReasoningCnnLearned {
            let mut n = 0;
            for label in Label::ALL {
                let examples = learning_examples(label, train);
                let mut seed =
                    crate::base::rng::SplitMix64::new(config.seed).fork(slot(label) as u64);
                let episode =
                    constraints::learn(label, &examples, &config.constraints, seed.next_u64());
                for (axiom, votes) in episode.kept {
                    n += 1;
                    learned.push((format!("L{n}"), axiom, votes));
                }
            }
            knowledge = knowledge.with_learned(
                learned
                    .iter()
                    .map(|(l, a, _)| (l.clone(), a.clone()))
                    .collect(),
            );
            let scenes: Vec<LabelledScene> = train.iter().map(|r| r.scene.clone()).collect();
            let relearned = reason_all(&knowledge, &scenes)?
                .into_iter()
                .map(|r| r.reasoning)
                .collect::<Vec<_>>();
            let again: Vec<Reasoned<'_>> = train
                .iter()
                .zip(relearned)
                .map(|(r, reasoning)| Reasoned {
                    scene: r.scene,
                    reasoning,
                })
                .collect();
            Some(Label::ALL.map(|label| failures(label, &again)))
        } else if system == System::Reasoning {
            None
        } else {
            Some(Label::ALL.map(|label| {
                if system == System::CnnAlone {
                    let mut all = Vec::new();
                    for r in train {
                        for o in asked(label, r.scene) {
                            all.push((roi(label, o), truth(label, o)));
                        }
                    }
                    all
                } else {
                    failures(label, train)
                }
            }))
        };
        let (networks, trained_on) = match examples {
            None => ([None, None], [0, 0]),
            Some(examples) => (
                Label::ALL.map(|label| train_cnn(label, &examples[slot(label)], config)),
                [examples[0].len(), examples[1].len()],
            ),
        };
        Ok(Classifier {
            system,
            knowledge,
            networks,
            majority,
            learned,
            trained_on,
        })
    }

    /// Decides a label for an object of a scene, given reasoning over it with
    /// [`Classifier::knowledge`] (ignored by the CNN alone).
    pub fn decide(
        &self,
        label: Label,
        reasoning: Option<&Reasoning>,
        o: &LabelledObject,
    ) -> Decision {
        self.decide_roi(label, reasoning, &o.name, roi(label, o))
    }

    /// Decides a label for the object `name` whose ROI for the label is `roi`, given reasoning
    /// over its scene with [`Classifier::knowledge`] (ignored by the CNN alone).
    pub fn decide_roi(
        &self,
        label: Label,
        reasoning: Option<&Reasoning>,
        name: &str,
        roi: &[f32],
    ) -> Decision {
        let net = self.networks[slot(label)].as_ref();
        if self.system == System::CnnAlone {
            return match net {
                Some(cnn) => Decision {
                    value: cnn_decides(label, cnn, roi),
                    source: Source::Cnn,
                },
                None => self.prior(label),
            };
        }
        if let Some(v) = reasoning.and_then(|r| reasoned(label, r, name)) {
            return Decision {
                value: v,
                source: Source::Reasoning,
            };
        }
        match net {
            Some(cnn) if self.system != System::Reasoning => Decision {
                value: cnn_decides(label, cnn, roi),
                source: Source::Cnn,
            },
            _ => self.prior(label),
        }
    }

    fn prior(&self, label: Label) -> Decision {
        Decision {
            value: self.majority[slot(label)],
            source: Source::Prior,
        }
    }
}

/// The training examples of a label that reasoning could not decide or decided wrongly, as
/// (ROI, true value).
pub fn failures<'a>(label: Label, over: &[Reasoned<'a>]) -> Vec<(&'a [f32], bool)> {
    let mut out = Vec::new();
    for r in over {
        for o in asked(label, r.scene) {
            let t = truth(label, o);
            if reasoned(label, &r.reasoning, &o.name) != Some(t) {
                out.push((roi(label, o), t));
            }
        }
    }
    out
}

/// One object's decisions for people: stability (only for objects on another object),
/// occlusion, and the physics labels when the scene has them.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjectReport {
    /// The object.
    pub name: String,
    /// Stable or not, with the source; `None` for objects on the table.
    pub stable: Option<Decision>,
    /// Occluded or not, with the source.
    pub occluded: Decision,
    /// The physics label of stability (objects on another object).
    pub true_stable: Option<bool>,
    /// The physics label of occlusion.
    pub true_occluded: bool,
}

/// Classifies a looked-at scene and says where each decision came from: a decision reasoning
/// makes only with the learned constraints names the ones that make it by themselves (each
/// tried alone beside the rest of the knowledge), or all of the label's when only several
/// together make it.
pub fn explain_scene(
    c: &Classifier,
    view: &View,
    scene: &LabelledScene,
) -> Result<Vec<ObjectReport>, ReasonError> {
    let with = c.knowledge.classify(view)?;
    let (without, alone) = if c.knowledge.learned.is_empty() {
        (None, Vec::new())
    } else {
        let mut k = c.knowledge.clone();
        k.learned.clear();
        // Each learned constraint alone beside the rest of the knowledge: the ones that decide
        // an object by themselves are the ones its decision names.
        let alone = c
            .knowledge
            .learned
            .iter()
            .map(|one| {
                let mut k1 = k.clone();
                k1.learned.push(one.clone());
                Ok((
                    one.0.clone(),
                    constraints::label_of(&one.1),
                    k1.classify(view)?,
                ))
            })
            .collect::<Result<Vec<_>, ReasonError>>()?;
        (Some(k.classify(view)?), alone)
    };
    let name_learned = |label: Label, d: Decision, o: &LabelledObject| {
        let (Some(w), Source::Reasoning) = (&without, &d.source) else {
            return d;
        };
        if reasoned(label, w, &o.name) == Some(d.value) {
            return d;
        }
        let of_label = || alone.iter().filter(|(_, l, _)| *l == Some(label));
        let mut labels: Vec<String> = of_label()
            .filter(|(_, _, r)| reasoned(label, r, &o.name) == Some(d.value))
            .map(|(n, _, _)| n.clone())
            .collect();
        if labels.is_empty() {
            // Only several together decide it: name every one of the label.
            labels = of_label().map(|(n, _, _)| n.clone()).collect();
        }
        Decision {
            source: Source::Learned(labels),
            ..d
        }
    };
    Ok(scene
        .objects
        .iter()
        .map(|o| {
            let stable = o.stacked.then(|| {
                name_learned(
                    Label::Stability,
                    c.decide(Label::Stability, Some(&with), o),
                    o,
                )
            });
            let occluded = name_learned(
                Label::Occlusion,
                c.decide(Label::Occlusion, Some(&with), o),
                o,
            );
            ObjectReport {
                name: o.name.clone(),
                stable,
                occluded,
                true_stable: o.stacked.then_some(o.labels.stable),
                true_occluded: o.labels.occluded,
            }
        })
        .collect())
}
