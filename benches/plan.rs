//! Planning on the golden scenes of DOMAIN.md 4.5 (tabletop task, exception goal, execution
//! example): the incremental search (one Control, one step part per horizon) against the
//! reference that translates and grounds every horizon afresh, first minimal plan and all
//! minimal plans. The comparison with clingo is `scripts/bench_plan.py`.
//!
//! `cargo bench --no-default-features --bench plan`

use std::path::Path;

use criterion::Criterion;
use lucent::action::{self, ast::Description};
use lucent::base::SourceMap;
use lucent::plan::{plan, PlanConfig, Search};

fn load(scene: &str) -> (Description, SourceMap) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("domains/ra/scenes")
        .join(scene);
    let mut sources = SourceMap::new();
    let text = std::fs::read_to_string(&path).unwrap();
    let file = sources.add(path.to_string_lossy().into_owned(), text);
    let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    (parsed.description, sources)
}

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
