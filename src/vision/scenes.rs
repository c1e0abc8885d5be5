//! Risky scenes from a seed: more objects and taller, riskier towers than `sim::generate`, as
//! placed, for labelling stability and occlusion.
//!
//! A scene has 6 to 9 objects (preset `Real` 6 to 8, `Simulated` 7 to 9), of which 3 to 7 stand
//! in 1 to 3 towers of height 2 to 4 (table level counted as 1: a tower of height 2 is a base and
//! one object on it); the rest are spread on the table, each with free space around it (a disc
//! bounding its footprint at any yaw, at least 1 cm from every other disc when there is room), so
//! objects on the table never touch each other. Kinds, colours and sizes come from the presets'
//! families (`Real`: cubes as the flat kind, a ball, fruit, a pig, a pot; `Simulated`: cubes,
//! cans and boxes as flat kinds, a ball, a duck, an apple, a pitcher, a bottle, a mug) and from
//! `sim::generate`'s plausible colours and sizes per kind.
//!
//! The scene is NOT settled: it is the configuration as placed, which the camera sees; physics
//! then decides whether it stays put (`labels`). Placement rule (the world's design):
//! - towers are built bottom up; each support below a tower's top is a flat-topped object (cube,
//!   can, box), except the irregular base of an "irregular" tower (below);
//! - an object placed on a **small** support lands off-centre: its centre is displaced from the
//!   support's centre by a distance drawn uniformly between 1.1 and 1.5 times the support's
//!   half-width (a small top is too narrow to centre anything on), in a random horizontal
//!   direction; the half-width is measured along that direction, from the centre of the
//!   support's top face to its edge (half the side towards a cube's face, up to `sqrt(2)` times
//!   that towards a corner; the radius of a can), so the carried object's centre of mass is
//!   always outside the support;
//! - an object placed on a **medium or large flat** support is placed within 1 cm of the
//!   support's centre (uniform in a disk of radius 0.01 m), and towers keep the rule "a support
//!   is at least as wide as what it carries" (by size class) for medium/large supports;
//! - an object placed on an **irregular** object (ball, apple, orange, pig, duck) is placed
//!   within 1 cm of its centre, resting on the support's top;
//! - about 1/3 of towers have an irregular object below the top, about 1/3 have a small support,
//!   the rest are safe (every support medium/large flat); a risky tower has exactly one risky
//!   support, **its base**, and every support above it is medium/large flat;
//! - a can carries no object standing on a cylinder's flat end (can, bottle, mug, pitcher, pot);
//! - every object rests exactly on what is below it, no gap: its resting height is found by
//!   casting its shape straight down (parry's `cast_shapes`) onto the objects already in the
//!   tower (or the table), then lifting it out of any overlap parry's `distance` still finds,
//!   so its lowest point touches the highest point under it; it is then
//!   sunk by [`SINK`] = 0.1 mm into it. The sinking is far below rapier's allowed penetration
//!   (1 mm), so the physics sees a resting contact; it is there for `sim::truth`'s `touch`:
//!   parry 0.31.1's cuboid-cuboid distance is wrong for *separated* boxes in some relative poses
//!   (those whose rotation has `-0.0` components, as an inverted yaw has): a cube touching
//!   another within 1e-7 m, or a duck's foot plate on a cube, measured 5 mm apart, and `on` was
//!   lost; interpenetrating shapes measure 0 whatever the pose.
//!
//! Measured (`measure::physics_rates_per_footing`, 300 scenes per preset, `labels`' defaults),
//! with [`Footing`] as the category: with this rule, stacked objects on an irregular support are
//! unstable in 99.2% (Real, 249 objects) and 98.4% (Simulated, 305), on a small support in 100%
//! (256, 278), and on medium/large flat supports stable in 98.7% (317) and 99.4% (329). The rule
//! as first specified (half-width = half the side, risky support anywhere below the top, every
//! irregular kind and every flat kind as supports) gave 85%/82% (irregular), 83%/89% (small) and
//! 97.0%/88.9% (flat). The changes and why:
//! - half-width along the displacement direction: towards a cube's corner its top reaches
//!   `sqrt(2)` half-sides, so 1.1-1.5 half-sides left the centre of mass over a yawed small cube
//!   in 18-23% of the placements, and those stayed put;
//! - no vessels (mug, pitcher, pot) as supports: their rim holds what is wider than the opening
//!   and what is narrower drops onto the flat body inside (all 18 objects put on a medium pot
//!   stayed); no bottle or capsicum either: their cap and stem are flat discs of 4-8 mm radius,
//!   on which the simulation balances an object centred within 1 cm (a bottle held 8 of 47, a
//!   medium capsicum 5 of 17);
//! - the risky support is the tower's base: when a risky support carries a toppling object, the
//!   fall pushes the risky support and whatever is under it (a ball on a cube rolls off it, a
//!   small cube slides): 27 of the 31 unstable objects on medium/large flat supports (of 834)
//!   lay under a toppling object, with nothing wrong under them;
//! - a can carries no cylinder-ended object: rapier's cylinder-on-cylinder contact rocks (a
//!   medium can centred on a medium can fell in 6 of 20 trials, a pitcher on a can in 13 of 20),
//!   while a can under a cube or a ball and a can on a cube hold (100 of 100 each).
//!
//! Invariants: the same `(preset, seed, count)` gives the same scene, bit for bit (one SplitMix64
//! stream seeded with the seed); objects are listed tower by tower, bottom up, then the loose
//! ones; names are `colour_kind`, with `_2`, `_3`, ... for repeats.

