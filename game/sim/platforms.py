"""Moving platforms: solids that follow a path drawn in Tiled, carrying and pushing bodies.

Where it sits: step 2 of a tick, before the bodies' own moves (:meth:`World.step`). Each
platform advances along its path, one axis at a time, and does two things to bodies:

* a body in its way is **pushed** to the platform's leading face, through the same swept
  move as any other step, so a wall stops it; if the wall leaves it no room, it is crushed;
* a body **riding** it (its feet found the platform with the ground probe last tick) is
  **carried** by the same amount, again through the swept move, so a ride never passes
  through a wall either.

Then, for the bodies' own moves, the platforms are simply more solid shapes: the world's
tile grid carries them as a second layer (:class:`PlatformIndex`, each platform filed once
in the cells its route can reach), and its one region query answers with the tiles plus the
platforms in the cells it visits, so :mod:`game.sim.movement` needs no special case and a
query costs the platforms near it, not every platform in the level.

>>> path = Route(((0.0, 0.0), (30.0, 0.0)), loop=False)
>>> [path.point_at(d) for d in (0.0, 10.0, 30.0, 40.0, 60.0)]    # there and back again
[(0.0, 0.0), (10.0, 0.0), (30.0, 0.0), (20.0, 0.0), (0.0, 0.0)]
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from functools import cached_property

from game.collision.aabb import Box
from game.sim.sprite import Anchor, BoxSprite
from game.sim.tilegrid import Entry, TileGrid, TileKind, TileShape, entry_of

Point = tuple[float, float]


@dataclass(frozen=True)
class Route:
    """A polyline to follow, by distance travelled: back and forth, or round a loop."""

    points: tuple[Point, ...]
    loop: bool = False

    @cached_property
    def legs(self) -> tuple[tuple[Point, Point], ...]:
        legs = list(zip(self.points, self.points[1:], strict=False))
        if self.loop and len(self.points) > 2:
            legs.append((self.points[-1], self.points[0]))
        return tuple(legs)

    @cached_property
    def length(self) -> float:
        return sum(math.dist(a, b) for a, b in self.legs)

    def point_at(self, distance: float) -> Point:
        """Where a traveller is after ``distance`` px along the path (ping-pong or loop)."""
        length = self.length
        if length == 0:
            return self.points[0]
        if self.loop:
            distance %= length
        else:
            distance %= 2 * length
            if distance > length:
                distance = 2 * length - distance
        for a, b in self.legs:
            leg = math.dist(a, b)
            if distance <= leg and leg > 0:
                t = distance / leg
                return (a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t)
            distance -= leg
        return self.points[-1] if not self.loop else self.points[0]


@dataclass(frozen=True)
class PlatformSpec:
    """A platform as the level describes it: its top-left corner follows ``path``."""

    path: Route
    width_px: float
    height_px: float
    speed_px_s: float


class Platform(BoxSprite):
    """A moving solid. Its place is a function of the distance it has travelled along its
    route, ``travelled_px``; ``box`` (exact), ``rect``, ``shape`` and ``entry`` follow it.

    A platform no body is near need not be moved each tick: the world only advances its
    distance (:meth:`advance`), and the box (with its rect, shape and entry) is brought to
    where that distance puts it the next time anything reads it, so no reader ever sees it
    lag. A level pays each tick for the platforms near a body, not for every platform.
    """

    anchor = Anchor.TOP_LEFT
    travelled_px = 0.0  # how far along its route it has gone
    _placed_px = 0.0    # the distance its box was last placed for

    def __init__(self, spec: PlatformSpec, number: int) -> None:
        x, y = spec.path.point_at(0.0)
        self.spec = spec
        self.number = number
        super().__init__(Box(x, y, spec.width_px, spec.height_px))
        self._follow_box()
        self.region = route_region(spec)

    @property
    def box(self) -> Box:
        if self._placed_px != self.travelled_px:  # moved on while nobody looked: catch up
            self._placed_px = self.travelled_px
            x, y = self.spec.path.point_at(self.travelled_px)
            self.place(Box(x, y, self.spec.width_px, self.spec.height_px))
        return self._box

    @box.setter
    def box(self, box: Box) -> None:
        self._box = box

    @property
    def entry(self) -> Entry:
        """The box as plain floats, for the tile grid's queries (up to date when read)."""
        self.box  # noqa: B018  (reading the box brings it up to date)
        return self._entry

    @property
    def shape(self) -> TileShape:
        self.box  # noqa: B018
        return self._entry[5]

    def advance(self, dt_s: float) -> None:
        """Travel on for one tick without moving the box (nothing is near enough to care)."""
        self.travelled_px += self.spec.speed_px_s * dt_s

    def next_point(self, dt_s: float) -> Point:
        """Travel on for one tick; where the top-left corner goes. The caller moves the box
        there (one axis at a time, pushing what is in the way)."""
        self.box  # noqa: B018  (start from where the last tick left it)
        self.travelled_px += self.spec.speed_px_s * dt_s
        self._placed_px = self.travelled_px
        return self.spec.path.point_at(self.travelled_px)

    def place(self, box: Box) -> None:
        """Set the exact position; the picture, the shape and its plain-float entry follow."""
        super().place(box)
        self._follow_box()

    def _follow_box(self) -> None:
        self._entry: Entry = entry_of(TileShape(self._box, TileKind.SOLID, col=-1,
                                                row=self.number))


