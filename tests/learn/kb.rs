//! `learn::kb` over the RA domain's AL_d files (domains/ra): the oracle (KB_full with the
//! learner's switches) and the learner (`learner` profile) disagree exactly where the five H1
//! targets are missing, surprises are classified as docs/domain.md 5.1 says, and a learned axiom
//! added to the learner changes its predictions at once.

use lucent::learn::episode::{LearnerKb, World};
use lucent::learn::h1;
use lucent::learn::kb::{KbSpec, KbWorld};
use lucent::learn::surprise::classify;
use lucent::learn::term::{Literal, IN_HAND};

use crate::support::learn as learn_support;

use learn_support::spec;

fn worlds() -> (KbWorld, KbWorld) {
    let s = spec();
    let oracle = KbWorld::new(
        KbSpec {
            options: h1::oracle_options(),
            ..s.clone()
        },
        &[],
    )
    .unwrap();
    (oracle, KbWorld::new(s, &[]).unwrap())
}

fn on(a: &str, b: &str) -> Literal {
    Literal::relation("on", a, b)
}

fn held(o: &str) -> Literal {
    Literal::ground(IN_HAND, &["rob1", o])
}

#[test]
fn surprises_where_the_targets_are_missing() {
    let (mut oracle, mut learner) = worlds();
    let facts = vec![
        on("red_cube_large", "table"),
        on("blue_ball", "red_cube_large"),
    ];
    // E7: picking up a covered object. The oracle forbids it, the learner predicts a state.
    let covered = Literal::ground("pickup", &["rob1", "red_cube_large"]);
    let o = oracle.step(&facts, &covered);
    let l = learner.step(&facts, &covered);
    assert!(o.after.is_none());
    let out = classify(&l.before, l.after.as_deref(), o.after.as_deref());
    assert!(out.unexpected.is_empty() && !out.extra.is_empty());
    // C3: picking up the free ball: in_hand is observed but not predicted.
    let free = Literal::ground("pickup", &["rob1", "blue_ball"]);
    let o = oracle.step(&facts, &free);
    let l = learner.step(&facts, &free);
    let out = classify(&l.before, l.after.as_deref(), o.after.as_deref());
    assert_eq!(out.unexpected, vec![held("blue_ball")]);
    // C2: putting down the held pitcher: in_hand persists by inertia in the learner only.
    let mut facts2 = facts.clone();
    facts2.push(held("pitcher"));
    let put = Literal::ground("putdown", &["rob1", "pitcher", "table"]);
    let o = oracle.step(&facts2, &put);
    let l = learner.step(&facts2, &put);
    let out = classify(&l.before, l.after.as_deref(), o.after.as_deref());
    assert_eq!(out.unexpected, vec![held("pitcher").complement()]);
    assert!(out.extra.is_empty());
    // Both agree where the learner keeps its axioms: E1 (an occupied support).
    let occupied = Literal::ground("putdown", &["rob1", "pitcher", "red_cube_large"]);
    assert!(oracle.step(&facts2, &occupied).after.is_none());
    assert!(learner.step(&facts2, &occupied).after.is_none());
    // The relevant step-0 literals mention the action's constants.
    let rel = lucent::learn::lift::relevant(&l.before, &put);
    assert!(rel.contains(&held("pitcher")));
    assert!(rel
        .iter()
        .all(|x| x.args.iter().any(|t| put.args.contains(t))));
}

#[test]
fn learned_axioms_change_the_learner_at_once() {
    let (_, mut learner) = worlds();
    let e7 = h1::targets()[0].clone();
    let c3 = h1::targets()[3].clone();
    learner.set_learned(&[("L1".into(), e7), ("L2".into(), c3)]);
    let facts = vec![
        on("red_cube_large", "table"),
        on("blue_ball", "red_cube_large"),
    ];
    let covered = Literal::ground("pickup", &["rob1", "red_cube_large"]);
    assert!(learner.step(&facts, &covered).after.is_none());
    let free = Literal::ground("pickup", &["rob1", "blue_ball"]);
    let after = learner.step(&facts, &free).after.unwrap();
    assert!(after.contains(&held("blue_ball")));
}
