//! Planning on the golden scenes of docs/domain.md 4.5 (tabletop task, exception goal, execution
//! example): the incremental search (one Control, one step part per horizon) against the
//! reference that translates and grounds every horizon afresh, first minimal plan and all
//! minimal plans. The comparison with clingo is `scripts/bench_plan.py`.
//!
//! `cargo bench --no-default-features --bench plan`

use criterion::Criterion;
use lucent::plan::{plan, PlanConfig, Search};

/// The tests' scene loader (`domains/ra/scenes`, includes resolved).
#[path = "../tests/support/ra_scenes.rs"]
mod ra_scenes;

use ra_scenes::load_scene as load;

fn main() {
    let mut c = Criterion::default().sample_size(10).configure_from_args();
    for (scene, h) in [
        ("tabletop_task.ald", 4),
        ("exception_goal.ald", 3),
        ("execution_example.ald", 6),
    ] {
        let (desc, sources) = load(scene);
        for (name, search, all) in [
            ("incremental-first", Search::Incremental, false),
            ("incremental-all", Search::Incremental, true),
            ("retranslate-all", Search::Retranslate, true),
        ] {
            let config = PlanConfig {
                max_horizon: h,
                search,
                all,
                ..PlanConfig::default()
            };
            c.bench_function(&format!("plan/{scene}/{name}"), |b| {
                b.iter(|| plan(&desc, &sources, &config).unwrap())
            });
        }
    }
    c.final_summary();
}
