//! Multi-shot solving on a `Control` with two solver threads (issue 31 item 3): a colouring
//! grown step by step (`#program step(t)`), external atoms switched between calls, assumptions
//! per call; after every step and every change, `threads: 2` answers as `threads: 1` does (all
//! answer sets when enumerating, outcome and optimum when optimizing).

use lucent::control::{Control, ControlConfig, Part, SolveOptions, Symbol, TruthValue};
use lucent::solve::{Config, OptMode};

/// SplitMix64 for the generated steps and switches.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        (z ^ (z >> 31)) % n
    }
}

/// Node t gets one of three colours, differs from its random neighbours among 1..t-1, and
/// must avoid the colours `forbid(t,C)` says (externals); optimization prefers colour 1.
fn program(seed: u64, steps: u64) -> String {
    let mut rng = Rng(seed);
    let mut text = String::from(
        "col(1..3).\n#program step(t).\nnode(t).\n#external forbid(t,C) : col(C).\n\
         1 { c(t,C) : col(C) } 1.\n:- c(t,C), forbid(t,C).\n\
         :- edge(t,U), c(t,C), c(U,C).\n:~ c(t,C), C > 1. [C@1,t]\n",
    );
    for t in 2..=steps {
        for u in 1..t {
            if rng.below(3) == 0 {
                text.push_str(&format!("edge({t},{u}) :- node({t}).\n"));
            }
        }
    }
    text
}

fn control(threads: usize, optimize: bool) -> Control {
    Control::new(ControlConfig {
        solve: Config {
            models: 0,
            threads,
            opt_mode: if optimize {
                OptMode::Opt
            } else {
                OptMode::Enum(Vec::new())
            },
            ..Config::default()
        },
        ..ControlConfig::default()
    })
}

/// What a call answers, in a form both thread counts must agree on.
fn answer(ctl: &mut Control, options: &SolveOptions, optimize: bool) -> String {
    let solved = ctl.solve_all(options);
    let outcome = format!("{:?}", solved.summary.outcome);
    if optimize {
        let best = solved.models.last().map(|m| m.costs.clone());
        return format!("{outcome} {best:?}");
    }
    let mut sets: Vec<Vec<String>> = solved
        .models
        .iter()
        .map(|m| {
            let mut a: Vec<String> = m.atoms.iter().map(Symbol::to_string).collect();
            a.sort();
            a
        })
        .collect();
    sets.sort();
    format!("{outcome} {sets:?}")
}

fn forbid(t: u64, c: u64) -> Symbol {
    Symbol::function(
        "forbid",
        vec![Symbol::number(t as i32), Symbol::number(c as i32)],
    )
}

#[test]
fn two_threads_follow_steps_externals_and_assumptions() {
    for seed in 0..12 {
        let optimize = seed % 2 == 1;
        let steps = 5;
        let text = program(seed, steps);
        let mut one = control(1, optimize);
        let mut two = control(2, optimize);
        for ctl in [&mut one, &mut two] {
            ctl.add_source("colour.lp", &text).unwrap();
            ctl.ground(&[Part::base()]).unwrap();
        }
        let mut rng = Rng(seed ^ 0xc0108);
        for t in 1..=steps {
            let part = Part::new("step", vec![Symbol::number(t as i32)]);
            one.ground(std::slice::from_ref(&part)).unwrap();
            two.ground(&[part]).unwrap();
            // Switch a few externals of this and earlier steps.
            for _ in 0..3 {
                let atom = forbid(1 + rng.below(t), 1 + rng.below(3));
                let value = match rng.below(3) {
                    0 => TruthValue::True,
                    1 => TruthValue::False,
                    _ => TruthValue::Free,
                };
                one.assign_external(&atom, value);
                two.assign_external(&atom, value);
            }
            let plain = SolveOptions::default();
            let a1 = answer(&mut one, &plain, optimize);
            let a2 = answer(&mut two, &plain, optimize);
            assert_eq!(a1, a2, "seed {seed}, step {t}");
            // An assumption on a colour of this step.
            let colour = Symbol::function("c", vec![Symbol::number(t as i32), Symbol::number(1)]);
            let assumed = SolveOptions {
                assumptions: vec![(colour, rng.below(2) == 0)],
            };
            let a1 = answer(&mut one, &assumed, optimize);
            let a2 = answer(&mut two, &assumed, optimize);
            assert_eq!(a1, a2, "seed {seed}, step {t}, assumption");
        }
    }
}
