//! Object kinds and their attributes: shape, size class, top surface, colour, and the parry
//! shape that models each kind.
//!
//! Invariants: the top surface follows from the kind alone (docs/domain.md §1.6 attribute
//! defaults), and every shape is built upright with its local origin inside it, so a body's pose
//! places the object and `shape(kind, size).compute_local_aabb()` gives its extent when upright.
//! Lengths are metres: a size class is the object's characteristic width.

use parry3d::math::{Pose, Rot3, Vector};
use parry3d::shape::SharedShape;
use serde::{Deserialize, Serialize};

/// The kind of a movable object; it fixes the shape and the top surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ObjectKind {
    /// A cube; flat top.
    Cube,
    /// A cylinder standing on its base (a can); flat top.
    #[serde(alias = "cylinder")]
    Can,
    /// A sphere (a tennis ball); irregular top.
    #[serde(alias = "sphere")]
    Ball,
    /// A cracker box lying on its broad face; flat top.
    Box,
    /// A mustard bottle with a cap; irregular top.
    Bottle,
    /// A rubber duck; irregular top.
    Duck,
    /// An apple with a stem; irregular top.
    Apple,
    /// An orange; irregular top.
    Orange,
    /// A lobed capsicum with a stem; irregular top.
    Capsicum,
    /// A toy pig on four legs; irregular top.
    Pig,
    /// A pitcher with an uneven rim, a spout and a handle; irregular top.
    Pitcher,
    /// A mug with an uneven rim and a handle; irregular top.
    Mug,
    /// A pot with an uneven rim and two handles; irregular top.
    Pot,
}

impl ObjectKind {
    /// Every kind, in declaration order.
    pub const ALL: [ObjectKind; 13] = [
        ObjectKind::Cube,
        ObjectKind::Can,
        ObjectKind::Ball,
        ObjectKind::Box,
        ObjectKind::Bottle,
        ObjectKind::Duck,
        ObjectKind::Apple,
        ObjectKind::Orange,
        ObjectKind::Capsicum,
        ObjectKind::Pig,
        ObjectKind::Pitcher,
        ObjectKind::Mug,
        ObjectKind::Pot,
    ];

