//! Occlusion seen from the camera image in the sense-plan-act loop: a [`World`] that wraps the
//! simulated tabletop and adds, to each look's percept, what scene understanding decides about
//! occlusion from the frontal picture of that moment.
//!
//! At each look the wrapper perceives as the tabletop does (the same look, so the same noisy
//! relations), reasons over that percept in classification mode, cuts each object's occlusion
//! ROI from the picture, and decides each object's occlusion with a [`Classifier`]. Where
//! reasoning decides, the robot's own knowledge derives the same literal, so nothing is added;
//! where the network decides, the decision becomes observations of `partially_occluded(A, B)`
//! for every object B that A is perceived to be behind (true when A is judged occluded, false
//! otherwise), with the network's output as the reading's confidence. Every look's decisions
//! are kept in [`Seeing::seen`] for the caller to report.
//!
//! Invariants: no decision reads the simulator's occlusion labels (each decision carries the
//! world's label beside it, for the report); the inner world's
//! percept is passed on unchanged apart from the added observations; a held object is not
//! judged (it is not in view).

use super::classify::{reason_all, Classifier, Decision, Source, System, TrainConfig};
use super::constraints::Label;
use super::dataset::{generate_with, occlusion_rois, DatasetConfig};
use super::labels::frontal;
use super::reason::{Knowledge, ReasonError, Reasoning, View};
use crate::control::Symbol;
use crate::plan::act::{Percept, Seen, World};
use crate::plan::tabletop::SimWorld;
use crate::sim::perceive::perceive_look;
use crate::sim::truth::Rel;

/// Seeds of the scenes a seeing robot is trained on start here, apart from the scenes it acts in.
pub const TRAINING_SEEDS: u64 = 1 << 40;

/// One decision about an object's occlusion at one look.
#[derive(Clone, Debug, PartialEq)]
pub struct SeenOcclusion {
    /// The scene's step (actions executed so far).
    pub step: u32,
    /// The look at that step.
    pub look: u32,
    /// The object.
    pub object: String,
    /// The decision and its source.
    pub decision: Decision,
    /// The objects it is perceived to be behind (the occluders the observations name).
    pub behind: Vec<String>,
    /// The world's label (`labels`: more than the threshold of its frontal silhouette hidden),
    /// measured for the report only: no decision reads it.
    pub truth: bool,
}

/// The tabletop world, seeing occlusion through scene understanding.
pub struct Seeing {
    /// The wrapped world.
    pub inner: SimWorld,
    /// The classifier (reasoning, then the network).
    pub classifier: Classifier,
    /// The picture sizes and the ROI settings.
    pub dataset: DatasetConfig,
    /// Every decision taken, in order.
    pub seen: Vec<SeenOcclusion>,
}

/// Trains the classifier a seeing robot uses: reasoning with `knowledge`, and a network on the
/// occlusion ROIs of `scenes` generated scenes (seeds from [`TRAINING_SEEDS`] + `seed`) that
/// reasoning cannot decide. Returns the classifier and the number of network examples.
/// `scene_done` hears each generated training scene (a progress bar's tick).
pub fn train_seer(
    knowledge: &Knowledge,
    dataset: &DatasetConfig,
    scenes: u64,
    seed: u64,
    scene_done: &(dyn Fn() + Sync),
) -> Result<Classifier, ReasonError> {
    let start = TRAINING_SEEDS + seed.wrapping_mul(scenes.max(1));
    let train = generate_with(dataset, start..start + scenes, scene_done);
    let reasoned = reason_all(knowledge, &train)?;
    Classifier::train(
        System::ReasoningCnn,
        knowledge,
        &reasoned,
        &TrainConfig::default(),
    )
}

impl Seeing {
    /// A seeing world over `inner`.
    pub fn new(inner: SimWorld, classifier: Classifier, dataset: DatasetConfig) -> Seeing {
        Seeing {
            inner,
            classifier,
            dataset,
            seen: Vec::new(),
        }
    }

    /// Reasoning over a look's view. A noisy look can contradict the knowledge (a relation
    /// perceived both ways, a cycle of `behind`) and leave no answer set, where the loop would
    /// doubt readings; occlusion depends only on `behind` (OC2), so the fallback reasons over the
    /// attributes and the `behind` relations not perceived both ways. `None` when that too has
    /// no answer set.
    fn reason(&self, view: &View) -> Option<Reasoning> {
        let knowledge = &self.classifier.knowledge;
        let consistent = |r: &Reasoning| r.models > 0;
        if let Some(r) = knowledge.classify(view).ok().filter(consistent) {
            return Some(r);
        }
        let behind = |a: &str, b: &str| {
            view.relations
                .iter()
                .any(|r| r.rel == Rel::Behind && r.a == a && r.b == b)
        };
        let narrowed = View {
            objects: view.objects.clone(),
            relations: view
                .relations
                .iter()
                .filter(|r| r.rel == Rel::Behind && !behind(&r.b, &r.a))
                .cloned()
                .collect(),
        };
        knowledge.classify(&narrowed).ok().filter(consistent)
    }

