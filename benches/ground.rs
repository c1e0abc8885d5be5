//! Grounder benchmarks (criterion): a recursive transitive closure (semi-naive joins), the
//! n-queens encoding (choice, constraints over arithmetic), and a graph colouring with an
//! aggregate. Inputs are generated here, so the benchmark needs no data files.

use criterion::{criterion_group, criterion_main, Criterion};
use lucent::base::SourceMap;
use lucent::ground::{ground, GroundConfig};
use lucent::syntax::ast::Dialect;
use lucent::syntax::parse;

fn grounded_rules(text: &str) -> usize {
    let mut sources = SourceMap::new();
    let id = sources.add("bench", text);
    let parsed = parse(id, text, Dialect::Clingo);
    ground(&parsed.program, None, &GroundConfig::default())
        .program
        .rules
        .len()
}

fn bench(c: &mut Criterion) {
    let tc = {
        let mut s = String::from("tc(X,Y) :- e(X,Y). tc(X,Z) :- tc(X,Y), e(Y,Z).\n");
        for i in 0..150 {
            s.push_str(&format!("e({},{}). ", i, (i * 7 + 1) % 150));
            s.push_str(&format!("e({},{}). ", i, (i + 1) % 150));
        }
        s
    };
    let queens = "#const n=20. q(1..n). { at(X,Y) : q(Y) } = 1 :- q(X).
        :- at(X1,Y), at(X2,Y), X1 < X2.
        :- at(X1,Y1), at(X2,Y2), X1 < X2, X2-X1 = |Y2-Y1|.";
    let colour = {
        let mut s = String::from(
            "col(r;g;b). { c(N,C) : col(C) } = 1 :- node(N). :- e(X,Y), c(X,C), c(Y,C).
             busy(N) :- node(N), #count { M : e(N,M) } > 2.\n",
        );
        for i in 0..400 {
            s.push_str(&format!(
                "node({i}). e({i},{}). e({i},{}). ",
                (i * 13 + 5) % 400,
                (i + 1) % 400
            ));
        }
        s
    };
    let mut group = c.benchmark_group("ground");
    group.sample_size(10);
    group.bench_function("transitive_closure_150", |b| b.iter(|| grounded_rules(&tc)));
    group.bench_function("queens_20", |b| b.iter(|| grounded_rules(queens)));
    group.bench_function("colouring_400", |b| b.iter(|| grounded_rules(&colour)));
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
