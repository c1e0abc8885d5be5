//! `lucent experiment` on the command line, cheaply (no learning run): the JSON shape of
//! `experiment h1` (issue 15's keys at the top, issue 16's `h1` key), hypotheses that this build
//! cannot run reported as "not available: <reason>" rather than numbers, and bad command lines,
//! bad trial ids and incomplete merges answered with a message and a non-zero exit.

use std::process::Command;

use serde_json::Value;

fn lucent(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("lucent runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn h1_json_keeps_issue_15_keys_and_has_the_h1_key() {
    let (code, out, err) = lucent(&["experiment", "h1", "--runs", "0", "--outf=2"]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    for key in ["strict", "relaxed"] {
        for m in ["precision", "recall"] {
            assert!(v[key][m].is_number(), "{key}.{m} in {v}");
            assert!(v["h1"][key][m].is_number(), "h1.{key}.{m} in {v}");
        }
    }
    assert_eq!(v["h1"]["paper"]["strict"]["precision"], 69.2);
    assert_eq!(v["seed"], 0);
    assert_eq!(v["trials"], 0);
}

#[test]
fn every_hypothesis_has_a_key_and_missing_ones_say_why() {
    let (code, out, err) = lucent(&[
        "experiment",
        "all",
        "--runs",
        "0",
        "--configurations",
        "0",
        "--no-classify",
        "--outf=2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    for h in ["h1", "h2", "h3", "h4"] {
        match &v[h] {
            Value::Object(_) => {}
            Value::String(s) => assert!(s.starts_with("not available: ") && s.len() > 20, "{s}"),
            other => panic!("{h}: {other}"),
        }
    }
    // `all` runs the classification experiment after H1-H4 (minutes); it has its own test.
    let (code, md, _) = lucent(&[
        "experiment",
        "all",
        "--runs",
        "0",
        "--configurations",
        "0",
        "--no-classify",
    ]);
    assert_eq!(code, 0);
    assert!(
        md.starts_with("# Lucent: the paper's experiments H1-H4"),
        "{md}"
    );
    assert!(md.contains("## H1: learning accuracy (Table 1)"), "{md}");
}

#[test]
fn bad_command_lines_and_incomplete_merges_fail_with_a_message() {
    let (code, _, err) = lucent(&["experiment", "h5"]);
    assert_eq!(code, 1);
    assert!(err.contains("unknown experiment 'h5'"), "{err}");
    let (code, _, err) = lucent(&["experiment", "h1", "--runs", "many"]);
    assert_eq!(code, 1);
    assert!(err.contains("'--runs': 'many' is not a number"), "{err}");
    let (code, _, err) = lucent(&["experiment", "h1", "--emit-jobs", "/dev/null"]);
    assert_eq!(code, 1);
    assert!(err.contains("--emit-jobs needs --out DIR"), "{err}");

    let dir = std::env::temp_dir().join(format!("lucent-experiment-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let d = dir.to_str().unwrap();
    let (code, _, err) = lucent(&["experiment", "merge", d]);
    assert_eq!(code, 65);
    assert!(err.contains("run.json"), "{err}");
    let jobs = dir.join("jobs.txt");
    let (code, _, err) = lucent(&[
        "experiment",
        "h1",
        "--runs",
        "3",
        "--out",
        d,
        "--emit-jobs",
        jobs.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(std::fs::read_to_string(&jobs).unwrap().lines().count(), 3);
    let (code, _, err) = lucent(&["experiment", "merge", d]);
    assert_eq!(code, 65);
    assert!(
        err.contains("3 of 3 trials have no result") && err.contains("h1-kb_full-0000"),
        "{err}"
    );
    let (code, _, err) = lucent(&["experiment", "trial", "h1-nowhere-1", "--out", d]);
    assert_eq!(code, 1);
    assert!(err.contains("'h1-nowhere-1' is not a trial id"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
