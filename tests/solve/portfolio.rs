//! The two-thread portfolio (issue 31 item 3) against the sequential solver on generated
//! programs: with `threads: 2` every call must answer as `threads: 1` does. All answer sets
//! (each exactly once), the optimum and its cost, the optimal models of optN, brave and
//! cautious consequences, the outcome (and a sound core) under assumptions, model limits, and
//! multi-shot steps with external atoms. Every model is re-checked by `solve::check`.
//!
//! The programs are small enough for the sequential solver to answer at once but big enough
//! (up to 44 atoms, random clauses over choices) to make the threads meet conflicts, learn,
//! share clauses and split the enumeration into cubes.

use lucent::ground::program::{ExternalValue, GroundProgram, Minimize, Output, Rule};
use lucent::solve::check;
use lucent::solve::{Config, EnumMode, OptMode, Outcome, SolveResult, Solver};

/// SplitMix64: a small deterministic generator for the test programs.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    fn lit(&mut self, n: u32) -> i32 {
        let a = 1 + self.below(n as u64) as i32;
        if self.below(2) == 0 {
            a
        } else {
            -a
        }
    }
}

/// A random program: choices on most atoms, rules deriving the others (some through positive
/// loops), random constraints of two or three literals, and, when `minimize`, two levels of
/// weak constraints.
fn random_program(seed: u64, minimize: bool) -> GroundProgram {
    let mut rng = Rng(seed);
    let n = 10 + rng.below(35) as u32;
    let mut p = GroundProgram::new();
    p.num_atoms = n;
    let mut rules = Vec::new();
    for a in 1..=n {
        match rng.below(5) {
            0 => {
                // Derived from one or two literals of other atoms (positive loops happen).
                let k = 1 + rng.below(2) as usize;
                let body: Vec<i32> = (0..k).map(|_| rng.lit(n)).collect();
                rules.push(Rule::normal(&[a], &body));
            }
            _ => rules.push(Rule::choice(&[a], &[])),
        }
    }
    let constraints = (n as u64) * (3 + rng.below(3)) / 2;
    for _ in 0..constraints {
        let k = 2 + rng.below(2) as usize;
        let body: Vec<i32> = (0..k).map(|_| rng.lit(n)).collect();
        rules.push(Rule::normal(&[], &body));
    }
    p.rules = rules.into();
    for a in 1..=n {
        p.outputs.push(Output::new(format!("x{a}"), vec![a as i32]));
    }
    if minimize {
        for priority in [1, 0] {
            let lits = (0..4 + rng.below(6))
                .map(|_| (rng.lit(n), 1 + rng.below(5) as i64))
                .collect();
            p.minimize.push(Minimize { priority, lits });
        }
    }
    p
}

fn config(threads: usize) -> Config {
    Config {
        models: 0,
        threads,
        ..Config::default()
    }
}

/// The models' atom sets, sorted (duplicates kept, so that a model reported twice shows).
fn sets(r: &SolveResult) -> Vec<Vec<u32>> {
    let mut s: Vec<Vec<u32>> = r.models.iter().map(|m| m.atoms.clone()).collect();
    s.sort();
    s
}

fn checked(p: &GroundProgram, r: &SolveResult) {
    for m in &r.models {
        assert!(check::check(p, &m.atoms).is_ok(), "not an answer set");
    }
}

#[test]
fn two_threads_enumerate_every_answer_set_once() {
    let mut sat = 0;
    for seed in 0..60 {
        let p = random_program(seed, false);
        let one = Solver::new(&p, config(1)).solve();
        let two = Solver::new(&p, config(2)).solve();
        checked(&p, &two);
        assert_eq!(one.outcome, two.outcome, "seed {seed}");
        assert!(two.exhausted, "seed {seed}: the enumeration was complete");
        assert_eq!(sets(&one), sets(&two), "seed {seed}");
        sat += usize::from(!one.models.is_empty());
    }
    assert!(
        sat >= 15,
        "too few satisfiable programs ({sat}) to test anything"
    );
}

#[test]
fn two_threads_find_one_model_or_refute() {
    for seed in 100..160 {
        let p = random_program(seed, false);
        let one = Solver::new(&p, Config::default()).solve();
        let two = Solver::new(
            &p,
            Config {
                threads: 2,
                ..Config::default()
            },
        )
        .solve();
        checked(&p, &two);
        assert_eq!(one.outcome, two.outcome, "seed {seed}");
        assert_eq!(two.models.len(), one.models.len(), "seed {seed}");
    }
}

#[test]
fn two_threads_respect_the_model_limit() {
    for seed in 200..230 {
        let p = random_program(seed, false);
        let all = Solver::new(&p, config(1)).solve().models.len();
        for limit in [2, 5] {
            let mut c = config(2);
            c.models = limit;
            let two = Solver::new(&p, c).solve();
            checked(&p, &two);
            assert_eq!(two.models.len(), all.min(limit), "seed {seed}, -n {limit}");
            let mut s = sets(&two);
            s.dedup();
            assert_eq!(s.len(), two.models.len(), "seed {seed}: a model twice");
        }
    }
}

#[test]
fn two_threads_prove_the_same_optimum() {
    let mut optimal = 0;
    for seed in 300..360 {
        let p = random_program(seed, true);
        let one = Solver::new(&p, config(1)).solve();
        let two = Solver::new(&p, config(2)).solve();
        checked(&p, &two);
        assert_eq!(one.outcome, two.outcome, "seed {seed}");
        assert_eq!(one.best_costs(), two.best_costs(), "seed {seed}");
        // Reported models improve strictly.
        for w in two.models.windows(2) {
            assert!(w[1].costs < w[0].costs, "seed {seed}: not improving");
        }
        optimal += usize::from(two.outcome == Outcome::Optimum);
    }
    assert!(
        optimal >= 15,
        "too few optimizations ({optimal}) to test anything"
    );
}

