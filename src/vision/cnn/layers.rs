//! The forward and backward passes of [`Cnn`]: im2col convolutions over CHW planes and dense
//! layers on `matrixmultiply::sgemm` (with [`gemm_nt`] for the products that read a matrix across
//! its rows, [`vec_mat`] for one image), 2x2 max pooling, and a batch's loss and gradient.
//!
//! Invariant: the parallel pieces (one example's convolutions, `ROWS_PER_PIECE` rows of a dense
//! product) are fixed by the sizes, and per-example gradients are summed in example order, so
//! the gradient of a batch is the same bit for bit on any number of threads.

use rayon::prelude::*;

use super::{
    Cnn, CONV1_B, CONV1_W, CONV2_B, CONV2_W, DENSE_B, DENSE_W, OUT_B, OUT_W, ROWS_PER_PIECE,
};

/// What the backward pass needs of one example's convolution layers.
pub(super) struct Trace {
    cols1: Vec<f32>,
    out1: Vec<f32>,
    arg1: Vec<u32>,
    cols2: Vec<f32>,
    out2: Vec<f32>,
    arg2: Vec<u32>,
}

impl Cnn {
    /// The pooled features of one image and what the backward pass needs.
    pub(super) fn conv_forward(&self, input: &[f32]) -> (Vec<f32>, Trace) {
        let s = &self.shape;
        let planes = to_planes(input, s.channels);
        let (cols1, out1) = conv_relu(
            &planes,
            (s.height, s.width, s.channels),
            s.kernel,
            self.group(CONV1_W),
            self.group(CONV1_B),
        );
        let (pool1, arg1) = max_pool(&out1, s.height, s.width, s.filters1);
        let (cols2, out2) = conv_relu(
            &pool1,
            (s.h1, s.w1, s.filters1),
            s.kernel,
            self.group(CONV2_W),
            self.group(CONV2_B),
        );
        let (features, arg2) = max_pool(&out2, s.h1, s.w1, s.filters2);
        let trace = Trace {
            cols1,
            out1,
            arg1,
            cols2,
            out2,
            arg2,
        };
        (features, trace)
    }

    /// One example's gradient of the convolution groups (the prefix of the flat vector up to the
    /// dense weights), from the gradient of its pooled features. A weight gradient is the im2col
    /// rows against the output-gradient planes, both contiguous along the positions
    /// ([`gemm_nt`]); the gradient at the first pooling is sgemm followed by [`col2im`].
    pub(super) fn conv_backward(&self, trace: &Trace, dfeatures: &[f32]) -> Vec<f32> {
        let s = &self.shape;
        let o = &s.offsets;
        let (k2, n1, n2) = (s.kernel * s.kernel, s.height * s.width, s.h1 * s.w1);
        let mut grads = vec![0.0f32; o[DENSE_W]];
        let (g1, g2) = grads.split_at_mut(o[CONV2_W]);
        let (gw1, gb1) = g1.split_at_mut(o[CONV1_B]);
        let (gw2, gb2) = g2.split_at_mut(o[CONV2_B] - o[CONV2_W]);
        let kk2 = k2 * s.filters1;

        let dout2 = unpool_relu(dfeatures, &trace.arg2, &trace.out2);
        gemm_nt(&trace.cols2, &dout2, n2, gw2);
        plane_sums(&dout2, gb2);
        let mut dcols2 = vec![0.0f32; n2 * kk2];
        gemm(
            View::new(self.group(CONV2_W), kk2, s.filters2),
            View::new(&dout2, s.filters2, n2),
            &mut dcols2,
        );
        let mut dpool1 = vec![0.0f32; n2 * s.filters1];
        col2im(&dcols2, (s.h1, s.w1, s.filters1), s.kernel, &mut dpool1);

        let dout1 = unpool_relu(&dpool1, &trace.arg1, &trace.out1);
        gemm_nt(&trace.cols1, &dout1, n1, gw1);
        plane_sums(&dout1, gb1);
        grads
    }

