//! Labelled scenes, generated in parallel by seed: a risky scene (`scenes`), what the robot
//! perceives of it at step 0 (relations, sizes and surfaces through the error model), the true
//! relations, and per object its ground-truth labels (`labels`) with its stability and occlusion
//! ROIs cropped from the camera image (`roi`).
//!
//! Per object: `supports` are the objects below it in its tower, nearest first (from the true
//! `on` relations, `labels::supports`); it is `stacked` if it has any. The stability ROI covers
//! it and its supports in the camera image; the occlusion ROI is cut from the picture of the
//! [`frontal_camera`], centred on the object and twice its size, and re-expressed relative to
//! the object's colour (`roi::relative_to_colour`: the network must know which object in the
//! crop it is asked about), while `occlusion_box` keeps the
//! union of its box and its possible occluders' (`roi::occluder_ids`) in the camera image. The
//! pictures are rendered to crop the ROIs and then dropped: [`image`] renders the camera image
//! again on demand (images are not stored).
//!
//! Invariants: a labelled scene is a function of `(config, preset, seed)` alone, whatever the
//! number of threads; [`generate`] returns the scenes in seed order, seed `i` using
//! `presets[i % presets.len()]`, and skips the seeds whose scene cannot be generated (a preset
//! that risky scenes do not support; no other failure is known), so a caller that needs every
//! seed compares the returned seeds with the range.

use super::labels::{label_world, supports, LabelConfig, ObjectLabels};
use super::roi::{crop_resize, group_box, occluder_ids, relative_to_colour, PixelBox, ROI_SIZE};
use super::scenes::{generate_risky, RiskyConfig};
use crate::sim::perceive::perceive_world;
use crate::sim::render::{render_camera, render_camera_world};
use crate::sim::truth::relations;
use crate::sim::{
    Camera, ErrorModel, Image, ObjectId, Percept, Preset, Relation, Scene, SimError, TruthConfig,
    World,
};
use serde::{Deserialize, Serialize};

/// What to generate and how to label it.
#[derive(Clone, Debug, PartialEq)]
pub struct DatasetConfig {
    /// The presets, used in turn by seed (`Real` and `Simulated`).
    pub presets: Vec<Preset>,
    /// Width of the camera image in pixels.
    pub image_width: u32,
    /// Height of the camera image in pixels.
    pub image_height: u32,
    /// Perception's error model.
    pub error: ErrorModel,
    /// The thresholds of the true relations (and of perception, which reads them).
    pub truth: TruthConfig,
    /// The thresholds of the labels.
    pub labels: LabelConfig,
    /// ROI margin, as a fraction of the box's size on each side.
    pub margin: f32,
}

impl Default for DatasetConfig {
    /// Both presets, a 256 x 192 image, the default error model, truth and labels, margin 0.15.
    fn default() -> Self {
        DatasetConfig {
            presets: vec![Preset::Real, Preset::Simulated],
            image_width: 256,
            image_height: 192,
            error: ErrorModel::default(),
            truth: TruthConfig::default(),
            labels: LabelConfig::default(),
            margin: 0.15,
        }
    }
}

/// One object of a labelled scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LabelledObject {
    /// The object's name.
    pub name: String,
    /// True if it stands on another object.
    pub stacked: bool,
    /// The objects below it in its tower, nearest first.
    pub supports: Vec<String>,
    /// Its ground-truth labels.
    pub labels: ObjectLabels,
    /// The stability ROI, `ROI_SIZE x ROI_SIZE x 3`, HWC, values in `[0, 1]`.
    pub stability_roi: Vec<f32>,
    /// The occlusion ROI, `ROI_SIZE x ROI_SIZE x 3`, HWC, values in `[0, 1]`, from the frontal
    /// camera's picture.
    pub occlusion_roi: Vec<f32>,
    /// The stability ROI's box before margin and squaring, in image pixels.
    pub stability_box: PixelBox,
    /// The union of its box and its possible occluders' boxes in the camera image, in pixels
    /// (for drawing; the occlusion ROI is cut from the frontal picture).
    pub occlusion_box: PixelBox,
}

/// A labelled scene.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LabelledScene {
    /// The seed it was generated from.
    pub seed: u64,
    /// The preset it was generated with.
    #[serde(with = "preset_name")]
    pub preset: Preset,
    /// The scene as placed.
    pub scene: Scene,
    /// The perceived relations and attributes at step 0, through the error model.
    pub percept: Percept,
    /// The true relations, sorted.
    pub truth: Vec<Relation>,
    /// Per object, in scene order.
    pub objects: Vec<LabelledObject>,
}

