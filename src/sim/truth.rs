//! Ground truth measured physically: spatial relations from geometry, stability by stepping a
//! copy of the world, and occlusion by ray casting from the camera.
//!
//! Relations (docs/domain.md §7.6), with A and B objects and the camera's axes taken parallel to
//! the table:
//! * `above(A, B)`: the footprints (x-z boxes) overlap and A's lowest point is at least B's
//!   mid-height while A's centre is above B's top; `below` is the converse.
//! * `front(A, B)`: A's depth interval ends before B's begins (within a tolerance) and their
//!   lateral intervals overlap, so A is between the camera and B in the image; `behind` is the
//!   converse.
//! * `left(A, B)`: A's lateral interval ends before B's begins; `right` is the converse.
//! * `touch`, `not_touch`, `far`: exclusive distance classes of the exact shape distance
//!   (parry): below `touch_distance`, up to `far_distance`, beyond it.
//! * `on(A, B)` = `above(A, B)` and `touch(A, B)`.
//! * With the table: every object over the table is `above` it (and the table `below` it);
//!   an object touching it is also `touch` and `on` it.
//!
//! Invariants: relations are computed from one world state and are deterministic; the held
//! object has no relations (lifting removes them, docs/domain.md C4).

use super::scene::{Scene, TABLE};
use super::world::{Hit, World};
use super::ObjectId;
use parry3d::bounding_volume::Aabb;
use parry3d::math::Vector;
use serde::{Deserialize, Serialize};
use std::fmt;

/// A spatial relation constant (the `spatial_rel` sort, without the reserved `in`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Rel {
    /// Higher, over an overlapping footprint.
    Above,
    /// The converse of `above`.
    Below,
    /// Nearer the camera, overlapping in the image.
    Front,
    /// The converse of `front`.
    Behind,
    /// To the camera's left.
    Left,
    /// To the camera's right.
    Right,
    /// In contact.
    Touch,
    /// Near but not in contact.
    NotTouch,
    /// Far apart.
    Far,
    /// Above and touching.
    On,
}

impl Rel {
    /// Every relation.
    pub const ALL: [Rel; 10] = [
        Rel::Above,
        Rel::Below,
        Rel::Front,
        Rel::Behind,
        Rel::Left,
        Rel::Right,
        Rel::Touch,
        Rel::NotTouch,
        Rel::Far,
        Rel::On,
    ];

    /// The constant used in `relation(S, A, B)`.
    pub fn name(self) -> &'static str {
        match self {
            Rel::Above => "above",
            Rel::Below => "below",
            Rel::Front => "front",
            Rel::Behind => "behind",
            Rel::Left => "left",
            Rel::Right => "right",
            Rel::Touch => "touch",
            Rel::NotTouch => "not_touch",
            Rel::Far => "far",
            Rel::On => "on",
        }
    }

    /// Parses a relation constant.
    pub fn parse(text: &str) -> Option<Rel> {
        Rel::ALL.into_iter().find(|r| r.name() == text)
    }
}

/// A ground relation literal `relation(rel, subject, object)` over location names.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub struct Relation {
    /// The relation.
    pub rel: Rel,
    /// The first location (an object name).
    pub a: String,
    /// The second location (an object name or `table`).
    pub b: String,
}

impl fmt::Display for Relation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "relation({},{},{})", self.rel.name(), self.a, self.b)
    }
}

/// Thresholds of the geometric relation and occlusion tests, in metres unless stated.
#[derive(Clone, Debug, PartialEq)]
pub struct TruthConfig {
    /// Shape distance below which two things touch.
    pub touch_distance: f32,
    /// Shape distance from which two objects are far apart.
    pub far_distance: f32,
    /// Allowed overlap of depth or lateral intervals for front/behind and left/right.
    pub interval_tolerance: f32,
    /// Minimal footprint overlap, in both x and z, for above/below.
    pub footprint_overlap: f32,
    /// Displacement beyond which an object counts as having moved (unstable).
    pub move_threshold: f32,
    /// Rotation in radians beyond which an object counts as having moved.
    pub turn_threshold: f32,
    /// Simulated seconds of the stability test.
    pub stability_seconds: f32,
    /// Occlusion samples per side of an object's image box.
    pub occlusion_grid: usize,
    /// Fraction of an object's visible samples another must hide to partially occlude it.
    pub occlusion_min: f32,
}

