//! The seeded pseudo-random generator every randomized layer draws from (SplitMix64): `sim`
//! (scenes, noise, action outcomes) and `learn` (states, data splits, tie-breaks).
//!
//! Invariant: the same seed yields the same stream on every platform and thread count; a layer
//! derives one generator per purpose with [`SplitMix64::fork`], so adding draws for one purpose
//! never shifts another. The two shuffles are kept apart because each layer's recorded results
//! (scene files, H1 figures) were produced with its own: `shuffle` draws indices by
//! multiply-shift, `shuffle_modulo` by remainder.

use serde::{Deserialize, Serialize};

/// SplitMix64 (Steele, Lea and Flood 2014): one 64-bit state word, full period, good mixing.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct SplitMix64 {
    /// The state word, advanced by the golden-ratio increment on every draw.
    state: u64,
}

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// An independent generator for a numbered purpose.
    pub fn fork(&self, purpose: u64) -> Self {
        let mut mixer = SplitMix64::new(self.state ^ purpose.wrapping_mul(0xD1B5_4A32_D192_ED03));
        SplitMix64::new(mixer.next_u64())
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform float in `[0, 1)` built from the top 53 bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform float in `[lo, hi)`.
    pub fn range_f32(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f64() as f32
    }

    /// A uniform integer in `[lo, hi]` by remainder; panics if `lo > hi`, which is API misuse.
    pub fn range_usize(&mut self, lo: usize, hi: usize) -> usize {
        assert!(lo <= hi, "range_usize needs lo <= hi, got {lo} > {hi}");
        let span = (hi - lo) as u64 + 1;
        lo + (self.next_u64() % span) as usize
    }

    /// A uniform integer in `[0, n)` by multiply-shift; panics if `n == 0`, which is API misuse.
    pub fn below(&mut self, n: u64) -> u64 {
        assert!(n > 0, "below(0) has no value");
        // Lemire's multiply-shift: unbiased enough for n far below 2^64.
        ((self.next_u64() as u128 * n as u128) >> 64) as u64
    }

    /// True with probability `p`.
    pub fn chance(&mut self, p: f64) -> bool {
        self.next_f64() < p
    }

    /// A uniformly chosen element; panics on an empty slice.
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len() as u64) as usize]
    }

    /// Shuffles a slice in place (Fisher-Yates, indices by [`SplitMix64::below`]).
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.below(i as u64 + 1) as usize;
            items.swap(i, j);
        }
    }

    /// Shuffles a slice in place (Fisher-Yates, indices by [`SplitMix64::range_usize`]).
    pub fn shuffle_modulo<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.range_usize(0, i);
            items.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first outputs of seed 0 under the published definition (Vigna's splitmix64.c),
    /// computed apart from this code with Python's integers masked to 64 bits:
    /// `s = (s + 0x9E3779B97F4A7C15) & M; z = s; z = ((z ^ z >> 30) * 0xBF58476D1CE4E5B9) & M;
    /// z = ((z ^ z >> 27) * 0x94D049BB133111EB) & M; z ^ z >> 31` with `M = 2**64 - 1`.
    #[test]
    fn reference_stream() {
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(r.next_u64(), 0x06C4_5D18_8009_454F);
    }

    #[test]
    fn same_seed_same_stream_and_forks_differ() {
        let mut a = SplitMix64::new(42);
        let mut b = SplitMix64::new(42);
        for _ in 0..100 {
            assert_eq!(a.next_u64(), b.next_u64());
        }
        let mut f1 = a.fork(1);
        let mut f2 = a.fork(2);
        assert_ne!(f1.next_u64(), f2.next_u64());
        let mut counts = [0u32; 3];
        for _ in 0..3000 {
            counts[a.below(3) as usize] += 1;
        }
        assert!(counts.iter().all(|&c| c > 900), "{counts:?}");
    }

    #[test]
    fn ranges_hold() {
        let mut r = SplitMix64::new(7);
        for _ in 0..1000 {
            let x = r.next_f64();
            assert!((0.0..1.0).contains(&x));
            let k = r.range_usize(3, 5);
            assert!((3..=5).contains(&k));
        }
    }
}
