//! Pictures for people: the robot's camera view framed so that every object is in it, with each
//! object's name written above it (the demo's and the run report's pictures).
//!
//! The robot's own camera ([`super::Camera`]) is what perception and the vision data use and is
//! never changed here: a tall tower at the back of the table can leave its frame. A picture for
//! a person keeps the camera's eye and target and widens the field of view just enough that the
//! bounding box of every object on the table lies inside the frame with a margin.
//!
//! Labels are drawn with a 5x7 bitmap font of capitals, digits and `_` (an object constant's
//! characters; anything else is a blank), on a light box to the right of the object (to its left
//! at the image's right edge) with a tick pointing at it, and moved down or up past labels
//! already placed so that no two overlap (a tower's labels stand in a column beside it).
//!
//! Invariants: a pure function of the scene and the size; the field of view never narrows
//! below the camera's own; labels stay inside the image.

use parry3d::math::Vector;

use super::render::{render_camera_world, Image};
use super::scene::Scene;
use super::truth::project;
use super::world::World;

/// The margin kept between the outermost object and the frame's edge, as a fraction of the
/// half-frame.
const MARGIN: f32 = 0.15;

/// The widest field of view a framing may take, in degrees.
const MAX_FOV: f32 = 100.0;

/// One object's name and where its label points (pixel coordinates of the middle of the
/// object's right edge in the image).
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// The object's constant.
    pub name: String,
    /// Pixel column of the object's right edge.
    pub x: f32,
    /// Pixel row of the object's middle.
    pub y: f32,
}

/// A framed camera picture and its labels' anchors (the labels are drawn into the image).
#[derive(Clone, Debug, PartialEq)]
pub struct Picture {
    /// The image, labels drawn.
    pub image: Image,
    /// The objects' anchors, in the scene's order (held objects are not in the picture).
    pub labels: Vec<Label>,
}

/// The scene with its camera's field of view widened so that every object lies in the frame of
/// an image of the given aspect (width / height).
pub fn framed(scene: &Scene, world: &World, aspect: f32) -> Scene {
    let mut out = scene.clone();
    let c = &scene.camera;
    let (fwd, right, up, eye) = (c.forward(), c.right(), c.up(), c.eye());
    // The tangent of the half field of view each corner needs.
    let mut need = (c.fov_y_degrees.to_radians() * 0.5).tan();
    for id in scene.ids() {
        let Some(b) = world.aabb(id) else { continue };
        for k in 0..8 {
            let corner = Vector::new(
                if k & 1 == 0 { b.mins.x } else { b.maxs.x },
                if k & 2 == 0 { b.mins.y } else { b.maxs.y },
                if k & 4 == 0 { b.mins.z } else { b.maxs.z },
            );
            let rel = corner - eye;
            let z = rel.dot(fwd);
            if z <= 1e-3 {
                continue;
            }
            let h = (rel.dot(up) / z)
                .abs()
                .max(rel.dot(right).abs() / (z * aspect));
            need = need.max(h * (1.0 + MARGIN));
        }
    }
    out.camera.fov_y_degrees = (2.0 * need.atan().to_degrees()).min(MAX_FOV);
    out
}

/// The framed camera picture of the scene, `width` x `height`, every object labelled.
pub fn picture(scene: &Scene, width: u32, height: u32) -> Picture {
    let world = World::build(scene);
    let aspect = width as f32 / height as f32;
    let view = framed(scene, &world, aspect);
    let mut image = render_camera_world(&view, &world, width, height);
    let mut labels = Vec::new();
    for id in scene.ids() {
        let Some(b) = world.aabb(id) else { continue };
        // The object's box in the image: its right edge's middle is the anchor.
        let (mut right, mut top, mut bottom) = (f32::MIN, f32::MAX, f32::MIN);
        for k in 0..8 {
            let corner = Vector::new(
                if k & 1 == 0 { b.mins.x } else { b.maxs.x },
                if k & 2 == 0 { b.mins.y } else { b.maxs.y },
                if k & 4 == 0 { b.mins.z } else { b.maxs.z },
            );
            if let Some((u, v)) = project(&view, corner, aspect) {
                right = right.max(u);
                top = top.min(v);
                bottom = bottom.max(v);
            }
        }
        if right == f32::MIN {
            continue;
        }
        labels.push(Label {
            name: scene.object(id).name.clone(),
            x: (right * width as f32).clamp(0.0, width as f32),
            y: (0.5 * (top + bottom) * height as f32).clamp(0.0, height as f32),
        });
    }
    draw_labels(&mut image, &labels);
    Picture { image, labels }
}

