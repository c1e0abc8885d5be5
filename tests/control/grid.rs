//! A robot on a 10 x 10 grid with walls, solved step by step as clingo's incremental mode
//! does it on one `Control` (benches/multishot.rs times the same loop): `base` and `check(0)`,
//! then per step `t` the external `query(t-1)` released, `step(t)` and `check(t)` grounded and
//! `query(t)` made true. Each step's model count is clingo's; beyond them, every first model
//! is a plan that the test replays on the grid (legal moves, the goal reached at `t`), which
//! also covers the steps where the solver must extend the previous step's model.

use lucent::control::{Control, ControlConfig, Part, Symbol, TruthValue};

/// The program of `grid_program(10)` in benches/multishot.rs, written out.
const GRID: &str = "
#program base.
dim(1..10).
obstacle(2,1..10-2). obstacle(5,3..10). obstacle(7,1..10-2). obstacle(2+1..5-2,10/2+1).
cell(X,Y) :- dim(X), dim(Y), not obstacle(X,Y).
dir(1,0). dir(-1,0). dir(0,1). dir(0,-1).
at(1,1,0).
visited(1,1,0).
goal(10,1).

#program step(t).
{ move(DX,DY,t) : dir(DX,DY) } 1.
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
";

/// Grounds the parts of step `t` of the incremental loop and makes `query(t)` true.
fn next_step(ctl: &mut Control, t: i32) {
    let query = |t: i32| Symbol::function("query", vec![Symbol::number(t)]);
    let mut parts = vec![Part::new("check", vec![Symbol::number(t)])];
    if t == 0 {
        parts.insert(0, Part::base());
    } else {
        ctl.release_external(&query(t - 1));
        parts.insert(0, Part::new("step", vec![Symbol::number(t)]));
    }
    ctl.ground(&parts).expect("the step grounds");
    ctl.assign_external(&query(t), TruthValue::True);
}

fn int(s: &Symbol) -> i32 {
    s.as_number().expect("a number")
}

/// Whether the moves `move(DX,DY,T)` of a model take the robot from (1,1) to the goal (10,1)
/// by step `t`, each move onto a free cell (the walls of `GRID`, by hand).
fn is_plan(moves: &[Symbol], t: i32) -> bool {
    let wall = |x: i32, y: i32| {
        (x == 2 && y <= 8) || (x == 5 && y >= 3) || (x == 7 && y <= 8) || (x == 3 && y == 6)
    };
    let mut steps: Vec<(i32, i32, i32)> = moves
        .iter()
        .map(|m| match m {
            Symbol::Function { args, .. } => (int(&args[2]), int(&args[0]), int(&args[1])),
            _ => panic!("a move is a function"),
        })
        .collect();
    steps.sort();
    if steps.windows(2).any(|w| w[0].0 == w[1].0) || steps.iter().any(|s| s.0 < 1 || s.0 > t) {
        return false;
    }
    let (mut x, mut y) = (1, 1);
    for (_, dx, dy) in steps {
        (x, y) = (x + dx, y + dy);
        if !(1..=10).contains(&x) || !(1..=10).contains(&y) || wall(x, y) {
            return false;
        }
    }
    (x, y) == (10, 1)
}

#[test]
fn grid_loop_model_counts_are_clingos() {
    // Recorded with clingo 5.8's Python API: `python3 scripts/bench_multishot.py --counts 40`
    // (the same loop, all models of each step): no plan up to step 38, 135 plans of 39 moves,
    // 5400 plans at step 40 (one wait anywhere, or a detour).
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add_source("grid", GRID).expect("the program parses");
    ctl.solve_config_mut().models = 0;
    for t in 0..=40 {
        next_step(&mut ctl, t);
        let solved = ctl.solve_all(&Default::default());
        let expected = match t {
            39 => 135,
            40 => 5400,
            _ => 0,
        };
        assert_eq!(solved.models.len(), expected, "models at step {t}");
        for m in &solved.models {
            assert!(is_plan(&m.shown, t), "step {t}: {:?} is no plan", m.shown);
        }
    }
}

#[test]
fn grid_loop_first_models_are_plans_at_every_step() {
    // As clingo's incmode loop with istop="UNKNOWN": one model per step. clingo 5.8 answers
    // UNSAT up to step 38 and SAT from 39 on (`python3 scripts/bench_multishot.py --counts 40`
    // above); from step 39 on each first model must be a plan reaching the goal at its step.
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add_source("grid", GRID).expect("the program parses");
    ctl.solve_config_mut().models = 1;
    for t in 0..=90 {
        next_step(&mut ctl, t);
        let solved = ctl.solve_all(&Default::default());
        assert_eq!(
            solved.summary.is_satisfiable(),
            t >= 39,
            "outcome at step {t}"
        );
        if let Some(m) = solved.models.first() {
            assert!(is_plan(&m.shown, t), "step {t}: {:?} is no plan", m.shown);
        }
    }
}
