"""A guard against a hang: fail a test that is still running after a generous time, instead
of hanging the whole run.

It asserts no speed (speed is the bench's to measure, as ratios): a limit of half a minute
for something that takes milliseconds only ever catches a loop that does not end.
"""

from __future__ import annotations

import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager

HANG_S = 30.0


@contextmanager
def hang_guard(seconds: float = HANG_S,
               error: Callable[[str], BaseException] = TimeoutError) -> Iterator[None]:
    """Raise ``error`` in the code still running after ``seconds``."""
    def expire(_signal: int, _frame: object) -> None:
        raise error(f"still running after {seconds} s: it hangs")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