    /// The mean loss of a batch, and its gradient written over `grads`. `masks`: the dropout
    /// multipliers of the hidden units (`batch x dense`, 0 or `1 / (1 - p)`), or none.
    pub(super) fn batch_gradient(
        &self,
        inputs: &[&[f32]],
        targets: &[&[bool]],
        masks: Option<&[f32]>,
        grads: &mut [f32],
    ) -> f32 {
        let s = &self.shape;
        let (b, p, d, o) = (inputs.len(), s.features, s.dense, s.outputs);
        let traces: Vec<(Vec<f32>, Trace)> =
            inputs.par_iter().map(|x| self.conv_forward(x)).collect();
        let mut x = Vec::with_capacity(b * p);
        for (features, _) in &traces {
            x.extend_from_slice(features);
        }
        let x = View::new(&x, b, p);
        let w1 = View::new(self.group(DENSE_W), p, d);

        // Hidden pre-activations transposed, Z1^T (d x b) = W1^T X^T, in fixed row pieces.
        let mut z1t = vec![0.0f32; d * b];
        z1t.par_chunks_mut(ROWS_PER_PIECE * b)
            .enumerate()
            .for_each(|(i, piece)| {
                let rows = w1.t().row_range(i * ROWS_PER_PIECE, piece.len() / b);
                gemm(rows, x.t(), piece);
            });
        let mut hidden = vec![0.0f32; b * d]; // after ReLU, before dropout
        let mut dropped = vec![0.0f32; b * d]; // after dropout
        for (j, bias) in self.group(DENSE_B).iter().enumerate() {
            for e in 0..b {
                let h = (z1t[j * b + e] + bias).max(0.0);
                hidden[e * d + j] = h;
                dropped[e * d + j] = masks.map_or(h, |m| h * m[e * d + j]);
            }
        }
        let mut z2 = vec![0.0f32; b * o];
        let w2 = View::new(self.group(OUT_W), d, o);
        gemm(View::new(&dropped, b, d), w2, &mut z2);

        let mut loss = 0.0f64;
        let mut dz2 = vec![0.0f32; b * o];
        for e in 0..b {
            for (j, bias) in self.group(OUT_B).iter().enumerate() {
                let z = z2[e * o + j] + bias;
                let y = targets[e][j];
                loss += cross_entropy(z, y) as f64;
                dz2[e * o + j] = (sigmoid(z) - if y { 1.0 } else { 0.0 }) / b as f32;
            }
        }

        let off = &s.offsets;
        let (gconv, rest) = grads.split_at_mut(off[DENSE_W]);
        let (gdw, rest) = rest.split_at_mut(off[DENSE_B] - off[DENSE_W]);
        let (gdb, rest) = rest.split_at_mut(off[OUT_W] - off[DENSE_B]);
        let (gow, gob) = rest.split_at_mut(off[OUT_B] - off[OUT_W]);
        gemm(View::new(&dropped, b, d).t(), View::new(&dz2, b, o), gow);
        column_sums(&dz2, gob);
        let mut dz1 = vec![0.0f32; b * d];
        gemm(View::new(&dz2, b, o), w2.t(), &mut dz1);
        for (i, g) in dz1.iter_mut().enumerate() {
            *g = if hidden[i] > 0.0 {
                *g * masks.map_or(1.0, |m| m[i])
            } else {
                0.0
            };
        }
        column_sums(&dz1, gdb);
        let dz1v = View::new(&dz1, b, d);
        // dW1 (p x d) = X^T dZ1 and dX^T (p x b) = W1 dZ1^T, in fixed row pieces; the second
        // reads W1 across its rows, which sgemm's packing would gather element by element.
        gdw.par_chunks_mut(ROWS_PER_PIECE * d)
            .enumerate()
            .for_each(|(i, piece)| {
                let rows = x.t().row_range(i * ROWS_PER_PIECE, piece.len() / d);
                gemm(rows, dz1v, piece);
            });
        let mut dxt = vec![0.0f32; p * b];
        let w1_rows = self.group(DENSE_W);
        dxt.par_chunks_mut(ROWS_PER_PIECE * b)
            .enumerate()
            .for_each(|(i, piece)| {
                let rows = &w1_rows[i * ROWS_PER_PIECE * d..][..piece.len() / b * d];
                gemm_nt(rows, &dz1, d, piece);
            });

        let conv_grads: Vec<Vec<f32>> = traces
            .par_iter()
            .enumerate()
            .map(|(e, (_, trace))| {
                let dfeatures: Vec<f32> = (0..p).map(|i| dxt[i * b + e]).collect();
                self.conv_backward(trace, &dfeatures)
            })
            .collect();
        gconv.fill(0.0);
        for g in &conv_grads {
            for (sum, v) in gconv.iter_mut().zip(g) {
                *sum += v;
            }
        }
        (loss / b as f64) as f32
    }
}

