"""A level as the game uses it: solids in a tile grid, a spawn, coins, enemies and exits.

Where it sits: produced by the Tiled loader (:mod:`game.levels`), consumed by
:class:`game.sim.world.World`. Nothing here reads files or touches the display, so tests can
build a level in a few lines.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import pygame

from game.collision.aabb import Box
from game.collision.tile_grid import TileGrid
from game.sim.platforms import PlatformSpec


@dataclass(frozen=True)
class CoinSpec:
    box: Box
    value: int = 1


@dataclass(frozen=True)
class EnemySpec:
    box: Box
    speed_px_s: float | None = None  # None: the game's default patrol speed
    kind: str = "walker"             # "walker" patrols; "hopper" patrols in hops


Animation = tuple[tuple[int, int], ...]  # a tile's frames: (gid shown, duration in ms)


@dataclass(frozen=True)
class TileLayer:
    """A tile layer to draw, in Tiled's document order: ``gids[row][col]`` (0 = empty)."""

    name: str
    gids: tuple[tuple[int, ...], ...]
    opacity: float = 1.0
    offset: tuple[float, float] = (0.0, 0.0)
    parallax: tuple[float, float] = (1.0, 1.0)  # how fast it scrolls with the camera (x, y)


@dataclass(frozen=True)
class Level:
    """Everything the simulation and the renderer need from one map."""

    path: Path
    grid: TileGrid
    spawn: Box
    coins: tuple[CoinSpec, ...] = ()
    enemies: tuple[EnemySpec, ...] = ()
    exits: tuple[Box, ...] = ()
    platforms: tuple[PlatformSpec, ...] = ()
    checkpoints: tuple[Box, ...] = ()
    title: str = ""
    next_level: Path | None = None
    properties: Mapping[str, object] = field(default_factory=dict)
    layers: tuple[TileLayer, ...] = ()  # drawn behind the sprites
    foreground: tuple[TileLayer, ...] = ()  # drawn over them (after the objects in Tiled)
    tile_images: Mapping[int, pygame.Surface] = field(default_factory=dict)  # drawn by gid
    animations: Mapping[int, Animation] = field(default_factory=dict)  # animated gids
    background_color: str | None = None
