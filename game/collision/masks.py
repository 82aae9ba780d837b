"""Pixel-perfect collision with ``pygame.mask``, behind a cheap rect guard.

Where it sits: pure geometry on whole pixels, beside :mod:`game.collision.aabb`. The tile world
needs
none of it (its shapes are boxes); masks are for sprites whose outline matters, such as a
spinning saw blade, tested after the movement passes like any other trigger.

What it teaches:
  * **A mask is one bit per pixel**: solid or not. Two sprites touch pixel-perfectly when
    some pixel is solid in both. A :class:`Masked` is a mask placed in the world: pixel
    ``(i, j)`` of a mask at ``(x, y)`` is the world square ``x+i <= px < x+i+1`` (and the
    same on y), so ``Masked.rect`` covers exactly the mask's pixels.
  * **The offset is the other mask's corner, seen from this one.** ``a.overlap(b, offset)``
    asks: "with ``b``'s top-left at ``offset`` in *my* pixel coordinates, which of my pixels
    is solid in both?" So ``offset = (b.x - a.x, b.y - a.y)``, and the pixel it answers is
    in ``a``'s coordinates: add ``(a.x, a.y)`` to get back to the world.
  * **Guard first.** ``Rect.colliderect`` is one call into C; a mask test walks bits. Test
    masks only when the rects overlap: rects that do not overlap cannot share a pixel.
    :class:`MaskStats` counts both so a test (or the overlay) can see the guard work.
  * **Analytic shapes to pixels.** :func:`circle_mask` and :func:`polygon_mask` make a pixel
    solid when its *centre* lies strictly inside the shape. Every solid pixel then lies
    within half a pixel diagonal of the shape; the same centre rule for two shapes means
    their masks share a pixel only if the shapes truly overlap. (``pygame.draw`` works
    headless too, and :meth:`Masked.from_surface` takes its output, but it truncates float
    centres and radii, which can move an edge by more than a pixel.)

>>> a = Masked(pygame.mask.Mask((4, 4), fill=True), 0, 0)
>>> contact_point(a, Masked(pygame.mask.Mask((4, 4), fill=True), 3, 3))   # world pixel
(3, 3)
>>> collide(a, Masked(pygame.mask.Mask((4, 4), fill=True), 4, 0))        # edges touch
False
>>> ball = circle_mask(Circle(10, 10, 5))      # area 78.5
>>> ball.rect, ball.mask.count()
(<rect(5, 5, 10, 10)>, 80)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import pygame

from game.collision.circles import Circle
from game.collision.sat import Polygon

ALPHA_SOLID_FROM = 127  # from_surface: a pixel is solid when its alpha is above this

Span = tuple[float, float]  # the open interval of x inside a shape along one pixel row


@dataclass(frozen=True)
class Masked:
    """A mask with its top-left corner at whole-pixel world position ``(x, y)``."""

    mask: pygame.mask.Mask
    x: int
    y: int

    def __post_init__(self) -> None:
        if not all(type(v) is int for v in (self.x, self.y)):
            raise ValueError(f"a mask sits at whole pixels, got ({self.x!r}, {self.y!r}); "
                             f"use Masked.at() to place it at a float position")

    @classmethod
    def at(cls, mask: pygame.mask.Mask, x: float, y: float) -> Masked:
        """Place a mask at a float position, flooring it like
        :meth:`game.collision.aabb.Box.to_rect`."""
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"cannot place a mask at a non-finite position ({x}, {y})")
        return cls(mask, math.floor(x), math.floor(y))

    @classmethod
    def from_surface(cls, surface: pygame.Surface, x: int, y: int) -> Masked:
        """The mask of a sprite image (per-pixel alpha or a colour key); no display needed."""
        return cls(pygame.mask.from_surface(surface, ALPHA_SOLID_FROM), x, y)

    @property
    def rect(self) -> pygame.Rect:
        """The world rect the mask's pixels cover: the cheap guard."""
        return pygame.Rect(self.x, self.y, *self.mask.get_size())


@dataclass
class MaskStats:
    """How many rect guards ran and how many of them let a mask test through."""

    rect_checks: int = 0
    mask_checks: int = 0

    def reset(self) -> None:
        self.rect_checks = 0
        self.mask_checks = 0


