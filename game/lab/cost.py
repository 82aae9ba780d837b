"""Live cost: the time one collision test takes, measured inside the scene that shows it.

Where it sits: beside :mod:`game.lab.scene`; a scene times what it teaches with a
:class:`CostMeter` every frame, and the testbed prints each figure with its spread and draws
its recent history (:meth:`CostMeter.history`).

What it teaches: **measure, side by side, on the machine in front of you, and show the
spread.** A figure in a book was true on someone else's computer. Here each test is called a
few dozen times in a row with ``time.perf_counter_ns`` around the batch (one call is too short
to time on its own), and the last :data:`WINDOW` batches are kept. The panel gives their
median, which one slow frame does not move, and the 10th to 90th percentile, which says how
far the figure wanders; the little graph shows every batch of the window. The counts of tests
made are exact; the times are measurements and move from frame to frame.
"""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Callable, Sequence

REPEATS = 32  # calls per measurement: enough to rise above the clock's resolution
WINDOW = 120  # measurements kept: the last two seconds at 60 frames a second
LOW, HIGH = 0.10, 0.90  # the spread shown: the 10th to the 90th percentile


def format_ns(ns: float) -> str:
    """A duration in the unit that reads best.

    >>> format_ns(640), format_ns(22_400), format_ns(3_100_000)
    ('640 ns', '22.4 us', '3.10 ms')
    """
    if ns < 1_000:
        return f"{ns:.0f} ns"
    if ns < 1_000_000:
        return f"{ns / 1_000:.1f} us"
    return f"{ns / 1_000_000:.2f} ms"


def percentile(ordered: Sequence[float], share: float) -> float:
    """The value ``share`` of the way up ``ordered`` (sorted), by the nearest rank below.

    >>> percentile([1.0, 2.0, 3.0, 4.0, 5.0], 0.5), percentile([1.0, 2.0, 3.0], 0.9)
    (3.0, 2.0)
    """
    return ordered[int(share * (len(ordered) - 1))]


class CostMeter:
    """The last :data:`WINDOW` measurements of nanoseconds per test, by label, in the order
    the labels were first timed."""

    def __init__(self, repeats: int = REPEATS, window: int = WINDOW) -> None:
        self.repeats = repeats
        self.window = window
        self.samples: dict[str, deque[float]] = {}

    def time(self, label: str, call: Callable[[], object], per: int = 1) -> float:
        """Run ``call`` :attr:`repeats` times; record and return the time per test (``per``
        tests a call)."""
        start = time.perf_counter_ns()
        for _ in range(self.repeats):
            call()
        elapsed = (time.perf_counter_ns() - start) / (self.repeats * max(1, per))
        self.samples.setdefault(label, deque(maxlen=self.window)).append(elapsed)
        return elapsed

    def labels(self) -> list[str]:
        return list(self.samples)

    def history(self, label: str) -> list[float]:
        """The measurements of ``label`` in the window, oldest first."""
        return list(self.samples.get(label, ()))

    def median(self, label: str) -> float:
        """The median of the window (0 before the first measurement)."""
        ordered = sorted(self.samples.get(label, ()))
        return percentile(ordered, 0.5) if ordered else 0.0

    def spread(self, label: str) -> tuple[float, float]:
        """The 10th and 90th percentiles of the window."""
        ordered = sorted(self.samples.get(label, ()))
        return (percentile(ordered, LOW), percentile(ordered, HIGH)) if ordered else (0.0, 0.0)

    def times(self, slow: str, fast: str) -> str:
        """How many times ``fast``'s median ``slow``'s is, in words (from the windows).

        >>> meter = CostMeter()
        >>> meter.samples = {"a": deque([300.0]), "b": deque([100.0])}
        >>> meter.times("a", "b"), meter.times("b", "a")
        ('3.0x', '0.33x')
        """
        fast_ns = self.median(fast)
        if fast_ns <= 0:
            return "-"
        ratio = self.median(slow) / fast_ns
        return f"{ratio:.1f}x" if ratio >= 1 else f"{ratio:.2f}x"

    def text(self, label: str) -> str:
        """``label: median (p10 to p90)``, ready to print ("-" before the first
        measurement)."""
        if label not in self.samples:
            return f"{label}: -"
        low, high = self.spread(label)
        return (f"{label}: {format_ns(self.median(label))}"
                f" ({format_ns(low)} to {format_ns(high)})")
