//! The brute-force reference solver on hand-derived answer sets, CR semantics and optimization,
//! and against clasp's answers recorded for the aspif test files.

use lucent::ground::aspif;
use lucent::ground::program::{Atom, CrRule, GroundProgram, Lit, Minimize, Prefer, Rule};
use lucent::solve::brute::{answer_sets, stable_models, BruteConfig, BruteModel};
use lucent::solve::CrMode;

fn program(num_atoms: u32, rules: Vec<Rule>) -> GroundProgram {
    GroundProgram {
        num_atoms,
        rules: rules.into(),
        ..Default::default()
    }
}

fn atoms_of(models: &[BruteModel]) -> Vec<Vec<Atom>> {
    models.iter().map(|m| m.atoms.clone()).collect()
}

#[test]
fn stable_models_of_small_programs() {
    // a :- not b.  b :- not a.  c :- a.
    let p = program(
        3,
        vec![
            Rule::normal(&[1], &[-2]),
            Rule::normal(&[2], &[-1]),
            Rule::normal(&[3], &[1]),
        ],
    );
    assert_eq!(stable_models(&p), vec![vec![1, 3], vec![2]]);
    // a :- not a.  No stable model.
    assert!(stable_models(&program(1, vec![Rule::normal(&[1], &[-1])])).is_empty());
    // a | b.  a :- b.  Only {a}.
    let p = program(
        2,
        vec![Rule::normal(&[1, 2], &[]), Rule::normal(&[1], &[2])],
    );
    assert_eq!(stable_models(&p), vec![vec![1]]);
    // {a; b; c}.  :- a, b.  Six subsets avoid {a, b}.
    let p = program(
        3,
        vec![Rule::choice(&[1, 2, 3], &[]), Rule::normal(&[], &[1, 2])],
    );
    assert_eq!(stable_models(&p).len(), 6);
}

/// p = 1, q = 2, r = 3, s = 4; CR rules r1: p :+.  r2: q :+.  r3: r :+.  with application
/// atoms 5, 6, 7; s :- q, r.  :- not p, not s.
/// Consistent applied sets: every set containing r1, or both r2 and r3.
fn cr_program() -> GroundProgram {
    let mut p = program(
        7,
        vec![
            Rule::choice(&[5], &[]),
            Rule::choice(&[6], &[]),
            Rule::choice(&[7], &[]),
            Rule::normal(&[1], &[5]),
            Rule::normal(&[2], &[6]),
            Rule::normal(&[3], &[7]),
            Rule::normal(&[4], &[2, 3]),
            Rule::normal(&[], &[-1, -4]),
        ],
    );
    p.cr_rules = vec![
        CrRule {
            appl: 5,
            label: "r1".into(),
        },
        CrRule {
            appl: 6,
            label: "r2".into(),
        },
        CrRule {
            appl: 7,
            label: "r3".into(),
        },
    ];
    p
}

#[test]
fn cr_cardinality_keeps_the_fewest_applications() {
    // {r1} (one application) beats {r2, r3} (two).
    let models = answer_sets(&cr_program(), BruteConfig::default());
    assert_eq!(
        models,
        vec![BruteModel {
            atoms: vec![1],
            applied: vec![5],
            costs: vec![]
        }]
    );
}

#[test]
fn cr_subset_keeps_every_minimal_support() {
    let config = BruteConfig {
        cr_mode: CrMode::Subset,
        optimize: false,
    };
    let models = answer_sets(&cr_program(), config);
    assert_eq!(atoms_of(&models), vec![vec![1], vec![2, 3, 4]]);
    // prefer(r2, r1): {r2, r3} dominates {r1}.
    let mut p = cr_program();
    p.prefers.push(Prefer {
        better: 6,
        worse: 5,
    });
    let models = answer_sets(&p, config);
    assert_eq!(
        models,
        vec![BruteModel {
            atoms: vec![2, 3, 4],
            applied: vec![6, 7],
            costs: vec![]
        }]
    );
    // Cardinality ignores preferences.
    assert_eq!(
        atoms_of(&answer_sets(&p, BruteConfig::default())),
        vec![vec![1]]
    );
}

