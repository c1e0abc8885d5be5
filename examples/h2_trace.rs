//! H2 diagnostics (issue 34): the plans of H2 pairs as the trial produces and judges them, one
//! JSON line per pair (`lucent::experiment::h2::trace`), for `scripts/h2_readings.py`.
//!
//! `cargo run --release --example h2_trace -- RUN_DIR PRESET SEED FIRST LAST [HORIZON] [one]`
//! traces pairs FIRST..=LAST (trial indices, configuration = index / 5, goal = index % 5) of
//! PRESET (`real`, `simulated`) under seed SEED, with the axioms of the H1 runs stored in
//! RUN_DIR/results (a `lucent experiment --out RUN_DIR` directory of the same seed), in the
//! fixed mode at HORIZON (default 9) and with the iterative planner; `one` adds the iterative
//! planner under each one-missing knowledge base; `dump DIR` writes each pair's fixed-mode
//! programs (without, with) to DIR as CR-Prolog text instead, traces nothing.

use lucent::experiment::h2::pair;
use lucent::experiment::h2::trace::{fixed_program, learned_of, trace_pair};
use lucent::experiment::{Domain, Record};
use lucent::explain::h3::ScenePreset;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.len() < 5 {
        eprintln!("usage: h2_trace RUN_DIR PRESET SEED FIRST LAST [HORIZON] [one]");
        std::process::exit(2);
    }
    let run_dir = &args[0];
    let preset = match args[1].as_str() {
        "real" => ScenePreset::Real,
        _ => ScenePreset::Simulated,
    };
    let seed: u64 = args[2].parse().expect("SEED");
    let first: usize = args[3].parse().expect("FIRST");
    let last: usize = args[4].parse().expect("LAST");
    let horizon = args.get(5).and_then(|h| h.parse().ok());
    let one = args.iter().skip(5).any(|a| a == "one");
    // `dump DIR`: write each pair's fixed-mode programs (without, with) as text instead.
    let dump = args
        .iter()
        .position(|a| a == "dump")
        .and_then(|k| args.get(k + 1));
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let domain = Domain {
        path: "domains/ra/kb_full.ald".into(),
        text: std::fs::read_to_string(root.join("domains/ra/kb_full.ald")).expect("kb_full"),
    };
    for index in first..=last {
        let (configuration, goal) = (index / 5, index % 5);
        let h1 = format!(
            "{run_dir}/results/h1-kb_full-{:04}.json",
            configuration % 20
        );
        let record: Record =
            serde_json::from_str(&std::fs::read_to_string(&h1).expect("H1 record")).unwrap();
        let learned = learned_of(&record).expect("H1 axioms");
        let scene = pair(preset, seed, configuration, goal);
        let name = format!("<h2 trace {} {index}>", preset.name());
        if let Some(dir) = dump {
            for (tag, axioms) in [("without", &[][..]), ("with", &learned[..])] {
                let text = fixed_program(&domain, &scene, axioms, horizon.unwrap_or(9)).unwrap();
                let file = format!("{dir}/{}-{index:04}-{tag}.lp", preset.name());
                std::fs::write(&file, text).expect("dump");
            }
            continue;
        }
        match trace_pair(&domain, &name, &scene, &learned, horizon, one) {
            Ok(t) => {
                let mut v = serde_json::to_value(&t).unwrap();
                v["preset"] = preset.name().into();
                v["index"] = index.into();
                println!("{v}");
            }
            Err(e) => eprintln!("{name}: {e}"),
        }
    }
}
