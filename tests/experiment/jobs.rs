//! The experiment harness's scale-out and resumption (issue 16): on a small configuration, the
//! job list run by GNU parallel and merged gives the same report as the in-process run for the
//! same seed, and a rerun over a results directory that already holds some trials reuses them
//! (the stored files are not rewritten) and still gives the same report; a run killed for real
//! resumes from the trials it stored, and a damaged result file is computed again.
//!
//! Timings are the only values allowed to differ: JSON keys `time`, `seconds` and `*_time` are
//! removed before comparing, so are the markdown rows of timing ratios (`| Planning time |`,
//! H2's Table 2), and plots of timings (`*time*.svg`) are not compared.
//! GNU parallel must be installed (`scripts/test.sh` installs it with apt-get when it is missing).

use std::path::{Path, PathBuf};
use std::process::Command;

use serde_json::Value;

/// The small configuration: two short learning runs, one (scene, goal) pair per preset.
// `--no-classify`: the classification experiment is not part of the trial store and its job
// list; `all` runs it in process after H1-H4.
const SMALL: [&str; 11] = [
    "--no-classify",
    "--seed",
    "3",
    "--runs",
    "2",
    "--episodes",
    "1",
    "--configurations",
    "1",
    "--goals",
    "1",
];

fn lucent(args: &[&str]) -> std::process::Output {
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("lucent runs");
    assert!(
        out.status.success(),
        "lucent {args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lucent-experiment-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn strip_times(v: &mut Value) {
    match v {
        Value::Object(map) => {
            map.retain(|k, _| !(k == "time" || k == "seconds" || k.ends_with("_time")));
            map.values_mut().for_each(strip_times);
        }
        Value::Array(items) => items.iter_mut().for_each(strip_times),
        _ => {}
    }
}

/// The report files of a run directory, timings removed.
fn report(dir: &Path) -> (Value, String, Vec<(String, String)>) {
    let mut json: Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("report.json")).unwrap()).unwrap();
    strip_times(&mut json);
    let mut markdown = String::new();
    for line in std::fs::read_to_string(dir.join("report.md"))
        .unwrap()
        .lines()
    {
        if !line.starts_with("| Planning time |") {
            markdown.push_str(line);
            markdown.push('\n');
        }
    }
    let mut plots = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if name.ends_with(".svg") && !name.contains("time") {
            plots.push((name, std::fs::read_to_string(&path).unwrap()));
        }
    }
    plots.sort();
    (json, markdown, plots)
}

fn args<'a>(head: &[&'a str], dir: &'a str, tail: &[&'a str]) -> Vec<&'a str> {
    let mut v: Vec<&str> = head.to_vec();
    v.extend(SMALL);
    v.extend(["--out", dir]);
    v.extend(tail);
    v
}

