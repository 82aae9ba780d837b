"""The broad-phase contract, and brute force: the O(n²) answer every other broad phase must match.

Where it sits: under the physics, beside :mod:`game.collision.tile_grid`. A *broad phase* answers
"which pairs of these boxes might collide?" cheaply, so the exact test (and the push-apart
in :mod:`game.collision.response`) only runs on pairs that matter. This module states what a broad
phase is; :mod:`game.collision.broad.spatial_grid`, :mod:`game.collision.broad.quadtree` and
:mod:`game.collision.broad.sort_and_sweep`
are three ways of doing it, interchangeable behind :class:`BroadPhase`.

What it teaches:
  * **The contract.** A broad phase holds *items*: keys (crate numbers, names) with a
    :class:`~game.collision.aabb.Box` each. It can ``insert``, ``remove`` and ``move`` them, and it
    answers two questions: :meth:`~BroadPhase.pairs`, every pair of items whose boxes
    overlap, and :meth:`~BroadPhase.query`, every item overlapping a given box. Overlap is
    :meth:`Box.overlaps`: strict, so boxes that only touch never pair, and empty boxes
    never pair with anything.
  * **One spelling per pair.** ``(a, b)`` and ``(b, a)`` are the same pair, so every
    broad phase writes it one way: smaller key first (see :func:`pair_of`). That is why
    keys must be orderable as well as hashable: ints or strings, not a mix.
  * **Brute force is the oracle.** Testing every pair is n(n-1)/2 tests: 4,950 for 100
    items, 499,500 for 1,000. It is too slow for a big crowd and perfectly fine for a
    dozen, and it is obviously right, so the tests check every clever structure against it.
  * **Count the work, not the time.** Each structure adds to a :class:`BroadPhaseStats`:
    exact box-vs-box tests and cells (or tree nodes) looked at. Counts are the same on
    every machine, so tests can assert them and the debug overlay can show them.

>>> phase: BruteForce[str] = BruteForce()
>>> phase.insert("crate", Box(0, 0, 16, 16))
>>> phase.insert("barrel", Box(10, 10, 16, 16))
>>> phase.insert("beside", Box(16, 0, 16, 16))      # touches the crate: not a pair
>>> sorted(phase.pairs())
[('barrel', 'beside'), ('barrel', 'crate')]
>>> sorted(phase.query(Box(-5, -5, 6, 6)))
['crate']
>>> phase.stats.pair_tests                           # 3 pairs + 3 query tests
6
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Generic, Protocol, TypeVar

from game.collision.aabb import Box


class Key(Protocol):
    """What an item's key must be: hashable (to be found) and orderable (to spell pairs)."""

    def __lt__(self, other: Any, /) -> bool: ...

    def __hash__(self) -> int: ...


K = TypeVar("K", bound=Key)


def pair_of(a: K, b: K) -> tuple[K, K]:
    """The one spelling of an unordered pair: the smaller key first.

    >>> pair_of(7, 3), pair_of(3, 7)
    ((3, 7), (3, 7))
    """
    return (a, b) if a < b else (b, a)


def check_box(box: Box) -> None:
    """Refuse a box a broad phase cannot file: NaN or infinite fields or edges.

    ``Box(1e308, 0, 1e308, 1)`` has finite fields but an infinite right edge, and no
    cell or tree node can hold that. Empty boxes (zero or negative size) are allowed:
    they are stored, and they pair with nothing.

    >>> check_box(Box(0, 0, float("inf"), 1))
    Traceback (most recent call last):
    ...
    ValueError: a broad phase needs finite boxes, not Box(x=0, y=0, w=inf, h=1)
    """
    if not (box.is_finite() and math.isfinite(box.right) and math.isfinite(box.bottom)):
        raise ValueError(f"a broad phase needs finite boxes, not {box}")


@dataclass
class BroadPhaseStats:
    """The work done since the last :meth:`reset`: read by tests and the debug overlay."""

    pair_tests: int = 0     # exact Box.overlaps tests between two items (or item and query)
    cells_visited: int = 0  # grid cells or tree nodes looked at; 0 for structures with none

    def reset(self) -> None:
        self.pair_tests = 0
        self.cells_visited = 0


class BroadPhase(Protocol[K]):
    """What every broad phase offers; code that uses one should ask for this, not a class."""

    stats: BroadPhaseStats

    def insert(self, key: K, box: Box) -> None:
        """Add a new item; a key already present is an error (use :meth:`move`)."""

    def remove(self, key: K) -> None:
        """Forget an item; an unknown key is a ``KeyError``."""

    def move(self, key: K, box: Box) -> None:
        """Give an item its new box."""

    def query(self, box: Box) -> set[K]:
        """The items whose boxes overlap ``box``. Never changes the structure."""

    def pairs(self) -> set[tuple[K, K]]:
        """Every pair of items whose boxes overlap, each spelled by :func:`pair_of`."""


class BruteForce(Generic[K]):
    """Every item against every other: the reference answer, O(n²) per :meth:`pairs`."""

    def __init__(self) -> None:
        self.stats = BroadPhaseStats()
        self._boxes: dict[K, Box] = {}

    def __len__(self) -> int:
        return len(self._boxes)

    def insert(self, key: K, box: Box) -> None:
        check_box(box)
        if key in self._boxes:
            raise ValueError(f"{key!r} is already in the broad phase; use move() to move it")
        self._boxes[key] = box

    def remove(self, key: K) -> None:
        del self._boxes[key]

    def move(self, key: K, box: Box) -> None:
        check_box(box)
        if key not in self._boxes:
            raise KeyError(key)
        self._boxes[key] = box

    def query(self, box: Box) -> set[K]:
        check_box(box)
        self.stats.pair_tests += len(self._boxes)
        return {key for key, item in self._boxes.items() if item.overlaps(box)}

    def pairs(self) -> set[tuple[K, K]]:
        items = list(self._boxes.items())
        found: set[tuple[K, K]] = set()
        for i, (key, box) in enumerate(items):
            for other, other_box in items[i + 1:]:
                self.stats.pair_tests += 1
                if box.overlaps(other_box):
                    found.add(pair_of(key, other))
        return found
