//! Generated planning tasks (docs/domain.md 7.1) over both scene presets, a fixed subset of the
//! 200-pair run of `examples/plan_generated.rs` (figures in
//! docs/bench/plan-generated-2026-12-05.md): every distinct minimal plan the planner returns is
//! optimal under the independent checks of `plan::check` (replay one transition at a time;
//! L* and E* by a search over states) and, replayed in rapier without noise,
//! succeeds at every action, reaches the goal and leaves every object stable.
//! Also the regression behind the withdrawn first version of this test: a generated scene not
//! at rest (`simulated` seed 57's duck; first seen with `real` seed 1's capsicum) is settled
//! before planning.

use crate::support::plan as plan_support;

use lucent::plan::physics::{
    generate_task, replay_physics, settle_to_rest, unstable_objects, Skip,
};
use lucent::plan::{default_max_horizon, plan, replay, PlanConfig, SceneFacts, StateSearch};
use lucent::sim::{generate, GenerateConfig, Preset};

/// Plans the task of `(preset, seed)` and checks every minimal plan; returns the plan count.
fn check_task(preset: Preset, seed: u64) -> usize {
    let (scene, goal) = generate_task(preset, seed).unwrap();
    let (desc, sources) = plan_support::problem(
        SceneFacts::from_sim(&scene).to_ald(),
        format!("goal {}.", goal.to_ald()),
    );
    let mut config = PlanConfig::default();
    config.max_horizon = default_max_horizon(&desc, &config);
    let found = plan(&desc, &sources, &config).unwrap();
    assert!(!found.plans.is_empty());
    let mut search = StateSearch::new(&desc, &sources, &config).unwrap();
    let minimal = search.minimal(found.length, 1_000_000);
    for p in &found.plans {
        let r = replay(&mut search, &p.actions);
        let what = format!(
            "{} {seed} {}: {}",
            preset.name(),
            goal.to_ald(),
            p.to_text()
        );
        assert!(
            r.failed.is_none() && r.goal,
            "{what}: incorrect in the domain"
        );
        assert_eq!(
            minimal,
            Some((p.actions.len(), r.cr_applied)),
            "{what}: not optimal"
        );
        let ph = replay_physics(&scene, &p.actions, &goal);
        assert!(ph.ok(), "{what}: physics {ph:?}");
    }
    found.plans.len()
}

#[test]
fn generated_tasks_of_both_presets_give_optimal_plans_that_work_in_physics() {
    let mut plans = 0;
    for (preset, seed) in [(Preset::Real, 2), (Preset::Real, 3), (Preset::Simulated, 2)] {
        plans += check_task(preset, seed);
    }
    assert!(plans >= 3);
}

#[test]
fn a_scene_not_at_rest_is_settled_before_a_task_is_posed() {
    // As generated (6 simulated seconds of settling), simulated seed 57's duck, fallen on its
    // back, still rocks (real seed 1's capsicum did until it got a flat foot, 2026-12-05; of
    // seeds 1-100 of both presets this is the one scene left that needs more settling).
    let mut scene = generate(&GenerateConfig::new(Preset::Simulated, 57)).unwrap();
    assert_eq!(unstable_objects(&scene), vec!["yellow_duck".to_string()]);
    assert!(settle_to_rest(&mut scene).is_empty());
    assert!(unstable_objects(&scene).is_empty());
    // The task is posed on the settled scene.
    let (task, _) = generate_task(Preset::Simulated, 57).unwrap();
    assert!(unstable_objects(&task).is_empty());
    assert_eq!(
        Skip::NotAtRest(vec!["a".into()]).to_string(),
        "the scene is not at rest: a still move"
    );
}
