"""The tile-grid lookup: find the solid shapes near a box without scanning every wall.

Where it sits: built once per level by the loader (:mod:`game.levels.solids`) and asked by
:mod:`game.collision.axis_sweep` in the x and y passes of every tick, and by the ground
probe, the hazard and the ledge checks. It is a :class:`~game.collision.shapes.ShapeSource`.

What it teaches:
  * A tile map *is* a spatial partition. The cells a box covers are found by dividing its
    edges by the tile size, so a query costs the cells the box covers, not the walls in
    the level: a map 20 times wider costs nothing more per query.
  * The covered cell range follows the strict overlap rule: a box whose right edge lies
    exactly on a cell border does not reach into the next cell.
  * Indices are clamped to the map, never wrapped: Python's ``row[-1]`` is the last column,
    which is exactly the wrong answer for a body just left of the map.
  * **Plain floats in the hot loop.** Each shape is stored once, when the level is built,
    as an :class:`~game.collision.shapes.Entry` (its four edges as floats, its kind, the
    shape). A query (:meth:`TileGrid.entries_in`) takes the region's four edges and
    compares floats; it builds nothing per shape it rejects.
  * **Nothing else.** Moving shapes, counting and logging are layers around this query,
    not inside it: :class:`CountedGrid` counts the work of each query from outside (the
    lab and the tests read it), and the game adds its platforms and its query log the same
    way (:mod:`game.sim.solids`, :mod:`game.sim.query_log`).

>>> grid = TileGrid(cols=4, rows=2, tile_w=16, tile_h=16)
>>> grid.put(2, 1, TileShape(Box(32, 16, 16, 16), TileKind.SOLID))
>>> list(grid.cells_covering(Box(16, 0, 16, 16)))          # exactly one cell
[(1, 0)]
>>> [s.box for s in grid.shapes_in(Box(20, 10, 20, 10))]
[Box(x=32, y=16, w=16, h=16)]
>>> grid.shapes_in(Box(-100, 0, 10, 10))                    # left of the map: nothing
[]
>>> counted = CountedGrid(grid)
>>> _ = counted.entries_in(20, 10, 40, 20)                  # 2 columns by 2 rows
>>> counted.stats
QueryStats(cells_visited=4, shapes_tested=1)
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from math import ceil, floor

from game.collision.aabb import Box
from game.collision.shapes import Entry, TileKind, TileShape

__all__ = ["CellBlock", "CountedGrid", "QueryStats", "TileGrid", "TileKind", "TileShape"]

CellBlock = tuple[int, int, int, int]  # first column, last column, first row, last row


@dataclass
class TileGrid:
    """Collision shapes bucketed by the tile cell they sit in.

    The buckets are one flat list, cell ``(col, row)`` at index ``row * cols + col``
    (reading a list is quicker than a dict, and the loader bounds a map's size); a cell
    with no shape holds None.
    """

    cols: int
    rows: int
    tile_w: int
    tile_h: int
    _cells: list[list[Entry] | None] = field(init=False, repr=False)
    _empty: list[tuple[int, TileShape]] = field(init=False, repr=False)
    width_px: int = field(init=False)   # the map's size in px, read by every x move
    height_px: int = field(init=False)

    def __post_init__(self) -> None:
        self.width_px = self.cols * self.tile_w
        self.height_px = self.rows * self.tile_h
        self._cells = [None] * (self.cols * self.rows)
        self._empty = []

    def put(self, col: int, row: int, shape: TileShape) -> None:
        """Add a shape to cell ``(col, row)``; the shape must lie inside that cell.

        A shape with no area can touch nothing, so it is kept for drawing only.
        """
        if not (0 <= col < self.cols and 0 <= row < self.rows):
            raise IndexError(f"cell ({col}, {row}) is outside a {self.cols}x{self.rows} map")
        key = row * self.cols + col
        if shape.box.w > 0 and shape.box.h > 0:
            bucket = self._cells[key]
            if bucket is None:
                self._cells[key] = [Entry.of(shape)]
            else:
                bucket.append(Entry.of(shape))
        else:
            self._empty.append((key, shape))

    def shapes(self) -> Iterator[TileShape]:
        """Every shape in the map (for drawing and for the brute-force comparisons)."""
        for bucket in self._cells:
            if bucket is not None:
                for entry in bucket:
                    yield entry.shape
        for _, shape in self._empty:
            yield shape

    def shapes_at(self, col: int, row: int) -> tuple[TileShape, ...]:
        """The shapes of one cell, with those of no area (for drawing, never for physics)."""
        if not (0 <= col < self.cols and 0 <= row < self.rows):
            return ()
        key = row * self.cols + col
        return (*(entry.shape for entry in self._cells[key] or ()),
                *(shape for k, shape in self._empty if k == key))

    def entries_at(self, col: int, row: int) -> list[Entry]:
        """The entries filed in one in-map cell (what a query visiting it tests)."""
        return self._cells[row * self.cols + col] or []

    def block_covering(self, left: float, top: float, right: float, bottom: float,
                       ) -> CellBlock | None:
        """The in-map cells whose interior the region overlaps, as first and last column and
        first and last row; None when there are none (an empty, infinite or NaN region, or
        one off the map).

        Every query of a tick asks this, so it keeps its block in the map by comparisons,
        not by calls of max() and min(); :meth:`block_covering_plainly` is the same with
        them, and a test holds the two equal."""
        if not (right > left and bottom > top):  # empty (or NaN): overlaps nothing
            return None
        try:  # floor() and ceil() refuse infinities
            first_col, last_col = floor(left / self.tile_w), ceil(right / self.tile_w) - 1
            first_row, last_row = floor(top / self.tile_h), ceil(bottom / self.tile_h) - 1
        except OverflowError:
            return None
        # Kept in the map: a region reaching past an edge visits the cells up to that edge.
        if first_col < 0:
            first_col = 0
        if last_col >= self.cols:
            last_col = self.cols - 1
        if first_row < 0:
            first_row = 0
        if last_row >= self.rows:
            last_row = self.rows - 1
        if first_col > last_col or first_row > last_row:
            return None
        return first_col, last_col, first_row, last_row

    def block_covering_plainly(self, left: float, top: float, right: float, bottom: float,
                               ) -> CellBlock | None:
        """:meth:`block_covering` with max() and min() keeping the block in the map."""
        if not (right > left and bottom > top):  # empty (or NaN): overlaps nothing
            return None
        try:  # floor() and ceil() refuse infinities; a region past an edge stops at it
            first_col, last_col = max(floor(left / self.tile_w), 0), min(
                ceil(right / self.tile_w), self.cols) - 1
            first_row, last_row = max(floor(top / self.tile_h), 0), min(
                ceil(bottom / self.tile_h), self.rows) - 1
        except OverflowError:
            return None
        if first_col > last_col or first_row > last_row:
            return None
        return first_col, last_col, first_row, last_row

    def cells_covering(self, region: Box) -> Iterator[tuple[int, int]]:
        """The in-map cells whose interior the region overlaps, row by row."""
        x, y, w, h = region
        block = self.block_covering(x, y, x + w, y + h)
        if block is None:
            return
        first_col, last_col, first_row, last_row = block
        for row in range(first_row, last_row + 1):
            for col in range(first_col, last_col + 1):
                yield col, row

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        """The shapes that overlap the region (strictly), as entries.

        The cells of :meth:`block_covering`, and in them the test of :meth:`Box.overlaps`
        on the region's four edges.
        """
        block = self.block_covering(left, top, right, bottom)
        if block is None:
            return []
        first_col, last_col, first_row, last_row = block
        cells, cols = self._cells, self.cols
        found: list[Entry] = []
        for row in range(first_row, last_row + 1):
            for col in range(first_col, last_col + 1):
                bucket = cells[row * cols + col]
                if bucket is None:
                    continue  # no shape in this cell
                for entry in bucket:
                    s_left, s_top, s_right, s_bottom, _, _ = entry
                    if s_left < right and left < s_right and s_top < bottom and top < s_bottom:
                        found.append(entry)
        return found

    def shapes_in(self, region: Box) -> list[TileShape]:
        """The shapes whose box overlaps the region (strictly)."""
        x, y, w, h = region
        return [entry.shape for entry in self.entries_in(x, y, x + w, y + h)]


@dataclass
class QueryStats:
    """What some queries cost: the cells they visited and the shapes filed in those."""

    cells_visited: int = 0
    shapes_tested: int = 0

    def reset(self) -> None:
        self.cells_visited = 0
        self.shapes_tested = 0

    def count(self, grid: TileGrid, left: float, top: float, right: float, bottom: float,
              ) -> CellBlock | None:
        """Add what a query of the region costs ``grid``; return the block it visits."""
        block = grid.block_covering(left, top, right, bottom)
        if block is not None:
            first_col, last_col, first_row, last_row = block
            for row in range(first_row, last_row + 1):
                for col in range(first_col, last_col + 1):
                    self.cells_visited += 1
                    self.shapes_tested += len(grid.entries_at(col, row))
        return block


@dataclass
class CountedGrid:
    """A tile grid whose queries are counted in :attr:`stats`; it answers as the grid does."""

    grid: TileGrid
    stats: QueryStats = field(default_factory=QueryStats)

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        self.stats.count(self.grid, left, top, right, bottom)
        return self.grid.entries_in(left, top, right, bottom)
