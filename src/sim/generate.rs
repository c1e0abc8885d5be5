//! Scene generation from a seed: presets of the paper's real and simulated scenes (docs/domain.md
//! §1.6) and the H1 learning scene, stacks built on flat supports, the rest spread on the table,
//! then physical settling.
//!
//! Invariants: the same `(preset, seed, count)` gives the same scene, bit for bit; a scene has
//! 5 to 9 objects, of which 3 to 5 stand in towers of two or more ("stacked", bases included);
//! every tower below its top object is made of flat-topped objects, widest at the bottom. Physics
//! decides the final poses: settling may still topple something, and the result is kept.

use super::object::{Colour, ObjectKind, Size};
use super::scene::{Scene, SceneObject};
use super::world::World;
use super::SimError;
use crate::base::rng::SplitMix64;
use parry3d::math::Rot3;

/// A family of scenes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Preset {
    /// Like the paper's real scenes: cubes, a tennis ball, fruit, a pig, a pot; 5 to 7 objects.
    Real,
    /// Like the paper's simulated scenes: cylinders, spheres, cubes, a duck and household
    /// objects; 7 to 9 objects.
    Simulated,
    /// The H1 learning scene's eight objects, randomly arranged.
    H1,
}

impl Preset {
    /// Every preset.
    pub const ALL: [Preset; 3] = [Preset::Real, Preset::Simulated, Preset::H1];

    /// The preset's name on the command line and in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Preset::Real => "real",
            Preset::Simulated => "simulated",
            Preset::H1 => "h1",
        }
    }

    /// Parses a preset name; `sim` is accepted for `simulated`.
    pub fn parse(text: &str) -> Result<Preset, SimError> {
        match text {
            "real" => Ok(Preset::Real),
            "simulated" | "sim" => Ok(Preset::Simulated),
            "h1" => Ok(Preset::H1),
            _ => Err(SimError::UnknownPreset(text.to_string())),
        }
    }

    /// The default range of object counts.
    pub fn count_range(self) -> (usize, usize) {
        match self {
            Preset::Real => (5, 7),
            Preset::Simulated => (7, 9),
            Preset::H1 => (8, 8),
        }
    }
}

/// What to generate.
#[derive(Clone, Debug, PartialEq)]
pub struct GenerateConfig {
    /// The preset.
    pub preset: Preset,
    /// The seed of every random choice.
    pub seed: u64,
    /// The number of objects, 5 to 9; `None` draws it from the preset's range.
    pub count: Option<usize>,
    /// Upper bound of simulated settling time in seconds.
    pub settle_seconds: f32,
}

impl GenerateConfig {
    /// A configuration with the preset's defaults.
    pub fn new(preset: Preset, seed: u64) -> Self {
        GenerateConfig {
            preset,
            seed,
            count: None,
            settle_seconds: 6.0,
        }
    }
}

/// An object chosen before placement.
struct Draft {
    /// What it is.
    kind: ObjectKind,
    /// Its colour.
    colour: Colour,
    /// Its size class.
    size: Size,
    /// A fixed name (the H1 scene's constants); otherwise named from colour and kind.
    name: Option<String>,
}

fn pick<T: Copy>(rng: &mut SplitMix64, items: &[T]) -> T {
    items[rng.range_usize(0, items.len() - 1)]
}

/// Plausible colours of a kind.
pub(crate) fn colours(kind: ObjectKind) -> &'static [Colour] {
    use Colour::*;
    match kind {
        ObjectKind::Cube => &[Red, Green, Blue, Yellow, White, Orange, Purple],
        ObjectKind::Can => &[White, Red, Green, Blue],
        ObjectKind::Ball => &[Yellow, Blue, Green, Red],
        ObjectKind::Box => &[Red, Yellow, Brown],
        ObjectKind::Bottle => &[Yellow],
        ObjectKind::Duck => &[Yellow],
        ObjectKind::Apple => &[Red, Green],
        ObjectKind::Orange => &[Orange],
        ObjectKind::Capsicum => &[Red, Green, Yellow],
        ObjectKind::Pig => &[Pink],
        ObjectKind::Pitcher => &[Blue, White],
        ObjectKind::Mug => &[Red, White, Black],
        ObjectKind::Pot => &[Black, Brown],
    }
}

/// Plausible sizes of a kind.
pub(crate) fn sizes(kind: ObjectKind) -> &'static [Size] {
    use Size::*;
    match kind {
        ObjectKind::Cube => &[Small, Medium, Large, Large],
        ObjectKind::Can => &[Small, Medium],
        ObjectKind::Ball | ObjectKind::Orange | ObjectKind::Apple => &[Small, Medium],
        ObjectKind::Mug | ObjectKind::Capsicum => &[Small, Medium],
        _ => &[Medium, Large],
    }
}