use crate::base::rng::SplitMix64;
use crate::sim::generate::{colours, sizes};
use crate::sim::object::{Colour, ObjectKind, Size, Surface};
use crate::sim::scene::{Scene, SceneObject, TABLE};
use crate::sim::truth::{Rel, Relation};
use crate::sim::{ObjectId, Preset, SimError};
use parry3d::bounding_volume::BoundingVolume;
use parry3d::math::{Pose, Rot3, Vector};
use parry3d::query::Ray;
use parry3d::shape::SharedShape;
use serde::{Deserialize, Serialize};

/// What to generate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RiskyConfig {
    /// The family of objects: `Preset::Real` or `Preset::Simulated` (`H1` is refused).
    pub preset: Preset,
    /// The seed of every random choice.
    pub seed: u64,
    /// The number of objects, 6 to 9; `None` draws it from the preset's range.
    pub count: Option<usize>,
}

impl RiskyConfig {
    /// A configuration drawing the object count from the preset's range.
    pub fn new(preset: Preset, seed: u64) -> Self {
        RiskyConfig {
            preset,
            seed,
            count: None,
        }
    }
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

/// The kinds of a preset.
struct Family {
    /// Flat-topped kinds.
    flat: &'static [ObjectKind],
    /// Irregular kinds that may support something (no vessels, see the module doc).
    supports: &'static [ObjectKind],
    /// Every kind of the preset.
    all: &'static [ObjectKind],
}

fn family(preset: Preset) -> Result<Family, SimError> {
    use ObjectKind::*;
    match preset {
        Preset::Real => Ok(Family {
            flat: &[Cube],
            supports: &[Ball, Apple, Orange, Pig],
            all: &[Cube, Ball, Apple, Orange, Capsicum, Pig, Pot],
        }),
        Preset::Simulated => Ok(Family {
            flat: &[Cube, Can, Box],
            supports: &[Ball, Duck, Apple],
            all: &[
                Cube, Can, Box, Ball, Duck, Apple, Pitcher, Bottle, Mug, Box, Cube, Can,
            ],
        }),
        Preset::H1 => Err(SimError::UnknownPreset(
            "h1 (risky scenes are real or simulated)".into(),
        )),
    }
}

/// The risk a tower is built with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Risk {
    /// Every support medium/large flat.
    Safe,
    /// One support irregular.
    Irregular,
    /// One support small and flat.
    Small,
}

