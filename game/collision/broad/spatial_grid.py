"""A uniform grid (spatial hash) for things that move: file each box under the cells it covers.

Where it sits: a broad phase (see :mod:`game.collision.broad.brute_force` for the contract). The
crate demo
(:mod:`game.demos.crates`) uses it. The level's walls use :mod:`game.collision.tile_grid`
instead, which is the
same idea fixed to the tile map; this one is for items that come, go and move every tick.

What it teaches:
  * **Hash the plane, not the items.** Cell ``(col, row)`` is the square
    ``[col * cell_size_px, (col + 1) * cell_size_px)`` and so on down; only occupied cells are
    stored, in a dict, so the grid is unbounded and negative coordinates just work. The cell
    of a coordinate is ``math.floor(c / cell_size_px)``: ``int()`` would put -0.5 in cell 0
    with +0.5, folding two cells into one.
  * **Filed by floor of both edges.** A box goes into every cell from ``floor(left / size)``
    to ``floor(right / size)`` (and the same down). A box whose right edge lies exactly on a
    border is therefore filed one cell further than it reaches. That is deliberate: it makes
    the rule one non-decreasing function, so two boxes that overlap always share a cell even
    when floats round. The "tight" rule, ``ceil(right / size) - 1``, files
    ``Box(0.5, 0, 1e-59, 1)`` in no cell at all (``0.5 + 1e-59`` rounds to ``0.5``), yet
    :meth:`Box.overlaps` says it overlaps ``Box(0, 0, 1, 1)``: the property tests found that.
    The exact test rejects the touching pairs the floor rule lets in.
  * **Each pair once.** Two boxes can share many cells. The pair is tested only in its
    *home* cell, the one at the top-left corner of where their cell ranges meet, so there are
    no duplicate tests, not just no duplicate answers.
  * **Big boxes are kept aside.** A box covering more than ``max_cells_per_item`` cells would
    fill thousands of dict entries; it goes on an *oversize* list instead and is tested
    against everything. Likewise a query bigger than the occupied area looks at the occupied
    cells rather than walking the empty ones.
  * **Choosing the cell size.** About the size of a typical item. Much smaller and every box
    covers many cells; much larger and every cell holds a crowd. For a dozen items, brute
    force is just as good: partitioning pays off with crowds.
  * **Moving is cheap when nothing changes.** Most ticks a box stays in the same cells, and
    :meth:`move` then only updates the box.

>>> grid: SpatialGrid[int] = SpatialGrid(cell_size_px=16)
>>> grid.insert(1, Box(-4, 2, 8, 8))        # straddles the border at x = 0
>>> grid.insert(2, Box(3, 3, 4, 4))
>>> grid.insert(3, Box(100, 100, 8, 8))
>>> sorted(grid.occupied_cells())
[(-1, 0), (0, 0), (6, 6)]
>>> grid.pairs()
{(1, 2)}
>>> grid.stats.pair_tests                     # item 3 is never tested against anything
1
>>> grid.query(Box(90, 90, 12, 12))
{3}
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from itertools import combinations
from typing import Generic, NamedTuple

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhaseStats, K, check_box, pair_of

Cell = tuple[int, int]


class CellRange(NamedTuple):
    """The block of cells from ``(first_col, first_row)`` to ``(last_col, last_row)``."""

    first_col: int
    first_row: int
    last_col: int
    last_row: int

    @property
    def cell_count(self) -> int:
        cols = self.last_col - self.first_col + 1
        rows = self.last_row - self.first_row + 1
        return max(0, cols) * max(0, rows)

    def holds(self, cell: Cell) -> bool:
        col, row = cell
        return (self.first_col <= col <= self.last_col
                and self.first_row <= row <= self.last_row)

    def cells(self) -> Iterator[Cell]:
        for row in range(self.first_row, self.last_row + 1):
            for col in range(self.first_col, self.last_col + 1):
                yield col, row


class SpatialGrid(Generic[K]):
    """Items filed under the square cells their boxes cover; only occupied cells exist."""

    def __init__(self, cell_size_px: float, max_cells_per_item: int = 64) -> None:
        if not (math.isfinite(cell_size_px) and cell_size_px > 0):
            raise ValueError(f"cell_size_px must be a positive number, not {cell_size_px}")
        if max_cells_per_item < 1:
            raise ValueError(f"max_cells_per_item must be at least 1, not {max_cells_per_item}")
        self.cell_size_px = cell_size_px
        self.max_cells_per_item = max_cells_per_item
        self.stats = BroadPhaseStats()
        self._boxes: dict[K, Box] = {}
        self._ranges: dict[K, CellRange] = {}   # where each filed item sits
        self._cells: dict[Cell, set[K]] = {}    # never holds an empty set
        self._oversize: set[K] = set()           # items too big to file

    def __len__(self) -> int:
        return len(self._boxes)

    def cell_range(self, box: Box) -> CellRange:
        """The cells a box is filed under (see the module notes on the floor rule)."""
        size = self.cell_size_px
        return CellRange(math.floor(box.left / size), math.floor(box.top / size),
                         math.floor(box.right / size), math.floor(box.bottom / size))

    def occupied_cells(self) -> frozenset[Cell]:
        """The cells holding at least one item, for the debug overlay and the tests."""
        return frozenset(self._cells)

    def oversize(self) -> frozenset[K]:
        """The items kept aside because they cover too many cells."""
        return frozenset(self._oversize)

    def insert(self, key: K, box: Box) -> None:
        check_box(box)
        if key in self._boxes:
            raise ValueError(f"{key!r} is already in the grid; use move() to move it")
        self._boxes[key] = box
        cells = self.cell_range(box)
        if cells.cell_count > self.max_cells_per_item:
            self._oversize.add(key)
            return
        self._ranges[key] = cells
        for cell in cells.cells():
            self._cells.setdefault(cell, set()).add(key)

    def remove(self, key: K) -> None:
        del self._boxes[key]
        if key in self._oversize:
            self._oversize.remove(key)
            return
        for cell in self._ranges.pop(key).cells():
            keys = self._cells[cell]
            keys.remove(key)
            if not keys:
                del self._cells[cell]  # empty cells go, so memory follows the items

    def move(self, key: K, box: Box) -> None:
        old = self._ranges.get(key)
        if old is None:  # unknown, or kept aside as oversize: file it from scratch
            if key not in self._boxes:
                raise KeyError(key)
            check_box(box)
            self.remove(key)
            self.insert(key, box)
            return
        # ``move`` runs for every item every tick: no CellRange is built for the check.
        size = self.cell_size_px
        x, y, w, h = box
        try:
            new = (math.floor(x / size), math.floor(y / size),
                   math.floor((x + w) / size), math.floor((y + h) / size))
        except (ValueError, OverflowError):  # floor() refuses NaN and infinities
            check_box(box)
            raise
        if new == old:
            self._boxes[key] = box  # same cells, the usual case: nothing to re-file
            return
        check_box(box)
        new_range = CellRange(*new)
        if new_range.cell_count > self.max_cells_per_item:
            self.remove(key)
            self.insert(key, box)
            return
        self._boxes[key] = box
        self._ranges[key] = new_range
        self._refile(key, old, new_range)

    def _refile(self, key: K, old: CellRange, new: CellRange) -> None:
        """Take ``key`` out of the cells it left and put it in the cells it entered.

        A small move shares most cells with the last tick's, so only the edges change.
        """
        cells = self._cells
        for cell in old.cells():
            if not new.holds(cell):
                keys = cells[cell]
                keys.remove(key)
                if not keys:
                    del cells[cell]
        for cell in new.cells():
            if not old.holds(cell):
                cells.setdefault(cell, set()).add(key)

    def query(self, box: Box) -> set[K]:
        check_box(box)
        found: set[K] = set()
        tested: set[K] = set()
        stats = self.stats
        wanted = self.cell_range(box)
        if wanted.cell_count <= len(self._cells):
            buckets = (self._cells.get(cell, set()) for cell in wanted.cells())
            stats.cells_visited += wanted.cell_count
        else:  # the query covers more cells than are occupied: look at those instead
            buckets = (keys for cell, keys in self._cells.items() if wanted.holds(cell))
            stats.cells_visited += len(self._cells)
        for keys in buckets:
            for key in keys - tested:
                tested.add(key)
                stats.pair_tests += 1
                if self._boxes[key].overlaps(box):
                    found.add(key)
        for key in self._oversize:
            stats.pair_tests += 1
            if self._boxes[key].overlaps(box):
                found.add(key)
        return found

    def pairs(self) -> set[tuple[K, K]]:
        found: set[tuple[K, K]] = set()
        stats = self.stats
        boxes, ranges = self._boxes, self._ranges
        stats.cells_visited += len(self._cells)
        tests = 0
        for (col, row), keys in self._cells.items():
            if len(keys) < 2:
                continue  # most cells hold one item: nothing to pair
            for key, other in combinations(keys, 2):
                mine, theirs = ranges[key], ranges[other]
                # Their home cell, the first cell both are filed under: the pair is tested
                # there and nowhere else. Inlined: this runs for every candidate.
                if (max(mine.first_col, theirs.first_col) != col
                        or max(mine.first_row, theirs.first_row) != row):
                    continue  # this pair is tested in another cell they share
                tests += 1
                ax, ay, aw, ah = boxes[key]
                bx, by, bw, bh = boxes[other]
                # Box.overlaps, inlined: this is the innermost loop of the broad phase.
                if (ax < bx + bw and bx < ax + aw and ay < by + bh and by < ay + ah
                        and aw > 0 < ah and bw > 0 < bh):
                    found.add(pair_of(key, other))
        stats.pair_tests += tests
        # Oversize items meet everything: the filed items, then each other once.
        oversize = list(self._oversize)
        for i, key in enumerate(oversize):
            box = self._boxes[key]
            for other in [*self._ranges, *oversize[i + 1:]]:
                stats.pair_tests += 1
                if box.overlaps(self._boxes[other]):
                    found.add(pair_of(key, other))
        return found

