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
platforms', so :mod:`game.sim.movement` needs no special case. A handful of platforms is
checked by brute force; there is no need for a structure.

>>> path = Route(((0.0, 0.0), (30.0, 0.0)), loop=False)
>>> [path.point_at(d) for d in (0.0, 10.0, 30.0, 40.0, 60.0)]    # there and back again
[(0.0, 0.0), (10.0, 0.0), (30.0, 0.0), (20.0, 0.0), (0.0, 0.0)]
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from game.collision.aabb import Box
from game.sim.sprite import Anchor, BoxSprite
from game.sim.tilegrid import TileGrid, TileKind, TileShape

Point = tuple[float, float]


@dataclass(frozen=True)
class Route:
    """A polyline to follow, by distance travelled: back and forth, or round a loop."""

    points: tuple[Point, ...]
    loop: bool = False

    @property
    def legs(self) -> list[tuple[Point, Point]]:
        legs = list(zip(self.points, self.points[1:], strict=False))
        if self.loop and len(self.points) > 2:
            legs.append((self.points[-1], self.points[0]))
        return legs

    @property
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

    @property
    def shape(self) -> TileShape:
        return TileShape(self.box, TileKind.SOLID, col=-1, row=self.number)

    def next_step(self, dt_s: float) -> tuple[float, float]:
        """The (dx, dy) this platform moves in the coming tick."""
        self.travelled_px += self.spec.speed_px_s * dt_s
        x, y = self.spec.path.point_at(self.travelled_px)
        return x - self.box.x, y - self.box.y


@dataclass
class SolidsWithPlatforms:
    """The tile grid plus moving platforms, behind the one query the movement code makes."""

    grid: TileGrid
    platforms: Sequence[Platform]
    ignored: Platform | None = None  # the platform that is itself moving right now

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def shapes_in(self, region: Box) -> list[TileShape]:
        found = self.grid.shapes_in(region)
        for platform in self.platforms:
            if platform is not self.ignored:
                self.grid.stats.shapes_tested += 1
                if platform.box.overlaps(region):
                    found.append(platform.shape)
        return found

    def without(self, platform: Platform) -> SolidsWithPlatforms:
        return SolidsWithPlatforms(self.grid, self.platforms, platform)

    def platform_of(self, shape: TileShape | None) -> Platform | None:
        """The platform a shape came from, if it is a platform's."""
        if shape is None or shape.col != -1:
            return None
        return next((p for p in self.platforms if p.number == shape.row), None)