/// An object placed in local tower coordinates (x, z relative to the tower's axis).
struct Placed {
    kind: ObjectKind,
    colour: Colour,
    size: Size,
    position: Vector,
    rotation: Rot3,
}

impl Placed {
    fn shape(&self) -> SharedShape {
        self.kind.shape(self.size)
    }

    fn pose(&self) -> Pose {
        Pose::from_parts(self.position, self.rotation)
    }
}

/// True for the kinds standing on a cylinder's flat end (can, bottle and the vessels), which a
/// can does not carry (see the module documentation).
fn cylinder_based(kind: ObjectKind) -> bool {
    matches!(
        kind,
        ObjectKind::Can
            | ObjectKind::Bottle
            | ObjectKind::Mug
            | ObjectKind::Pitcher
            | ObjectKind::Pot
    )
}

/// Radius of a disc around the origin that holds the object's footprint at any yaw.
fn footprint_radius(kind: ObjectKind, size: Size) -> f32 {
    let aabb = kind.shape(size).compute_local_aabb();
    let (x, z) = (
        aabb.mins.x.abs().max(aabb.maxs.x.abs()),
        aabb.mins.z.abs().max(aabb.maxs.z.abs()),
    );
    (x * x + z * z).sqrt()
}

/// A uniformly drawn kind among `kinds` that has a size allowed by `allowed`, and a size of it
/// drawn from `sizes(kind)` (with its multiplicities) among the allowed ones.
fn draw(
    rng: &mut SplitMix64,
    kinds: &[ObjectKind],
    allowed: impl Fn(Size) -> bool,
) -> (ObjectKind, Size) {
    let usable: Vec<ObjectKind> = kinds
        .iter()
        .copied()
        .filter(|&k| sizes(k).iter().any(|&s| allowed(s)))
        .collect();
    assert!(!usable.is_empty(), "every draw has a kind of some size");
    let kind = *rng.pick(&usable);
    let fitting: Vec<Size> = sizes(kind)
        .iter()
        .copied()
        .filter(|&s| allowed(s))
        .collect();
    (kind, *rng.pick(&fitting))
}

/// Splits `stacked` objects into 1 to 3 towers of height 2 to 4.
fn tower_heights(stacked: usize, rng: &mut SplitMix64) -> Vec<usize> {
    let fewest = stacked.div_ceil(4);
    let most = (stacked / 2).min(3);
    let towers = rng.range_usize(fewest, most);
    let mut heights = vec![2; towers];
    for _ in 0..stacked - 2 * towers {
        let open: Vec<usize> = (0..towers).filter(|&t| heights[t] < 4).collect();
        heights[*rng.pick(&open)] += 1;
    }
    heights
}

/// Distance from the centre of a flat support's top face to its edge along the horizontal
/// direction `dir` (unit), for the support's yaw `rotation`.
fn edge_distance(kind: ObjectKind, size: Size, rotation: Rot3, dir: Vector) -> f32 {
    let half = kind.shape(size).compute_local_aabb().maxs;
    let local = rotation.inverse() * dir;
    match kind {
        ObjectKind::Can => half.x,
        _ => {
            let tx = half.x / local.x.abs().max(1e-6);
            let tz = half.z / local.z.abs().max(1e-6);
            tx.min(tz)
        }
    }
}

/// How far every object is sunk into what it rests on, in metres (see the module documentation).
pub const SINK: f32 = 1e-4;

