//! Ground-truth labels from physics, per object: **stable** and **occluded**.
//!
//! * **stable**: the object moves less than `move_threshold` and turns less than
//!   `turn_threshold` when the scene is simulated untouched for `stability_seconds`
//!   (`sim::truth::stability` on a fresh world of the scene as given).
//! * **occluded**: measured in the *frontal view*, an orthographic view along the camera's depth
//!   axis parallel to the table (`Camera::depth_axis`, lateral axis `Camera::right`, vertical =
//!   world Y). A `grid x grid` lattice of rays covers the object's frontal silhouette box (its
//!   bounding box projected on the lateral and vertical axes), each ray starting in front of the
//!   whole scene and travelling along +depth. The rays that hit the object when it is cast alone
//!   (`World::cast_at`) are its silhouette; of those, the ones whose first hit in the whole world
//!   (`World::cast`) is another object, nearer, are hidden by that object. `hidden` =
//!   hidden / silhouette, `occluded` = `hidden > occlusion_threshold`, and `occluders` lists the
//!   objects hiding at least `occluder_min` of it with their fraction.
//!
//! Why the frontal view rather than the camera's: the domain's `front`/`behind` relations, which
//! the reasoner uses to explain occlusion, are defined along the same depth axis, parallel to the
//! table. In that view an object stacked on another never "occludes" it: the two occupy
//! different heights. A camera looking down at a stack would instead see the lower object's top
//! face covered by the upper one and call it occluded, although nothing stands in front of it.
//!
//! Invariants: labels are a deterministic function of the scene and the configuration; a held
//! object (not in the physics) is labelled stable, with no displacement and nothing hidden.

use crate::sim::object::{Size, Surface};
use crate::sim::scene::TABLE;
use crate::sim::truth::{stability, Rel, Relation, TruthConfig};
use crate::sim::world::Hit;
use crate::sim::{ObjectId, Scene, World};
use parry3d::math::Vector;
use serde::{Deserialize, Serialize};

/// Thresholds and resolution of the labels.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LabelConfig {
    /// Simulated seconds of the stability test.
    pub stability_seconds: f32,
    /// Displacement in metres from which an object is unstable.
    pub move_threshold: f32,
    /// Rotation in radians from which an object is unstable.
    pub turn_threshold: f32,
    /// Hidden fraction above which an object is occluded.
    pub occlusion_threshold: f32,
    /// Smallest hidden fraction for which another object is listed as an occluder.
    pub occluder_min: f32,
    /// Rays per side of the frontal silhouette box.
    pub grid: usize,
}

impl Default for LabelConfig {
    /// 3 s of simulation, 2 cm, 0.35 rad; occluded above 20% hidden, occluders from 2%; 24 x 24
    /// rays.
    fn default() -> Self {
        LabelConfig {
            stability_seconds: 3.0,
            move_threshold: 0.02,
            turn_threshold: 0.35,
            occlusion_threshold: 0.2,
            occluder_min: 0.02,
            grid: 24,
        }
    }
}

impl LabelConfig {
    /// The truth configuration of the stability test: these thresholds and duration, the other
    /// fields at their defaults.
    pub fn truth(&self) -> TruthConfig {
        TruthConfig {
            move_threshold: self.move_threshold,
            turn_threshold: self.turn_threshold,
            stability_seconds: self.stability_seconds,
            ..TruthConfig::default()
        }
    }
}

/// The labels of one object.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ObjectLabels {
    /// The object's name.
    pub name: String,
    /// True if it stays put when the scene is left alone.
    pub stable: bool,
    /// How far its origin moved during the stability test, in metres.
    pub displacement: f32,
    /// True if more than `occlusion_threshold` of its frontal silhouette is hidden.
    pub occluded: bool,
    /// Fraction of its frontal silhouette hidden by other objects.
    pub hidden: f32,
    /// The objects hiding at least `occluder_min` of it, with the fraction each hides, in scene
    /// order.
    pub occluders: Vec<(String, f32)>,
}

/// The frontal-view occlusion of one object.
#[derive(Clone, Debug, PartialEq)]
pub struct Frontal {
    /// Rays of the lattice that hit the object alone.
    pub silhouette: usize,
    /// Per object of the scene, how many of those rays it stops first.
    pub hidden_by: Vec<usize>,
}

impl Frontal {
    /// Fraction of the silhouette hidden (0 for an empty silhouette).
    pub fn hidden(&self) -> f32 {
        self.hidden_by.iter().sum::<usize>() as f32 / self.silhouette.max(1) as f32
    }
}