#[test]
fn job_list_through_gnu_parallel_and_a_resumed_run_match_the_in_process_run() {
    let has_parallel = Command::new("parallel")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    assert!(
        has_parallel,
        "GNU parallel is missing: `apt-get install -y parallel` (scripts/test.sh does it)"
    );

    // 1. In process.
    let a = scratch("inprocess");
    let a_str = a.to_str().unwrap();
    let printed = lucent(&args(&["experiment", "all"], a_str, &["--outf=2"]));
    let mut printed: Value = serde_json::from_slice(&printed.stdout).unwrap();
    strip_times(&mut printed);
    let (json_a, md_a, plots_a) = report(&a);
    assert_eq!(printed, json_a, "--outf=2 prints what report.json holds");
    for h in ["h1", "h2", "h3", "h4"] {
        assert!(json_a.get(h).is_some(), "key {h} in {json_a}");
    }
    for key in ["strict", "relaxed"] {
        for m in ["precision", "recall"] {
            assert!(json_a["h1"][key][m].is_f64(), "h1.{key}.{m} in {json_a}");
        }
    }
    let trials = json_a["trials"].as_u64().unwrap();
    assert!(trials >= 2, "at least the two H1 runs: {json_a}");
    assert!(md_a.contains("| strict |"), "{md_a}");
    assert!(plots_a.iter().any(|(n, _)| n == "h1.svg"));

    // 2. The job list, run by GNU parallel as separate processes, then merged.
    let b = scratch("parallel");
    let b_str = b.to_str().unwrap();
    let jobs = b.join("jobs.txt");
    let emitted = lucent(&args(
        &["experiment", "all"],
        b_str,
        &["--emit-jobs", jobs.to_str().unwrap()],
    ));
    assert!(emitted.stdout.is_empty(), "--emit-jobs runs nothing");
    let lines = std::fs::read_to_string(&jobs).unwrap();
    assert_eq!(lines.lines().count() as u64, trials, "{lines}");
    assert!(
        lines.lines().all(|l| l.contains(" experiment trial ")),
        "{lines}"
    );
    let status = Command::new("parallel")
        .args(["--will-cite", "--halt", "now,fail=1", "-j", "2"])
        .stdin(std::fs::File::open(&jobs).unwrap())
        .status()
        .unwrap();
    assert!(status.success(), "parallel ran the jobs");
    lucent(&["experiment", "merge", b_str]);
    let (json_b, md_b, plots_b) = report(&b);
    assert_eq!(json_a, json_b);
    assert_eq!(md_a, md_b);
    assert_eq!(plots_a, plots_b);

    // 3. An interrupted run: only the first H1 trial finished (its file carries a marker in its
    // timing, which a recomputation would overwrite).
    let c = scratch("resumed");
    let c_str = c.to_str().unwrap();
    std::fs::create_dir_all(c.join("results")).unwrap();
    let first = "h1-kb_full-0000.json";
    let mut kept: Value =
        serde_json::from_str(&std::fs::read_to_string(a.join("results").join(first)).unwrap())
            .unwrap();
    kept["seconds"] = Value::from(12345.5);
    let kept_text = serde_json::to_string_pretty(&kept).unwrap();
    std::fs::write(c.join("results").join(first), &kept_text).unwrap();
    let resumed = lucent(&args(&["experiment", "all"], c_str, &[]));
    let stderr = String::from_utf8_lossy(&resumed.stderr);
    assert!(
        stderr.contains(&format!(
            "experiment: {trials} trials, {} computed, 1 reused",
            trials - 1
        )),
        "{stderr}"
    );
    assert_eq!(
        std::fs::read_to_string(c.join("results").join(first)).unwrap(),
        kept_text,
        "the finished trial was reused, not recomputed"
    );
    let (json_c, md_c, plots_c) = report(&c);
    assert_eq!(json_a, json_c);
    assert_eq!(md_a, md_c);
    assert_eq!(plots_a, plots_c);

    // A result of another setup is not reused: with another seed everything is computed.
    let other = lucent(&[
        "experiment",
        "h1",
        "--seed",
        "4",
        "--runs",
        "1",
        "--episodes",
        "1",
        "--out",
        c_str,
    ]);
    let stderr = String::from_utf8_lossy(&other.stderr);
    assert!(
        stderr.contains("experiment: 1 trials, 1 computed, 0 reused"),
        "{stderr}"
    );

    for d in [a, b, c] {
        let _ = std::fs::remove_dir_all(d);
    }
}

/// A real interruption: the run is killed (SIGKILL, no clean-up) once its first trial is stored;
/// the rerun reuses every stored trial and computes only the rest, a stored result that was
/// damaged afterwards is computed again, and the report is the uninterrupted run's.
#[test]
fn a_killed_run_resumes_and_a_damaged_result_is_computed_again() {
    const RUN: [&str; 8] = [
        "experiment",
        "h1",
        "--seed",
        "5",
        "--runs",
        "3",
        "--episodes",
        "1",
    ];
    let whole = scratch("whole");
    let mut a: Vec<&str> = RUN.to_vec();
    a.extend(["--out", whole.to_str().unwrap()]);
    lucent(&a);

    let cut = scratch("killed");
    let cut_str = cut.to_str().unwrap();
    let mut b: Vec<&str> = RUN.to_vec();
    b.extend(["--out", cut_str]);
    let mut child = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(&b)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("lucent runs");
    let results = cut.join("results");
    let stored = || -> usize {
        std::fs::read_dir(&results)
            .map(|d| {
                d.filter_map(Result::ok)
                    .filter(|e| {
                        let n = e.file_name().to_string_lossy().to_string();
                        n.starts_with("h1-") && n.ends_with(".json")
                    })
                    .count()
            })
            .unwrap_or(0)
    };
    let start = std::time::Instant::now();
    while stored() == 0 && start.elapsed().as_secs() < 600 {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    let _ = child.kill();
    let _ = child.wait();
    let finished = stored();
    assert!(finished >= 1, "a trial was stored before the kill");

    let rerun = lucent(&b);
    let stderr = String::from_utf8_lossy(&rerun.stderr);
    assert!(
        stderr.contains(&format!(
            "experiment: 3 trials, {} computed, {finished} reused",
            3 - finished
        )),
        "{stderr}"
    );
    assert_eq!(report(&whole), report(&cut));

    // A result file cut short (a disk filled, a copy interrupted) is not trusted.
    let victim = results.join("h1-kb_full-0001.json");
    let text = std::fs::read_to_string(&victim).unwrap();
    std::fs::write(&victim, &text[..text.len() / 2]).unwrap();
    let again = lucent(&b);
    let stderr = String::from_utf8_lossy(&again.stderr);
    assert!(
        stderr.contains("experiment: 3 trials, 1 computed, 2 reused"),
        "{stderr}"
    );
    let rewritten = std::fs::read_to_string(&victim).unwrap();
    assert!(
        serde_json::from_str::<Value>(&rewritten).is_ok(),
        "{rewritten}"
    );
    assert_eq!(report(&whole), report(&cut));

    for d in [whole, cut] {
        let _ = std::fs::remove_dir_all(d);
    }
}
