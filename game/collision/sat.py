"""The separating axis theorem: convex polygons and rotated boxes, with the push that parts them.

Where it sits: pure geometry, beside :mod:`game.collision.aabb` and :mod:`game.collision.circles`.
The tiles are
axis-aligned, so the game's movement never needs this; it is here for rotated things (a
swinging bar, a tilted platform) and as the exact answer AABB approximations are judged by.

What it teaches:
  * **The theorem.** Two convex shapes are apart exactly when some line separates them, and
    for polygons that line can always be found parallel to one of their edges. So project
    both shapes onto the normal of every edge; if on any of those axes the two shadows do not
    overlap, the shapes do not either. If every shadow overlaps, they collide.
  * **The minimum translation vector (MTV).** On each axis the overlap says how far ``a``
    would have to move, one way or the other, to clear ``b``. The smallest such push over
    all axes is the MTV: the shortest move that separates the shapes (they end up touching).
  * **Strict, like every shape here.** Shadows that only touch (overlap of exactly 0) count
    as apart, so polygons that share an edge or a corner do not collide.
  * **Only for convex polygons**, so :class:`Polygon` checks its points and says what is wrong.

Coordinates are screen coordinates (y grows downwards); an angle turns clockwise on screen.

>>> square = Polygon.from_box(Box(0, 0, 10, 10))
>>> collide(square, Polygon.from_box(Box(10, 0, 10, 10)))     # sharing an edge: apart
>>> collide(square, Polygon.from_box(Box(8, 1, 10, 10)))      # push a 2 px to the left
Mtv(nx=-1.0, ny=0.0, depth=2.0)
>>> diamond = oriented_box(0, 0, 5, 5, math.pi / 4)           # a square turned 45 degrees
>>> collide(diamond, Polygon.from_box(Box(4, -10, 10, 20))) is not None
True
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import NamedTuple

from game.collision.aabb import Box

Point = tuple[float, float]


class Mtv(NamedTuple):
    """The minimum translation vector: move ``a`` by ``depth`` along the unit normal
    ``(nx, ny)`` and the two shapes just touch."""

    nx: float
    ny: float
    depth: float

    @property
    def vector(self) -> Point:
        """The push itself, ``(nx * depth, ny * depth)``."""
        return (self.nx * self.depth, self.ny * self.depth)


def _cross(o: Point, p: Point, q: Point) -> float:
    """The z of (p - o) x (q - o): positive when o -> p -> q turns one way, negative the other."""
    return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])


@dataclass(frozen=True)
class Polygon:
    """A convex polygon: at least three finite points in order (either winding), every turn
    the same way, going round once. Invalid points raise ``ValueError`` saying why."""

    points: tuple[Point, ...]

    def __post_init__(self) -> None:
        pts = self.points
        if len(pts) < 3:
            raise ValueError(f"a polygon needs at least 3 points, got {len(pts)}: {pts}")
        if not all(math.isfinite(c) for p in pts for c in p):
            raise ValueError(f"every polygon point must be finite (no NaN or inf): {pts}")
        n = len(pts)
        turns = [_cross(pts[i - 1], pts[i], pts[(i + 1) % n]) for i in range(n)]
        for i, turn in enumerate(turns):
            if turn == 0:
                raise ValueError(
                    f"polygon points {pts[i - 1]}, {pts[i]}, {pts[(i + 1) % n]} lie on one "
                    f"line (or repeat); remove the middle one: {pts}")
        if not (all(t > 0 for t in turns) or all(t < 0 for t in turns)):
            raise ValueError(f"the polygon is not convex (it turns both ways): {pts}")
        # Turning the same way at every corner still allows a star that winds round twice.
        heading_change = 0.0
        for i in range(n):
            a, b, c = pts[i - 1], pts[i], pts[(i + 1) % n]
            u = (b[0] - a[0], b[1] - a[1])
            v = (c[0] - b[0], c[1] - b[1])
            heading_change += math.atan2(u[0] * v[1] - u[1] * v[0], u[0] * v[0] + u[1] * v[1])
        if abs(abs(heading_change) - 2 * math.pi) > 1e-6:
            raise ValueError(f"the polygon crosses itself (it winds round more than once): {pts}")

    @classmethod
    def of(cls, points: Iterable[Point]) -> Polygon:
        """A polygon from any iterable of ``(x, y)`` pairs."""
        return cls(tuple((float(x), float(y)) for x, y in points))

    @classmethod
    def from_box(cls, box: Box) -> Polygon:
        """The four corners of a (non-empty, normalised) box, clockwise on screen."""
        return cls.of([(box.left, box.top), (box.right, box.top),
                       (box.right, box.bottom), (box.left, box.bottom)])

    def moved(self, dx: float = 0.0, dy: float = 0.0) -> Polygon:
        """This polygon shifted by ``(dx, dy)``."""
        return Polygon(tuple((x + dx, y + dy) for x, y in self.points))

    def bounds(self) -> Box:
        """The axis-aligned box around the polygon: what an AABB-only engine would test.

        >>> Polygon.of([(0, 3), (4, 0), (6, 5)]).bounds()
        Box(x=0.0, y=0.0, w=6.0, h=5.0)
        """
        xs = [x for x, _ in self.points]
        ys = [y for _, y in self.points]
        left, top = min(xs), min(ys)
        return Box(left, top, max(xs) - left, max(ys) - top)

    def axes(self) -> list[Point]:
        """The unit normal of every edge: the candidate separating axes this polygon brings."""
        normals: list[Point] = []
        pts = self.points
        for i, (x1, y1) in enumerate(pts):
            x2, y2 = pts[(i + 1) % len(pts)]
            length = math.hypot(x2 - x1, y2 - y1)
            normals.append(((y2 - y1) / length, (x1 - x2) / length))
        return normals

    def project(self, axis: Point) -> tuple[float, float]:
        """The shadow of the polygon on an axis: the lowest and highest dot product."""
        dots = [x * axis[0] + y * axis[1] for x, y in self.points]
        return min(dots), max(dots)


def oriented_box(cx: float, cy: float, half_w: float, half_h: float,
                 angle_rad: float) -> Polygon:
    """A box of size ``2*half_w`` by ``2*half_h`` centred on ``(cx, cy)``, turned by the angle.

    >>> oriented_box(10, 10, 2, 1, 0).points
    ((8.0, 9.0), (12.0, 9.0), (12.0, 11.0), (8.0, 11.0))
    """
    if not all(math.isfinite(v) for v in (cx, cy, half_w, half_h, angle_rad)):
        raise ValueError(
            f"an oriented box needs finite numbers, got centre ({cx}, {cy}), half size "
            f"({half_w}, {half_h}), angle {angle_rad}")
    if half_w <= 0 or half_h <= 0:
        raise ValueError(f"an oriented box needs half sizes > 0, got ({half_w}, {half_h})")
    cos, sin = math.cos(angle_rad), math.sin(angle_rad)
    corners = [(-half_w, -half_h), (half_w, -half_h), (half_w, half_h), (-half_w, half_h)]
    return Polygon.of((cx + x * cos - y * sin, cy + x * sin + y * cos) for x, y in corners)


def collide(a: Polygon, b: Polygon) -> Mtv | None:
    """None when the polygons are apart (or only touch); otherwise the push that parts them.

    Every edge normal of ``a``, then of ``b``, is tried in order. On each axis, ``a`` could
    move forwards by ``b_max - a_min`` or backwards by ``a_max - b_min`` to clear ``b``; if
    either is ``<= 0`` that axis separates them and we stop. Otherwise the smaller of the two
    is this axis's push, and the smallest push over all axes is the MTV. Ties go to the axis
    met first and, on one axis, to the forward direction, so the answer is deterministic.
    """
    best: Mtv | None = None
    for axis in a.axes() + b.axes():
        a_min, a_max = a.project(axis)
        b_min, b_max = b.project(axis)
        forward = b_max - a_min
        backward = a_max - b_min
        if forward <= 0 or backward <= 0:
            return None
        if forward <= backward:
            push = Mtv(axis[0], axis[1], forward)
        else:
            push = Mtv(0.0 - axis[0], 0.0 - axis[1], backward)  # 0.0 - x: never -0.0
        if best is None or push.depth < best.depth:
            best = push
    return best
