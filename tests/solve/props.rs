//! Property tests: the CDCL solver against the brute-force reference (`solve::brute`) on random
//! programs of up to nine atoms with normal, choice, disjunctive and weight rules, minimize
//! statements and CR rules. Every model the solver reports must also pass the independent
//! stable-model checker.

use lucent::ground::program::{Body, CrRule, GroundProgram, HeadKind, Minimize, Prefer, Rule};
use lucent::solve::brute::{self, BruteConfig};
use lucent::solve::check;
use lucent::solve::{Config, CrMode, OptMode, Solver};
use proptest::prelude::*;

/// The number of cases of a property: `default`, or `PROPTEST_CASES` when set (for soaks:
/// `PROPTEST_CASES=5000 cargo test --release --test solve props::`).
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn lit_strategy(n: u32) -> impl Strategy<Value = i32> {
    (1..=n, any::<bool>()).prop_map(|(a, pos)| if pos { a as i32 } else { -(a as i32) })
}

fn rule_strategy(n: u32) -> impl Strategy<Value = Rule> {
    let head = prop::collection::vec(1..=n, 0..3);
    let normal = prop::collection::vec(lit_strategy(n), 0..4).prop_map(Body::Normal);
    let weight = (
        0i64..5,
        prop::collection::vec((lit_strategy(n), 1i64..4), 1..5),
    )
        .prop_map(|(lower, lits)| Body::Weight { lower, lits });
    let body = prop_oneof![3 => normal, 1 => weight];
    (any::<u8>(), head, body).prop_map(|(k, head, body)| {
        let head_kind = if k % 3 == 0 && !head.is_empty() {
            HeadKind::Choice
        } else {
            HeadKind::Disjunction
        };
        Rule {
            head_kind,
            head,
            body,
        }
    })
}

fn program_strategy() -> impl Strategy<Value = GroundProgram> {
    (3u32..10)
        .prop_flat_map(|n| {
            (
                Just(n),
                prop::collection::vec(rule_strategy(n), 1..10),
                prop::collection::vec(
                    (
                        0i64..2,
                        prop::collection::vec((lit_strategy(n), -2i64..4), 1..4),
                    ),
                    0..3,
                ),
            )
        })
        .prop_map(|(n, rules, mins)| {
            let mut p = GroundProgram::new();
            p.num_atoms = n;
            p.rules = rules.into();
            p.minimize = mins
                .into_iter()
                .map(|(priority, lits)| Minimize { priority, lits })
                .collect();
            p
        })
}

/// Adds up to two CR rules: fresh application atoms `{r}.` that guard copies of random rules.
fn cr_program_strategy() -> impl Strategy<Value = GroundProgram> {
    (
        program_strategy(),
        prop::collection::vec(any::<u16>(), 1..3),
        any::<bool>(),
    )
        .prop_map(|(mut p, picks, prefer)| {
            for (i, pick) in picks.iter().enumerate() {
                let appl = p.new_atom();
                p.rules.push(Rule {
                    head_kind: HeadKind::Choice,
                    head: vec![appl],
                    body: Body::Normal(vec![]),
                });
                let n = p.num_atoms - 1;
                let h = (*pick as u32 % n) + 1;
                let b = ((*pick as u32 / 7) % n) + 1;
                p.rules.push(Rule {
                    head_kind: HeadKind::Disjunction,
                    head: vec![h],
                    body: Body::Normal(vec![appl as i32, -(b as i32)]),
                });
                p.cr_rules.push(CrRule {
                    appl,
                    label: format!("r{i}"),
                });
            }
            if prefer && p.cr_rules.len() == 2 {
                p.prefers.push(Prefer {
                    better: p.cr_rules[0].appl,
                    worse: p.cr_rules[1].appl,
                });
            }
            p
        })
}

fn solver_atoms(p: &GroundProgram, config: Config) -> Vec<(Vec<u32>, Vec<i64>)> {
    let mut s = Solver::new(p, config.clone());
    let r = s.solve();
    assert!(r.exhausted, "search must be exhausted on tiny programs");
    let appl: Vec<u32> = p.cr_rules.iter().map(|c| c.appl).collect();
    let mut out: Vec<(Vec<u32>, Vec<i64>)> = Vec::new();
    for m in &r.models {
        if let Err(v) = check::check(p, &m.atoms) {
            panic!("model {:?} is not stable: {v:?}", m.atoms);
        }
        if config.opt_mode == OptMode::OptN && !p.minimize.is_empty() && !m.optimal {
            continue;
        }
        out.push((
            m.atoms
                .iter()
                .copied()
                .filter(|a| !appl.contains(a))
                .collect(),
            m.costs.clone(),
        ));
    }
    out.sort();
    let before = out.len();
    out.dedup();
    assert_eq!(before, out.len(), "an answer set was reported twice");
    out
}

