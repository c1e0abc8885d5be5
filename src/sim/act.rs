//! Actuation: `pickup(R, O)` and `putdown(R, O, L)` executed physically in the world, with a
//! configurable rate of manipulation failures (docs/domain.md §7.6: about 15%).
//!
//! A pickup fails physically when the hand is full or something rests on the object; a putdown
//! fails when the robot does not hold the object. A putdown lowers the object, upright, onto the
//! highest point under the destination's centre (the table: a free spot) and lets physics decide
//! what happens. A manipulation failure is a slipped grasp (the object stays) or a slipped
//! release (the object is dropped on the table beside the destination). After every action the
//! world settles and the robot perceives, so expected and observed states can be compared.
//!
//! Invariants: malformed actions, unknown names and `putdown(R, O, O)` are errors (`SimError`);
//! anything the world can do, including failing, is an `ActionReport`. Every executed action,
//! failed or not, advances the scene's step by one. Outcomes are a function of the scene, its
//! seed and its step.

use super::perceive::{perceive_world, ErrorModel, Percept};
use super::scene::{Scene, TABLE};
use super::truth::{relations, Rel, TruthConfig};
use super::world::World;
use super::{ObjectId, SimError};
use crate::base::rng::SplitMix64;
use parry3d::math::{Pose, Rot3, Vector};
use serde::{Deserialize, Serialize};
use std::fmt;

/// Stream tag for manipulation failures and placement jitter.
const ACTION_STREAM: u64 = 0x4143_5421;

/// An action of the robot.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Action {
    /// `pickup(robot, object)`.
    Pickup {
        /// The robot.
        robot: String,
        /// The object to grasp.
        object: String,
    },
    /// `putdown(robot, object, destination)`.
    Putdown {
        /// The robot.
        robot: String,
        /// The held object.
        object: String,
        /// An object or `table`.
        destination: String,
    },
}

impl fmt::Display for Action {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Action::Pickup { robot, object } => write!(f, "pickup({robot},{object})"),
            Action::Putdown {
                robot,
                object,
                destination,
            } => {
                write!(f, "putdown({robot},{object},{destination})")
            }
        }
    }
}

impl Action {
    /// Parses `pickup(R,O)` or `putdown(R,O,L)`, whitespace allowed, an optional final period.
    pub fn parse(text: &str) -> Result<Action, SimError> {
        let bad = || SimError::MalformedAction(text.to_string());
        let compact: String = text.chars().filter(|c| !c.is_whitespace()).collect();
        let compact = compact.strip_suffix('.').unwrap_or(&compact);
        let (head, rest) = compact.split_once('(').ok_or_else(bad)?;
        let args = rest.strip_suffix(')').ok_or_else(bad)?;
        let args: Vec<&str> = args.split(',').collect();
        Action::from_parts(head, &args).map_err(|_| bad())
    }

    /// The action `name(args)`: `pickup` with a robot and an object, `putdown` with a robot, an
    /// object and a destination, every argument a constant.
    pub fn from_parts(name: &str, args: &[&str]) -> Result<Action, SimError> {
        let bad = || SimError::MalformedAction(format!("{name}({})", args.join(",")));
        if !args.iter().all(|a| super::scene::is_constant(a)) {
            return Err(bad());
        }
        match (name, args) {
            ("pickup", [r, o]) => Ok(Action::Pickup {
                robot: r.to_string(),
                object: o.to_string(),
            }),
            ("putdown", [r, o, l]) => Ok(Action::Putdown {
                robot: r.to_string(),
                object: o.to_string(),
                destination: l.to_string(),
            }),
            _ => Err(bad()),
        }
    }
}

/// How actions are executed.
#[derive(Clone, Debug, PartialEq)]
pub struct ActConfig {
    /// Probability that a physically possible action fails (slipped grasp or release).
    pub failure_rate: f64,
    /// Upper bound of the simulated seconds the world settles after the action.
    pub settle_seconds: f32,
    /// The perception error model for the report's observations.
    pub perception: ErrorModel,
    /// Thresholds of the geometric tests.
    pub truth: TruthConfig,
}

impl Default for ActConfig {
    fn default() -> Self {
        ActConfig {
            failure_rate: 0.15,
            settle_seconds: 2.0,
            perception: ErrorModel::default(),
            truth: TruthConfig::default(),
        }
    }
}