fn drafts(preset: Preset, count: usize, rng: &mut SplitMix64) -> Vec<Draft> {
    let free = |kind: ObjectKind, rng: &mut SplitMix64| Draft {
        kind,
        colour: pick(rng, colours(kind)),
        size: pick(rng, sizes(kind)),
        name: None,
    };
    match preset {
        Preset::H1 => {
            let fixed = |kind, colour, size, name: &str| Draft {
                kind,
                colour,
                size,
                name: Some(name.into()),
            };
            vec![
                fixed(
                    ObjectKind::Cube,
                    Colour::Green,
                    Size::Large,
                    "green_cube_large",
                ),
                fixed(ObjectKind::Cube, Colour::Red, Size::Large, "red_cube_large"),
                fixed(
                    ObjectKind::Cube,
                    Colour::Yellow,
                    Size::Large,
                    "yellow_cube_large",
                ),
                fixed(
                    ObjectKind::Cube,
                    Colour::White,
                    Size::Large,
                    "white_cube_large",
                ),
                fixed(
                    ObjectKind::Can,
                    Colour::White,
                    Size::Small,
                    "white_can_small",
                ),
                fixed(ObjectKind::Ball, Colour::Blue, Size::Medium, "blue_ball"),
                fixed(ObjectKind::Pitcher, Colour::Blue, Size::Large, "pitcher"),
                fixed(
                    ObjectKind::Duck,
                    Colour::Yellow,
                    Size::Medium,
                    "yellow_duck",
                ),
            ]
        }
        Preset::Real | Preset::Simulated => {
            let (supports, others): (&[ObjectKind], &[ObjectKind]) = if preset == Preset::Real {
                (
                    &[ObjectKind::Cube],
                    &[
                        ObjectKind::Ball,
                        ObjectKind::Apple,
                        ObjectKind::Orange,
                        ObjectKind::Capsicum,
                        ObjectKind::Pig,
                        ObjectKind::Pot,
                    ],
                )
            } else {
                (
                    &[ObjectKind::Cube, ObjectKind::Can, ObjectKind::Box],
                    &[
                        ObjectKind::Ball,
                        ObjectKind::Duck,
                        ObjectKind::Apple,
                        ObjectKind::Pitcher,
                        ObjectKind::Bottle,
                        ObjectKind::Mug,
                        ObjectKind::Box,
                        ObjectKind::Cube,
                        ObjectKind::Can,
                    ],
                )
            };
            // At least four flat supports let any tower arrangement of up to five be built.
            let flat = rng.range_usize(4, (count - 1).min(5));
            let mut out: Vec<Draft> = (0..flat).map(|_| free(pick(rng, supports), rng)).collect();
            let mut pool = others.to_vec();
            rng.shuffle_modulo(&mut pool);
            for i in 0..count - flat {
                out.push(free(pool[i % pool.len()], rng));
            }
            out
        }
    }
}

fn name_drafts(drafts: &[Draft]) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for d in drafts {
        let base = d
            .name
            .clone()
            .unwrap_or_else(|| format!("{}_{}", d.colour.name(), d.kind.name()));
        let mut name = base.clone();
        let mut k = 2;
        while names.contains(&name) {
            name = format!("{base}_{k}");
            k += 1;
        }
        names.push(name);
    }
    names
}

/// Splits `stacked` objects into towers of at least two.
fn tower_heights(stacked: usize, rng: &mut SplitMix64) -> Vec<usize> {
    match stacked {
        4 if rng.chance(0.5) => vec![2, 2],
        5 if rng.chance(0.6) => vec![3, 2],
        n => vec![n],
    }
}