/// The rows of a glyph, five bits each (the high bit is the left column); `None` for a blank.
fn glyph(c: char) -> Option<[u8; 7]> {
    Some(match c.to_ascii_uppercase() {
        'A' => [0x0E, 0x11, 0x11, 0x11, 0x1F, 0x11, 0x11],
        'B' => [0x1E, 0x11, 0x11, 0x1E, 0x11, 0x11, 0x1E],
        'C' => [0x0E, 0x11, 0x10, 0x10, 0x10, 0x11, 0x0E],
        'D' => [0x1C, 0x12, 0x11, 0x11, 0x11, 0x12, 0x1C],
        'E' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F],
        'F' => [0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x10],
        'G' => [0x0E, 0x11, 0x10, 0x17, 0x11, 0x11, 0x0F],
        'H' => [0x11, 0x11, 0x11, 0x1F, 0x11, 0x11, 0x11],
        'I' => [0x0E, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E],
        'J' => [0x07, 0x02, 0x02, 0x02, 0x02, 0x12, 0x0C],
        'K' => [0x11, 0x12, 0x14, 0x18, 0x14, 0x12, 0x11],
        'L' => [0x10, 0x10, 0x10, 0x10, 0x10, 0x10, 0x1F],
        'M' => [0x11, 0x1B, 0x15, 0x15, 0x11, 0x11, 0x11],
        'N' => [0x11, 0x11, 0x19, 0x15, 0x13, 0x11, 0x11],
        'O' => [0x0E, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E],
        'P' => [0x1E, 0x11, 0x11, 0x1E, 0x10, 0x10, 0x10],
        'Q' => [0x0E, 0x11, 0x11, 0x11, 0x15, 0x12, 0x0D],
        'R' => [0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11],
        'S' => [0x0F, 0x10, 0x10, 0x0E, 0x01, 0x01, 0x1E],
        'T' => [0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04],
        'U' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E],
        'V' => [0x11, 0x11, 0x11, 0x11, 0x11, 0x0A, 0x04],
        'W' => [0x11, 0x11, 0x11, 0x15, 0x15, 0x15, 0x0A],
        'X' => [0x11, 0x11, 0x0A, 0x04, 0x0A, 0x11, 0x11],
        'Y' => [0x11, 0x11, 0x11, 0x0A, 0x04, 0x04, 0x04],
        'Z' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x10, 0x1F],
        '0' => [0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E],
        '1' => [0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E],
        '2' => [0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F],
        '3' => [0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E],
        '4' => [0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02],
        '5' => [0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E],
        '6' => [0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E],
        '7' => [0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08],
        '8' => [0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E],
        '9' => [0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C],
        '_' => [0, 0, 0, 0, 0, 0, 0x1F],
        _ => return None,
    })
}

/// A placed label box in pixels: left, top, width, height.
type Rect = (i64, i64, i64, i64);

fn overlaps(a: Rect, b: Rect) -> bool {
    a.0 < b.0 + b.2 && b.0 < a.0 + a.2 && a.1 < b.1 + b.3 && b.1 < a.1 + a.3
}

/// Draws each label beside its anchor: dark capitals on a light box with a dark tick to the
/// anchor; a label that would overlap one already drawn moves down, then up.
pub fn draw_labels(image: &mut Image, labels: &[Label]) {
    let scale: i64 = if image.width >= 480 { 2 } else { 1 };
    let (w, h) = (image.width as i64, image.height as i64);
    let (pad, tick) = (2 * scale, 6 * scale);
    let mut placed: Vec<Rect> = Vec::new();
    // Top to bottom, so that a tower's labels keep its order.
    let mut order: Vec<&Label> = labels.iter().collect();
    order.sort_by(|a, b| a.y.total_cmp(&b.y).then(a.name.cmp(&b.name)));
    for l in order {
        let chars = l.name.chars().count() as i64;
        let bw = chars * 6 * scale - scale + 2 * pad;
        let bh = 7 * scale + 2 * pad;
        let (ax, ay) = (l.x.round() as i64, l.y.round() as i64);
        let x = if ax + tick + bw <= w {
            ax + tick
        } else {
            (ax - 2 * tick - bw).max(0)
        };
        let centred = (ay - bh / 2).clamp(0, (h - bh).max(0));
        // Candidate rows: the centred one, then alternately lower and higher.
        let y = (0..64)
            .map(|k: i64| {
                let step = (k + 1) / 2 * (bh + scale);
                if k % 2 == 1 {
                    centred + step
                } else {
                    centred - step
                }
            })
            .filter(|&y| y >= 0 && y + bh <= h)
            .find(|&y| !placed.iter().any(|&r| overlaps(r, (x, y, bw, bh))))
            .unwrap_or(centred);
        placed.push((x, y, bw, bh));
        // The tick from the anchor to the box's nearer side, then along it to the text's middle.
        let (x0, x1) = if x > ax { (ax, x) } else { (x + bw, ax) };
        let my = y + bh / 2;
        for xx in x0..x1 {
            let yy = ay + (my - ay) * (xx - x0) / (x1 - x0).max(1);
            let yy = if x > ax {
                yy
            } else {
                my + (ay - my) * (xx - x0) / (x1 - x0).max(1)
            };
            for d in 0..scale {
                put(image, xx, yy + d, [40, 40, 40]);
            }
        }
        for yy in y..y + bh {
            for xx in x..x + bw {
                blend(image, xx, yy, [255, 255, 255], 0.8);
            }
        }
        for (i, c) in l.name.chars().enumerate() {
            let Some(rows) = glyph(c) else { continue };
            let gx = x + pad + i as i64 * 6 * scale;
            for (r, bits) in rows.iter().enumerate() {
                for col in 0..5 {
                    if bits & (0x10 >> col) == 0 {
                        continue;
                    }
                    for sy in 0..scale {
                        for sx in 0..scale {
                            put(
                                image,
                                gx + col * scale + sx,
                                y + pad + r as i64 * scale + sy,
                                [20, 20, 20],
                            );
                        }
                    }
                }
            }
        }
    }
}

