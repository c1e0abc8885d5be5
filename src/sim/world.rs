//! The physics world: a rapier `PhysicsWorld` built from a `Scene`, stepped, and written back.
//!
//! Invariants: bodies are referred to only by rapier's generational `RigidBodyHandle`s (kept per
//! object and in a reverse map), never by raw arena indices; a held object has no body; the
//! table and a floor below it are fixed colliders without a movable body. Stepping is
//! deterministic for a given scene because bodies are inserted in scene order and rapier runs
//! single-threaded here.

use super::scene::{Scene, TABLE_HALF_EXTENTS};
use super::ObjectId;
use hashbrown::HashMap;
use parry3d::bounding_volume::Aabb;
use parry3d::math::{Pose, Vector};
use parry3d::query::{Ray, RayCast};
use rapier3d::prelude::{
    ColliderBuilder, ColliderHandle, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle,
};

/// The physics time step in seconds (120 Hz keeps 5 cm objects well resolved).
pub const TIME_STEP: f32 = 1.0 / 120.0;

/// Largest motion, in metres per half second, of a settled object.
pub const SETTLED_MOTION: f32 = 0.001;

/// Solver iterations per step: more than rapier's default 4, because towers on a small base
/// have mass ratios of 30 to 1, which sink into each other with fewer iterations.
pub const SOLVER_ITERATIONS: usize = 8;

/// Natural frequency in Hz of the soft contacts between bodies. rapier's default, 30 Hz, scales
/// the contact stiffness with the lighter body's mass, so four large cubes on a small one sink a
/// centimetre into it; 120 Hz keeps such penetration near a millimetre.
pub const CONTACT_FREQUENCY: f32 = 120.0;

/// Coefficient of rolling resistance of the objects that can roll (`ObjectKind::rolls`): the
/// resisting torque is this times the normal force times the radius, so a rolling body loses
/// angular speed at `ROLLING_RESISTANCE * g / radius` per second while it touches something.
/// [ours: rubber and plastic on wood lie in 0.005-0.03; 0.01 still let a lying can roll 34 mm
/// in a 2 s window after the world was rebuilt from the scene.] rapier has no
/// rolling resistance, and a can lying on its side on the bare table rolled 5-35 mm per 2 s
/// without it (its contacts inject a little rotation every step), so lying cans and bottles
/// never came to rest. A Coulomb-type resistance stops such creep yet cannot hold a body that
/// gravity turns harder (a toppling object, a ball on a slope).
pub const ROLLING_RESISTANCE: f32 = 0.02;

/// Gravity, in metres per second squared.
const GRAVITY: f32 = 9.81;

/// Height of the floor below the table top, in metres.
pub const FLOOR_DEPTH: f32 = 0.75;

/// What a ray or a contact hit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// A movable object.
    Object(ObjectId),
    /// The table top.
    Table,
    /// The floor around the table.
    Floor,
}

/// A rapier world mirroring one scene.
pub struct World {
    /// The rapier state: bodies, colliders, broad and narrow phase, solver.
    physics: PhysicsWorld,
    /// Per object of the scene, its body; `None` for the held object.
    bodies: Vec<Option<RigidBodyHandle>>,
    /// Per object of the scene, its collider; `None` for the held object.
    colliders: Vec<Option<ColliderHandle>>,
    /// Which object each collider belongs to (the table and floor are absent).
    owner: HashMap<ColliderHandle, ObjectId>,
    /// The table's fixed collider.
    table: ColliderHandle,
    /// Per body that can roll: its collider and the angular deceleration its rolling
    /// resistance gives while it touches something (radians per second squared).
    rolling: Vec<(RigidBodyHandle, ColliderHandle, f32)>,
    /// Every collider with its world bounding box, as of the last build or step; ray casts
    /// test these boxes first.
    boxes: Vec<(ColliderHandle, Aabb)>,
}

