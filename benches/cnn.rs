//! Benchmarks of the scene-understanding CNN at its published size (56 x 56 x 3 input, 1,024
//! dense units): one forward pass of one image, and one training step of a batch of 10 (the
//! convolutions in parallel over the examples, the dense products in fixed row pieces).

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use lucent::base::rng::SplitMix64;
use lucent::vision::cnn::{Cnn, CnnConfig};

fn random_images(config: &CnnConfig, n: usize, seed: u64) -> Vec<Vec<f32>> {
    let mut rng = SplitMix64::new(seed);
    let len = config.height * config.width * config.channels;
    (0..n)
        .map(|_| (0..len).map(|_| rng.range_f32(0.0, 1.0)).collect())
        .collect()
}

fn benches(c: &mut Criterion) {
    let config = CnnConfig {
        steps: 1,
        ..CnnConfig::default()
    };
    let images = random_images(&config, 10, 1);
    let inputs: Vec<&[f32]> = images.iter().map(|x| x.as_slice()).collect();
    let labels: Vec<Vec<bool>> = (0..10).map(|i| vec![i % 2 == 0]).collect();
    let cnn = Cnn::new(config.clone());
    c.bench_function("cnn_forward_56x56x3", |b| {
        b.iter(|| black_box(cnn.forward(black_box(inputs[0]))))
    });
    let mut group = c.benchmark_group("cnn_train");
    group.sample_size(20);
    let mut trained = Cnn::new(config);
    group.bench_function("one_step_batch_10", |b| {
        b.iter(|| black_box(trained.train(&inputs, &labels)))
    });
    group.finish();
}

criterion_group!(cnn, benches);
criterion_main!(cnn);
