//! Actuation: physical preconditions, physics after putdown, failure rates, errors for bad input.

use lucent::sim::{
    execute, measure, ActConfig, Action, Colour, Failure, Literal, ObjectKind, Rel, Scene,
    SimError, Size, TruthConfig,
};

/// A red cube carrying a blue cube, a ball, and a loose green cube.
fn scene() -> Scene {
    let mut scene = Scene::custom(9);
    scene.add_resting(
        "red_cube",
        ObjectKind::Cube,
        Colour::Red,
        Size::Large,
        (0.0, 0.0, 0.0),
    );
    scene.add_resting(
        "blue_cube",
        ObjectKind::Cube,
        Colour::Blue,
        Size::Medium,
        (0.0, 0.1, 0.0),
    );
    scene.add_resting(
        "ball",
        ObjectKind::Ball,
        Colour::Yellow,
        Size::Medium,
        (0.2, 0.0, 0.1),
    );
    scene.add_resting(
        "green_cube",
        ObjectKind::Cube,
        Colour::Green,
        Size::Medium,
        (-0.2, 0.0, 0.1),
    );
    scene
}

fn exact() -> ActConfig {
    ActConfig {
        failure_rate: 0.0,
        perception: lucent::sim::ErrorModel::exact(),
        ..ActConfig::default()
    }
}

fn act(scene: &mut Scene, text: &str, config: &ActConfig) -> lucent::sim::ActionReport {
    execute(scene, &Action::parse(text).unwrap(), config).unwrap()
}

fn holds(scene: &Scene, rel: Rel, a: &str, b: &str) -> bool {
    measure(scene, &TruthConfig::default())
        .relations
        .iter()
        .any(|r| r.rel == rel && r.a == a && r.b == b)
}

#[test]
fn pickup_of_a_covered_object_fails_physically() {
    let mut scene = scene();
    let report = act(&mut scene, "pickup(rob1, red_cube)", &exact());
    assert_eq!(
        report.failure,
        Some(Failure::Covered(vec!["blue_cube".into()]))
    );
    assert_eq!(scene.in_hand, None);
    assert_eq!(scene.step, 1, "a failed action still takes a step");
    assert_eq!(report.percept.step, 1);
}

#[test]
fn pickup_then_putdown_moves_the_object() {
    let mut scene = scene();
    let report = act(&mut scene, "pickup(rob1,blue_cube)", &exact());
    assert!(report.succeeded());
    assert_eq!(scene.in_hand.as_deref(), Some("blue_cube"));
    let held = Literal::InHand("rob1".into(), "blue_cube".into());
    assert!(report.percept.facts().any(|o| o.literal == held && o.value));
    assert!(
        report.percept.facts().all(|o| !matches!(&o.literal, Literal::Relation(r) if r.a == "blue_cube" || r.b == "blue_cube")),
        "a held object has no relations"
    );
    let full = act(&mut scene, "pickup(rob1,green_cube)", &exact());
    assert_eq!(full.failure, Some(Failure::HandFull("blue_cube".into())));
    let report = act(&mut scene, "putdown(rob1,blue_cube,green_cube)", &exact());
    assert!(report.succeeded());
    assert_eq!(scene.in_hand, None);
    assert!(holds(&scene, Rel::On, "blue_cube", "green_cube"));
    let report = act(&mut scene, "putdown(rob1,blue_cube,table)", &exact());
    assert_eq!(report.failure, Some(Failure::NotHeld));
    assert_eq!(scene.step, 4);
}

#[test]
fn a_block_put_on_a_ball_rolls_off() {
    let mut scene = scene();
    act(&mut scene, "pickup(rob1,green_cube)", &exact());
    let report = act(&mut scene, "putdown(rob1,green_cube,ball)", &exact());
    assert!(report.succeeded(), "the action itself was carried out");
    assert!(!holds(&scene, Rel::On, "green_cube", "ball"));
    assert!(holds(&scene, Rel::On, "green_cube", "table"));
}

