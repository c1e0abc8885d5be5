//! A small LeNet-style convolutional network, trained and run on the CPU: the classifier of the
//! scene-understanding pipeline for what reasoning cannot decide.
//!
//! Architecture (the LeNet of the authors' pipeline): an `H x W x C` image with values in
//! `[0, 1]`, stored HWC row-major (index `(y * W + x) * C + c`); a `k x k` convolution with
//! `filters1` filters, "same" zero padding, bias, ReLU; 2x2 max pooling of stride 2 (an odd last
//! row or column is dropped); a second `k x k` convolution with `filters2` filters, same padding,
//! bias, ReLU; 2x2 max pooling; a dense layer of `dense` ReLU units with inverted dropout during
//! training; a dense output layer with one sigmoid per label. Loss: sigmoid cross-entropy from the
//! logits in the stable form `max(z, 0) - z y + ln(1 + exp(-|z|))`, summed over the labels and
//! averaged over the batch. Optimizer: Adam. [`CnnConfig::default`] gives the published sizes
//! (56 x 56 x 3, 5x5 kernels, 6 and 16 filters, 1,024 dense units, dropout 0.4, learning rate
//! 0.0002, batches of 10, 1,000 steps).
//!
//! Decision: the layers are written here by hand over `matrixmultiply` 0.3's `sgemm` (a small,
//! dependency-free crate by the ndarray authors, already in the tree) rather than candle or burn:
//! no run-time download, no GPU, seconds of build instead of minutes, and bit-for-bit determinism
//! because every summation order is fixed here. Inside, activations are CHW planes. The forward
//! convolutions are im2col plus one sgemm, the dense layers of a batch are sgemms. sgemm packs
//! its operands into panels, which is a copy of runs when the panel runs along memory and an
//! element-by-element gather when it runs across (it cost more than the product itself): the
//! products that read a matrix across its rows (the weight gradients of the convolutions, the
//! input gradient of the hidden layer) are dot products of contiguous rows instead
//! (`layers::gemm_nt`), and one image's dense layers are a vector-matrix loop that reads each
//! weight once instead of packing the 12.8 MB hidden layer.
//!
//! Invariants: every random draw (initialization, batches, dropout masks) comes from
//! [`SplitMix64`] streams forked from the config's seed, drawn on the calling thread. Parallel
//! work is split into pieces fixed by the sizes (one example, or a fixed number of matrix rows),
//! never by the thread count, and the pieces are summed in a fixed order; so a seed gives the same
//! weights bit for bit, whatever the number of rayon threads. Across machines, matrixmultiply
//! picks its kernel (FMA or not) by CPU feature, which may change the last bits.
//!
//! Files: this one the config, the network's API, the training loop and Adam; `layers.rs` the
//! forward and backward passes.

use std::fmt;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::base::rng::SplitMix64;

mod layers;

use layers::{cross_entropy, sigmoid, vec_mat};

/// The sizes and training settings of a network.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CnnConfig {
    /// Input height in pixels.
    pub height: usize,
    /// Input width in pixels.
    pub width: usize,
    /// Input channels (3 for RGB).
    pub channels: usize,
    /// Side of both convolutions' square kernels; odd, so that "same" padding is symmetric.
    pub kernel: usize,
    /// Filters of the first convolution.
    pub filters1: usize,
    /// Filters of the second convolution.
    pub filters2: usize,
    /// Units of the hidden dense layer.
    pub dense: usize,
    /// Sigmoid outputs, one per label.
    pub outputs: usize,
    /// Probability of dropping a hidden dense unit during training, in `[0, 1)`.
    pub dropout: f32,
    /// Adam's learning rate.
    pub learning_rate: f32,
    /// Adam's first-moment decay.
    pub adam_beta1: f32,
    /// Adam's second-moment decay.
    pub adam_beta2: f32,
    /// Adam's denominator offset.
    pub adam_epsilon: f32,
    /// Examples per training step.
    pub batch: usize,
    /// Training steps of one [`Cnn::train`] call.
    pub steps: usize,
    /// Seed of the initialization, the batches and the dropout masks.
    pub seed: u64,
}