/// Generates and settles a scene.
pub fn generate(config: &GenerateConfig) -> Result<Scene, SimError> {
    let mut rng = SplitMix64::new(config.seed);
    let (lo, hi) = config.preset.count_range();
    let count = match config.count {
        Some(n) if (5..=9).contains(&n) && !(config.preset == Preset::H1 && n > 8) => n,
        Some(n) => return Err(SimError::BadCount(n)),
        None => rng.range_usize(lo, hi),
    };
    let mut drafts = drafts(config.preset, count, &mut rng);
    if config.preset == Preset::H1 && count != 8 {
        drafts.truncate(count.min(8));
    }
    let names = name_drafts(&drafts);
    let n = drafts.len();
    // Supports: flat objects (the H1 scene's ball, pitcher and duck never support anything).
    let mut flat: Vec<usize> = (0..n)
        .filter(|&i| drafts[i].kind.surface() == super::Surface::Flat)
        .collect();
    rng.shuffle_modulo(&mut flat);
    let mut stacked = rng.range_usize(3, 5).min(n - 1);
    let mut heights = tower_heights(stacked, &mut rng);
    // Each tower needs height - 1 supports; shrink the plan if the scene lacks them.
    while heights.iter().map(|h| h - 1).sum::<usize>() > flat.len().saturating_sub(1) {
        stacked = stacked.saturating_sub(1);
        heights = tower_heights(stacked.max(2), &mut rng);
    }
    let mut used = vec![false; n];
    let mut towers: Vec<Vec<usize>> = Vec::new();
    for h in &heights {
        // The top first: preferably an object that cannot support (so irregular objects get
        // stacked), then supports at least as large as it, widest at the bottom, as in the
        // paper's stacked scenes. Physics still decides whether the tower stands.
        let mut candidates: Vec<usize> = (0..n).filter(|&i| !used[i]).collect();
        rng.shuffle_modulo(&mut candidates);
        candidates.sort_by_key(|&i| drafts[i].kind.surface() == super::Surface::Flat);
        let free_flat = |used: &[bool]| flat.iter().filter(|&&i| !used[i]).count();
        let top = candidates
            .into_iter()
            .find(|&i| {
                let others = free_flat(&used) - usize::from(flat.contains(&i));
                others >= h - 1
            })
            .expect("the plan leaves enough supports for every tower");
        used[top] = true;
        let mut pool: Vec<usize> = flat.iter().copied().filter(|&i| !used[i]).collect();
        pool.sort_by_key(|&i| std::cmp::Reverse(drafts[i].size >= drafts[top].size));
        let mut tower: Vec<usize> = pool.into_iter().take(h - 1).collect();
        for &i in &tower {
            used[i] = true;
        }
        tower.sort_by(|&a, &b| drafts[b].size.cmp(&drafts[a].size));
        tower.push(top);
        towers.push(tower);
    }
    let mut scene = Scene::custom(config.seed);
    scene.preset = config.preset.name().to_string();
    // Footprint radius of each object, for spreading bases and loose objects on the table.
    let radius = |i: usize| {
        let aabb = drafts[i].kind.shape(drafts[i].size).compute_local_aabb();
        let (dx, dz) = (aabb.maxs.x - aabb.mins.x, aabb.maxs.z - aabb.mins.z);
        0.5 * (dx * dx + dz * dz).sqrt()
    };
    let mut placed: Vec<(f32, f32, f32)> = Vec::new();
    let mut spot = |r: f32, rng: &mut SplitMix64| {
        for attempt in 0..400 {
            let slack = if attempt < 300 { 0.01 } else { 0.0 };
            let x = rng.range_f32(-0.42 + r, 0.42 - r);
            let z = rng.range_f32(-0.25 + r, 0.32 - r);
            if placed
                .iter()
                .all(|&(px, pz, pr)| ((px - x).powi(2) + (pz - z).powi(2)).sqrt() > pr + r + slack)
            {
                placed.push((x, z, r));
                return (x, z);
            }
        }
        // The table always has room for nine objects; this is only a guard.
        let x = -0.5 + 0.12 * placed.len() as f32;
        placed.push((x, 0.35, r));
        (x, 0.35)
    };
    let mut objects: Vec<Option<SceneObject>> = (0..n).map(|_| None).collect();
    let mut make = |i: usize, x: f32, bottom: f32, z: f32, rng: &mut SplitMix64| {
        let d = &drafts[i];
        let yaw = rng.range_f32(-std::f32::consts::PI, std::f32::consts::PI);
        let q = Rot3::from_rotation_y(yaw);
        let lowest = d.kind.shape(d.size).compute_local_aabb().mins.y;
        objects[i] = Some(SceneObject {
            name: names[i].clone(),
            kind: d.kind,
            colour: d.colour,
            size: d.size,
            position: [x, bottom - lowest + 0.001, z],
            rotation: [q.x, q.y, q.z, q.w],
        });
        d.kind
            .shape(d.size)
            .compute_aabb(&parry3d::math::Pose::from_parts(
                parry3d::math::Vector::new(x, bottom - lowest + 0.001, z),
                q,
            ))
    };
    for tower in &towers {
        let r = tower.iter().map(|&i| radius(i)).fold(0.0, f32::max);
        let (x, z) = spot(r, &mut rng);
        let mut bottom = 0.0;
        for &i in tower {
            let jx = rng.range_f32(-0.004, 0.004);
            let jz = rng.range_f32(-0.004, 0.004);
            let aabb = make(i, x + jx, bottom, z + jz, &mut rng);
            bottom = aabb.maxs.y + 0.001;
        }
    }
    let loose: Vec<usize> = (0..n).filter(|&i| !used[i]).collect();
    for i in loose {
        let (x, z) = spot(radius(i), &mut rng);
        make(i, x, 0.0, z, &mut rng);
    }
    scene.objects = objects
        .into_iter()
        .map(|o| o.expect("every object was placed"))
        .collect();
    let mut world = World::build(&scene);
    world.settle(config.settle_seconds);
    world.write_back(&mut scene);
    Ok(scene)
}

/// Generates many scenes in parallel with rayon (coarse grain: one scene per task), in the order
/// of the configurations; each result is the same as `generate` would give alone.
pub fn generate_many(configs: &[GenerateConfig]) -> Vec<Result<Scene, SimError>> {
    use rayon::prelude::*;
    configs.par_iter().map(generate).collect()
}