/// Why an action failed in the world.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Failure {
    /// The hand already held this object.
    HandFull(String),
    /// These objects rest on the object to pick up.
    Covered(Vec<String>),
    /// The object to put down is not in the hand.
    NotHeld,
    /// The grasp slipped; the object stayed where it was.
    GraspSlipped,
    /// The release slipped; the object was dropped off target.
    ReleaseSlipped,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Failure::HandFull(o) => write!(f, "the hand already holds {o}"),
            Failure::Covered(on) => write!(f, "{} rests on it", on.join(" and ")),
            Failure::NotHeld => write!(f, "the object is not in the hand"),
            Failure::GraspSlipped => write!(f, "the grasp slipped"),
            Failure::ReleaseSlipped => {
                write!(f, "the release slipped and the object fell off target")
            }
        }
    }
}

/// What happened when an action was executed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ActionReport {
    /// The action.
    pub action: Action,
    /// The step at which it was executed; observations are of `step + 1`.
    pub step: u32,
    /// `None` if it succeeded.
    pub failure: Option<Failure>,
    /// What the robot observes afterwards.
    pub percept: Percept,
}

impl ActionReport {
    /// True if the action had its intended effect.
    pub fn succeeded(&self) -> bool {
        self.failure.is_none()
    }
}

/// Checks names and arity-independent sense of an action against a scene.
fn check(scene: &Scene, action: &Action) -> Result<(), SimError> {
    let (robot, object) = match action {
        Action::Pickup { robot, object } => (robot, object),
        Action::Putdown {
            robot,
            object,
            destination,
        } => {
            if destination == object {
                return Err(SimError::ImpossibleAction(format!(
                    "{action}: an object cannot be put down on itself"
                )));
            }
            if destination != TABLE {
                scene.lookup(destination)?;
            }
            (robot, object)
        }
    };
    if *robot != scene.robot {
        return Err(SimError::UnknownRobot(robot.clone()));
    }
    scene.lookup(object)?;
    Ok(())
}

/// The objects resting on `id` (`on(X, id)` holds geometrically).
fn resting_on(scene: &Scene, world: &World, id: ObjectId, truth: &TruthConfig) -> Vec<String> {
    let name = &scene.object(id).name;
    relations(scene, world, truth)
        .into_iter()
        .filter(|r| r.rel == Rel::On && &r.b == name)
        .map(|r| r.a)
        .collect()
}

/// A free spot on the table for an object of footprint radius `r`, near `near`: spots are drawn
/// around `near` with a spread growing with the attempts, and a spot is free when the footprint
/// clears every object's box by 1 cm. With `unblocking`, the free spot kept is the one that puts
/// the object in front of the fewest objects as the camera sees it, then behind the fewest, then
/// the first drawn (the nearest); otherwise the first free spot. Why: the domain predicts no new
/// `behind` relation from a putdown (C1 gives only `on` and what follows from it) and E8 forbids
/// picking up an object behind another, so a deliberate putdown should not hide an object when
/// the table has room (in simulated episode 38 of 2026-12-04 the bottle, put down in front of
/// the blue can each time, blocked the can's pickup eleven times). A slipped release
/// (`unblocking` false) lands wherever the first free spot is.
fn table_spot(
    world: &World,
    scene: &Scene,
    r: f32,
    near: (f32, f32),
    unblocking: bool,
    rng: &mut SplitMix64,
) -> (f32, f32) {
    let boxes: Vec<_> = scene.ids().filter_map(|id| world.aabb(id)).collect();
    let (depth_axis, right_axis) = (scene.camera.depth_axis(), scene.camera.right());
    // An axis-aligned box's interval along a horizontal unit axis.
    let project = |b: &parry3d::bounding_volume::Aabb, axis: Vector| {
        let c = b.center().dot(axis);
        let h = b.half_extents();
        let reach = h.x * axis.x.abs() + h.z * axis.z.abs();
        (c - reach, c + reach)
    };
    let views: Vec<_> = boxes
        .iter()
        .map(|b| (project(b, right_axis), project(b, depth_axis)))
        .collect();
    let tol = TruthConfig::default().interval_tolerance;
    // (objects the spot is in front of, objects it is behind) as the truth measures them.
    let occlusions = |x: f32, z: f32| {
        let at = Vector::new(x, 0.0, z);
        let (lateral, depth) = (at.dot(right_axis), at.dot(depth_axis));
        let (lateral, depth) = ((lateral - r, lateral + r), (depth - r, depth + r));
        views
            .iter()
            .filter(|(l, _)| lateral.1.min(l.1) - lateral.0.max(l.0) > tol)
            .fold((0, 0), |(front, behind), (_, d)| {
                if depth.1 <= d.0 + tol {
                    (front + 1, behind)
                } else if d.1 <= depth.0 + tol {
                    (front, behind + 1)
                } else {
                    (front, behind)
                }
            })
    };
    let mut last = (near.0.clamp(-0.45, 0.45), near.1.clamp(-0.3, 0.35));
    let mut best: Option<((usize, usize), (f32, f32))> = None;
    for attempt in 0..300 {
        let spread = 0.05 + 0.002 * attempt as f32;
        let x = (near.0 + rng.range_f32(-spread, spread)).clamp(-0.5 + r, 0.5 - r);
        let z = (near.1 + rng.range_f32(-spread, spread)).clamp(-0.35 + r, 0.38 - r);
        last = (x, z);
        let clear = boxes.iter().all(|b| {
            x + r < b.mins.x - 0.01
                || x - r > b.maxs.x + 0.01
                || z + r < b.mins.z - 0.01
                || z - r > b.maxs.z + 0.01
        });
        if !clear {
            continue;
        }
        if !unblocking {
            return (x, z);
        }
        let score = occlusions(x, z);
        if score == (0, 0) {
            return (x, z);
        }
        if best.is_none_or(|(b, _)| score < b) {
            best = Some((score, (x, z)));
        }
    }
    best.map_or(last, |(_, spot)| spot)
}

