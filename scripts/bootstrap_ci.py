"""The 95% percentile-bootstrap interval that the experiment scripts print beside a mean
(scripts/experiment_by_target.py, scripts/h2_readings.py): 2000 resamples of the values with a
fixed seed, so the same records always print the same interval (as src/experiment/interval.rs).
"""
import random


def ci(values, digits=2):
    """` [lo, hi]` of the mean of `values`, or "" for fewer than two values."""
    if len(values) < 2:
        return ""
    rng = random.Random(0x424F4F54)
    means = sorted(sum(rng.choice(values) for _ in values) / len(values) for _ in range(2000))
    lo, hi = means[int(0.025 * 1999)], means[-1 - int(0.025 * 1999)]
    return f" [{lo:.{digits}f}, {hi:.{digits}f}]"


def cell(values, digits=2):
    """The mean of `values` with its interval, or "n/a" when there are none."""
    return f"{sum(values) / len(values):.{digits}f}{ci(values, digits)}" if values else "n/a"
