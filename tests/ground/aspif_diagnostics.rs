//! Malformed aspif at the command line (`lucent --mode=clasp`): exit code 65 and a diagnostic
//! `file:line:column: error: malformed aspif input: ...` (snapshots), never a panic. The inputs
//! are named after their error; each comment says where the error is and why.

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs `lucent --mode=clasp` on `input` from standard input; returns (exit code, stderr).
fn clasp_mode(input: &[u8]) -> (i32, String) {
    let (code, _, err) = clasp_mode_out(input, &["-n0"]);
    (code, err)
}

fn diagnostic(input: &[u8]) -> String {
    let (code, err) = clasp_mode(input);
    assert_eq!(code, 65, "{err}");
    assert!(!err.contains("panicked"), "{err}");
    err
}

#[test]
fn bad_header() {
    // Line 1, column 1: `aps` is not the `asp` header.
    insta::assert_snapshot!(diagnostic(b"aps 1 0 0\n0\n"));
}

#[test]
fn letter_in_atom() {
    // Line 2, column 7: the head atom `1x` is not a number.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n1 0 1 1x 0 0\n0\n"));
}

#[test]
fn atom_out_of_range() {
    // Line 2, column 7: atoms are positive; `-3` in a head is out of range.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n1 0 1 -3 0 0\n0\n"));
}

#[test]
fn unknown_statement() {
    // Line 2, column 1: aspif version 1 has statement types 0 to 10.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n42 1 2\n0\n"));
}

#[test]
fn bad_external_value() {
    // Line 2, column 5: external values are 0 to 3.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n5 1 7\n0\n"));
}

#[test]
fn missing_end_of_step() {
    // The input ends after line 2 without the step's closing `0`.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n1 0 1 1 0 0\n"));
}

#[test]
fn truncated_rule() {
    // Line 2: the body announces two literals and gives one; the newline comes where the
    // second literal should be.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n1 0 1 1 0 2 3\n0\n"));
}

#[test]
fn negative_weight() {
    // Line 2, column 17 (the weight of literal 2): weight bodies take non-negative weights (clasp rejects them too).
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n1 0 1 1 1 1 1 2 -1\n0\n"));
}

#[test]
fn binary_garbage() {
    // Not text at all: the header is missing.
    insta::assert_snapshot!(diagnostic(b"\x00\xff\xfe\x01asp"));
}

#[test]
fn output_symbol_not_utf8() {
    // Line 2, column 5: the output symbol's two bytes are not UTF-8.
    insta::assert_snapshot!(diagnostic(b"asp 1 0 0\n4 2 \xff\xfe 0\n0\n"));
}

#[test]
fn weight_body_too_heavy() {
    // Line 2, column 17 (the first weight): the bound 1 and the weight 4611686018427387904
    // (2^62) of a weight body add up to more than 2^62, so sums over them could overflow.
    insta::assert_snapshot!(diagnostic(
        b"asp 1 0 0\n1 0 1 3 1 1 2 1 4611686018427387904 2 1\n0\n"
    ));
}

#[test]
fn huge_bound() {
    // Line 2, column 11: the bound -9223372036854775808 alone is beyond 2^62 in absolute value.
    insta::assert_snapshot!(diagnostic(
        b"asp 1 0 0\n1 0 1 3 1 -9223372036854775808 1 1 5\n0\n"
    ));
}

#[test]
fn minimize_priority_too_heavy() {
    // Line 3, column 10: the weights of priority 0 add up over both statements to 2^62 + 1
    // (each alone fits); the solver adds the statements of one priority together.
    insta::assert_snapshot!(diagnostic(
        b"asp 1 0 0\n2 0 1 1 4611686018427387904\n2 0 1 -2 -1\n0\n"
    ));
}

/// Runs `lucent --mode=clasp` on `input` with `args`; returns (exit code, stdout, stderr).
fn clasp_mode_out(input: &[u8], args: &[&str]) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .arg("--mode=clasp")
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    child.stdin.take().unwrap().write_all(input).unwrap();
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().expect("exited, not killed by a signal"),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

#[test]
fn largest_atom_id_is_solved_in_little_memory() {
    // Atoms 2147483647 (the largest aspif literal), 5 and 7: {a; b}. c :- 2 {a = 3; b = 1}.
    // #minimize {1 : a; 3 : not b}. Sized by the largest atom, the solver's per-atom arrays
    // would take tens of gigabytes; renumbered, three atoms. Optimal answer sets by hand:
    // {} costs 3, {b} 0, {a, c} 4, {a, b, c} 1 (c holds exactly when a does), so {b} is the
    // single optimum. Same program with atoms 1, 2, 3: `clasp --opt-mode=optN -n0` gives the
    // single optimal model `b` with `Optimization: 0`.
    let input = b"asp 1 0 0\n1 1 2 2147483647 5 0 0\n1 0 1 7 1 2 2 2147483647 3 5 1\n\
2 0 2 2147483647 1 -5 3\n4 1 a 1 2147483647\n4 1 b 1 5\n4 1 c 1 7\n0\n";
    let (code, out, err) = clasp_mode_out(input, &["--opt-mode=optN", "-n0", "--check"]);
    assert_eq!(code, 30, "{err}");
    assert!(
        out.contains("Answer: 1\nb\nOptimization: 0\nOPTIMUM FOUND"),
        "{out}"
    );
}

#[test]
fn extreme_weights_and_bounds_do_not_overflow() {
    // {a; b}. #minimize {-2^61 : not a; -2^61 : not b}. (the largest sum the reader accepts in
    // absolute value, 2^62). Costs by hand: {} -2^62, {a} and {b} -2^61, {a, b} 0, so the
    // number of models with cost at most the bound is counted by hand. Every command-line
    // bound, down to i64::MIN and up to i64::MAX, is taken as it is, without overflow.
    let input =
        b"asp 1 0 0\n1 1 2 1 2 0 0\n2 0 2 -1 -2305843009213693952 -2 -2305843009213693952\n\
4 1 a 1 1\n0\n";
    for (bound, models) in [
        ("-9223372036854775808", 0),
        ("-4611686018427387905", 0),
        ("-4611686018427387904", 1),
        ("-2305843009213693952", 3),
        ("9223372036854775807", 4),
    ] {
        let (code, out, err) = clasp_mode_out(
            input,
            &[&format!("--opt-mode=enum,{bound}"), "-n0", "--check"],
        );
        assert!(!err.contains("panicked"), "{err}");
        assert_eq!(
            code,
            if models == 0 { 20 } else { 30 },
            "{bound}: {out}{err}"
        );
        assert_eq!(out.matches("Answer:").count(), models, "{bound}: {out}");
    }
    let (code, out, err) = clasp_mode_out(input, &["--opt-mode=optN", "-n0"]);
    assert_eq!(code, 30, "{err}");
    assert!(
        out.contains("Answer: 1\n\nOptimization: -4611686018427387904\nOPTIMUM FOUND"),
        "{out}"
    );
}
