"""Move a body one axis at a time and stop it flush at the first solid face it sweeps.

Where it sits: steps 3 and 4 of a tick (see :meth:`game.sim.world.World.step`). Entities only
set velocities; these functions are the only code that turns a velocity into a new position,
and they return what was hit so the entity can react (land, bump its head, turn round).

What it teaches:
  * **Separate x and y passes.** Moving on x and resolving, then on y and resolving, means
    each pass only has to answer "how far can I go along this one line?", and a floor under
    the feet can never stop a run across it (it only touches the body, it does not overlap).
  * **Sweep every move.** The region a body passes through in one axis step is the union of
    its old and new box. Every solid shape in that region is a candidate, and the nearest
    face in the direction of travel wins. Nothing passes through a one-tile wall at any
    speed, and there is no nudging one pixel at a time in a loop.
  * **Flush stops.** The body ends with its edge exactly on the face: touching, not
    overlapping, so the next tick starts clean.
  * **One-way platforms** only count when the body's bottom starts at or above their top.
  * **The ground probe** is a one-pixel strip under the feet; it reports ground only when a
    top face lies exactly at the feet, so standing still never flickers.
  * **Plain floats, few objects.** A sweep asks the solids for the entries in its region by
    four float edges (:meth:`TileGrid.entries_in`) and compares faces as floats; it makes
    one :class:`Move` (and a :class:`Hit` only when something stopped it). The region swept
    and the path travelled are worked out from the move when first asked for, and kept.
    Its new ``Box`` and ``Hit`` are made with ``tuple.__new__`` (``_new``): a NamedTuple's
    own constructor is a Python function, and skipping it is a measurable share of a move.

>>> from game.sim.tilegrid import TileGrid, TileShape, TileKind
>>> grid = TileGrid(cols=10, rows=4, tile_w=16, tile_h=16)
>>> grid.put(5, 0, TileShape(Box(80, 0, 16, 16), TileKind.SOLID))
>>> move = move_x(grid, Box(10, 2, 12, 12), 500.0)      # 500 px in one tick: still stops
>>> move.box.x, move.hit.side, move.hit.face
(68, <Side.RIGHT: 'right'>, 80)
"""

from __future__ import annotations

import math
from enum import Enum
from typing import NamedTuple

from game.collision.aabb import Box
from game.sim.tilegrid import Solids, TileKind, TileShape

GROUND_PROBE_PX = 1.0  # height of the strip under the feet that looks for ground
INF = math.inf
_new = tuple.__new__  # Box(...) or Hit(...) minus the Python-level __new__ of a NamedTuple

SOLID, ONE_WAY, HAZARD = TileKind.SOLID, TileKind.ONE_WAY, TileKind.HAZARD
Edges = tuple[float, float, float, float]  # left, top, right, bottom


class Side(Enum):
    """The side of the *moving body* that made contact."""

    LEFT = "left"
    RIGHT = "right"
    TOP = "top"        # head: a ceiling
    BOTTOM = "bottom"  # feet: a floor


class Hit(NamedTuple):
    """What stopped a move: the body's side, the face coordinate, and the shape.

    ``shape`` is None when the body stopped at the left or right edge of the map, which
    acts as a wall so nobody walks off the side of the world.
    """

    side: Side
    face: float
    shape: TileShape | None


