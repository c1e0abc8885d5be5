//! Regions of interest: image boxes of objects and groups of objects, cropped and resized to the
//! network's `ROI_SIZE x ROI_SIZE x 3` input.
//!
//! An object's box is its world bounding box's eight corners projected through the camera
//! (`sim::truth::project`, with the image's aspect), in pixel coordinates (x right, y down, the
//! image spanning `[0, width] x [0, height]`). Two ROIs per object:
//! * the **stability ROI**: the union of the object's box and the boxes of every object below it
//!   in its tower (what supports it, down to the table);
//! * the **occlusion ROI**: the union of the object's box and the boxes of its possible occluders:
//!   the objects measured hiding part of it (`labels`) and those in front of it that overlap it
//!   laterally (truth's geometric `front` relation).
//!
//! Cropping (`crop_resize`): the box grows by `margin` times its width (height) on each side, is
//! made square around its centre with the longer side, and is resampled bilinearly to
//! `size x size` samples at the centres of the output pixels. A sample outside the image is 0 (the
//! image is padded with black); inside, the four neighbouring pixel centres are interpolated,
//! their indices clamped to the image.
//!
//! Invariants: an ROI has `size * size * 3` values in `[0, 1]`, layout HWC row-major
//! (`(y * size + x) * 3 + c`), the same layout as `vision::cnn`'s input.

use super::labels::ObjectLabels;
use crate::sim::truth::{project, Rel, Relation};
use crate::sim::{Image, ObjectId, Scene, World};
use serde::{Deserialize, Serialize};

/// The side of a region of interest fed to the network, in pixels.
pub const ROI_SIZE: usize = 56;

/// An axis-aligned box in pixel coordinates (x right, y down), `x0 <= x1`, `y0 <= y1`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PixelBox {
    /// Left edge.
    pub x0: f32,
    /// Top edge.
    pub y0: f32,
    /// Right edge.
    pub x1: f32,
    /// Bottom edge.
    pub y1: f32,
}

impl PixelBox {
    /// Width in pixels.
    pub fn width(&self) -> f32 {
        self.x1 - self.x0
    }

    /// Height in pixels.
    pub fn height(&self) -> f32 {
        self.y1 - self.y0
    }

    /// The centre (x, y).
    pub fn centre(&self) -> (f32, f32) {
        (0.5 * (self.x0 + self.x1), 0.5 * (self.y0 + self.y1))
    }
}

/// The box of an object in an image of `width x height` pixels: its bounding box's corners
/// projected through the camera. `None` if it is held or a corner is behind the camera.
pub fn object_box(
    scene: &Scene,
    world: &World,
    id: ObjectId,
    width: u32,
    height: u32,
) -> Option<PixelBox> {
    let aabb = world.aabb(id)?;
    let aspect = width as f32 / height as f32;
    let mut out = PixelBox {
        x0: f32::INFINITY,
        y0: f32::INFINITY,
        x1: f32::NEG_INFINITY,
        y1: f32::NEG_INFINITY,
    };
    for corner in aabb.vertices() {
        let (u, v) = project(scene, corner, aspect)?;
        let (x, y) = (u * width as f32, v * height as f32);
        out.x0 = out.x0.min(x);
        out.y0 = out.y0.min(y);
        out.x1 = out.x1.max(x);
        out.y1 = out.y1.max(y);
    }
    Some(out)
}

/// The smallest box holding all the boxes, or `None` if there are none.
pub fn union<'a>(boxes: impl IntoIterator<Item = &'a PixelBox>) -> Option<PixelBox> {
    boxes.into_iter().fold(None, |acc, b| {
        Some(match acc {
            None => *b,
            Some(a) => PixelBox {
                x0: a.x0.min(b.x0),
                y0: a.y0.min(b.y0),
                x1: a.x1.max(b.x1),
                y1: a.y1.max(b.y1),
            },
        })
    })
}

/// The union of the boxes of some objects; `None` if any of them has no box or the list is
/// empty.
pub fn group_box(
    scene: &Scene,
    world: &World,
    ids: &[ObjectId],
    width: u32,
    height: u32,
) -> Option<PixelBox> {
    let boxes = ids
        .iter()
        .map(|&id| object_box(scene, world, id, width, height))
        .collect::<Option<Vec<_>>>()?;
    union(&boxes)
}

