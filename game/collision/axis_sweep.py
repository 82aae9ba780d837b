"""Move a body through the level: along x, then along y, stopping flush at the first solid
face each pass sweeps, then look for ground under its feet.

Where it sits: the collision path the game runs. :func:`move_body` is steps 3 and 4 of a
tick (:meth:`game.sim.world.World.step`) for every body: the x pass (:func:`move_x`), the
y pass (:func:`move_y`, with :func:`slide_past_ceiling_corner` when a rise clips a
ceiling's corner), and the ground probe (:func:`ground_under`). The moving platforms push
and carry bodies with the same two moves. Entities only set velocities; these functions
work out where a velocity takes a body, and return what was hit so the entity can react.
Start reading here, at :func:`move_body`.

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
  * **Corner correction.** A jump that clips a ceiling's corner by a few pixels slides past
    it instead of stopping dead.
  * **The ground probe** is a one-pixel strip under the feet; it reports ground only when a
    top face lies exactly at the feet, so standing still never flickers.

Each move asks its :class:`~game.collision.shapes.ShapeSource` once, for the region it
sweeps, and returns a :class:`Move`: where the box ended, what stopped it (a :class:`Hit`),
where it started. Each answer is an :class:`~game.collision.shapes.Entry`, unpacked into
names in the order of its fields (``s_left, s_top, s_right, s_bottom, kind, shape``, the
``s`` for shape), of which a move keeps the one face it travels towards: ``s_left`` moving
right, ``s_right`` moving left, ``s_top`` falling, ``s_bottom`` rising. ``front`` is the
moving side of the body: where it would end with nothing in the way, then each nearer face.

>>> from game.collision.tile_grid import TileGrid
>>> grid = TileGrid(cols=10, rows=4, tile_w=16, tile_h=16)
>>> grid.put(5, 0, TileShape(Box(80, 0, 16, 16), TileKind.SOLID))
>>> move = move_x(grid, Box(10, 2, 12, 12), 500.0)      # 500 px in one tick: still stops
>>> move.box.x, move.hit.side, move.hit.face
(68, <Side.RIGHT: 'right'>, 80)
>>> for col in range(10):                                # a floor along the bottom row
...     grid.put(col, 3, TileShape(Box(col * 16, 48, 16, 16), TileKind.SOLID, col, 3))
>>> moves = move_body(grid, Box(10, 20, 12, 14), 30.0, 40.0)
>>> moves.x.box.x, moves.y.box.y, moves.y.hit.side, moves.ground is moves.y.hit.shape
(40.0, 34, <Side.BOTTOM: 'bottom'>, True)
"""

from __future__ import annotations

import math
from enum import Enum
from typing import NamedTuple

from game.collision.aabb import Box
from game.collision.shapes import ShapeSource, TileKind, TileShape

GROUND_PROBE_PX = 1.0  # height of the strip under the feet that looks for ground
SKY_LIMIT_PX = 1_000_000.0  # how far above the map a body may fly before the sky stops it
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
    """The result of one axis step: where the box ended, what it hit, where it started.

    :attr:`swept` is the region checked (the start box to the intended box), worked out
    when first read; :attr:`path` is the region actually travelled (the start box to the
    final box), which is what triggers such as coins and spikes test, and
    :attr:`path_edges` its left, top, right and bottom edges, as plain floats.
    """

    __slots__ = ("_path", "_swept", "box", "dx", "dy", "hit", "start")

    def __init__(self, box: Box, hit: Hit | None, start: Box, dx: float = 0.0,
                 dy: float = 0.0, swept: Box | None = None) -> None:
        self.box, self.hit, self.start = box, hit, start
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
        """The path's left, top, right and bottom edges, worked out when first read."""
        if self._path is None:
            (x0, y0, w0, h0), (x1, y1, w1, h1) = self.start, self.box
            self._path = (min(x0, x1), min(y0, y1), max(x0 + w0, x1 + w1), max(y0 + h0, y1 + h1))
        return self._path

    @property
    def path(self) -> Box:
        left, top, right, bottom = self.path_edges
        return Box(left, top, right - left, bottom - top)

    def followed_by(self, later: Move) -> Move:
        """This move and a later one on the same axis as one: from this start to the later
        end, over both swept regions, keeping what this one hit (a corner slide)."""
        return Move(later.box, self.hit, self.start, swept=self.swept.union(later.swept))


