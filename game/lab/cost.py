"""Live cost: the time one collision test takes, measured inside the scene that shows it.

Where it sits: beside :mod:`game.lab.scene`; scenes that set a cheaper method next to an
exact one time both with a :class:`CostMeter` every frame and print the figures.

What it teaches: **measure, side by side, on the machine in front of you.** A figure in a
book was true on someone else's computer. Here each test is called a few dozen times in a
row with ``time.perf_counter_ns`` around the batch (one call is too short to time on its
own), and the figure is smoothed over frames so it can be read. The counts of tests made are
exact; the times are estimates and move a little from frame to frame.
"""

from __future__ import annotations

import time
from collections.abc import Callable

REPEATS = 32  # calls per measurement: enough to rise above the clock's resolution
SMOOTHING = 0.1  # weight of the newest measurement in the running average


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


class CostMeter:
    """Smoothed nanoseconds per call, by label."""

    def __init__(self, repeats: int = REPEATS) -> None:
        self.repeats = repeats
        self.ns: dict[str, float] = {}

    def time(self, label: str, call: Callable[[], object], per: int = 1) -> float:
        """Run ``call`` :attr:`repeats` times; record the time per test (``per`` tests a call)."""
        start = time.perf_counter_ns()
        for _ in range(self.repeats):
            call()
        elapsed = (time.perf_counter_ns() - start) / (self.repeats * max(1, per))
        old = self.ns.get(label)
        self.ns[label] = elapsed if old is None else old + SMOOTHING * (elapsed - old)
        return self.ns[label]

    def text(self, label: str) -> str:
        """The figure for ``label``, ready to print ("-" before the first measurement)."""
        return format_ns(self.ns[label]) if label in self.ns else "-"
