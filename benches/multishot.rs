//! Multi-shot solving on one solver (issue 12): 100,000 `solve_with` calls with changing
//! assumptions on the 8-queens program, plain and with one CR rule, printing the mean cost of
//! the first 1,000 and of the last 1,000 calls and their ratio (goal: at most 1.2: the cost per
//! call stays flat, nothing leaks from one call into the next; medians beside, as they resist
//! the preemptions of a loaded machine), with the engine's variable and clause counts at the
//! end; then 20,000 `add_program` steps of a growing chain, first and last 1,000 steps
//! compared likewise (a step costs the same at any length); then `step(t)` parts grounded one
//! by one on a `Control`, the first and last tenth compared. Then criterion measures one call on
//! a warm solver, and one `add_program` step.
//!
//! `cargo bench --no-default-features --bench multishot`; `LUCENT_MULTISHOT_CALLS=N` changes
//! the number of calls of the flatness runs, `LUCENT_MULTISHOT_STEPS=N` the chain's steps,
//! `LUCENT_MULTISHOT_PARTS=N` the number of `step(t)` parts a `Control` grounds one by one
//! (the grounding cost per part, first and last tenth compared; `LUCENT_MULTISHOT_WINDOW=N`
//! compares the first and last N parts instead), `LUCENT_MULTISHOT_CRITERION=0` skips
//! criterion.

use criterion::{black_box, Criterion};
use lucent::ground::program::{Body, CrRule, GroundProgram, HeadKind, Output, Rule};
use lucent::solve::{Config, Solver};
use std::time::Instant;

fn choice(head: Vec<u32>) -> Rule {
    Rule {
        head_kind: HeadKind::Choice,
        head,
        body: Body::Normal(vec![]),
    }
}

fn constraint(body: Vec<i32>) -> Rule {
    Rule {
        head_kind: HeadKind::Disjunction,
        head: vec![],
        body: Body::Normal(body),
    }
}

/// `n` queens: atom `r * n + c + 1` is a queen on row `r`, column `c`.
fn queens(n: u32) -> GroundProgram {
    let mut p = GroundProgram::new();
    let at = |r: u32, c: u32| (r * n + c + 1) as i32;
    p.num_atoms = n * n;
    for r in 0..n {
        p.rules
            .push(choice((0..n).map(|c| at(r, c) as u32).collect()));
        p.rules
            .push(constraint((0..n).map(|c| -at(r, c)).collect()));
    }
    for r1 in 0..n {
        for c1 in 0..n {
            for r2 in 0..n {
                for c2 in 0..n {
                    let (a, b) = (at(r1, c1), at(r2, c2));
                    if a < b
                        && (r1 == r2
                            || c1 == c2
                            || r1 + c2 == r2 + c1
                            || r1 as i64 - c1 as i64 == r2 as i64 - c2 as i64)
                    {
                        p.rules.push(constraint(vec![a, b]));
                    }
                }
            }
        }
    }
    for a in 1..=n * n {
        p.outputs.push(Output {
            symbol: format!("q{a}"),
            condition: vec![a as i32],
        });
    }
    p
}

/// `queens(n)` plus one CR rule `r: q1 :+ .` (application atom `{r}.`, rule `q1 :- r.`).
fn queens_cr(n: u32) -> GroundProgram {
    let mut p = queens(n);
    let appl = p.new_atom();
    p.rules.push(choice(vec![appl]));
    p.rules.push(Rule::normal(&[1], &[appl as i32]));
    p.cr_rules.push(CrRule {
        appl,
        label: "r".into(),
    });
    p
}

/// A small deterministic generator (xorshift), so that every run makes the same calls.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
}

/// Two assumptions on random squares, each positive or negative.
fn assumptions(rng: &mut Rng, squares: u32) -> Vec<i32> {
    (0..2)
        .map(|_| {
            let a = (rng.next() % squares as u64) as i32 + 1;
            if rng.next() % 2 == 0 {
                a
            } else {
                -a
            }
        })
        .collect()
}

/// Mean and median, in microseconds, of durations in seconds.
fn stats(d: &mut [f64]) -> (f64, f64) {
    d.sort_by(|a, b| a.partial_cmp(b).expect("durations are numbers"));
    let mean = d.iter().sum::<f64>() / d.len() as f64;
    (mean * 1e6, d[d.len() / 2] * 1e6)
}