def _offset(a: Masked, b: Masked) -> tuple[int, int]:
    """Where ``b``'s top-left corner lies in ``a``'s pixel coordinates."""
    return (b.x - a.x, b.y - a.y)


def _guard(a: Masked, b: Masked, stats: MaskStats | None) -> bool:
    """The rect test that must pass before any bits are compared."""
    if stats is not None:
        stats.rect_checks += 1
    if not a.rect.colliderect(b.rect):
        return False
    if stats is not None:
        stats.mask_checks += 1
    return True


def contact_point(a: Masked, b: Masked, stats: MaskStats | None = None) -> tuple[int, int] | None:
    """A world pixel solid in both masks, or None (pygame picks the first it finds)."""
    if not _guard(a, b, stats):
        return None
    local = a.mask.overlap(b.mask, _offset(a, b))
    if local is None:
        return None
    return (a.x + local[0], a.y + local[1])


def collide(a: Masked, b: Masked, stats: MaskStats | None = None) -> bool:
    """True when some pixel is solid in both masks; the masks are read only if rects overlap."""
    return contact_point(a, b, stats) is not None


def overlap_area(a: Masked, b: Masked, stats: MaskStats | None = None) -> int:
    """How many pixels are solid in both: a measure of how deep a pixel-perfect hit is."""
    if not _guard(a, b, stats):
        return 0
    return a.mask.overlap_area(b.mask, _offset(a, b))


def _rasterise(left: float, top: float, right: float, bottom: float,
               span_at: Callable[[float], Span | None]) -> Masked:
    """A mask over the pixels the bounds touch, solid where a pixel's centre is inside.

    ``span_at(y)`` gives the open interval of x inside the shape on the row ``y``. Pixel
    ``i`` of the row (world centre ``x0 + i + 0.5``) is solid when ``left < centre < right``,
    so the row is filled from ``floor(left - 0.5 - x0) + 1`` to ``ceil(right - 0.5 - x0) - 1``.
    """
    x0, y0 = math.floor(left), math.floor(top)
    width, height = math.ceil(right) - x0, math.ceil(bottom) - y0
    mask = pygame.mask.Mask((width, height))
    for j in range(height):
        span = span_at(y0 + j + 0.5)
        if span is None:
            continue
        lo, hi = max(span[0], x0 - 1.0), min(span[1], x0 + width + 1.0)
        first = max(0, math.floor(lo - 0.5 - x0) + 1)
        last = min(width - 1, math.ceil(hi - 0.5 - x0) - 1)
        if first <= last:
            mask.draw(pygame.mask.Mask((last - first + 1, 1), fill=True), (first, j))
    return Masked(mask, x0, y0)


def circle_mask(circle: Circle) -> Masked:
    """The pixels whose centres lie strictly inside the circle, placed in the world."""
    cx, cy, r = circle.cx, circle.cy, circle.r

    def span_at(y: float) -> Span | None:
        room = r * r - (y - cy) ** 2
        if room <= 0:
            return None
        half = math.sqrt(room)
        return (cx - half, cx + half)

    return _rasterise(cx - r, cy - r, cx + r, cy + r, span_at)


def polygon_mask(polygon: Polygon) -> Masked:
    """The pixels whose centres lie strictly inside a convex polygon (a rotated bar, say).

    >>> from game.collision.sat import oriented_box
    >>> bar = polygon_mask(oriented_box(20, 20, 10, 2, math.pi / 4))   # 20 x 4 at 45 degrees
    >>> bar.rect, bar.mask.count()
    (<rect(11, 11, 18, 18)>, 72)
    """
    pts = polygon.points
    n = len(pts)
    winding = math.copysign(1.0, sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1]
                                     for i in range(n)))

    def span_at(y: float) -> Span | None:
        # Inside means: on the inner side of every edge p -> q, i.e. a + b * x > 0 per edge.
        lo, hi = -math.inf, math.inf
        for i in range(n):
            (px, py), (qx, qy) = pts[i - 1], pts[i]
            a = winding * ((qx - px) * (y - py) + (qy - py) * px)
            b = -winding * (qy - py)
            if b > 0:
                lo = max(lo, -a / b)
            elif b < 0:
                hi = min(hi, -a / b)
            elif a <= 0:
                return None
        return (lo, hi) if lo < hi else None

    box = polygon.bounds()
    return _rasterise(box.left, box.top, box.right, box.bottom, span_at)
