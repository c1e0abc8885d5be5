//! Golden test of scene understanding on one small hand-built scene: what the robot decides
//! about each object, and where each decision comes from, with perfect perception and KB_full.
//!
//! The scene (positions in metres; the camera looks along +z from z = -0.7):
//! - `blue_ball` (medium ball) on the table at x = -0.2, with `red_cube` (small) placed on it;
//! - `green_cube` (large) on the table at x = 0.1, with `white_cube` (small) centred on it;
//! - `yellow_cube` (medium) on the table at x = 0.1, 0.25 m behind `green_cube`.
//!
//! Expected, derived by hand from KB_full and from physics:
//! - `red_cube` has an irregular object below it (IB), so ST1 makes it unstable, and physics
//!   agrees (a cube rolls off a ball);
//! - `white_cube` stands centred on a large flat cube: nothing derives `-stable`, it has a tower
//!   height (on green_cube, on the table), so reasoning says stable, and physics agrees;
//! - `yellow_cube` is behind `green_cube` (same lateral position, further away, lower than the
//!   stack): OC2 rules out every other occluder but `green_cube`, so reasoning cannot decide
//!   its occlusion and without training the decision is the prior; physics says it is hidden
//!   (the large cube covers more than a fifth of its frontal silhouette);
//! - every other object has no object it is behind, so OC2 makes it not occluded.

use lucent::sim::{Colour, ObjectKind, Scene, Size};
use lucent::vision::classify::{explain_scene, Classifier, Source, System, TrainConfig};
use lucent::vision::dataset::{labelled_from, DatasetConfig};
use lucent::vision::reason::{Knowledge, View};

fn scene() -> Scene {
    let mut s = Scene::custom(3);
    let ball = s.add_resting(
        "blue_ball",
        ObjectKind::Ball,
        Colour::Blue,
        Size::Medium,
        (-0.2, 0.0, 0.0),
    );
    let top = s.object(ball).position[1] + 0.5 * Size::Medium.width();
    s.add_resting(
        "red_cube",
        ObjectKind::Cube,
        Colour::Red,
        Size::Small,
        (-0.195, top, 0.0),
    );
    s.add_resting(
        "green_cube",
        ObjectKind::Cube,
        Colour::Green,
        Size::Large,
        (0.1, 0.0, 0.0),
    );
    s.add_resting(
        "white_cube",
        ObjectKind::Cube,
        Colour::White,
        Size::Small,
        (0.1, Size::Large.width(), 0.0),
    );
    s.add_resting(
        "yellow_cube",
        ObjectKind::Cube,
        Colour::Yellow,
        Size::Medium,
        (0.1, 0.0, 0.25),
    );
    s
}

#[test]
fn one_small_scene_is_classified_as_derived_by_hand() {
    let config = DatasetConfig {
        error: lucent::sim::ErrorModel::exact(),
        ..DatasetConfig::default()
    };
    let looked = labelled_from(&config, scene()).expect("the scene looks fine");
    let knowledge = Knowledge::kb_full();
    let c = Classifier::train(System::Reasoning, &knowledge, &[], &TrainConfig::default())
        .expect("no training needed");
    let view = View::from_percept(&looked.scene, &looked.percept);
    let report = explain_scene(&c, &view, &looked).unwrap();
    let line = |name: &str| {
        let r = report.iter().find(|r| r.name == name).unwrap();
        (
            r.stable.as_ref().map(|d| (d.value, d.source.clone())),
            (r.occluded.value, r.occluded.source.clone()),
            r.true_stable,
            r.true_occluded,
        )
    };
    assert_eq!(
        line("red_cube"),
        (
            Some((false, Source::Reasoning)),
            (false, Source::Reasoning),
            Some(false),
            false
        )
    );
    assert_eq!(
        line("white_cube"),
        (
            Some((true, Source::Reasoning)),
            (false, Source::Reasoning),
            Some(true),
            false
        )
    );
    let yellow = line("yellow_cube");
    assert_eq!(yellow.0, None, "yellow_cube stands on the table");
    assert_eq!(yellow.1 .1, Source::Prior, "reasoning cannot decide it");
    assert!(yellow.3, "physics: the large cube hides the yellow cube");
    for name in ["blue_ball", "green_cube"] {
        assert_eq!(line(name).1, (false, Source::Reasoning), "{name}");
    }
}

/// The explanations of the same scene, derived by hand: the red cube is unstable because of
/// ST1 through IB (an irregular object, the ball, is below it); the white cube is stable
/// because it stands on the large flat green cube on the table and nothing makes it unstable;
/// the ball is behind no object, so OC2 rules out every occluder.
#[test]
fn the_scene_is_explained_from_the_proof_tree() {
    let config = DatasetConfig {
        error: lucent::sim::ErrorModel::exact(),
        ..DatasetConfig::default()
    };
    let looked = labelled_from(&config, scene()).expect("the scene looks fine");
    let knowledge = Knowledge::kb_full();
    let c = Classifier::train(System::Reasoning, &knowledge, &[], &TrainConfig::default())
        .expect("no training needed");
    let view = View::from_percept(&looked.scene, &looked.percept);
    let report = explain_scene(&c, &view, &looked).unwrap();
    let decided = |object: &str, label: &str| {
        let r = report.iter().find(|r| r.name == object)?;
        match label {
            "stability" => r.stable.clone(),
            _ => Some(r.occluded.clone()),
        }
    };
    let lexicon = lucent::explain::lexicon::Lexicon::ra();
    let ask = |q: &str| {
        lucent::explain::scene::why(&knowledge, &view, q, &lexicon, &decided)
            .unwrap()
            .text
    };
    let unstable = ask("why is the red cube unstable?");
    assert!(
        unstable.contains("blue ball") && unstable.contains("irregular"),
        "{unstable}"
    );
    assert_eq!(
        ask("why is the white cube stable?"),
        "Because nothing I know makes the white cube unstable: it stands on the green cube \
         (large, flat), which stands on the table."
    );
    assert_eq!(
        ask("why is the blue ball not occluded?"),
        "Because the blue ball is behind no other object, and OC2 says an object is hidden only \
         by an object it is behind."
    );
    let hidden = ask("why is the yellow cube occluded?");
    assert!(
        hidden.starts_with("My knowledge could not decide"),
        "{hidden}"
    );
}