/// Runs `calls` calls on one solver; prints the means of the first and last 1,000.
fn flatness(name: &str, p: &GroundProgram, calls: usize) {
    let mut s = Solver::new(p, Config::default());
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let window = 1000.min(calls / 2).max(1);
    let (mut first, mut last) = (Vec::new(), Vec::new());
    let mut models = 0usize;
    let mut conflicts = 0u64;
    let mut learnt_after_window = 0;
    // Propagations per call in the two windows: a count the machine's load does not change.
    let (mut props_first, mut props_last, mut props_before) = (0u64, 0u64, 0u64);
    let start = Instant::now();
    for i in 0..calls {
        let a = assumptions(&mut rng, 64);
        let t = Instant::now();
        let r = s.solve_with(&a);
        let dt = t.elapsed().as_secs_f64();
        models += r.models.len();
        conflicts += r.stats.conflicts;
        let props = r.stats.propagations - props_before;
        props_before = r.stats.propagations;
        if i < window {
            props_first += props;
        }
        if i >= calls - window {
            props_last += props;
        }
        if i + 1 == window {
            learnt_after_window = s.engine_size().learnts;
        }
        if i < window {
            first.push(dt);
        }
        if i >= calls - window {
            last.push(dt);
        }
    }
    let ((first, first_med), (last, last_med)) = (stats(&mut first), stats(&mut last));
    let size = s.engine_size();
    println!(
        "{name}: {calls} calls in {:.2} s ({models} with a model, {:.1} conflicts per call); \
         mean of the first {window}: {first:.2} us/call, of the last {window}: {last:.2} us/call, \
         last/first {:.3} (medians {first_med:.2} and {last_med:.2}, last/first {:.3}; \
         propagations per call {:.1} and {:.1}, last/first {:.3}); engine \
         after {window} calls: {learnt_after_window} learnt; at the end: {} variables, \
         {} clauses, {} learnt, {} weight constraints",
        start.elapsed().as_secs_f64(),
        conflicts as f64 / calls as f64,
        last / first,
        last_med / first_med,
        props_first as f64 / window as f64,
        props_last as f64 / window as f64,
        props_last as f64 / props_first as f64,
        size.vars,
        size.clauses,
        size.learnts,
        size.weights,
    );
}

/// Step `t` of a growing chain: `{y_t}. x_t :- x_{t-1}, not y_t.` (atoms `2t - 1`, `2t`).
fn chain_step(t: u32) -> GroundProgram {
    let (x, y) = (2 * t - 1, 2 * t);
    let mut d = GroundProgram::new();
    d.num_atoms = y;
    d.rules.push(choice(vec![y]));
    let mut body = vec![-(y as i32)];
    if t > 1 {
        body.push(x as i32 - 2);
    }
    d.rules.push(Rule::normal(&[x], &body));
    d
}

/// `steps` steps of `chain_step` on one solver, solving under `x_t` after every `every`-th
/// step; prints the mean cost of `add_program` over the first and the last 1,000 steps.
fn chain(steps: u32, every: u32) {
    let mut s = Solver::new(&GroundProgram::new(), Config::default());
    let window = 1000.min(steps / 2).max(1);
    let (mut first, mut last) = (Vec::new(), Vec::new());
    let start = Instant::now();
    for t in 1..=steps {
        let d = chain_step(t);
        let t0 = Instant::now();
        s.add_program(&d).expect("fresh atoms");
        let dt = t0.elapsed().as_secs_f64();
        if t <= window {
            first.push(dt);
        }
        if t > steps - window {
            last.push(dt);
        }
        if t % every == 0 {
            black_box(s.solve_with(&[2 * t as i32 - 1]).models.len());
        }
    }
    let ((first, first_med), (last, last_med)) = (stats(&mut first), stats(&mut last));
    println!(
        "chain of {steps} steps (a solve every {every}): {:.2} s; add_program mean of the \
         first {window}: {first:.2} us/step, of the last {window}: {last:.2} us/step, last/first \
         {:.3} (medians {first_med:.2} and {last_med:.2}, last/first {:.3})",
        start.elapsed().as_secs_f64(),
        last / first,
        last_med / first_med
    );
}

