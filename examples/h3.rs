//! The H3 run (docs/domain.md 7.5): N generated scenes per preset (real-scene-like and
//! simulated-scene-like, `explain::h3::generate`, seeds 0..N), each planned under KB_full
//! (`lucent::plan`, first minimal plan), its plan executed as a history (`explain::history`), and
//! the H3 questions and beliefs asked over it (`explain::h3::check_history`): every proof tree
//! re-checked, no literal repeated on a path, every leaf of a docs/domain.md 6.2 kind.
//!
//! `cargo run --release --example h3 -- N` prints one line per triple and a summary (the record
//! is docs/bench/h3-2026-12-01.txt). Exit status 1 if any tree failed.
//! `cargo run --release --example h3 -- show PRESET SEED` prints one generated scene as AL_d and
//! its minimal plans (how the H4 scenes of tests/data/h4 were drawn).

use std::path::Path;
use std::time::Instant;

use lucent::action;
use lucent::base::SourceMap;
use lucent::explain::h3::{check_history, generate, ScenePreset, TreeCounts, LEAF_KINDS};
use lucent::explain::history::{explain_history, HistoryConfig};
use lucent::plan::{plan, PlanConfig};

fn show(preset: &str, seed: u64) {
    let preset = match preset {
        "real" => ScenePreset::Real,
        _ => ScenePreset::Simulated,
    };
    let scene = generate(preset, seed);
    let text = scene.to_ald("../kb_full.ald", true);
    println!("{text}");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("domains/ra/scenes");
    let mut sources = SourceMap::new();
    let file = sources.add(
        dir.join("generated.ald").to_string_lossy().into_owned(),
        text,
    );
    let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    for profile in [None, Some("learner")] {
        let mut config = PlanConfig {
            max_horizon: 10,
            profile: profile.map(str::to_string),
            ..PlanConfig::default()
        };
        if profile.is_some() {
            config
                .overrides
                .push(("planning".into(), lucent::action::ast::Value::Bool(true)));
        }
        match plan(&parsed.description, &sources, &config) {
            Ok(found) => {
                println!("% {} plans:", profile.unwrap_or("KB_full"));
                for p in &found.plans {
                    println!("%   {}", p.to_text());
                }
            }
            Err(e) => println!("% {}: {e}", profile.unwrap_or("KB_full")),
        }
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    if args.get(1).map(String::as_str) == Some("show") {
        for seed in args[3..].iter().filter_map(|s| s.parse().ok()) {
            show(&args[2], seed);
        }
        return;
    }
    let n: u64 = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(100);
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("domains/ra/scenes");
    let (mut triples, mut trees, mut questions, mut failed) = (0, 0, 0, 0);
    let mut no_plan = 0;
    let mut counts = TreeCounts::default();
    let start = Instant::now();
    for preset in ScenePreset::ALL {
        for seed in 0..n {
            let scene = generate(preset, seed);
            let text = scene.to_ald("../kb_full.ald", true);
            let mut sources = SourceMap::new();
            let file = sources.add(
                dir.join("generated.ald").to_string_lossy().into_owned(),
                text,
            );
            let mut read = |p: &Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
            let parsed = action::load(&mut sources, file, &mut read);
            assert!(!parsed.has_errors(), "{:?}", parsed.diagnostics);
            let desc = parsed.description;
            let t0 = Instant::now();
            let config = PlanConfig {
                max_horizon: 10,
                ..PlanConfig::default()
            };
            let found = match plan(&desc, &sources, &config) {
                Ok(p) => p,
                Err(e) => {
                    println!("{} goal {:?}: no plan ({e})", scene.name(), scene.goal);
                    no_plan += 1;
                    continue;
                }
            };
            let t_plan = t0.elapsed().as_secs_f64();
            let chosen = &found.plans[0];
            let t1 = Instant::now();
            let h = match explain_history(
                &desc,
                &mut sources,
                &chosen.actions,
                &HistoryConfig::default(),
            ) {
                Ok(h) => h,
                Err(e) => {
                    println!("{}: history failed: {e}", scene.name());
                    failed += 1;
                    continue;
                }
            };
            let report = check_history(&h.scenario(), &h.objects(), seed);
            let t_explain = t1.elapsed().as_secs_f64();
            triples += 1;
            trees += report.trees;
            questions += report.questions;
            counts.add(&report.counts);
            let status = if report.failures.is_empty() {
                "ok".to_string()
            } else {
                failed += 1;
                format!("FAILED {:?}", report.failures)
            };
            println!(
                "{:<14} objects {} goal {:?} plan length {} ({} plans) | {} questions, {} trees, {} nodes | plan {:.2}s explain {:.2}s | {status}",
                scene.name(),
                scene.objects.len(),
                scene.goal,
                found.length,
                found.plans.len(),
                report.questions,
                report.trees,
                report.counts.nodes,
                t_plan,
                t_explain
            );
        }
    }
    println!();
    println!(
        "triples {triples} (no plan within 10: {no_plan}); questions {questions}; trees {trees}; \
         failed triples {failed}; time {:.0}s",
        start.elapsed().as_secs_f64()
    );
    println!(
        "tree nodes {}; root-to-leaf paths {}; longest path {} nodes",
        counts.nodes, counts.paths, counts.depth
    );
    let leaves: Vec<String> = LEAF_KINDS
        .iter()
        .zip(counts.leaves)
        .map(|(k, c)| format!("{k} {c}"))
        .collect();
    println!(
        "leaves: {}; false literals without a rule (why-not bottoms) {}",
        leaves.join(", "),
        counts.false_leaves
    );
    if failed > 0 {
        std::process::exit(1);
    }
}