/// Serialises a preset by its name (`sim::Preset` has no serde derive).
mod preset_name {
    use crate::sim::Preset;
    use serde::{Deserialize, Deserializer, Serializer};

    pub fn serialize<S: Serializer>(preset: &Preset, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(preset.name())
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Preset, D::Error> {
        let name = String::deserialize(d)?;
        Preset::parse(&name).map_err(serde::de::Error::custom)
    }
}

/// Generates and labels the scene of one seed.
pub fn labelled_scene(
    config: &DatasetConfig,
    preset: Preset,
    seed: u64,
) -> Result<LabelledScene, SimError> {
    let scene = generate_risky(&RiskyConfig::new(preset, seed))?;
    let mut out = labelled_from(config, scene)?;
    out.preset = preset;
    Ok(out)
}

/// Looks at and labels a given scene as it stands (its seed is the scene's, its preset the
/// scene's preset when it names one, else `real`): what `lucent classify` does with a scene
/// file.
pub fn labelled_from(config: &DatasetConfig, scene: Scene) -> Result<LabelledScene, SimError> {
    let seed = scene.seed;
    let preset = Preset::parse(&scene.preset).unwrap_or(Preset::Real);
    let world = World::build(&scene);
    let truth = relations(&scene, &world, &config.truth);
    let percept = perceive_world(&scene, &world, &config.error, &config.truth);
    let labels = label_world(&scene, &world, &config.labels);
    let chains = supports(&scene, &truth);
    let (w, h) = (config.image_width, config.image_height);
    let picture = render_camera_world(&scene, &world, w, h);
    let boxed = |ids: Vec<ObjectId>| {
        group_box(&scene, &world, &ids, w, h).ok_or_else(|| {
            SimError::MalformedScene("an object is behind the camera or held".into())
        })
    };
    let mut occlusion_rois = occlusion_rois(&scene, &world, w, h).into_iter();
    let mut objects = Vec::with_capacity(scene.objects.len());
    for (id, labels) in scene.ids().zip(labels) {
        let chain = &chains[id.index()];
        let stability_box = boxed(std::iter::once(id).chain(chain.iter().copied()).collect())?;
        let occluders = occluder_ids(&scene, id, &truth, &labels);
        let occlusion_box = boxed(std::iter::once(id).chain(occluders).collect())?;
        let occlusion_roi = occlusion_rois.next().flatten().ok_or_else(|| {
            SimError::MalformedScene("an object is behind the frontal camera or held".into())
        })?;
        objects.push(LabelledObject {
            name: scene.object(id).name.clone(),
            stacked: !chain.is_empty(),
            supports: chain
                .iter()
                .map(|&s| scene.object(s).name.clone())
                .collect(),
            labels,
            stability_roi: crop_resize(&picture, &stability_box, config.margin, ROI_SIZE),
            occlusion_roi,
            stability_box,
            occlusion_box,
        });
    }
    Ok(LabelledScene {
        seed,
        preset,
        scene,
        percept,
        truth,
        objects,
    })
}

/// Per object of the scene, in scene order, its occlusion ROI: cut from the picture of the
/// [`frontal_camera`] (the paper's robot has a top and a frontal view; this one looks along the
/// depth axis of `front`/`behind`, so the occlusion the labels measure is what its picture
/// shows), centred on the object, twice its size, so that the object asked about is always the
/// one in the middle and what stands in front of it shows over it (a union box of several
/// objects leaves the network guessing which one is asked about), and expressed relative to
/// the object's perceived colour (`roi::relative_to_colour`). `None` for an object held or
/// behind the frontal camera.
pub fn occlusion_rois(
    scene: &Scene,
    world: &World,
    width: u32,
    height: u32,
) -> Vec<Option<Vec<f32>>> {
    let mut frontal = scene.clone();
    frontal.camera = frontal_camera(&scene.camera);
    let picture = render_camera_world(&frontal, world, width, height);
    scene
        .ids()
        .map(|id| {
            let b = group_box(&frontal, world, &[id], width, height)?;
            let mut roi = crop_resize(&picture, &centred_box(&b, 2.0), 0.0, ROI_SIZE);
            relative_to_colour(&mut roi, scene.object(id).colour.rgb());
            Some(roi)
        })
        .collect()
}

/// The frontal camera of a scene's camera: on the same side of the table, 8 cm above it and
/// looking horizontally along the main camera's depth axis at the table's middle, from 10 m away
/// with a 3.72 degree field of view (the framing of a 36 degree view from 1 m). So distant, it
/// sees nearly the orthographic view in which `labels` measures occlusion: an object 30 cm nearer
/// than another looks 3% larger, where from 1 m it looked 43% larger and hid what the labels
/// call visible (the network learned 0.71 of the undecided examples from the 1 m view).
pub fn frontal_camera(main: &Camera) -> Camera {
    const DISTANCE: f32 = 10.0;
    let target = main.target;
    let depth = main.depth_axis();
    let fov = 2.0 * ((18.0f32).to_radians().tan() / DISTANCE).atan();
    Camera {
        eye: [
            target[0] - DISTANCE * depth.x,
            0.08,
            target[2] - DISTANCE * depth.z,
        ],
        target: [target[0], 0.08, target[2]],
        fov_y_degrees: fov.to_degrees(),
    }
}

/// The square box centred on `b` whose side is `scale` times `b`'s longer side.
fn centred_box(b: &PixelBox, scale: f32) -> PixelBox {
    let (cx, cy) = ((b.x0 + b.x1) / 2.0, (b.y0 + b.y1) / 2.0);
    let half = scale * b.width().max(b.height()) / 2.0;
    PixelBox {
        x0: cx - half,
        y0: cy - half,
        x1: cx + half,
        y1: cy + half,
    }
}

/// Generates the labelled scenes of a range of seeds in parallel (rayon, one scene per task),
/// in seed order; seed `i` uses `presets[i % presets.len()]`. Seeds whose scene cannot be
/// generated are skipped (see the module documentation). Panics if `presets` is empty.
pub fn generate(config: &DatasetConfig, seeds: std::ops::Range<u64>) -> Vec<LabelledScene> {
    generate_with(config, seeds, &|| ())
}

/// [`generate`], calling `done` once per seed as its scene is finished (from any thread, in
/// any order): a progress bar's tick.
pub fn generate_with(
    config: &DatasetConfig,
    seeds: std::ops::Range<u64>,
    done: &(dyn Fn() + Sync),
) -> Vec<LabelledScene> {
    use rayon::prelude::*;
    assert!(!config.presets.is_empty(), "a dataset needs a preset");
    let seeds: Vec<u64> = seeds.collect();
    seeds
        .par_iter()
        .map(|&seed| {
            let preset = config.presets[(seed % config.presets.len() as u64) as usize];
            let scene = labelled_scene(config, preset, seed).ok();
            done();
            scene
        })
        .collect::<Vec<_>>()
        .into_iter()
        .flatten()
        .collect()
}

/// Renders a labelled scene's camera image again, as its ROIs were cropped from.
pub fn image(config: &DatasetConfig, scene: &LabelledScene) -> Image {
    render_camera(&scene.scene, config.image_width, config.image_height)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::perceive::Literal;

    #[test]
    fn same_seed_gives_the_same_labelled_scene() {
        let config = DatasetConfig::default();
        let a = labelled_scene(&config, Preset::Simulated, 11).unwrap();
        let b = labelled_scene(&config, Preset::Simulated, 11).unwrap();
        assert_eq!(a, b);
        let json = serde_json::to_string(&a).unwrap();
        let back: LabelledScene = serde_json::from_str(&json).unwrap();
        assert_eq!(back.preset, a.preset);
        assert_eq!(back.objects.len(), a.objects.len());
        assert_eq!(json, serde_json::to_string(&b).unwrap());
    }

    #[test]
    fn small_dataset_has_full_rois_and_perceived_statics() {
        let config = DatasetConfig::default();
        let data = generate(&config, 0..6);
        assert_eq!(
            data.iter().map(|s| s.seed).collect::<Vec<_>>(),
            (0..6).collect::<Vec<_>>()
        );
        let mut stacked = 0;
        for s in &data {
            assert_eq!(s.preset, config.presets[(s.seed % 2) as usize]);
            assert_eq!(s.objects.len(), s.scene.objects.len());
            for o in &s.objects {
                for roi in [&o.stability_roi, &o.occlusion_roi] {
                    assert_eq!(roi.len(), ROI_SIZE * ROI_SIZE * 3);
                    assert!(roi.iter().all(|v| (0.0..=1.0).contains(v)));
                }
                assert_eq!(o.stacked, !o.supports.is_empty());
                stacked += usize::from(o.stacked);
                let facts: Vec<&Literal> = s.percept.facts().map(|f| &f.literal).collect();
                assert!(facts
                    .iter()
                    .any(|l| matches!(l, Literal::HasSize(n, _) if *n == o.name)));
                assert!(facts
                    .iter()
                    .any(|l| matches!(l, Literal::HasSurface(n, _) if *n == o.name)));
            }
        }
        assert!(stacked >= 6, "{stacked} stacked objects in 6 scenes");
        let picture = image(&config, &data[0]);
        assert_eq!((picture.width, picture.height), (256, 192));
    }
}
