//! Property test of multi-shot grounding: for random programs with a `#program step(t).` part,
//! grounding `base` and then the step parts `step(1)`, ..., `step(k)` one by one on one
//! `Control` (solving after each) gives the same answer sets as grounding the whole program at
//! horizon k in one shot (the step part unrolled with t = 1..k).
//!
//! The base part is a program of the differential test's generator
//! (`tests/support/random_program.rs`); the step part is generated here. Its rules define
//! only atoms of step `t` and read atoms of the base and of steps `t` and `t-1` (positively and
//! under `not`), so each step is a module on top of the earlier ones, as gringo's incremental
//! grounding requires. Answer sets are compared as sets of all true atoms
//! (`Model::atoms`), with optimization statements ignored (`--opt-mode=enum`).

use crate::support;

use lucent::control::{Control, ControlConfig, Part, SolveOptions, Symbol};
use lucent::solve::{Config, OptMode};
use support::random_program::{program, Features, Rng};

/// One step rule as a template: `@t` is the step, `@p` the step before.
fn step_rule(rng: &mut Rng) -> String {
    // Body literals that bind X (a domain atom first keeps every rule safe).
    let bound_x = ["d(X)", "p(X)", "q(X)", "x(@p,X)", "z(@p,X)", "x(@t,X)"];
    let closed = [
        "a",
        "b",
        "not a",
        "y(@p)",
        "not y(@p)",
        "w(@p)",
        "not w(@p)",
        "y(@t)",
        "not y(@t)",
        "not x(@p,1)",
        "not z(@t,2)",
        "s(2)",
    ];
    let with_x = [
        "not p(X)",
        "not x(@p,X)",
        "not z(@p,X)",
        "q(X)",
        "X != 2",
        "not x(@t,X)",
    ];
    let heads_x = ["x(@t,X)", "z(@t,X)"];
    let heads = ["y(@t)", "w(@t)"];
    let mut body: Vec<String> = Vec::new();
    let uses_x = rng.chance(70);
    if uses_x {
        body.push("d(X)".to_string());
        if rng.chance(50) {
            body.push(rng.pick(&bound_x).to_string());
        }
        if rng.chance(50) {
            body.push(rng.pick(&with_x).to_string());
        }
    }
    for _ in 0..rng.below(3) {
        body.push(rng.pick(&closed).to_string());
    }
    let head = match rng.below(6) {
        0 => String::new(),
        1 if uses_x => format!("{{ {} }}", rng.pick(&heads_x)),
        1 => format!("{{ {} }}", rng.pick(&heads)),
        2 if uses_x => format!("{} ; {}", rng.pick(&heads_x), rng.pick(&heads)),
        _ if uses_x && rng.chance(60) => rng.pick(&heads_x).to_string(),
        _ => rng.pick(&heads).to_string(),
    };
    if body.is_empty() && head.is_empty() {
        return "y(@t) :- not w(@p).".to_string();
    }
    if body.is_empty() {
        format!("{head}.")
    } else {
        format!("{head} :- {}.", body.join(", "))
    }
}

/// The base program and the step part's rules (templates).
fn case(seed: u64) -> (String, Vec<String>) {
    let mut base = program(
        seed,
        Features {
            conditional_disjunction: false,
            aggregate_not_equal: false,
        },
    );
    let mut rng = Rng::new(seed ^ 0x5eed);
    // The step part may read w(0), defined in the base.
    if rng.chance(50) {
        base.push_str("w(0) :- not b.\n");
    }
    let n = 2 + rng.below(5);
    let rules = (0..n).map(|_| step_rule(&mut rng)).collect();
    (base, rules)
}

fn config() -> ControlConfig {
    ControlConfig {
        solve: Config {
            models: 0,
            opt_mode: OptMode::Enum(Vec::new()),
            ..Config::default()
        },
        ..ControlConfig::default()
    }
}