class BodyMoves(NamedTuple):
    """One body's moves in one tick (:func:`move_body`): along x, then along y from where
    that ended, and the shape the feet stand on after both (None in the air)."""

    x: Move
    y: Move
    ground: TileShape | None = None

    def path_edges(self) -> Edges:
        """Left, top, right and bottom of all this tick's path: a first, cheap test before
        :meth:`crosses`."""
        left, top, right, bottom = self.x.path_edges
        left_y, top_y, right_y, bottom_y = self.y.path_edges
        return (min(left, left_y), min(top, top_y), max(right, right_y),
                max(bottom, bottom_y))

    def crosses(self, region: Box) -> bool:
        """Did this tick's path (the x step, then the y step) overlap ``region``?

        Testing the path, not just the final box, means a fast body cannot skip over a coin
        or a spike in one tick: the trigger version of "sweep every move".
        """
        x, y, w, h = region
        if not (w > 0 and h > 0):
            return False
        right, bottom = x + w, y + h
        for move in (self.x, self.y):
            left, top, p_right, p_bottom = move.path_edges
            if left < right and x < p_right and top < bottom and y < p_bottom:
                return True
        return False


def move_body(solids: ShapeSource, box: Box, dx: float, dy: float, *,
              through_one_way: bool = False, corner_px: float = 0.0) -> BodyMoves:
    """A body's whole move in one tick: the x pass, the y pass, the ground probe.

    The y pass starts where the x pass stopped. A rise that hits a ceiling's corner by at
    most ``corner_px`` slides past it (the slide sideways joins the x move). Below the map
    is the void and far above it (:data:`SKY_LIMIT_PX`) the sky ends, so a body flung at any
    speed keeps coordinates a Rect can hold. The feet then stand on the floor the y move
    landed on, or else on what the one-pixel probe finds.
    """
    x_move = move_x(solids, box, dx)
    y_move = move_y(solids, x_move.box, dy, through_one_way=through_one_way)
    if corner_px and y_move.hit is not None and y_move.hit.side is Side.TOP:
        slid = slide_past_ceiling_corner(solids, x_move.box, dy, corner_px)
        if slid is not None:
            x_move, y_move = x_move.followed_by(slid.side), slid.rise
    x, y, w, h = y_move.box
    if not -SKY_LIMIT_PX <= y <= solids.height_px:
        y = min(max(y, -SKY_LIMIT_PX), float(solids.height_px))
        y_move = Move(Box(x, y, w, h), y_move.hit, y_move.start, y_move.dx, y_move.dy)
    landed = y_move.hit if dy > 0 else None  # what stopped a fall: a floor
    if landed is not None and landed.face == y + h:
        ground = landed.shape  # the fall found the floor at the feet: no probe needed
    else:
        ground = ground_under(solids, y_move.box, through_one_way=through_one_way)
    return BodyMoves(x_move, y_move, ground)


def _refuse(delta: float) -> None:
    raise ValueError(f"a step must be a finite number of pixels, not {delta}")


def move_x(solids: ShapeSource, box: Box, dx: float) -> Move:
    """Move ``box`` by ``dx`` along x, stopping flush at the nearest solid face or map edge."""
    if not -math.inf < dx < math.inf:  # NaN fails this too
        _refuse(dx)
    if dx == 0:
        return Move(box, None, box, swept=box)
    x, y, w, h = box
    right = x + w
    found: TileShape | None = None
    if dx > 0:  # moving right: the nearest left face ahead of the body's right edge
        front = right + dx
        for s_left, _, _, _, kind, shape in solids.entries_in(x, y, front, y + h):
            if right <= s_left < front and kind is TileKind.SOLID:
                front, found = s_left, shape
        hit = None if found is None else Hit(Side.RIGHT, front, found)
        width = solids.width_px
        if right <= width < front:
            front, hit = width, Hit(Side.RIGHT, width, None)
        return Move(Box(front - w, y, w, h), hit, box, dx)
    front = x + dx  # moving left: the nearest right face behind the body's left edge
    for _, _, s_right, _, kind, shape in solids.entries_in(front, y, right, y + h):
        if front < s_right <= x and kind is TileKind.SOLID:
            front, found = s_right, shape
    hit = None if found is None else Hit(Side.LEFT, front, found)
    if front < 0 <= x:
        front, hit = 0, Hit(Side.LEFT, 0, None)
    return Move(Box(front, y, w, h), hit, box, dx)