/// The shape used to find resting heights: every cuboid, also inside a compound, replaced by the
/// convex hull of its corners (the same solid, measured by parry's general distance rather than
/// its cuboid-cuboid one), and every cylinder by the hull of a 48-sided prism inscribed in it
/// (parry's distance between two cylinders' parallel flat ends was 0 at 1 mm apart, 2.5 mm at
/// 1 mm and 2.1 mm at 2 mm; prisms are measured exactly).
fn placement_shape(shape: &SharedShape) -> SharedShape {
    if let Some(cylinder) = shape.as_cylinder() {
        let (h, r) = (cylinder.half_height, cylinder.radius);
        let rim: Vec<Vector> = (0..48)
            .flat_map(|k| {
                let phi = std::f32::consts::TAU * k as f32 / 48.0;
                let (x, z) = (r * phi.cos(), r * phi.sin());
                [Vector::new(x, -h, z), Vector::new(x, h, z)]
            })
            .collect();
        SharedShape::convex_hull(&rim).expect("a prism's corners span three dimensions")
    } else if let Some(cuboid) = shape.as_cuboid() {
        let h = cuboid.half_extents;
        let corners: Vec<Vector> = (0..8)
            .map(|i| {
                let sign = |bit: u32| if i & bit == 0 { -1.0 } else { 1.0 };
                Vector::new(sign(1) * h.x, sign(2) * h.y, sign(4) * h.z)
            })
            .collect();
        SharedShape::convex_hull(&corners).expect("a box's corners span three dimensions")
    } else if let Some(compound) = shape.as_compound() {
        SharedShape::compound(
            compound
                .shapes()
                .iter()
                .map(|(pose, part)| (*pose, placement_shape(part)))
                .collect(),
        )
    } else {
        shape.clone()
    }
}

/// How far an object of placement shape `shape` at `pose` must rise so that, along the vertical
/// line through (x, z), its underside clears the tops of `supports` and the plane `floor`
/// (negative: the gap between them); `None` if the line misses the object. Ray casts, which
/// parry does exactly for convex polyhedra.
fn lift_needed(
    shape: &SharedShape,
    pose: &Pose,
    supports: &[(Pose, SharedShape)],
    floor: f32,
    (x, z): (f32, f32),
) -> Option<f32> {
    let own = shape.compute_aabb(pose);
    let below = own.mins.y - 0.01;
    let up = Ray::new(Vector::new(x, below, z), Vector::Y);
    let bottom = below + shape.cast_ray(pose, &up, 1.0, true)?;
    let top = supports
        .iter()
        .map(|(p, s)| s.compute_aabb(p).maxs.y)
        .fold(floor, f32::max);
    let down = Ray::new(Vector::new(x, top + 0.01, z), -Vector::Y);
    let ground = supports
        .iter()
        .filter_map(|(p, s)| s.cast_ray(p, &down, 10.0, true))
        .map(|t| top + 0.01 - t)
        .fold(floor, f32::max);
    Some(ground - bottom)
}

/// The largest [`lift_needed`] over an `n x n` lattice covering the object's footprint, and where.
fn deepest(
    shape: &SharedShape,
    pose: &Pose,
    supports: &[(Pose, SharedShape)],
    floor: f32,
    area: (f32, f32, f32, f32),
    n: usize,
) -> Vec<(f32, f32, f32)> {
    let (x0, z0, x1, z1) = area;
    let mut out = Vec::with_capacity(n * n);
    for i in 0..n {
        for j in 0..n {
            let x = x0 + (x1 - x0) * (i as f32 + 0.5) / n as f32;
            let z = z0 + (z1 - z0) * (j as f32 + 0.5) / n as f32;
            if let Some(lift) = lift_needed(shape, pose, supports, floor, (x, z)) {
                out.push((lift, x, z));
            }
        }
    }
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    out
}