/// Measures the frontal-view occlusion of one object (see the module documentation), or `None`
/// if it is held.
pub fn frontal(scene: &Scene, world: &World, id: ObjectId, grid: usize) -> Option<Frontal> {
    let (depth, right) = (scene.camera.depth_axis(), scene.camera.right());
    let aabb = world.aabb(id)?;
    let span = |axis: Vector, b: &parry3d::bounding_volume::Aabb| {
        b.vertices()
            .iter()
            .map(|c| c.dot(axis))
            .fold((f32::INFINITY, f32::NEG_INFINITY), |(lo, hi), d| {
                (lo.min(d), hi.max(d))
            })
    };
    // Start every ray 10 cm in front of the nearest object, run it 10 cm past the farthest.
    let (mut near, mut far) = (f32::INFINITY, f32::NEG_INFINITY);
    for other in scene.ids() {
        if let Some(b) = world.aabb(other) {
            let (lo, hi) = span(depth, &b);
            near = near.min(lo);
            far = far.max(hi);
        }
    }
    let start = near - 0.1;
    let reach = far - start + 0.1;
    let (l0, l1) = span(right, &aabb);
    let (y0, y1) = (aabb.mins.y, aabb.maxs.y);
    let n = grid.max(1);
    let mut out = Frontal {
        silhouette: 0,
        hidden_by: vec![0; scene.objects.len()],
    };
    for i in 0..n {
        let lateral = l0 + (l1 - l0) * (i as f32 + 0.5) / n as f32;
        for j in 0..n {
            let height = y0 + (y1 - y0) * (j as f32 + 0.5) / n as f32;
            let origin = right * lateral + Vector::Y * height + depth * start;
            let Some(t_self) = world.cast_at(id, origin, depth, reach) else {
                continue;
            };
            out.silhouette += 1;
            if let Some((Hit::Object(other), t, _)) = world.cast(origin, depth, reach) {
                if other != id && t < t_self {
                    out.hidden_by[other.index()] += 1;
                }
            }
        }
    }
    Some(out)
}

/// The labels of every object, in scene order.
pub fn label(scene: &Scene, config: &LabelConfig) -> Vec<ObjectLabels> {
    label_world(scene, &World::build(scene), config)
}

/// The labels of every object, in scene order, with the scene's world already built (as placed,
/// not stepped); the stability test still steps a world of its own.
pub fn label_world(scene: &Scene, world: &World, config: &LabelConfig) -> Vec<ObjectLabels> {
    let moved = stability(scene, &config.truth());
    scene
        .ids()
        .map(|id| {
            let name = scene.object(id).name.clone();
            let (stable, displacement) = moved
                .iter()
                .find(|s| s.name == name)
                .map_or((true, 0.0), |s| (s.stable, s.displacement));
            let (hidden, occluders) = match frontal(scene, world, id, config.grid) {
                None => (0.0, Vec::new()),
                Some(f) => {
                    let total = f.silhouette.max(1) as f32;
                    let by = f
                        .hidden_by
                        .iter()
                        .enumerate()
                        .map(|(o, &k)| (o, k as f32 / total))
                        .filter(|&(_, share)| share > 0.0 && share >= config.occluder_min)
                        .map(|(o, share)| (scene.objects[o].name.clone(), share))
                        .collect();
                    (f.hidden(), by)
                }
            };
            ObjectLabels {
                name,
                stable,
                displacement,
                occluded: hidden > config.occlusion_threshold,
                hidden,
                occluders,
            }
        })
        .collect()
}

/// What a stacked object stands on, judged by the riskiest support below it in its tower: a
/// tower falls from its risky support up, so everything above that support shares its fate.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Footing {
    /// Not stacked: it stands on the table.
    Table,
    /// Some support below it has an irregular top.
    Irregular,
    /// Some support below it is a small flat object (and none is irregular).
    Small,
    /// Every support below it is a medium or large flat object.
    Flat,
}

impl Footing {
    /// The category's name in reports.
    pub fn name(self) -> &'static str {
        match self {
            Footing::Table => "table",
            Footing::Irregular => "on irregular",
            Footing::Small => "on small support",
            Footing::Flat => "on medium/large flat",
        }
    }
}

/// Per object, the objects below it in its tower, nearest first: those reached from it by
/// following `on(A, B)` relations down to the table (breadth first; ties by scene order).
pub fn supports(scene: &Scene, relations: &[Relation]) -> Vec<Vec<ObjectId>> {
    let under: Vec<Vec<ObjectId>> = scene
        .ids()
        .map(|id| {
            let name = &scene.object(id).name;
            let mut below: Vec<ObjectId> = relations
                .iter()
                .filter(|r| r.rel == Rel::On && &r.a == name && r.b != TABLE)
                .filter_map(|r| scene.find(&r.b))
                .collect();
            below.sort();
            below
        })
        .collect();
    scene
        .ids()
        .map(|id| {
            let mut chain: Vec<ObjectId> = Vec::new();
            let mut frontier = vec![id];
            while !frontier.is_empty() {
                let mut next = Vec::new();
                for o in frontier {
                    for &b in &under[o.index()] {
                        if b != id && !chain.contains(&b) && !next.contains(&b) {
                            next.push(b);
                        }
                    }
                }
                next.sort();
                chain.extend(&next);
                frontier = next;
            }
            chain
        })
        .collect()
}