impl Default for CnnConfig {
    /// The published network: 56 x 56 x 3 input, 5x5 kernels, 6 and 16 filters, 1,024 dense
    /// units with dropout 0.4, one output; Adam (0.9, 0.999, 1e-8) at 0.0002, 1,000 steps of 10.
    fn default() -> Self {
        CnnConfig {
            height: 56,
            width: 56,
            channels: 3,
            kernel: 5,
            filters1: 6,
            filters2: 16,
            dense: 1024,
            outputs: 1,
            dropout: 0.4,
            learning_rate: 0.0002,
            adam_beta1: 0.9,
            adam_beta2: 0.999,
            adam_epsilon: 1e-8,
            batch: 10,
            steps: 1000,
            seed: 0,
        }
    }
}

/// What a [`Cnn::train`] call did.
#[derive(Clone, Debug, PartialEq)]
pub struct TrainReport {
    /// Steps taken.
    pub steps: usize,
    /// Mean of the last `min(steps, 20)` batch losses (NaN after zero steps).
    pub final_loss: f32,
    /// The mean batch loss of every step (with dropout), in order.
    pub losses: Vec<f32>,
}

/// The parameter groups of a network, for setting weights by hand. Layouts are row-major:
/// convolution weights `[ky][kx][input channel][filter]` (the im2col row order), dense weights
/// `[input][unit]`; the hidden layer's inputs are the second pooling's output channel by channel
/// (CHW: index `(filter * (height / 4) + y) * (width / 4) + x`).
#[derive(Debug)]
pub struct Parameters<'a> {
    /// First convolution, `kernel * kernel * channels * filters1`.
    pub conv1_weights: &'a mut [f32],
    /// First convolution's biases, `filters1`.
    pub conv1_bias: &'a mut [f32],
    /// Second convolution, `kernel * kernel * filters1 * filters2`.
    pub conv2_weights: &'a mut [f32],
    /// Second convolution's biases, `filters2`.
    pub conv2_bias: &'a mut [f32],
    /// Hidden dense layer, `features * dense` (features: the second pooling's output).
    pub dense_weights: &'a mut [f32],
    /// Hidden dense layer's biases, `dense`.
    pub dense_bias: &'a mut [f32],
    /// Output layer, `dense * outputs`.
    pub output_weights: &'a mut [f32],
    /// Output layer's biases, `outputs`.
    pub output_bias: &'a mut [f32],
}

// Parameter groups, in the order of the flat parameter vector (convolutions first, so that an
// example's convolution gradient is one prefix of it).
const CONV1_W: usize = 0;
const CONV1_B: usize = 1;
const CONV2_W: usize = 2;
const CONV2_B: usize = 3;
const DENSE_W: usize = 4;
const DENSE_B: usize = 5;
const OUT_W: usize = 6;
const OUT_B: usize = 7;
const GROUPS: usize = 8;

/// Matrix rows per parallel piece of the dense layers' products (fixed: determinism).
const ROWS_PER_PIECE: usize = 128;
/// Parameters per parallel piece of the Adam update.
const ADAM_PIECE: usize = 1 << 15;

/// Sizes derived from a config, checked once.
#[derive(Clone, Debug)]
struct Shape {
    height: usize,
    width: usize,
    channels: usize,
    kernel: usize,
    filters1: usize,
    filters2: usize,
    /// Height and width after the first pooling.
    h1: usize,
    w1: usize,
    /// Flattened length of the second pooling's output.
    features: usize,
    dense: usize,
    outputs: usize,
    /// Start of every parameter group in the flat vector, and its length at the end.
    offsets: [usize; GROUPS + 1],
}

