"""The moving platforms' tracks: a faint dotted line along each route, so a player sees where
a platform goes before riding it, even when its route runs out of view.

Where it sits: drawn by :class:`game.app.render.WorldRenderer` after the sky and before the
tile layers, so the ground covers a track that runs behind it and the platform rides over
its own. Like the rest of the drawing it only reads the level: a :class:`Tracks` is made
once a level from the platforms' routes (:class:`game.sim.platforms.PlatformSpec`).

What it teaches:
  * **Evenly spaced along a polyline.** A dot every :data:`TRACK_DOT_GAP_PX` of the route's
    length is the point the platform itself would reach after that distance
    (:meth:`game.sim.platforms.Route.point_at`), so the dots follow corners and a loop's
    closing leg exactly as the platform does, and no leg gets a gap or a clump.
  * **The route is the platform's corner; the track is its middle.** A route is where the
    platform's top-left corner goes; the track is drawn through the platform's centre, so it
    runs down the middle of the plank at every stop.
  * **Art direction**: the planks' own dark wood, half seen, no outline: a track belongs to
    the background, and only the plank on it is something to stand on. Each end and corner
    of a route gets a small ring, a stop.

>>> from game.sim.platforms import PlatformSpec, Route
>>> spec = PlatformSpec(Route(((0.0, 0.0), (20.0, 0.0))), 16.0, 8.0, 30.0)
>>> track_dots(spec)
[(8, 4), (13, 4), (18, 4), (23, 4), (28, 4)]
>>> track_stops(spec)
[(8, 4), (28, 4)]
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import pygame

from game.sim.platforms import PlatformSpec

TRACK_DOT_GAP_PX = 5  # from one dot to the next, along the route
TRACK_DOT_PX = 2  # each dot is this many pixels square
TRACK_COLOR = (62, 36, 20, 160)  # the planks' dark edge (render.PLANK_EDGE_COLOR), half seen
STOP_RADIUS_PX = 3  # the ring at each end and corner of a route

Pixel = tuple[int, int]


def _centre(spec: PlatformSpec, x: float, y: float) -> Pixel:
    return round(x + spec.width_px / 2), round(y + spec.height_px / 2)


def track_dots(spec: PlatformSpec) -> list[Pixel]:
    """The map pixels of a route's dots, through the platform's centre, from its start."""
    route = spec.path
    count = math.floor(route.length / TRACK_DOT_GAP_PX) + 1
    return [_centre(spec, *route.point_at(number * TRACK_DOT_GAP_PX)) for number in range(count)]


def track_stops(spec: PlatformSpec) -> list[Pixel]:
    """The map pixels of a route's ends and corners, through the platform's centre."""
    return [_centre(spec, x, y) for x, y in spec.path.points]


class Tracks:
    """Every platform's track of one level, ready to draw through the camera."""

    def __init__(self, platforms: Iterable[PlatformSpec]) -> None:
        self.dots: list[Pixel] = []
        self.stops: list[Pixel] = []
        for spec in platforms:
            if spec.path.length > 0:  # a platform that stays put has no track
                self.dots.extend(track_dots(spec))
                self.stops.extend(track_stops(spec))
        self.dot = pygame.Surface((TRACK_DOT_PX, TRACK_DOT_PX), pygame.SRCALPHA)
        self.dot.fill(TRACK_COLOR)
        side = 2 * STOP_RADIUS_PX + 1
        self.stop = pygame.Surface((side, side), pygame.SRCALPHA)
        pygame.draw.circle(self.stop, TRACK_COLOR, (STOP_RADIUS_PX, STOP_RADIUS_PX),
                           STOP_RADIUS_PX, width=1)

    def draw(self, target: pygame.Surface, offset: Pixel) -> None:
        """Blit the dots and stops in view, ``offset`` being the camera's whole pixel."""
        if not self.dots:
            return
        dx, dy = offset
        view = target.get_rect().inflate(2 * STOP_RADIUS_PX + 2, 2 * STOP_RADIUS_PX + 2)
        half = TRACK_DOT_PX // 2
        target.blits([(self.dot, (x - dx - half, y - dy - half)) for x, y in self.dots
                      if view.collidepoint(x - dx, y - dy)], doreturn=False)
        target.blits([(self.stop, (x - dx - STOP_RADIUS_PX, y - dy - STOP_RADIUS_PX))
                      for x, y in self.stops if view.collidepoint(x - dx, y - dy)],
                     doreturn=False)