impl Default for TruthConfig {
    fn default() -> Self {
        TruthConfig {
            touch_distance: 0.004,
            far_distance: 0.25,
            interval_tolerance: 0.005,
            footprint_overlap: 0.005,
            move_threshold: 0.01,
            turn_threshold: 0.35,
            stability_seconds: 2.0,
            occlusion_grid: 20,
            occlusion_min: 0.02,
        }
    }
}

/// Geometry of one object used by the relation tests.
struct Extent {
    /// World bounding box.
    aabb: Aabb,
    /// Interval along the camera's depth axis (parallel to the table).
    depth: (f32, f32),
    /// Interval along the camera's right axis.
    lateral: (f32, f32),
}

fn interval(aabb: &Aabb, axis: Vector) -> (f32, f32) {
    let mut lo = f32::INFINITY;
    let mut hi = f32::NEG_INFINITY;
    for corner in aabb.vertices() {
        let d = corner.dot(axis);
        lo = lo.min(d);
        hi = hi.max(d);
    }
    (lo, hi)
}

fn overlap(a: (f32, f32), b: (f32, f32)) -> f32 {
    a.1.min(b.1) - a.0.max(b.0)
}

/// The exact distance between two objects' shapes, falling back to the boxes' gap if parry has
/// no algorithm for the pair.
fn distance(world: &World, a: ObjectId, b: ObjectId) -> f32 {
    let (sa, pa) = world
        .shape(a)
        .expect("only objects with bodies are compared");
    let (sb, pb) = world
        .shape(b)
        .expect("only objects with bodies are compared");
    match parry3d::query::distance(&pa, sa, &pb, sb) {
        Ok(d) => d.distance,
        Err(_) => aabb_gap(&world.aabb(a).unwrap(), &world.aabb(b).unwrap()),
    }
}

fn aabb_gap(a: &Aabb, b: &Aabb) -> f32 {
    let d = (a.mins - b.maxs).max(b.mins - a.maxs).max(Vector::ZERO);
    d.length()
}

/// The distance from an object to the table top.
pub fn table_distance(world: &World, a: ObjectId) -> f32 {
    let (sa, pa) = world
        .shape(a)
        .expect("only objects with bodies are compared");
    let (st, pt) = world.table_shape();
    match parry3d::query::distance(&pa, sa, &pt, st) {
        Ok(d) => d.distance,
        Err(_) => world.aabb(a).unwrap().mins.y.max(0.0),
    }
}