impl Shape {
    fn of(c: &CnnConfig) -> Shape {
        assert!(
            c.height > 0 && c.width > 0 && c.channels > 0,
            "CnnConfig: the input needs a positive height, width and channel count"
        );
        assert!(
            c.filters1 > 0 && c.filters2 > 0 && c.dense > 0 && c.outputs > 0,
            "CnnConfig: filter, dense-unit and output counts must be positive"
        );
        assert!(
            c.kernel % 2 == 1,
            "CnnConfig: the kernel side must be odd for same padding, got {}",
            c.kernel
        );
        assert!(
            c.height >= 4 && c.width >= 4,
            "CnnConfig: two 2x2 poolings need an input of at least 4x4, got {}x{}",
            c.height,
            c.width
        );
        assert!(
            (0.0..1.0).contains(&c.dropout),
            "CnnConfig: dropout must lie in [0, 1), got {}",
            c.dropout
        );
        assert!(c.batch > 0, "CnnConfig: the batch size must be positive");
        assert!(
            (0.0..1.0).contains(&c.adam_beta1) && (0.0..1.0).contains(&c.adam_beta2),
            "CnnConfig: Adam's betas must lie in [0, 1), got {} and {}",
            c.adam_beta1,
            c.adam_beta2
        );
        let (h1, w1) = (c.height / 2, c.width / 2);
        let features = (h1 / 2) * (w1 / 2) * c.filters2;
        let k2 = c.kernel * c.kernel;
        let sizes = [
            k2 * c.channels * c.filters1,
            c.filters1,
            k2 * c.filters1 * c.filters2,
            c.filters2,
            features * c.dense,
            c.dense,
            c.dense * c.outputs,
            c.outputs,
        ];
        let mut offsets = [0; GROUPS + 1];
        for (g, size) in sizes.iter().enumerate() {
            offsets[g + 1] = offsets[g] + size;
        }
        Shape {
            height: c.height,
            width: c.width,
            channels: c.channels,
            kernel: c.kernel,
            filters1: c.filters1,
            filters2: c.filters2,
            h1,
            w1,
            features,
            dense: c.dense,
            outputs: c.outputs,
            offsets,
        }
    }

    fn input_len(&self) -> usize {
        self.height * self.width * self.channels
    }
}

/// A network: its config, weights and Adam state (the default network has 3.2 million
/// parameters, 12.8 MB, and twice that in Adam's moments).
#[derive(Clone)]
pub struct Cnn {
    config: CnnConfig,
    shape: Shape,
    /// All parameters, group after group (see [`Parameters`] for the layouts).
    params: Vec<f32>,
    /// Adam's first and second moments, parallel to `params`.
    moment1: Vec<f32>,
    moment2: Vec<f32>,
    /// Adam steps taken so far (for the bias correction).
    adam_steps: u64,
    /// The stream of batches and dropout masks; continues across `train` calls.
    rng: SplitMix64,
}

impl fmt::Debug for Cnn {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Cnn")
            .field("config", &self.config)
            .field("parameters", &self.params.len())
            .field("adam_steps", &self.adam_steps)
            .finish()
    }
}

impl Cnn {
    /// A network with fresh weights: He-uniform (limit `sqrt(6 / fan_in)`) for the ReLU layers,
    /// Glorot-uniform (limit `sqrt(6 / (fan_in + fan_out))`) for the sigmoid outputs, biases 0.
    /// Panics with a sentence on an unusable config (even kernel, input under 4x4, zero sizes,
    /// dropout or an Adam beta outside `[0, 1)`, zero batch).
    pub fn new(config: CnnConfig) -> Cnn {
        let shape = Shape::of(&config);
        let root = SplitMix64::new(config.seed);
        let mut init = root.fork(1);
        let mut params = vec![0.0f32; shape.offsets[GROUPS]];
        let s = &shape;
        let k2 = s.kernel * s.kernel;
        let layers = [
            (CONV1_W, k2 * s.channels, s.filters1, true),
            (CONV2_W, k2 * s.filters1, s.filters2, true),
            (DENSE_W, s.features, s.dense, true),
            (OUT_W, s.dense, s.outputs, false),
        ];
        for (group, fan_in, fan_out, relu) in layers {
            let limit = if relu {
                (6.0 / fan_in as f64).sqrt()
            } else {
                (6.0 / (fan_in + fan_out) as f64).sqrt()
            } as f32;
            for p in &mut params[s.offsets[group]..s.offsets[group + 1]] {
                *p = init.range_f32(-limit, limit);
            }
        }
        let n = params.len();
        Cnn {
            rng: root.fork(2),
            config,
            shape,
            params,
            moment1: vec![0.0; n],
            moment2: vec![0.0; n],
            adam_steps: 0,
        }
    }

    /// The config the network was built with.
    pub fn config(&self) -> &CnnConfig {
        &self.config
    }

    /// Values of one input image: `height * width * channels`.
    pub fn input_len(&self) -> usize {
        self.shape.input_len()
    }

