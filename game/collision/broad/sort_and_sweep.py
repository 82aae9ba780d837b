"""Sort and sweep (sweep and prune): sort boxes by their left edge, then sweep left to right.

Where it sits: a broad phase (see :mod:`game.collision.broad.brute_force` for the contract), and
the one with
no cell size or tree to tune. It suits many similar items spread along one axis, as in a
side-scrolling level.

What it teaches:
  * **One axis prunes most pairs.** Two boxes can only overlap if their x intervals do.
    Walk the boxes in order of left edge, keeping an *active list* of those whose right edge
    is still ahead of the sweep line. A new box can only meet the active ones; a box drops
    out once the sweep passes its right edge (touching is not overlapping, so ``<=``), and it
    can never meet anything later, which starts even further right.
  * **Then test y.** Active boxes overlap the new one on x already; the exact
    :meth:`Box.overlaps` test settles the rest.
  * **The cost** is the sort plus one test per pair that overlaps on x: about n log n when
    things are spread out along x, and back to n² when they are stacked in one column
    (then sweep along y instead, or use a grid).
  * **Kept in order.** The list stays sorted as items come, go and move, by binary search
    (``bisect``), so :meth:`pairs` only sweeps and :meth:`query` stops at the first box
    starting right of the query. Engines with thousands of movers instead re-sort each tick
    with an insertion sort, which is nearly linear on a list that was sorted last tick.

>>> sweep: SortAndSweep[int] = SortAndSweep()
>>> for key, x in enumerate([0, 100, 5, 200]):
...     sweep.insert(key, Box(x, 0, 10, 10))
>>> sweep.pairs()
{(0, 2)}
>>> sweep.stats.pair_tests          # only boxes 0 and 2 ever overlap on x
1
"""

from __future__ import annotations

from bisect import bisect_left, insort
from typing import Generic

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhaseStats, K, check_box, pair_of


class SortAndSweep(Generic[K]):
    """Items in a list sorted by left edge (then key), swept with an active list."""

    def __init__(self) -> None:
        self.stats = BroadPhaseStats()
        self._boxes: dict[K, Box] = {}
        self._by_left: list[tuple[float, K]] = []

    def __len__(self) -> int:
        return len(self._boxes)

    def insert(self, key: K, box: Box) -> None:
        check_box(box)
        if key in self._boxes:
            raise ValueError(f"{key!r} is already in the sweep; use move() to move it")
        self._boxes[key] = box
        insort(self._by_left, (box.left, key))

    def remove(self, key: K) -> None:
        box = self._boxes.pop(key)
        del self._by_left[bisect_left(self._by_left, (box.left, key))]

    def move(self, key: K, box: Box) -> None:
        check_box(box)
        if key not in self._boxes:
            raise KeyError(key)
        self.remove(key)
        self.insert(key, box)

    def query(self, box: Box) -> set[K]:
        check_box(box)
        # Entries from here on start at or right of the query's right edge: none can overlap.
        end = bisect_left(self._by_left, (box.right,))
        self.stats.pair_tests += end
        return {key for _, key in self._by_left[:end] if self._boxes[key].overlaps(box)}

    def pairs(self) -> set[tuple[K, K]]:
        found: set[tuple[K, K]] = set()
        active: list[tuple[K, Box]] = []
        for left, key in self._by_left:
            box = self._boxes[key]
            active = [(k, b) for k, b in active if b.right > left]  # drop those swept past
            for other, other_box in active:
                self.stats.pair_tests += 1
                if box.overlaps(other_box):
                    found.add(pair_of(key, other))
            active.append((key, box))
        return found