impl World {
    /// Builds the world for a scene: the table, the floor and one dynamic body per object that
    /// is not held.
    pub fn build(scene: &Scene) -> World {
        let mut physics = PhysicsWorld::new();
        physics.integration_parameters.dt = TIME_STEP;
        physics.integration_parameters.num_solver_iterations = SOLVER_ITERATIONS;
        physics
            .integration_parameters
            .contact_softness
            .natural_frequency = CONTACT_FREQUENCY;
        physics
            .integration_parameters
            .static_contact_softness
            .natural_frequency = 2.0 * CONTACT_FREQUENCY;
        let [hx, hy, hz] = TABLE_HALF_EXTENTS;
        let table = physics.insert_collider(
            ColliderBuilder::cuboid(hx, hy, hz)
                .translation(Vector::new(0.0, -hy, 0.0))
                .friction(0.8),
            None,
        );
        physics.insert_collider(
            ColliderBuilder::cuboid(4.0, 0.05, 4.0)
                .translation(Vector::new(0.0, -FLOOR_DEPTH - 0.05, 0.0))
                .friction(0.8),
            None,
        );
        let held = scene.held();
        let mut bodies = Vec::with_capacity(scene.objects.len());
        let mut colliders = Vec::with_capacity(scene.objects.len());
        let mut owner = HashMap::new();
        let mut rolling = Vec::new();
        for id in scene.ids() {
            if Some(id) == held {
                bodies.push(None);
                colliders.push(None);
                continue;
            }
            let object = scene.object(id);
            let body = RigidBodyBuilder::dynamic()
                .pose(object.pose())
                .linear_damping(0.1)
                .angular_damping(object.kind.rolling_damping())
                .ccd_enabled(true)
                .can_sleep(false);
            let collider = ColliderBuilder::new(object.kind.shape(object.size))
                .density(500.0)
                .friction(0.7)
                .restitution(0.0);
            let (b, c) = physics.insert(body, collider);
            if object.kind.rolls() {
                let radius = 0.5 * object.size.width();
                rolling.push((b, c, ROLLING_RESISTANCE * GRAVITY / radius));
            }
            bodies.push(Some(b));
            colliders.push(Some(c));
            owner.insert(c, id);
        }
        let mut world = World {
            physics,
            bodies,
            colliders,
            owner,
            table,
            rolling,
            boxes: Vec::new(),
        };
        world.refresh_boxes();
        world
    }

    /// Recomputes the cached bounding boxes after the bodies moved.
    fn refresh_boxes(&mut self) {
        self.boxes = self
            .physics
            .colliders
            .iter()
            .map(|(handle, collider)| (handle, collider.compute_aabb()))
            .collect();
    }

    /// Advances the simulation by whole time steps covering `seconds`.
    pub fn step_for(&mut self, seconds: f32) {
        let steps = (seconds / TIME_STEP).ceil() as usize;
        for _ in 0..steps {
            self.physics.step();
            self.resist_rolling();
        }
        self.refresh_boxes();
    }

    /// Applies one time step of rolling resistance (`ROLLING_RESISTANCE`): every body that can
    /// roll and touches something loses up to its deceleration times the step of angular
    /// speed, and stops turning if it had less.
    fn resist_rolling(&mut self) {
        for &(body, collider, deceleration) in &self.rolling {
            let touching = self
                .physics
                .contact_pairs_with(collider)
                .any(|pair| pair.has_any_active_contact());
            if !touching {
                continue;
            }
            let rb = &mut self.physics.bodies[body];
            let spin = rb.angvel();
            let speed = spin.length();
            let loss = deceleration * TIME_STEP;
            let slower = if speed <= loss {
                Vector::ZERO
            } else {
                spin * (1.0 - loss / speed)
            };
            rb.set_angvel(slower, false);
        }
    }