/// The logistic function, without overflow for large `|z|`.
pub(super) fn sigmoid(z: f32) -> f32 {
    if z >= 0.0 {
        1.0 / (1.0 + (-z).exp())
    } else {
        let e = z.exp();
        e / (1.0 + e)
    }
}

/// Sigmoid cross-entropy of a logit against a label, stable for large `|z|`.
pub(super) fn cross_entropy(z: f32, y: bool) -> f32 {
    z.max(0.0) - if y { z } else { 0.0 } + (-z.abs()).exp().ln_1p()
}

/// A read-only matrix view with arbitrary strides, for [`gemm`].
#[derive(Clone, Copy)]
pub(super) struct View<'a> {
    data: &'a [f32],
    rows: usize,
    cols: usize,
    row_stride: usize,
    col_stride: usize,
}

impl<'a> View<'a> {
    /// A row-major `rows x cols` matrix.
    pub(super) fn new(data: &'a [f32], rows: usize, cols: usize) -> Self {
        View {
            data,
            rows,
            cols,
            row_stride: cols,
            col_stride: 1,
        }
    }

    pub(super) fn t(self) -> Self {
        View {
            rows: self.cols,
            cols: self.rows,
            row_stride: self.col_stride,
            col_stride: self.row_stride,
            ..self
        }
    }

    /// Rows `start..start + rows`.
    fn row_range(self, start: usize, rows: usize) -> Self {
        View {
            data: &self.data[start * self.row_stride..],
            rows,
            ..self
        }
    }

    fn in_bounds(&self) -> bool {
        self.rows == 0
            || self.cols == 0
            || (self.rows - 1) * self.row_stride + (self.cols - 1) * self.col_stride
                < self.data.len()
    }
}

/// `c = a b`, with `c` row-major `a.rows x b.cols`.
pub(super) fn gemm(a: View<'_>, b: View<'_>, c: &mut [f32]) {
    let (m, k, n) = (a.rows, a.cols, b.cols);
    assert!(b.rows == k && c.len() == m * n, "gemm: mismatched sizes");
    assert!(
        a.in_bounds() && b.in_bounds(),
        "gemm: a view exceeds its data"
    );
    if m == 0 || n == 0 {
        return;
    }
    // SAFETY: the assertions above keep every element that sgemm reads, `a` and `b` at
    // `row * row_stride + col * col_stride`, inside its slice, and every element it writes,
    // `c` at `row * n + col`, inside `c`; `c` is an exclusive borrow, so nothing aliases it.
    unsafe {
        matrixmultiply::sgemm(
            m,
            k,
            n,
            1.0,
            a.data.as_ptr(),
            a.row_stride as isize,
            a.col_stride as isize,
            b.data.as_ptr(),
            b.row_stride as isize,
            b.col_stride as isize,
            0.0,
            c.as_mut_ptr(),
            n as isize,
            1,
        );
    }
}

