"""Check several maps side by side, one process per core, and give the reports back in order.

Where it sits: ``python -m game.levels check`` hands it the maps to check and prints each
report as it comes back. Each map's check is independent and deterministic (its search is
bounded by work, not by seconds), so checking maps side by side changes nothing but the
wall time: the same lines come out, in the same order, as when they are checked one at a
time (``--jobs 1``). It never runs more processes than there are cores.

What it teaches: a process pool from the standard library (:class:`multiprocessing.pool.Pool`)
used with care:

* **Longest first.** The pool starts the biggest maps first (a map's file size stands for
  its cost), so a long search does not start last and leave a core idle.
* **In order.** Reports arrive in any order; each is held until every map before it has
  been printed.
* **One Ctrl-C.** The workers ignore Ctrl-C; the parent stops them all at once. While the
  pool is being built, Ctrl-C is held back (:func:`signal.pthread_sigmask`) and lands the
  moment the pool is whole. Landing earlier, it was lost inside a fork's own clean-up, or
  it left a half-built pool whose thread that replaces lost workers went on starting new
  ones as the command ended: they waited for work for ever, holding its output open.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import multiprocessing.pool
import os
import signal
from collections.abc import Iterator
from pathlib import Path

from game.levels.checking import MapReport, Options, check_map


def usable_cores() -> int:
    """The cores this process may run on (the default number of maps checked at once)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def _ignore_ctrl_c() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


@contextlib.contextmanager
def _ctrl_c_held() -> Iterator[None]:
    """Hold Ctrl-C back for the block, then let one that came meanwhile arrive."""
    if not hasattr(signal, "pthread_sigmask"):  # Windows: workers are spawned, not forked
        yield
        return
    before = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, before)


def _started_pool(jobs: int) -> multiprocessing.pool.Pool:
    """A pool of ``jobs`` workers that ignore Ctrl-C, all started before Ctrl-C can land."""
    with _ctrl_c_held():
        return multiprocessing.Pool(jobs, initializer=_ignore_ctrl_c)


def _check(job: tuple[int, Path, Options]) -> tuple[int, MapReport]:
    index, path, options = job
    return index, check_map(path, options)


def _size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:
        return 0


def check_maps(paths: list[Path], options: Options, jobs: int) -> Iterator[MapReport]:
    """Check ``paths``, up to ``jobs`` at once (never more than there are cores), and
    yield their reports in their order."""
    jobs = min(jobs, usable_cores(), len(paths))
    if jobs <= 1:
        for path in paths:
            yield check_map(path, options)
        return
    biggest_first = sorted(range(len(paths)), key=lambda index: -_size(paths[index]))
    waiting: dict[int, MapReport] = {}
    printed = 0
    with _started_pool(jobs) as pool:
        for index, report in pool.imap_unordered(
                _check, [(index, paths[index], options) for index in biggest_first]):
            waiting[index] = report
            while printed in waiting:
                yield waiting.pop(printed)
                printed += 1
