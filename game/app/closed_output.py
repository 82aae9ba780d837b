"""Standard output that closes or fills up is the reader's business, not a crash.

Where it sits: around every command of the app and the programs beside it. The app's,
the bench's, the stress scene's and the lab's start through
:func:`game.app.arguments.run_command`, which calls :func:`quiet_when_output_closes`; the
asset tools call it from their ``__main__`` blocks.

What it teaches:
  * **A closed pipe is a normal end.** ``python -m game.bench | head -1`` closes the pipe
    after one line; Python ignores SIGPIPE, so the next ``print`` raises BrokenPipeError,
    a traceback, and the interpreter's last flush says "Exception ignored" as well. Here
    the first write that fails turns standard output into a sink: the command carries on
    to its end (the files it writes are its real work), says nothing more, and exits with
    its own status.
  * **A full output is a lost output.** When the write fails for another reason (``>
    /dev/full``: no space left), what was printed is lost, so a command that would have
    ended with 0 ends with 1, still without a traceback.
  * **The last flush goes nowhere.** The descriptor of standard output is pointed at the
    null device once a write has failed, so the bytes still held in Python's buffer are
    flushed there at exit instead of failing again.
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from collections.abc import Callable
from typing import Any, TextIO, cast

EXIT_OUTPUT_LOST = 1  # a command whose output could not be written, for a reason but EPIPE


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
        with contextlib.suppress(OSError, ValueError, AttributeError):
            null = os.open(os.devnull, os.O_WRONLY)
            try:
                os.dup2(null, self.stream.fileno())  # the buffer's last flush goes nowhere
            finally:
                os.close(null)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.stream, name)


def quiet_when_output_closes(main: Callable[[], int | None]) -> int:
    """Call ``main`` with a standard output whose failures end nothing; return its status
    (None is 0), or :data:`EXIT_OUTPUT_LOST` instead of 0 when the output was lost for a
    reason other than a reader that stopped reading."""
    guard = _SinkOnFailure(sys.stdout)
    guarded = sys.stdout = cast(TextIO, guard)
    try:
        status = main() or 0
        guard.flush()
    finally:
        if sys.stdout is guarded:  # unless main put its own in its place
            sys.stdout = guard.stream
    lost = guard.failure is not None and guard.failure.errno != errno.EPIPE
    return EXIT_OUTPUT_LOST if lost and status == 0 else status
