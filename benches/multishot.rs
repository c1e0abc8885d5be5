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
//! compares the first and last N parts instead; `LUCENT_MULTISHOT_SOLVE=0` and
//! `LUCENT_MULTISHOT_EVICT=1`: see `control_steps`), `LUCENT_MULTISHOT_CRITERION=0` skips
//! criterion. `LUCENT_MULTISHOT_ONLY=grid` runs only the grid step loop (`grid_loop`: clingo's
//! incmode loop over a robot on a grid; `LUCENT_MULTISHOT_GRID=N` parts, default 150 with
//! `--bench`, `LUCENT_MULTISHOT_GRID_SIZE`, `LUCENT_MULTISHOT_GRID_TRACE=1` prints every part,
//! `LUCENT_MULTISHOT_GRID_OUT=path` writes the program); scripts/bench_multishot.py runs it
//! beside clingo's Python API.

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
        p.outputs.push(Output::new(format!("q{a}"), vec![a as i32]));
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
    let (mut props_first, mut props_last) = (0u64, 0u64);
    let start = Instant::now();
    for i in 0..calls {
        let a = assumptions(&mut rng, 64);
        let t = Instant::now();
        let r = s.solve_with(&a);
        let dt = t.elapsed().as_secs_f64();
        models += r.models.len();
        conflicts += r.stats.conflicts;
        // A call's statistics are that call's own.
        let props = r.stats.propagations;
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
/// `LUCENT_MULTISHOT_SOLVE=0` leaves the solve calls out (the grounding alone, warm caches),
/// with `LUCENT_MULTISHOT_EVICT=1` a 64 MB write between parts instead (cold caches, as after
/// a solve over a large program).
fn control_steps(steps: i32) {
    use lucent::control::{Control, ControlConfig, Part, Symbol};
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add_source("steps", STEPS_PROGRAM)
        .expect("the program parses");
    ctl.ground(&[Part::base()]).expect("base grounds");
    let window = std::env::var("LUCENT_MULTISHOT_WINDOW")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or((steps / 10).max(1))
        .clamp(1, steps.max(1));
    let solve = std::env::var("LUCENT_MULTISHOT_SOLVE").map_or(true, |v| v != "0");
    let evict = std::env::var("LUCENT_MULTISHOT_EVICT").is_ok_and(|v| v == "1");
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
        if solve {
            black_box(ctl.solve(&Default::default(), |_| false).models);
        } else if evict {
            // Writes 64 MB, a cache line at a time: the next part starts with cold caches,
            // as after a solve call over a large program.
            let mut v = vec![1u8; 64 << 20];
            for i in (0..v.len()).step_by(64) {
                v[i] = v[i].wrapping_add(i as u8);
            }
            black_box(&v);
        }
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

/// A robot on a `size` x `size` grid with walls, in clingo's incmode shape: `base` (cells,
/// walls, start, goal), `step(t)` (at most one move per step, its effect, a move into a wall or
/// off the grid forbidden, the position and the visited cells kept by inertia) and `check(t)`
/// (the goal asked for by the external `query(t)`). Walls: three vertical walls with a gap
/// each, and one short wall, so the shortest path winds (27 steps on the 10 x 10 grid).
pub fn grid_program(size: i32) -> String {
    let s = size;
    // Vertical walls at columns s/4, s/2 and 3s/4 (at least 2, 3, 4), open at alternate ends.
    let (c1, c2, c3) = ((s / 4).max(2), (s / 2).max(3), (3 * s / 4).max(4));
    format!(
        "#program base.
dim(1..{s}).
obstacle({c1},1..{s}-2). obstacle({c2},3..{s}). obstacle({c3},1..{s}-2). obstacle({c1}+1..{c2}-2,{s}/2+1).
cell(X,Y) :- dim(X), dim(Y), not obstacle(X,Y).
dir(1,0). dir(-1,0). dir(0,1). dir(0,-1).
at(1,1,0).
visited(1,1,0).
goal({s},1).

#program step(t).
{{ move(DX,DY,t) : dir(DX,DY) }} 1.
moved(t) :- move(_,_,t).
at(X+DX,Y+DY,t) :- at(X,Y,t-1), move(DX,DY,t), cell(X+DX,Y+DY).
:- move(DX,DY,t), at(X,Y,t-1), not cell(X+DX,Y+DY).
at(X,Y,t) :- at(X,Y,t-1), not moved(t).
visited(X,Y,t) :- visited(X,Y,t-1).
visited(X,Y,t) :- at(X,Y,t).

#program check(t).
#external query(t).
:- query(t), goal(X,Y), not at(X,Y,t).
#show move/3.
"
    )
}

/// clingo's incmode loop over `grid_program(size)` on one `Control`: `base` and `check(0)`,
/// then per step `t` the external `query(t-1)` released, `step(t)` and `check(t)` grounded,
/// `query(t)` made true and one model asked for. Prints, per part with `trace`, the ground and
/// solve times and the outcome; then the mean ground time of the first and last `window`
/// parts, their ratio, and the slowest solve.
fn grid_loop(size: i32, parts: i32, window: i32, trace: bool) {
    use lucent::control::{Control, ControlConfig, Part, Symbol, TruthValue};
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add_source("grid", &grid_program(size))
        .expect("the program parses");
    let query = |t: i32| Symbol::function("query", vec![Symbol::number(t)]);
    let (mut ground, mut solve) = (Vec::new(), Vec::new());
    let start = Instant::now();
    for t in 0..=parts {
        let mut todo = vec![Part::new("check", vec![Symbol::number(t)])];
        if t == 0 {
            todo.insert(0, Part::base());
        } else {
            ctl.release_external(&query(t - 1));
            todo.insert(0, Part::new("step", vec![Symbol::number(t)]));
        }
        let t0 = Instant::now();
        ctl.ground(&todo).expect("the step grounds");
        let g = t0.elapsed().as_secs_f64();
        ctl.assign_external(&query(t), TruthValue::True);
        let t1 = Instant::now();
        let summary = ctl.solve(&Default::default(), |_| false);
        let s = t1.elapsed().as_secs_f64();
        if trace {
            println!(
                "grid part {t}: ground {:.3} ms, solve {:.3} ms, {} ({} choices, {} conflicts, \
                 {} restarts, {} propagations, {} learnt, {} loop nogoods)",
                g * 1e3,
                s * 1e3,
                if summary.is_satisfiable() {
                    "SAT"
                } else {
                    "UNSAT"
                },
                summary.stats.choices,
                summary.stats.conflicts,
                summary.stats.restarts,
                summary.stats.propagations,
                summary.stats.learnt,
                summary.stats.loop_nogoods,
            );
        }
        if t > 0 {
            ground.push(g);
            solve.push((s, t));
        }
    }
    let w = (window as usize).clamp(1, ground.len().max(1));
    let (first, _) = stats(&mut ground[..w].to_vec());
    let (last, _) = stats(&mut ground[ground.len() - w..].to_vec());
    let (slowest, at) = solve
        .iter()
        .copied()
        .fold((0.0, 0), |m, x| if x.0 > m.0 { x } else { m });
    let total_solve: f64 = solve.iter().map(|x| x.0).sum();
    println!(
        "grid {size}x{size}: {parts} step parts in {:.2} s; ground mean of parts 1-{w}: \
         {:.3} ms, of the last {w}: {:.3} ms, last/first {:.2}; solve: {:.1} ms in all, \
         slowest {:.2} ms (part {at}); atoms at the end: {}",
        start.elapsed().as_secs_f64(),
        first * 1e-3,
        last * 1e-3,
        last / first,
        total_solve * 1e3,
        slowest * 1e3,
        ctl.num_atoms()
    );
}

fn main() {
    // `cargo test --all-targets` runs benches without `--bench`, as a smoke test: small counts.
    let bench = std::env::args().any(|a| a == "--bench");
    let env = |name: &str| std::env::var(name).ok().and_then(|v| v.parse::<i32>().ok());
    let only = std::env::var("LUCENT_MULTISHOT_ONLY").unwrap_or_default();
    if only == "grid" {
        if let Ok(path) = std::env::var("LUCENT_MULTISHOT_GRID_OUT") {
            let size = env("LUCENT_MULTISHOT_GRID_SIZE").unwrap_or(10);
            std::fs::write(&path, grid_program(size)).expect("the program file is written");
        }
        let parts = env("LUCENT_MULTISHOT_GRID").unwrap_or(if bench { 150 } else { 20 });
        grid_loop(
            env("LUCENT_MULTISHOT_GRID_SIZE").unwrap_or(10),
            parts,
            env("LUCENT_MULTISHOT_WINDOW").unwrap_or(10),
            std::env::var("LUCENT_MULTISHOT_GRID_TRACE").is_ok_and(|v| v == "1"),
        );
        return;
    }
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
