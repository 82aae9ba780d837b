"""A moving platform's route is drawn as a faint dotted track, so a player sees where it goes;
a platform that stays put has none."""

from __future__ import annotations

import dataclasses

import pygame

from game.app.assets import Assets
from game.app.render import WorldRenderer, screen_offset
from game.app.tracks import TRACK_DOT_GAP_PX, track_dots
from game.sim.platforms import PlatformSpec, Route
from game.sim.world import World
from tests.maps import level_from_ascii

ROWS = [" P                  ", *["                    "] * 10, "####################"]
START = (16.0, 40.0)  # the platform's top-left corner where its route begins
END = (260.0, 40.0)


def frame(assets: Assets, route: Route) -> tuple[pygame.Surface, tuple[int, int]]:
    """The first frame of a level with one platform on ``route``, and the camera's pixel."""
    level = dataclasses.replace(level_from_ascii(ROWS),
                                platforms=(PlatformSpec(route, 32.0, 8.0, 30.0),))
    target = pygame.display.get_surface()
    world = World(level)
    WorldRenderer(assets).draw(target, world, 0)
    return target.copy(), screen_offset(world.camera)


def test_a_moving_platform_s_route_shows_its_track_all_the_way(assets: Assets) -> None:
    moving, (dx, dy) = frame(assets, Route((START, END)))
    still, camera = frame(assets, Route((START,)))
    assert camera == (dx, dy)
    spec = PlatformSpec(Route((START, END)), 32.0, 8.0, 30.0)
    dots = [(x - dx, y - dy) for x, y in track_dots(spec)
            if x > START[0] + 40]  # clear of the plank, on screen
    assert len(dots) >= (END[0] - START[0] - 40) // TRACK_DOT_GAP_PX
    differ = [dot for dot in dots if moving.get_at(dot) != still.get_at(dot)]
    assert differ == dots
    x, y = dots[0]
    assert moving.get_at((x, y - 6)) == still.get_at((x, y - 6))  # only the track is new
