//! Perception: exact perception equals the measured truth; noisy perception is deterministic
//! and produces the configured error rates.

use lucent::sim::{
    generate, measure, perceive, ErrorModel, FactStyle, GenerateConfig, Literal, Preset, Relation,
    Scene, TruthConfig,
};
use std::collections::BTreeSet;

fn scene() -> Scene {
    let mut config = GenerateConfig::new(Preset::Simulated, 11);
    config.count = Some(9);
    generate(&config).unwrap()
}

fn observed_relations(scene: &Scene, model: &ErrorModel) -> BTreeSet<Relation> {
    perceive(scene, model, &TruthConfig::default())
        .facts()
        .filter_map(|o| match &o.literal {
            Literal::Relation(r) => Some(r.clone()),
            _ => None,
        })
        .collect()
}

#[test]
fn exact_perception_is_the_measured_truth() {
    let scene = scene();
    let truth: BTreeSet<Relation> = measure(&scene, &TruthConfig::default())
        .relations
        .into_iter()
        .collect();
    assert_eq!(observed_relations(&scene, &ErrorModel::exact()), truth);
    let percept = perceive(&scene, &ErrorModel::exact(), &TruthConfig::default());
    for object in &scene.objects {
        assert!(percept
            .facts()
            .any(|o| o.literal == Literal::HasSize(object.name.clone(), object.size)));
        assert!(percept
            .facts()
            .any(|o| o.literal == Literal::HasSurface(object.name.clone(), object.surface())));
        assert!(percept
            .facts()
            .any(|o| o.literal == Literal::InHand("rob1".into(), object.name.clone()) && !o.value));
    }
}

#[test]
fn same_seed_and_step_same_observations() {
    let scene = scene();
    let model = ErrorModel::default();
    let a = perceive(&scene, &model, &TruthConfig::default());
    let b = perceive(&scene, &model, &TruthConfig::default());
    assert_eq!(a, b);
    let mut later = scene.clone();
    later.step = 1;
    let c = perceive(&later, &model, &TruthConfig::default());
    assert_ne!(
        a.observations, c.observations,
        "each step draws fresh noise"
    );
}

/// Over many independent percepts (one noise stream per step), the fraction of true relation
/// literals missing from the output estimates `relation_error`, and the fraction of output
/// literals that are false estimates `relation_error * substitute_share` relative to the truth.
/// Each literal is an independent Bernoulli trial, so an estimate from N trials has standard
/// deviation sqrt(p (1 - p) / N); we accept 4 standard deviations, which a correct model fails
/// with probability below 1e-4 (and the fixed seeds make the outcome reproducible anyway).
#[test]
fn relation_error_rate_matches_the_model() {
    let scene = scene();
    let truth: BTreeSet<Relation> = measure(&scene, &TruthConfig::default())
        .relations
        .into_iter()
        .collect();
    let model = ErrorModel {
        relation_error: 0.15,
        substitute_share: 0.5,
        threshold: 0.0,
        ..ErrorModel::default()
    };
    let (mut trials, mut missing, mut wrong) = (0usize, 0usize, 0usize);
    let mut counted_errors = 0usize;
    for step in 0..150 {
        let mut s = scene.clone();
        s.step = step;
        let observed = observed_relations(&s, &model);
        trials += truth.len();
        missing += truth.difference(&observed).count();
        wrong += observed.difference(&truth).count();
        let percept = perceive(&s, &model, &TruthConfig::default());
        counted_errors += percept.errors.dropped + percept.errors.substituted;
    }
    let n = trials as f64;
    let check = |name: &str, k: usize, p: f64| {
        let rate = k as f64 / n;
        let sigma = (p * (1.0 - p) / n).sqrt();
        assert!(
            (rate - p).abs() < 4.0 * sigma,
            "{name}: {rate:.4} vs {p} (sigma {sigma:.4}, n {n})"
        );
    };
    check("missing", missing, 0.15);
    check("counted", counted_errors, 0.15);
    // Two wrong readings may coincide, so the number of distinct false literals is at most the
    // number of substitutions; coincidences are rare, within the tolerance.
    check("wrong", wrong, 0.075);
}

#[test]
fn size_error_rate_matches_the_model() {
    let scene = scene();
    let model = ErrorModel {
        size_error: 0.1,
        ..ErrorModel::exact()
    };
    let (mut trials, mut wrong) = (0usize, 0usize);
    for step in 0..200 {
        let mut s = scene.clone();
        s.step = step;
        for o in perceive(&s, &model, &TruthConfig::default()).observations {
            if let Literal::HasSize(name, size) = &o.literal {
                trials += 1;
                let id = s.find(name).unwrap();
                wrong += usize::from(s.object(id).size != *size);
            }
        }
    }
    let (n, p) = (trials as f64, 0.1);
    let rate = wrong as f64 / n;
    let sigma = (p * (1.0 - p) / n).sqrt();
    assert!(
        (rate - p).abs() < 4.0 * sigma,
        "{rate} vs {p} ± 4 × {sigma}"
    );
}

#[test]
fn threshold_selects_facts() {
    let scene = scene();
    let all = ErrorModel {
        threshold: 0.0,
        ..ErrorModel::default()
    };
    let strict = ErrorModel {
        threshold: 0.99,
        ..ErrorModel::default()
    };
    let p_all = perceive(&scene, &all, &TruthConfig::default());
    let p_strict = perceive(&scene, &strict, &TruthConfig::default());
    assert_eq!(p_all.facts().count(), p_all.observations.len());
    assert!(p_strict.facts().count() < p_all.facts().count());
    assert!(p_strict.facts().all(|o| o.confidence >= 0.99));
    // Wrong readings are drawn below 0.9, so a threshold of 0.9 keeps only correct ones.
    let sure = ErrorModel {
        threshold: 0.9,
        ..ErrorModel::default()
    };
    assert!(perceive(&scene, &sure, &TruthConfig::default())
        .facts()
        .all(|o| !o.erroneous));
}

#[test]
fn observations_print_as_program_facts() {
    let scene = scene();
    let percept = perceive(&scene, &ErrorModel::exact(), &TruthConfig::default());
    let obs = percept.to_program(FactStyle::Obs);
    let on = measure(&scene, &TruthConfig::default())
        .relations
        .into_iter()
        .find(|r| r.rel == lucent::sim::Rel::On)
        .unwrap();
    assert!(
        obs.contains(&format!("obs(relation(on,{},{}),true,0).", on.a, on.b)),
        "{obs}"
    );
    assert!(obs.contains("has_surface(table,flat)."));
    assert!(obs
        .lines()
        .any(|l| l.starts_with("obs(in_hand(rob1,") && l.ends_with(",false,0).")));
    let holds = percept.to_program(FactStyle::Holds);
    assert!(holds.contains(&format!("holds(relation(on,{},{}),0).", on.a, on.b)));
    assert!(holds.lines().any(|l| l.starts_with("-holds(in_hand(rob1,")));
    for line in obs.lines().filter(|l| !l.starts_with('%')) {
        assert!(line.ends_with(").") && !line.contains(' '), "{line}");
    }
}
