//! 95% intervals for the report's figures: the percentile bootstrap over the units a figure
//! averages (H2's pairs, H4's questions, H1's learning runs), with a fixed seed.
//!
//! Method: draw [`RESAMPLES`] samples of the units with replacement (as many as there are),
//! compute the statistic on each, sort, and take the 2.5th and 97.5th percentiles (the values
//! at ranks `floor(0.025 (B - 1))` and `ceil(0.975 (B - 1))`). A resample whose statistic is
//! undefined (e.g. no pair with a plan) is skipped.
//!
//! Invariants: the interval is a pure function of the units in the order given (the callers pass
//! records sorted by id, then seed) and of [`SEED`]; no clock, no thread count enters it, so an
//! in-process run, a resumed run and a merge of job outputs print the same intervals. Fewer
//! than two units give no interval (`None`, printed as no bracket).

use serde::{Deserialize, Serialize};

use crate::base::rng::SplitMix64;

/// Bootstrap resamples per interval.
pub const RESAMPLES: usize = 2_000;

/// The bootstrap's fixed seed.
pub const SEED: u64 = 0x0042_4f4f_5453_5452;

/// A 95% interval.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Interval {
    /// The 2.5th percentile.
    pub lo: f64,
    /// The 97.5th percentile.
    pub hi: f64,
}

/// The percentile bootstrap interval of `stat` over `units`.
pub fn bootstrap<T>(units: &[T], stat: impl Fn(&[&T]) -> Option<f64>) -> Option<Interval> {
    let n = units.len();
    if n < 2 {
        return None;
    }
    let mut rng = SplitMix64::new(SEED);
    let mut values = Vec::with_capacity(RESAMPLES);
    let mut sample: Vec<&T> = Vec::with_capacity(n);
    for _ in 0..RESAMPLES {
        sample.clear();
        sample.extend((0..n).map(|_| &units[rng.below(n as u64) as usize]));
        if let Some(v) = stat(&sample) {
            values.push(v);
        }
    }
    if values.is_empty() {
        return None;
    }
    values.sort_by(f64::total_cmp);
    let last = (values.len() - 1) as f64;
    Some(Interval {
        lo: values[(0.025 * last).floor() as usize],
        hi: values[(0.975 * last).ceil() as usize],
    })
}

/// The interval of the mean of `values`.
pub fn mean(values: &[f64]) -> Option<Interval> {
    bootstrap(values, |s| {
        (!s.is_empty()).then(|| s.iter().copied().sum::<f64>() / s.len() as f64)
    })
}

/// `v [lo, hi]` with `digits` decimals; `n/a` without a value, no bracket without an interval.
pub fn cell(v: Option<f64>, i: Option<Interval>, digits: usize) -> String {
    match (v, i) {
        (None, _) => "n/a".into(),
        (Some(v), None) => format!("{v:.digits$}"),
        (Some(v), Some(i)) => format!("{v:.digits$} [{:.digits$}, {:.digits$}]", i.lo, i.hi),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constant_data_give_a_point_and_spread_data_cover_the_mean() {
        assert_eq!(
            mean(&[2.0; 10]),
            Some(Interval { lo: 2.0, hi: 2.0 }),
            "every resample of a constant has the same mean"
        );
        assert_eq!(mean(&[1.0]), None, "one unit has no interval");
        // Half zeros, half ones: the mean 0.5 lies inside, and the interval is roughly
        // 0.5 +- 1.96 * sqrt(0.25 / 40) = 0.5 +- 0.155.
        let v: Vec<f64> = (0..40).map(|k| (k % 2) as f64).collect();
        let i = mean(&v).unwrap();
        assert!(i.lo < 0.5 && 0.5 < i.hi, "{i:?}");
        assert!(
            (0.3..0.4).contains(&i.lo) && (0.6..0.7).contains(&i.hi),
            "{i:?}"
        );
        assert_eq!(mean(&v), Some(i), "a fixed seed: the same interval again");
    }

    #[test]
    fn cells_print_value_and_bracket() {
        let i = Interval { lo: 0.1, hi: 0.25 };
        assert_eq!(cell(Some(0.2), Some(i), 2), "0.20 [0.10, 0.25]");
        assert_eq!(cell(Some(0.2), None, 1), "0.2");
        assert_eq!(cell(None, Some(i), 2), "n/a");
    }
}