def move_y(solids: ShapeSource, box: Box, dy: float, *, through_one_way: bool = False) -> Move:
    """Move ``box`` by ``dy`` along y (down is positive), stopping flush at the nearest face.

    Going down, solid tops and one-way tops that start at or below the feet stop the body
    (one-way tops are skipped when ``through_one_way`` is set, to drop through them); where
    tops meet at the height it stops at, the hit names a Solid before a OneWay, else the
    first the query found. Going up, only solid bottoms do. The map has no floor and no
    ceiling of its own.
    """
    if not -math.inf < dy < math.inf:
        _refuse(dy)
    if dy == 0:
        return Move(box, None, box, swept=box)
    x, y, w, h = box
    bottom = y + h
    found: TileShape | None = None
    if dy > 0:  # falling: the nearest top at or below the feet
        front = bottom + dy
        for _, s_top, _, _, kind, shape in solids.entries_in(x, y, x + w, front):
            if bottom <= s_top < front and (kind is TileKind.SOLID or (
                    kind is TileKind.ONE_WAY and not through_one_way)):
                front, found = s_top, shape
            elif (s_top == front and kind is TileKind.SOLID and found is not None
                    and found.kind is TileKind.ONE_WAY):
                found = shape  # a tie: a Solid top at the same height is the floor reported
        hit = None if found is None else Hit(Side.BOTTOM, front, found)
        return Move(Box(x, front - h, w, h), hit, box, 0.0, dy)
    front = y + dy  # rising: the nearest solid bottom at or above the head
    for _, _, _, s_bottom, kind, shape in solids.entries_in(x, front, x + w, bottom):
        if front < s_bottom <= y and kind is TileKind.SOLID:
            front, found = s_bottom, shape
    hit = None if found is None else Hit(Side.TOP, front, found)
    return Move(Box(x, front, w, h), hit, box, 0.0, dy)


class CornerSlide(NamedTuple):
    """A rise that slid past a ceiling's corner: the sideways move, then the rise from there."""

    side: Move
    rise: Move


def slide_past_ceiling_corner(solids: ShapeSource, box: Box, dy: float,
                              max_px: float) -> CornerSlide | None:
    """Corner correction: a rise blocked by a ceiling's corner by ``max_px`` or less slides past.

    Returns the sideways move and the rise from there, or None when no slide of at most
    ``max_px`` (the smaller one first; left first on a tie) is free and lets the rise go on.

    >>> from game.collision.tile_grid import TileGrid
    >>> grid = TileGrid(cols=10, rows=10, tile_w=16, tile_h=16)
    >>> grid.put(3, 2, TileShape(Box(48, 32, 16, 16), TileKind.SOLID))
    >>> slide = slide_past_ceiling_corner(grid, Box(37, 50, 12, 14), -10.0, 4.0)
    >>> slide.side.box.x, slide.rise.box.y, slide.rise.hit
    (36, 40.0, None)
    """
    blocked = move_y(solids, box, dy)
    if blocked.hit is None or blocked.hit.side is not Side.TOP or blocked.hit.shape is None:
        return None
    c_left, _, c_width, _ = blocked.hit.shape.box
    x, _, w, _ = box
    for shift in sorted((c_left - (x + w), c_left + c_width - x), key=abs):
        if shift == 0 or abs(shift) > max_px:
            continue
        side = move_x(solids, box, shift)
        if side.hit is not None:
            continue
        rise = move_y(solids, side.box, dy)
        if rise.box.y < blocked.box.y:
            return CornerSlide(side, rise)
    return None


def ground_under(solids: ShapeSource, box: Box, *, through_one_way: bool = False,
                 ) -> TileShape | None:
    """The solid or one-way shape whose top lies exactly at the feet, if any (the probe);
    a Solid before a OneWay, so feet partly on a Solid stand on it."""
    x, y, w, h = box
    feet = y + h
    one_way: TileShape | None = None
    for _, s_top, _, _, kind, shape in solids.entries_in(x, feet, x + w, feet + GROUND_PROBE_PX):
        if s_top != feet or kind is TileKind.HAZARD or (
                kind is TileKind.ONE_WAY and through_one_way):
            continue
        if kind is TileKind.SOLID:
            return shape
        if one_way is None:
            one_way = shape
    return one_way
