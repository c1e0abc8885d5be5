//! Physical tests on hand-built scenes: stability, toppling, occlusion and geometric relations;
//! round objects come to rest (flat feet, rolling resistance) and still topple when they
//! overhang their support.

use lucent::sim::{
    measure, truth, Colour, ObjectKind, Rel, Relation, Scene, Size, TruthConfig, World,
};
use parry3d::math::{Pose, Rot3, Vector};

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

/// The horizontal offset of the centre of mass of equal cubes.
fn mean_x(xs: &[f32]) -> f32 {
    xs.iter().sum::<f32>() / xs.len() as f32
}

/// A small cube carrying four large ones: statics says the tower stands exactly when the centre
/// of mass of the four lies over the small cube's top (|x| < half its width), the only support
/// of the load. The simulation must agree in both cases.
#[test]
fn tower_of_five_on_a_small_base_behaves_as_statics_says() {
    let small = Size::Small.width();
    let large = Size::Large.width();
    for offsets in [[0.0, 0.0, 0.0, 0.0], [0.015, 0.03, 0.045, 0.06]] {
        let mut scene = Scene::custom(5);
        cube(&mut scene, "base", Size::Small, (0.0, 0.0, 0.0));
        let mut bottom = small;
        for (level, x) in offsets.iter().enumerate() {
            cube(
                &mut scene,
                &format!("c{level}"),
                Size::Large,
                (*x, bottom, 0.0),
            );
            bottom += large;
        }
        let predicted_stable = mean_x(&offsets).abs() < 0.5 * small;
        let report = truth::stability(&scene, &TruthConfig::default());
        let all_stable = report.iter().all(|s| s.stable);
        assert_eq!(
            all_stable, predicted_stable,
            "offsets {offsets:?}: {report:?}"
        );
        settle(&mut scene, 4.0);
        let top = scene.object(scene.find("c3").unwrap()).position[1];
        let standing_top = small + 3.5 * large;
        assert_eq!(
            (top - standing_top).abs() < 0.01,
            predicted_stable,
            "top at {top}"
        );
    }
}

/// Two large cubes side by side on the camera's centre line, one behind the other; a small cube
/// right behind a large one is hidden, and the one in front is not.
#[test]
fn occlusion_by_ray_casting() {
    let mut scene = Scene::custom(2);
    scene.add_resting(
        "big",
        ObjectKind::Cube,
        Colour::Blue,
        Size::Large,
        (0.0, 0.0, -0.1),
    );
    scene.add_resting(
        "hidden",
        ObjectKind::Cube,
        Colour::Red,
        Size::Small,
        (0.0, 0.0, -0.015),
    );
    scene.add_resting(
        "aside",
        ObjectKind::Cube,
        Colour::Green,
        Size::Small,
        (0.25, 0.0, -0.1),
    );
    let occlusion = measure(&scene, &TruthConfig::default()).occlusion;
    let of = |n: &str| occlusion.iter().find(|o| o.name == n).unwrap().clone();
    assert!(of("hidden").hidden > 0.95, "{:?}", of("hidden"));
    assert_eq!(of("hidden").by.len(), 1);
    assert_eq!(of("hidden").by[0].0, "big");
    assert_eq!(of("big").hidden, 0.0);
    assert_eq!(of("aside").hidden, 0.0);
}

/// A hand-built scene whose relations are known exactly. The camera looks along +z, so its
/// right is world -x: `east` (x = -0.2) is to the right of `west` (x = 0.2).
#[test]
fn relations_follow_geometry_exactly() {
    let mut scene = Scene::custom(3);
    cube(&mut scene, "east", Size::Large, (-0.2, 0.0, 0.0));
    scene.add_resting(
        "lid",
        ObjectKind::Cube,
        Colour::Blue,
        Size::Medium,
        (-0.2, Size::Large.width(), 0.0),
    );
    cube(&mut scene, "west", Size::Medium, (0.2, 0.0, 0.0));
    cube(&mut scene, "back", Size::Medium, (0.2, 0.0, 0.2));
    let mut got: Vec<String> = measure(&scene, &TruthConfig::default())
        .relations
        .iter()
        .filter(|r| r.b != "table" && r.a != "table")
        .filter(|r| !matches!(r.rel, Rel::NotTouch | Rel::Far))
        .map(|r| r.to_string())
        .collect();
    got.sort();
    let mut want: Vec<String> = [
        "above,lid,east",
        "below,east,lid",
        "on,lid,east",
        "touch,lid,east",
        "touch,east,lid",
        "front,west,back",
        "behind,back,west",
        "right,east,west",
        "right,east,back",
        "right,lid,west",
        "right,lid,back",
        "left,west,east",
        "left,back,east",
        "left,west,lid",
        "left,back,lid",
    ]
    .iter()
    .map(|s| format!("relation({s})"))
    .collect();
    want.sort();
    assert_eq!(got, want);
    let all = measure(&scene, &TruthConfig::default()).relations;
    assert!(has(&all, Rel::Far, "east", "west"), "0.3 m apart is far");
    assert!(has(&all, Rel::NotTouch, "west", "back"));
    assert!(has(&all, Rel::On, "east", "table"));
    assert!(has(&all, Rel::Above, "lid", "table"));
    assert!(!has(&all, Rel::On, "lid", "table"));
}

