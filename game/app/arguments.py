"""Command-line options read like the rest of the game's input: checked, and explained.

Where it sits: under every command of the app and the programs beside it (``python -m game``,
the stress scene, the bench). Each parses its options with :class:`Parser` and the number
types made by :func:`whole_number`, and starts through :func:`run_command`.

What it teaches:
  * **A number is checked before it is converted.** ``int()`` of a 5,000-digit string
    raises (Python caps the digits it converts, against a denial of service), so the
    length is looked at first and the value is compared with its limits after.
  * **Errors quote a short excerpt.** A value pasted by mistake can be megabytes long; the
    message shows its start and its length, never all of it.
  * **A reader that stops reading is not a crash either** (``| head -1``): see
    :mod:`game.levels.closed_output`.
  * **Ctrl-C is a way to stop, not a crash**: exit status 130, the shell's code for a
    program stopped by SIGINT, and one line instead of a traceback.

>>> ticks = whole_number(0, 1000, "ticks")
>>> ticks("60")
60
>>> ticks("-1")
Traceback (most recent call last):
    ...
argparse.ArgumentTypeError: -1 is not a whole number from 0 to 1,000 ticks
>>> ticks("9" * 5000)  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
argparse.ArgumentTypeError: '999...' (5,000 characters) is not a whole number from 0 to ...
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
from collections.abc import Callable
from typing import Any, NoReturn

from game.levels.closed_output import quiet_when_output_closes
from game.sim.whole_numbers import NumberTextError, read_whole

EXIT_USAGE = 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT
MAX_QUOTED_CHARS = 40  # at most this much of a bad value is quoted back
MAX_MESSAGE_CHARS = 400  # a usage error longer than this is cut short
MAX_DIGITS = 18  # longer numbers are out of every limit these commands have


def excerpt(text: str) -> str:
    """``text`` as a message quotes it: whole if short, else its start and its length.

    >>> excerpt("abc"), excerpt("x" * 100)
    ("'abc'", "'xxx...' (100 characters)")
    """
    if len(text) <= MAX_QUOTED_CHARS:
        return repr(text)
    return f"{text[:3]!r}"[:-1] + f"...' ({len(text):,} characters)"


def whole_number(low: int, high: int, unit: str) -> Callable[[str], int]:
    """An argparse ``type`` for a whole number from ``low`` to ``high`` (in ``unit``)."""
    def parse(text: str) -> int:
        limits = f"from {low:,} to {high:,} {unit}"
        try:
            value = read_whole(text.strip(), MAX_DIGITS, signed=True)
        except NumberTextError:
            shown = text if len(text) <= MAX_QUOTED_CHARS else excerpt(text)
            raise argparse.ArgumentTypeError(f"{shown} is not a whole number {limits}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"{text.strip()} is not a whole number {limits}")
        return value

    parse.__name__ = unit  # argparse names the type in some messages
    return parse


class Parser(argparse.ArgumentParser):
    """An ArgumentParser whose error messages stay short, whatever was typed."""

    def error(self, message: str) -> NoReturn:
        if len(message) > MAX_MESSAGE_CHARS:
            message = message[:MAX_MESSAGE_CHARS] + f"... ({len(message):,} characters)"
        super().error(message)


def run_command(main: Callable[[], int]) -> int:
    """Call ``main`` and return its exit status; Ctrl-C returns 130 with one line, and a
    standard output closed or full ends nothing (:mod:`game.levels.closed_output`).

    While ``main`` runs, Ctrl-C is a KeyboardInterrupt it may catch (to write what a run has
    done so far); before and after, the handler the program installed (the ``__main__``
    modules' guard for the imports) is in charge."""
    previous = _interrupts_raise()
    try:
        return quiet_when_output_closes(main)
    except KeyboardInterrupt:
        print("stopped by Ctrl-C", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        if previous is not None:
            with contextlib.suppress(ValueError, TypeError):
                signal.signal(signal.SIGINT, previous)


def _interrupts_raise() -> Any:
    """Make Ctrl-C raise KeyboardInterrupt; the handler it replaced (None off the main
    thread, where handlers cannot be set)."""
    try:
        return signal.signal(signal.SIGINT, signal.default_int_handler)
    except ValueError:
        return None
