//! The CDCL solver, with the independent checker on (`Config::check_models`, as `--check`), on
//! the random ground programs of `tests/data/aspif/random` against the answers recorded
//! there by `generate.py` (clingo 5.8.3's stable models in `.models`, its optimal models in
//! `.optimal`; the command is in `generate.py`).
//!
//! Regression: `018` has `#external a(3).` on an atom that also heads rules. clasp ignores the
//! external statement (the rules define the atom), so its only answer set is `{a(1)}`; the
//! solver used to keep `a(3)` free, reported `{a(1), a(3)}` and `{a(1), a(3), a(4)}` as well,
//! and `--check` then panicked with "the solver found a model that is not stable".

use lucent::ground::aspif;
use lucent::ground::program::{Atom, GroundProgram};
use lucent::solve::{Config, OptMode, Solver};

fn line_of(atoms: &[Atom]) -> String {
    atoms
        .iter()
        .map(|a| a.to_string())
        .collect::<Vec<_>>()
        .join(" ")
}

/// `atoms` without the application atoms `appl` (the recorded answers leave them out).
fn without(atoms: &[Atom], appl: &[Atom]) -> Vec<Atom> {
    atoms
        .iter()
        .copied()
        .filter(|a| !appl.contains(a))
        .collect()
}

fn random_programs() -> Vec<std::path::PathBuf> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/aspif/random");
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "aspif"))
        .collect();
    paths.sort();
    assert_eq!(paths.len(), 60);
    paths
}

/// All stable models with CR rules read as the plain choices they are in aspif (what clasp
/// computes), application atoms left out, one line per model (duplicates kept), sorted.
fn stable_model_lines(p: &GroundProgram) -> Vec<String> {
    let appl: Vec<Atom> = p.cr_rules.iter().map(|c| c.appl).collect();
    let mut plain = p.clone();
    plain.cr_rules.clear();
    plain.prefers.clear();
    let config = Config {
        opt_mode: OptMode::Ignore,
        check_models: true,
        ..Config::all_models()
    };
    let mut lines: Vec<String> = Solver::new(&plain, config)
        .solve()
        .models
        .iter()
        .map(|m| line_of(&without(&m.atoms, &appl)))
        .collect();
    lines.sort();
    lines
}

#[test]
fn solver_agrees_with_clasp_on_random_programs() {
    let mut optimal_checked = 0;
    for path in random_programs() {
        let p = aspif::read_program(&std::fs::read(&path).unwrap()).unwrap();
        let want: Vec<String> = std::fs::read_to_string(path.with_extension("models"))
            .unwrap()
            .lines()
            .map(str::to_owned)
            .collect();
        assert_eq!(
            stable_model_lines(&p),
            want,
            "stable models of {}",
            path.display()
        );
        if let Ok(optimal) = std::fs::read_to_string(path.with_extension("optimal")) {
            let appl: Vec<Atom> = p.cr_rules.iter().map(|c| c.appl).collect();
            let config = Config {
                opt_mode: OptMode::OptN,
                check_models: true,
                ..Config::all_models()
            };
            let mut got: Vec<String> = Solver::new(&p, config)
                .solve()
                .models
                .iter()
                // With CR rules only, every answer set reported has the minimal number of
                // applied CR rules, which is what clasp's optimum of the CR minimize is.
                .filter(|m| m.optimal || p.minimize.is_empty())
                .map(|m| line_of(&without(&m.atoms, &appl)))
                .collect();
            got.sort();
            got.dedup();
            let want: Vec<String> = optimal.lines().map(str::to_owned).collect();
            assert_eq!(got, want, "optimal models of {}", path.display());
            optimal_checked += 1;
        }
    }
    assert!(optimal_checked > 20, "{optimal_checked}");
}
