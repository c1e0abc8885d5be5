//! The tabletop world (issue 5): a rapier3d/parry3d simulation of the robot's scenes, with
//! physically measured ground truth, noisy perception in the domain's vocabulary, physical
//! actuation, pictures, and JSON scene files.
//!
//! Pipeline: `generate` builds and settles a `Scene` from a seed; `World` mirrors a scene in
//! rapier; `truth` measures relations, stability and occlusion; `perceive` turns them into
//! observations through an error model; `act` executes `pickup`/`putdown` and reports what is
//! observed afterwards; `render` draws the camera and top views; `picture` frames and labels the camera view for people.
//!
//! Versions and math types: rapier3d is pinned to exactly 0.36.1 and parry3d to 0.31.1 (the
//! parry version that rapier uses, so shapes and poses pass between them unchanged). Since
//! rapier 0.32 the public math types are glam's, through `glamx`, not nalgebra's: in `f32` 3D,
//! `Vector` = `glam::Vec3`, `Rotation` = `Rot3` = `glam::Quat`, and `Pose` = `glamx::Pose3`
//! (a struct with public `rotation: Quat` and `translation: Vec3`; it replaced nalgebra's
//! `Isometry3`). Rays, AABBs and shapes come from parry3d with these same types. This module
//! exposes only `Pose`, `Vector` and `Aabb` from them; scene files store plain `[f32; 3]`
//! positions and `[x, y, z, w]` quaternions so they do not depend on the math library.
//!
//! Invariants: everything random is drawn from seeded SplitMix64 streams, so a seed determines
//! the scene, its observations and the outcome of its actions; bodies are addressed through
//! rapier's generational handles only; the library does no file I/O (the `lucent sim` command in
//! `cli` does).

pub(crate) mod act;
pub mod generate;
pub(crate) mod object;
pub mod perceive;
pub(crate) mod picture;
pub(crate) mod render;
pub(crate) mod scene;
pub mod truth;
pub(crate) mod world;

pub use crate::base::rng::SplitMix64;
pub use act::{execute, ActConfig, Action, ActionReport, Failure};
pub use generate::{generate, generate_many, GenerateConfig, Preset};
pub use object::{Colour, ObjectKind, Size, Surface};
pub use perceive::{
    perceive, perceive_look, perceive_world, ErrorModel, FactStyle, Literal, Observation, Percept,
};
pub use picture::{picture, Picture};
pub use render::{render_camera, render_top, Image};
pub use scene::{Camera, ObjectId, Scene, SceneObject, ROBOT, TABLE};
pub use truth::{measure, GroundTruth, Rel, Relation, TruthConfig};
pub use world::World;

/// Operational errors of the simulator: bad input, never a failed action (that is an
/// observation, see `act`).
#[derive(Debug, thiserror::Error, Clone, PartialEq, Eq)]
pub enum SimError {
    /// A name that is no object of the scene.
    #[error("unknown object `{0}`")]
    UnknownObject(String),
    /// A robot other than the scene's.
    #[error("unknown robot `{0}`")]
    UnknownRobot(String),
    /// A preset name that does not exist.
    #[error("unknown preset `{0}` (expected real, simulated or h1)")]
    UnknownPreset(String),
    /// An object count outside 5 to 9.
    #[error("a scene has 5 to 9 objects (the h1 preset at most 8), not {0}")]
    BadCount(usize),
    /// Text that is not `pickup(R,O)` or `putdown(R,O,L)`.
    #[error("malformed action `{0}` (expected pickup(R,O) or putdown(R,O,L))")]
    MalformedAction(String),
    /// An action that makes no sense in any state, such as putting an object on itself.
    #[error("impossible action {0}")]
    ImpossibleAction(String),
    /// A scene file that does not parse or breaks a scene invariant.
    #[error("malformed scene: {0}")]
    MalformedScene(String),
    /// The PNG encoder failed.
    #[error("cannot encode the image: {0}")]
    Render(String),
}