/// The footing of an object whose supports (from [`supports`]) are given.
pub fn footing(scene: &Scene, supports: &[ObjectId]) -> Footing {
    if supports.is_empty() {
        Footing::Table
    } else if supports
        .iter()
        .any(|&s| scene.object(s).surface() == Surface::Irregular)
    {
        Footing::Irregular
    } else if supports
        .iter()
        .any(|&s| scene.object(s).size == Size::Small)
    {
        Footing::Small
    } else {
        Footing::Flat
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{Colour, ObjectKind, Size};

    /// The default camera looks along +z (depth axis) with its right along -x.
    fn two_cubes(front_size: Size, shift: f32) -> Scene {
        let mut scene = Scene::custom(1);
        scene.add_resting(
            "back",
            ObjectKind::Cube,
            Colour::Red,
            Size::Medium,
            (0.0, 0.0, 0.15),
        );
        scene.add_resting(
            "front",
            ObjectKind::Cube,
            Colour::Blue,
            front_size,
            (shift, 0.0, -0.05),
        );
        scene
    }

    #[test]
    fn half_hidden_by_a_cube_shifted_half_a_width() {
        // Same size, shifted by half a width: the front cube covers exactly the 12 of 24 lattice
        // columns on its side and every row, so half the back cube is hidden.
        let scene = two_cubes(Size::Medium, 0.0375);
        let labels = label(&scene, &LabelConfig::default());
        assert_eq!(labels[0].name, "back");
        assert!((labels[0].hidden - 0.5).abs() < 1e-6, "{:?}", labels[0]);
        assert!(labels[0].occluded);
        assert_eq!(labels[0].occluders.len(), 1);
        assert_eq!(labels[0].occluders[0].0, "front");
        assert!((labels[0].occluders[0].1 - 0.5).abs() < 1e-6);
        assert_eq!(labels[1].hidden, 0.0);
        assert!(!labels[1].occluded && labels[1].occluders.is_empty());
        assert!(labels.iter().all(|l| l.stable), "{labels:?}");
    }

    #[test]
    fn small_cube_centred_in_front_hides_four_ninths() {
        // The back cube is 7.5 cm wide, the front one 5 cm: the lattice step is 7.5/24 cm, the
        // front cube covers columns 4..=19 and rows 0..=15 (16 x 16 of 24 x 24 rays) = 4/9.
        let scene = two_cubes(Size::Small, 0.0);
        let labels = label(&scene, &LabelConfig::default());
        assert!(
            (labels[0].hidden - 4.0 / 9.0).abs() < 1e-6,
            "{:?}",
            labels[0]
        );
        // Shifted sideways by its own width plus the back cube's half width, it hides nothing.
        let apart = label(
            &two_cubes(Size::Small, 0.0625 + 0.001),
            &LabelConfig::default(),
        );
        assert_eq!(apart[0].hidden, 0.0);
        assert!(!apart[0].occluded);
    }

    #[test]
    fn stacked_cube_does_not_occlude_its_support() {
        let mut scene = Scene::custom(2);
        scene.add_resting(
            "base",
            ObjectKind::Cube,
            Colour::Red,
            Size::Large,
            (0.0, 0.0, 0.1),
        );
        scene.add_resting(
            "top",
            ObjectKind::Cube,
            Colour::Blue,
            Size::Medium,
            (0.0, 0.1, 0.1),
        );
        let labels = label(&scene, &LabelConfig::default());
        assert!(
            labels.iter().all(|l| l.hidden == 0.0 && l.stable),
            "{labels:?}"
        );
    }

    #[test]
    fn cube_on_a_ball_is_unstable() {
        let mut scene = Scene::custom(3);
        scene.add_resting(
            "ball",
            ObjectKind::Ball,
            Colour::Yellow,
            Size::Medium,
            (0.0, 0.0, 0.1),
        );
        // 5 mm off the ball's top: a perfectly centred cube would balance in the simulation.
        scene.add_resting(
            "cube",
            ObjectKind::Cube,
            Colour::Red,
            Size::Small,
            (0.005, 0.075, 0.1),
        );
        let labels = label(&scene, &LabelConfig::default());
        assert!(!labels[1].stable, "{:?}", labels[1]);
        assert!(labels[1].displacement >= 0.02);
    }

    #[test]
    fn cube_centred_on_a_large_cube_is_stable() {
        let mut scene = Scene::custom(4);
        scene.add_resting(
            "base",
            ObjectKind::Cube,
            Colour::Green,
            Size::Large,
            (0.1, 0.0, 0.0),
        );
        scene.add_resting(
            "top",
            ObjectKind::Cube,
            Colour::Red,
            Size::Medium,
            (0.105, 0.1, 0.0),
        );
        let labels = label(&scene, &LabelConfig::default());
        assert!(labels.iter().all(|l| l.stable), "{labels:?}");
        assert!(labels[1].displacement < 0.005);
    }
}
