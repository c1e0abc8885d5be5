//! `plan::check` (DOMAIN.md 4.3): plans replayed one transition at a time and classified
//! against the minimal length and CR count that a breadth-first search over states finds.
//!
//! - the planner's minimal plans for the golden scenes are optimal, with L* and E* as 4.5
//!   states them (tabletop 3 and 0, exception goal 2 and 1);
//! - a plan that needs an exception it could avoid, or takes a detour, is sub-optimal;
//! - a plan with an action that is not executable, or that misses the goal, is incorrect,
//!   with the failing step named.

#[path = "support/plan.rs"]
mod plan_support;

use lucent::plan::{classify, plan, PlanConfig, Quality};
use plan_support::{actions, load, EXCEPTION_GOAL, TABLETOP};

#[test]
fn minimal_plans_of_the_golden_scenes_are_optimal() {
    for (scene, expected) in [(TABLETOP, (3, 0)), (EXCEPTION_GOAL, (2, 1))] {
        let (desc, sources) = load(scene);
        let config = PlanConfig {
            max_horizon: 4,
            ..PlanConfig::default()
        };
        let found = plan(&desc, &sources, &config).unwrap();
        for p in &found.plans {
            let v = classify(&desc, &sources, &config, &p.actions, 100_000).unwrap();
            assert_eq!(
                v.quality,
                Quality::Optimal,
                "{scene}: {} {v:?}",
                p.to_text()
            );
            assert_eq!(v.minimal, Some(expected), "{scene}");
            assert_eq!(v.cr_applied, p.cr_applied.len(), "{scene}");
        }
    }
}

#[test]
fn an_unnecessary_exception_or_a_detour_is_sub_optimal() {
    let (desc, sources) = load(TABLETOP);
    let config = PlanConfig::default();
    // The pitcher on the small can: length 3, but D1 is assumed at steps 2 and 3.
    let can = actions(&[
        "pickup(rob1,pitcher)",
        "putdown(rob1,pitcher,white_can_small)",
        "pickup(rob1,red_cube_large)",
    ]);
    let v = classify(&desc, &sources, &config, &can, 100_000).unwrap();
    assert_eq!(v.quality, Quality::SubOptimal, "{v:?}");
    assert_eq!(v.minimal, Some((3, 0)));
    assert_eq!(v.cr_applied, 2);
    // A detour through the green cube: length 5.
    let detour = actions(&[
        "pickup(rob1,green_cube_large)",
        "putdown(rob1,green_cube_large,table)",
        "pickup(rob1,pitcher)",
        "putdown(rob1,pitcher,table)",
        "pickup(rob1,red_cube_large)",
    ]);
    let v = classify(&desc, &sources, &config, &detour, 100_000).unwrap();
    assert_eq!(v.quality, Quality::SubOptimal, "{v:?}");
    assert_eq!(v.minimal, Some((3, 0)));
}

#[test]
fn an_impossible_action_or_a_missed_goal_is_incorrect() {
    let (desc, sources) = load(TABLETOP);
    let config = PlanConfig::default();
    // The red cube is below the pitcher (E7).
    let v = classify(
        &desc,
        &sources,
        &config,
        &actions(&["pickup(rob1,red_cube_large)"]),
        100_000,
    )
    .unwrap();
    assert_eq!(v.quality, Quality::Incorrect);
    assert!(
        v.reason.as_deref().unwrap().contains("step 0"),
        "{:?}",
        v.reason
    );
    // The pitcher on the ball: the pitcher would be unstable (irregular surface below).
    let v = classify(
        &desc,
        &sources,
        &config,
        &actions(&["pickup(rob1,pitcher)", "putdown(rob1,pitcher,blue_ball)"]),
        100_000,
    )
    .unwrap();
    assert_eq!(v.quality, Quality::Incorrect);
    assert!(
        v.reason.as_deref().unwrap().contains("step 1"),
        "{:?}",
        v.reason
    );
    // Executable, but the red cube is not in the hand at the end.
    let v = classify(
        &desc,
        &sources,
        &config,
        &actions(&["pickup(rob1,pitcher)", "putdown(rob1,pitcher,table)"]),
        100_000,
    )
    .unwrap();
    assert_eq!(v.quality, Quality::Incorrect);
    assert!(
        v.reason.as_deref().unwrap().contains("goal"),
        "{:?}",
        v.reason
    );
}