/// Settles `scene` for 4 s, then runs the stability test three times, each from the scene as
/// written back by the one before (as a plan's replay does between actions); returns the
/// largest displacement and rotation of `name` over the three.
fn creep(scene: &mut Scene, name: &str) -> (f32, f32) {
    settle(scene, 4.0);
    let (mut moved, mut turned) = (0.0f32, 0.0f32);
    for _ in 0..3 {
        let s = truth::stability(scene, &TruthConfig::default())
            .into_iter()
            .find(|s| s.name == name)
            .unwrap();
        assert!(s.stable, "{name}: {s:?}");
        moved = moved.max(s.displacement);
        turned = turned.max(s.rotation);
        settle(scene, 2.0);
    }
    (moved, turned)
}

/// An upright capsicum slid 2-30 mm per 2 s on the bare table at some yaws, and apples and ducks
/// rocked on their faceted poles; on their flat feet each stands still at every yaw tried.
#[test]
fn fruit_and_ducks_stand_still_on_the_table_at_any_yaw() {
    for kind in [ObjectKind::Capsicum, ObjectKind::Apple, ObjectKind::Duck] {
        for size in Size::ALL {
            for i in 0..8 {
                let yaw = 0.1 * i as f32;
                let mut scene = Scene::custom(1);
                let lowest = kind.shape(size).compute_local_aabb().mins.y;
                scene.add("x", kind, Colour::Red, size, [0.05, -lowest, 0.02], yaw);
                let (moved, _) = creep(&mut scene, "x");
                assert!(
                    moved < 0.002,
                    "{kind:?} {size:?} yaw {yaw}: moved {moved} m"
                );
            }
        }
    }
}

/// A can lying on its side rolled 5-60 mm per 2 s on the bare table without rolling resistance
/// (rapier has none); with it, it comes to rest whatever its yaw: after 4 s it moves less than
/// 2 mm and 0.1 rad in each of three more 2 s windows of the same world. (A world rebuilt from
/// the scene, as the stability test does, restarts the contacts cold: the small can at yaw 1.2
/// then rolls about 8 mm in the first window, recorded in docs/bench/plan-generated-2026-12-05.md.)
#[test]
fn a_can_lying_on_its_side_comes_to_rest() {
    for size in Size::ALL {
        for i in 0..8 {
            let yaw = 0.2 * i as f32;
            let mut scene = Scene::custom(1);
            let id = scene.add("can", ObjectKind::Can, Colour::Red, size, [0.0; 3], 0.0);
            let lying =
                Rot3::from_rotation_y(yaw) * Rot3::from_rotation_x(std::f32::consts::FRAC_PI_2);
            let radius = 0.45 * size.width();
            scene.objects[id.index()].set_pose(&Pose::from_parts(
                Vector::new(0.05, radius + 0.001, 0.02),
                lying,
            ));
            let mut world = World::build(&scene);
            world.step_for(4.0);
            for window in 0..3 {
                let before = world.pose(id).unwrap();
                world.step_for(2.0);
                let after = world.pose(id).unwrap();
                let moved = (after.translation - before.translation).length();
                let turned = before.rotation.angle_between(after.rotation);
                assert!(
                    moved < 0.002 && turned < 0.1,
                    "{size:?} yaw {yaw} window {window}: moved {moved} m, turned {turned} rad"
                );
            }
        }
    }
}

/// Rolling resistance stops creep, not falls: a can standing on a large cube topples when its
/// centre of mass is 1 cm beyond the cube's edge, and stands when it is 1 cm inside.
#[test]
fn a_can_overhanging_its_support_still_topples() {
    let edge = 0.5 * Size::Large.width();
    for (offset, topples) in [(edge + 0.01, true), (edge - 0.01, false)] {
        let mut scene = Scene::custom(4);
        cube(&mut scene, "base", Size::Large, (0.0, 0.0, 0.0));
        scene.add_resting(
            "can",
            ObjectKind::Can,
            Colour::Blue,
            Size::Medium,
            (offset, Size::Large.width(), 0.0),
        );
        assert_eq!(!stable(&scene, "can"), topples, "offset {offset}");
        settle(&mut scene, 3.0);
        let relations = measure(&scene, &TruthConfig::default()).relations;
        assert_eq!(
            has(&relations, Rel::On, "can", "base"),
            !topples,
            "{relations:?}"
        );
    }
}
