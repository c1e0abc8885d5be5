//! `lucent classify` and `lucent experiment classify` on the command line: exit codes, the
//! JSON's keys, and a tiny experiment end to end.

use std::process::Command;

use serde_json::Value;

fn lucent(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bad_input_and_bad_command_lines_exit_as_clingo() {
    let (code, _, err) = lucent(&["classify", "/nonexistent/scene.json"]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("/nonexistent/scene.json:1:1: error"), "{err}");
    let dir = std::env::temp_dir().join(format!("lucent-vision-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.json");
    std::fs::write(&bad, "{ not json").unwrap();
    let (code, _, err) = lucent(&["classify", bad.to_str().unwrap()]);
    assert_eq!(code, 65, "{err}");
    let (code, _, err) = lucent(&["classify", "--frobnicate"]);
    assert_eq!(code, 1, "{err}");
    let (code, _, err) = lucent(&["experiment", "classify", "--sizes", "a,b"]);
    assert_eq!(code, 1, "{err}");
}

/// A risky scene, classified with KB_full only (no training), as JSON, with a question.
#[test]
fn a_generated_scene_is_classified_and_explained_as_json() {
    let dir = std::env::temp_dir().join(format!("lucent-vision-json-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("scene.json");
    let (code, _, err) = lucent(&[
        "sim",
        "generate",
        "--risky",
        "--seed",
        "1",
        "-o",
        scene.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = lucent(&[
        "classify",
        scene.to_str().unwrap(),
        "--train",
        "0",
        "--why",
        "why is the frobnicator unstable?",
        "--outf=2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let objects = v["Objects"].as_array().unwrap();
    assert!(!objects.is_empty());
    for o in objects {
        assert!(o["occluded"]["value"].is_boolean(), "{o}");
        assert!(o["occluded"]["source"].is_string(), "{o}");
    }
    // The question names no object of the scene: the reply says what was not understood.
    let answer = v["Answers"][0]["answer"].as_str().unwrap();
    assert!(answer.contains("frobnicator"), "{answer}");
}

/// The experiment at a toy scale runs end to end and reports every system and both labels.
#[test]
fn a_tiny_classification_experiment_reports_every_system() {
    let (code, out, err) = lucent(&[
        "experiment",
        "classify",
        "--sizes",
        "4",
        "--test",
        "3",
        "--runs",
        "1",
        "--outf=2",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let rows = v["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 8, "four systems, two labels: {v}");
    for r in rows {
        let acc = r["accuracy"].as_f64().unwrap();
        assert!((0.0..=1.0).contains(&acc), "{r}");
        // 95% intervals of accuracy, precision and recall over the 3 test scenes.
        for i in r["intervals"].as_array().unwrap() {
            let (lo, hi) = (i["lo"].as_f64().unwrap(), i["hi"].as_f64().unwrap());
            assert!(0.0 <= lo && lo <= hi && hi <= 1.0, "{r}");
        }
    }
    // One learning run: no interval (the bootstrap needs two units).
    assert_eq!(
        v["learning"]["intervals"],
        serde_json::json!([null, null, null, null])
    );
    assert_eq!(v["learning"]["runs"], 1);
    assert_eq!(v["removals"].as_array().unwrap().len(), 6);
}

/// `lucent run --see-occlusion N` trains a network at the start, decides occlusion at every
/// look and lists the decisions with their source; zero training scenes is a bad command line.
#[test]
fn a_run_sees_occlusion_from_the_image() {
    let (code, _, err) = lucent(&["run", "--preset", "simulated", "--see-occlusion", "0"]);
    assert_eq!(code, 1, "{err}");
    let (code, out, err) = lucent(&[
        "run",
        "--preset",
        "simulated",
        "--seed",
        "1",
        "--see-occlusion",
        "3",
        "--max-actions",
        "1",
    ]);
    assert!(code == 0 || code == 20, "{err}");
    assert!(err.contains("seeing occlusion: a network trained"), "{err}");
    let line = out
        .lines()
        .find(|l| l.starts_with("Occlusion: "))
        .unwrap_or_else(|| panic!("no occlusion line in {out}"));
    // "Occlusion: R decisions by reasoning (r as the world says), N by the network from the
    // image (n as the world says)": every object in view is judged at every look.
    let numbers: Vec<usize> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter(|w| !w.is_empty())
        .map(|w| w.parse().unwrap())
        .collect();
    assert_eq!(numbers.len(), 4, "{line}");
    assert!(
        numbers[0] + numbers[2] >= 6,
        "a simulated scene has 6 or more objects: {line}"
    );
    assert!(
        numbers[1] <= numbers[0] && numbers[3] <= numbers[2],
        "{line}"
    );
}
