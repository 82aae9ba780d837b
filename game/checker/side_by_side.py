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
* **One Ctrl-C, one SIGTERM.** The workers ignore Ctrl-C; the parent stops them all at
  once, and on SIGTERM (what ``kill`` and service managers send) it does the same, so no
  worker searches on after the command has ended. While the pool is being built, both are
  held back (:func:`signal.pthread_sigmask`) and land the moment the pool is whole. Landing
  earlier, Ctrl-C was lost inside a fork's own clean-up, or it left a half-built pool whose
  thread that replaces lost workers went on starting new ones as the command ended: they
  waited for work for ever, holding its output open.
* **A worker that dies.** A pool whose worker is killed (by the out-of-memory killer, say)
  waits for ever for the map that worker held. So each worker notes, in memory shared
  with the parent, which map it has started, and the parent, between results, looks at
  its children: when one has gone, the map it held is reported with a sentence, the pool
  (whose queues the death may have left locked) is ended, and the maps not yet reported
  are checked by a new one.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import multiprocessing.pool
import multiprocessing.sharedctypes
import os
import signal
from collections.abc import Generator, Iterator
from pathlib import Path
from types import FrameType
from typing import Any

from game.checker.checking import MapReport, Options, check_map

POLL_S = 0.2  # how often the parent looks for a worker that died, while it waits
MAX_NEW_POOLS = 8  # pools started after deaths no map explains; then one map at a time
FIX_DIED = ("check this map alone (--jobs 1) to see where it stops; if it is killed again, "
            "make it smaller")


class Terminated(BaseException):
    """SIGTERM arrived: the command stops, its workers with it (exit status 143)."""


def usable_cores() -> int:
    """The cores this process may run on (the default number of maps checked at once)."""
    if hasattr(os, "sched_getaffinity"):
        return max(1, len(os.sched_getaffinity(0)))
    return max(1, os.cpu_count() or 1)


def _worker_signals() -> None:
    """In a worker: Ctrl-C is the parent's to handle; SIGTERM ends the worker at once (the
    worker was forked with it held back, and with the parent's handler)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGTERM})


def _terminated(_signal: int, _frame: FrameType | None) -> None:
    raise Terminated


@contextlib.contextmanager
def _stopped_by_sigterm() -> Iterator[None]:
    """In the block, SIGTERM raises :class:`Terminated`, which ends the pool's workers."""
    try:
        previous = signal.signal(signal.SIGTERM, _terminated)
    except ValueError:  # not the main thread: signals are not ours to handle
        yield
        return
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)


@contextlib.contextmanager
def _ctrl_c_held() -> Iterator[None]:
    """Hold Ctrl-C and SIGTERM back for the block, then let one that came meanwhile arrive."""
    if not hasattr(signal, "pthread_sigmask"):  # Windows: workers are spawned, not forked
        yield
        return
    before = signal.pthread_sigmask(signal.SIG_BLOCK, {signal.SIGINT, signal.SIGTERM})
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, before)


def _started_pool(jobs: int) -> multiprocessing.pool.Pool:
    """A pool of ``jobs`` workers that ignore Ctrl-C, all started before Ctrl-C can land."""
    with _ctrl_c_held():
        return multiprocessing.Pool(jobs, initializer=_worker_signals)


# Which process started each map (0: none yet). Made before the pool's workers are forked,
# who inherit it; each writes only the slots of its own maps, so it needs no lock.
_started_by: Any = None


def _check(job: tuple[int, Path, Options]) -> tuple[int, MapReport]:
    index, path, options = job
    if _started_by is not None and index < len(_started_by):
        _started_by[index] = os.getpid()
    return index, check_map(path, options)


def _size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:
        return 0


def _died(path: Path, exitcode: int | None) -> MapReport:
    """The report of a map whose worker died while checking it."""
    how = (f"was killed by signal {-exitcode}" if exitcode is not None and exitcode < 0
           else f"ended with status {exitcode}")
    report = MapReport(path)
    report.add("error", "", f"the process checking this map {how} (for want of memory, "
               "perhaps) before it was done", FIX_DIED)
    return report


def _next(results: multiprocessing.pool.IMapIterator[tuple[int, MapReport]],
          timeout: float) -> tuple[int, MapReport]:
    """The next result, waiting at most ``timeout`` seconds; multiprocessing.TimeoutError
    when none came in time, StopIteration when there are no more."""
    return results.next(timeout)


def _run_pool(indexes: list[int], paths: list[Path], options: Options, jobs: int,
              started_by: Any) -> Generator[tuple[int, MapReport] | None, None, None]:
    """Check the maps at ``indexes`` in one pool, biggest first; yield each result as it
    comes, a died map's report as soon as its death is seen, and None (then stop) when a
    worker died: the maps not yet yielded need a new pool."""
    biggest_first = sorted(indexes, key=lambda index: -_size(paths[index]))
    for index in indexes:
        started_by[index] = 0
    with _started_pool(jobs) as pool:
        results = pool.imap_unordered(_check, [(index, paths[index], options)
                                               for index in biggest_first])
        if not isinstance(results, multiprocessing.pool.IMapIterator):
            yield from results  # a pool that runs its jobs in this process
            return
        pending = set(indexes)
        workers = {child.pid: child for child in multiprocessing.active_children()}
        while pending:
            try:
                index, report = _next(results, POLL_S)
            except StopIteration:
                return
            except multiprocessing.TimeoutError:
                gone = [child for pid, child in workers.items()
                        if pid is not None and child.exitcode is not None]
                workers.update((child.pid, child) for child in
                               multiprocessing.active_children())
                if not gone:
                    continue
                for index, report in _arrived(results):  # sent before the death
                    pending.discard(index)
                    yield index, report
                for child in gone:
                    for index in [i for i in pending if started_by[i] == child.pid]:
                        pending.discard(index)
                        yield index, _died(paths[index], child.exitcode)
                yield None
                return
            if index in pending:
                pending.discard(index)
                yield index, report


def _arrived(results: multiprocessing.pool.IMapIterator[tuple[int, MapReport]]
             ) -> Iterator[tuple[int, MapReport]]:
    """The results already back, without waiting for more."""
    while True:
        try:
            yield _next(results, 0)
        except (multiprocessing.TimeoutError, StopIteration):
            return


def check_maps(paths: list[Path], options: Options, jobs: int
               ) -> Generator[MapReport, None, None]:
    """Check ``paths``, up to ``jobs`` at once (never more than there are cores), and
    yield their reports in their order."""
    global _started_by
    jobs = min(jobs, usable_cores(), len(paths))
    if jobs <= 1:
        for path in paths:
            yield check_map(path, options)
        return
    waiting: dict[int, MapReport] = {}  # reports back, held until those before are out
    printed = 0
    left = list(range(len(paths)))
    _started_by = multiprocessing.sharedctypes.RawArray("q", len(paths))
    try:
        with _stopped_by_sigterm():
            for _pool in range(MAX_NEW_POOLS + 1):
                with contextlib.closing(_run_pool(left, paths, options, min(jobs, len(left)),
                                                  _started_by)) as results:
                    for result in results:
                        if result is None:  # a worker died: a new pool for the rest
                            break
                        waiting[result[0]] = result[1]
                        while printed in waiting:
                            yield waiting.pop(printed)
                            printed += 1
                left = [index for index in range(printed, len(paths))
                        if index not in waiting]
                if not left:
                    return
            for index in left:  # workers die and no map explains it: here, one at a time
                waiting[index] = check_map(paths[index], options)
                while printed in waiting:
                    yield waiting.pop(printed)
                    printed += 1
    finally:
        _started_by = None