    /// The constant used for the kind in names and in `has_shape` facts.
    pub fn name(self) -> &'static str {
        match self {
            ObjectKind::Cube => "cube",
            ObjectKind::Can => "can",
            ObjectKind::Ball => "ball",
            ObjectKind::Box => "box",
            ObjectKind::Bottle => "bottle",
            ObjectKind::Duck => "duck",
            ObjectKind::Apple => "apple",
            ObjectKind::Orange => "orange",
            ObjectKind::Capsicum => "capsicum",
            ObjectKind::Pig => "pig",
            ObjectKind::Pitcher => "pitcher",
            ObjectKind::Mug => "mug",
            ObjectKind::Pot => "pot",
        }
    }

    /// The top surface that follows from the shape: flat for cubes, cans and boxes.
    pub fn surface(self) -> Surface {
        match self {
            ObjectKind::Cube | ObjectKind::Can | ObjectKind::Box => Surface::Flat,
            _ => Surface::Irregular,
        }
    }

    /// True for the kinds that can roll on a flat surface (round in some direction): everything
    /// but cubes, boxes and the four-legged pig. They get rolling resistance in `World`.
    pub fn rolls(self) -> bool {
        !matches!(self, ObjectKind::Cube | ObjectKind::Box | ObjectKind::Pig)
    }

    /// Angular damping of the body. Rapier has no rolling resistance, so round objects get
    /// more damping, as felt balls and fruit on a table stop rolling within a second or two.
    pub fn rolling_damping(self) -> f32 {
        match self {
            ObjectKind::Ball | ObjectKind::Orange | ObjectKind::Apple => 12.0,
            _ => 1.5,
        }
    }

    /// The parry shape of an object of this kind and size, upright, origin inside the object.
    pub fn shape(self, size: Size) -> SharedShape {
        let s = size.width();
        let at = |x: f32, y: f32, z: f32| Pose::from_translation(Vector::new(x, y, z));
        match self {
            ObjectKind::Cube => SharedShape::cuboid(0.5 * s, 0.5 * s, 0.5 * s),
            ObjectKind::Can => SharedShape::cylinder(0.5 * s, 0.45 * s),
            ObjectKind::Ball => SharedShape::ball(0.5 * s),
            ObjectKind::Orange => SharedShape::ball(0.45 * s),
            ObjectKind::Box => SharedShape::cuboid(0.8 * s, 0.25 * s, 0.55 * s),
            ObjectKind::Bottle => SharedShape::compound(vec![
                (at(0.0, 0.0, 0.0), SharedShape::cylinder(0.6 * s, 0.3 * s)),
                (
                    at(0.0, 0.6 * s + 0.1 * s, 0.0),
                    SharedShape::cone(0.1 * s, 0.2 * s),
                ),
                (
                    at(0.0, 0.85 * s, 0.0),
                    SharedShape::cylinder(0.05 * s, 0.06 * s),
                ),
            ]),
            ObjectKind::Duck => SharedShape::compound(vec![
                (at(0.0, 0.0, 0.0), ellipsoid(0.5 * s, 0.3 * s, 0.35 * s)),
                foot(0.12 * s, -0.3 * s, s),
                (at(0.28 * s, 0.38 * s, 0.0), SharedShape::ball(0.18 * s)),
                (
                    at(0.48 * s, 0.36 * s, 0.0),
                    SharedShape::cuboid(0.08 * s, 0.03 * s, 0.06 * s),
                ),
                (at(-0.45 * s, 0.2 * s, 0.0), SharedShape::ball(0.08 * s)),
            ]),
            ObjectKind::Apple => SharedShape::compound(vec![
                (at(0.0, 0.0, 0.0), ellipsoid(0.5 * s, 0.42 * s, 0.5 * s)),
                foot(0.16 * s, -0.42 * s, s),
                (
                    at(0.0, 0.48 * s, 0.0),
                    SharedShape::cylinder(0.08 * s, 0.03 * s),
                ),
            ]),
            ObjectKind::Capsicum => SharedShape::compound(vec![
                (at(0.0, 0.0, 0.0), lobed(0.5 * s, 0.45 * s)),
                foot(0.24 * s, -0.45 * s, s),
                (
                    at(0.0, 0.52 * s, 0.0),
                    SharedShape::cylinder(0.1 * s, 0.04 * s),
                ),
            ]),
            ObjectKind::Pig => {
                let leg = || SharedShape::cylinder(0.09 * s, 0.07 * s);
                SharedShape::compound(vec![
                    (
                        at(0.0, 0.0, 0.0),
                        SharedShape::capsule_x(0.25 * s, 0.25 * s),
                    ),
                    (at(0.5 * s, 0.12 * s, 0.0), SharedShape::ball(0.2 * s)),
                    (at(-0.52 * s, 0.15 * s, 0.0), SharedShape::ball(0.06 * s)),
                    (at(0.22 * s, -0.28 * s, 0.13 * s), leg()),
                    (at(0.22 * s, -0.28 * s, -0.13 * s), leg()),
                    (at(-0.22 * s, -0.28 * s, 0.13 * s), leg()),
                    (at(-0.22 * s, -0.28 * s, -0.13 * s), leg()),
                ])
            }
            ObjectKind::Pitcher => vessel(
                s,
                0.65,
                0.4,
                &[0.12, 0.04, 0.0, 0.02, 0.0, 0.05, 0.01, 0.03],
                true,
                false,
            ),
            ObjectKind::Mug => vessel(
                s,
                0.45,
                0.4,
                &[0.0, 0.05, 0.02, 0.06, 0.0, 0.04, 0.01, 0.05],
                true,
                false,
            ),
            ObjectKind::Pot => vessel(
                s,
                0.35,
                0.5,
                &[0.03, 0.0, 0.06, 0.01, 0.04, 0.0, 0.05, 0.02],
                false,
                true,
            ),
        }
    }
}

