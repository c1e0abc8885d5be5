//! Generated planning tasks (DOMAIN.md 7.1) over the `real` and `simulated` scene presets:
//! for each seed, a scene and a goal; the planner's minimal plans (all of them) are checked
//! against the independent checks of `plan::check` (the breadth-first search's L* and E*, and
//! the replay one transition at a time) and replayed in the physics world without noise.
//!
//! usage: cargo run --release --example plan_generated -- [COUNT_PER_PRESET] [FIRST_SEED]
//! Not yet run at full size: the first tasks show plans that are optimal in the domain but leave
//! an object unstable in rapier (see docs/bench/plan-2026-12-01.txt).

use std::path::Path;
use std::time::Instant;

use lucent::action;
use lucent::base::SourceMap;
use lucent::plan::physics::{generate_task, replay_physics};
use lucent::plan::scene::add_statements;
use lucent::plan::{default_max_horizon, plan, replay, PlanConfig, SceneFacts, StateSearch};
use lucent::sim::Preset;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let count: u64 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(100);
    let first: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    let domain = Path::new(env!("CARGO_MANIFEST_DIR")).join("domains/ra/kb_full.ald");
    let (mut tasks, mut plans, mut optimal, mut sub, mut incorrect, mut physics_ok) =
        (0, 0, 0, 0, 0, 0);
    let mut errors = Vec::new();
    let start = Instant::now();
    println!("preset seed goal | length cr plans | L* E* | classes (opt/sub/inc) | physics ok | s");
    for preset in [Preset::Real, Preset::Simulated] {
        for seed in first..first + count {
            let t0 = Instant::now();
            let Some((scene, goal)) = generate_task(preset, seed) else {
                println!("{} {seed}: no task (no goal fits)", preset.name());
                continue;
            };
            tasks += 1;
            let mut sources = SourceMap::new();
            let text = std::fs::read_to_string(&domain).unwrap();
            let file = sources.add(domain.to_string_lossy().into_owned(), text);
            let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
            let mut desc = action::load(&mut sources, file, &mut read).description;
            let facts = SceneFacts::from_sim(&scene).to_ald();
            add_statements(&mut desc, &mut sources, "<scene>", facts).unwrap();
            add_statements(
                &mut desc,
                &mut sources,
                "<goal>",
                format!("goal {}.", goal.to_ald()),
            )
            .unwrap();
            let mut config = PlanConfig::default();
            config.max_horizon = default_max_horizon(&desc, &config);
            let found = match plan(&desc, &sources, &config) {
                Ok(f) => f,
                Err(e) => {
                    println!("{} {seed} {}: {e}", preset.name(), goal.to_ald());
                    errors.push(format!("{} {seed}: {e}", preset.name()));
                    continue;
                }
            };
            let mut search = StateSearch::new(&desc, &sources, &config).unwrap();
            let minimal = search.minimal(found.length, 1_000_000);
            let (mut o, mut s, mut i, mut p_ok) = (0, 0, 0, 0);
            for p in &found.plans {
                plans += 1;
                let r = replay(&mut search, &p.actions);
                if r.failed.is_some() || !r.goal {
                    i += 1;
                } else if minimal == Some((p.actions.len(), r.cr_applied)) {
                    o += 1;
                } else {
                    s += 1;
                }
                let ph = replay_physics(&scene, &p.actions, &goal);
                if ph.ok() {
                    p_ok += 1;
                } else {
                    println!("  physics: {} {:?}", p.to_text(), ph);
                }
            }
            optimal += o;
            sub += s;
            incorrect += i;
            physics_ok += p_ok;
            println!(
                "{} {seed} {} | {} {} {} | {:?} | {o}/{s}/{i} | {p_ok}/{} | {:.1}",
                preset.name(),
                goal.to_ald(),
                found.length,
                found.cr_applied,
                found.plans.len(),
                minimal,
                found.plans.len(),
                t0.elapsed().as_secs_f64()
            );
        }
    }
    println!(
        "tasks {tasks}, planned {}, plans {plans}: optimal {optimal}, sub-optimal {sub}, \
         incorrect {incorrect}; physics ok {physics_ok}/{plans}; errors {}; {:.0} s",
        tasks - errors.len(),
        errors.len(),
        start.elapsed().as_secs_f64()
    );
    for e in errors {
        println!("error: {e}");
    }
}
