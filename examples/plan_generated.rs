//! Generated planning tasks (docs/domain.md 7.1) over the `real` and `simulated` scene presets:
//! for each seed, a scene and a goal; the planner's minimal plans (all of them) are checked
//! against the independent checks of `plan::check` (the state search's L* and E*, and
//! the replay one transition at a time) and replayed in the physics world without noise.
//!
//! usage: cargo run --release --example plan_generated -- [TASKS_PER_PRESET] [FIRST_SEED]
//!        [--first] [--preset real|simulated] [--seeds S,S,...] [--blind]
//! Seeds are taken in order from FIRST_SEED until TASKS_PER_PRESET tasks were posed per preset
//! (or only the seeds listed); a seed that gives no task is reported with its reason
//! (`plan::physics::Skip`). With `--first` only the planner's first minimal plan is checked
//! (what `lucent plan` returns by default); otherwise all distinct minimal plans. `--blind`
//! also runs the search without its lower bound (`StateSearch::minimal_blind`) and reports any
//! difference. Each line gives the planner's and the checks' CPU seconds apart. The figures of the 200-pair run are in
//! docs/bench/plan-generated-2026-12-05.md; tests/plan/generated.rs runs a fixed subset.

use std::path::Path;
use std::time::Instant;

use lucent::action;
use lucent::base::SourceMap;
use lucent::plan::physics::{generate_task, replay_physics};
use lucent::plan::{default_max_horizon, plan, replay, PlanConfig, SceneFacts, StateSearch};
use lucent::sim::Preset;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let count: usize = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(100);
    let first: u64 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1);
    let all = !args.iter().any(|a| a == "--first");
    let blind = args.iter().any(|a| a == "--blind");
    let value = |flag: &str| {
        args.iter()
            .position(|a| a == flag)
            .and_then(|i| args.get(i + 1).cloned())
    };
    let only_preset = value("--preset");
    let seeds: Option<Vec<u64>> =
        value("--seeds").map(|s| s.split(',').filter_map(|x| x.parse().ok()).collect());
    let (mut plan_cpu, mut check_cpu, mut physics_cpu) = (0.0, 0.0, 0.0);
    let mut differ = Vec::new();
    let domain = Path::new(env!("CARGO_MANIFEST_DIR")).join("domains/ra/kb_full.ald");
    let (mut tasks, mut plans, mut optimal, mut sub, mut incorrect, mut physics_ok) =
        (0, 0, 0, 0, 0, 0);
    let mut errors = Vec::new();
    let mut skipped = Vec::new();
    let start = Instant::now();
    println!(
        "preset seed goal | length cr plans | L* E* | classes (opt/sub/inc) | physics ok | \
         wall s | cpu s: plan check physics | expansions"
    );
    for preset in [Preset::Real, Preset::Simulated] {
        if only_preset.as_deref().is_some_and(|p| p != preset.name()) {
            continue;
        }
        let mut posed = 0;
        let list: Box<dyn Iterator<Item = u64>> = match &seeds {
            Some(s) => Box::new(s.clone().into_iter()),
            None => Box::new(first..),
        };
        for seed in list {
            if seeds.is_none() && posed == count {
                break;
            }
            let t0 = Instant::now();
            let (scene, goal) = match generate_task(preset, seed) {
                Ok(task) => task,
                Err(why) => {
                    println!("{} {seed}: no task: {why}", preset.name());
                    skipped.push(format!("{} {seed}: {why}", preset.name()));
                    continue;
                }
            };
            posed += 1;
            tasks += 1;
            let mut sources = SourceMap::new();
            let text = std::fs::read_to_string(&domain).unwrap();
            let file = sources.add(domain.to_string_lossy().into_owned(), text);
            let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
            let mut desc = action::load(&mut sources, file, &mut read).description;
            desc.statements
                .extend(SceneFacts::from_sim(&scene).statements());
            desc.statements.push(goal.statement());
            let mut config = PlanConfig {
                all,
                ..PlanConfig::default()
            };
            config.max_horizon = default_max_horizon(&desc, &config);
            let c0 = cpu_seconds();
            let found = match plan(&desc, &sources, &config) {
                Ok(f) => f,
                Err(e) => {
                    println!("{} {seed} {}: {e}", preset.name(), goal.to_ald());
                    errors.push(format!("{} {seed}: {e}", preset.name()));
                    continue;
                }
            };
            let c1 = cpu_seconds();
            let mut search = StateSearch::new(&desc, &sources, &config).unwrap();
            let minimal = search.minimal(found.length, 1_000_000);
            let stats = search.stats();
            if blind {
                let mut reference = StateSearch::new(&desc, &sources, &config).unwrap();
                let m = reference.minimal_blind(found.length, 1_000_000);
                if m != minimal {
                    println!("  DIFFERENT: bound {minimal:?}, blind {m:?}");
                    differ.push(format!("{} {seed}", preset.name()));
                }
                println!(
                    "  blind: {m:?}, {} expansions",
                    reference.stats().expansions
                );
            }
            let (mut o, mut s, mut i, mut p_ok) = (0, 0, 0, 0);
            let mut task_physics = 0.0;
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
                let t = cpu_seconds();
                let ph = replay_physics(&scene, &p.actions, &goal);
                task_physics += cpu_seconds() - t;
                if ph.ok() {
                    p_ok += 1;
                } else {
                    println!("  physics: {} {:?}", p.to_text(), ph);
                }
            }
            let check = cpu_seconds() - c1 - task_physics;
            plan_cpu += c1 - c0;
            check_cpu += check;
            physics_cpu += task_physics;
            optimal += o;
            sub += s;
            incorrect += i;
            physics_ok += p_ok;
            println!(
                "{} {seed} {} | {} {} {} | {:?} | {o}/{s}/{i} | {p_ok}/{} | {:.1} | \
                 {:.2} {:.2} {:.2} | {}",
                preset.name(),
                goal.to_ald(),
                found.length,
                found.cr_applied,
                found.plans.len(),
                minimal,
                found.plans.len(),
                t0.elapsed().as_secs_f64(),
                c1 - c0,
                check,
                task_physics,
                stats.expansions
            );
        }
    }
    println!(
        "tasks {tasks}, planned {}, plans {plans}: optimal {optimal}, sub-optimal {sub}, \
         incorrect {incorrect}; physics ok {physics_ok}/{plans}; errors {}; seeds skipped {}; \
         {:.0} s",
        tasks - errors.len(),
        errors.len(),
        skipped.len(),
        start.elapsed().as_secs_f64()
    );
    println!(
        "cpu s: planner {plan_cpu:.1}, checks {check_cpu:.1}, physics {physics_cpu:.1}; \
         bound and blind search differ: {}",
        if blind {
            format!("{} {differ:?}", differ.len())
        } else {
            "not compared".into()
        }
    );
    for s in skipped {
        println!("skipped: {s}");
    }
    for e in errors {
        println!("error: {e}");
    }
}

/// The CPU time of this process (user + system), in seconds (0 where it cannot be read).
fn cpu_seconds() -> f64 {
    lucent::cli::report::process_cpu_seconds().unwrap_or(0.0)
}
