//! Perception: turns the measured state into observations in the domain's vocabulary, through a
//! configurable error model, and prints them as program facts.
//!
//! Error model (docs/domain.md §7.6: about 15% of relations are misrecognised): each true relation
//! literal is independently erroneous with probability `relation_error`; an error either drops the
//! literal or, with probability `substitute_share`, replaces it by a confusable one (arguments
//! swapped for positional relations and `on`; a neighbouring distance class for touch, not_touch
//! and far). Sizes and surfaces are misread with their own rates; `in_hand` is proprioceptive and
//! exact. Every observation carries a confidence, drawn higher for correct readings than for
//! wrong ones; those at or above `threshold` become facts (the paper's "perceptions with high
//! probability become certain literals").
//!
//! Invariant: observations are a function of the scene, its seed, its step and the look number
//! alone (look 0 unless the robot looks again at the same step).

use super::object::{Size, Surface};
use super::scene::{Scene, TABLE};
use super::truth::{relations, Rel, Relation, TruthConfig};
use super::world::World;
use crate::base::rng::SplitMix64;
use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// Stream tag for perception noise, so that it never shares draws with action failures.
const PERCEPTION_STREAM: u64 = 0x5045_5243;

/// The error model of perception.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ErrorModel {
    /// Probability that a true relation literal is misperceived.
    pub relation_error: f64,
    /// Of the misperceived relation literals, the share replaced by a wrong one (the rest are
    /// dropped).
    pub substitute_share: f64,
    /// Probability that an object's size class is misread.
    pub size_error: f64,
    /// Probability that an object's surface type is misread.
    pub surface_error: f64,
    /// Confidence at or above which an observation becomes a fact.
    pub threshold: f64,
}

impl Default for ErrorModel {
    fn default() -> Self {
        ErrorModel {
            relation_error: 0.15,
            substitute_share: 0.5,
            size_error: 0.0,
            surface_error: 0.0,
            threshold: 0.5,
        }
    }
}

impl ErrorModel {
    /// A perfect perceiver.
    pub fn exact() -> Self {
        ErrorModel {
            relation_error: 0.0,
            size_error: 0.0,
            surface_error: 0.0,
            ..Self::default()
        }
    }
}

/// An observable literal.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Literal {
    /// `relation(S, A, B)`.
    Relation(Relation),
    /// `in_hand(R, O)`.
    InHand(String, String),
    /// `has_size(O, Size)`, a static.
    HasSize(String, Size),
    /// `has_surface(L, Surface)`, a static.
    HasSurface(String, Surface),
}

impl Literal {
    /// The literal as a term, e.g. `relation(on,a,b)`.
    pub fn term(&self) -> String {
        match self {
            Literal::Relation(r) => r.to_string(),
            Literal::InHand(r, o) => format!("in_hand({r},{o})"),
            Literal::HasSize(o, s) => format!("has_size({o},{})", s.name()),
            Literal::HasSurface(o, s) => format!("has_surface({o},{})", s.name()),
        }
    }

    /// True for statics, which are printed as plain facts rather than step-indexed fluents.
    pub fn is_static(&self) -> bool {
        matches!(self, Literal::HasSize(..) | Literal::HasSurface(..))
    }
}

/// One observation: a literal, its truth value and the perceiver's confidence.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Observation {
    /// What was observed.
    pub literal: Literal,
    /// Observed true or false.
    pub value: bool,
    /// Confidence in `[0, 1]`.
    pub confidence: f64,
    /// True if the reading is wrong (known only to the simulator; for evaluation).
    pub erroneous: bool,
}

/// Counts of the errors drawn, for checking the error model.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct ErrorCounts {
    /// True relation literals considered.
    pub relations: usize,
    /// Of them, dropped.
    pub dropped: usize,
    /// Of them, replaced by a wrong literal.
    pub substituted: usize,
    /// Size readings made.
    pub sizes: usize,
    /// Of them, wrong.
    pub sizes_wrong: usize,
    /// Surface readings made.
    pub surfaces: usize,
    /// Of them, wrong.
    pub surfaces_wrong: usize,
}

/// What the robot perceives at one step.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Percept {
    /// The time step of the observations.
    pub step: u32,
    /// All observations, sorted by literal; a literal appears at most once.
    pub observations: Vec<Observation>,
    /// The errors drawn.
    pub errors: ErrorCounts,
    /// The threshold of the model that produced it.
    pub threshold: f64,
}

/// How observations are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FactStyle {
    /// `obs(relation(on,a,b),true,0).` (docs/domain.md §3.2 history).
    Obs,
    /// `holds(relation(on,a,b),0).` and `-holds(...)` for false ones (the 2020 code's style).
    Holds,
}

/// A confusable wrong reading of a true relation.
fn confuse(relation: &Relation, rng: &mut SplitMix64) -> Relation {
    let swapped = |r: &Relation| Relation {
        rel: r.rel,
        a: r.b.clone(),
        b: r.a.clone(),
    };
    let with = |rel: Rel| Relation {
        rel,
        a: relation.a.clone(),
        b: relation.b.clone(),
    };
    match relation.rel {
        Rel::Above | Rel::Below | Rel::Front | Rel::Behind | Rel::Left | Rel::Right | Rel::On => {
            swapped(relation)
        }
        Rel::Touch => with(Rel::NotTouch),
        Rel::NotTouch => with(if rng.chance(0.5) {
            Rel::Touch
        } else {
            Rel::Far
        }),
        Rel::Far => with(Rel::NotTouch),
    }
}