def route_region(spec: PlatformSpec) -> Box:
    """Every place a platform can be: its route's bounding box, grown by its size."""
    xs = [x for x, _ in spec.path.points]
    ys = [y for _, y in spec.path.points]
    left, top = min(xs), min(ys)
    return Box(left, top, max(xs) - left + spec.width_px, max(ys) - top + spec.height_px)


@dataclass
class PlatformIndex:
    """Which platforms can be in which cells of the tile grid: a second layer over the tiles.

    A platform is filed once, when the level starts, in every in-map cell its route region
    covers (every place its route can take it). The tile grid's query looks up this layer
    in the same cells it visits for tiles (:meth:`TileGrid.entries_in`, on the grid a world
    makes with :meth:`TileGrid.with_movers`), so a query costs the platforms that can be
    near it, not every platform in the level; :meth:`near` tells the world which platforms
    a body could meet this tick. A platform whose route leaves the map is kept apart and
    tested by every query, since no cell holds the part of it out there.
    """

    grid: TileGrid
    platforms: Sequence[Platform] = ()
    # Keyed like the tiles: a flat list, the platforms of cell (col, row) at row * cols + col.
    cells: list[list[Platform] | None] = field(default_factory=list)
    outside: list[Platform] = field(default_factory=list)
    # The block of map every filed route region lies in: a body outside it is near none.
    bounds: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    # The same block grown to whole cells: a query whose region misses it visits no cell
    # this layer files anything in, so it need not look this layer up at all.
    cell_bounds: tuple[float, float, float, float] = (math.inf, math.inf, -math.inf, -math.inf)

    def __post_init__(self) -> None:
        for platform in self.platforms:
            self.file(platform)

    def file(self, platform: Platform) -> None:
        """Put the platform in the cells of its route region (the cells are made for the
        first one: a level with no platform on the map has none)."""
        grid = self.grid
        left, top, w, h = platform.region
        right, bottom = left + w, top + h
        if not (left >= 0 and right <= grid.width_px and top >= 0 and bottom <= grid.height_px):
            self.outside.append(platform)
            return
        if self.cells:
            low_x, low_y, high_x, high_y = self.bounds
            self.bounds = (min(low_x, left), min(low_y, top), max(high_x, right),
                           max(high_y, bottom))
        else:
            self.bounds = (left, top, right, bottom)
        first_col, end_col = math.floor(left / grid.tile_w), math.ceil(right / grid.tile_w)
        first_row, end_row = math.floor(top / grid.tile_h), math.ceil(bottom / grid.tile_h)
        if not self.cells:
            self.cells = [None] * (grid.cols * grid.rows)
        for row in range(first_row, end_row):
            for col in range(first_col, end_col):
                key = row * grid.cols + col
                bucket = self.cells[key]
                if bucket is None:
                    self.cells[key] = [platform]
                else:
                    bucket.append(platform)
        low_x, low_y, high_x, high_y = self.bounds
        self.cell_bounds = (math.floor(low_x / grid.tile_w) * grid.tile_w,
                            math.floor(low_y / grid.tile_h) * grid.tile_h,
                            math.ceil(high_x / grid.tile_w) * grid.tile_w,
                            math.ceil(high_y / grid.tile_h) * grid.tile_h)

    def near(self, boxes: Iterable[Box]) -> set[Platform]:
        """The platforms whose route region shares a cell with any of the boxes (and those
        off the map, which any box may meet)."""
        found: set[Platform] = set(self.outside)
        if not self.cells:
            return found
        grid, cells, cols = self.grid, self.cells, self.grid.cols
        low_x, low_y, high_x, high_y = self.bounds
        for x, y, w, h in boxes:
            if not (w > 0 and h > 0 and x <= high_x and low_x <= x + w and y <= high_y
                    and low_y <= y + h):
                continue  # nowhere near any route (or NaN)
            block = grid.block_covering(x, y, x + w, y + h)
            if block is None:
                continue
            first_col, last_col, first_row, last_row = block
            for row in range(first_row, last_row + 1):
                key = row * cols
                for col in range(first_col, last_col + 1):
                    filed = cells[key + col]
                    if filed is not None:
                        found.update(filed)
        return found

    def platform_of(self, shape: TileShape | None) -> Platform | None:
        """The platform a shape came from, if it is a platform's (``col == -1``, its number
        as ``row``)."""
        if shape is None or shape.col != -1:
            return None
        number = shape.row
        platforms = self.platforms
        if 0 <= number < len(platforms) and platforms[number].number == number:
            return platforms[number]
        return next((p for p in platforms if p.number == number), None)


@dataclass(frozen=True)
class SolidsWithout:
    """The world's solids less one platform: what that platform pushes and carries bodies
    against while it moves (it must not stop them itself)."""

    grid: TileGrid
    platform: Platform

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        return self.grid.entries_in(left, top, right, bottom, self.platform)
