//! `lucent demo`, the README's first command: with the simulator it generates its scene, writes
//! the camera view before and after as PNG files into the directory it names, prints the plan
//! and the plan in English, executes it in the physics world with replanning, and exits 0 when
//! the goal was reached; its run is deterministic. Bad arguments are exit 1.

#[path = "support/cli.rs"]
mod cli_support;

/// `lucent demo ARGS` (the binary).
fn demo(args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["demo"];
    all.extend_from_slice(args);
    cli_support::lucent_binary(&all, "")
}

#[cfg(feature = "sim")]
#[test]
fn the_demo_plans_acts_and_pictures_the_scene() {
    let dir = std::env::temp_dir().join(format!("lucent-demo-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let (code, out, err) = demo(&["--out", dir.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}\n{err}");
    for name in ["before.png", "after.png"] {
        let bytes = std::fs::read(dir.join(name)).unwrap();
        assert_eq!(&bytes[1..4], b"PNG", "{name}");
    }
    assert!(out.contains("plan "), "{out}");
    assert!(out.contains("In English: I will pick up the"), "{out}");
    assert!(out.contains("executed "), "{out}");
    assert!(out.contains("What I did: I picked up the"), "{out}");
    assert!(out.contains("Result: GOAL REACHED"), "{out}");
    // The robot explains its own run: the run is saved and three questions are answered, each
    // with a reason (seed 3's run moves the pot and the red cube, so every question has one).
    assert!(dir.join("run.json").exists());
    assert!(out.contains("Asked about my run:"), "{out}");
    let answers: Vec<&str> = out.lines().filter(|l| l.starts_with("  A: ")).collect();
    assert_eq!(answers.len(), 3, "{out}");
    assert!(
        answers.iter().all(|a| a.starts_with("  A: Because ")),
        "{out}"
    );
    // Deterministic: the same seed tells the same story (timings aside).
    let (_, again, _) = demo(&["--out", dir.to_str().unwrap()]);
    let story = |t: &str| -> Vec<String> {
        t.lines()
            .filter(|l| !l.starts_with("Time"))
            .map(String::from)
            .collect()
    };
    assert_eq!(story(&out), story(&again));
}

#[test]
fn bad_arguments_are_a_usage_error() {
    let (code, _, err) = demo(&["--frobnicate", "1"]);
    assert_eq!(code, 1, "{err}");
    let (code, out, _) = demo(&["--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("usage: lucent demo"));
}
