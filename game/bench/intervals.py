"""How sure a ratio is: a bootstrap 95 % interval over interleaved rounds.

Where it sits: under :mod:`game.bench.targets` and the charts that print a ratio. A module
times two methods in the same rounds (:func:`game.bench.timing.interleaved`) and hands the
two lists of per-round times to :func:`paired_ratio`.

What it teaches:
  * **A ratio from a handful of rounds is a coin toss.** On a shared machine one round can
    be twice as slow as the next; a verdict taken from three rounds flips from run to run.
    Here every ratio comes from many rounds (30 or more for a target) and carries an
    interval that says how far it could plausibly move.
  * **Ratios round by round.** An interleaved round times both methods one right after
    the other, under the same load: that is the point of interleaving. So the ratio is
    taken within each round, ``a[k] / b[k]``, where a slow patch of the machine mostly
    cancels, and the estimate is the median of those per-round ratios.
  * **The bootstrap.** Draw as many per-round ratios as were measured, with replacement,
    and take their median; do that a few thousand times; the middle 95 % of those medians
    is the interval.
  * **A verdict that holds** passes only when the *whole* interval clears the limit; a
    ratio whose interval straddles the limit is not yet known to meet it, and fails.
  * The draws come from a seeded generator, so the same measurements always give the same
    interval.

>>> slow, fast = [10.0, 11.0, 12.0, 10.5] * 8, [1.0, 1.1, 1.2, 1.05] * 8
>>> r = paired_ratio(slow, fast)
>>> round(r.estimate, 6), r.low <= r.estimate <= r.high, r.clears(">=", 9.0)
(10.0, True, True)
>>> Interval(1.4, 1.2, 1.6).clears("<=", 1.5)     # the median is inside, the interval is not
False
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

CONFIDENCE = 0.95
RESAMPLES = 4000
SEED = 13


@dataclass(frozen=True)
class Interval:
    """A measured figure and its bootstrap interval, ``low <= estimate <= high``."""

    estimate: float
    low: float
    high: float

    @classmethod
    def exact(cls, value: float) -> Interval:
        """A figure with no sampling error (a count, a distance that is computed)."""
        return cls(value, value, value)

    def clears(self, comparison: str, limit: float) -> bool:
        """Does the whole interval lie on the right side of ``limit``?"""
        if comparison == ">=":
            return self.low >= limit
        if comparison == "<=":
            return self.high <= limit
        raise ValueError(f"a comparison is '>=' or '<=', not {comparison!r}")

    def text(self, digits: int = 3) -> str:
        """``"12.3 [11.8, 12.9]"``; an exact figure prints alone."""
        def figure(value: float) -> str:
            return f"{value:#.{digits}g}".rstrip(".")

        if self.low == self.high == self.estimate:
            return figure(self.estimate)
        return f"{figure(self.estimate)} [{figure(self.low)}, {figure(self.high)}]"


def _rounds(first: Sequence[float], second: Sequence[float]) -> tuple[np.ndarray, np.ndarray]:
    a, b = np.asarray(first, dtype=float), np.asarray(second, dtype=float)
    if a.shape != b.shape or a.ndim != 1 or len(a) == 0:
        raise ValueError(f"need two equally long, non-empty lists of rounds, got {len(a)} "
                         f"and {len(b)}")
    return a, b


def median_interval(samples: Sequence[float] | np.ndarray, resamples: int = RESAMPLES,
                    seed: int = SEED) -> Interval:
    """The median of one list of figures with its bootstrap interval."""
    figures = np.asarray(samples, dtype=float)
    if figures.ndim != 1 or len(figures) == 0:
        raise ValueError("need a non-empty list of figures")
    draws = np.random.default_rng(seed).integers(0, len(figures),
                                                 size=(resamples, len(figures)))
    medians = np.median(figures[draws], axis=1)
    tail = (1 - CONFIDENCE) / 2 * 100
    low, high = np.percentile(medians, [tail, 100 - tail])
    estimate = float(np.median(figures))
    return Interval(estimate, min(float(low), estimate), max(float(high), estimate))


def paired_ratio(numerator: Sequence[float], denominator: Sequence[float],
                 resamples: int = RESAMPLES, seed: int = SEED) -> Interval:
    """The median over the rounds of ``numerator[k] / denominator[k]``, with its interval.

    Both lists hold one figure per round, round ``k`` of each measured together.
    """
    top, bottom = _rounds(numerator, denominator)
    return median_interval(top / bottom, resamples, seed)


def paired_difference(first: Sequence[float], second: Sequence[float],
                      resamples: int = RESAMPLES, seed: int = SEED) -> Interval:
    """The median over the rounds of ``first[k] - second[k]``, with its interval: for costs
    so small that a ratio would divide by noise."""
    a, b = _rounds(first, second)
    return median_interval(a - b, resamples, seed)
