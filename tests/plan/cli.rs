//! `lucent plan` on the command line: the tabletop task as text and as JSON, `--all`, and the
//! error paths (horizon budget too small, malformed file, missing file) with their exit codes.

use crate::support::plan as plan_support;

use plan_support::{lucent as run, DOMAIN, SCENE, TABLETOP};

#[test]
fn plan_prints_json_with_all_minimal_plans() {
    let (code, out, err) = run(&["plan", TABLETOP, "--all", "--outf=2", "--max-horizon", "4"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["length"], 3);
    assert_eq!(v["cr_applied"], 0);
    let plans = v["plans"].as_array().unwrap();
    assert_eq!(plans.len(), 4);
    for p in plans {
        let p = p.as_array().unwrap();
        assert_eq!(p[0], "pickup(rob1,pitcher)");
        assert_eq!(p[2], "pickup(rob1,red_cube_large)");
    }
}

#[test]
fn plan_prints_one_plan_as_text() {
    let (code, out, err) = run(&["plan", TABLETOP]);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.matches("Plan: ").count(), 1, "{out}");
    assert!(out.contains("Length: 3"), "{out}");
}

#[test]
fn plan_reports_no_plan_within_the_budget() {
    let (code, out, err) = run(&["plan", TABLETOP, "--max-horizon=2"]);
    assert_eq!(code, 20);
    assert!(out.is_empty());
    assert!(err.contains("no_plan_within(2)"), "{err}");
}

#[test]
fn plan_rejects_bad_files() {
    let dir = std::env::temp_dir().join(format!("lucent_plan_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.ald");
    std::fs::write(&bad, "sort s = {a}.\ngoal f(a.\n").unwrap();
    let (code, _, err) = run(&["plan", bad.to_str().unwrap()]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("bad.ald:"), "{err}");
    let (code, _, err) = run(&["plan", "no/such/file.ald"]);
    assert_eq!(code, 65, "{err}");
    assert!(err.contains("no/such/file.ald"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `lucent plan` on KB_full with a scene of facts (`--scene SCENE`) and `args` after it.
fn plan_scene(scene: &str, args: &[&str]) -> (i32, String, String) {
    let mut all = vec!["plan", DOMAIN, "--scene", scene];
    all.extend_from_slice(args);
    run(&all)
}

#[test]
fn plan_takes_a_scene_of_facts_and_a_goal_as_literals_or_english() {
    let (code, out, err) = plan_scene(SCENE, &["--goal", "on(mug, white_block)", "--outf=2"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["length"], 2);
    assert_eq!(
        v["plans"][0],
        serde_json::json!(["pickup(rob1,mug)", "putdown(rob1,mug,white_block)"])
    );
    assert!(v["time"]["total"].as_f64().is_some());
    // The same goal in controlled English, with the plan checked.
    let (code, out, err) = plan_scene(
        SCENE,
        &["--goal", "put the mug on the white block", "--check"],
    );
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("Plan: pickup(rob1,mug)@0; putdown(rob1,mug,white_block)@1"),
        "{out}"
    );
    assert!(out.contains("Check: optimal"), "{out}");
    // Holding the red block needs the white block moved first: length 3.
    let (code, out, err) = plan_scene(SCENE, &["--goal", "pick up the red block", "--all"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Length: 3"), "{out}");
}

#[test]
fn plan_rejects_bad_scenes_and_goals_with_clear_messages() {
    // (the case, the scene, the arguments after it, the exit code, what the error names)
    let cases: &[(&str, &str, &[&str], i32, &str)] = &[
        (
            "an unknown object in the goal",
            SCENE,
            &["--goal", "on(ghost, mug)"],
            65,
            "`ghost` is not in sort",
        ),
        (
            "an unknown object in an English goal",
            SCENE,
            &["--goal", "put the ghost on the mug"],
            65,
            "ghost",
        ),
        (
            "a malformed scene file: a positioned syntax error",
            "tests/data/plan/malformed.lp",
            &[],
            65,
            "malformed.lp:3:1",
        ),
        (
            "an impossible goal (nothing stays on the mug's irregular top): no plan within H",
            SCENE,
            &["--goal", "on(red_block, mug)", "--max-horizon=4"],
            20,
            "no_plan_within(4)",
        ),
        (
            "the same without a budget: the default H = max(9, 2 * 3 + 2), no hang",
            SCENE,
            &["--goal", "on(red_block, mug)"],
            20,
            "no_plan_within(9)",
        ),
        (
            "an initially unstable scene",
            "tests/data/plan/unstable.lp",
            &["--goal", "in_hand(rob1, red_block)"],
            20,
            "initially_unstable(red_block)",
        ),
        (
            "a missing scene file",
            "no/such/scene.lp",
            &[],
            65,
            "no/such/scene.lp",
        ),
    ];
    for (case, scene, args, want, names) in cases {
        let (code, _, err) = plan_scene(scene, args);
        assert_eq!(code, *want, "{case}: {err}");
        assert!(err.contains(names), "{case}: {err}");
    }
}
