//! Bad AL_d input gets positioned diagnostics in gringo's format and exit code 65, never a
//! panic: every file of `tests/data/action/malformed/` is named after its error, and the
//! diagnostics of `lucent translate FILE` are snapshotted; `lucent FILE` (solving) stops with
//! the same diagnostics and exit code. The files also go through the fuzz target's body.

use std::path::PathBuf;

use lucent::action::fuzzing::check_action_invariants;

/// The malformed files, relative to the package root (cargo runs tests there).
fn files() -> Vec<PathBuf> {
    let dir = "tests/data/action/malformed";
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "ald"))
        .collect();
    out.sort();
    assert!(out.len() >= 20, "{}", out.len());
    out
}

use crate::support::cli as cli_support;

fn run(args: &[&str]) -> (i32, String, String) {
    cli_support::lucent_in_process(args, "")
}

#[test]
fn malformed_descriptions_snapshot() {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
    for path in files() {
        let name = path.to_string_lossy().into_owned();
        let (code, out, err) = run(&["translate", &name]);
        assert_eq!(code, 65, "{name}: {err}");
        assert!(out.is_empty(), "{name}");
        let first = err.lines().next().unwrap_or_default();
        assert!(
            first.starts_with(&format!("{name}:")) && first.contains(": error: "),
            "{name}: {first}"
        );
        let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
        insta::assert_snapshot!(stem, err);
        // Solving the file stops at the same diagnostics.
        let (code, _, solve_err) = run(&[&name]);
        assert_eq!(code, 65, "{name}");
        assert!(solve_err.contains(first), "{name}: {solve_err}");
        check_action_invariants(&std::fs::read(&path).unwrap())
            .unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}