fn put(image: &mut Image, x: i64, y: i64, rgb: [u8; 3]) {
    blend(image, x, y, rgb, 1.0);
}

fn blend(image: &mut Image, x: i64, y: i64, rgb: [u8; 3], alpha: f32) {
    if x < 0 || y < 0 || x >= image.width as i64 || y >= image.height as i64 {
        return;
    }
    let i = 3 * (y as usize * image.width as usize + x as usize);
    for (old, new) in image.rgb[i..i + 3].iter_mut().zip(rgb) {
        *old = (*old as f32 + alpha * (new as f32 - *old as f32)).round() as u8;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{generate, Colour, GenerateConfig, ObjectKind, Preset, Size};

    /// Whether a world point lies inside the frame of `scene`'s camera.
    fn inside(scene: &Scene, p: Vector, aspect: f32) -> bool {
        project(scene, p, aspect)
            .is_some_and(|(u, v)| (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v))
    }

    /// A tower of four objects at the back of the table: its top leaves the robot's own frame
    /// (the camera looks down at the middle), and the framed picture takes it in.
    #[test]
    fn a_tall_tower_at_the_back_is_in_the_framed_picture() {
        let mut scene = Scene::custom(1);
        let top_of_table = 0.0;
        let side = ObjectKind::Cube
            .shape(Size::Large)
            .compute_local_aabb()
            .extents()
            .y;
        for i in 0..4 {
            let bottom = top_of_table + side * i as f32;
            scene.add_resting(
                &format!("cube_{i}"),
                ObjectKind::Cube,
                Colour::Red,
                Size::Large,
                (0.0, bottom, 0.4),
            );
        }
        let world = World::build(&scene);
        let top_id = scene.ids().last().unwrap();
        let b = world.aabb(top_id).unwrap();
        let top = Vector::new(0.0, b.maxs.y, b.maxs.z);
        let aspect = 640.0 / 480.0;
        assert!(
            !inside(&scene, top, aspect),
            "the test needs a tower the camera crops"
        );
        let view = framed(&scene, &world, aspect);
        assert!(inside(&view, top, aspect));
        assert!(view.camera.fov_y_degrees > scene.camera.fov_y_degrees);
        assert_eq!(view.camera.eye, scene.camera.eye);
    }

    #[test]
    fn a_generated_scene_keeps_the_cameras_view_and_gets_every_label() {
        let scene = generate(&GenerateConfig::new(Preset::Real, 3)).unwrap();
        let world = World::build(&scene);
        let view = framed(&scene, &world, 640.0 / 480.0);
        assert!(view.camera.fov_y_degrees >= scene.camera.fov_y_degrees);
        let p = picture(&scene, 320, 240);
        assert_eq!(p.labels.len(), scene.objects.len());
        for l in &p.labels {
            assert!(
                (0.0..=320.0).contains(&l.x) && (0.0..=240.0).contains(&l.y),
                "{l:?}"
            );
        }
        // Label text is drawn: the picture differs from the unlabelled render.
        let plain = render_camera_world(&view, &world, 320, 240);
        assert_ne!(plain.rgb, p.image.rgb);
    }

    #[test]
    fn every_constant_character_has_a_glyph() {
        for c in "abcdefghijklmnopqrstuvwxyz0123456789_".chars() {
            assert!(glyph(c).is_some(), "{c}");
        }
        assert!(glyph('(').is_none());
    }
}
