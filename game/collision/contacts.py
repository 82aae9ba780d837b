"""Contact tracking: turn "these pairs touch now" into "this contact started", "that one ended".

Where it sits: after collision detection in a tick. Whatever found the touching pairs (a
broad phase, :mod:`game.demos.crates`) hands the whole set to :meth:`ContactTracker.update` once
per tick; sounds, scores and the debug overlay react to the changes it returns.

What it teaches:
  * **Report changes, not states.** Collision detection answers a *level* question, "what
    touches now?", and the answer barely changes from one tick to the next. Printing it
    every tick floods the console: a crate resting on another is 60 identical lines a
    second, a pile of ten crates is hundreds, and the one line that mattered (when the
    touch began) scrolls away in a blink. Printing also costs real time per line, so the
    logging itself slows the frame it is trying to explain. Comparing with last tick's set
    gives the *edges*: a pair appears in ``started`` once, on the tick it begins, and in
    ``ended`` once, on the tick it stops, however long it lasts in between.
  * **Set difference does it.** ``started = now - before`` and ``ended = before - now``.
    Pairs are spelled one way (:func:`game.collision.broad.brute_force.pair_of`) first, so ``(b,
    a)`` this
    tick is not mistaken for a new contact after ``(a, b)`` last tick.
  * **A bounded log.** The overlay shows the last few events from a ``deque`` with a
    ``maxlen``: old events fall off the far end, so a long session cannot grow it.

>>> tracker: ContactTracker[int] = ContactTracker(log_size=8)
>>> tracker.update({(1, 2)}).started
frozenset({(1, 2)})
>>> tracker.update({(2, 1)})                   # same contact, either spelling: no change
ContactChanges(started=frozenset(), ended=frozenset())
>>> tracker.update(set()).ended
frozenset({(1, 2)})
>>> [str(event) for event in tracker.log]
['tick 1: (1, 2) started', 'tick 3: (1, 2) ended']
"""

from __future__ import annotations

from collections import deque
from collections.abc import Collection
from dataclasses import dataclass
from enum import Enum
from typing import Any, Generic

from game.collision.broad.brute_force import K, pair_of

LOG_SIZE_EVENTS = 32  # how many recent events the debug overlay can show


class Change(Enum):
    STARTED = "started"
    ENDED = "ended"


@dataclass(frozen=True)
class ContactEvent(Generic[K]):
    """One contact starting or ending, on a numbered tick (the first update is tick 1)."""

    tick: int
    pair: tuple[K, K]
    change: Change

    def __str__(self) -> str:
        return f"tick {self.tick}: {self.pair} {self.change.value}"


@dataclass(frozen=True)
class ContactChanges(Generic[K]):
    """What changed this tick: the pairs that began touching and the pairs that stopped."""

    started: frozenset[tuple[K, K]]
    ended: frozenset[tuple[K, K]]


NOTHING_CHANGED: ContactChanges[Any] = ContactChanges(frozenset(), frozenset())  # one for all


class ContactTracker(Generic[K]):
    """Remembers last tick's touching pairs and reports only what changed."""

    def __init__(self, log_size: int = LOG_SIZE_EVENTS) -> None:
        self.tick = 0
        self.touching: frozenset[tuple[K, K]] = frozenset()
        self.log: deque[ContactEvent[K]] = deque(maxlen=log_size)

    def update(self, touching: Collection[tuple[K, K]]) -> ContactChanges[K]:
        """Take this tick's whole set of touching pairs; return the ones that changed."""
        self.tick += 1
        if not touching and not self.touching:  # nothing touched then or now: nothing changed
            return NOTHING_CHANGED  # (most ticks: asked before a set is made of nothing)
        now = frozenset(pair_of(a, b) for a, b in touching)
        changes = ContactChanges(started=now - self.touching, ended=self.touching - now)
        self.touching = now
        for pair in sorted(changes.ended):  # endings first: a hand-over reads in order
            self.log.append(ContactEvent(self.tick, pair, Change.ENDED))
        for pair in sorted(changes.started):
            self.log.append(ContactEvent(self.tick, pair, Change.STARTED))
        return changes