/// A flat foot under a hull whose lowest point is at height `bottom`: a thin square plate of
/// half width `half_width` whose underside lies `0.03 * s` below that point, so the object
/// stands on the plate. A faceted hull resting on its pole vertex or on a many-sided face never
/// came to rest in rapier (an upright capsicum slid 2-30 mm per 2 s at some yaws, apples and
/// ducks rocked on their pole), and a disc foot slid too; a box face rests like a cube's. Real
/// fruit and rubber ducks have a flattened base.
fn foot(half_width: f32, bottom: f32, s: f32) -> (Pose, SharedShape) {
    let half = 0.03 * s;
    (
        Pose::from_translation(Vector::new(0.0, bottom - 0.03 * s + half, 0.0)),
        SharedShape::cuboid(half_width, half, half_width),
    )
}

/// A convex hull approximating an ellipsoid with semi-axes `a`, `b`, `c` (x, y, z).
fn ellipsoid(a: f32, b: f32, c: f32) -> SharedShape {
    let mut points = Vec::new();
    for i in 0..=8 {
        let theta = std::f32::consts::PI * i as f32 / 8.0;
        for j in 0..12 {
            let phi = std::f32::consts::TAU * j as f32 / 12.0;
            points.push(Vector::new(
                a * theta.sin() * phi.cos(),
                b * theta.cos(),
                c * theta.sin() * phi.sin(),
            ));
        }
    }
    SharedShape::convex_hull(&points).expect("an ellipsoid point cloud spans three dimensions")
}

/// A convex hull of a lobed, slightly tapered body (a capsicum): four bulges around the y axis.
fn lobed(radius: f32, half_height: f32) -> SharedShape {
    let mut points = Vec::new();
    for i in 0..=6 {
        let t = i as f32 / 6.0;
        let y = -half_height + 2.0 * half_height * t;
        let taper = 0.75 + 0.25 * (std::f32::consts::PI * t).sin();
        for j in 0..16 {
            let phi = std::f32::consts::TAU * j as f32 / 16.0;
            let r = radius * taper * (0.85 + 0.15 * (4.0 * phi).cos());
            points.push(Vector::new(r * phi.cos(), y, r * phi.sin()));
        }
    }
    // The lobes dip at the top, which the hull fills; the top bumps come from the lobe tips.
    for j in 0..4 {
        let phi = std::f32::consts::FRAC_PI_2 * j as f32;
        points.push(Vector::new(
            0.45 * radius * phi.cos(),
            half_height * 1.08,
            0.45 * radius * phi.sin(),
        ));
    }
    SharedShape::convex_hull(&points).expect("a lobed point cloud spans three dimensions")
}

/// An open vessel: a body cylinder whose top is an uneven rim of eight blocks (heights given as
/// fractions of the width), with a side handle and optionally a second one opposite.
fn vessel(
    s: f32,
    half_height: f32,
    radius: f32,
    rim: &[f32; 8],
    handle: bool,
    two_handles: bool,
) -> SharedShape {
    let (hh, r) = (half_height * s, radius * s);
    let mut parts = vec![(Pose::identity(), SharedShape::cylinder(hh, r))];
    for (k, extra) in rim.iter().enumerate() {
        let phi = std::f32::consts::TAU * k as f32 / 8.0;
        let half_block = 0.04 * s + 0.5 * extra * s;
        let centre = Vector::new(0.85 * r * phi.cos(), hh + half_block, 0.85 * r * phi.sin());
        let pose = Pose::from_parts(centre, Rot3::from_rotation_y(-phi));
        parts.push((pose, SharedShape::cuboid(0.15 * r, half_block, 0.35 * r)));
    }
    let grip = |x: f32| {
        (
            Pose::from_translation(Vector::new(x, 0.15 * hh, 0.0)),
            SharedShape::cuboid(0.12 * s, 0.35 * hh, 0.04 * s),
        )
    };
    if handle || two_handles {
        parts.push(grip(r + 0.1 * s));
    }
    if two_handles {
        parts.push(grip(-r - 0.1 * s));
    }
    SharedShape::compound(parts)
}

