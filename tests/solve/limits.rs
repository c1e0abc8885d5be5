//! Limits: a deadline or a raised interrupt flag makes the solver stop with `Unknown` and a stop
//! reason, promptly, on a problem far too hard to finish (pigeonhole with 14 pigeons, which
//! needs exponentially many conflicts for resolution-based solvers).

use lucent::ground::program::{Body, GroundProgram, HeadKind, Rule};
use lucent::solve::{Config, Outcome, Solver, StopReason};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

fn pigeonhole(pigeons: u32) -> GroundProgram {
    let holes = pigeons - 1;
    let at = |i: u32, j: u32| (i * holes + j + 1) as i32;
    let mut p = GroundProgram::new();
    p.num_atoms = pigeons * holes;
    let rule = |head_kind, head: Vec<u32>, body: Vec<i32>| Rule {
        head_kind,
        head,
        body: Body::Normal(body),
    };
    for i in 0..pigeons {
        let row: Vec<u32> = (0..holes).map(|j| at(i, j) as u32).collect();
        p.rules.push(rule(HeadKind::Choice, row.clone(), vec![]));
        p.rules.push(rule(
            HeadKind::Disjunction,
            vec![],
            row.iter().map(|&a| -(a as i32)).collect(),
        ));
    }
    for j in 0..holes {
        for a in 0..pigeons {
            for b in a + 1..pigeons {
                p.rules.push(rule(
                    HeadKind::Disjunction,
                    vec![],
                    vec![at(a, j), at(b, j)],
                ));
            }
        }
    }
    p
}

#[test]
fn deadline_gives_unknown() {
    let p = pigeonhole(14);
    let start = Instant::now();
    let cfg = Config {
        deadline: Some(start + Duration::from_millis(300)),
        ..Config::default()
    };
    let r = Solver::new(&p, cfg).solve();
    assert_eq!(r.outcome, Outcome::Unknown);
    assert_eq!(r.stop, Some(StopReason::TimeLimit));
    assert!(!r.exhausted);
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "the deadline was not honoured"
    );
}

#[test]
fn interrupt_flag_gives_unknown() {
    let p = pigeonhole(14);
    let flag = Arc::new(AtomicBool::new(false));
    let setter = flag.clone();
    let t = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(200));
        setter.store(true, Ordering::Relaxed);
    });
    let start = Instant::now();
    let cfg = Config {
        interrupt: Some(flag),
        ..Config::default()
    };
    let r = Solver::new(&p, cfg).solve();
    t.join().expect("the setter thread ends");
    assert_eq!(r.outcome, Outcome::Unknown);
    assert_eq!(r.stop, Some(StopReason::Interrupted));
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "the interrupt was not honoured"
    );
}
