//! The learner's inner loop as a benchmark client of `control::Control`: N times, a fresh
//! Control (built from the argument `0`, every model, as the Python side's) parses a one-step program, grounds it, solves it and reads the model (every true
//! atom as a `Symbol`). Prints the calls per second; `scripts/bench_learner_loop.py` runs it
//! beside clingo's Python API doing the same.
//!
//! usage: learner_loop FILE [N]
//!
//! It uses mimalloc as its global allocator, the `lucent` binary's (`src/mi_alloc.rs`).

use std::time::Instant;

use lucent::control::{Control, Part, SolveOptions};

#[path = "../src/mi_alloc.rs"]
mod mi_alloc;

#[global_allocator]
static GLOBAL: mi_alloc::Mi = mi_alloc::Mi;

fn main() {
    mi_alloc::purge_at_once();
    let args: Vec<String> = std::env::args().collect();
    let Some(path) = args.get(1) else {
        eprintln!("usage: learner_loop FILE [N]");
        std::process::exit(2);
    };
    let n: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(1000);
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| {
        eprintln!("learner_loop: cannot read {path}: {e}");
        std::process::exit(2);
    });
    let start = Instant::now();
    let mut atoms = 0usize;
    for _ in 0..n {
        // As the Python side's `clingo.Control(["0"])`: every model (every improving model of
        // a program that optimizes).
        let mut ctl = Control::from_args(&["0"]).expect("0 is a valid argument");
        ctl.add_source(path, &text).expect("the program parses");
        ctl.ground(&[Part::base()]).expect("the program grounds");
        ctl.solve(&SolveOptions::default(), |m| {
            atoms += m.atoms().len();
            true
        });
    }
    let secs = start.elapsed().as_secs_f64();
    println!(
        "lucent calls={n} seconds={secs:.3} calls_per_second={:.1} atoms_read={atoms}",
        n as f64 / secs
    );
}