/// A size class; the paper's "big" is `large`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Size {
    /// About 5 cm wide.
    Small,
    /// About 7.5 cm wide.
    Medium,
    /// About 10 cm wide.
    Large,
}

impl Size {
    /// Every size, smallest first.
    pub const ALL: [Size; 3] = [Size::Small, Size::Medium, Size::Large];

    /// The characteristic width in metres.
    pub fn width(self) -> f32 {
        match self {
            Size::Small => 0.05,
            Size::Medium => 0.075,
            Size::Large => 0.10,
        }
    }

    /// The constant used in `has_size` facts.
    pub fn name(self) -> &'static str {
        match self {
            Size::Small => "small",
            Size::Medium => "medium",
            Size::Large => "large",
        }
    }
}

/// The type of an object's top surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Surface {
    /// Something placed on it can rest.
    Flat,
    /// Something placed on it may roll or slide off.
    Irregular,
}

impl Surface {
    /// The constant used in `has_surface` facts.
    pub fn name(self) -> &'static str {
        match self {
            Surface::Flat => "flat",
            Surface::Irregular => "irregular",
        }
    }
}

/// A named colour with its display value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Colour {
    /// Red.
    Red,
    /// Green.
    Green,
    /// Blue.
    Blue,
    /// Yellow.
    Yellow,
    /// White.
    White,
    /// Orange.
    Orange,
    /// Purple.
    Purple,
    /// Brown.
    Brown,
    /// Pink.
    Pink,
    /// Black.
    Black,
}

impl Colour {
    /// Every colour.
    pub const ALL: [Colour; 10] = [
        Colour::Red,
        Colour::Green,
        Colour::Blue,
        Colour::Yellow,
        Colour::White,
        Colour::Orange,
        Colour::Purple,
        Colour::Brown,
        Colour::Pink,
        Colour::Black,
    ];

    /// The colour's name, used as the prefix of generated object names.
    pub fn name(self) -> &'static str {
        match self {
            Colour::Red => "red",
            Colour::Green => "green",
            Colour::Blue => "blue",
            Colour::Yellow => "yellow",
            Colour::White => "white",
            Colour::Orange => "orange",
            Colour::Purple => "purple",
            Colour::Brown => "brown",
            Colour::Pink => "pink",
            Colour::Black => "black",
        }
    }

    /// The colour as linear-ish RGB in `[0, 1]`, for rendering.
    pub fn rgb(self) -> [f32; 3] {
        match self {
            Colour::Red => [0.85, 0.12, 0.10],
            Colour::Green => [0.15, 0.65, 0.20],
            Colour::Blue => [0.15, 0.30, 0.85],
            Colour::Yellow => [0.95, 0.85, 0.15],
            Colour::White => [0.93, 0.93, 0.90],
            Colour::Orange => [0.98, 0.55, 0.10],
            Colour::Purple => [0.55, 0.20, 0.70],
            Colour::Brown => [0.50, 0.32, 0.18],
            Colour::Pink => [0.95, 0.60, 0.70],
            Colour::Black => [0.12, 0.12, 0.14],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shape_is_built_with_origin_inside() {
        for kind in ObjectKind::ALL {
            for size in Size::ALL {
                let aabb = kind.shape(size).compute_local_aabb();
                assert!(aabb.mins.y < 0.0 && aabb.maxs.y > 0.0, "{kind:?} {size:?}");
                assert!(
                    aabb.maxs.x - aabb.mins.x <= 1.6 * size.width() + 1e-4,
                    "{kind:?}"
                );
            }
        }
    }

    #[test]
    fn surface_follows_shape() {
        assert_eq!(ObjectKind::Cube.surface(), Surface::Flat);
        assert_eq!(ObjectKind::Can.surface(), Surface::Flat);
        assert_eq!(ObjectKind::Duck.surface(), Surface::Irregular);
        assert_eq!(ObjectKind::Ball.surface(), Surface::Irregular);
    }
}