/// The height of the origin at which an object of this shape at (x, z) with this rotation rests
/// on the highest of `below` under it (or on the table), then sunk by [`SINK`]: the largest lift
/// it needs along vertical lines through its footprint over the supports, on a lattice of steps
/// of at most 2.5 mm refined twice by 9 x 9 lattices around the four highest points (steps of a
/// few hundredths of a millimetre near the contact).
fn resting_height(below: &[Placed], shape: &SharedShape, x: f32, z: f32, rotation: Rot3) -> f32 {
    let shape = placement_shape(shape);
    let supports: Vec<(Pose, SharedShape)> = below
        .iter()
        .map(|p| (p.pose(), placement_shape(&p.shape())))
        .collect();
    let pose = Pose::from_parts(Vector::new(x, 0.0, z), rotation);
    // On the table, the lowest point of the upright shape rests on it exactly.
    let on_table = -shape.compute_local_aabb().mins.y;
    if supports.is_empty() {
        return on_table - SINK;
    }
    // Over the supports, a lattice whose step (at most 2.5 mm) cannot miss a stem or a leg.
    let foot = shape.compute_aabb(&pose);
    let under = supports
        .iter()
        .map(|(p, s)| s.compute_aabb(p))
        .reduce(|a, b| a.merged(&b))
        .expect("there are supports");
    let area = (
        foot.mins.x.max(under.mins.x),
        foot.mins.z.max(under.mins.z),
        foot.maxs.x.min(under.maxs.x),
        foot.maxs.z.min(under.maxs.z),
    );
    let n = (((area.2 - area.0).max(area.3 - area.1) / 0.0025).ceil() as usize).max(8);
    let mut best = deepest(&shape, &pose, &supports, 0.0, area, n);
    best.truncate(4);
    let (mut cx, mut cz) = ((area.2 - area.0) / n as f32, (area.3 - area.1) / n as f32);
    // Twice: around the four highest points so far, a 9 x 9 lattice one cell either side.
    for _ in 0..2 {
        let mut finer: Vec<(f32, f32, f32)> = best
            .iter()
            .flat_map(|&(_, px, pz)| {
                let near = (px - cx, pz - cz, px + cx, pz + cz);
                deepest(&shape, &pose, &supports, 0.0, near, 9)
            })
            .chain(best.iter().copied())
            .collect();
        finer.sort_by(|a, b| b.0.total_cmp(&a.0));
        finer.truncate(4);
        best = finer;
        (cx, cz) = (2.0 * cx / 9.0, 2.0 * cz / 9.0);
    }
    let lift = best.first().map_or(on_table, |d| d.0.max(on_table));
    lift - SINK
}

/// A random yaw.
fn yaw(rng: &mut SplitMix64) -> Rot3 {
    Rot3::from_rotation_y(rng.range_f32(-std::f32::consts::PI, std::f32::consts::PI))
}

/// Builds one tower of height `height` around the local origin, bottom up.
fn build_tower(height: usize, risk: Risk, family: &Family, rng: &mut SplitMix64) -> Vec<Placed> {
    // The risky support is the base (see the module documentation); a safe tower has none.
    let risky_level = if risk == Risk::Safe { usize::MAX } else { 0 };
    let mut tower: Vec<Placed> = Vec::with_capacity(height);
    // The size of the medium/large flat support directly below, which caps what it carries.
    let mut cap: Option<Size> = None;
    for level in 0..height {
        let fits = |s: Size| cap.is_none_or(|c| s <= c);
        let big_flat = |s: Size| s >= Size::Medium && cap.is_none_or(|c| s <= c);
        let on_can = tower.last().is_some_and(|p| p.kind == ObjectKind::Can);
        let allowed = |kinds: &'static [ObjectKind]| -> Vec<ObjectKind> {
            kinds
                .iter()
                .copied()
                .filter(|&k| !(on_can && cylinder_based(k)))
                .collect()
        };
        let (kind, size) = if level + 1 == height {
            draw(rng, &allowed(family.all), fits)
        } else if level == risky_level && risk == Risk::Irregular {
            draw(rng, &allowed(family.supports), fits)
        } else if level == risky_level && risk == Risk::Small {
            draw(rng, &allowed(family.flat), |s| s == Size::Small)
        } else {
            draw(rng, &allowed(family.flat), big_flat)
        };
        let colour = *rng.pick(colours(kind));
        let rotation = yaw(rng);
        let (x, z) = match tower.last() {
            None => (0.0, 0.0),
            Some(support) => {
                let centre = support.position;
                let angle = rng.range_f32(0.0, std::f32::consts::TAU);
                let dir = Vector::new(angle.cos(), 0.0, angle.sin());
                let distance = if level == risky_level + 1 && risk == Risk::Small {
                    let edge = edge_distance(support.kind, support.size, support.rotation, dir);
                    rng.range_f32(1.1, 1.5) * edge
                } else {
                    0.01 * rng.next_f64().sqrt() as f32
                };
                (centre.x + distance * dir.x, centre.z + distance * dir.z)
            }
        };
        let shape = kind.shape(size);
        let y = resting_height(&tower, &shape, x, z, rotation);
        cap = (kind.surface() == Surface::Flat && size >= Size::Medium).then_some(size);
        tower.push(Placed {
            kind,
            colour,
            size,
            position: Vector::new(x, y, z),
            rotation,
        });
    }
    tower
}

