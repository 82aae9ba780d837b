"""Fair timing: every method measured in the same rounds, the collector off, medians reported.

Where it sits: under every bench module. A module hands :func:`interleaved` a list of
:class:`Case` objects (one per method, or per method and size) and gets back, for each, one
time per round.

What it teaches:
  * **Interleave, do not batch.** Timing method A for ten seconds and then method B for ten
    seconds lets a background job, a CPU that warms up or a laptop that throttles favour
    one of them. Here each *round* times every case once, one after the other, so whatever
    the machine is doing hits them all alike; the starting case rotates from round to round
    so none is always first.
  * **Medians, not means.** One round spoiled by another process is an outlier; the median
    of the rounds ignores it, the mean does not.
  * **Count the CPU time, not the wall clock.** On a machine shared with other busy
    processes, a stretch of wall-clock time includes the slices the scheduler gave to
    them, and a long case is interrupted more often than a short one, which skews every
    ratio between them. :func:`clock` is the CPU time of this thread: what the case
    itself cost.
  * **The garbage collector is off while timing.** A collection can start inside any case and
    bill it for garbage others made. :func:`collector_off` collects once, then disables it.
  * **Time enough work.** The clock resolves well under a microsecond, but a single
    ``colliderect`` takes tens of nanoseconds, so each case runs as many times as fit in
    ``min_s`` (calibrated once, then fixed for every round) and the time is divided down to
    one operation.

>>> from statistics import median
>>> times = interleaved([Case("sum", lambda: sum(range(100)), ops=100)], rounds=3, min_s=1e-4)
>>> len(times["sum"]), median(times["sum"]) > 0
(3, True)
>>> percentile([1.0, 2.0, 3.0, 4.0, 5.0], 50)
3.0
"""

from __future__ import annotations

import gc
import math
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from time import thread_time

clock = thread_time
"""The bench's clock: this thread's CPU time in seconds (``clock_gettime`` with
``CLOCK_THREAD_CPUTIME_ID``, nanosecond resolution, about 0.5 µs a call)."""


@dataclass(frozen=True)
class Case:
    """One thing to time: ``run()`` performs ``ops`` operations (times are per operation)."""

    name: str
    run: Callable[[], object]
    ops: int = 1


@contextmanager
def collector_off() -> Iterator[None]:
    """Collect the garbage now, then keep the collector off until the block ends."""
    was_enabled = gc.isenabled()
    gc.collect()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def calibrate(run: Callable[[], object], min_s: float) -> int:
    """How many calls of ``run`` take at least ``min_s`` (doubling from one; at least one)."""
    loops = 1
    while True:
        started = clock()
        for _ in range(loops):
            run()
        if clock() - started >= min_s:
            return loops
        loops *= 2


def interleaved(cases: Sequence[Case], rounds: int, min_s: float = 0.002,
                ) -> dict[str, list[float]]:
    """Seconds per operation for every case, one figure per round, all rounds interleaved."""
    if len({case.name for case in cases}) != len(cases):
        raise ValueError("every case needs its own name")
    times: dict[str, list[float]] = {case.name: [] for case in cases}
    with collector_off():
        loops = {case.name: calibrate(case.run, min_s) for case in cases}
        for round_no in range(rounds):
            shift = round_no % len(cases) if cases else 0
            for case in [*cases[shift:], *cases[:shift]]:
                run, n = case.run, loops[case.name]
                started = clock()
                for _ in range(n):
                    run()
                elapsed = clock() - started
                times[case.name].append(elapsed / (n * case.ops))
    return times


def percentile(values: Sequence[float], q: float) -> float:
    """The ``q``-th percentile (0-100) by linear interpolation between the sorted values."""
    if not values:
        raise ValueError("no values to take a percentile of")
    ordered = sorted(values)
    rank = (len(ordered) - 1) * q / 100
    low, high = math.floor(rank), math.ceil(rank)
    return ordered[low] + (ordered[high] - ordered[low]) * (rank - low)
