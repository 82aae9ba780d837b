"""Axis-aligned bounding boxes with exact float edges.

Where it sits: the bottom of the dependency ladder. Every other collision module speaks in
``Box`` values; nothing here knows about sprites, tiles or the screen.

What it teaches:
  * A box is ``x <= px < x + w`` on each axis: the left/top edge is inside, the right/bottom
    edge is not. Two boxes that only *touch* (one's right edge equals the other's left edge)
    do not overlap. This is the rule ``pygame.Rect.colliderect`` uses, written with strict
    inequalities.
  * A box with zero width or height overlaps nothing, not even itself.
  * Sizes are expected to be normalised (``w, h >= 0``): :meth:`Box.overlaps` counts a
    negative size as empty, while ``pygame.Rect.colliderect`` flips it first. Use
    :meth:`Box.normalized`, or :func:`rects_overlap`, to get pygame's answer for any sizes.
  * Positions are floats. pygame 2.6 ``Rect`` coordinates are integers, so a Rect cannot
    hold a body that moves 0.4 px per tick; the exact position lives here and the Rect is
    derived from it with ``math.floor`` (see :func:`Box.to_rect`).

>>> a = Box(0, 0, 16, 16)
>>> a.overlaps(Box(16, 0, 16, 16))       # edges touch: no overlap
False
>>> a.overlaps(Box(15.5, 0, 16, 16))
True
>>> Box(0, 0, 0, 16).overlaps(Box(-5, -5, 50, 50))
False
>>> Box(10.4, -0.5, 12, 14).to_rect()
<rect(10, -1, 12, 14)>
>>> rects_overlap(Box(10, 10, -10, -10), Box(2, 2, 4, 4))   # pygame flips negative sizes
True
"""

from __future__ import annotations

import math
from typing import NamedTuple

import pygame

RECT_MIN, RECT_MAX = -(2**31), 2**31 - 1  # what a pygame Rect's C ints can hold