/// Finds free spots on the table for discs of given radii, keeping 1 cm between discs while
/// there is room for it.
struct Spots {
    placed: Vec<(f32, f32, f32)>,
}

impl Spots {
    fn find(&mut self, r: f32, rng: &mut SplitMix64) -> Result<(f32, f32), SimError> {
        for attempt in 0..2000 {
            let slack = if attempt < 1500 { 0.01 } else { 0.0 };
            let x = rng.range_f32(-0.42 + r, 0.42 - r);
            let z = rng.range_f32(-0.25 + r, 0.32 - r);
            let free = self
                .placed
                .iter()
                .all(|&(px, pz, pr)| ((px - x).powi(2) + (pz - z).powi(2)).sqrt() > pr + r + slack);
            if free {
                self.placed.push((x, z, r));
                return Ok((x, z));
            }
        }
        Err(SimError::MalformedScene(
            "no room on the table for a risky scene's objects".into(),
        ))
    }
}

/// Generates a risky scene as placed (not settled), following the placement rule of the module
/// documentation. Errors: `UnknownPreset` for `H1`, `BadCount` for a count outside 6 to 9,
/// `MalformedScene` if the table had no room (not observed).
pub fn generate_risky(config: &RiskyConfig) -> Result<Scene, SimError> {
    let family = family(config.preset)?;
    let mut rng = SplitMix64::new(config.seed);
    let (lo, hi) = if config.preset == Preset::Real {
        (6, 8)
    } else {
        (7, 9)
    };
    let count = match config.count {
        Some(n) if (6..=9).contains(&n) => n,
        Some(n) => return Err(SimError::BadCount(n)),
        None => rng.range_usize(lo, hi),
    };
    let stacked = rng.range_usize(3, 7.min(count - 1));
    let mut towers = Vec::new();
    for height in tower_heights(stacked, &mut rng) {
        let risk = match rng.range_usize(0, 2) {
            0 => Risk::Safe,
            1 => Risk::Irregular,
            _ => Risk::Small,
        };
        towers.push(build_tower(height, risk, &family, &mut rng));
    }
    let mut spots = Spots { placed: Vec::new() };
    let mut objects: Vec<Placed> = Vec::with_capacity(count);
    for tower in towers {
        let r = tower
            .iter()
            .map(|p| p.position.x.hypot(p.position.z) + footprint_radius(p.kind, p.size))
            .fold(0.0, f32::max);
        let (x, z) = spots.find(r, &mut rng)?;
        for mut p in tower {
            p.position += Vector::new(x, 0.0, z);
            objects.push(p);
        }
    }
    for _ in stacked..count {
        let (kind, size) = draw(&mut rng, family.all, |_| true);
        let colour = *rng.pick(colours(kind));
        let rotation = yaw(&mut rng);
        let (x, z) = spots.find(footprint_radius(kind, size), &mut rng)?;
        let y = -kind.shape(size).compute_local_aabb().mins.y - SINK;
        objects.push(Placed {
            kind,
            colour,
            size,
            position: Vector::new(x, y, z),
            rotation,
        });
    }
    let mut scene = Scene::custom(config.seed);
    scene.preset = config.preset.name().to_string();
    for p in objects {
        let base = format!("{}_{}", p.colour.name(), p.kind.name());
        let mut name = base.clone();
        let mut k = 2;
        while scene.find(&name).is_some() {
            name = format!("{base}_{k}");
            k += 1;
        }
        let mut object = SceneObject {
            name,
            kind: p.kind,
            colour: p.colour,
            size: p.size,
            position: [0.0; 3],
            rotation: [0.0, 0.0, 0.0, 1.0],
        };
        object.set_pose(&p.pose());
        scene.objects.push(object);
    }
    Ok(scene)
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
    use crate::sim::truth::{relations, TruthConfig};
    use crate::sim::World;

    #[test]
    fn same_seed_same_scene_and_counts_in_range() {
        for preset in [Preset::Real, Preset::Simulated] {
            for seed in 0..20 {
                let config = RiskyConfig::new(preset, seed);
                let scene = generate_risky(&config).unwrap();
                assert_eq!(scene, generate_risky(&config).unwrap());
                scene.validate().unwrap();
                let (lo, hi) = if preset == Preset::Real {
                    (6, 8)
                } else {
                    (7, 9)
                };
                assert!((lo..=hi).contains(&scene.objects.len()));
            }
        }
        assert!(generate_risky(&RiskyConfig::new(Preset::H1, 0)).is_err());
        let bad = RiskyConfig {
            count: Some(5),
            ..RiskyConfig::new(Preset::Real, 0)
        };
        assert_eq!(generate_risky(&bad), Err(SimError::BadCount(5)));
    }

    /// Every object stands on one thing (it touches it: no gap) and overlaps nothing beyond the
    /// sinking; only an object and what it stands on touch; 3 to 7 objects are in towers.
    #[test]
    fn objects_rest_exactly_and_loose_ones_are_apart() {
        let truth = TruthConfig::default();
        for seed in 0..40 {
            let preset = if seed % 2 == 0 {
                Preset::Real
            } else {
                Preset::Simulated
            };
            let scene = generate_risky(&RiskyConfig::new(preset, seed)).unwrap();
            let world = World::build(&scene);
            let rels = relations(&scene, &world, &truth);
            let chains = supports(&scene, &rels);
            let mut in_towers = 0;
            for id in scene.ids() {
                let name = &scene.object(id).name;
                let on: Vec<&Relation> = rels
                    .iter()
                    .filter(|r| r.rel == Rel::On && &r.a == name)
                    .collect();
                assert_eq!(
                    on.len(),
                    1,
                    "seed {seed} {name} stands on one thing: {on:?} {:?}",
                    rels.iter().filter(|r| &r.a == name).collect::<Vec<_>>()
                );
                let carries = rels.iter().any(|r| r.rel == Rel::On && &r.b == name);
                if !chains[id.index()].is_empty() || carries {
                    in_towers += 1;
                }
                // Overlap is the sinking: along vertical lines on a 64 x 64 lattice, no object
                // dips more than 0.6 mm into one below it (that it touches what it stands on is
                // `on` above).
                let shape = |o: ObjectId| {
                    let object = scene.object(o);
                    (
                        object.pose(),
                        placement_shape(&object.kind.shape(object.size)),
                    )
                };
                let (pose, own) = shape(id);
                let foot = own.compute_aabb(&pose);
                let area = (foot.mins.x, foot.mins.z, foot.maxs.x, foot.maxs.z);
                for other in scene.ids().filter(|&o| o != id) {
                    if scene.object(other).position[1] > scene.object(id).position[1] {
                        continue;
                    }
                    let lift = deepest(&own, &pose, &[shape(other)], f32::NEG_INFINITY, area, 64)
                        .first()
                        .map_or(f32::NEG_INFINITY, |d| d.0);
                    let o = &scene.object(other).name;
                    assert!(lift < 6e-4, "seed {seed}: {name} dips {lift} into {o}");
                }
            }
            assert!((3..=7).contains(&in_towers), "seed {seed}: {in_towers}");
            let on = |a: &str, b: &str| {
                rels.iter()
                    .any(|r| r.rel == Rel::On && r.a == a && r.b == b)
            };
            for r in rels.iter().filter(|r| r.rel == Rel::Touch) {
                if r.a != TABLE && r.b != TABLE {
                    assert!(on(&r.a, &r.b) || on(&r.b, &r.a), "seed {seed}: {r}");
                }
            }
        }
    }

    #[test]
    fn tower_heights_partition_the_stacked_objects() {
        let mut rng = SplitMix64::new(7);
        for stacked in 3..=7 {
            for _ in 0..50 {
                let h = tower_heights(stacked, &mut rng);
                assert!((1..=3).contains(&h.len()));
                assert!(h.iter().all(|&x| (2..=4).contains(&x)));
                assert_eq!(h.iter().sum::<usize>(), stacked);
            }
        }
    }

    #[test]
    fn edge_distance_of_a_cube_grows_towards_its_corner() {
        let (kind, size) = (ObjectKind::Cube, Size::Small);
        let face = edge_distance(kind, size, Rot3::IDENTITY, Vector::X);
        assert!((face - 0.025).abs() < 1e-6);
        let diagonal = Vector::new(1.0, 0.0, 1.0).normalize();
        let corner = edge_distance(kind, size, Rot3::IDENTITY, diagonal);
        assert!((corner - 0.025 * 2f32.sqrt()).abs() < 1e-5);
        let turned = edge_distance(
            kind,
            size,
            Rot3::from_rotation_y(std::f32::consts::FRAC_PI_4),
            diagonal,
        );
        assert!((turned - 0.025).abs() < 1e-5);
    }
}

