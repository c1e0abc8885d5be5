//! The binary works from any directory (the domain files its verbs default to are built in),
//! and a long job's progress bar is drawn on a terminal without hanging (regression: two rayon
//! workers once waited on a standard-error lock the main thread held while it waited for them).

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

fn lucent() -> &'static str {
    env!("CARGO_BIN_EXE_lucent")
}

/// A fresh empty directory outside the checkout.
fn elsewhere(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lucent-anywhere-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs a command to completion within `limit`, killing it (and failing) if it takes longer.
fn run_within(cmd: &mut Command, limit: Duration) -> (i32, String, String) {
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the command starts");
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let out = child.wait_with_output().unwrap();
            return (
                status.code().unwrap_or(-1),
                String::from_utf8_lossy(&out.stdout).into_owned(),
                String::from_utf8_lossy(&out.stderr).into_owned(),
            );
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            panic!("{cmd:?} did not finish within {limit:?}: it hangs");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn verbs_run_outside_the_checkout() {
    let dir = elsewhere("verbs");
    let limit = Duration::from_secs(900);
    let cases: &[&[&str]] = &[
        &["learn", "--episodes", "2"],
        &["experiment", "h1", "--runs", "1"],
        &["demo", "--out", "demo"],
        &["plan", "domains/ra/scenes/tabletop_task.ald"],
    ];
    for args in cases {
        let (code, _, err) =
            run_within(Command::new(lucent()).args(*args).current_dir(&dir), limit);
        assert!(
            code == 0 || (args[0] == "demo" && code == 20),
            "lucent {args:?} from {}: exit {code}\n{err}",
            dir.display()
        );
        assert!(!err.contains("No such file"), "{args:?}: {err}");
    }
    assert!(dir.join("demo").read_dir().unwrap().next().is_some());
    let _ = std::fs::remove_dir_all(&dir);
}

/// `script` (util-linux) gives the command a pseudo-terminal, so the progress bar is drawn.
#[test]
fn progress_is_drawn_on_a_terminal_without_hanging() {
    let found = Command::new("script").arg("--version").output();
    assert!(
        found.is_ok(),
        "this test needs `script` from util-linux to make a pseudo-terminal: \
         apt-get install -y util-linux"
    );
    let dir = elsewhere("pty");
    // Runs `lucent ARGS` on a pseudo-terminal in `dir`; what the terminal showed.
    let on_terminal = |args: &str| -> String {
        let log = dir.join("typescript");
        let inner = format!("{} {args}", lucent());
        let (code, _, err) = run_within(
            Command::new("script")
                .args(["-qec", &inner])
                .arg(&log)
                .current_dir(&dir),
            // The jobs take seconds; the hang this guards against never ends.
            Duration::from_secs(300),
        );
        assert_eq!(code, 0, "lucent {args}: {err}");
        std::fs::read_to_string(&log).unwrap_or_default()
    };
    let out = dir.join("out");
    let drawn = on_terminal(&format!("experiment h1 --runs 2 --out {}", out.display()));
    assert!(
        drawn.contains("2/2 trials"),
        "no progress bar was drawn:\n{drawn}"
    );
    // `learn` shows a bar over its episodes while it learns.
    let drawn = on_terminal("learn --episodes 2");
    assert!(
        drawn.contains("/2 episodes learning"),
        "no episode bar was drawn:\n{drawn}"
    );
    // Generating a dataset shows a bar over its scenes.
    let drawn = on_terminal("run --preset real --seed 2 --see-occlusion 4");
    assert!(
        drawn.contains("/4 training scenes generated"),
        "no dataset bar was drawn:\n{drawn}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
