//! Proof trees on random ground programs (the H3 checks on programs of every shape): for each
//! program, the least model with negation over fixed base atoms (so it is the stable model), and
//! for every atom a proof tree; every tree passes the independent re-check (which also checks
//! that no literal repeats on a path and that every leaf is of a leaf kind), and every atom that
//! holds gets at least one root (the model is well founded, so a support without cycles exists).

use std::collections::HashSet;

use lucent::control::Symbol;
use lucent::explain::build::{BuildConfig, Builder};
use lucent::explain::tree::{recheck, AxiomKind, BodyLiteral, ModelOracle, RuleInstance};

/// A small deterministic generator (64-bit LCG, Knuth's constants).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
}

fn atom(k: u64) -> Symbol {
    Symbol::parse(&format!("holds(p({k}),{})", k % 3)).unwrap()
}

fn program(seed: u64) -> ModelOracle {
    let mut rng = Rng(seed);
    let n = 4 + rng.below(10);
    let base = 1 + rng.below(3).min(n - 1);
    let mut rules = Vec::new();
    let kinds = [
        AxiomKind::StateConstraint,
        AxiomKind::CausalLaw,
        AxiomKind::Inertia,
        AxiomKind::Default,
        AxiomKind::Executability,
    ];
    // Base atoms: facts or nothing; their values are fixed.
    for k in 0..base {
        if rng.below(2) == 0 {
            rules.push(RuleInstance {
                label: "fact".into(),
                kind: AxiomKind::Fact,
                rule: None,
                head: atom(k),
                body: Vec::new(),
            });
        }
    }
    // Other atoms: rules over any non-base atoms (cycles allowed) and negation of base atoms.
    for _ in 0..rng.below(3 * n) + n {
        let head = base + rng.below(n - base);
        let mut body = Vec::new();
        for _ in 0..rng.below(3) {
            body.push(BodyLiteral::Pos(atom(rng.below(n))));
        }
        if rng.below(3) == 0 {
            body.push(BodyLiteral::Not(atom(rng.below(base))));
        }
        let kind = kinds[rng.below(kinds.len() as u64) as usize];
        let kind = if body.is_empty() {
            AxiomKind::Fact
        } else {
            kind
        };
        let kind = if kind == AxiomKind::Inertia
            && body.iter().all(|b| !matches!(b, BodyLiteral::Pos(_)))
        {
            AxiomKind::StateConstraint
        } else {
            kind
        };
        rules.push(RuleInstance {
            label: format!("R{}", rules.len()),
            kind,
            rule: Some(rules.len() as u32),
            head: atom(head),
            body,
        });
    }
    // The least model, negation read against the fixed base.
    let mut model: HashSet<Symbol> = HashSet::new();
    loop {
        let before = model.len();
        for r in &rules {
            let ok = r.body.iter().all(|b| match b {
                BodyLiteral::Pos(t) => model.contains(t),
                BodyLiteral::Not(t) => !model.contains(t),
                BodyLiteral::Test(_) => true,
            });
            if ok {
                model.insert(r.head.clone());
            }
        }
        if model.len() == before {
            break;
        }
    }
    ModelOracle { rules, model }
}

#[test]
fn every_tree_passes_the_recheck() {
    let (mut trees, mut false_trees, mut nodes) = (0, 0, 0);
    for seed in 0..300 {
        let o = program(seed);
        let atoms: HashSet<Symbol> = o
            .rules
            .iter()
            .flat_map(|r| {
                std::iter::once(r.head.clone()).chain(r.body.iter().filter_map(|b| match b {
                    BodyLiteral::Pos(t) | BodyLiteral::Not(t) => Some(t.clone()),
                    BodyLiteral::Test(_) => None,
                }))
            })
            .collect();
        let mut atoms: Vec<Symbol> = atoms.into_iter().collect();
        atoms.sort();
        for a in &atoms {
            let tree = Builder::new(&o, BuildConfig::default()).build(a);
            recheck(&tree, &o).unwrap_or_else(|e| panic!("seed {seed}, {a}: {e}\n{tree:#?}"));
            if o.model.contains(a) {
                assert!(
                    !tree.roots.is_empty(),
                    "seed {seed}: {a} holds but has no tree"
                );
                assert!(!tree.path.is_empty());
                trees += 1;
            } else if !tree.roots.is_empty() {
                false_trees += 1;
            }
            nodes += tree.nodes.len();
        }
    }
    // Some trees of each sort were built (the generator is not degenerate).
    assert!(
        trees > 300 && false_trees > 100,
        "{trees} {false_trees} {nodes}"
    );
}