    /// The occlusion decisions of one look at the inner world's current scene, with the
    /// observations they add.
    fn look_at(&self, look: u32) -> (Vec<SeenOcclusion>, Vec<Seen>) {
        let scene = &self.inner.scene;
        let world = crate::sim::World::build(scene);
        let act = &self.inner.act;
        let percept = perceive_look(scene, &world, &act.perception, &act.truth, look);
        let view = View::from_percept(scene, &percept);
        let reasoning = self.reason(&view);
        let rois = occlusion_rois(
            scene,
            &world,
            self.dataset.image_width,
            self.dataset.image_height,
        );
        let mut decisions = Vec::new();
        let mut seen = Vec::new();
        for (id, roi) in scene.ids().zip(rois) {
            let Some(roi) = roi else { continue };
            let name = &scene.object(id).name;
            let decision =
                self.classifier
                    .decide_roi(Label::Occlusion, reasoning.as_ref(), name, &roi);
            let behind: Vec<String> = view
                .relations
                .iter()
                .filter(|r| r.rel == Rel::Behind && &r.a == name)
                .map(|r| r.b.clone())
                .collect();
            if decision.source == Source::Cnn {
                let confidence = self.classifier.networks[1]
                    .as_ref()
                    .map_or(0.5, |cnn| f64::from(cnn.forward(&roi)[0]));
                let confidence = if decision.value {
                    confidence
                } else {
                    1.0 - confidence
                };
                for b in &behind {
                    seen.push(Seen {
                        fluent: Symbol::function(
                            "partially_occluded",
                            vec![
                                Symbol::constant(name.as_str()),
                                Symbol::constant(b.as_str()),
                            ],
                        ),
                        value: decision.value,
                        confidence,
                        exact: false,
                    });
                }
            }
            let labels = &self.dataset.labels;
            let truth = frontal(scene, &world, id, labels.grid)
                .is_some_and(|f| f.hidden() > labels.occlusion_threshold);
            decisions.push(SeenOcclusion {
                step: scene.step,
                look,
                object: name.clone(),
                decision,
                behind,
                truth,
            });
        }
        (decisions, seen)
    }
}

impl World for Seeing {
    fn objects(&self) -> Vec<String> {
        self.inner.objects()
    }

    fn perceive(&mut self, look: u32) -> Percept {
        let mut percept = self.inner.perceive(look);
        let (decisions, seen) = self.look_at(look);
        percept.fluents.extend(seen);
        self.seen.extend(decisions);
        percept
    }

    fn execute(&mut self, action: &Symbol) -> Result<Option<String>, String> {
        self.inner.execute(action)
    }

    fn holds_in_truth(&mut self, literal: &Symbol) -> Option<bool> {
        self.inner.holds_in_truth(literal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::act::ActConfig;
    use crate::sim::{Colour, ErrorModel, ObjectKind, Scene, Size};
    use crate::vision::cnn::{Cnn, CnnConfig};

    /// A large green cube with a small red cube 25 cm straight behind it, and a blue cube far
    /// to the side; perception exact.
    fn world() -> SimWorld {
        let mut s = Scene::custom(5);
        for (name, colour, size, at) in [
            ("green_cube", Colour::Green, Size::Large, (0.0, 0.0, 0.0)),
            ("red_cube", Colour::Red, Size::Small, (0.0, 0.0, 0.25)),
            ("blue_cube", Colour::Blue, Size::Medium, (-0.3, 0.0, 0.0)),
        ] {
            s.add_resting(name, ObjectKind::Cube, colour, size, at);
        }
        let act = ActConfig {
            perception: ErrorModel::exact(),
            ..ActConfig::default()
        };
        SimWorld::new(s, act)
    }

    /// Reasoning (KB_full's OC2) decides the two cubes that are behind nothing and adds no
    /// observation for them; the red cube, behind the green one, goes to the network, whose
    /// decision (an untrained, seeded network: whatever it says) becomes one observation of
    /// `partially_occluded(red_cube, green_cube)` with that value.
    #[test]
    fn the_network_decides_what_reasoning_cannot_and_its_decision_is_observed() {
        let knowledge = Knowledge::kb_full();
        let mut classifier = Classifier::train(
            System::ReasoningCnn,
            &knowledge,
            &[],
            &TrainConfig::default(),
        )
        .unwrap();
        classifier.networks[1] = Some(Cnn::new(CnnConfig {
            outputs: 1,
            ..CnnConfig::default()
        }));
        let mut seeing = Seeing::new(world(), classifier, DatasetConfig::default());
        let before = seeing.inner.perceive(0);
        let percept = seeing.perceive(0);
        assert_eq!(percept.statics, before.statics);
        assert_eq!(
            &percept.fluents[..before.fluents.len()],
            &before.fluents[..]
        );
        let added = &percept.fluents[before.fluents.len()..];
        let by = |name: &str| seeing.seen.iter().find(|s| s.object == name).unwrap();
        for name in ["green_cube", "blue_cube"] {
            assert_eq!(by(name).decision.source, Source::Reasoning, "{name}");
            assert!(!by(name).decision.value, "{name}");
        }
        let red = by("red_cube");
        assert_eq!(red.decision.source, Source::Cnn);
        assert_eq!(red.behind, vec!["green_cube".to_string()]);
        assert_eq!(added.len(), 1, "{added:?}");
        assert_eq!(
            added[0].fluent.to_string(),
            "partially_occluded(red_cube,green_cube)"
        );
        assert_eq!(added[0].value, red.decision.value);
        assert!((0.5..=1.0).contains(&added[0].confidence));
    }
}
