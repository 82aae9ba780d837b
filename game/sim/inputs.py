"""What the player is holding this tick, from the keyboard or from an input script.

Where it sits: step 1 of a tick. The simulation reads an :class:`Actions` set and never the
keyboard, so a scripted run, a recorded run and a person playing all drive the same code.

The input script format (one event per line; ``#`` comments and blank lines are ignored)::

    # <tick> <+|-><action>      actions: left right up down jump
    0 +right
    45 +jump
    52 -jump

An action is held from its ``+`` tick until its ``-`` tick. Ticks never decrease.

>>> script = InputScript.parse("0 +right\\n3 +jump\\n4 -jump\\n", "demo.txt")
>>> [sorted(a.value for a in script.held_at(t)) for t in range(5)]
[['right'], ['right'], ['right'], ['jump', 'right'], ['right']]
>>> InputScript.parse("5 +fly", "bad.txt")  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
game.sim.inputs.InputScriptError: bad.txt: line 1: unknown action 'fly' — use one of left, ...
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

from game.sim.whole_numbers import NumberTextError, is_digits, read_whole


class Action(Enum):
    LEFT = "left"
    RIGHT = "right"
    UP = "up"
    DOWN = "down"
    JUMP = "jump"


Actions = frozenset[Action]
NOTHING: Actions = frozenset()
ACTION_NAMES = ", ".join(a.value for a in Action)
MAX_TICK_DIGITS = 12  # a million years of ticks: longer is a typo, not a run
MAX_QUOTED_CHARS = 40  # a message quotes at most this much of a bad line


class InputScriptError(Exception):
    """A line of an input script that cannot be read; the message names file and line."""


@dataclass(frozen=True)
class InputEvent:
    tick: int
    pressed: bool
    action: Action

    def __str__(self) -> str:
        return f"{self.tick} {'+' if self.pressed else '-'}{self.action.value}"


def _excerpt(text: str) -> str:
    """``text`` quoted for a message, cut short if long.

    >>> _excerpt("fly"), _excerpt("9" * 5000)
    ("'fly'", "'9999999999999999999999999999999999999999…' (5,000 characters)")
    """
    if len(text) <= MAX_QUOTED_CHARS:
        return repr(text)
    return f"{text[:MAX_QUOTED_CHARS]!r}"[:-1] + f"…' ({len(text):,} characters)"


def _parse_line(text: str, where: str) -> InputEvent:
    parts = text.split()
    if len(parts) != 2:
        raise InputScriptError(f"{where}: expected '<tick> <+|-><action>', "
                               f"got {_excerpt(text)}")
    tick_text, change = parts
    if not is_digits(tick_text):
        raise InputScriptError(f"{where}: the tick must be a whole number >= 0, "
                               f"got {_excerpt(tick_text)}")
    try:
        tick = read_whole(tick_text, MAX_TICK_DIGITS)
    except NumberTextError:
        raise InputScriptError(f"{where}: the tick {_excerpt(tick_text)} is more than "
                               f"{MAX_TICK_DIGITS} digits long — no run lasts that long"
                               ) from None
    if change[:1] not in ("+", "-"):
        raise InputScriptError(f"{where}: the action must start with + or -, "
                               f"got {_excerpt(change)}")
    try:
        action = Action(change[1:])
    except ValueError:
        raise InputScriptError(
            f"{where}: unknown action {_excerpt(change[1:])} — use one of {ACTION_NAMES}"
        ) from None
    return InputEvent(tick, change[0] == "+", action)


@dataclass
class InputScript:
    """A parsed script, replayed tick by tick with :meth:`held_at`."""

    events: list[InputEvent]
    _cursor: int = 0
    _held: set[Action] = field(default_factory=set)

    @classmethod
    def parse(cls, text: str, name: str) -> InputScript:
        """Read a script's text; a UTF-8 byte-order mark (Windows' Notepad writes one) is
        not part of the first line."""
        events: list[InputEvent] = []
        text = text.removeprefix("\ufeff")
        for number, raw in enumerate(text.splitlines(), start=1):
            line = raw.split("#", 1)[0].strip()
            if not line:
                continue
            event = _parse_line(line, f"{name}: line {number}")
            if events and event.tick < events[-1].tick:
                raise InputScriptError(
                    f"{name}: line {number}: tick {event.tick} comes after tick "
                    f"{events[-1].tick} — ticks must never decrease")
            events.append(event)
        return cls(events)


    def held_at(self, tick: int) -> Actions:
        """The actions held during ``tick``; call with increasing ticks."""
        while self._cursor < len(self.events) and self.events[self._cursor].tick <= tick:
            event = self.events[self._cursor]
            if event.pressed:
                self._held.add(event.action)
            else:
                self._held.discard(event.action)
            self._cursor += 1
        return frozenset(self._held)


@dataclass
class Recorder:
    """Turns the held actions of each tick back into script events.

    ``keep=False`` (a run that does not ``--record``) keeps nothing: a million ticks of
    play then cost no memory for a history nobody will write.

    >>> quiet = Recorder(keep=False)
    >>> quiet.observe(0, frozenset({Action.JUMP}))
    >>> quiet.events
    []
    """

    events: list[InputEvent] = field(default_factory=list)
    keep: bool = True
    _last: Actions = NOTHING

    def observe(self, tick: int, held: Actions) -> None:
        if not self.keep:
            return
        for action in Action:  # a fixed order keeps recordings identical run to run
            if action in held and action not in self._last:
                self.events.append(InputEvent(tick, True, action))
            elif action in self._last and action not in held:
                self.events.append(InputEvent(tick, False, action))
        self._last = held

    def text(self) -> str:
        lines = ["# <tick> <+|-><action>   recorded by python -m game --record"]
        lines += [str(event) for event in self.events]
        return "\n".join(lines) + "\n"
