//! Generated planning tasks (DOMAIN.md 7.1) over both scene presets: a scene from a seed, its
//! measured state as facts, a goal drawn from the seed. Every plan the planner returns must be
//! optimal under the independent checks (`plan::check`: replay and breadth-first search) and,
//! executed in the physics world without noise, reach the goal with every object stable.
//! A few seeds here; `examples/plan_generated.rs` runs the 200 of docs/bench.
#![cfg(feature = "sim")]

use std::path::Path;

use lucent::action;
use lucent::base::SourceMap;
use lucent::plan::physics::{generate_task, replay_physics};
use lucent::plan::scene::add_statements;
use lucent::plan::{classify, default_max_horizon, plan, PlanConfig, Quality, SceneFacts};
use lucent::sim::Preset;

#[test]
fn generated_tasks_get_optimal_plans_that_work_in_the_physics_world() {
    let domain = Path::new(env!("CARGO_MANIFEST_DIR")).join("domains/ra/kb_full.ald");
    let mut planned = 0;
    for preset in [Preset::Real, Preset::Simulated] {
        for seed in 1..=2u64 {
            let Some((scene, goal)) = generate_task(preset, seed) else {
                continue;
            };
            let mut sources = SourceMap::new();
            let text = std::fs::read_to_string(&domain).unwrap();
            let file = sources.add(domain.to_string_lossy().into_owned(), text);
            let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
            let mut desc = action::load(&mut sources, file, &mut read).description;
            add_statements(
                &mut desc,
                &mut sources,
                "<scene>",
                SceneFacts::from_sim(&scene).to_ald(),
            )
            .unwrap();
            add_statements(
                &mut desc,
                &mut sources,
                "<goal>",
                format!("goal {}.", goal.to_ald()),
            )
            .unwrap();
            let mut config = PlanConfig {
                all: false,
                ..PlanConfig::default()
            };
            config.max_horizon = default_max_horizon(&desc, &config);
            let found = match plan(&desc, &sources, &config) {
                Ok(f) => f,
                Err(e) => panic!("{} seed {seed} {goal:?}: {e}", preset.name()),
            };
            for p in &found.plans {
                let v = classify(&desc, &sources, &config, &p.actions, 200_000).unwrap();
                assert_eq!(
                    v.quality,
                    Quality::Optimal,
                    "{} {seed}: {} {v:?}",
                    preset.name(),
                    p.to_text()
                );
                let r = replay_physics(&scene, &p.actions, &goal);
                assert!(r.ok(), "{} {seed}: {} {r:?}", preset.name(), p.to_text());
                planned += 1;
            }
        }
    }
    assert!(planned >= 3, "{planned}");
}
