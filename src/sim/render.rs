//! Pictures: ray-cast colour images of a scene from the robot's camera and from above, and
//! their PNG encoding (the `png` crate).
//!
//! Invariants: rendering reads the world and never changes it; each pixel is the first hit of one
//! ray through its centre, shaded by a Lambert term, an ambient term and a shadow ray, so the
//! image is a deterministic function of the scene.

use super::scene::{Scene, TABLE_HALF_EXTENTS};
use super::truth::pixel_ray;
use super::world::{Hit, World};
use super::SimError;
use parry3d::math::Vector;

/// An 8-bit RGB image, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Row-major RGB bytes, `3 * width * height` of them.
    pub rgb: Vec<u8>,
}

impl Image {
    /// The colour of a pixel.
    pub fn pixel(&self, x: u32, y: u32) -> [u8; 3] {
        let i = 3 * (y * self.width + x) as usize;
        [self.rgb[i], self.rgb[i + 1], self.rgb[i + 2]]
    }

    /// Encodes the image as PNG.
    pub fn to_png(&self) -> Result<Vec<u8>, SimError> {
        let mut out = Vec::new();
        {
            let mut encoder = png::Encoder::new(&mut out, self.width, self.height);
            encoder.set_color(png::ColorType::Rgb);
            encoder.set_depth(png::BitDepth::Eight);
            let mut writer = encoder
                .write_header()
                .map_err(|e| SimError::Render(e.to_string()))?;
            writer
                .write_image_data(&self.rgb)
                .map_err(|e| SimError::Render(e.to_string()))?;
        }
        Ok(out)
    }
}

/// Direction towards the light (a lamp above, behind and left of the camera).
fn light() -> Vector {
    Vector::new(0.35, 1.0, -0.45).normalize()
}

const TABLE_RGB: [f32; 3] = [0.72, 0.58, 0.40];
const FLOOR_RGB: [f32; 3] = [0.35, 0.35, 0.38];
const SKY_RGB: [f32; 3] = [0.86, 0.90, 0.95];

/// Shades the first hit of a ray.
fn shade(scene: &Scene, world: &World, origin: Vector, dir: Vector) -> [u8; 3] {
    let colour = match world.cast(origin, dir, 20.0) {
        None => SKY_RGB,
        Some((hit, t, normal)) => {
            let base = match hit {
                Hit::Object(id) => scene.object(id).colour.rgb(),
                Hit::Table => {
                    let p = origin + dir * t;
                    // Faint boards make the table's perspective readable.
                    let board = ((p.x * 10.0).floor() as i32).rem_euclid(2) as f32;
                    let [r, g, b] = TABLE_RGB;
                    [r - 0.04 * board, g - 0.04 * board, b - 0.03 * board]
                }
                Hit::Floor => FLOOR_RGB,
            };
            let n = if normal.dot(dir) > 0.0 {
                -normal
            } else {
                normal
            };
            let p = origin + dir * t + n * 1e-3;
            let l = light();
            let lit = world.cast(p, l, 5.0).is_none();
            let diffuse = if lit { n.dot(l).max(0.0) } else { 0.0 };
            let k = 0.35 + 0.65 * diffuse;
            base.map(|c| c * k)
        }
    };
    colour.map(|c| (c.clamp(0.0, 1.0).powf(1.0 / 1.2) * 255.0).round() as u8)
}

/// Renders the scene from its camera.
pub fn render_camera(scene: &Scene, width: u32, height: u32) -> Image {
    let world = World::build(scene);
    render_camera_world(scene, &world, width, height)
}

/// Renders from the camera a scene whose world is already built.
pub fn render_camera_world(scene: &Scene, world: &World, width: u32, height: u32) -> Image {
    let aspect = width as f32 / height as f32;
    let eye = scene.camera.eye();
    let mut rgb = Vec::with_capacity((3 * width * height) as usize);
    for y in 0..height {
        for x in 0..width {
            let u = (x as f32 + 0.5) / width as f32;
            let v = (y as f32 + 0.5) / height as f32;
            rgb.extend_from_slice(&shade(scene, world, eye, pixel_ray(scene, u, v, aspect)));
        }
    }
    Image { width, height, rgb }
}

/// Renders the table from straight above (orthographic), the camera's side at the bottom.
pub fn render_top(scene: &Scene, width: u32, height: u32) -> Image {
    let world = World::build(scene);
    let [hx, _, hz] = TABLE_HALF_EXTENTS;
    let (sx, sz) = (2.0 * hx * 1.05, 2.0 * hz * 1.05);
    let scale = (sx / width as f32).max(sz / height as f32);
    let mut rgb = Vec::with_capacity((3 * width * height) as usize);
    let down = Vector::new(0.0, -1.0, 0.0);
    for y in 0..height {
        for x in 0..width {
            // Image right is world -x and image up is world +z, as seen by the robot's camera.
            let wx = -((x as f32 + 0.5) - 0.5 * width as f32) * scale;
            let wz = (0.5 * height as f32 - (y as f32 + 0.5)) * scale;
            rgb.extend_from_slice(&shade(scene, &world, Vector::new(wx, 2.0, wz), down));
        }
    }
    Image { width, height, rgb }
}
