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