#[test]
fn a_wide_box_centred_on_a_small_can_stands_as_statics_says() {
    let mut scene = Scene::custom(4);
    scene.add_resting(
        "can",
        ObjectKind::Can,
        Colour::White,
        Size::Small,
        (0.0, 0.0, 0.0),
    );
    scene.add_resting(
        "big",
        ObjectKind::Box,
        Colour::Red,
        Size::Large,
        (0.25, 0.0, 0.0),
    );
    act(&mut scene, "pickup(rob1,big)", &exact());
    // Placed within millimetres of the can's centre, the box's centre of mass stays over the
    // can's top, so it stands even though the knowledge base says a small base is unstable.
    assert!(act(&mut scene, "putdown(rob1,big,can)", &exact()).succeeded());
    assert!(holds(&scene, Rel::On, "big", "can"));
    assert!(
        lucent::sim::truth::stability(&scene, &TruthConfig::default())
            .iter()
            .all(|s| s.stable)
    );
}

#[test]
fn a_large_cube_on_a_small_bottle_topples() {
    let mut scene = Scene::custom(4);
    scene.add_resting(
        "bottle",
        ObjectKind::Bottle,
        Colour::Yellow,
        Size::Small,
        (0.0, 0.0, 0.0),
    );
    scene.add_resting(
        "big",
        ObjectKind::Cube,
        Colour::Red,
        Size::Large,
        (0.25, 0.0, 0.0),
    );
    act(&mut scene, "pickup(rob1,big)", &exact());
    assert!(act(&mut scene, "putdown(rob1,big,bottle)", &exact()).succeeded());
    assert!(
        !holds(&scene, Rel::On, "big", "bottle"),
        "the cap is too small and round to hold it"
    );
    assert!(holds(&scene, Rel::On, "big", "table"));
}

/// Each action draws its failure from a stream of the scene's seed and step; over N independent
/// steps the failure count is binomial, with standard deviation sqrt(p (1 - p) / N) of the rate.
/// We accept 4 standard deviations.
#[test]
fn manipulation_failure_rate_matches_the_configuration() {
    let config = ActConfig {
        failure_rate: 0.15,
        settle_seconds: 0.25,
        ..exact()
    };
    let base = scene();
    let trials = 300;
    let mut failures = 0;
    for step in 0..trials {
        let mut s = base.clone();
        s.step = step;
        let report = act(&mut s, "pickup(rob1,green_cube)", &config);
        failures += usize::from(report.failure == Some(Failure::GraspSlipped));
    }
    let (n, p) = (trials as f64, 0.15);
    let rate = failures as f64 / n;
    let sigma = (p * (1.0 - p) / n).sqrt();
    assert!(
        (rate - p).abs() < 4.0 * sigma,
        "{rate} vs {p} ± 4 × {sigma}"
    );
}

#[test]
fn same_scene_same_action_same_report() {
    let config = ActConfig::default();
    let (mut a, mut b) = (scene(), scene());
    let ra = act(&mut a, "pickup(rob1,ball)", &config);
    let rb = act(&mut b, "pickup(rob1,ball)", &config);
    assert_eq!(ra, rb);
    assert_eq!(a, b);
}

#[test]
fn bad_input_is_an_error_not_a_panic() {
    let mut scene = scene();
    let config = ActConfig::default();
    let err =
        |text: &str, scene: &mut Scene| execute(scene, &Action::parse(text)?, &config).map(|_| ());
    assert_eq!(
        err("pickup(rob1,unicorn)", &mut scene),
        Err(SimError::UnknownObject("unicorn".into()))
    );
    assert_eq!(
        err("pickup(rob2,ball)", &mut scene),
        Err(SimError::UnknownRobot("rob2".into()))
    );
    assert!(matches!(
        err("pickup(rob1)", &mut scene),
        Err(SimError::MalformedAction(_))
    ));
    assert!(matches!(
        err("jump(rob1,ball)", &mut scene),
        Err(SimError::MalformedAction(_))
    ));
    assert!(matches!(
        err("pickup(rob1,Ball)", &mut scene),
        Err(SimError::MalformedAction(_))
    ));
    assert!(matches!(
        err("putdown(rob1,ball,ball)", &mut scene),
        Err(SimError::ImpossibleAction(_))
    ));
    assert!(matches!(
        err("putdown(rob1,ball,moon)", &mut scene),
        Err(SimError::UnknownObject(_))
    ));
    assert_eq!(scene.step, 0, "errors leave the scene untouched");
    assert_eq!(
        Action::parse("putdown(rob1, ball, table).")
            .unwrap()
            .to_string(),
        "putdown(rob1,ball,table)"
    );
}
