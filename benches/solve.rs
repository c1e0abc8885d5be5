//! Criterion benchmarks of the solver on ground programs generated in Rust (no grounder needed):
//! pigeonhole (unsatisfiable, conflict analysis), n-queens (all models, enumeration) and
//! Hamiltonian cycles on a ring with chords (non-tight, unfounded sets).

use criterion::{criterion_group, criterion_main, Criterion};
use lucent::ground::program::{Body, GroundProgram, HeadKind, Rule};
use lucent::solve::{Config, Solver};

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

/// Exactly one of `atoms`: a choice, "at least one" as a constraint, pairwise "at most one".
fn exactly_one(p: &mut GroundProgram, atoms: &[u32]) {
    p.rules.push(choice(atoms.to_vec()));
    p.rules
        .push(constraint(atoms.iter().map(|&a| -(a as i32)).collect()));
    for (i, &a) in atoms.iter().enumerate() {
        for &b in &atoms[i + 1..] {
            p.rules.push(constraint(vec![a as i32, b as i32]));
        }
    }
}

/// `pigeons` pigeons in `pigeons - 1` holes.
fn pigeonhole(pigeons: u32) -> GroundProgram {
    let holes = pigeons - 1;
    let mut p = GroundProgram::new();
    let at = |i: u32, j: u32| i * holes + j + 1;
    p.num_atoms = pigeons * holes;
    for i in 0..pigeons {
        let row: Vec<u32> = (0..holes).map(|j| at(i, j)).collect();
        p.rules.push(choice(row.clone()));
        p.rules
            .push(constraint(row.iter().map(|&a| -(a as i32)).collect()));
    }
    for j in 0..holes {
        for a in 0..pigeons {
            for b in a + 1..pigeons {
                p.rules
                    .push(constraint(vec![at(a, j) as i32, at(b, j) as i32]));
            }
        }
    }
    p
}

fn queens(n: u32) -> GroundProgram {
    let mut p = GroundProgram::new();
    let q = |r: u32, c: u32| r * n + c + 1;
    p.num_atoms = n * n;
    for r in 0..n {
        let row: Vec<u32> = (0..n).map(|c| q(r, c)).collect();
        exactly_one(&mut p, &row);
    }
    for r1 in 0..n {
        for r2 in r1 + 1..n {
            for c1 in 0..n {
                for c2 in 0..n {
                    if c1 == c2 || r2 - r1 == c1.abs_diff(c2) {
                        p.rules
                            .push(constraint(vec![q(r1, c1) as i32, q(r2, c2) as i32]));
                    }
                }
            }
        }
    }
    p
}

/// Hamiltonian cycle on a ring of `n` nodes with chords `i -> i + 2`.
fn hamcycle(n: u32) -> GroundProgram {
    let mut p = GroundProgram::new();
    let mut edges = Vec::new();
    for i in 0..n {
        edges.push((i, (i + 1) % n));
        edges.push((i, (i + 2) % n));
    }
    let hc: Vec<u32> = edges.iter().map(|_| p.new_atom()).collect();
    let reach: Vec<u32> = (0..n).map(|_| p.new_atom()).collect();
    for &h in &hc {
        p.rules.push(choice(vec![h]));
    }
    for v in 0..n {
        let out: Vec<u32> = (0..edges.len())
            .filter(|&k| edges[k].0 == v)
            .map(|k| hc[k])
            .collect();
        let inc: Vec<u32> = (0..edges.len())
            .filter(|&k| edges[k].1 == v)
            .map(|k| hc[k])
            .collect();
        for set in [out, inc] {
            p.rules
                .push(constraint(set.iter().map(|&a| -(a as i32)).collect()));
            for (i, &a) in set.iter().enumerate() {
                for &b in &set[i + 1..] {
                    p.rules.push(constraint(vec![a as i32, b as i32]));
                }
            }
        }
        p.rules.push(constraint(vec![-(reach[v as usize] as i32)]));
    }
    // reach(0).  reach(Y) :- reach(X), hc(X, Y).
    p.rules.push(Rule {
        head_kind: HeadKind::Disjunction,
        head: vec![reach[0]],
        body: Body::Normal(vec![]),
    });
    for (k, &(x, y)) in edges.iter().enumerate() {
        p.rules.push(Rule {
            head_kind: HeadKind::Disjunction,
            head: vec![reach[y as usize]],
            body: Body::Normal(vec![reach[x as usize] as i32, hc[k] as i32]),
        });
    }
    p
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("solve");
    g.sample_size(10);
    let php = pigeonhole(8);
    g.bench_function("pigeonhole-8", |b| {
        b.iter(|| Solver::new(&php, Config::default()).solve())
    });
    let q = queens(8);
    g.bench_function("queens-8-all", |b| {
        b.iter(|| Solver::new(&q, Config::all_models()).solve())
    });
    let h = hamcycle(30);
    g.bench_function("hamcycle-30-all", |b| {
        b.iter(|| Solver::new(&h, Config::all_models()).solve())
    });
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