/// All answer sets, each as its sorted atoms, sorted.
fn answer_sets(ctl: &mut Control) -> Vec<Vec<String>> {
    let solved = ctl.solve_all(&SolveOptions::default());
    assert!(solved.summary.exhausted, "the enumeration was complete");
    let mut sets: Vec<Vec<String>> = solved
        .models
        .iter()
        .map(|m| {
            let mut atoms: Vec<String> = m.atoms.iter().map(Symbol::to_string).collect();
            atoms.sort();
            atoms
        })
        .collect();
    sets.sort();
    sets
}

fn step_by_step(base: &str, rules: &[String], k: i32) -> Vec<Vec<String>> {
    let mut text = format!("{base}\n#program step(t).\n");
    for r in rules {
        text.push_str(&r.replace("@t", "t").replace("@p", "(t-1)"));
        text.push('\n');
    }
    let mut ctl = Control::new(config());
    ctl.add_source("steps.lp", &text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    answer_sets(&mut ctl);
    for t in 1..=k {
        ctl.ground(&[Part::new("step", vec![Symbol::number(t)])])
            .unwrap();
        if t < k {
            // Solving in between: later steps are added to a solver that has searched.
            answer_sets(&mut ctl);
        }
    }
    answer_sets(&mut ctl)
}

fn one_shot(base: &str, rules: &[String], k: i32) -> Vec<Vec<String>> {
    let mut text = format!("{base}\n");
    for t in 1..=k {
        for r in rules {
            text.push_str(
                &r.replace("@t", &t.to_string())
                    .replace("@p", &(t - 1).to_string()),
            );
            text.push('\n');
        }
    }
    let mut ctl = Control::new(config());
    ctl.add_source("unrolled.lp", &text).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    answer_sets(&mut ctl)
}

#[test]
fn step_parts_one_by_one_equal_the_unrolled_program() {
    let seeds: u64 = std::env::var("LUCENT_MULTISHOT_SEEDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    let mut nonempty = 0;
    for seed in 0..seeds {
        let (base, rules) = case(seed);
        // Programs the grounder rejects (e.g. unsafe random rules) are not this test's subject.
        let mut probe = Control::new(config());
        if probe.add_source("probe.lp", &base).is_err() || probe.ground(&[Part::base()]).is_err() {
            continue;
        }
        let k = 1 + (seed % 3) as i32;
        let inc = step_by_step(&base, &rules, k);
        let whole = one_shot(&base, &rules, k);
        assert_eq!(
            inc,
            whole,
            "seed {seed}, horizon {k}\n--- base\n{base}--- step(t)\n{}",
            rules.join("\n")
        );
        nonempty += usize::from(!inc.is_empty());
    }
    assert!(
        nonempty * 3 >= seeds as usize,
        "too few satisfiable cases ({nonempty} of {seeds}) to test anything"
    );
}

/// Complementary atoms across parts: `e(t)` is new while `-e(t)` is an older fact no part
/// shows (no grounding numbered it, so a later grounding's scope leaves it out unless named),
/// and `-b(t-1)` is new while `b(t-1)` was numbered by the step before. Step by step must equal
/// the unrolled program. By hand: `e(t)` is never true (`-e(t)` is a fact), and of the six free
/// choices `a(1..3)`, `b(1..3)` the pairs `a(2), b(1)` and `a(3), b(2)` exclude each other:
/// 2^6 * (3/4)^2 = 36 answer sets.
#[test]
fn complements_across_parts_stay_exclusive() {
    let base = "#show a/1. #show b/1.\n-e(1..4).\n";
    let rules: Vec<String> = [
        "{ e(@t) }.",
        "{ a(@t) }.",
        "{ b(@t) }.",
        "-b(@p) :- a(@t).",
        "c(@t) :- e(@t).",
    ]
    .iter()
    .map(|r| r.to_string())
    .collect();
    let inc = step_by_step(base, &rules, 3);
    assert_eq!(inc, one_shot(base, &rules, 3));
    assert_eq!(inc.len(), 36);
    assert!(inc.iter().flatten().all(|a| !a.starts_with("e(")));
}
