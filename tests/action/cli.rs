//! `lucent translate FILE.ald` and `lucent FILE.ald` on the command line: the printed program
//! (snapshotted for a description with every statement kind), its origin comments, profiles,
//! `-c` switches, and solving an AL_d file like any other program.

use lucent::base::FileId;
use lucent::syntax::ast::Dialect;

use crate::support::cli as cli_support;

fn run(args: &[&str]) -> (i32, String, String) {
    cli_support::lucent_in_process(args, "")
}

fn at_root() {
    std::env::set_current_dir(env!("CARGO_MANIFEST_DIR")).unwrap();
}

#[test]
fn translation_of_every_statement_kind() {
    at_root();
    let (code, out, err) = run(&["translate", "tests/data/action/every_kind.ald"]);
    assert_eq!(code, 0, "{err}");
    // The output is a CR-Prolog program of the clingo dialect.
    let parsed = lucent::syntax::parse(FileId(0), &out, Dialect::Clingo);
    assert!(!parsed.has_errors(), "{:?}", parsed.diagnostics);
    insta::assert_snapshot!(out);
}

#[test]
fn profiles_and_switches_change_the_translation() {
    at_root();
    let file = "tests/data/action/every_kind.ald";
    let (_, plain, _) = run(&["translate", file]);
    assert!(plain.contains("#const horizon = 9."));
    assert!(!plain.contains("% E2:"));
    let (code, careful, _) = run(&["translate", file, "--profile", "careful"]);
    assert_eq!(code, 0);
    assert!(careful.contains("#const horizon = 2."));
    assert!(careful.contains("% E2: executability condition: impossible drop(R, X, P) if small(P)"));
    let (_, set, _) = run(&[
        "translate",
        file,
        "--profile=careful",
        "-c",
        "horizon=5",
        "-cstrict=off",
    ]);
    assert!(set.contains("#const horizon = 5."));
    assert!(!set.contains("% E2:"));
    let (_, creation, _) = run(&[
        "translate",
        file,
        "-c",
        "stability_constraint=creation_only",
    ]);
    assert!(
        creation.contains(":- -holds(steady(X), I + 1), not -holds(steady(X), I)"),
        "{creation}"
    );
    let (_, iterative, _) = run(&["translate", file, "-c", "horizon_mode=iterative"]);
    assert!(iterative.contains(":- not goal(horizon)."));
    assert!(!iterative.contains("success"));
}

#[test]
fn unknown_profile_is_an_input_error() {
    at_root();
    let (code, out, err) = run(&[
        "translate",
        "tests/data/action/every_kind.ald",
        "--profile",
        "nope",
    ]);
    assert_eq!(code, 65);
    assert!(out.is_empty());
    assert!(
        err.starts_with("tests/data/action/every_kind.ald:1:1-2: error: unknown profile `nope` (the description declares: careful)"),
        "{err}"
    );
}

#[test]
fn usage_of_translate() {
    let (code, out, _) = run(&["translate", "--help"]);
    assert_eq!(code, 0);
    assert!(out.starts_with("usage: lucent translate FILE.ald"));
    let (code, _, err) = run(&["translate"]);
    assert_eq!(code, 1);
    assert!(err.contains("needs a file"));
    let (code, _, _) = run(&["translate", "/nonexistent/x.ald"]);
    assert_eq!(code, 65);
}

#[test]
fn an_ald_file_is_solved_like_any_program() {
    at_root();
    let (code, out, err) = run(&[
        "domains/ra/scenes/tabletop_task.ald",
        "--profile",
        "tabletop",
        "-n",
        "0",
    ]);
    assert_eq!(code, 30, "{err}");
    assert!(out.contains("Models       : 4"), "{out}");
    let (code, out, _) = run(&[
        "domains/ra/scenes/tabletop_task.ald",
        "-c",
        "horizon=2",
        "-c",
        "horizon_mode=iterative",
    ]);
    assert_eq!(code, 20);
    assert!(out.contains("UNSATISFIABLE"));
}
