"""Print to an output that may be closed or full, and end quietly when it is.

Where it sits: every line ``python -m game.levels`` and ``python -m game.lab --list`` print
goes through :func:`say`; the app's, the bench's and the stress scene's commands start
through :func:`game.app.arguments.run_command`, and the asset tools from their ``__main__``
blocks, both of which call :func:`quiet_when_output_closes`, which guards every ``print``.
A reader of the output may stop reading early (``check levels | head -1``) or the output may
be a full disk (``> /dev/full``); either way a write fails, with :class:`BrokenPipeError` or
:class:`OSError`.

What it teaches: Python ignores SIGPIPE, so a closed pipe is an exception at the next write,
and again when the interpreter flushes its streams at exit (the "Exception ignored" line).
The cure Python's documentation gives (the note on SIGPIPE in the :mod:`signal` docs):
when a write fails, point the stream's descriptor at ``os.devnull`` with :func:`os.dup2`, so
everything after, the flush at exit included, goes nowhere without an error. The command
then carries on: it writes its files (a solved route's ``--out`` script), finishes its work
and ends with the exit status it would have had; only its printed lines are lost, and those
nobody was reading. Closed or full, the status is the command's own: a status says how the
work went, and the work went the same. The one exception is said where it is made: ``solve``
with no ``--out``, whose route is its printed output, ends with 1 when it could not print it.

>>> import io
>>> say("one line", io.StringIO())
True
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Callable
from typing import Any, TextIO, cast


def say(text: str, stream: TextIO | None = None, end: str = "\n") -> bool:
    """Write ``text`` and ``end`` to ``stream`` (standard output by default) and flush it;
    False, and the stream silenced for good, if it is closed or full."""
    stream = sys.stdout if stream is None else stream
    if stream is None:  # started with the descriptor closed (``>&-``)
        return False
    try:
        stream.write(text + end)
        stream.flush()
    except (OSError, ValueError):  # ValueError: the stream object itself was closed
        silence(stream)
        return False
    return True


def tell(text: str) -> bool:
    """:func:`say` on standard error: the sentences a command ends with."""
    return say(text, sys.stderr)


def silence(stream: TextIO) -> None:
    """Send everything ``stream`` still holds or is given to ``os.devnull``."""
    try:
        descriptor = stream.fileno()
    except (OSError, ValueError, AttributeError):  # an in-memory stream: nothing to redirect
        return
    with contextlib.suppress(OSError):
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, descriptor)
        os.close(devnull)


def flush_both() -> None:
    """Flush standard output and standard error now, silencing either that cannot take it,
    so the flush at exit has nothing left to fail on."""
    for stream in (sys.stdout, sys.stderr):
        if stream is None:
            continue
        try:
            stream.flush()
        except (OSError, ValueError):
            silence(stream)


class _SinkOnFailure:
    """A text stream that passes writes on to ``stream`` until one fails, then drops them."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream
        self.failure: OSError | None = None

    def write(self, text: str) -> int:
        if self.failure is None:
            try:
                return self.stream.write(text)
            except OSError as error:
                self._fail(error)
        return len(text)

    def flush(self) -> None:
        if self.failure is None:
            try:
                self.stream.flush()
            except OSError as error:
                self._fail(error)

    def _fail(self, error: OSError) -> None:
        self.failure = error
        silence(self.stream)  # the buffer's last flush goes nowhere

    def __getattr__(self, name: str) -> Any:
        return getattr(self.stream, name)


def quiet_when_output_closes(main: Callable[[], int | None]) -> int:
    """Call ``main`` with a standard output whose failures end nothing; return its status
    (None is 0), whether its output was read, closed or full."""
    guard = _SinkOnFailure(sys.stdout)
    guarded = sys.stdout = cast(TextIO, guard)
    try:
        status = main() or 0
        guard.flush()
    finally:
        if sys.stdout is guarded:  # unless main put its own in its place
            sys.stdout = guard.stream
    return status
