"""The tile-grid lookup: find the solid shapes near a box without scanning every wall.

Where it sits: built once per level by the loader; a world plays on a grid that shares its
buckets and carries the level's moving platforms as a second layer
(:meth:`TileGrid.with_movers`), queried by :mod:`game.sim.movement` in the x and y passes of
every tick, and by the ground probe, the hazard and the ledge checks.

What it teaches:
  * A tile map *is* a spatial partition. The cells a box covers are found by dividing its
    edges by the tile size, so a query costs the cells the box covers, not the walls in
    the level: a map 20 times wider costs nothing more per query.
  * The covered cell range follows the strict overlap rule: a box whose right edge lies
    exactly on a cell border does not reach into the next cell.
  * Indices are clamped to the map, never wrapped: Python's ``row[-1]`` is the last column,
    which is exactly the wrong answer for a body just left of the map.
  * **Plain floats in the hot loop.** Each shape is stored once, when the level is built,
    as an :data:`Entry`: its four edges as floats, its kind and the shape itself. A query
    (:meth:`TileGrid.entries_in`) takes the region's four edges and compares floats; it
    builds no boxes, no generators, and nothing per shape it rejects.
  * **Things that move, filed where they can be.** A layer of movers (the platforms) is
    filed in the same cells, each in every cell its route can take it to, and the same
    query looks them up in the cells it visits: no query scans every platform.
  * **Counting and logging the work.** Every query adds what it visited to
    :class:`QueryStats`; when a :class:`QueryLog` is attached (the debug overlay attaches
    one), it also writes down which cells it looked in, so the overlay can show exactly
    what was tested and nothing else.

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

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from enum import Enum
from math import ceil, floor
from typing import NamedTuple, Protocol

from game.collision.aabb import Box


class TileKind(Enum):
    """What a tile shape does to a body (the tile's Class in Tiled)."""

    SOLID = "Solid"      # blocks from every side
    ONE_WAY = "OneWay"   # blocks only a body coming down onto its top
    HAZARD = "Hazard"    # hurts on touch, blocks nothing


class TileShape(NamedTuple):
    """One collision rectangle of one tile, in map pixels (a moving platform's shape has
    ``col == -1`` and its number as ``row``)."""

    box: Box
    kind: TileKind
    col: int = 0
    row: int = 0


# A shape as the queries read it: left, top, right, bottom (floats), its kind, the shape.
Entry = tuple[float, float, float, float, TileKind, TileShape]


def entry_of(shape: TileShape) -> Entry:
    """The plain-float form of a shape, computed once."""
    x, y, w, h = shape.box
    return (x, y, x + w, y + h, shape.kind, shape)


class Mover(Protocol):
    """A moving shape filed in the grid's second layer: it keeps its current entry."""

    @property
    def number(self) -> int: ...

    @property
    def entry(self) -> Entry: ...


def _number(mover: Mover) -> int:
    return mover.number


class MoverLayer(Protocol):
    """Moving shapes filed by the cells they can reach, keyed like the tiles (the platforms'
    :class:`game.sim.platforms.PlatformIndex` is one)."""

    @property
    def cells(self) -> Sequence[Sequence[Mover] | None]:
        """The movers of cell ``(col, row)`` at ``row * cols + col``, as for the tiles."""
        ...

    @property
    def cell_bounds(self) -> tuple[float, float, float, float]:
        """Left, top, right, bottom of whole cells holding every filed cell: a region
        outside it visits none, so the layer need not be looked up."""
        ...

    @property
    def outside(self) -> Sequence[Mover]:
        """Movers that can leave the map, where no cell holds them: tested by every query."""
        ...


class Solids(Protocol):
    """What the movement code needs of the world's solids: a region query and the map size.

    The tile grid is one (with its moving platforms when a world has filed them,
    :meth:`TileGrid.with_movers`); :class:`game.sim.platforms.SolidsWithout` leaves out
    the platform that is itself moving.
    """

    @property
    def width_px(self) -> int: ...

    @property
    def height_px(self) -> int: ...

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]: ...


@dataclass
class QueryStats:
    """What the lookups cost this tick: read by the debug overlay and by tests."""

    cells_visited: int = 0
    shapes_tested: int = 0

    def reset(self) -> None:
        self.cells_visited = 0
        self.shapes_tested = 0


class Query(NamedTuple):
    """One lookup as the log keeps it: what asked, the block of cells visited (inclusive,
    empty when ``first_col > last_col``), and the moving shapes tested beside the tiles."""

    purpose: str
    first_col: int
    last_col: int
    first_row: int
    last_row: int
    extra: tuple[TileShape, ...] = ()

    def cells(self) -> Iterator[tuple[int, int]]:
        for row in range(self.first_row, self.last_row + 1):
            for col in range(self.first_col, self.last_col + 1):
                yield col, row