#[test]
fn two_threads_enumerate_the_same_optimal_models() {
    for seed in 400..440 {
        let p = random_program(seed, true);
        let run = |threads| {
            let mut c = config(threads);
            c.opt_mode = OptMode::OptN;
            let r = Solver::new(&p, c).solve();
            let mut opt: Vec<Vec<u32>> = r
                .models
                .iter()
                .filter(|m| m.optimal)
                .map(|m| m.atoms.clone())
                .collect();
            opt.sort();
            (r.outcome, opt)
        };
        assert_eq!(run(1), run(2), "seed {seed}");
    }
}

#[test]
fn two_threads_give_the_same_consequences() {
    for seed in 500..540 {
        let p = random_program(seed, false);
        for mode in [EnumMode::Brave, EnumMode::Cautious] {
            let run = |threads| {
                let mut c = config(threads);
                c.enum_mode = mode;
                let r = Solver::new(&p, c).solve();
                (r.outcome, r.models.last().map(|m| m.symbols.clone()))
            };
            assert_eq!(run(1), run(2), "seed {seed} {mode:?}");
        }
    }
}

#[test]
fn two_threads_answer_under_assumptions_with_a_sound_core() {
    let mut refuted = 0;
    for seed in 600..660 {
        let p = random_program(seed, seed % 2 == 0);
        let mut rng = Rng(seed ^ 0xa55);
        let mut one = Solver::new(&p, config(1));
        let mut two = Solver::new(&p, config(2));
        // Several calls on the same solvers, each under other assumptions.
        for call in 0..4 {
            let assume: Vec<i32> = (0..1 + rng.below(4))
                .map(|_| rng.lit(p.num_atoms))
                .collect();
            let r1 = one.solve_with(&assume);
            let r2 = two.solve_with(&assume);
            checked(&p, &r2);
            assert_eq!(r1.outcome, r2.outcome, "seed {seed} call {call} {assume:?}");
            if r1.best_costs().is_some() {
                assert_eq!(r1.best_costs(), r2.best_costs(), "seed {seed} call {call}");
            } else {
                assert_eq!(sets(&r1), sets(&r2), "seed {seed} call {call}");
            }
            if r2.outcome == Outcome::Unsatisfiable {
                refuted += 1;
                let core = two.core().expect("a refuted call has a core").to_vec();
                assert!(core.iter().all(|l| assume.contains(l)), "seed {seed}");
                let mut probe = Solver::new(&p, config(1));
                let r = probe.solve_with(&core);
                assert_eq!(
                    r.outcome,
                    Outcome::Unsatisfiable,
                    "seed {seed}: core {core:?}"
                );
            }
        }
    }
    assert!(
        refuted >= 10,
        "too few refuted calls ({refuted}) to test cores"
    );
}

#[test]
fn two_threads_follow_multi_shot_steps_with_externals() {
    for seed in 700..740 {
        let mut rng = Rng(seed);
        let base = random_program(seed, seed % 3 == 0);
        let n = base.num_atoms;
        // Step 0: the base program with two more atoms declared external.
        let mut p0 = base.clone();
        p0.num_atoms = n + 2;
        p0.externals = vec![(n + 1, ExternalValue::False), (n + 2, ExternalValue::Free)];
        for a in [n + 1, n + 2] {
            p0.outputs
                .push(Output::new(format!("e{a}"), vec![a as i32]));
        }
        let mut c1 = config(1);
        let mut c2 = config(2);
        if seed % 3 == 0 {
            c1.opt_mode = OptMode::Opt;
            c2.opt_mode = OptMode::Opt;
        }
        let mut one = Solver::new(&p0, c1);
        let mut two = Solver::new(&p0, c2);
        let compare = |one: &mut Solver, two: &mut Solver, what: &str| {
            let r1 = one.solve();
            let r2 = two.solve();
            checked(two.program(), &r2);
            assert_eq!(r1.outcome, r2.outcome, "seed {seed} {what}");
            if r1.best_costs().is_some() {
                assert_eq!(r1.best_costs(), r2.best_costs(), "seed {seed} {what}");
            } else {
                assert_eq!(sets(&r1), sets(&r2), "seed {seed} {what}");
            }
        };
        compare(&mut one, &mut two, "step 0");
        for (a, v) in [
            (n + 1, ExternalValue::True),
            (n + 2, ExternalValue::False),
            (n + 1, ExternalValue::Free),
        ] {
            one.assign_external(a, v).unwrap();
            two.assign_external(a, v).unwrap();
            compare(&mut one, &mut two, &format!("external {a} {v:?}"));
        }
        // Step 1: rules for the first external (it stops being external) and a new atom.
        let mut delta = GroundProgram::new();
        delta.num_atoms = n + 3;
        let b1 = rng.lit(n);
        let b2 = rng.lit(n);
        delta.rules = vec![
            Rule::normal(&[n + 1], &[b1]),
            Rule::choice(&[n + 3], &[b2]),
            Rule::normal(&[], &[(n + 3) as i32, -((n + 1) as i32)]),
        ]
        .into();
        one.add_program(&delta).unwrap();
        two.add_program(&delta).unwrap();
        compare(&mut one, &mut two, "step 1");
        one.release_external(n + 2).unwrap();
        two.release_external(n + 2).unwrap();
        compare(&mut one, &mut two, "released");
    }
}