#[test]
fn cr_not_needed_means_not_applied() {
    // r1: p :+.  with p also a fact: the program is consistent without CR rules.
    let mut p = program(
        2,
        vec![
            Rule::choice(&[2], &[]),
            Rule::normal(&[1], &[2]),
            Rule::normal(&[1], &[]),
        ],
    );
    p.cr_rules = vec![CrRule {
        appl: 2,
        label: "r1".into(),
    }];
    let models = answer_sets(
        &p,
        BruteConfig {
            cr_mode: CrMode::Subset,
            optimize: false,
        },
    );
    assert_eq!(
        models,
        vec![BruteModel {
            atoms: vec![1],
            applied: vec![],
            costs: vec![]
        }]
    );
}

#[test]
fn cr_models_equal_up_to_application_are_merged() {
    // r1: p :+.  r2: p :+.  :- not p.  Both {r1} and {r2} give {p}: reported once, with r1.
    let mut p = program(
        3,
        vec![
            Rule::choice(&[2], &[]),
            Rule::choice(&[3], &[]),
            Rule::normal(&[1], &[2]),
            Rule::normal(&[1], &[3]),
            Rule::normal(&[], &[-1]),
        ],
    );
    p.cr_rules = vec![
        CrRule {
            appl: 2,
            label: "r1".into(),
        },
        CrRule {
            appl: 3,
            label: "r2".into(),
        },
    ];
    for cr_mode in [CrMode::Cardinality, CrMode::Subset] {
        let models = answer_sets(
            &p,
            BruteConfig {
                cr_mode,
                optimize: false,
            },
        );
        assert_eq!(
            models,
            vec![BruteModel {
                atoms: vec![1],
                applied: vec![2],
                costs: vec![]
            }]
        );
    }
}

#[test]
fn optimization_is_lexicographic_by_priority() {
    // {a; b}.  :- not a, not b.  c :- b.
    // #minimize { 1@2 : a; 1@1 : b; 1@1 : c }.   (a = 1, b = 2, c = 3)
    // {a}: (1, 0); {b, c}: (0, 2); {a, b, c}: (1, 2).  Priority 2 first: {b, c} is optimal.
    let mut p = program(
        3,
        vec![
            Rule::choice(&[1, 2], &[]),
            Rule::normal(&[], &[-1, -2]),
            Rule::normal(&[3], &[2]),
        ],
    );
    p.minimize.push(Minimize {
        priority: 2,
        lits: vec![(1, 1)],
    });
    p.minimize.push(Minimize {
        priority: 1,
        lits: vec![(2, 1), (3, 1)],
    });
    let all = answer_sets(&p, BruteConfig::default());
    assert_eq!(all.len(), 3);
    let best = answer_sets(
        &p,
        BruteConfig {
            optimize: true,
            ..BruteConfig::default()
        },
    );
    assert_eq!(
        best,
        vec![BruteModel {
            atoms: vec![2, 3],
            applied: vec![],
            costs: vec![0, 2]
        }]
    );
}

/// The shown symbols of a model, without duplicates, sorted.
fn shown(program: &GroundProgram, atoms: &[Atom]) -> Vec<String> {
    let holds = |l: Lit| atoms.binary_search(&l.unsigned_abs()).is_ok() == (l > 0);
    let mut symbols: Vec<String> = program
        .outputs
        .iter()
        .filter(|o| o.condition.iter().all(|&l| holds(l)))
        .map(|o| o.symbol.clone())
        .collect();
    symbols.sort();
    symbols.dedup();
    symbols
}