/// Executes an action in the scene, settles the world and reports what the robot observes.
pub fn execute(
    scene: &mut Scene,
    action: &Action,
    config: &ActConfig,
) -> Result<ActionReport, SimError> {
    check(scene, action)?;
    let mut rng = SplitMix64::new(scene.seed).fork(ACTION_STREAM ^ ((scene.step as u64) << 32));
    let slipped = rng.chance(config.failure_rate);
    let world = World::build(scene);
    let failure = match action {
        Action::Pickup { object, .. } => {
            let id = scene.lookup(object)?;
            let covered = resting_on(scene, &world, id, &config.truth);
            if let Some(held) = scene.in_hand.clone() {
                Some(Failure::HandFull(held))
            } else if !covered.is_empty() {
                Some(Failure::Covered(covered))
            } else if slipped {
                Some(Failure::GraspSlipped)
            } else {
                scene.in_hand = Some(object.clone());
                None
            }
        }
        Action::Putdown {
            object,
            destination,
            ..
        } => {
            if scene.in_hand.as_deref() != Some(object.as_str()) {
                Some(Failure::NotHeld)
            } else {
                let id = scene.lookup(object)?;
                let o = scene.object(id);
                let shape = o.kind.shape(o.size);
                let local = shape.compute_local_aabb();
                let r = 0.5 * (local.maxs - local.mins).length();
                let yaw = rng.range_f32(-0.3, 0.3);
                let target = if destination == TABLE {
                    let spot = table_spot(&world, scene, r, (0.0, 0.0), true, &mut rng);
                    (spot.0, spot.1)
                } else {
                    let d = scene.lookup(destination)?;
                    let b = world.aabb(d).ok_or_else(|| {
                        SimError::ImpossibleAction(format!("{action}: the destination is held"))
                    })?;
                    (b.center().x, b.center().z)
                };
                let (x, z, failure) = if !slipped {
                    let (x, z) = target;
                    (
                        x + rng.range_f32(-0.004, 0.004),
                        z + rng.range_f32(-0.004, 0.004),
                        None,
                    )
                } else {
                    let (x, z) = table_spot(
                        &world,
                        scene,
                        r,
                        (target.0 + 0.12, target.1),
                        false,
                        &mut rng,
                    );
                    (x, z, Some(Failure::ReleaseSlipped))
                };
                // The lowest clear height over the footprint: the top of anything beneath it.
                let footprint = (
                    x - 0.5 * (local.maxs.x - local.mins.x),
                    x + 0.5 * (local.maxs.x - local.mins.x),
                );
                let depth = (
                    z - 0.5 * (local.maxs.z - local.mins.z),
                    z + 0.5 * (local.maxs.z - local.mins.z),
                );
                let floor = scene
                    .ids()
                    .filter_map(|i| world.aabb(i))
                    .filter(|b| {
                        b.mins.x < footprint.1
                            && b.maxs.x > footprint.0
                            && b.mins.z < depth.1
                            && b.maxs.z > depth.0
                    })
                    .map(|b| b.maxs.y)
                    .fold(0.0f32, f32::max);
                let pose = Pose::from_parts(
                    Vector::new(x, floor - local.mins.y + 0.002, z),
                    Rot3::from_rotation_y(yaw),
                );
                scene.objects[id.index()].set_pose(&pose);
                scene.in_hand = None;
                failure
            }
        }
    };
    let mut world = World::build(scene);
    world.settle(config.settle_seconds);
    world.write_back(scene);
    let step = scene.step;
    scene.step += 1;
    let percept = perceive_world(scene, &world, &config.perception, &config.truth);
    Ok(ActionReport {
        action: action.clone(),
        step,
        failure,
        percept,
    })
}
