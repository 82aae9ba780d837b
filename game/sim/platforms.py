"""Moving platforms: solids that follow a path drawn in Tiled, carrying and pushing bodies.

Where it sits: step 2 of a tick, before the bodies' own moves (:meth:`World.step`). Each
platform advances along its path, one axis at a time, and does two things to bodies:

* a body in its way is **pushed** to the platform's leading face, through the same swept
  move as any other step, so a wall stops it; if the wall leaves it no room, it is crushed
  (:func:`push`: a body with room ends exactly flush against the face, so no rounding in
  the move can leave it a hair inside the platform and cost a life);
* a body **riding** it (its feet found the platform with the ground probe last tick) is
  **carried** by the same amount, again through the swept move, so a ride never passes
  through a wall either.

Then, for the bodies' own moves, the platforms are simply more solid shapes: a second
:class:`~game.collision.shapes.ShapeSource` (:class:`PlatformIndex`, each platform filed
once in the tile cells its route can reach), asked beside the tile grid by
:class:`game.sim.solids.LevelSolids`, so the swept moves of :mod:`game.collision.axis_sweep`
need no special case and a query costs the platforms near it, not every platform in the
level.

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
from game.collision.axis_sweep import move_x, move_y
from game.collision.shapes import Entry, ShapeSource, TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.sprite import Anchor, BoxSprite

Point = tuple[float, float]
FEW_PLATFORMS = 8  # up to this many on the map, a query tests each route's block of cells


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
    """A moving solid. Where it is is a function of how far it has travelled along its
    route, ``travelled_px``: only :meth:`advance` (called by the tick) changes that, and
    ``box`` (exact), ``rect``, ``shape`` and ``entry`` are worked out from it.

    A platform no body is near costs the tick one addition (:meth:`advance`); its box is
    worked out from the distance the first time anything reads it after that, and kept
    until it travels on. Reading it never moves it: it is where its distance says.
    """

    anchor = Anchor.TOP_LEFT
    travelled_px = 0.0  # how far along its route it has gone

    def __init__(self, spec: PlatformSpec, number: int) -> None:
        self.spec = spec
        self.number = number
        self.speed_px_s = spec.speed_px_s  # read by every tick's advance, of every platform
        self._entry_at: tuple[float, Entry] | None = None  # the distance it was made for
        super().__init__(self.box_at(0.0))
        self.region = route_region(spec)

    def box_at(self, travelled_px: float) -> Box:
        """Where the platform is after ``travelled_px`` along its route."""
        x, y = self.spec.path.point_at(travelled_px)
        return Box(x, y, self.spec.width_px, self.spec.height_px)

    @property
    def box(self) -> Box:
        return self.entry.shape.box

    @box.setter
    def box(self, box: Box) -> None:
        """Only :class:`BoxSprite` sets it, at the start: the route says where it is."""

    @property
    def entry(self) -> Entry:
        """The box as plain floats, for the queries (a platform's shape has ``col == -1``
        and the platform's number as ``row``)."""
        made = self._entry_at
        if made is None or made[0] != self.travelled_px:
            shape = TileShape(self.box_at(self.travelled_px), TileKind.SOLID, col=-1,
                              row=self.number)
            made = self._entry_at = (self.travelled_px, Entry.of(shape))
        return made[1]

    @property
    def shape(self) -> TileShape:
        return self.entry.shape

    def advance(self, dt_s: float) -> None:
        """Travel on along the route for one tick."""
        self.travelled_px += self.speed_px_s * dt_s


def flush_before(face: float, size: float) -> float:
    """Where a box of ``size`` starts to end exactly at ``face`` without crossing it:
    ``face - size``, or the float just below when rounding would put its end past the face.

    >>> flush_before(58.0, 12.0), flush_before(0.1, 0.3) + 0.3 <= 0.1
    (46.0, True)
    """
    start = face - size
    while start + size > face:  # only when rounding carried the end past the face
        start = math.nextafter(start, -math.inf)
    return start


def push(solids: ShapeSource, body: Box, pusher: Box, axis: str, step: float,
         ) -> tuple[Box, bool]:
    """Where a body in a moving pusher's way ends, and whether it is crushed.

    ``pusher`` is where the platform now is, having moved ``step`` px along ``axis`` (``"x"``
    or ``"y"``). The body's goal is the box flush against the pusher's leading face, worked
    out from that face alone; it is swept there against ``solids`` (the level less the
    pusher). With room it ends exactly at its goal, touching the face and not overlapping
    it. It is crushed only when a wall stops it short of the goal, and then it stays
    flush against that wall.

    >>> from game.collision.tile_grid import TileGrid
    >>> walls = TileGrid(cols=10, rows=4, tile_w=16, tile_h=16)
    >>> push(walls, Box(56, 0, 12, 14), Box(42.00000000000001, 0, 16, 64), "x", 2.0)
    (Box(x=58.00000000000001, y=0, w=12, h=14), False)
    >>> push(walls, Box(140, 0, 12, 14), Box(138, 0, 16, 64), "x", 2.0)   # the map's edge
    (Box(x=148, y=0, w=12, h=14), True)
    """
    x, y, w, h = body
    if axis == "x":
        goal = (Box(pusher.right, y, w, h) if step > 0
                else Box(flush_before(pusher.left, w), y, w, h))
        move = move_x(solids, body, goal.x - x)
    else:
        goal = (Box(x, pusher.bottom, w, h) if step > 0
                else Box(x, flush_before(pusher.top, h), w, h))
        move = move_y(solids, body, goal.y - y)
    hit = move.hit
    if hit is None:
        return goal, False
    # Stopped: short of the goal is a crush; a wall exactly at the goal's far side is room.
    if axis == "x":
        short = hit.face < goal.right if step > 0 else hit.face > goal.left
    else:
        short = hit.face < goal.bottom if step > 0 else hit.face > goal.top
    return (move.box, True) if short else (goal, False)


def route_region(spec: PlatformSpec) -> Box:
    """Every place a platform can be: its route's bounding box, grown by its size."""
    xs = [x for x, _ in spec.path.points]
    ys = [y for _, y in spec.path.points]
    left, top = min(xs), min(ys)
    return Box(left, top, max(xs) - left + spec.width_px, max(ys) - top + spec.height_px)


@dataclass
class PlatformIndex:
    """Which platforms can be in which cells of the tile grid: a source of moving shapes.

    A platform is filed once, when the level starts, in every in-map cell its route region
    covers (every place its route can take it). A query (:meth:`entries_in`) looks in the
    cells the region covers, so it costs the platforms that can be near it, not every
    platform in the level; :meth:`near` tells the world which platforms a body could meet
    this tick. A platform whose route leaves the map is kept apart and tested by every
    query, since no cell holds the part of it out there.

    Two ways find the platforms near a region, and find the same ones
    (``tests/test_platforms.py`` compares them): :meth:`routes_touching` tests each route's
    block of cells, one by one, and :meth:`cells_touching` walks the cells the region
    covers. With a handful of platforms on the map (up to :data:`FEW_PLATFORMS`) the first
    does less work (a few route tests against a walk of every cell covered), so it is the
    one used; with more, the second.
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
        self.tile_w, self.tile_h, self.cols = self.grid.tile_w, self.grid.tile_h, self.grid.cols
        self.routes: list[tuple[float, float, float, float, Platform]] = []
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
        route_left, route_top, route_right, route_bottom = self.cell_block(left, top, right, bottom)
        if route_right > route_left and route_bottom > route_top:
            self.routes.append((route_left, route_top, route_right, route_bottom, platform))
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

    def cell_block(self, left: float, top: float, right: float, bottom: float,
                   ) -> tuple[float, float, float, float]:
        """The region grown to whole cells: the cells it is filed in, as edges."""
        tile_w, tile_h = self.tile_w, self.tile_h
        return (math.floor(left / tile_w) * tile_w, math.floor(top / tile_h) * tile_h,
                math.ceil(right / tile_w) * tile_w, math.ceil(bottom / tile_h) * tile_h)

    def few_routes(self) -> list[tuple[float, float, float, float, Platform]] | None:
        """Each route's block of cells (left, top, right, bottom) and its platform, when a
        query tests those one by one (up to :data:`FEW_PLATFORMS`, none off the map); else
        None."""
        return None if self.outside or len(self.routes) > FEW_PLATFORMS else self.routes

    def near(self, boxes: Iterable[Box]) -> set[Platform]:
        """The platforms whose route region shares a cell with any of the boxes (and those
        off the map, which any box may meet)."""
        found: set[Platform] = set(self.outside)
        low_x, low_y, high_x, high_y = self.bounds
        # the way to find them, chosen once for all the boxes
        touching = self.routes_touching if self.few_routes() is not None else self.cells_touching
        for x, y, w, h in boxes:
            if not (self.cells and w > 0 and h > 0 and x <= high_x and low_x <= x + w
                    and y <= high_y and low_y <= y + h):
                continue  # nowhere near any route (or NaN)
            found.update(touching(x, y, x + w, y + h))
        return found

    def routes_touching(self, left: float, top: float, right: float, bottom: float,
                        ) -> list[Platform]:
        """The platforms whose route's block of cells the region overlaps (strictly), in the
        order of their numbers: each route tested in turn."""
        return [platform for r_left, r_top, r_right, r_bottom, platform in self.routes
                if left < r_right and r_left < right and top < r_bottom and r_top < bottom]

    def cells_touching(self, left: float, top: float, right: float, bottom: float,
                       ) -> list[Platform]:
        """The platforms filed in the cells the region covers, in the order of their
        numbers: those cells walked in turn (no further than the cells that hold a
        platform, so finite and on the map)."""
        low_x, low_y, high_x, high_y = self.cell_bounds
        block = self.grid.block_covering(max(left, low_x), max(top, low_y),
                                         min(right, high_x), min(bottom, high_y))
        found: set[Platform] = set()
        if block is not None:
            first_col, last_col, first_row, last_row = block
            for row in range(first_row, last_row + 1):
                for col in range(first_col, last_col + 1):
                    found.update(self.cells[row * self.cols + col] or ())
        return sorted(found, key=_number)

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def tested_in(self, left: float, top: float, right: float, bottom: float,
                  leaving_out: Platform | None = None) -> list[Platform]:
        """The platforms a query of the region tests: those near it on the map
        (:meth:`routes_touching` with a handful, else :meth:`cells_touching`), in the order
        of their numbers, then those off the map; ``leaving_out`` is skipped."""
        low_x, low_y, high_x, high_y = self.cell_bounds
        if not (left < high_x and low_x < right and top < high_y and low_y < bottom):
            near: list[Platform] = []  # far from every route on the map
        elif len(self.routes) <= FEW_PLATFORMS:
            near = self.routes_touching(left, top, right, bottom)
        else:
            near = self.cells_touching(left, top, right, bottom)
        if self.outside:
            near = [*near, *self.outside]
        # a new list only when one is left out (the bodies' own moves leave out none)
        return near if leaving_out is None else [p for p in near if p is not leaving_out]

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   leaving_out: Platform | None = None) -> list[Entry]:
        """The platforms that overlap the region (strictly), as entries (see
        :meth:`tested_in` for which are tested, and in what order)."""
        if not (right > left and bottom > top):  # empty (or NaN): overlaps nothing
            return []
        found: list[Entry] = []
        for platform in self.tested_in(left, top, right, bottom, leaving_out):
            e_left, e_top, e_right, e_bottom, _, _ = entry = platform.entry
            if (e_left < right and left < e_right and e_top < bottom and top < e_bottom
                    and e_right > e_left and e_bottom > e_top):
                found.append(entry)
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


def _number(platform: Platform) -> int:
    return platform.number
