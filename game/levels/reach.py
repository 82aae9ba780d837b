"""How high and how far the player can jump, measured by the game itself.

Where it sits: ``python -m game.levels check`` prints it for the maps it checks, and the
level designer's guide (``levels/README.md``) quotes it, so a designer knows which ledges
are in reach before drawing them.

What it teaches: measure, don't derive by hand. The height of a jump is not simply
``v² / 2g``: the tick applies gravity before it moves, speeds are capped, and letting go of
jump cuts the rise. So :func:`measure_reach` builds a flat test level, runs the player up to
full speed, holds jump until it lands, and reads the highest point and the landing place off
the real :meth:`World.step` with the given tuning.

>>> reach = measure_reach(Tuning())
>>> round(reach.height_px, 1), round(reach.distance_px, 1)
(44.3, 57.0)
>>> reach.describe(16)
'jumps 2.8 tiles high and 3.6 tiles across at a run (16 px tiles)'
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import Action
from game.sim.level import Level
from game.sim.tuning import Tuning
from game.sim.world import World

TEST_TILE_PX = 16
TEST_COLS, TEST_ROWS = 400, 40
RUN_UP_TICKS = 30  # long enough to reach full speed with any sane tuning
MAX_AIR_TICKS = 60 * 60


@dataclass(frozen=True)
class Reach:
    """A full jump at a run: how much higher the feet get, and how far it carries."""

    height_px: float
    distance_px: float

    def describe(self, tile_px: int) -> str:
        return (f"jumps {self.height_px / tile_px:.1f} tiles high and "
                f"{self.distance_px / tile_px:.1f} tiles across at a run ({tile_px} px tiles)")


def jump_path(tuning: Tuning) -> list[Box]:
    """The hitbox at take-off and after every tick of a full jump at a run, until it lands,
    on a flat floor with nothing overhead."""
    floor_row = TEST_ROWS - 1
    grid = TileGrid(TEST_COLS, TEST_ROWS, TEST_TILE_PX, TEST_TILE_PX)
    for col in range(TEST_COLS):
        grid.put(col, floor_row, TileShape(
            Box(col * TEST_TILE_PX, floor_row * TEST_TILE_PX, TEST_TILE_PX, TEST_TILE_PX),
            TileKind.SOLID, col, floor_row))
    spawn = Box(TEST_TILE_PX, floor_row * TEST_TILE_PX - tuning.player_height_px,
                tuning.player_width_px, tuning.player_height_px)
    world = World(Level(Path("reach"), grid, spawn), tuning)
    run, jump = frozenset({Action.RIGHT}), frozenset({Action.RIGHT, Action.JUMP})
    for _ in range(RUN_UP_TICKS):
        world.step(run)
    path = [world.player.box]
    for _ in range(MAX_AIR_TICKS):
        world.step(jump)
        path.append(world.player.box)
        if world.player.on_ground:
            break
    return path


def measure_reach(tuning: Tuning) -> Reach:
    """The reach of a full jump with ``tuning``: the highest point and the landing place of
    :func:`jump_path`."""
    path = jump_path(tuning)
    take_off = path[0]
    highest = min(box.y for box in path)
    return Reach(take_off.y - highest, path[-1].x - take_off.x)
