"""Circles: circle-vs-circle, circle-vs-box, and the bounding-circle pre-check.

Where it sits: pure geometry, next to :mod:`game.collision.aabb`. The tile world is all boxes;
circles
are here for round things (a bouncing ball, a saw blade) and for the pre-check lesson.

What it teaches:
  * **Compare squared distances.** Two circles overlap when the distance between centres is
    less than the sum of the radii. Squaring both sides gives the same answer with no square
    root: ``dx*dx + dy*dy < (r1 + r2) ** 2``.
  * **Strict, like boxes.** Circles that only touch do not overlap, and a circle of radius 0
    overlaps nothing, so every shape in the project follows one rule.
  * **Circle against box: clamp, then measure.** The point of the box closest to the centre
    is the centre clamped into the box; the shapes overlap when that point is nearer than
    the radius. When the centre is inside the box the clamp leaves it where it is (distance 0).
  * **A pre-check is only worth what it saves.** :func:`precheck_then_rect` first compares the
    boxes' bounding circles and only then calls ``Rect.colliderect``. In Python that pre-check
    builds two boxes and two circles and does a dozen float operations in the interpreter,
    all to guard one call into C, so it usually costs *more* than the test it guards (the
    benchmark measures it). A pre-check pays only when the guarded test is expensive: a
    pixel mask, a many-sided polygon.

>>> Circle(0, 0, 2).overlaps(Circle(3, 4, 3))        # centres 5 apart, radii sum 5: touching
False
>>> Circle(0, 0, 2).overlaps(Circle(3, 4, 3.5))
True
>>> Circle(0, 0, 5).overlaps_box(Box(4, 4, 10, 10))  # nearest corner is sqrt(32) > 5 away
False
>>> bounding_circle(Box(0, 0, 6, 8))
Circle(cx=3.0, cy=4.0, r=5.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import pygame

from game.collision.aabb import Box


@dataclass(frozen=True, slots=True)
class Circle:
    """A disc with centre ``(cx, cy)`` and radius ``r`` in pixels; refuses NaN and ``r < 0``."""

    cx: float
    cy: float
    r: float

    def __post_init__(self) -> None:
        if not all(math.isfinite(v) for v in (self.cx, self.cy, self.r)) or self.r < 0:
            raise ValueError(
                f"a circle needs a finite centre and a finite radius >= 0, got {self}")

    def overlaps(self, other: Circle) -> bool:
        """True when the discs' interiors intersect; touching circles do not overlap."""
        if self.r <= 0 or other.r <= 0:
            return False
        dx = other.cx - self.cx
        dy = other.cy - self.cy
        radii = self.r + other.r
        return dx * dx + dy * dy < radii * radii

    def overlaps_box(self, box: Box) -> bool:
        """True when the disc and the box share interior points (the box must be normalised).

        >>> Circle(5, 5, 1).overlaps_box(Box(0, 0, 10, 10))   # centre inside the box
        True
        >>> Circle(-3, 5, 3).overlaps_box(Box(0, 0, 10, 10))  # touches the left edge
        False
        """
        if self.r <= 0 or box.w <= 0 or box.h <= 0:
            return False
        nearest_x = min(max(self.cx, box.left), box.right)
        nearest_y = min(max(self.cy, box.top), box.bottom)
        dx = self.cx - nearest_x
        dy = self.cy - nearest_y
        return dx * dx + dy * dy < self.r * self.r

    def bounds(self) -> Box:
        """The smallest box around the disc: what an AABB-only engine would test.

        >>> Circle(10, 10, 4).bounds()
        Box(x=6, y=6, w=8, h=8)
        """
        return Box(self.cx - self.r, self.cy - self.r, 2 * self.r, 2 * self.r)


def bounding_circle(box: Box) -> Circle:
    """The circle through the box's four corners: centred on it, radius half the diagonal.

    Negative sizes are fine (pygame-style Rects): the centre and the diagonal do not care.
    """
    cx, cy = box.center
    return Circle(cx, cy, math.hypot(box.w, box.h) / 2)


def circles_may_touch(a: Circle, b: Circle) -> bool:
    """The pre-check: False only when the circles are certainly apart.

    Unlike :meth:`Circle.overlaps` this is *not* strict (touching counts as "maybe"): a
    filter may say "maybe" too often, but it must never say "no" to a real overlap, and the
    ``<=`` keeps a rounding error in the square root from ever doing that.
    """
    dx = b.cx - a.cx
    dy = b.cy - a.cy
    radii = a.r + b.r
    return dx * dx + dy * dy <= radii * radii


def precheck_then_rect(a: pygame.Rect, b: pygame.Rect) -> bool:
    """``a.colliderect(b)``, asked only when the rects' bounding circles may touch.

    Always the same answer as ``colliderect`` (the tests pin that); in Python, usually slower.

    >>> precheck_then_rect(pygame.Rect(0, 0, 10, 10), pygame.Rect(9, 9, 10, 10))
    True
    >>> precheck_then_rect(pygame.Rect(0, 0, 10, 10), pygame.Rect(40, 0, 10, 10))
    False
    """
    if not circles_may_touch(bounding_circle(Box.from_rect(a)), bounding_circle(Box.from_rect(b))):
        return False
    return a.colliderect(b)
