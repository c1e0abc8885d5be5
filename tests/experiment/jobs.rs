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

/// Runs of five seeds merged into one report (`lucent experiment merge DIR... --out OUT`):
/// every count is the sum of the seeds' counts and every mean the trial-weighted mean of the
/// seeds' means, whichever order the directories are given in; the five seeds' job lists run
/// by one GNU parallel invocation and merged give the same report as the in-process runs
/// merged; a run of another setup is refused.
#[test]
fn a_merge_of_seeds_equals_the_sum_of_its_parts() {
    const SEEDS: [&str; 5] = ["3", "4", "5", "6", "7"];
    let small_with_seed = |seed: &'static str| -> Vec<&'static str> {
        let mut v: Vec<&str> = SMALL.to_vec();
        let at = v.iter().position(|a| *a == "--seed").unwrap();
        v[at + 1] = seed;
        v
    };
    let mut parts = Vec::new();
    let mut dirs = Vec::new();
    for seed in SEEDS {
        let d = scratch(&format!("seed{seed}"));
        let mut a = vec!["experiment", "all"];
        a.extend(small_with_seed(seed));
        let d_str = d.to_str().unwrap().to_string();
        let mut owned: Vec<String> = a.iter().map(|s| s.to_string()).collect();
        owned.extend(["--out".to_string(), d_str, "--outf=2".to_string()]);
        let refs: Vec<&str> = owned.iter().map(String::as_str).collect();
        let printed = lucent(&refs);
        parts.push(serde_json::from_slice::<Value>(&printed.stdout).unwrap());
        dirs.push(d);
    }
    let merged_dir = scratch("merged");
    let m = merged_dir.to_str().unwrap();
    let names: Vec<&str> = dirs.iter().map(|d| d.to_str().unwrap()).collect();
    let mut a = vec!["experiment", "merge"];
    a.extend(&names);
    a.extend(["--out", m, "--outf=2"]);
    let mut merged: Value = serde_json::from_slice(&lucent(&a).stdout).unwrap();
    let mut a = vec!["experiment", "merge"];
    a.extend(names.iter().rev());
    a.push("--outf=2");
    let mut reversed: Value = serde_json::from_slice(&lucent(&a).stdout).unwrap();
    strip_times(&mut merged);
    strip_times(&mut reversed);
    assert_eq!(
        merged, reversed,
        "the order of the directories does not matter"
    );
    let md = std::fs::read_to_string(merged_dir.join("report.md")).unwrap();
    assert!(md.contains("Seeds 3, 4, 5, 6, 7 pooled"), "{md}");
    assert_eq!(merged["seeds"], serde_json::json!([3, 4, 5, 6, 7]));

    let n = |v: &Value| v.as_u64().unwrap_or_else(|| panic!("a count: {v}"));
    let f = |v: &Value| v.as_f64();
    let sum = |path: &dyn Fn(&Value) -> &Value| parts.iter().map(|p| n(path(p))).sum::<u64>();
    assert_eq!(n(&merged["trials"]), sum(&|v| &v["trials"]));
    for key in ["strict_counts", "relaxed_counts"] {
        for c in ["tp", "fp", "fn"] {
            assert_eq!(
                n(&merged["h1"][key][c]),
                sum(&|v| &v["h1"][key][c]),
                "h1.{key}.{c}"
            );
        }
    }
    assert_eq!(
        merged["h1"]["runs"].as_array().unwrap().len(),
        parts
            .iter()
            .map(|p| p["h1"]["runs"].as_array().unwrap().len())
            .sum::<usize>()
    );
    for k in 0..2 {
        for c in ["trees", "rechecked", "repeats", "bad_leaves", "no_plan"] {
            assert_eq!(
                n(&merged["h3"]["presets"][k][c]),
                sum(&|v| &v["h3"]["presets"][k][c]),
                "h3 preset {k} {c}"
            );
        }
    }
    // A trial-weighted mean of the parts' fractions, checked against the merged figure.
    let weighted = |at: &dyn Fn(&Value) -> Value, value: &str, weight: &dyn Fn(&Value) -> u64| {
        let (mut total, mut count) = (0.0, 0);
        for p in &parts {
            let x = at(p);
            if let Some(v) = f(&x[value]) {
                total += v * weight(&x) as f64;
                count += weight(&x);
            }
        }
        (count > 0).then(|| total / count as f64)
    };
    // H2: pair counts add up, fractions are the trial-weighted means of the parts', in both
    // modes and in the readings.
    for preset in ["real", "simulated"] {
        assert_eq!(
            n(&merged["h2"][preset]["pairs"]),
            sum(&|v| &v["h2"][preset]["pairs"])
        );
        for mode in ["fixed", "iterative"] {
            for cond in ["without", "with"] {
                let at = |v: &Value| v["h2"][preset][mode][cond].clone();
                let total: u64 = parts.iter().map(|p| n(&at(p)["trials"])).sum();
                assert_eq!(n(&at(&merged)["trials"]), total, "{preset} {mode} {cond}");
                for frac in ["optimal", "suboptimal", "incorrect"] {
                    if let Some(want) = weighted(&at, frac, &|x| n(&x["trials"])) {
                        let got = f(&at(&merged)[frac]).unwrap();
                        assert!(
                            (got - want).abs() < 1e-9,
                            "{preset} {mode} {cond} {frac}: {got} vs {want}"
                        );
                    }
                }
            }
        }
        for reading in ["one_missing", "fixed_one"] {
            let at = |v: &Value| v["h2"][preset]["readings"][reading]["without"].clone();
            let total: u64 = parts.iter().map(|p| n(&at(p)["trials"])).sum();
            assert_eq!(n(&at(&merged)["trials"]), total, "{preset} {reading}");
            if let Some(want) = weighted(&at, "incorrect", &|x| n(&x["trials"])) {
                let got = f(&at(&merged)["incorrect"]).unwrap();
                assert!(
                    (got - want).abs() < 1e-9,
                    "{preset} {reading}: {got} vs {want}"
                );
            }
        }
    }
    // H4: question counts add up, precision is the count-weighted mean of the parts'.
    for preset in ["real", "simulated"] {
        for cond in 0..2 {
            for q in 0..4 {
                let row = |v: &Value| v["h4"][preset][cond]["rows"][q].clone();
                let total: u64 = parts.iter().map(|p| n(&row(p)[3])).sum();
                assert_eq!(n(&row(&merged)[3]), total, "{preset} {cond} {q}");
                if total > 0 {
                    let w: f64 = parts
                        .iter()
                        .map(|p| f(&row(p)[1]).map_or(0.0, |v| v * n(&row(p)[3]) as f64))
                        .sum();
                    let got = f(&row(&merged)[1]).unwrap();
                    assert!(
                        (got - w / total as f64).abs() < 1e-9,
                        "{preset} {cond} {q}: {got} vs {}",
                        w / total as f64
                    );
                }
            }
        }
    }
    // The same five seeds as one job list, run by one GNU parallel invocation, then merged:
    // the report of the in-process runs, merged.
    let mut job_dirs = Vec::new();
    let mut all_jobs = String::new();
    for seed in SEEDS {
        let d = scratch(&format!("jobs{seed}"));
        let jobs = d.join("jobs.txt");
        let mut a = vec!["experiment", "all"];
        a.extend(small_with_seed(seed));
        a.extend([
            "--out",
            d.to_str().unwrap(),
            "--emit-jobs",
            jobs.to_str().unwrap(),
        ]);
        lucent(&a);
        all_jobs.push_str(&std::fs::read_to_string(&jobs).unwrap());
        job_dirs.push(d);
    }
    let jobs = merged_dir.join("all-jobs.txt");
    std::fs::write(&jobs, &all_jobs).unwrap();
    assert_eq!(all_jobs.lines().count() as u64, n(&merged["trials"]));
    let status = Command::new("parallel")
        .args(["--will-cite", "--halt", "now,fail=1", "-j", "2"])
        .stdin(std::fs::File::open(&jobs).unwrap())
        .status()
        .expect("GNU parallel runs (`apt-get install -y parallel`)");
    assert!(status.success(), "parallel ran the five seeds' jobs");
    let pooled = scratch("pooled");
    let mut a = vec!["experiment", "merge"];
    let job_names: Vec<&str> = job_dirs.iter().map(|d| d.to_str().unwrap()).collect();
    a.extend(&job_names);
    a.extend(["--out", pooled.to_str().unwrap()]);
    lucent(&a);
    assert_eq!(
        report(&merged_dir),
        report(&pooled),
        "one parallel run of the five seeds merges to the in-process runs' report"
    );
    for d in job_dirs.into_iter().chain([pooled]) {
        let _ = std::fs::remove_dir_all(d);
    }
    // A run of another setup (here: more runs) is refused, with exit 65.
    let other = scratch("other");
    let o = other.to_str().unwrap();
    let mut a: Vec<&str> = vec!["experiment", "h1"];
    a.extend(small_with_seed("5"));
    let at = a.iter().position(|x| *x == "--runs").unwrap();
    a[at + 1] = "1";
    a.extend(["--out", o]);
    lucent(&a);
    let refused = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(["experiment", "merge", names[0], o])
        .output()
        .unwrap();
    assert_eq!(refused.status.code(), Some(65), "{refused:?}");
    assert!(
        String::from_utf8_lossy(&refused.stderr).contains("differ"),
        "{refused:?}"
    );
    for d in dirs.into_iter().chain([merged_dir, other]) {
        let _ = std::fs::remove_dir_all(d);
    }
}
