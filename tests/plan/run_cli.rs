//! `lucent run` from the command line: a noise-free run on a generated scene reaches its goal
//! (exit 0), saves a history that loads back and prints it with `--outf=2`; bad input (an
//! unknown object in the goal, a malformed goal, a malformed scene file, an unknown option)
//! gets a message and a non-zero exit, never a panic; an impossible goal and a horizon budget
//! too small end the run with "no plan of at most H steps" and exit 20.

use lucent::plan::history::{Ending, History};

use crate::support::cli as cli_support;

/// `lucent ARGS` (the binary).
fn lucent(args: &[&str]) -> (i32, String, String) {
    cli_support::lucent_binary(args, "")
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("lucent-run-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

#[test]
fn a_noise_free_run_reaches_its_goal_and_saves_its_history() {
    let path = scratch("h.json");
    let log = scratch("run.log");
    let (code, out, err) = lucent(&[
        "run",
        "--preset",
        "real",
        "--seed",
        "1",
        "--goal",
        "in_hand(rob1,red_capsicum)",
        "--perception-noise",
        "0",
        "--actuation-noise",
        "0",
        "--save-history",
        path.to_str().unwrap(),
        "--log",
        log.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{out}\n{err}");
    assert!(out.contains("Result: GOAL REACHED"), "{out}");
    assert!(
        err.contains("[step 0] plan of 1 action (initial): pickup(rob1,red_capsicum)"),
        "{err}"
    );
    assert!(
        err.contains("[step 0] executed pickup(rob1,red_capsicum)"),
        "{err}"
    );
    let h = History::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
    assert_eq!(h.ending, Some(Ending::GoalObserved));
    assert_eq!(h.actions(), vec!["pickup(rob1,red_capsicum)"]);
    assert_eq!(h.goal_in_truth, Some(true));
    let logged = std::fs::read_to_string(&log).unwrap();
    assert!(logged.contains("executed pickup(rob1,red_capsicum)"));
    assert!(logged.contains("Result: GOAL REACHED"));

    let (code, out, _) = lucent(&[
        "run",
        "--preset=real",
        "--seed=1",
        "--goal=in_hand(rob1,red_capsicum)",
        "--perception-noise=0",
        "--actuation-noise=0",
        "--outf=2",
    ]);
    assert_eq!(code, 0);
    assert_eq!(History::from_json(&out).unwrap(), h);
}

#[test]
fn bad_input_is_a_message_and_a_non_zero_exit() {
    let (code, _, err) = lucent(&[
        "run",
        "--preset",
        "real",
        "--seed",
        "1",
        "--goal",
        "on(unicorn,table)",
    ]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("`unicorn` is no object of the scene"), "{err}");

    let (code, _, err) = lucent(&["run", "--goal", "stable(a)"]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("expected on(X,Y)"), "{err}");

    let bad = scratch("bad.json");
    std::fs::write(&bad, "{\"objects\": [").unwrap();
    let (code, _, err) = lucent(&["run", "--scene", bad.to_str().unwrap()]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("bad.json"), "{err}");

    let (code, _, err) = lucent(&["run", "--preset", "nowhere"]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("unknown preset"), "{err}");

    let (code, _, err) = lucent(&["run", "--frobnicate"]);
    assert_eq!(code, 1, "{err}");
    let (code, _, err) = lucent(&["run", "--perception-noise", "2"]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("probability"), "{err}");

    // A goal no plan reaches (nothing stays on the capsicum's irregular top), and a horizon
    // budget too small for a reachable goal (red_cube_2 stands on red_cube): the run ends
    // without acting, exit 20, the budget named.
    for (goal, budget) in [
        ("on(red_cube,red_capsicum)", "4"),
        ("on(red_cube_3,red_cube)", "1"),
    ] {
        let (code, out, err) = lucent(&[
            "run",
            "--preset",
            "real",
            "--seed",
            "1",
            "--perception-noise",
            "0",
            "--actuation-noise",
            "0",
            "--goal",
            goal,
            "--max-horizon",
            budget,
        ]);
        assert_eq!(code, 20, "{goal}: {out}{err}");
        assert!(
            out.contains(&format!("no plan of at most {budget} steps")),
            "{goal}: {out}"
        );
        assert!(out.contains("GOAL NOT REACHED"), "{goal}: {out}");
    }

    let (code, out, _) = lucent(&["run", "--help"]);
    assert_eq!(code, 0);
    assert!(out.contains("--save-history"));
}