class Box(NamedTuple):
    """A rectangle with float position and size: ``x``/``y`` is the top-left corner."""

    x: float
    y: float
    w: float
    h: float

    @property
    def left(self) -> float:
        return self.x

    @property
    def top(self) -> float:
        return self.y

    @property
    def right(self) -> float:
        return self.x + self.w

    @property
    def bottom(self) -> float:
        return self.y + self.h

    @property
    def center(self) -> tuple[float, float]:
        """The exact middle, as floats (``Rect.center`` rounds it to whole pixels).

        >>> Box(0, 0, 5, 3).center
        (2.5, 1.5)
        """
        return (self.x + self.w / 2, self.y + self.h / 2)

    @classmethod
    def from_rect(cls, rect: pygame.Rect) -> Box:
        """The box with the same four numbers as ``rect`` (negative sizes are kept as they are).

        >>> Box.from_rect(pygame.Rect(3, 4, -5, 6))
        Box(x=3, y=4, w=-5, h=6)
        """
        return cls(rect.x, rect.y, rect.w, rect.h)

    def normalized(self) -> Box:
        """The same region with a non-negative width and height, as pygame reads a Rect.

        A width of -5 at ``x = 3`` covers ``-2 <= px < 3``: the corner moves, the size flips.

        >>> Box(3, 4, -5, 6).normalized()
        Box(x=-2, y=4, w=5, h=6)
        """
        x, w = (self.x + self.w, -self.w) if self.w < 0 else (self.x, self.w)
        y, h = (self.y + self.h, -self.h) if self.h < 0 else (self.y, self.h)
        return Box(x, y, w, h)

    def overlaps(self, other: Box) -> bool:
        """True when the interiors intersect; touching edges and empty boxes never overlap.

        Expects normalised boxes: a negative width or height counts as empty here. Call
        :meth:`normalized` first (or use :func:`rects_overlap`) for pygame's flipping rule.
        """
        return (
            self.w > 0
            and self.h > 0
            and other.w > 0
            and other.h > 0
            and self.x < other.x + other.w
            and other.x < self.x + self.w
            and self.y < other.y + other.h
            and other.y < self.y + self.h
        )

    def touches(self, other: Box) -> bool:
        """True when the boxes meet only along an edge or at a corner: no shared interior.

        The third answer beside "overlapping" and "apart". Empty boxes touch nothing, just as
        they overlap nothing.

        >>> Box(0, 0, 16, 16).touches(Box(16, 4, 8, 8))     # flush against the right edge
        True
        >>> Box(0, 0, 16, 16).touches(Box(16, 16, 8, 8))    # corner to corner
        True
        >>> Box(0, 0, 16, 16).touches(Box(8, 8, 8, 8))      # overlapping is not touching
        False
        >>> Box(0, 0, 0, 16).touches(Box(0, 0, 16, 16))     # a zero-width box: nothing
        False
        """
        return (
            self.w > 0
            and self.h > 0
            and other.w > 0
            and other.h > 0
            and self.x <= other.x + other.w
            and other.x <= self.x + self.w
            and self.y <= other.y + other.h
            and other.y <= self.y + self.h
            and not self.overlaps(other)
        )

    def moved(self, dx: float = 0.0, dy: float = 0.0) -> Box:
        """This box shifted by ``(dx, dy)``.

        >>> Box(1, 2, 3, 4).moved(dx=10)
        Box(x=11, y=2.0, w=3, h=4)
        """
        return Box(self.x + dx, self.y + dy, self.w, self.h)

    def union(self, other: Box) -> Box:
        """The smallest box holding both: the region a body sweeps through in one axis step.

        >>> Box(0, 0, 10, 10).union(Box(25, 0, 10, 10))
        Box(x=0, y=0, w=35, h=10)
        """
        left = min(self.x, other.x)
        top = min(self.y, other.y)
        return Box(left, top, max(self.right, other.right) - left,
                   max(self.bottom, other.bottom) - top)

    def penetration(self, other: Box) -> float:
        """How far the two boxes overlap along their shallower axis; 0.0 when they do not.

        >>> Box(0, 0, 10, 10).penetration(Box(8, 3, 10, 10))
        2
        """
        if not self.overlaps(other):
            return 0.0
        depth_x = min(self.right, other.right) - max(self.x, other.x)
        depth_y = min(self.bottom, other.bottom) - max(self.y, other.y)
        return min(depth_x, depth_y)

    def gap(self, other: Box) -> float:
        """How far apart the two boxes are along the farther axis; 0.0 when they touch or
        overlap.

        >>> Box(0, 0, 10, 10).gap(Box(25, 3, 10, 10))
        15
        """
        return max(0.0, other.left - self.right, self.left - other.right,
                   other.top - self.bottom, self.top - other.bottom)

    def is_finite(self) -> bool:
        """False if any field is NaN or infinite: such a box must never become a Rect.

        >>> Box(float("nan"), 0, 1, 1).is_finite()
        False
        """
        return all(math.isfinite(v) for v in self)

    def to_rect(self) -> pygame.Rect:
        """The integer Rect that draws this box: ``floor`` of the corner, never ``int()``.

        ``int(-0.5)`` is ``0`` but the box starts half a pixel left of 0, so ``floor`` it is.
        Refuses NaN and infinities, which pygame would silently turn into -2147483648, and
        edges beyond the 32-bit range of a Rect, which pygame would silently wrap round.

        >>> Box(2.0**40, 0, 1, 1).to_rect()
        Traceback (most recent call last):
            ...
        ValueError: cannot make a Rect from Box(x=1099511627776.0, y=0, w=1, h=1): an edge ...
        """
        x, y, w, h = self
        try:
            left, top, width, height = math.floor(x), math.floor(y), math.ceil(w), math.ceil(h)
        except (ValueError, OverflowError):  # NaN and infinities have no floor
            raise ValueError(f"cannot make a Rect from a non-finite box {self}") from None
        if not (RECT_MIN <= left <= RECT_MAX and RECT_MIN <= top <= RECT_MAX
                and RECT_MIN <= left + width <= RECT_MAX and RECT_MIN <= top + height <= RECT_MAX):
            raise ValueError(f"cannot make a Rect from {self}: an edge lies outside "
                             f"{RECT_MIN}..{RECT_MAX}, the range a pygame Rect can hold")
        return pygame.Rect(left, top, width, height)


def rects_overlap(a: Box, b: Box) -> bool:
    """Overlap by ``pygame.Rect.colliderect``'s rule for any sizes: flip negative sizes, then
    test strictly. Zero-size boxes still overlap nothing.

    >>> rects_overlap(Box(0, 0, -10, 5), Box(-5, 0, 2, 5))
    True
    >>> Box(0, 0, -10, 5).overlaps(Box(-5, 0, 2, 5))             # not normalised: empty
    False
    """
    return a.normalized().overlaps(b.normalized())
