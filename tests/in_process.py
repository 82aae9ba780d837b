"""A command's ``main`` called in the test's own process: a quicker stand-in for starting it
as a program (each start loads pygame and pytmx again), for tests where nothing they check
depends on being a separate process.

What the command prints goes through UTF-8 text streams, as it would through a pipe, so a
line it could not encode fails here as it would fail there. An exception escaping ``main``
fails the test: as a program, that would have been a traceback. A usage error (argparse's
``SystemExit``) becomes the exit status the program would have ended with. Where a command
could wait for ever (a pipe named as a map), ``hang_s`` stops it the way a timeout stops a
program: with an error no ``except Exception`` in the command can turn into a sentence.
Several maps are checked with ``--jobs 1``: a worker forked from the test run, whose other
threads (pygame starts some) may hold a lock at that moment, can wait on it for ever;
``tests/test_side_by_side.py`` shows that one job prints what several print.

Signals, the interpreter's start-up, an installed wheel, the environment read when pygame
loads and the exit status of the real entry point still need the program itself; every
command keeps tests that start it (``tests/test_cli.py``, ``tests/test_levels.py``,
``tests/test_lab.py``).
"""

from __future__ import annotations

import contextlib
import io
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

import pytest

from tests.hang_guard import hang_guard


class Hung(BaseException):
    """A command still running after its ``hang_s``: it waits for something that never comes."""


@dataclass(frozen=True)
class Ran:
    """What a command did: named as :class:`subprocess.CompletedProcess` names it."""

    returncode: int
    stdout: str
    stderr: str


def call_main(main: Callable[[list[str]], int], args: Sequence[str | Path],
              cwd: Path | None = None, hang_s: float | None = None) -> Ran:
    """``main(args)`` run in ``cwd`` (if given): its exit status and what it printed."""
    out, err = _pipe(), _pipe()
    with pytest.MonkeyPatch.context() as patch, contextlib.redirect_stdout(out), \
            contextlib.redirect_stderr(err), _stopped_after(hang_s):
        if cwd is not None:
            patch.chdir(cwd)
        try:
            status = main([str(arg) for arg in args])
        except SystemExit as leaving:
            code = leaving.code
            status = 0 if code is None else code if isinstance(code, int) else 1
    return Ran(status, _read(out), _read(err))


@contextlib.contextmanager
def _stopped_after(seconds: float | None) -> Iterator[None]:
    if seconds is None:
        yield
        return
    with hang_guard(seconds, Hung):
        yield


def _pipe() -> io.TextIOWrapper:
    return io.TextIOWrapper(io.BytesIO(), encoding="utf-8", newline="")


def _read(stream: io.TextIOWrapper) -> str:
    stream.flush()
    buffer = stream.buffer
    assert isinstance(buffer, io.BytesIO)
    return buffer.getvalue().decode("utf-8")