#[cfg(test)]
mod measure {
    use super::*;
    use crate::sim::truth::{relations, TruthConfig};
    use crate::sim::World;
    use crate::vision::labels::{label, LabelConfig};
    use rayon::prelude::*;

    /// Per preset, the fraction of stacked objects stable per footing over 300 scenes, and per
    /// kind of the support directly below. Run with
    /// `cargo test --release --lib vision::scenes::measure -- --ignored --nocapture`.
    #[test]
    #[ignore]
    fn physics_rates_per_footing() {
        let truth = TruthConfig::default();
        let labels = LabelConfig::default();
        for preset in [Preset::Real, Preset::Simulated] {
            let rows: Vec<Vec<(Footing, String, bool)>> = (0..300u64)
                .into_par_iter()
                .map(|seed| {
                    let scene = generate_risky(&RiskyConfig::new(preset, seed)).unwrap();
                    let world = World::build(&scene);
                    let chains = supports(&scene, &relations(&scene, &world, &truth));
                    let l = label(&scene, &labels);
                    scene
                        .ids()
                        .filter(|id| !chains[id.index()].is_empty())
                        .map(|id| {
                            let below = scene.object(chains[id.index()][0]);
                            let what = format!("{}/{}", below.kind.name(), below.size.name());
                            (
                                footing(&scene, &chains[id.index()]),
                                what,
                                l[id.index()].stable,
                            )
                        })
                        .collect()
                })
                .collect();
            let all: Vec<_> = rows.into_iter().flatten().collect();
            println!("{}: {} stacked objects", preset.name(), all.len());
            for f in [Footing::Irregular, Footing::Small, Footing::Flat] {
                let of: Vec<_> = all.iter().filter(|r| r.0 == f).collect();
                let stable = of.iter().filter(|r| r.2).count();
                println!(
                    "  {:22} {:4} objects, stable {:.3}, unstable {:.3}",
                    f.name(),
                    of.len(),
                    stable as f64 / of.len().max(1) as f64,
                    1.0 - stable as f64 / of.len().max(1) as f64
                );
                let mut kinds: Vec<&String> = of.iter().map(|r| &r.1).collect();
                kinds.sort();
                kinds.dedup();
                for k in kinds {
                    let n = of.iter().filter(|r| &r.1 == k).count();
                    let s = of.iter().filter(|r| &r.1 == k && r.2).count();
                    println!("      directly on {k:18} {n:4}, stable {s:4}");
                }
            }
        }
    }
}