@dataclass
class QueryLog:
    """Every lookup made while attached, labelled with what it was for.

    The world sets :attr:`purpose` before each kind of query ("x sweep", "ground probe", ...)
    and clears :attr:`queries` at the start of a tick, so after a tick it holds exactly that
    tick's lookups. Attached only when something will read it (the debug overlay).
    """

    purpose: str = ""
    queries: list[Query] = field(default_factory=list)

    def add(self, first_col: int, last_col: int, first_row: int, last_row: int) -> None:
        self.queries.append(Query(self.purpose, first_col, last_col, first_row, last_row))

    def add_extra(self, shapes: tuple[TileShape, ...]) -> None:
        """Note the moving shapes the last query tested besides its tiles."""
        if self.queries and shapes:
            last = self.queries[-1]
            self.queries[-1] = last._replace(extra=last.extra + shapes)


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
    stats: QueryStats = field(default_factory=QueryStats)
    log: QueryLog | None = None  # attached by whoever wants every query written down
    _cells: list[list[Entry] | None] = field(default_factory=list, repr=False)  # a slot a cell
    _empty: list[tuple[int, TileShape]] = field(default_factory=list)
    movers: MoverLayer | None = None  # a second layer of moving shapes (a world's platforms)
    width_px: int = field(init=False)   # the map's size in px, read by every x move
    height_px: int = field(init=False)

    def __post_init__(self) -> None:
        self.width_px = self.cols * self.tile_w
        self.height_px = self.rows * self.tile_h
        if not self._cells:  # a new grid; one made by with_movers shares its buckets
            self._cells = [None] * (self.cols * self.rows)

    def with_movers(self, layer: MoverLayer) -> TileGrid:
        """The same tiles (shared, not copied) with a layer of moving shapes, and counts and
        a log of its own: what a world queries while a level plays."""
        return TileGrid(self.cols, self.rows, self.tile_w, self.tile_h, _cells=self._cells,
                        _empty=self._empty, movers=layer)

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
                self._cells[key] = [entry_of(shape)]
            else:
                bucket.append(entry_of(shape))
        else:
            self._empty.append((key, shape))

    def shapes(self) -> Iterator[TileShape]:
        """Every shape in the map (for drawing and for the brute-force comparisons)."""
        for bucket in self._cells:
            if bucket is not None:
                for entry in bucket:
                    yield entry[5]
        for _, shape in self._empty:
            yield shape

    def shapes_at(self, col: int, row: int) -> tuple[TileShape, ...]:
        """The shapes of one cell, read without counting (for drawing, never for physics)."""
        if not (0 <= col < self.cols and 0 <= row < self.rows):
            return ()
        key = row * self.cols + col
        return (*(entry[5] for entry in self._cells[key] or ()),
                *(shape for k, shape in self._empty if k == key))

    def block_covering(self, left: float, top: float, right: float, bottom: float,
                       ) -> tuple[int, int, int, int] | None:
        """The in-map cells whose interior the region overlaps, as first and last column and
        first and last row; None when there are none (an empty, infinite or NaN region, or
        one off the map)."""
        if not (right > left and bottom > top):
            return None
        try:  # floor() and ceil() refuse infinities
            first_col, last_col = floor(left / self.tile_w), ceil(right / self.tile_w) - 1
            first_row, last_row = floor(top / self.tile_h), ceil(bottom / self.tile_h) - 1
        except OverflowError:
            return None
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
                   ignoring: Mover | None = None) -> list[Entry]:
        """The shapes that overlap the region (strictly), as entries, counting the work.

        The cells of :meth:`cells_covering` and the test of :meth:`Box.overlaps`, on the
        region's four edges: every body calls this several times a tick, so it takes floats,
        makes no call per shape and updates the counts once. With a layer of
        :attr:`movers` (moving platforms), the same cells are looked up in it too, when the
        region reaches the layer's cells at all; each mover found is tested once, after the
        tiles and in the order of their numbers (then those off the map), and ``ignoring``
        is skipped.
        """
        if not (right > left and bottom > top):  # empty (or NaN): overlaps nothing
            return []
        cols = self.cols
        # The block of block_covering, worked out inline: the hottest call of a tick.
        try:  # the covered cells, clamped to the map (floor() and ceil() refuse infinities)
            first_col, last_col = floor(left / self.tile_w), ceil(right / self.tile_w) - 1
            first_row, last_row = floor(top / self.tile_h), ceil(bottom / self.tile_h) - 1
        except OverflowError:
            return []
        if first_col < 0:
            first_col = 0
        if last_col >= cols:
            last_col = cols - 1
        if first_row < 0:
            first_row = 0
        if last_row >= self.rows:
            last_row = self.rows - 1
        log = self.log
        if log is not None:
            log.add(first_col, last_col, first_row, last_row)
        layer = self.movers
        filed: Sequence[Sequence[Mover] | None] | None = None
        if layer is not None:
            low_x, low_y, high_x, high_y = layer.cell_bounds
            if left < high_x and low_x < right and top < high_y and low_y < bottom:
                filed = layer.cells
        found: list[Entry] = []
        near: list[Mover] = []
        cells = self._cells
        tested = 0
        for row in range(first_row, last_row + 1):
            key = row * cols
            for col in range(first_col, last_col + 1):
                bucket = cells[key + col]
                if bucket is not None:
                    tested += len(bucket)
                    for entry in bucket:
                        if (entry[0] < right and left < entry[2]
                                and entry[1] < bottom and top < entry[3]):
                            found.append(entry)
                if filed is not None:
                    movers = filed[key + col]
                    if movers is not None:
                        for mover in movers:
                            if mover not in near and mover is not ignoring:
                                near.append(mover)
        if len(near) > 1:
            near.sort(key=_number)
        if layer is not None and layer.outside:
            near.extend(mover for mover in layer.outside if mover is not ignoring)
        if near:
            tested += len(near)
            for mover in near:
                entry = mover.entry
                if (entry[0] < right and left < entry[2] and entry[1] < bottom
                        and top < entry[3] and entry[2] > entry[0] and entry[3] > entry[1]):
                    found.append(entry)
            if log is not None:
                log.add_extra(tuple(mover.entry[5] for mover in near))
        stats = self.stats
        if last_col >= first_col and last_row >= first_row:
            stats.cells_visited += (last_col - first_col + 1) * (last_row - first_row + 1)
        stats.shapes_tested += tested
        return found

    def shapes_in(self, region: Box) -> list[TileShape]:
        """The shapes whose box overlaps the region (strictly), counting the work done."""
        x, y, w, h = region
        return [entry[5] for entry in self.entries_in(x, y, x + w, y + h)]