/// The objects of an object's occlusion ROI besides itself: those its labels name as occluders
/// and those truly in front of it (`front(other, it)` in `relations`, which requires lateral
/// overlap), in scene order.
pub fn occluder_ids(
    scene: &Scene,
    id: ObjectId,
    relations: &[Relation],
    labels: &ObjectLabels,
) -> Vec<ObjectId> {
    let name = &scene.object(id).name;
    let mut out: Vec<ObjectId> = relations
        .iter()
        .filter(|r| r.rel == Rel::Front && &r.b == name)
        .map(|r| r.a.as_str())
        .chain(labels.occluders.iter().map(|(o, _)| o.as_str()))
        .filter_map(|o| scene.find(o))
        .filter(|&o| o != id)
        .collect();
    out.sort();
    out.dedup();
    out
}

/// Crops the box, grown by `margin` times its size on each side and made square around its
/// centre, out of the image (black outside it) and resamples it bilinearly to `size x size x 3`
/// values in `[0, 1]`, HWC row-major.
pub fn crop_resize(image: &Image, b: &PixelBox, margin: f32, size: usize) -> Vec<f32> {
    let (w, h) = (b.width().max(0.0), b.height().max(0.0));
    let side = (w * (1.0 + 2.0 * margin))
        .max(h * (1.0 + 2.0 * margin))
        .max(1.0);
    let (cx, cy) = b.centre();
    let (left, top) = (cx - 0.5 * side, cy - 0.5 * side);
    let step = side / size as f32;
    let (iw, ih) = (image.width as f32, image.height as f32);
    let last_x = image.width.saturating_sub(1) as i64;
    let last_y = image.height.saturating_sub(1) as i64;
    let texel = |x: i64, y: i64, c: usize| -> f32 {
        let i =
            3 * (y.clamp(0, last_y) as usize * image.width as usize + x.clamp(0, last_x) as usize);
        image.rgb[i + c] as f32 / 255.0
    };
    let mut out = vec![0.0f32; size * size * 3];
    for oy in 0..size {
        let sy = top + (oy as f32 + 0.5) * step;
        if !(0.0..ih).contains(&sy) {
            continue;
        }
        let fy = sy - 0.5;
        let y0 = fy.floor();
        let ty = fy - y0;
        for ox in 0..size {
            let sx = left + (ox as f32 + 0.5) * step;
            if !(0.0..iw).contains(&sx) {
                continue;
            }
            let fx = sx - 0.5;
            let x0 = fx.floor();
            let tx = fx - x0;
            let (x0, y0) = (x0 as i64, y0 as i64);
            for c in 0..3 {
                let top_row = texel(x0, y0, c) * (1.0 - tx) + texel(x0 + 1, y0, c) * tx;
                let bottom_row = texel(x0, y0 + 1, c) * (1.0 - tx) + texel(x0 + 1, y0 + 1, c) * tx;
                out[(oy * size + ox) * 3 + c] =
                    (top_row * (1.0 - ty) + bottom_row * ty).clamp(0.0, 1.0);
            }
        }
    }
    out
}

/// The ROI mirrored left to right (`size x size x 3`, HWC): the labels do not change under
/// the mirror (a tower topples, an object hides another, whichever side it is on), so the
/// mirrored ROIs double a training set.
pub fn mirrored(roi: &[f32], size: usize) -> Vec<f32> {
    let mut out = vec![0.0; roi.len()];
    for y in 0..size {
        for x in 0..size {
            let (from, to) = ((y * size + x) * 3, (y * size + size - 1 - x) * 3);
            out[to..to + 3].copy_from_slice(&roi[from..from + 3]);
        }
    }
    out
}