fn brute_atoms(p: &GroundProgram, cfg: BruteConfig) -> Vec<(Vec<u32>, Vec<i64>)> {
    let mut v: Vec<(Vec<u32>, Vec<i64>)> = brute::answer_sets(p, cfg)
        .into_iter()
        .map(|m| (m.atoms, m.costs))
        .collect();
    v.sort();
    v
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(400), ..ProptestConfig::default() })]

    #[test]
    fn all_answer_sets_match_brute_force(p in program_strategy()) {
        let want = brute_atoms(&p, BruteConfig { optimize: false, ..BruteConfig::default() });
        // With and without the merging of equivalent atoms (translate::equivalences).
        for eq in [false, true] {
            let cfg = Config { models: 0, opt_mode: OptMode::Ignore, eq, ..Config::default() };
            let got = solver_atoms(&p, cfg);
            prop_assert_eq!(got, want.clone());
        }
    }

    #[test]
    fn optimal_answer_sets_match_brute_force(p in program_strategy()) {
        let want = brute_atoms(&p, BruteConfig { optimize: !p.minimize.is_empty(), ..BruteConfig::default() });
        for eq in [false, true] {
            let cfg = Config { models: 0, opt_mode: OptMode::OptN, eq, ..Config::default() };
            let got = solver_atoms(&p, cfg);
            prop_assert_eq!(got, want.clone());
        }
    }

    #[test]
    fn opt_mode_proves_the_brute_force_optimum(p in program_strategy()) {
        let mut s = Solver::new(&p, Config::all_models());
        let r = s.solve();
        let want = brute_atoms(&p, BruteConfig { optimize: true, ..BruteConfig::default() });
        match want.first() {
            None => prop_assert!(r.models.is_empty()),
            Some((_, costs)) => prop_assert_eq!(&r.models.last().unwrap().costs, costs),
        }
    }

    #[test]
    fn cr_cardinality_matches_brute_force(p in cr_program_strategy()) {
        let cfg = Config { models: 0, opt_mode: OptMode::Ignore, ..Config::default() };
        let got = solver_atoms(&p, cfg);
        let mut want = brute_atoms(&p, BruteConfig { optimize: false, cr_mode: CrMode::Cardinality });
        if !p.minimize.is_empty() {
            // Costs are reported by both; compare atoms only in ignore mode.
            want.iter_mut().for_each(|w| w.1.clear());
        }
        let got: Vec<_> = got.into_iter().map(|(a, c)| (a, if p.minimize.is_empty() { c } else { vec![] })).collect();
        prop_assert_eq!(got, want);
    }

    #[test]
    fn cr_subset_matches_brute_force(p in cr_program_strategy()) {
        let cfg = Config { models: 0, opt_mode: OptMode::OptN, cr_mode: CrMode::Subset, ..Config::default() };
        let got = solver_atoms(&p, cfg);
        let want = brute_atoms(&p, BruteConfig { optimize: !p.minimize.is_empty(), cr_mode: CrMode::Subset });
        prop_assert_eq!(got, want);
    }
}

/// Programs dense in positive loops, for the source-pointer unfounded-set propagator: a few free
/// choices feed rules whose bodies are mostly positive, so most atoms sit in non-trivial
/// strongly connected components; some bodies are weight bodies inside the loops, and a few
/// rules are constraints or two-atom disjunctions (which makes some programs non-head-cycle-free).
fn loop_program_strategy() -> impl Strategy<Value = GroundProgram> {
    (4u32..13)
        .prop_flat_map(|n| {
            let lit = prop_oneof![4 => (1..=n).prop_map(|a| a as i32), 1 => lit_strategy(n)];
            let rule = (
                any::<u8>(),
                1..=n,
                1..=n,
                prop::collection::vec(lit, 1..4),
                1i64..4,
            )
                .prop_map(|(k, h, g, body, lower)| match k % 10 {
                    0 => Rule::choice(&[h], &body),
                    1 | 2 => Rule {
                        head_kind: HeadKind::Disjunction,
                        head: vec![h],
                        body: Body::Weight {
                            lower,
                            lits: body
                                .iter()
                                .enumerate()
                                .map(|(i, &l)| (l, 1 + (i as i64 + lower) % 3))
                                .collect(),
                        },
                    },
                    3 => Rule::normal(&[], &body[..1]),
                    4 => Rule::normal(&[h, g], &body),
                    _ => Rule::normal(&[h], &body),
                });
            (
                Just(n),
                prop::collection::vec(1..=n, 1..4),
                prop::collection::vec(rule, 2..16),
            )
        })
        .prop_map(|(n, free, rules)| {
            let mut p = GroundProgram::new();
            p.num_atoms = n;
            for a in free {
                p.rules.push(Rule::choice(&[a], &[]));
            }
            p.rules.extend(rules);
            p
        })
}