/// All relations that hold in the world, sorted.
pub fn relations(scene: &Scene, world: &World, config: &TruthConfig) -> Vec<Relation> {
    let camera = &scene.camera;
    let (depth_axis, right_axis) = (camera.depth_axis(), camera.right());
    let present: Vec<(ObjectId, Extent)> = scene
        .ids()
        .filter_map(|id| {
            let aabb = world.aabb(id)?;
            let depth = interval(&aabb, depth_axis);
            let lateral = interval(&aabb, right_axis);
            Some((
                id,
                Extent {
                    aabb,
                    depth,
                    lateral,
                },
            ))
        })
        .collect();
    let name = |id: ObjectId| scene.object(id).name.clone();
    let mut out = Vec::new();
    let mut push = |rel: Rel, a: String, b: String| out.push(Relation { rel, a, b });
    let [thx, _, thz] = super::scene::TABLE_HALF_EXTENTS;
    for (i, (a, ea)) in present.iter().enumerate() {
        let centre = ea.aabb.center();
        if centre.x.abs() <= thx && centre.z.abs() <= thz && ea.aabb.mins.y > -0.01 {
            push(Rel::Above, name(*a), TABLE.into());
            push(Rel::Below, TABLE.into(), name(*a));
            if table_distance(world, *a) < config.touch_distance {
                push(Rel::Touch, name(*a), TABLE.into());
                push(Rel::Touch, TABLE.into(), name(*a));
                push(Rel::On, name(*a), TABLE.into());
            }
        }
        for (b, eb) in &present[i + 1..] {
            let (na, nb) = (name(*a), name(*b));
            let d = distance(world, *a, *b);
            let dist_rel = if d < config.touch_distance {
                Rel::Touch
            } else if d < config.far_distance {
                Rel::NotTouch
            } else {
                Rel::Far
            };
            push(dist_rel, na.clone(), nb.clone());
            push(dist_rel, nb.clone(), na.clone());
            let footprint = overlap(
                (ea.aabb.mins.x, ea.aabb.maxs.x),
                (eb.aabb.mins.x, eb.aabb.maxs.x),
            )
            .min(overlap(
                (ea.aabb.mins.z, ea.aabb.maxs.z),
                (eb.aabb.mins.z, eb.aabb.maxs.z),
            ));
            let over = |top: &Extent, bottom: &Extent| {
                let mid = 0.5 * (bottom.aabb.mins.y + bottom.aabb.maxs.y);
                top.aabb.mins.y >= mid && top.aabb.center().y > bottom.aabb.maxs.y
            };
            let vertical = if footprint >= config.footprint_overlap {
                if over(ea, eb) {
                    Some((na.clone(), nb.clone()))
                } else if over(eb, ea) {
                    Some((nb.clone(), na.clone()))
                } else {
                    None
                }
            } else {
                None
            };
            if let Some((top, bottom)) = vertical {
                push(Rel::Above, top.clone(), bottom.clone());
                push(Rel::Below, bottom.clone(), top.clone());
                if dist_rel == Rel::Touch {
                    push(Rel::On, top, bottom);
                }
            }
            let tol = config.interval_tolerance;
            if overlap(ea.lateral, eb.lateral) > tol {
                if ea.depth.1 <= eb.depth.0 + tol {
                    push(Rel::Front, na.clone(), nb.clone());
                    push(Rel::Behind, nb.clone(), na.clone());
                } else if eb.depth.1 <= ea.depth.0 + tol {
                    push(Rel::Front, nb.clone(), na.clone());
                    push(Rel::Behind, na.clone(), nb.clone());
                }
            }
            if ea.lateral.1 <= eb.lateral.0 + tol {
                push(Rel::Left, na.clone(), nb.clone());
                push(Rel::Right, nb.clone(), na.clone());
            } else if eb.lateral.1 <= ea.lateral.0 + tol {
                push(Rel::Left, nb.clone(), na.clone());
                push(Rel::Right, na.clone(), nb.clone());
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

/// The outcome of the stability test for one object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Stability {
    /// The object's name.
    pub name: String,
    /// How far its origin moved during the test, in metres.
    pub displacement: f32,
    /// How far it turned, in radians.
    pub rotation: f32,
    /// True if it moved less than both thresholds.
    pub stable: bool,
}

/// Steps a copy of the scene's world for `stability_seconds` and reports how far each object
/// that is not held moved. The scene itself is unchanged.
pub fn stability(scene: &Scene, config: &TruthConfig) -> Vec<Stability> {
    let mut world = World::build(scene);
    let before: Vec<_> = scene.ids().map(|id| world.pose(id)).collect();
    world.step_for(config.stability_seconds);
    scene
        .ids()
        .filter_map(|id| {
            let start = before[id.index()]?;
            let end = world.pose(id)?;
            let displacement = (end.translation - start.translation).length();
            let rotation = start.rotation.angle_between(end.rotation);
            Some(Stability {
                name: scene.object(id).name.clone(),
                displacement,
                rotation,
                stable: displacement < config.move_threshold && rotation < config.turn_threshold,
            })
        })
        .collect()
}

/// How much of one object the camera cannot see.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Occlusion {
    /// The object's name.
    pub name: String,
    /// Fraction of the rays that reach the object's surface when alone but are stopped earlier
    /// by another object.
    pub hidden: f32,
    /// The objects hiding at least `occlusion_min` of it, with the fraction each hides.
    pub by: Vec<(String, f32)>,
}

/// Maps a world point to normalised image coordinates (u right, v down, both in [0, 1] inside
/// the frame), or `None` if it is behind the camera.
pub fn project(scene: &Scene, point: Vector, aspect: f32) -> Option<(f32, f32)> {
    let c = &scene.camera;
    let rel = point - c.eye();
    let z = rel.dot(c.forward());
    if z <= 1e-6 {
        return None;
    }
    let half = (c.fov_y_degrees.to_radians() * 0.5).tan();
    let x = rel.dot(c.right()) / (z * half * aspect);
    let y = rel.dot(c.up()) / (z * half);
    Some((0.5 * (x + 1.0), 0.5 * (1.0 - y)))
}

/// The unit ray direction through normalised image coordinates (u, v).
pub fn pixel_ray(scene: &Scene, u: f32, v: f32, aspect: f32) -> Vector {
    let c = &scene.camera;
    let half = (c.fov_y_degrees.to_radians() * 0.5).tan();
    let x = (2.0 * u - 1.0) * half * aspect;
    let y = (1.0 - 2.0 * v) * half;
    (c.forward() + c.right() * x + c.up() * y).normalize()
}

/// Measures occlusion of every object that is not held, from the camera, by ray casting: a grid
/// of rays over the object's image box; rays that hit the object when it is cast alone are its
/// visible surface, and those whose first hit in the whole world is another object are hidden.
pub fn occlusion(scene: &Scene, world: &World, config: &TruthConfig) -> Vec<Occlusion> {
    let eye = scene.camera.eye();
    let n = config.occlusion_grid.max(2);
    scene
        .ids()
        .filter_map(|id| {
            let aabb = world.aabb(id)?;
            let (mut u0, mut v0, mut u1, mut v1) = (f32::MAX, f32::MAX, f32::MIN, f32::MIN);
            for corner in aabb.vertices() {
                let (u, v) = project(scene, corner, 1.0)?;
                u0 = u0.min(u);
                v0 = v0.min(v);
                u1 = u1.max(u);
                v1 = v1.max(v);
            }
            let mut seen = 0usize;
            let mut hidden_by = vec![0usize; scene.objects.len()];
            for i in 0..n {
                for j in 0..n {
                    let u = u0 + (u1 - u0) * (i as f32 + 0.5) / n as f32;
                    let v = v0 + (v1 - v0) * (j as f32 + 0.5) / n as f32;
                    let dir = pixel_ray(scene, u, v, 1.0);
                    let Some(t_self) = world.cast_at(id, eye, dir, 10.0) else {
                        continue;
                    };
                    seen += 1;
                    if let Some((Hit::Object(other), t, _)) = world.cast(eye, dir, 10.0) {
                        if other != id && t < t_self {
                            hidden_by[other.index()] += 1;
                        }
                    }
                }
            }
            let total = seen.max(1) as f32;
            let hidden = hidden_by.iter().sum::<usize>() as f32 / total;
            let by = hidden_by
                .iter()
                .enumerate()
                .filter(|(_, &k)| k as f32 / total >= config.occlusion_min)
                .map(|(o, &k)| (scene.objects[o].name.clone(), k as f32 / total))
                .collect();
            Some(Occlusion {
                name: scene.object(id).name.clone(),
                hidden,
                by,
            })
        })
        .collect()
}

/// Everything measured about one scene state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct GroundTruth {
    /// The relations that hold, sorted.
    pub relations: Vec<Relation>,
    /// Per object, the stability test.
    pub stability: Vec<Stability>,
    /// Per object, the occlusion measure.
    pub occlusion: Vec<Occlusion>,
}

/// Measures relations, stability and occlusion of a scene as it stands.
pub fn measure(scene: &Scene, config: &TruthConfig) -> GroundTruth {
    let world = World::build(scene);
    GroundTruth {
        relations: relations(scene, &world, config),
        stability: stability(scene, config),
        occlusion: occlusion(scene, &world, config),
    }
}
