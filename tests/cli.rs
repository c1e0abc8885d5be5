//! Command-line tests: exit codes, output sections and diagnostic format, through the real
//! binary. Expected outputs are derived from REFERENCE.md (exit codes) and from gringo's
//! diagnostic format (`file:line:col-col: error: message`).

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs `lucent ARGS` with `stdin` and returns (exit code, stdout, stderr).
fn lucent(args: &[&str], stdin: &str) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the lucent binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn help_lists_options_and_exits_0() {
    let (code, out, _) = lucent(&["--help"], "");
    assert_eq!(code, 0);
    for option in [
        "--models",
        "--const",
        "--outf",
        "--opt-mode",
        "--time-limit",
        "--mode",
    ] {
        assert!(out.contains(option), "--help lacks {option}");
    }
}

#[test]
fn version_exits_0() {
    let (code, out, _) = lucent(&["--version"], "");
    assert_eq!(code, 0);
    assert!(out.starts_with("lucent version "));
}

#[test]
fn unknown_option_is_a_usage_error() {
    let (code, out, err) = lucent(&["--no-such-option"], "");
    assert_eq!(code, 128);
    assert!(out.is_empty());
    assert!(err.contains("*** ERROR: (lucent): 'no-such-option': unknown option"));
    assert!(err.contains("Try '--help'"));
}

#[test]
fn bad_value_is_a_usage_error() {
    let (code, _, err) = lucent(&["-n", "many"], "");
    assert_eq!(code, 128);
    assert!(err.contains("'many' invalid value for: 'models'"));
}

#[test]
fn missing_file_is_an_input_error() {
    let (code, _, err) = lucent(&["/nonexistent/program.lp"], "");
    assert_eq!(code, 65);
    assert!(err.contains("<cmd>: error: file could not be opened:\n  /nonexistent/program.lp"));
}

/// The sorted answer sets in clasp's text output (each as its sorted atoms).
fn answer_sets(out: &str) -> Vec<Vec<String>> {
    let lines: Vec<&str> = out.lines().collect();
    let mut models: Vec<Vec<String>> = lines
        .iter()
        .enumerate()
        .filter(|(_, l)| l.starts_with("Answer:"))
        .map(|(i, _)| {
            let mut atoms: Vec<String> = lines[i + 1]
                .split_whitespace()
                .map(str::to_string)
                .collect();
            atoms.sort();
            atoms
        })
        .collect();
    models.sort();
    models
}

#[test]
fn project_atom_ranges_over_its_predicate() {
    // `#project q(X,Y) : p(X).` binds Y from q/2's atoms as gringo does: the four answer sets
    // of {q(1,1); q(1,2)} stay four (clingo 5.8.3: `clingo 0 --project` on this program).
    let prog = "p(1). {q(1,1..2)}. {r}. #project q(X,Y) : p(X).";
    let (code, out, _) = lucent(&["0", "--project"], prog);
    assert_eq!(code, 30);
    let want: Vec<Vec<&str>> = vec![
        vec!["p(1)"],
        vec!["p(1)", "q(1,1)"],
        vec!["p(1)", "q(1,1)", "q(1,2)"],
        vec!["p(1)", "q(1,2)"],
    ];
    assert_eq!(answer_sets(&out), want);
}

#[test]
fn external_value_is_a_term_of_the_instance() {
    // `[X]` takes each instance's value; values other than true, false, free and release leave
    // the instance out (clingo 5.8.3: `clingo 0` on this program gives these two answer sets).
    let prog = "d(true;false;free;release;7). #external e(X) : d(X). [X]";
    let (code, out, _) = lucent(&["0"], prog);
    assert_eq!(code, 30);
    let d = ["d(7)", "d(false)", "d(free)", "d(release)", "d(true)"];
    let mut one: Vec<&str> = d.to_vec();
    one.push("e(true)");
    let mut two = one.clone();
    two.push("e(free)");
    two.sort();
    one.sort();
    let mut want = vec![one, two];
    want.sort();
    assert_eq!(answer_sets(&out), want);
}