/// `c = a b^T` for row-major `a` (`m x k`) and `b` (`n x k`), `c` row-major `m x n`: every
/// element is the dot product of two contiguous rows, so `a` streams through once where sgemm
/// would gather it across its rows into packed panels.
pub(super) fn gemm_nt(a: &[f32], b: &[f32], k: usize, c: &mut [f32]) {
    assert!(
        k > 0 && a.len() % k == 0 && b.len() % k == 0,
        "gemm_nt: rows of k values"
    );
    let n = b.len() / k;
    assert!(c.len() == a.len() / k * n, "gemm_nt: mismatched sizes");
    for (a_row, c_row) in a.chunks_exact(k).zip(c.chunks_exact_mut(n)) {
        for (b_row, out) in b.chunks_exact(k).zip(c_row.iter_mut()) {
            *out = dot(a_row, b_row);
        }
    }
}

/// A dot product in 16 interleaved partial sums (so it vectorizes), added up in a fixed order.
fn dot(a: &[f32], b: &[f32]) -> f32 {
    const LANES: usize = 16;
    let mut lanes = [0.0f32; LANES];
    let (a_blocks, b_blocks) = (a.chunks_exact(LANES), b.chunks_exact(LANES));
    let tail: f32 = a_blocks
        .remainder()
        .iter()
        .zip(b_blocks.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in a_blocks.zip(b_blocks) {
        for l in 0..LANES {
            lanes[l] += x[l] * y[l];
        }
    }
    lanes.iter().sum::<f32>() + tail
}

/// `out = x w` for one row `x` and a row-major `w` with `out.len()` columns, rows of `w` added in
/// order, skipping zeros of `x` (ReLU outputs). For one example the dense layers are
/// vector-matrix products: sgemm would first pack all of `w` (a copy of the 12.8 MB hidden
/// layer per image); this loop reads each weight once.
pub(super) fn vec_mat(x: &[f32], w: &[f32], out: &mut [f32]) {
    let n = out.len();
    assert!(w.len() == x.len() * n, "vec_mat: mismatched sizes");
    out.fill(0.0);
    for (&xi, row) in x.iter().zip(w.chunks_exact(n)) {
        if xi != 0.0 {
            for (o, &wv) in out.iter_mut().zip(row) {
                *o += xi * wv;
            }
        }
    }
}

/// An HWC image as CHW planes (channel after channel, each row-major).
fn to_planes(input: &[f32], c: usize) -> Vec<f32> {
    let hw = input.len() / c;
    let mut planes = vec![0.0f32; input.len()];
    for (pos, pixel) in input.chunks_exact(c).enumerate() {
        for (ci, &v) in pixel.iter().enumerate() {
            planes[ci * hw + pos] = v;
        }
    }
    planes
}

/// The output columns `x` at which kernel column `kx` reads inside the image,
/// `0 <= x + kx - pad < w`, as a range (possibly empty).
fn valid_columns(kx: usize, w: usize, k: usize) -> (usize, usize) {
    let pad = k / 2;
    let start = pad.saturating_sub(kx).min(w);
    (start, (w + pad).saturating_sub(kx).clamp(start, w))
}

/// The row segments of im2col over CHW planes: for patch element `e = (ky * k + kx) * c + ci`
/// and output row `y`, `f(e, y, plane_start, x0, x1)` where output columns `x0..x1` read plane
/// values `plane_start..plane_start + x1 - x0` and the other columns lie in the zero padding
/// (no call when the whole row does).
fn patch_rows(
    (h, w, c): (usize, usize, usize),
    k: usize,
    mut f: impl FnMut(usize, usize, usize, usize, usize),
) {
    let pad = k / 2;
    for e in 0..k * k * c {
        let (ky, kx, ci) = (e / (k * c), e / c % k, e % c);
        let (x0, x1) = valid_columns(kx, w, k);
        for y in 0..h {
            let iy = y + ky;
            if x0 < x1 && iy >= pad && iy - pad < h {
                f(e, y, ci * h * w + (iy - pad) * w + x0 + kx - pad, x0, x1);
            }
        }
    }
}

/// im2col over CHW planes: row `(ky * k + kx) * c + ci` of the result (`k * k * c` rows of `h * w`)
/// holds plane `ci` shifted by `(ky - pad, kx - pad)`, zero outside the image, so that the
/// convolution is `W^T cols` and every row is built from contiguous copies.
fn im2col(planes: &[f32], dims: (usize, usize, usize), k: usize) -> Vec<f32> {
    let (h, w, c) = dims;
    let mut cols = vec![0.0f32; k * k * c * h * w];
    patch_rows(dims, k, |e, y, start, x0, x1| {
        let row = &mut cols[e * h * w + y * w..][..w];
        row[x0..x1].copy_from_slice(&planes[start..start + x1 - x0]);
    });
    cols
}

/// The adjoint of [`im2col`]: adds every row back onto the plane positions it was copied from.
fn col2im(cols: &[f32], dims: (usize, usize, usize), k: usize, planes: &mut [f32]) {
    let (h, w, _) = dims;
    patch_rows(dims, k, |e, y, start, x0, x1| {
        let row = &cols[e * h * w + y * w..][..w];
        for (d, v) in planes[start..start + x1 - x0].iter_mut().zip(&row[x0..x1]) {
            *d += v;
        }
    });
}

/// A same-padded convolution with bias and ReLU over CHW planes: the im2col matrix and the
/// output planes (`f x h x w`).
fn conv_relu(
    planes: &[f32],
    dims: (usize, usize, usize),
    k: usize,
    weights: &[f32],
    bias: &[f32],
) -> (Vec<f32>, Vec<f32>) {
    let (h, w, c) = dims;
    let (f, rows) = (bias.len(), k * k * c);
    let cols = im2col(planes, dims, k);
    let mut out = vec![0.0f32; f * h * w];
    gemm(
        View::new(weights, rows, f).t(),
        View::new(&cols, rows, h * w),
        &mut out,
    );
    for (plane, b) in out.chunks_exact_mut(h * w).zip(bias) {
        for o in plane {
            *o = (*o + b).max(0.0);
        }
    }
    (cols, out)
}

/// 2x2 max pooling of stride 2 over CHW planes (an odd last row or column is dropped): the
/// pooled planes and, for each value, the index of its maximum in `planes` (the first on ties).
fn max_pool(planes: &[f32], h: usize, w: usize, c: usize) -> (Vec<f32>, Vec<u32>) {
    let (ho, wo) = (h / 2, w / 2);
    let mut out = Vec::with_capacity(c * ho * wo);
    let mut arg = Vec::with_capacity(c * ho * wo);
    for (ch, plane) in planes.chunks_exact(h * w).enumerate() {
        for y in 0..ho {
            let (upper, lower) = (&plane[2 * y * w..][..w], &plane[(2 * y + 1) * w..][..w]);
            for x in 0..wo {
                let (mut best, mut at) = (upper[2 * x], 2 * y * w + 2 * x);
                for (v, i) in [
                    (upper[2 * x + 1], at + 1),
                    (lower[2 * x], at + w),
                    (lower[2 * x + 1], at + w + 1),
                ] {
                    if v > best {
                        (best, at) = (v, i);
                    }
                }
                out.push(best);
                arg.push((ch * h * w + at) as u32);
            }
        }
    }
    (out, arg)
}

/// The gradient at a ReLU convolution's output from the gradient at its pooling: each pooled
/// gradient goes to its window's maximum, if that unit was active.
fn unpool_relu(dpooled: &[f32], arg: &[u32], out: &[f32]) -> Vec<f32> {
    let mut d = vec![0.0f32; out.len()];
    for (&g, &i) in dpooled.iter().zip(arg) {
        if out[i as usize] > 0.0 {
            d[i as usize] = g;
        }
    }
    d
}

/// The sum of every plane (`sums.len()` of them), in order.
fn plane_sums(planes: &[f32], sums: &mut [f32]) {
    let size = planes.len() / sums.len();
    for (sum, plane) in sums.iter_mut().zip(planes.chunks_exact(size)) {
        *sum = plane.iter().sum();
    }
}

/// Column sums of a row-major matrix with `sums.len()` columns, rows added in order.
fn column_sums(matrix: &[f32], sums: &mut [f32]) {
    sums.fill(0.0);
    for row in matrix.chunks_exact(sums.len()) {
        for (s, v) in sums.iter_mut().zip(row) {
            *s += v;
        }
    }
}
#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::rng::SplitMix64;
    use crate::vision::cnn::tests::{random_examples, refs, tiny};
    use crate::vision::cnn::{CnnConfig, GROUPS};

    // A reference network in f64 with direct loops (convolution by its definition, no im2col,
    // no sgemm): checks the fast forward pass and gives the finite differences their precision.
    fn ref_conv(
        x: &[f64],
        (h, w, c): (usize, usize, usize),
        k: usize,
        wt: &[f64],
        bias: &[f64],
    ) -> Vec<f64> {
        let (f, pad) = (bias.len(), (k / 2) as isize);
        let mut out = vec![0.0; h * w * f];
        for y in 0..h {
            for xx in 0..w {
                for fo in 0..f {
                    let mut sum = bias[fo];
                    for ky in 0..k {
                        for kx in 0..k {
                            let iy = y as isize + ky as isize - pad;
                            let ix = xx as isize + kx as isize - pad;
                            if iy < 0 || ix < 0 || iy >= h as isize || ix >= w as isize {
                                continue;
                            }
                            for ci in 0..c {
                                let v = x[(iy as usize * w + ix as usize) * c + ci];
                                sum += v * wt[((ky * k + kx) * c + ci) * f + fo];
                            }
                        }
                    }
                    out[(y * w + xx) * f + fo] = sum.max(0.0);
                }
            }
        }
        out
    }

    fn ref_pool(x: &[f64], h: usize, w: usize, c: usize) -> Vec<f64> {
        let mut out = Vec::new();
        for y in 0..h / 2 {
            for xx in 0..w / 2 {
                for ch in 0..c {
                    let at = |dy: usize, dx: usize| x[((2 * y + dy) * w + 2 * xx + dx) * c + ch];
                    out.push(at(0, 0).max(at(0, 1)).max(at(1, 0)).max(at(1, 1)));
                }
            }
        }
        out
    }

    fn ref_dense(x: &[f64], wt: &[f64], bias: &[f64]) -> Vec<f64> {
        let n = bias.len();
        (0..n)
            .map(|j| {
                bias[j]
                    + x.iter()
                        .enumerate()
                        .map(|(i, v)| v * wt[i * n + j])
                        .sum::<f64>()
            })
            .collect()
    }

    /// Logits of the reference network with parameters `p`; `mask`: dropout multipliers.
    fn ref_logits(cnn: &Cnn, p: &[f64], input: &[f32], mask: Option<&[f32]>) -> Vec<f64> {
        let s = &cnn.shape;
        let g = |i: usize| &p[s.offsets[i]..s.offsets[i + 1]];
        let x: Vec<f64> = input.iter().map(|&v| v as f64).collect();
        let c1 = ref_conv(&x, (s.height, s.width, s.channels), s.kernel, g(0), g(1));
        let p1 = ref_pool(&c1, s.height, s.width, s.filters1);
        let c2 = ref_conv(&p1, (s.h1, s.w1, s.filters1), s.kernel, g(2), g(3));
        let p2 = ref_pool(&c2, s.h1, s.w1, s.filters2);
        // The dense layer reads the pooled features channel by channel (CHW).
        let (f2, n2) = (s.filters2, p2.len() / s.filters2);
        let chw: Vec<f64> = (0..p2.len()).map(|i| p2[(i % n2) * f2 + i / n2]).collect();
        let mut hidden = ref_dense(&chw, g(4), g(5));
        for (j, h) in hidden.iter_mut().enumerate() {
            *h = h.max(0.0) * mask.map_or(1.0, |m| m[j] as f64);
        }
        ref_dense(&hidden, g(6), g(7))
    }

    fn ref_loss(cnn: &Cnn, p: &[f64], xs: &[&[f32]], ys: &[&[bool]], masks: Option<&[f32]>) -> f64 {
        let d = cnn.shape.dense;
        let mut total = 0.0;
        for (e, (x, y)) in xs.iter().zip(ys).enumerate() {
            let mask = masks.map(|m| &m[e * d..(e + 1) * d]);
            for (z, &t) in ref_logits(cnn, p, x, mask).iter().zip(y.iter()) {
                total += z.max(0.0) - if t { *z } else { 0.0 } + (-z.abs()).exp().ln_1p();
            }
        }
        total / xs.len() as f64
    }

    #[test]
    fn forward_matches_the_direct_reference() {
        // Non-square, 5x5 kernels, odd sizes after the first pooling, several channels.
        let config = CnnConfig {
            kernel: 5,
            filters1: 3,
            filters2: 4,
            dense: 6,
            outputs: 3,
            ..tiny(10, 14, 3)
        };
        let mut cnn = Cnn::new(config);
        let mut rng = SplitMix64::new(5);
        for b in cnn.parameters_mut().conv1_bias.iter_mut() {
            *b = rng.range_f32(-0.2, 0.2);
        }
        let (xs, _) = random_examples(&cnn, 4, 6);
        let p: Vec<f64> = cnn.parameters().iter().map(|&v| v as f64).collect();
        let batch = cnn.forward_batch(&refs(&xs));
        for (x, out) in xs.iter().zip(&batch) {
            assert_eq!(out, &cnn.forward(x), "forward_batch differs from forward");
            let expected = ref_logits(&cnn, &p, x, None);
            for (z, e) in cnn.logits(x).iter().zip(&expected) {
                assert!((*z as f64 - e).abs() < 1e-4, "logit {z} against {e}");
            }
        }
    }

    fn check_gradient(cnn: &Cnn, xs: &[&[f32]], ys: &[&[bool]], masks: Option<&[f32]>) {
        let mut grads = vec![0.0f32; cnn.params.len()];
        let loss = cnn.batch_gradient(xs, ys, masks, &mut grads);
        let mut p: Vec<f64> = cnn.params.iter().map(|&v| v as f64).collect();
        assert!((loss as f64 - ref_loss(cnn, &p, xs, ys, masks)).abs() < 1e-5);
        let h = 1e-4;
        for g in 0..GROUPS {
            let range = cnn.shape.offsets[g]..cnn.shape.offsets[g + 1];
            let largest = grads[range.clone()]
                .iter()
                .fold(0.0f32, |m, v| m.max(v.abs()));
            assert!(largest > 1e-4, "group {g} has no gradient to check");
            for i in range {
                let saved = p[i];
                p[i] = saved + h;
                let up = ref_loss(cnn, &p, xs, ys, masks);
                p[i] = saved - h;
                let down = ref_loss(cnn, &p, xs, ys, masks);
                p[i] = saved;
                let numeric = (up - down) / (2.0 * h);
                let analytic = grads[i] as f64;
                let error =
                    (analytic - numeric).abs() / analytic.abs().max(numeric.abs()).max(1e-3);
                assert!(
                    error < 1e-2,
                    "group {g} parameter {i}: analytic {analytic}, numeric {numeric}"
                );
            }
        }
    }

    #[test]
    fn gradients_match_finite_differences() {
        // 6x6 -> pool 3x3 -> pool 1x1 (the odd row and column dropped).
        let mut cnn = Cnn::new(CnnConfig {
            seed: 3,
            ..tiny(6, 6, 2)
        });
        let mut rng = SplitMix64::new(11);
        let p = cnn.parameters_mut();
        for b in [p.conv1_bias, p.conv2_bias, p.dense_bias, p.output_bias] {
            for v in b.iter_mut() {
                *v = rng.range_f32(0.05, 0.3);
            }
        }
        let (xs, ys) = random_examples(&cnn, 3, 12);
        let ys: Vec<&[bool]> = ys.iter().map(|y| y.as_slice()).collect();
        check_gradient(&cnn, &refs(&xs), &ys, None);
        // With dropout: unit 1 of example 0 and unit 2 of example 2 dropped, the rest scaled.
        let mut masks = vec![2.0f32; 3 * 4];
        masks[1] = 0.0;
        masks[2 * 4 + 2] = 0.0;
        check_gradient(&cnn, &refs(&xs), &ys, Some(&masks));
    }
}
