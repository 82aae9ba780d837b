"""Draw a solver's route over the whole map: where the player went, and how far it got.

Where it sits: ``python -m game.levels solve MAP --picture PNG`` calls :func:`draw_route`
with what :func:`game.checker.solver.solve` found. It draws the map's own tiles (the images
of its tilesets), each moving platform where it starts with the line its route follows,
the spawn, the Exits, the path of the hitbox's centre tick by tick, and, when no route was
found, a ring round the furthest place reached. When a map was proven impossible it also
tints every cell the proof's fill reached (:mod:`game.checker.reachable`), so the designer
sees where the player's reach ends and the Exit lies outside it.

What it teaches: a picture made from the same data the game plays is the quickest way to
see why a level can or cannot be finished; nothing here changes the level or the route.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import pygame

from game.collision.aabb import Box
from game.sim.level import Level, TileLayer

SKY = pygame.Color("#8fd3ff")
ROUTE = pygame.Color(255, 255, 255)
ROUTE_EDGE = pygame.Color(30, 30, 60)
SPAWN = pygame.Color("#3a7bd5")  # the colours the Tiled project gives these classes
EXIT = pygame.Color("#5cb85c")
PLATFORM = pygame.Color("#e67e22")
FURTHEST = pygame.Color("#d9534f")
REACHED = pygame.Color(255, 235, 120, 90)  # a cell the player's reach may touch
MAX_PICTURE_PX = 8192  # a bigger map is drawn at a fraction of its size


def _draw_layer(target: pygame.Surface, layer: TileLayer, level: Level) -> None:
    grid = level.grid
    dx, dy = layer.offset
    for row, gids in enumerate(layer.gids):
        for col, gid in enumerate(gids):
            image = level.tile_images.get(gid) if gid else None
            if image is not None:
                # Tiled draws a tile bigger than the grid standing on its cell's bottom-left.
                x = col * grid.tile_w + dx
                y = (row + 1) * grid.tile_h - image.get_height() + dy
                if layer.opacity < 1.0:
                    image = image.copy()
                    image.set_alpha(round(layer.opacity * 255))
                target.blit(image, (x, y))


def _outline(target: pygame.Surface, box: Box, color: pygame.Color) -> None:
    pygame.draw.rect(target, color, box.to_rect(), 2)


def _tint_cells(target: pygame.Surface, level: Level, cells: Iterable[tuple[int, int]]) -> None:
    grid = level.grid
    wash = pygame.Surface((grid.tile_w, grid.tile_h), pygame.SRCALPHA)
    wash.fill(REACHED)
    for col, row in cells:
        if 0 <= row < grid.rows:
            target.blit(wash, (col * grid.tile_w, row * grid.tile_h))


def draw_route(level: Level, route: Sequence[Box], furthest: Box | None,
               reach: Iterable[tuple[int, int]] | None = None) -> pygame.Surface:
    """The map with the route drawn over it (``furthest`` ringed when the route fell short,
    and the cells of ``reach`` tinted when given)."""
    grid = level.grid
    picture = pygame.Surface((grid.width_px, grid.height_px))
    picture.fill(pygame.Color(level.background_color) if level.background_color else SKY)
    for layer in (*level.layers, *level.foreground):
        _draw_layer(picture, layer, level)
    if reach is not None:
        _tint_cells(picture, level, reach)
    for platform in level.platforms:
        w, h = platform.width_px, platform.height_px
        x, y = platform.path.points[0]
        _outline(picture, Box(x, y, w, h), PLATFORM)
        centres = [(px + w / 2, py + h / 2) for px, py in platform.path.points]
        if len(centres) >= 2:
            pygame.draw.lines(picture, PLATFORM, platform.path.loop, centres, 1)
    for goal in level.exits:
        _outline(picture, goal, EXIT)
    _outline(picture, level.spawn, SPAWN)
    points = [box.center for box in route]
    if len(points) >= 2:
        pygame.draw.lines(picture, ROUTE_EDGE, False, points, 4)
        pygame.draw.lines(picture, ROUTE, False, points, 2)
    if furthest is not None:
        _outline(picture, furthest, FURTHEST)
        x, y = furthest.center
        pygame.draw.circle(picture, FURTHEST, (round(x), round(y)), 12, 2)
    scale = min(1.0, MAX_PICTURE_PX / max(picture.get_width(), picture.get_height()))
    if scale < 1.0:
        size = (max(1, round(picture.get_width() * scale)),
                max(1, round(picture.get_height() * scale)))
        picture = pygame.transform.smoothscale(picture, size)
    return picture