/// A planner-like program in parts: `base` with 20 fluents at step 0, `step(t)` with inertia,
/// one action choice and a goal check per step (every part adds the same number of atoms).
const STEPS_PROGRAM: &str = "
    #program base.
    f(1..20). holds(F,0) :- f(F), F < 10.
    #program step(t).
    { occurs(a(F),t) : f(F) } 1.
    holds(F,t) :- occurs(a(F),t).
    holds(F,t) :- holds(F,t-1), not ab(F,t).
    ab(F,t) :- occurs(a(G),t), f(F), F = G + 1.
    done(t) :- holds(20,t).
";

/// `steps` parts `step(1..steps)` grounded one by one on one `Control` (a solve call after
/// each, as the planner does); prints the mean time of `ground` over the first and the last
/// tenth of the steps. Each part adds the same atoms, so a grounding that costs what its part
/// adds keeps last/first near 1; a grounding that reads every earlier atom grows linearly.
fn control_steps(steps: i32) {
    use lucent::control::{Control, ControlConfig, Part, Symbol};
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("steps", STEPS_PROGRAM).expect("the program parses");
    ctl.ground(&[Part::base()]).expect("base grounds");
    let window = std::env::var("LUCENT_MULTISHOT_WINDOW")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or((steps / 10).max(1))
        .clamp(1, steps.max(1));
    let (mut first, mut last) = (Vec::new(), Vec::new());
    let start = Instant::now();
    for t in 1..=steps {
        let t0 = Instant::now();
        ctl.ground(&[Part::new("step", vec![Symbol::number(t)])])
            .expect("the step grounds");
        let dt = t0.elapsed().as_secs_f64();
        if t <= window {
            first.push(dt);
        }
        if t > steps - window {
            last.push(dt);
        }
        black_box(ctl.solve(&Default::default(), |_| false).models);
    }
    let ((first, first_med), (last, last_med)) = (stats(&mut first), stats(&mut last));
    println!(
        "Control: {steps} step parts grounded one by one: {:.2} s; ground mean of the first \
         {window}: {:.3} ms/step, of the last {window}: {:.3} ms/step, last/first {:.2} \
         (medians {:.3} and {:.3}, last/first {:.2}); atoms at the end: {}",
        start.elapsed().as_secs_f64(),
        first * 1e-3,
        last * 1e-3,
        last / first,
        first_med * 1e-3,
        last_med * 1e-3,
        last_med / first_med,
        ctl.num_atoms()
    );
}

fn main() {
    // `cargo test --all-targets` runs benches without `--bench`, as a smoke test: small counts.
    let bench = std::env::args().any(|a| a == "--bench");
    let calls: usize = std::env::var("LUCENT_MULTISHOT_CALLS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(if bench { 100_000 } else { 2_000 });
    flatness("queens8 + assumptions", &queens(8), calls);
    flatness("queens8 + assumptions + 1 CR rule", &queens_cr(8), calls);
    let steps: u32 = std::env::var("LUCENT_MULTISHOT_STEPS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(if bench { 20_000 } else { 2_000 });
    chain(steps, 1000);
    let parts: i32 = std::env::var("LUCENT_MULTISHOT_PARTS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(if bench { 200 } else { 20 });
    control_steps(parts);
    if std::env::var("LUCENT_MULTISHOT_CRITERION").is_ok_and(|v| v == "0") {
        return;
    }

    let mut c = Criterion::default().configure_from_args();
    let p = queens(8);
    let mut s = Solver::new(&p, Config::default());
    let mut rng = Rng(7);
    c.bench_function("multishot/queens8 solve_with on a warm solver", |b| {
        b.iter(|| {
            let a = assumptions(&mut rng, 64);
            black_box(s.solve_with(&a).models.len())
        })
    });
    let p = queens_cr(8);
    let mut s = Solver::new(&p, Config::default());
    c.bench_function("multishot/queens8+cr solve_with on a warm solver", |b| {
        b.iter(|| {
            let a = assumptions(&mut rng, 64);
            black_box(s.solve_with(&a).models.len())
        })
    });
    // One step of a growing chain, solved after the step.
    let mut s = Solver::new(&GroundProgram::new(), Config::default());
    let mut t = 0u32;
    c.bench_function("multishot/add_program chain step", |b| {
        b.iter(|| {
            t += 1;
            s.add_program(&chain_step(t)).expect("fresh atoms");
        })
    });
    c.final_summary();
}
