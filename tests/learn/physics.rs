//! Issue 15: the physics world (`learn::physics`, rapier) as the learning oracle in place of
//! KB_full. On the transitions whose physical outcome is the domain's (a clear object picked up,
//! a held object put on the table or on a clear cube), the physics world and KB_full observe the
//! same support relations; a small learning run against it is deterministic per seed, finds the
//! learner's missing knowledge as a surprise, and `lucent experiment h1 --oracle physics`
//! reports it under its own name.

use std::process::Command;

use lucent::learn::episode::{LearnConfig, World};
use lucent::learn::h1::{self, Caches, Oracle};
use lucent::learn::kb::{KbSpec, KbWorld};
use lucent::learn::physics::{Catalogue, PhysicsWorld, OBSERVED};
use lucent::learn::term::{Literal, IN_HAND, RELATION};

use crate::support::learn as learn_support;

use learn_support::spec;

/// The positive literals the physics oracle observes, from any state.
fn observed(state: &[Literal]) -> Vec<Literal> {
    let names: Vec<&str> = OBSERVED.iter().map(|r| r.name()).collect();
    let mut out: Vec<Literal> = state
        .iter()
        .filter(|l| l.positive)
        .filter(|l| {
            l.name == IN_HAND
                || (l.name == RELATION
                    && matches!(l.args.first(), Some(lucent::learn::term::Term::Const(c)) if names.contains(&c.as_str())))
        })
        .cloned()
        .collect();
    out.sort();
    out.dedup();
    out
}

fn on(x: &str, y: &str) -> Literal {
    Literal::relation("on", x, y)
}

#[test]
fn physics_and_kb_full_agree_on_ordinary_transitions() {
    let mut oracle = KbWorld::new(
        KbSpec {
            options: h1::oracle_options(),
            ..spec()
        },
        &[],
    )
    .unwrap();
    let mut physics = PhysicsWorld::new(Catalogue::h1());
    let state = vec![
        on("red_cube_large", "table"),
        on("green_cube_large", "red_cube_large"),
        on("pitcher", "table"),
        on("white_can_small", "table"),
        on("yellow_duck", "white_cube_large"),
        on("white_cube_large", "table"),
    ];
    let mut held = state.clone();
    held.push(Literal::ground(IN_HAND, &["rob1", "blue_ball"]));
    let cases = [
        (
            &state,
            Literal::ground("pickup", &["rob1", "green_cube_large"]),
        ),
        (&state, Literal::ground("pickup", &["rob1", "pitcher"])),
        (
            &state,
            Literal::ground("pickup", &["rob1", "red_cube_large"]),
        ),
        (
            &held,
            Literal::ground("putdown", &["rob1", "blue_ball", "table"]),
        ),
        (
            &held,
            Literal::ground("putdown", &["rob1", "blue_ball", "green_cube_large"]),
        ),
    ];
    for (facts, action) in cases {
        let k = oracle.step(facts, &action);
        let p = physics.step(facts, &action);
        assert_eq!(
            k.after.is_some(),
            p.after.is_some(),
            "{action:?}: executable in KB_full {} vs physics {}",
            k.after.is_some(),
            p.after.is_some()
        );
        if let (Some(k), Some(p)) = (k.after, p.after) {
            assert_eq!(observed(&k), observed(&p), "{action:?}");
        }
    }
    assert_eq!(physics.unsettled, 0);
}

#[test]
fn a_small_run_against_physics_is_deterministic_and_finds_a_surprise() {
    let config = LearnConfig {
        episodes: 1,
        ..LearnConfig::default()
    };
    let seed = h1::run_seed(0, 0);
    let run =
        || h1::one_run_with(&spec(), &config, seed, Oracle::Physics, &Caches::default()).unwrap();
    let (a, b) = (run(), run());
    assert_eq!(a.trials, b.trials);
    assert_eq!(a.store.to_ald(), b.store.to_ald());
    let first = &a.episodes[0];
    assert!(
        first.detected_at.is_some(),
        "the learner profile lacks five axioms the world obeys: {first:?}"
    );
    assert!(!a.store.current().is_empty(), "{first:?}");
}

#[test]
fn experiment_h1_reports_the_physics_oracle_by_name() {
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args([
            "experiment",
            "h1",
            "--oracle",
            "physics",
            "--runs",
            "1",
            "--episodes",
            "1",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("lucent runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("learning runs against the physics world"),
        "{text}"
    );
    assert!(text.contains("| strict |"), "{text}");
}
