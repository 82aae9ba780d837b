"""Moving platforms: solids that follow a path drawn in Tiled, carrying and pushing bodies.

Where it sits: step 2 of a tick, before the bodies' own moves (:meth:`World.step`). Each
platform advances along its path, one axis at a time, and does two things to bodies:

* a body in its way is **pushed** to the platform's leading face, through the same swept
  move as any other step, so a wall stops it; if the wall leaves it no room, it is crushed;
* a body **riding** it (its feet found the platform with the ground probe last tick) is
  **carried** by the same amount, again through the swept move, so a ride never passes
  through a wall either.

Then, for the bodies' own moves, the platforms are simply more solid shapes:
:class:`SolidsWithPlatforms` answers region queries with the tile grid's shapes plus the
platforms', so :mod:`game.sim.movement` needs no special case. The platforms are found
through the grid's own cells (:class:`PlatformIndex`, a second layer that a platform is
refiled in only when it crosses a cell border), so a query costs the platforms near it,
not every platform in the level.

>>> path = Route(((0.0, 0.0), (30.0, 0.0)), loop=False)
>>> [path.point_at(d) for d in (0.0, 10.0, 30.0, 40.0, 60.0)]    # there and back again
[(0.0, 0.0), (10.0, 0.0), (30.0, 0.0), (20.0, 0.0), (0.0, 0.0)]
"""

from __future__ import annotations

import math
from collections.abc import Sequence
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
    """A moving solid. ``box`` is exact; its picture fills the box (its hitbox is its look)."""

    anchor = Anchor.TOP_LEFT

    def __init__(self, spec: PlatformSpec, number: int) -> None:
        x, y = spec.path.point_at(0.0)
        super().__init__(Box(x, y, spec.width_px, spec.height_px))
        self.spec = spec
        self.number = number
        self.travelled_px = 0.0
        self._follow_box()

    def next_step(self, dt_s: float) -> tuple[float, float]:
        """The (dx, dy) this platform moves in the coming tick."""
        self.travelled_px += self.spec.speed_px_s * dt_s
        x, y = self.spec.path.point_at(self.travelled_px)
        return x - self.box.x, y - self.box.y

    def place(self, box: Box) -> None:
        """Set the exact position; the picture, the shape and its plain-float entry follow."""
        super().place(box)
        self._follow_box()

    def _follow_box(self) -> None:
        self.shape = TileShape(self.box, TileKind.SOLID, col=-1, row=self.number)
        self.entry: Entry = entry_of(self.shape)


@dataclass
class PlatformIndex:
    """Which platforms lie in which cells of the tile grid: a second layer over the tiles.

    A platform is filed in every in-map cell its box overlaps, and refiled only when that
    block of cells changes. The tile grid's query looks up this layer in the same cells it
    visits for tiles (:meth:`TileGrid.entries_in`), so a query costs the platforms near it,
    not every platform in the level. A platform that reaches outside the map is kept apart
    and tested by every query, since no cell holds the part of it out there.
    """

    grid: TileGrid
    cells: dict[int, list[Platform]] = field(default_factory=dict)
    outside: list[Platform] = field(default_factory=list)
    _spans: dict[int, tuple[int, int, int, int] | None] = field(default_factory=dict)

    def file(self, platform: Platform) -> None:
        """Put the platform in the cells of its current box (after it moved)."""
        grid = self.grid
        left, top, right, bottom = platform.entry[:4]
        span: tuple[int, int, int, int] | None = None  # outside the map: no cells
        if left >= 0 and right <= grid.width_px and top >= 0 and bottom <= grid.height_px:
            span = (math.floor(left / grid.tile_w), math.ceil(right / grid.tile_w) - 1,
                    math.floor(top / grid.tile_h), math.ceil(bottom / grid.tile_h) - 1)
        number = platform.number
        if number in self._spans and self._spans[number] == span:
            return  # still in the same cells: nothing to refile
        for key in _keys(self._spans.get(number), grid.cols):
            self.cells[key].remove(platform)
        if platform in self.outside:
            self.outside.remove(platform)
        for key in _keys(span, grid.cols):
            here = self.cells.setdefault(key, [])
            here.append(platform)
            here.sort(key=_number)
        if span is None:
            self.outside.append(platform)
            self.outside.sort(key=_number)
        self._spans[number] = span


def _keys(span: tuple[int, int, int, int] | None, cols: int) -> list[int]:
    if span is None:
        return []
    first_col, last_col, first_row, last_row = span
    return [row * cols + col for row in range(first_row, last_row + 1)
            for col in range(first_col, last_col + 1)]


def _number(platform: Platform) -> int:
    return platform.number


@dataclass
class SolidsWithPlatforms:
    """The tile grid plus moving platforms, behind the one query the movement code makes."""

    grid: TileGrid
    platforms: Sequence[Platform]
    ignored: Platform | None = None  # the platform that is itself moving right now
    index: PlatformIndex | None = None

    def __post_init__(self) -> None:
        if self.index is None:
            self.index = PlatformIndex(self.grid)
            for platform in self.platforms:
                self.index.file(platform)

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def moved(self, platform: Platform) -> None:
        """Refile a platform that has just moved."""
        assert self.index is not None
        self.index.file(platform)

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        """The tile grid's entries in the region, then the platforms' (by number)."""
        index = self.index
        assert index is not None
        found = self.grid.entries_in(left, top, right, bottom, index.cells, self.ignored)
        if index.outside and right > left and bottom > top:
            tested = [p for p in index.outside if p is not self.ignored]
            found.extend(p.entry for p in tested if _overlaps(p.entry, left, top, right, bottom))
            self.grid.stats.shapes_tested += len(tested)
            if self.grid.log is not None:
                self.grid.log.add_extra(tuple(p.shape for p in tested))
        return found

    def shapes_in(self, region: Box) -> list[TileShape]:
        x, y, w, h = region
        return [entry[5] for entry in self.entries_in(x, y, x + w, y + h)]

    def without(self, platform: Platform) -> SolidsWithPlatforms:
        return SolidsWithPlatforms(self.grid, self.platforms, platform, self.index)


    def platform_of(self, shape: TileShape | None) -> Platform | None:
        """The platform a shape came from, if it is a platform's."""
        if shape is None or shape.col != -1:
            return None
        number = shape.row
        if 0 <= number < len(self.platforms) and self.platforms[number].number == number:
            return self.platforms[number]
        return next((p for p in self.platforms if p.number == number), None)


def _overlaps(entry: Entry, left: float, top: float, right: float, bottom: float) -> bool:
    return (entry[0] < right and left < entry[2] and entry[1] < bottom and top < entry[3]
            and entry[2] > entry[0] and entry[3] > entry[1])
