"""A composite collider: one body made of several boxes, placed relative to an origin.

Where it sits: pure geometry, one step above :mod:`game.collision.aabb`. For a body whose outline is
not one rectangle (an L-shaped crate, a cannon with a barrel) the parts are tested instead
of one big box around them.

What it teaches:
  * **One box over a non-rectangular body lies.** The bounding box of an L also covers the
    empty notch of the L, so a coin sitting in the notch "hits" it. Testing the parts gives
    the true answer; the bounding box is still used, as a cheap first check.
  * **Parts are relative, the origin moves.** The parts never change; moving the body moves
    only ``(x, y)``, and world boxes are made on demand. Parts may touch or overlap each
    other; the body is their union.
  * **Still strict**: two composites that only touch along some edge do not overlap.

>>> crate = l_shape(0, 0, width=30, height=30, thickness=10)   # an L: left column + bottom row
>>> notch = Box(15, 5, 10, 10)                                 # inside the L's empty corner
>>> crate.bounds().overlaps(notch), crate.overlaps(notch)
(True, False)
>>> crate.overlaps(Box(5, 5, 10, 10))
True
"""

from __future__ import annotations

from dataclasses import dataclass

from game.collision.aabb import Box


@dataclass(frozen=True)
class Composite:
    """Boxes ``parts`` (relative to the origin) placed with the origin at world ``(x, y)``."""

    x: float
    y: float
    parts: tuple[Box, ...]

    def __post_init__(self) -> None:
        if not self.parts:
            raise ValueError("a composite collider needs at least one part")
        origin = Box(self.x, self.y, 0, 0)
        if not origin.is_finite():
            raise ValueError(f"a composite's origin must be finite, got ({self.x}, {self.y})")
        for part in self.parts:
            if not part.is_finite() or part.w <= 0 or part.h <= 0:
                raise ValueError(
                    f"every part must be a finite box with width and height > 0, got {part}")

    def world_parts(self) -> tuple[Box, ...]:
        """The parts where they are in the world."""
        return tuple(part.moved(self.x, self.y) for part in self.parts)

    def bounds(self) -> Box:
        """One box around every part: the cheap check, and the lie it would be on its own."""
        boxes = self.world_parts()
        total = boxes[0]
        for box in boxes[1:]:
            total = total.union(box)
        return total

    def moved(self, dx: float = 0.0, dy: float = 0.0) -> Composite:
        """The same body with its origin shifted by ``(dx, dy)``."""
        return Composite(self.x + dx, self.y + dy, self.parts)

    def overlaps(self, other: Box | Composite) -> bool:
        """True when some part overlaps ``other`` (a box, or any part of another composite).

        The bounding boxes are compared first; only when they overlap are the parts tried.
        """
        others = other.world_parts() if isinstance(other, Composite) else (other,)
        other_bounds = other.bounds() if isinstance(other, Composite) else other
        if not self.bounds().overlaps(other_bounds):
            return False
        return any(mine.overlaps(theirs) for mine in self.world_parts() for theirs in others)


def l_shape(x: float, y: float, *, width: float, height: float, thickness: float) -> Composite:
    """An L: a column ``thickness`` wide down the left, and a row ``thickness`` tall along
    the bottom, with its top-left corner at ``(x, y)``.

    >>> l_shape(100, 50, width=30, height=20, thickness=5).world_parts()
    (Box(x=100, y=50, w=5, h=20), Box(x=100, y=65, w=30, h=5))
    """
    if not 0 < thickness < min(width, height):
        raise ValueError(f"an L needs 0 < thickness < width and height, got thickness "
                         f"{thickness} for {width} x {height}")
    column = Box(0, 0, thickness, height)
    row = Box(0, height - thickness, width, thickness)
    return Composite(x, y, (column, row))
