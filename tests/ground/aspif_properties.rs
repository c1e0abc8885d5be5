//! Properties of the aspif reader and writer on generated inputs: programs round-trip through
//! the canonical layout, and mutated files give errors or programs, never panics.

use lucent::ground::aspif;
use lucent::ground::program::{
    Body, BodyRef, CrRule, Edge, ExternalValue, GroundProgram, HeadKind, Heuristic,
    HeuristicModifier, Minimize, Output, Prefer, Rule,
};
use proptest::prelude::*;

const N: u32 = 12;

fn lit() -> impl Strategy<Value = i32> {
    (1..=N as i32, any::<bool>()).prop_map(|(a, neg)| if neg { -a } else { a })
}

fn rule() -> impl Strategy<Value = Rule> {
    let normal = proptest::collection::vec(lit(), 0..4).prop_map(Body::Normal);
    let weighted = (-3..6i64, proptest::collection::vec((lit(), 0..5i64), 0..4))
        .prop_map(|(lower, lits)| Body::Weight { lower, lits });
    (
        proptest::collection::vec(1..=N, 0..3),
        prop_oneof![normal, weighted],
        any::<bool>(),
    )
        .prop_map(|(head, body, choice)| Rule {
            head_kind: if choice {
                HeadKind::Choice
            } else {
                HeadKind::Disjunction
            },
            head,
            body,
        })
}

fn program() -> impl Strategy<Value = GroundProgram> {
    let rules = proptest::collection::vec(rule(), 0..8);
    let minimize = proptest::collection::vec(
        (-2..3i64, proptest::collection::vec((lit(), -5..5i64), 0..3))
            .prop_map(|(priority, lits)| Minimize { priority, lits }),
        0..3,
    );
    let outputs = proptest::collection::vec(
        (
            "[a-z][a-z0-9_]{0,5}(\\(\"[ a-z\\\\]{0,4}\"\\))?",
            proptest::collection::vec(lit(), 0..3),
        )
            .prop_map(|(symbol, condition)| Output::new(symbol, condition)),
        0..4,
    );
    let externals = proptest::collection::vec(
        (1..=N, 0..4u8).prop_map(|(a, v)| {
            let v = [
                ExternalValue::Free,
                ExternalValue::True,
                ExternalValue::False,
                ExternalValue::Release,
            ][v as usize];
            (a, v)
        }),
        0..3,
    );
    let others = (
        proptest::collection::vec(1..=N, 0..3),
        proptest::collection::vec(lit(), 0..3),
        proptest::collection::vec(
            (
                0..6u8,
                1..=N,
                -3..3i32,
                0..4u32,
                proptest::collection::vec(lit(), 0..2),
            ),
            0..2,
        ),
        proptest::collection::vec(
            (0..4i32, 0..4i32, proptest::collection::vec(lit(), 0..2)),
            0..2,
        ),
        proptest::collection::vec((1..=N, "[a-z]{1,3}(\\([0-9], ?\"x y\"\\))?"), 0..3),
    );
    (rules, minimize, outputs, externals, others).prop_map(
        |(
            rules,
            minimize,
            outputs,
            externals,
            (projections, assumptions, heuristics, edges, crs),
        )| {
            let modifiers = [
                HeuristicModifier::Level,
                HeuristicModifier::Sign,
                HeuristicModifier::Factor,
                HeuristicModifier::Init,
                HeuristicModifier::True,
                HeuristicModifier::False,
            ];
            let mut p = GroundProgram {
                num_atoms: 0,
                rules: rules.into(),
                minimize,
                projections,
                outputs,
                externals,
                assumptions,
                heuristics: heuristics
                    .into_iter()
                    .map(|(m, atom, bias, priority, condition)| Heuristic {
                        modifier: modifiers[m as usize],
                        atom,
                        bias,
                        priority,
                        condition,
                    })
                    .collect(),
                edges: edges
                    .into_iter()
                    .map(|(from, to, condition)| Edge {
                        from,
                        to,
                        condition,
                    })
                    .collect(),
                theory: Vec::new(),
                theory_atoms: Vec::new(),
                cr_rules: crs
                    .into_iter()
                    .map(|(appl, label)| CrRule { appl, label })
                    .collect(),
                prefers: Vec::new(),
                provenance: Default::default(),
            };
            if p.cr_rules.len() >= 2 {
                p.prefers.push(Prefer {
                    better: p.cr_rules[0].appl,
                    worse: p.cr_rules[1].appl,
                });
            }
            p.num_atoms = max_atom(&p);
            p
        },
    )
}

/// The largest atom a program mentions, which is what the reader computes as `num_atoms`.
fn max_atom(p: &GroundProgram) -> u32 {
    let mut m = 0;
    let mut lit = |l: i32| m = m.max(l.unsigned_abs());
    for r in &p.rules {
        r.head.iter().for_each(|&a| lit(a as i32));
        match r.body {
            BodyRef::Normal(ls) => ls.iter().for_each(|&l| lit(l)),
            BodyRef::Weight { lits, .. } => lits.iter().for_each(|&(l, _)| lit(l)),
        }
    }
    p.minimize
        .iter()
        .flat_map(|x| &x.lits)
        .for_each(|&(l, _)| lit(l));
    p.projections.iter().for_each(|&a| lit(a as i32));
    p.outputs
        .iter()
        .flat_map(|o| &o.condition)
        .for_each(|&l| lit(l));
    p.externals.iter().for_each(|&(a, _)| lit(a as i32));
    p.assumptions.iter().for_each(|&l| lit(l));
    for h in &p.heuristics {
        lit(h.atom as i32);
        h.condition.iter().for_each(|&l| lit(l));
    }
    p.edges
        .iter()
        .flat_map(|e| &e.condition)
        .for_each(|&l| lit(l));
    p.cr_rules.iter().for_each(|c| lit(c.appl as i32));
    m
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn programs_round_trip(p in program()) {
        let text = aspif::write_program(&p);
        let back = aspif::read_program(text.as_bytes())
            .map_err(|e| TestCaseError::fail(format!("{e}\n{text}")))?;
        prop_assert_eq!(&back, &p);
        let again = aspif::write(&aspif::read(text.as_bytes()).unwrap());
        prop_assert_eq!(again, text);
    }

    #[test]
    fn mutated_files_never_panic(
        p in program(),
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>(), 0..3u8), 1..4),
    ) {
        let mut bytes = aspif::write_program(&p).into_bytes();
        for (at, byte, kind) in edits {
            let i = at.index(bytes.len());
            let byte = b"0123456789 -\n\"x"[byte as usize % 15];
            match kind {
                0 => bytes[i] = byte,
                1 => bytes.insert(i, byte),
                _ => {
                    bytes.remove(i);
                }
            }
            if bytes.is_empty() {
                break;
            }
        }
        // Either outcome is fine; an error must carry a position inside the input.
        if let Err(e) = aspif::read(&bytes) {
            let lines = bytes.iter().filter(|&&b| b == b'\n').count() as u32 + 1;
            prop_assert!(e.line >= 1 && e.line <= lines, "{e}");
            prop_assert!(e.column >= 1);
        }
    }
}