/// Splits a line of clasp's output into symbols: at spaces outside string constants. The
/// result is sorted (clasp prints in atom order, which is not the output-statement order).
fn split_symbols(line: &str) -> Vec<String> {
    let mut symbols = Vec::new();
    let mut current = String::new();
    let (mut in_string, mut escaped) = (false, false);
    for c in line.chars() {
        match c {
            ' ' if !in_string => symbols.push(std::mem::take(&mut current)),
            _ => {
                if in_string && !escaped && c == '"' {
                    in_string = false;
                } else if !in_string && c == '"' {
                    in_string = true;
                }
                escaped = in_string && !escaped && c == '\\';
                current.push(c);
            }
        }
    }
    if !current.is_empty() {
        symbols.push(current);
    }
    symbols.sort();
    symbols
}

#[test]
fn brute_force_agrees_with_recorded_clasp_answers() {
    // `<name>.models`: the answer sets clasp 3.3.5 prints for `<name>.aspif` with
    // `clasp -n 0 --opt-mode=ignore`, one line per answer set (duplicates kept: models that
    // differ only in hidden atoms print the same line), lines sorted; symbols are compared as
    // sorted sets.
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/aspif");
    let mut checked = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "models") {
            continue;
        }
        let expected = std::fs::read_to_string(&path).unwrap();
        let text = std::fs::read(path.with_extension("aspif")).unwrap();
        let p = aspif::read_program(&text).unwrap();
        let mut got: Vec<Vec<String>> = stable_models(&p).iter().map(|m| shown(&p, m)).collect();
        got.sort();
        let mut want: Vec<Vec<String>> = expected.lines().map(split_symbols).collect();
        want.sort();
        assert_eq!(got, want, "{}", path.display());
        checked += 1;
    }
    assert!(
        checked >= 4,
        "expected recorded .models files, found {checked}"
    );
}

/// One recorded model line: sorted atom numbers separated by spaces.
fn line_of(atoms: &[Atom]) -> String {
    atoms
        .iter()
        .map(|a| a.to_string())
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn brute_force_agrees_with_clasp_on_random_programs() {
    // tests/data/aspif/random: 60 random ground programs (choice, disjunctive and weight rules,
    // constraints, externals, minimize statements, CR rules with Lucent's comments and CR
    // minimize) with clasp's stable models and optimal models, recorded by `generate.py`
    // there. clasp reads the CR minimize as an ordinary minimize, which is exactly the default
    // cardinality semantics.
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/aspif/random");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "aspif"))
        .collect();
    paths.sort();
    assert_eq!(paths.len(), 60);
    let (mut models_seen, mut optimal_checked) = (0, 0);
    for path in paths {
        let p = aspif::read_program(&std::fs::read(&path).unwrap()).unwrap();
        let appl: Vec<Atom> = p.cr_rules.iter().map(|c| c.appl).collect();
        let mut got: Vec<String> = stable_models(&p)
            .iter()
            .map(|m| {
                let shown: Vec<Atom> = m.iter().copied().filter(|a| !appl.contains(a)).collect();
                line_of(&shown)
            })
            .collect();
        got.sort();
        let want: Vec<String> = std::fs::read_to_string(path.with_extension("models"))
            .unwrap()
            .lines()
            .map(str::to_owned)
            .collect();
        assert_eq!(got, want, "stable models of {}", path.display());
        models_seen += got.len();
        if let Ok(optimal) = std::fs::read_to_string(path.with_extension("optimal")) {
            let config = BruteConfig {
                cr_mode: CrMode::Cardinality,
                optimize: true,
            };
            let mut got: Vec<String> = answer_sets(&p, config)
                .iter()
                .map(|m| line_of(&m.atoms))
                .collect();
            got.sort();
            got.dedup();
            let want: Vec<String> = optimal.lines().map(str::to_owned).collect();
            assert_eq!(got, want, "optimal models of {}", path.display());
            optimal_checked += 1;
        }
    }
    assert!(
        models_seen > 60 && optimal_checked > 20,
        "{models_seen} {optimal_checked}"
    );
}