fn holds(atoms: &[u32], l: i32) -> bool {
    atoms.contains(&l.unsigned_abs()) == (l > 0)
}

/// The answer sets among `all` (brute force, with costs) in which every assumption holds.
fn models_under(all: &[(Vec<u32>, Vec<i64>)], assumptions: &[i32]) -> Vec<Vec<u32>> {
    all.iter()
        .filter(|(m, _)| assumptions.iter().all(|&l| holds(m, l)))
        .map(|(m, _)| m.clone())
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(600), ..ProptestConfig::default() })]

    #[test]
    fn loop_programs_match_brute_force(p in loop_program_strategy()) {
        let want = brute_atoms(&p, BruteConfig { optimize: false, ..BruteConfig::default() });
        for eq in [false, true] {
            let cfg = Config { models: 0, opt_mode: OptMode::Ignore, eq, ..Config::default() };
            let got = solver_atoms(&p, cfg);
            prop_assert_eq!(got, want.clone());
        }
    }

    /// One solver answers several calls under different assumptions: the source pointers and
    /// loop nogoods kept from earlier calls must not change later answers.
    #[test]
    fn loop_programs_under_assumptions_match_brute_force(
        p in loop_program_strategy(),
        calls in prop::collection::vec(prop::collection::vec((1u32..13, any::<bool>()), 0..3), 1..5),
    ) {
        let all = brute_atoms(&p, BruteConfig { optimize: false, ..BruteConfig::default() });
        let mut s = Solver::new(&p, Config { models: 0, opt_mode: OptMode::Ignore, ..Config::default() });
        for call in calls {
            let assumptions: Vec<i32> = call
                .into_iter()
                .filter(|&(a, _)| a <= p.num_atoms)
                .map(|(a, pos)| if pos { a as i32 } else { -(a as i32) })
                .collect();
            let r = s.solve_with(&assumptions);
            prop_assert!(r.exhausted);
            let mut got: Vec<Vec<u32>> = r.models.iter().map(|m| m.atoms.clone()).collect();
            for m in &got {
                prop_assert!(check::check(&p, m).is_ok(), "model {:?} is not stable", m);
            }
            got.sort();
            let want = models_under(&all, &assumptions);
            prop_assert_eq!(got, want, "assumptions {:?}", assumptions);
        }
    }
}

/// The atoms of a model without the CR rules' application atoms.
fn without_appl(p: &GroundProgram, atoms: &[u32]) -> Vec<u32> {
    let appl: Vec<u32> = p.cr_rules.iter().map(|c| c.appl).collect();
    atoms
        .iter()
        .copied()
        .filter(|a| !appl.contains(a))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(600), ..ProptestConfig::default() })]

    /// `--models=1` on CR programs (the cardinality loop may stop at its first phase when that
    /// phase's answer set applies no CR rule): one solver answers several calls under different
    /// assumptions, and each answer must be one of the CR-minimal answer sets that full
    /// enumeration on a fresh solver finds under the same assumptions; "exhausted" with one
    /// model must mean there is exactly one.
    #[test]
    fn cr_cardinality_first_model_is_cr_minimal(
        p in cr_program_strategy(),
        calls in prop::collection::vec(prop::collection::vec((1u32..13, any::<bool>()), 0..3), 1..5),
    ) {
        let one = Config { models: 1, opt_mode: OptMode::Ignore, ..Config::default() };
        let all = Config { models: 0, opt_mode: OptMode::Ignore, ..Config::default() };
        let mut s = Solver::new(&p, one);
        for call in calls {
            let assumptions: Vec<i32> = call
                .into_iter()
                .filter(|&(a, _)| a <= p.num_atoms)
                .map(|(a, pos)| if pos { a as i32 } else { -(a as i32) })
                .collect();
            let r = s.solve_with(&assumptions);
            let want = Solver::new(&p, all.clone()).solve_with(&assumptions);
            prop_assert!(want.exhausted);
            let want: Vec<Vec<u32>> = want.models.iter().map(|m| without_appl(&p, &m.atoms)).collect();
            prop_assert!(r.models.len() <= 1);
            match r.models.first() {
                None => prop_assert!(want.is_empty(), "no model, but {:?} under {:?}", want, assumptions),
                Some(m) => {
                    prop_assert!(check::check(&p, &m.atoms).is_ok(), "model {:?} is not stable", m.atoms);
                    let got = without_appl(&p, &m.atoms);
                    prop_assert!(want.contains(&got), "{:?} not among {:?} under {:?}", got, want, assumptions);
                    if r.exhausted {
                        prop_assert_eq!(want.len(), 1, "exhausted, but {:?}", want);
                    }
                }
            }
        }
    }
}