class Move:
    """The result of one axis step: where the body ended, what it hit, where it started.

    :attr:`swept` is the region checked (the start box to the intended box); :attr:`path` is
    the region actually travelled (the start box to the final box), which is what triggers
    such as coins and spikes test. Both are worked out on first use and kept, so the coins,
    the contacts and the hazards of a tick share one path.
    """

    __slots__ = ("_path", "_swept", "box", "dx", "dy", "hit", "start")

    def __init__(self, box: Box, hit: Hit | None, start: Box, dx: float = 0.0,
                 dy: float = 0.0, swept: Box | None = None) -> None:
        self.box = box
        self.hit = hit
        self.start = start
        self.dx, self.dy = dx, dy  # the step asked for
        self._swept = swept
        self._path: Edges | None = None

    def __repr__(self) -> str:
        return f"Move(box={self.box}, hit={self.hit}, start={self.start})"

    @property
    def swept(self) -> Box:
        if self._swept is None:
            self._swept = self.start.union(self.start.moved(self.dx, self.dy))
        return self._swept

    @property
    def path_edges(self) -> Edges:
        """The path's left, top, right and bottom edges, as plain floats."""
        if self._path is None:
            x0, y0, w0, h0 = self.start
            x1, y1, w1, h1 = self.box
            self._path = (min(x0, x1), min(y0, y1), max(x0 + w0, x1 + w1),
                          max(y0 + h0, y1 + h1))
        return self._path

    @property
    def path(self) -> Box:
        left, top, right, bottom = self.path_edges
        return Box(left, top, right - left, bottom - top)


def _refuse(delta: float) -> None:
    raise ValueError(f"a step must be a finite number of pixels, not {delta}")


def move_x(grid: Solids, box: Box, dx: float) -> Move:
    """Move ``box`` by ``dx`` along x, stopping flush at the nearest solid face or map edge."""
    if not -INF < dx < INF:  # NaN fails this too
        _refuse(dx)
    if dx == 0:
        return Move(box, None, box, swept=box)
    x, y, w, h = box
    right = x + w
    found: TileShape | None = None
    if dx > 0:
        stop = right + dx
        for face, _, _, _, kind, shape in grid.entries_in(x, y, stop, y + h):
            if kind is SOLID and right <= face < stop:
                stop, found = face, shape
        hit = None if found is None else _new(Hit, (Side.RIGHT, stop, found))
        width = grid.width_px
        if right <= width < stop:
            stop, hit = width, Hit(Side.RIGHT, width, None)
        return Move(_new(Box, (stop - w, y, w, h)), hit, box, dx)
    stop = x + dx
    for _, _, face, _, kind, shape in grid.entries_in(stop, y, right, y + h):
        if kind is SOLID and stop < face <= x:
            stop, found = face, shape
    hit = None if found is None else _new(Hit, (Side.LEFT, stop, found))
    if stop < 0 <= x:
        stop, hit = 0, Hit(Side.LEFT, 0, None)
    return Move(_new(Box, (stop, y, w, h)), hit, box, dx)


def move_y(grid: Solids, box: Box, dy: float, *, through_one_way: bool = False) -> Move:
    """Move ``box`` by ``dy`` along y (down is positive), stopping flush at the nearest face.

    Going down, solid tops and one-way tops that start at or below the feet stop the body
    (one-way tops are skipped when ``through_one_way`` is set, to drop through them).
    Going up, only solid bottoms do. The map has no floor and no ceiling of its own.
    """
    if not -INF < dy < INF:
        _refuse(dy)
    if dy == 0:
        return Move(box, None, box, swept=box)
    x, y, w, h = box
    bottom = y + h
    found: TileShape | None = None
    if dy > 0:
        stop = bottom + dy
        for _, face, _, _, kind, shape in grid.entries_in(x, y, x + w, stop):
            if ((kind is SOLID or (kind is ONE_WAY and not through_one_way))
                    and bottom <= face < stop):
                stop, found = face, shape
        hit = None if found is None else _new(Hit, (Side.BOTTOM, stop, found))
        return Move(_new(Box, (x, stop - h, w, h)), hit, box, 0.0, dy)
    stop = y + dy
    for _, _, _, face, kind, shape in grid.entries_in(x, stop, x + w, bottom):
        if kind is SOLID and stop < face <= y:
            stop, found = face, shape
    hit = None if found is None else _new(Hit, (Side.TOP, stop, found))
    return Move(_new(Box, (x, stop, w, h)), hit, box, 0.0, dy)