    /// All parameters as one vector, group after group in [`Parameters`]' field order.
    pub fn parameters(&self) -> &[f32] {
        &self.params
    }

    /// The parameter groups, writable (for tests and hand-set networks).
    pub fn parameters_mut(&mut self) -> Parameters<'_> {
        let o = self.shape.offsets;
        let mut rest = self.params.as_mut_slice();
        let mut take = |g: usize| {
            let (head, tail) = std::mem::take(&mut rest).split_at_mut(o[g + 1] - o[g]);
            rest = tail;
            head
        };
        Parameters {
            conv1_weights: take(CONV1_W),
            conv1_bias: take(CONV1_B),
            conv2_weights: take(CONV2_W),
            conv2_bias: take(CONV2_B),
            dense_weights: take(DENSE_W),
            dense_bias: take(DENSE_B),
            output_weights: take(OUT_W),
            output_bias: take(OUT_B),
        }
    }

    fn group(&self, g: usize) -> &[f32] {
        &self.params[self.shape.offsets[g]..self.shape.offsets[g + 1]]
    }

    /// Why `input` is not an input of this network (its length is wrong), or `None`.
    pub fn input_error(&self, input: &[f32]) -> Option<String> {
        let s = &self.shape;
        (input.len() != s.input_len()).then(|| {
            format!(
                "the input has {} values, the network takes {}x{}x{} = {}",
                input.len(),
                s.height,
                s.width,
                s.channels,
                s.input_len()
            )
        })
    }

    fn check_input(&self, input: &[f32], caller: &str) {
        if let Some(e) = self.input_error(input) {
            panic!("Cnn::{caller}: {e}");
        }
    }

    fn check_examples(&self, inputs: &[&[f32]], labels: &[Vec<bool>], caller: &str) {
        assert!(
            inputs.len() == labels.len(),
            "Cnn::{caller}: {} inputs but {} label vectors",
            inputs.len(),
            labels.len()
        );
        assert!(!inputs.is_empty(), "Cnn::{caller}: there are no examples");
        for (input, label) in inputs.iter().zip(labels) {
            self.check_input(input, caller);
            assert!(
                label.len() == self.shape.outputs,
                "Cnn::{caller}: a label vector has {} values, the network has {} outputs",
                label.len(),
                self.shape.outputs
            );
        }
    }

    /// The output logits for one image (no dropout). Panics if the input has the wrong length.
    pub fn logits(&self, input: &[f32]) -> Vec<f32> {
        self.check_input(input, "logits");
        let s = &self.shape;
        let (features, _) = self.conv_forward(input);
        let mut hidden = vec![0.0; s.dense];
        vec_mat(&features, self.group(DENSE_W), &mut hidden);
        for (h, b) in hidden.iter_mut().zip(self.group(DENSE_B)) {
            *h = (*h + b).max(0.0);
        }
        let mut logits = vec![0.0; s.outputs];
        vec_mat(&hidden, self.group(OUT_W), &mut logits);
        for (z, b) in logits.iter_mut().zip(self.group(OUT_B)) {
            *z += b;
        }
        logits
    }

    /// The sigmoid outputs for one image (no dropout). Panics if the input has the wrong length.
    pub fn forward(&self, input: &[f32]) -> Vec<f32> {
        let mut out = self.logits(input);
        for z in &mut out {
            *z = sigmoid(*z);
        }
        out
    }

    /// Whether each output exceeds 0.5 for one image.
    pub fn predict(&self, input: &[f32]) -> Vec<bool> {
        self.forward(input).into_iter().map(|p| p > 0.5).collect()
    }

    /// [`Cnn::forward`] for many images, in parallel over the images; equal to calling
    /// `forward` on each.
    pub fn forward_batch(&self, inputs: &[&[f32]]) -> Vec<Vec<f32>> {
        inputs.par_iter().map(|input| self.forward(input)).collect()
    }

    /// The mean over the examples of the summed sigmoid cross-entropy, without dropout. Panics
    /// on mismatched lengths or no examples.
    pub fn loss(&self, inputs: &[&[f32]], labels: &[Vec<bool>]) -> f32 {
        self.check_examples(inputs, labels, "loss");
        let each: Vec<f64> = inputs
            .par_iter()
            .zip(labels.par_iter())
            .map(|(input, label)| {
                let logits = self.logits(input);
                logits
                    .iter()
                    .zip(label)
                    .map(|(&z, &y)| cross_entropy(z, y) as f64)
                    .sum()
            })
            .collect();
        (each.iter().sum::<f64>() / inputs.len() as f64) as f32
    }

    /// Trains for `config.steps` Adam steps on batches of `config.batch` examples drawn from the
    /// seeded stream: distinct examples per batch, or with replacement when there are fewer
    /// examples than a batch. Deterministic for a seed whatever the rayon thread count; a second
    /// call continues the stream and the Adam state. Panics on mismatched lengths or no examples.
    pub fn train(&mut self, inputs: &[&[f32]], labels: &[Vec<bool>]) -> TrainReport {
        self.check_examples(inputs, labels, "train");
        let (n, batch, steps) = (inputs.len(), self.config.batch, self.config.steps);
        let dropout = self.config.dropout;
        let keep_scale = 1.0 / (1.0 - dropout);
        let mut order: Vec<usize> = (0..n).collect();
        let mut grads = vec![0.0f32; self.params.len()];
        let mut masks = vec![0.0f32; batch * self.shape.dense];
        let mut losses = Vec::with_capacity(steps);
        for _ in 0..steps {
            let chosen: Vec<usize> = if n >= batch {
                // A partial Fisher-Yates shuffle: `batch` distinct examples.
                for i in 0..batch {
                    let j = i + self.rng.below((n - i) as u64) as usize;
                    order.swap(i, j);
                }
                order[..batch].to_vec()
            } else {
                (0..batch)
                    .map(|_| self.rng.below(n as u64) as usize)
                    .collect()
            };
            let xs: Vec<&[f32]> = chosen.iter().map(|&i| inputs[i]).collect();
            let ys: Vec<&[bool]> = chosen.iter().map(|&i| labels[i].as_slice()).collect();
            let mask = if dropout > 0.0 {
                for m in &mut masks {
                    *m = if self.rng.chance(dropout as f64) {
                        0.0
                    } else {
                        keep_scale
                    };
                }
                Some(masks.as_slice())
            } else {
                None
            };
            losses.push(self.batch_gradient(&xs, &ys, mask, &mut grads));
            self.adam(&grads);
        }
        let tail = &losses[losses.len() - losses.len().min(20)..];
        let final_loss = tail.iter().map(|&l| l as f64).sum::<f64>() / tail.len() as f64;
        TrainReport {
            steps,
            final_loss: final_loss as f32,
            losses,
        }
    }

    /// One Adam step (Kingma and Ba 2015, algorithm 1) with the gradient `grads`.
    fn adam(&mut self, grads: &[f32]) {
        self.adam_steps += 1;
        let c = &self.config;
        let (b1, b2, eps) = (c.adam_beta1, c.adam_beta2, c.adam_epsilon);
        let t = self.adam_steps.min(i32::MAX as u64) as i32;
        let rate = (c.learning_rate as f64 / (1.0 - (b1 as f64).powi(t))) as f32;
        let inverse_correction2 = (1.0 / (1.0 - (b2 as f64).powi(t))) as f32;
        self.params
            .par_chunks_mut(ADAM_PIECE)
            .zip(self.moment1.par_chunks_mut(ADAM_PIECE))
            .zip(self.moment2.par_chunks_mut(ADAM_PIECE))
            .zip(grads.par_chunks(ADAM_PIECE))
            .for_each(|(((p, m), v), g)| {
                for (((p, m), v), &g) in p.iter_mut().zip(m).zip(v).zip(g) {
                    *m = b1 * *m + (1.0 - b1) * g;
                    *v = b2 * *v + (1.0 - b2) * g * g;
                    *p -= rate * *m / ((*v * inverse_correction2).sqrt() + eps);
                }
            });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(super) fn tiny(height: usize, width: usize, channels: usize) -> CnnConfig {
        CnnConfig {
            height,
            width,
            channels,
            kernel: 3,
            filters1: 2,
            filters2: 3,
            dense: 4,
            outputs: 2,
            dropout: 0.0,
            ..CnnConfig::default()
        }
    }

    pub(super) fn random_examples(
        cnn: &Cnn,
        n: usize,
        seed: u64,
    ) -> (Vec<Vec<f32>>, Vec<Vec<bool>>) {
        let mut rng = SplitMix64::new(seed);
        let xs = (0..n)
            .map(|_| {
                (0..cnn.input_len())
                    .map(|_| rng.range_f32(0.0, 1.0))
                    .collect()
            })
            .collect();
        let outputs = cnn.config().outputs;
        let ys = (0..n)
            .map(|_| (0..outputs).map(|_| rng.chance(0.5)).collect())
            .collect();
        (xs, ys)
    }

    pub(super) fn refs(xs: &[Vec<f32>]) -> Vec<&[f32]> {
        xs.iter().map(|x| x.as_slice()).collect()
    }

    #[test]
    fn forward_on_a_hand_set_network() {
        let mut cnn = Cnn::new(CnnConfig {
            height: 4,
            width: 4,
            channels: 1,
            kernel: 3,
            filters1: 1,
            filters2: 1,
            dense: 2,
            outputs: 1,
            ..CnnConfig::default()
        });
        // conv1 (weights [ky][kx]): 1 at the centre, -2 right of it, bias 0.1, so
        // out(y, x) = in(y, x) - 2 in(y, x + 1) + 0.1 (0 right of the image). On the input
        //   0.1 0.2 0.3 0.4      -0.2 -0.3 -0.4  0.5          0   0    0  0.5
        //   0.5 0.6 0.7 0.8  ->  -0.6 -0.7 -0.8  0.9  ReLU->  0   0    0  0.9  pool-> 0   0.9
        //   0.9 1.0 0.0 0.1      -1.0  1.1 -0.1  0.2          0  1.1   0  0.2         1.1 0.6
        //   0.2 0.3 0.4 0.5      -0.3 -0.4 -0.5  0.6          0   0    0  0.6
        // conv2: 1 at the centre, 1 above it, bias -0.2: out(y, x) = p(y, x) + p(y - 1, x) - 0.2
        //   = [0 + 0 - 0.2, 0.9 + 0 - 0.2; 1.1 + 0 - 0.2, 0.6 + 0.9 - 0.2] = [-0.2, 0.7; 0.9, 1.3]
        //   -> ReLU and pool: the single feature 1.3.
        // dense: weights (2, -1), biases (0, 0.5): (2.6, -0.8) -> ReLU (2.6, 0).
        // output: weights (1, 3), bias -2: logit 2.6 - 2 = 0.6, sigmoid(0.6) = 0.645656.
        let p = cnn.parameters_mut();
        p.conv1_weights.fill(0.0);
        p.conv1_weights[4] = 1.0;
        p.conv1_weights[5] = -2.0;
        p.conv1_bias[0] = 0.1;
        p.conv2_weights.fill(0.0);
        p.conv2_weights[4] = 1.0;
        p.conv2_weights[1] = 1.0;
        p.conv2_bias[0] = -0.2;
        p.dense_weights.copy_from_slice(&[2.0, -1.0]);
        p.dense_bias.copy_from_slice(&[0.0, 0.5]);
        p.output_weights.copy_from_slice(&[1.0, 3.0]);
        p.output_bias[0] = -2.0;
        let input = [
            0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 0.0, 0.1, 0.2, 0.3, 0.4, 0.5,
        ];
        let (features, _) = cnn.conv_forward(&input);
        assert_eq!(features.len(), 1);
        assert!((features[0] - 1.3).abs() < 1e-6, "{features:?}");
        let logit = cnn.logits(&input)[0];
        assert!((logit - 0.6).abs() < 1e-6, "logit {logit}");
        let out = cnn.forward(&input)[0];
        assert!((out - 0.645_656_5).abs() < 1e-6, "output {out}");
        assert_eq!(cnn.predict(&input), vec![true]);
    }

    /// Images whose left half is brighter than the right (label true) or the reverse.
    fn halves(n: usize, seed: u64) -> (Vec<Vec<f32>>, Vec<Vec<bool>>) {
        let (h, w, c) = (8, 8, 3);
        let mut rng = SplitMix64::new(seed);
        let mut xs = Vec::new();
        let mut ys = Vec::new();
        for _ in 0..n {
            let left_brighter = rng.chance(0.5);
            let bright = rng.range_f32(0.5, 0.9);
            let dark = rng.range_f32(0.1, 0.45);
            let mut image = vec![0.0; h * w * c];
            for y in 0..h {
                for x in 0..w {
                    let base = if (x < w / 2) == left_brighter {
                        bright
                    } else {
                        dark
                    };
                    for ch in 0..c {
                        let v = base + rng.range_f32(-0.15, 0.15);
                        image[(y * w + x) * c + ch] = v.clamp(0.0, 1.0);
                    }
                }
            }
            xs.push(image);
            ys.push(vec![left_brighter]);
        }
        (xs, ys)
    }

    #[test]
    fn learns_which_half_is_brighter() {
        let config = CnnConfig {
            height: 8,
            width: 8,
            channels: 3,
            kernel: 3,
            filters1: 4,
            filters2: 8,
            dense: 32,
            outputs: 1,
            learning_rate: 0.001,
            steps: 300,
            seed: 4,
            ..CnnConfig::default()
        };
        let mut cnn = Cnn::new(config);
        let (xs, ys) = halves(200, 1);
        let before = cnn.loss(&refs(&xs), &ys);
        let report = cnn.train(&refs(&xs), &ys);
        assert_eq!((report.steps, report.losses.len()), (300, 300));
        let after = cnn.loss(&refs(&xs), &ys);
        assert!(after < before / 2.0, "loss {before} -> {after}");
        let accuracy = |xs: &[Vec<f32>], ys: &[Vec<bool>]| {
            let right = xs
                .iter()
                .zip(ys)
                .filter(|(x, y)| cnn.predict(x) == **y)
                .count();
            right as f64 / xs.len() as f64
        };
        let train = accuracy(&xs, &ys);
        assert!(train > 0.95, "training accuracy {train}");
        let (test_xs, test_ys) = halves(200, 2);
        let test = accuracy(&test_xs, &test_ys);
        assert!(test > 0.9, "held-out accuracy {test}");
    }

    #[test]
    fn training_is_deterministic_across_thread_counts() {
        // More than ROWS_PER_PIECE dense units and features, so the dense products are split.
        let config = CnnConfig {
            filters2: 12,
            dense: 200,
            outputs: 2,
            dropout: 0.4,
            batch: 6,
            steps: 15,
            learning_rate: 0.001,
            seed: 9,
            ..tiny(16, 16, 3)
        };
        let probe = Cnn::new(config.clone());
        assert!(probe.shape.features > ROWS_PER_PIECE && probe.shape.dense > ROWS_PER_PIECE);
        let (xs, ys) = random_examples(&probe, 20, 8);
        let run = |threads: usize, seed: u64| {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap();
            pool.install(|| {
                let mut cnn = Cnn::new(CnnConfig {
                    seed,
                    ..config.clone()
                });
                let report = cnn.train(&refs(&xs), &ys);
                let bits: Vec<u32> = cnn.parameters().iter().map(|v| v.to_bits()).collect();
                (bits, report.losses)
            })
        };
        let one = run(1, 9);
        assert!(one == run(1, 9), "two runs on one thread differ");
        assert!(one == run(2, 9), "one and two threads differ");
        assert!(one.0 != run(2, 10).0, "the seed changes nothing");
    }

    #[test]
    fn fewer_examples_than_a_batch_are_drawn_with_replacement() {
        let mut cnn = Cnn::new(CnnConfig {
            batch: 10,
            steps: 100,
            learning_rate: 0.01,
            ..tiny(4, 4, 1)
        });
        let (xs, ys) = random_examples(&cnn, 3, 2);
        let before = cnn.loss(&refs(&xs), &ys);
        let report = cnn.train(&refs(&xs), &ys);
        assert!(report.final_loss.is_finite());
        let after = cnn.loss(&refs(&xs), &ys);
        assert!(after < before, "loss {before} -> {after}");
    }

    #[test]
    fn a_wrong_input_length_is_said_in_a_sentence() {
        // `forward`, `logits` and training panic with this sentence (API misuse).
        let cnn = Cnn::new(tiny(4, 4, 1));
        assert_eq!(
            cnn.input_error(&[0.0; 15]).as_deref(),
            Some("the input has 15 values, the network takes 4x4x1 = 16")
        );
        assert_eq!(cnn.input_error(&[0.0; 16]), None);
    }
}
