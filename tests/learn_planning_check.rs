//! Issue 15 (c), one action deep: after a learning run (seed 0, run 0, as `lucent learn`), the
//! learner's knowledge base with the learned axioms, written as the AL_d file and read back
//! (`Store::to_ald`, `Store::from_ald`), predicts every generated (state, action) pair as KB_full
//! does, where the bare `learner` profile predicts some of them wrongly.
//!
//! A one-action plan is incorrect when its prediction differs from the KB_full transition:
//! the learner takes the action to be executable and KB_full does not, or the reverse, or the
//! successor states differ in the observable vocabulary (the discrepancy of DOMAIN.md 5.1, which
//! is what `learn::surprise::classify` reports). The planner's `plan::check` over the planning
//! issue's (scene, goal) pairs is the multi-step version of this check.

use lucent::action;
use lucent::base::rng::SplitMix64;
use lucent::base::SourceMap;
use lucent::learn::episode::{LearnConfig, World};
use lucent::learn::h1;
use lucent::learn::kb::{KbSpec, KbWorld};
use lucent::learn::state::{generate, ActionType, Pools};
use lucent::learn::strength::Store;
use lucent::learn::surprise::classify;
use lucent::learn::term::Axiom;

fn spec() -> KbSpec {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/domains/ra/scenes/h1.ald");
    let mut sources = SourceMap::new();
    let file = sources.add(path.to_string(), std::fs::read_to_string(path).unwrap());
    let mut read = |p: &std::path::Path| std::fs::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    assert!(!parsed.has_errors(), "{:?}", parsed.diagnostics);
    KbSpec {
        description: parsed.description,
        options: h1::learner_options(),
        sources,
    }
}

#[test]
fn learned_axioms_remove_every_incorrect_one_action_plan() {
    let s = spec();
    let report = h1::one_run(&s, &LearnConfig::default(), h1::run_seed(0, 0)).unwrap();
    let store = Store::from_ald(&report.store.to_ald()).unwrap();
    assert_eq!(store.current(), report.store.current());
    let learned: Vec<(String, Axiom)> = store
        .axioms
        .iter()
        .map(|l| (l.label.clone(), l.axiom.clone()))
        .collect();
    assert!(!learned.is_empty());
    let mut oracle = KbWorld::new(
        KbSpec {
            options: h1::oracle_options(),
            ..s.clone()
        },
        &[],
    )
    .unwrap();
    let mut bare = KbWorld::new(s.clone(), &[]).unwrap();
    let mut taught = KbWorld::new(s, &learned).unwrap();
    let pools = Pools::h1();
    let mut rng = SplitMix64::new(15);
    let (mut wrong_bare, mut wrong_taught, mut forbidden) = (0, 0, 0);
    let pairs = 200;
    for _ in 0..pairs {
        let ty = if rng.chance(0.5) {
            ActionType::Pickup
        } else {
            ActionType::Putdown
        };
        let st = generate(&pools, ty, &mut rng);
        let facts = st.facts(&pools.robot);
        let o = oracle.step(&facts, &st.action);
        if o.after.is_none() {
            forbidden += 1;
        }
        let b = bare.step(&facts, &st.action);
        if classify(&b.before, b.after.as_deref(), o.after.as_deref()).surprising() {
            wrong_bare += 1;
        }
        let t = taught.step(&facts, &st.action);
        let out = classify(&t.before, t.after.as_deref(), o.after.as_deref());
        if out.surprising() {
            wrong_taught += 1;
            eprintln!("still wrong: {} {:?}", st.action, out);
        }
    }
    eprintln!(
        "{pairs} pairs ({forbidden} not executable in KB_full): incorrect one-action plans \
         {wrong_bare} without the learned axioms, {wrong_taught} with them ({})",
        store
            .axioms
            .iter()
            .map(|l| format!("{}: {}", l.label, l.axiom))
            .collect::<Vec<_>>()
            .join("; ")
    );
    assert!(wrong_bare > 0);
    assert_eq!(wrong_taught, 0);
}