def slide_past_ceiling_corner(grid: Solids, box: Box, dy: float,
                              max_px: float) -> tuple[Move, Move] | None:
    """Corner correction: a rise blocked by a ceiling's corner by ``max_px`` or less slides past.

    Returns the sideways move and the rise from there, or None when no slide of at most
    ``max_px`` (the smaller one first; left first on a tie) is free and lets the rise go on.

    >>> from game.sim.tilegrid import TileGrid, TileShape, TileKind
    >>> grid = TileGrid(cols=10, rows=10, tile_w=16, tile_h=16)
    >>> grid.put(3, 2, TileShape(Box(48, 32, 16, 16), TileKind.SOLID))
    >>> side, rise = slide_past_ceiling_corner(grid, Box(37, 50, 12, 14), -10.0, 4.0)
    >>> side.box.x, rise.box.y, rise.hit
    (36, 40.0, None)
    """
    blocked = move_y(grid, box, dy)
    if blocked.hit is None or blocked.hit.side is not Side.TOP or blocked.hit.shape is None:
        return None
    ceiling = blocked.hit.shape.box
    shifts = sorted((ceiling.left - box.right, ceiling.right - box.left), key=abs)
    for shift in shifts:
        if shift == 0 or abs(shift) > max_px:
            continue
        side = move_x(grid, box, shift)
        if side.hit is not None:
            continue
        rise = move_y(grid, side.box, dy)
        if rise.box.top < blocked.box.top:
            return side, rise
    return None


def ground_under(grid: Solids, box: Box, *, through_one_way: bool = False,
                 ) -> TileShape | None:
    """The solid or one-way shape whose top lies exactly at the feet, if any (the probe)."""
    x, y, w, h = box
    feet = y + h
    for _, top, _, _, kind, shape in grid.entries_in(x, feet, x + w, feet + GROUND_PROBE_PX):
        if top != feet or kind is HAZARD or (kind is ONE_WAY and through_one_way):
            continue
        return shape
    return None


def touching(grid: Solids, box: Box, kind: TileKind) -> list[TileShape]:
    """The shapes of one kind that overlap the box (hazards, for instance)."""
    x, y, w, h = box
    return [entry[5] for entry in grid.entries_in(x, y, x + w, y + h) if entry[4] is kind]


def penetration_depth(grid: Solids, box: Box) -> float:
    """How deep the box sits inside any solid shape: 0.0 after a correct resolution."""
    return max((box.penetration(s.box) for s in touching(grid, box, TileKind.SOLID)),
               default=0.0)


def nearest_free_place(grid: Solids, box: Box, search_px: float = 64.0) -> Box:
    """The closest position to ``box`` where it overlaps no solid: a spawn inside a wall.

    Around axis-aligned walls the nearest free position has each coordinate either where it
    was or flush with some wall face, so only those combinations are tried; the window grows
    until one is free. Ties go to the higher, then the more left, position.

    >>> from game.sim.tilegrid import TileGrid, TileShape, TileKind
    >>> grid = TileGrid(cols=10, rows=10, tile_w=16, tile_h=16)
    >>> for col in range(10):
    ...     grid.put(col, 5, TileShape(Box(col * 16, 80, 16, 16), TileKind.SOLID))
    >>> nearest_free_place(grid, Box(40, 70, 12, 14))    # sunk 4 px into a floor: up it goes
    Box(x=40, y=66, w=12, h=14)
    """
    if penetration_depth(grid, box) == 0.0:
        return box
    limit = max(grid.width_px, grid.height_px) + box.w + box.h
    while True:
        window = Box(box.x - search_px, box.y - search_px,
                     box.w + 2 * search_px, box.h + 2 * search_px)
        solids = touching(grid, window, TileKind.SOLID)
        xs = {box.x} | {s.box.left - box.w for s in solids} | {s.box.right for s in solids}
        ys = {box.y} | {s.box.top - box.h for s in solids} | {s.box.bottom for s in solids}
        free = [box._replace(x=x, y=y) for x in xs for y in ys
                if penetration_depth(grid, box._replace(x=x, y=y)) == 0.0]
        if free:
            return min(free, key=lambda b: ((b.x - box.x) ** 2 + (b.y - box.y) ** 2, b.y, b.x))
        if search_px > limit:
            return box._replace(y=-box.h)  # a map solid everywhere: stand on top of it
        search_px *= 2