    /// Advances the simulation in half-second rounds until no object moved more than
    /// `SETTLED_MOTION` during a round, or `max_seconds` have passed; returns the simulated time
    /// spent. Bodies never sleep (a body put to sleep while balancing would look settled), so
    /// this is a test of motion, not of rapier's sleep state.
    pub fn settle(&mut self, max_seconds: f32) -> f32 {
        let round = 0.5;
        let mut spent = 0.0;
        while spent < max_seconds {
            let before: Vec<Option<Pose>> = (0..self.len())
                .map(|i| self.pose(ObjectId(i as u32)))
                .collect();
            self.step_for(round);
            spent += round;
            let moved = before.iter().enumerate().any(|(i, start)| {
                match (start, self.pose(ObjectId(i as u32))) {
                    (Some(a), Some(b)) => {
                        (a.translation - b.translation).length() > SETTLED_MOTION
                            || a.rotation.angle_between(b.rotation) > 10.0 * SETTLED_MOTION
                    }
                    _ => false,
                }
            });
            if !moved {
                break;
            }
        }
        spent
    }

    /// Copies body poses back into the scene.
    pub fn write_back(&self, scene: &mut Scene) {
        for id in scene.ids().collect::<Vec<_>>() {
            if let Some(pose) = self.pose(id) {
                scene.objects[id.index()].set_pose(&pose);
            }
        }
    }

    /// The current pose of an object, or `None` if it is held.
    pub fn pose(&self, id: ObjectId) -> Option<Pose> {
        self.bodies[id.index()].map(|b| *self.physics.bodies[b].position())
    }

    /// The world-space bounding box of an object, or `None` if it is held.
    pub fn aabb(&self, id: ObjectId) -> Option<Aabb> {
        self.colliders[id.index()].map(|c| self.physics.colliders[c].compute_aabb())
    }

    /// The shape and pose of an object, or `None` if it is held.
    pub fn shape(&self, id: ObjectId) -> Option<(&dyn parry3d::shape::Shape, Pose)> {
        self.colliders[id.index()].map(|c| {
            let collider = &self.physics.colliders[c];
            (collider.shape(), *collider.position())
        })
    }

    /// The table's shape and pose.
    pub fn table_shape(&self) -> (&dyn parry3d::shape::Shape, Pose) {
        let collider = &self.physics.colliders[self.table];
        (collider.shape(), *collider.position())
    }

    /// Classifies a collider.
    fn classify(&self, collider: ColliderHandle) -> Hit {
        match self.owner.get(&collider) {
            Some(&id) => Hit::Object(id),
            None if collider == self.table => Hit::Table,
            None => Hit::Floor,
        }
    }

    /// Casts a ray (unit direction) against everything; returns what it hits first, the distance
    /// and the surface normal.
    ///
    /// The colliders are tested one by one (their cached bounding boxes first): with at most a
    /// dozen colliders this is as fast as the broad phase, and it is valid right after `build`
    /// and after every step, without a broad-phase update in between.
    pub fn cast(&self, origin: Vector, dir: Vector, max: f32) -> Option<(Hit, f32, Vector)> {
        let ray = Ray::new(origin, dir);
        let mut best: Option<(ColliderHandle, f32, Vector)> = None;
        for &(handle, aabb) in &self.boxes {
            let limit = best.map_or(max, |b| b.1);
            if aabb.cast_local_ray(&ray, limit, true).is_none() {
                continue;
            }
            let collider = &self.physics.colliders[handle];
            if let Some(hit) =
                collider
                    .shape()
                    .cast_ray_and_get_normal(collider.position(), &ray, limit, true)
            {
                if best.is_none_or(|b| hit.time_of_impact < b.1) {
                    best = Some((handle, hit.time_of_impact, hit.normal));
                }
            }
        }
        best.map(|(c, t, n)| (self.classify(c), t, n))
    }

    /// Casts a ray against one object only; returns the distance to it.
    pub fn cast_at(&self, id: ObjectId, origin: Vector, dir: Vector, max: f32) -> Option<f32> {
        let (shape, pose) = self.shape(id)?;
        shape.cast_ray(&pose, &Ray::new(origin, dir), max, true)
    }

    /// The number of objects mirrored (held or not).
    pub fn len(&self) -> usize {
        self.bodies.len()
    }

    /// True if the scene had no objects.
    pub fn is_empty(&self) -> bool {
        self.bodies.is_empty()
    }
}