/// Perceives the scene as it stands at its current step.
pub fn perceive(scene: &Scene, model: &ErrorModel, truth: &TruthConfig) -> Percept {
    let world = World::build(scene);
    perceive_world(scene, &world, model, truth)
}

/// Perceives a scene whose world is already built.
pub fn perceive_world(
    scene: &Scene,
    world: &World,
    model: &ErrorModel,
    truth: &TruthConfig,
) -> Percept {
    perceive_look(scene, world, model, truth, 0)
}

/// Perceives a scene whose world is already built, the `look`-th time at this step: each look
/// draws its own errors (look 0 is [`perceive_world`]), so a robot that looks again sees
/// independent noise of the same state.
pub fn perceive_look(
    scene: &Scene,
    world: &World,
    model: &ErrorModel,
    truth: &TruthConfig,
    look: u32,
) -> Percept {
    let mut rng = SplitMix64::new(scene.seed)
        .fork(PERCEPTION_STREAM ^ ((scene.step as u64) << 32) ^ ((look as u64) << 16));
    let mut errors = ErrorCounts::default();
    let mut observations: Vec<Observation> = Vec::new();
    let mut emit = |literal: Literal, value: bool, erroneous: bool, rng: &mut SplitMix64| {
        let confidence = if erroneous {
            0.3 + 0.6 * rng.next_f64()
        } else {
            0.6 + 0.4 * rng.next_f64()
        };
        observations.push(Observation {
            literal,
            value,
            confidence,
            erroneous,
        });
    };
    for relation in relations(scene, world, truth) {
        errors.relations += 1;
        if rng.chance(model.relation_error) {
            if rng.chance(model.substitute_share) {
                errors.substituted += 1;
                let wrong = confuse(&relation, &mut rng);
                emit(Literal::Relation(wrong), true, true, &mut rng);
            } else {
                errors.dropped += 1;
            }
        } else {
            emit(Literal::Relation(relation), true, false, &mut rng);
        }
    }
    let held = scene.held();
    for id in scene.ids() {
        let object = scene.object(id);
        let name = object.name.clone();
        emit(
            Literal::InHand(scene.robot.clone(), name.clone()),
            Some(id) == held,
            false,
            &mut rng,
        );
        errors.sizes += 1;
        let size = if rng.chance(model.size_error) {
            errors.sizes_wrong += 1;
            let others: Vec<Size> = Size::ALL
                .into_iter()
                .filter(|&s| s != object.size)
                .collect();
            Some(others[rng.range_usize(0, others.len() - 1)])
        } else {
            None
        };
        emit(
            Literal::HasSize(name.clone(), size.unwrap_or(object.size)),
            true,
            size.is_some(),
            &mut rng,
        );
        errors.surfaces += 1;
        let wrong_surface = rng.chance(model.surface_error);
        let surface = match (object.surface(), wrong_surface) {
            (s, false) => s,
            (Surface::Flat, true) => Surface::Irregular,
            (Surface::Irregular, true) => Surface::Flat,
        };
        errors.surfaces_wrong += wrong_surface as usize;
        emit(
            Literal::HasSurface(name, surface),
            true,
            wrong_surface,
            &mut rng,
        );
    }
    observations.push(Observation {
        literal: Literal::HasSurface(TABLE.into(), Surface::Flat),
        value: true,
        confidence: 1.0,
        erroneous: false,
    });
    // A wrong reading may coincide with a true one; keep the most confident reading per literal.
    observations.sort_by(|x, y| {
        x.literal
            .cmp(&y.literal)
            .then(y.confidence.total_cmp(&x.confidence))
    });
    observations.dedup_by(|later, first| later.literal == first.literal);
    Percept {
        step: scene.step,
        observations,
        errors,
        threshold: model.threshold,
    }
}

impl Percept {
    /// The observations whose confidence reaches the threshold.
    pub fn facts(&self) -> impl Iterator<Item = &Observation> {
        self.observations
            .iter()
            .filter(move |o| o.confidence >= self.threshold)
    }

    /// The facts as program text: statics first, then fluents in the chosen style.
    pub fn to_program(&self, style: FactStyle) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "% observations at step {} (confidence >= {})",
            self.step, self.threshold
        );
        for o in self.facts().filter(|o| o.literal.is_static()) {
            let _ = writeln!(out, "{}.", o.literal.term());
        }
        for o in self.facts().filter(|o| !o.literal.is_static()) {
            let term = o.literal.term();
            let _ = match style {
                FactStyle::Obs => writeln!(out, "obs({term},{},{}).", o.value, self.step),
                FactStyle::Holds if o.value => writeln!(out, "holds({term},{}).", self.step),
                FactStyle::Holds => writeln!(out, "-holds({term},{}).", self.step),
            };
        }
        out
    }
}
