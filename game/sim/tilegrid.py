"""The tile-grid lookup: find the solid shapes near a box without scanning every wall.

Where it sits: built once per level by the loader; queried by :mod:`game.sim.movement` in the
x and y passes of every tick, and by the hazard and ledge checks.

What it teaches:
  * A tile map *is* a spatial partition. The cells a box covers are found by dividing its
    edges by the tile size, so a query costs the cells the box covers, not the walls in
    the level: a map 20 times wider costs nothing more per query.
  * The covered cell range follows the strict overlap rule: a box whose right edge lies
    exactly on a cell border does not reach into the next cell.
  * Indices are clamped to the map, never wrapped: Python's ``row[-1]`` is the last column,
    which is exactly the wrong answer for a body just left of the map.

>>> grid = TileGrid(cols=4, rows=2, tile_w=16, tile_h=16)
>>> grid.put(2, 1, TileShape(Box(32, 16, 16, 16), TileKind.SOLID))
>>> list(grid.cells_covering(Box(16, 0, 16, 16)))          # exactly one cell
[(1, 0)]
>>> [s.box for s in grid.shapes_in(Box(20, 10, 20, 10))]
[Box(x=32, y=16, w=16, h=16)]
>>> grid.shapes_in(Box(-100, 0, 10, 10))                    # left of the map: nothing
[]
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from enum import Enum
from typing import Protocol

from game.collision.aabb import Box


class TileKind(Enum):
    """What a tile shape does to a body (the tile's Class in Tiled)."""

    SOLID = "Solid"      # blocks from every side
    ONE_WAY = "OneWay"   # blocks only a body coming down onto its top
    HAZARD = "Hazard"    # hurts on touch, blocks nothing


@dataclass(frozen=True)
class TileShape:
    """One collision rectangle of one tile, in map pixels."""

    box: Box
    kind: TileKind
    col: int = 0
    row: int = 0


class Solids(Protocol):
    """What the movement code needs of the world's solids: a region query and the map size.

    The tile grid is one; :class:`game.sim.platforms.SolidsWithPlatforms` adds moving platforms.
    """

    @property
    def width_px(self) -> int: ...

    @property
    def height_px(self) -> int: ...

    def shapes_in(self, region: Box) -> list[TileShape]: ...


@dataclass
class QueryStats:
    """What the lookups cost this tick: read by the debug overlay and by tests."""

    cells_visited: int = 0
    shapes_tested: int = 0

    def reset(self) -> None:
        self.cells_visited = 0
        self.shapes_tested = 0


@dataclass
class TileGrid:
    """Collision shapes bucketed by the tile cell they sit in."""

    cols: int
    rows: int
    tile_w: int
    tile_h: int
    stats: QueryStats = field(default_factory=QueryStats)
    _cells: dict[tuple[int, int], list[TileShape]] = field(default_factory=dict)

    @property
    def width_px(self) -> int:
        return self.cols * self.tile_w

    @property
    def height_px(self) -> int:
        return self.rows * self.tile_h

    def put(self, col: int, row: int, shape: TileShape) -> None:
        """Add a shape to cell ``(col, row)``; the shape must lie inside that cell."""
        if not (0 <= col < self.cols and 0 <= row < self.rows):
            raise IndexError(f"cell ({col}, {row}) is outside a {self.cols}x{self.rows} map")
        self._cells.setdefault((col, row), []).append(shape)

    def shapes(self) -> Iterator[TileShape]:
        """Every shape in the map (for drawing and for the brute-force comparisons)."""
        for bucket in self._cells.values():
            yield from bucket

    def shapes_at(self, col: int, row: int) -> tuple[TileShape, ...]:
        """The shapes of one cell, read without counting (for drawing, never for physics)."""
        return tuple(self._cells.get((col, row), ()))

    def cells_covering(self, region: Box) -> Iterator[tuple[int, int]]:
        """The in-map cells whose interior the region overlaps, row by row."""
        if not region.is_finite() or region.w <= 0 or region.h <= 0:
            return
        first_col = max(0, math.floor(region.left / self.tile_w))
        last_col = min(self.cols - 1, math.ceil(region.right / self.tile_w) - 1)
        first_row = max(0, math.floor(region.top / self.tile_h))
        last_row = min(self.rows - 1, math.ceil(region.bottom / self.tile_h) - 1)
        for row in range(first_row, last_row + 1):
            for col in range(first_col, last_col + 1):
                yield col, row

    def shapes_in(self, region: Box) -> list[TileShape]:
        """The shapes whose box overlaps the region (strictly), counting the work done.

        The cells of :meth:`cells_covering` and the test of :meth:`Box.overlaps`, written
        out inline: every body calls this several times a tick, so it builds no generator,
        makes no method call per shape and updates the counts once.
        """
        x, y, w, h = region
        if not (w > 0 and h > 0):  # empty (or NaN): overlaps nothing
            return []
        right, bottom = x + w, y + h
        try:
            first_col = max(0, math.floor(x / self.tile_w))
            last_col = min(self.cols - 1, math.ceil(right / self.tile_w) - 1)
            first_row = max(0, math.floor(y / self.tile_h))
            last_row = min(self.rows - 1, math.ceil(bottom / self.tile_h) - 1)
        except (ValueError, OverflowError):  # floor() and ceil() refuse NaN and infinities
            return []
        found: list[TileShape] = []
        cells = self._cells
        visited = tested = 0
        for row in range(first_row, last_row + 1):
            for col in range(first_col, last_col + 1):
                visited += 1
                for shape in cells.get((col, row), ()):
                    tested += 1
                    sx, sy, sw, sh = shape.box
                    if (sx < right and x < sx + sw and sy < bottom and y < sy + sh
                            and sw > 0 and sh > 0):
                        found.append(shape)
        self.stats.cells_visited += visited
        self.stats.shapes_tested += tested
        return found