/// Re-expresses an ROI relative to the colour of the object asked about, in place: for each
/// pixel `p`, channels 0 and 1 are twice the absolute differences of its red and green
/// chromaticities (`p / sum(p)`) from the object's, channel 2 is half its brightness (`sum(p)`)
/// over the object's unshaded brightness; each clamped to `[0, 1]`. The renderer shades a colour
/// `c` as `(k c)^(1/1.2)` with one factor `k` per pixel, so the object's own pixels have
/// chromaticity differences 0 whatever their shading and brightness ratios in `[0.2, 0.5]`,
/// while an occluder of another hue or lightness stands out. A black pixel (padding) counts as
/// neutral grey chromaticity with brightness 0.
pub fn relative_to_colour(roi: &mut [f32], colour: [f32; 3]) {
    let target = colour.map(|c| c.max(0.0).powf(1.0 / 1.2));
    let total = target.iter().sum::<f32>().max(1e-6);
    let chroma = |p: [f32; 3], sum: f32| -> [f32; 2] {
        if sum <= 1e-6 {
            [1.0 / 3.0; 2]
        } else {
            [p[0] / sum, p[1] / sum]
        }
    };
    let t = chroma(target, total);
    for px in roi.chunks_exact_mut(3) {
        let p = [px[0], px[1], px[2]];
        let sum: f32 = p.iter().sum();
        let q = chroma(p, sum);
        px[0] = (2.0 * (q[0] - t[0]).abs()).clamp(0.0, 1.0);
        px[1] = (2.0 * (q[1] - t[1]).abs()).clamp(0.0, 1.0);
        px[2] = (0.5 * sum / total).clamp(0.0, 1.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::truth::project;
    use crate::sim::Scene;

    /// A 4 x 4 image whose red channel is `16 * (4 y + x)`, green `255 - red`, blue 0.
    fn ramp() -> Image {
        let mut rgb = Vec::new();
        for y in 0..4u32 {
            for x in 0..4u32 {
                let r = 16 * (4 * y + x) as u8;
                rgb.extend_from_slice(&[r, 255 - r, 0]);
            }
        }
        Image {
            width: 4,
            height: 4,
            rgb,
        }
    }

    fn whole() -> PixelBox {
        PixelBox {
            x0: 0.0,
            y0: 0.0,
            x1: 4.0,
            y1: 4.0,
        }
    }

    #[test]
    fn shrink_to_two_by_two_averages_quads() {
        // Output samples fall at source (1, 1), (3, 1), ...: each the mean of a 2 x 2 quad. The
        // top-left quad has red 0, 16, 64, 80: mean 40.
        let out = crop_resize(&ramp(), &whole(), 0.0, 2);
        assert_eq!(out.len(), 2 * 2 * 3);
        let red = |x: usize, y: usize| out[(y * 2 + x) * 3] * 255.0;
        assert!((red(0, 0) - 40.0).abs() < 1e-3);
        assert!((red(1, 0) - 72.0).abs() < 1e-3);
        assert!((red(0, 1) - 168.0).abs() < 1e-3);
        assert!((red(1, 1) - 200.0).abs() < 1e-3);
        let green = out[1] * 255.0;
        assert!((green - 215.0).abs() < 1e-3);
        assert!(out.iter().skip(2).step_by(3).all(|&b| b == 0.0));
    }

    #[test]
    fn enlarge_to_eight_by_eight_interpolates() {
        // Samples at source 0.25, 0.75, 1.25, ...: pixel coordinates -0.25 (clamped to pixel 0),
        // 0.25 (0.75 p0 + 0.25 p1), 0.75 (0.25 p0 + 0.75 p1), ...
        let out = crop_resize(&ramp(), &whole(), 0.0, 8);
        assert_eq!(out.len(), 8 * 8 * 3);
        let red = |x: usize, y: usize| out[(y * 8 + x) * 3] * 255.0;
        assert!(red(0, 0).abs() < 1e-3);
        assert!((red(1, 0) - 4.0).abs() < 1e-3);
        assert!((red(2, 0) - 12.0).abs() < 1e-3);
        assert!((red(7, 0) - 48.0).abs() < 1e-3);
        // Row 1 of the output samples pixel row 0.25: 0.75 row 0 + 0.25 row 1 (+64 * 0.25).
        assert!((red(1, 1) - 20.0).abs() < 1e-3);
        assert!((red(7, 7) - 240.0).abs() < 1e-3);
        assert!(out.iter().all(|v| (0.0..=1.0).contains(v)));
    }

    #[test]
    fn outside_the_image_is_black() {
        // A 4 x 4 box from (2, 2): samples at 3 (inside, pixel coordinate 2.5 = mean of pixels 2
        // and 3) and 5 (outside, 0).
        let b = PixelBox {
            x0: 2.0,
            y0: 2.0,
            x1: 6.0,
            y1: 6.0,
        };
        let out = crop_resize(&ramp(), &b, 0.0, 2);
        let red = |x: usize, y: usize| out[(y * 2 + x) * 3] * 255.0;
        // Pixels (2,2), (3,2), (2,3), (3,3): red 160, 176, 224, 240: mean 200.
        assert!((red(0, 0) - 200.0).abs() < 1e-3);
        assert_eq!(red(1, 0), 0.0);
        assert_eq!(red(0, 1), 0.0);
        assert_eq!(red(1, 1), 0.0);
        assert!(out[(2 + 1) * 3 + 1] == 0.0);
    }

    #[test]
    fn margin_and_squaring() {
        // A 2 x 1 box at the image centre with margin 0.5 becomes 4 x 2, then square 4 x 4: the
        // whole image.
        let b = PixelBox {
            x0: 1.0,
            y0: 1.5,
            x1: 3.0,
            y1: 2.5,
        };
        assert_eq!(
            crop_resize(&ramp(), &b, 0.5, 2),
            crop_resize(&ramp(), &whole(), 0.0, 2)
        );
    }

    #[test]
    fn union_and_projection() {
        let a = PixelBox {
            x0: 1.0,
            y0: 2.0,
            x1: 3.0,
            y1: 4.0,
        };
        let b = PixelBox {
            x0: 0.0,
            y0: 3.0,
            x1: 2.0,
            y1: 5.0,
        };
        let u = union([&a, &b]).unwrap();
        assert_eq!((u.x0, u.y0, u.x1, u.y1), (0.0, 2.0, 3.0, 5.0));
        assert!(union(std::iter::empty()).is_none());
        let scene = Scene::custom(0);
        let c = &scene.camera;
        let on_axis = c.eye() + c.forward() * 0.8;
        let (x, y) = project(&scene, on_axis, 256.0 / 192.0).unwrap();
        assert!((x * 256.0 - 128.0).abs() < 1e-3 && (y * 192.0 - 96.0).abs() < 1e-3);
        // A point right of the axis lands right of the centre, one above it higher.
        let (xr, _) = project(&scene, on_axis + c.right() * 0.05, 1.0).unwrap();
        let (_, yu) = project(&scene, on_axis + c.up() * 0.05, 1.0).unwrap();
        assert!(xr > 0.5 && yu < 0.5);
    }

    #[test]
    fn object_box_centres_an_object_on_the_axis() {
        let mut scene = Scene::custom(0);
        let c = scene.camera.clone();
        // The point where the camera's axis meets the table top, and a small cube centred there.
        let t = -c.eye[1] / c.forward().y;
        let hit = c.eye() + c.forward() * t;
        let id = scene.add(
            "cube",
            crate::sim::ObjectKind::Cube,
            crate::sim::Colour::Red,
            crate::sim::Size::Small,
            [hit.x, 0.0, hit.z],
            0.0,
        );
        let world = World::build(&scene);
        let b = object_box(&scene, &world, id, 256, 192).unwrap();
        let (x, _) = b.centre();
        assert!((x - 128.0).abs() < 1e-3, "{b:?}");
        assert!(b.y0 < 96.0 && b.y1 > 96.0);
    }

    #[test]
    fn relative_to_colour_by_hand() {
        // The object's colour (0.5, 0.25, 0.25) renders unshaded as c^(1/1.2); call it (a, b, b)
        // with a = 0.5^(1/1.2) = 0.5612, b = 0.25^(1/1.2) = 0.3150, sum 1.1912, chromaticity
        // (0.4711, 0.2644). Pixel 1 is the object at half shading (k = 0.5): every channel times
        // 0.5^(1/1.2) = 0.5612, so differences 0 and brightness 0.5 * 0.5612 = 0.2806. Pixel 2
        // is pure green (0, 1, 0): differences 2 * 0.4711 = 0.9422 and 2 * 0.7356 -> 1 (clamped),
        // brightness 0.5 / 1.1912 = 0.4197. Pixel 3 is padding (0, 0, 0): chromaticity 1/3,
        // differences 2 * 0.1378 = 0.2756 and 2 * 0.0689 = 0.1378, brightness 0.
        let a = 0.5f32.powf(1.0 / 1.2);
        let b = 0.25f32.powf(1.0 / 1.2);
        let k = 0.5f32.powf(1.0 / 1.2);
        let mut roi = vec![a * k, b * k, b * k, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0];
        relative_to_colour(&mut roi, [0.5, 0.25, 0.25]);
        let expected = [0.0, 0.0, 0.2806, 0.9422, 1.0, 0.4197, 0.2756, 0.1378, 0.0];
        for (got, want) in roi.iter().zip(expected) {
            assert!((got - want).abs() < 1e-3, "{roi:?}");
        }
    }

    #[test]
    fn mirrored_swaps_columns() {
        // A 2 x 2 ROI, pixels numbered 0..4 row by row (channel c of pixel i is 10 i + c):
        // mirrored, row 0 reads pixel 1 then 0, row 1 pixel 3 then 2.
        let roi: Vec<f32> = (0..4)
            .flat_map(|i| (0..3).map(move |c| (10 * i + c) as f32))
            .collect();
        let expected: Vec<f32> = [1, 0, 3, 2]
            .iter()
            .flat_map(|&i| (0..3).map(move |c| (10 * i + c) as f32))
            .collect();
        assert_eq!(mirrored(&roi, 2), expected);
    }
}
