//! Physical tests on hand-built scenes: stability, toppling, occlusion and geometric relations.

#![cfg(feature = "sim")]

use lucent::sim::{
    measure, truth, Colour, ObjectKind, Rel, Relation, Scene, Size, TruthConfig, World,
};

fn cube(scene: &mut Scene, name: &str, size: Size, at: (f32, f32, f32)) {
    scene.add_resting(name, ObjectKind::Cube, Colour::Red, size, at);
}

fn has(relations: &[Relation], rel: Rel, a: &str, b: &str) -> bool {
    relations
        .iter()
        .any(|r| r.rel == rel && r.a == a && r.b == b)
}

fn stable(scene: &Scene, name: &str) -> bool {
    truth::stability(scene, &TruthConfig::default())
        .into_iter()
        .find(|s| s.name == name)
        .unwrap()
        .stable
}

fn settle(scene: &mut Scene, seconds: f32) {
    let mut world = World::build(scene);
    world.step_for(seconds);
    world.write_back(scene);
}

#[test]
fn cube_on_cube_is_stable() {
    let mut scene = Scene::custom(1);
    cube(&mut scene, "a", Size::Large, (0.0, 0.0, 0.0));
    cube(&mut scene, "b", Size::Medium, (0.004, 0.1, -0.003));
    assert!(stable(&scene, "a"));
    assert!(stable(&scene, "b"));
    let relations = measure(&scene, &TruthConfig::default()).relations;
    assert!(has(&relations, Rel::On, "b", "a"));
    assert!(has(&relations, Rel::On, "a", "table"));
    assert!(!has(&relations, Rel::On, "b", "table"));
}

#[test]
fn cube_on_ball_falls_to_the_table() {
    let mut scene = Scene::custom(1);
    scene.add_resting(
        "ball",
        ObjectKind::Ball,
        Colour::Blue,
        Size::Medium,
        (0.0, 0.0, 0.0),
    );
    // A few millimetres off centre, as any real placement is.
    cube(&mut scene, "block", Size::Medium, (0.006, 0.075, 0.003));
    assert!(!stable(&scene, "block"));
    settle(&mut scene, 3.0);
    let relations = measure(&scene, &TruthConfig::default()).relations;
    assert!(has(&relations, Rel::On, "block", "table"), "{relations:?}");
    assert!(!has(&relations, Rel::On, "block", "ball"));
}
