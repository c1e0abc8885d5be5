//! Parser throughput (MB/s) on generated inputs: a large fact file (`p(1,2). p(2,3). ...`), a
//! rule-heavy clingo program with aggregates, choices and CR rules, and a SPARC program with
//! many sort definitions and rules; and the lexer alone on the fact file. Run with
//! `cargo bench --no-default-features --bench parse`.

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};

use lucent::base::FileId;
use lucent::syntax::ast::Dialect;
use lucent::syntax::lexer::{Lexer, TokenKind};
use lucent::syntax::parse;

/// `p(i,i+1).` facts, about `bytes` long.
fn facts(bytes: usize) -> String {
    let mut out = String::with_capacity(bytes + 32);
    let mut i = 0u64;
    while out.len() < bytes {
        out.push_str(&format!("p({},{}). ", i, i + 1));
        i += 1;
        if i % 8 == 0 {
            out.push('\n');
        }
    }
    out
}

/// A rule-heavy program: `n` copies of a block of varied rules over indexed predicates.
fn rules(n: usize) -> String {
    let mut out = String::from("#const horizon = 10.\n");
    for i in 0..n {
        out.push_str(&format!(
            "% block {i}\n\
             holds{i}(F, T+1) :- holds{i}(F, T), not -holds{i}(F, T+1), step(T), T < horizon.\n\
             1 {{ occurs{i}(A, T) : action(A), not banned(A, T) }} 1 :- step(T), not goal{i}(T).\n\
             total{i}(S) :- S = #sum {{ W, I : item{i}(I, W), W > 2 * {i} }}.\n\
             :- #count {{ X : sel{i}(X) }} > 3, not ok{i}.\n\
             a{i} | b{i} ; c{i} :- d{i}(X), X = (1;2;3), |X - {i}| <= 2.\n\
             r{i}(T) : fix{i}(T) :+ step(T), broken{i}(T).\n\
             :~ cost{i}(X, C). [C@1, X]\n\
             #show holds{i}/2.\n"
        ));
    }
    out
}

/// A SPARC program with `n` sorts, predicates and rules.
fn sparc(n: usize) -> String {
    let mut out = String::from("#const steps = 5.\nsorts\n#step = 0..steps.\n");
    for i in 0..n {
        out.push_str(&format!(
            "#obj{i} = [o{i}_][1..4] + {{a{i}, b{i}, c{i}}}.\n\
             #act{i} = move{i}(#obj{i}, #obj{i}) + pick{i}(#obj{i}(X), #obj{i}(Y)) : X != Y.\n"
        ));
    }
    out.push_str("predicates\n");
    for i in 0..n {
        out.push_str(&format!(
            "holds{i}(#obj{i}, #step).\noccurs{i}(#act{i}, #step).\n"
        ));
    }
    out.push_str("rules\n");
    for i in 0..n {
        out.push_str(&format!(
            "holds{i}(X, I+1) :- occurs{i}(move{i}(X, Y), I), #step(I), not -holds{i}(X, I+1).\n\
             -holds{i}(X, I) :- #obj{i}(X), #step(I), not holds{i}(X, I).\n\
             holds{i}(X, I) :+ #obj{i}(X), #step(I).\n"
        ));
    }
    out.push_str("display\noccurs0.\n");
    out
}

/// Lexes the whole text and returns the number of tokens.
fn lex(text: &str) -> usize {
    let mut lexer = Lexer::new(FileId(0), text, Dialect::Clingo);
    let mut diags = Vec::new();
    let mut count = 0;
    while lexer.next_token(&mut diags).kind != TokenKind::Eof {
        count += 1;
    }
    count
}

fn bench(c: &mut Criterion) {
    let inputs = [
        ("facts_16MB", facts(16 << 20), Dialect::Clingo),
        ("rules_4MB", rules(6_500), Dialect::Clingo),
        ("sparc_2MB", sparc(4_000), Dialect::Sparc),
    ];
    let mut group = c.benchmark_group("parse");
    group.sample_size(10);
    group.throughput(Throughput::Bytes(inputs[0].1.len() as u64));
    group.bench_function("lex_facts_16MB", |b| {
        b.iter(|| lex(black_box(&inputs[0].1)))
    });
    for (name, text, dialect) in &inputs {
        let parsed = parse(FileId(0), text, *dialect);
        assert!(
            parsed.diagnostics.is_empty(),
            "{name}: {:?}",
            &parsed.diagnostics[..1]
        );
        group.throughput(Throughput::Bytes(text.len() as u64));
        group.bench_function(*name, |b| {
            b.iter(|| parse(FileId(0), black_box(text), *dialect))
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
