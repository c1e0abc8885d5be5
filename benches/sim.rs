//! Benchmarks of the tabletop world: generating and settling a 9-object scene, executing one
//! action (with settling and perception), perceiving, rendering, and generating scenes in
//! parallel with rayon over all cores against one after another.

use criterion::{black_box, criterion_group, criterion_main, BatchSize, Criterion};
use lucent::sim::{
    execute, generate, generate_many, perceive, render_camera, ActConfig, Action, ErrorModel,
    GenerateConfig, Preset, Scene, TruthConfig,
};

fn nine(seed: u64) -> GenerateConfig {
    let mut config = GenerateConfig::new(Preset::Simulated, seed);
    config.count = Some(9);
    config
}

/// A loose object of the scene (nothing on it, on the table), for a pickup that can succeed.
fn loose(scene: &Scene) -> String {
    let truth = lucent::sim::measure(scene, &TruthConfig::default());
    scene
        .objects
        .iter()
        .map(|o| o.name.clone())
        .find(|n| {
            !truth
                .relations
                .iter()
                .any(|r| r.rel == lucent::sim::Rel::On && &r.b == n)
        })
        .expect("some object has nothing on it")
}

fn benches(c: &mut Criterion) {
    c.bench_function("generate_and_settle_9_objects", |b| {
        let mut seed = 0;
        b.iter(|| {
            seed += 1;
            black_box(generate(&nine(seed)).unwrap())
        })
    });
    let scene = generate(&nine(1)).unwrap();
    let object = loose(&scene);
    let pickup = Action::parse(&format!("pickup(rob1,{object})")).unwrap();
    let config = ActConfig {
        failure_rate: 0.0,
        ..ActConfig::default()
    };
    c.bench_function("execute_pickup_settle_observe", |b| {
        b.iter_batched(
            || scene.clone(),
            |mut s| black_box(execute(&mut s, &pickup, &config).unwrap()),
            BatchSize::SmallInput,
        )
    });
    let mut holding = scene.clone();
    execute(&mut holding, &pickup, &config).unwrap();
    let putdown = Action::parse(&format!("putdown(rob1,{object},table)")).unwrap();
    c.bench_function("execute_putdown_settle_observe", |b| {
        b.iter_batched(
            || holding.clone(),
            |mut s| black_box(execute(&mut s, &putdown, &config).unwrap()),
            BatchSize::SmallInput,
        )
    });
    c.bench_function("perceive_9_objects", |b| {
        b.iter(|| {
            black_box(perceive(
                &scene,
                &ErrorModel::default(),
                &TruthConfig::default(),
            ))
        })
    });
    c.bench_function("render_camera_320x200", |b| {
        b.iter(|| black_box(render_camera(&scene, 320, 200)))
    });
    let mut group = c.benchmark_group("generate_16_scenes");
    group.sample_size(10);
    group.bench_function("sequential", |b| {
        b.iter(|| {
            (0..16u64)
                .map(|s| generate(&nine(s)).unwrap())
                .collect::<Vec<_>>()
        })
    });
    group.bench_function("rayon_all_cores", |b| {
        let configs: Vec<GenerateConfig> = (0..16u64).map(nine).collect();
        b.iter(|| generate_many(&configs))
    });
    group.finish();
}

criterion_group!(sim, benches);
criterion_main!(sim);
