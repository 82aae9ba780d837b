"""Build levels for tests from ASCII art, in memory or as real Tiled files.

Legend: ``#`` solid tile, ``-`` one-way tile, ``^`` hazard tile, ``P`` player spawn (top-left
of a 12x14 hitbox at the cell's corner), ``C`` coin (8x8 at the cell's corner), ``E`` enemy
(14x12 at the cell's corner), ``D`` exit (the whole cell). Every other character is empty.
"""

from __future__ import annotations

import math
from pathlib import Path

from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import NOTHING, Action
from game.sim.level import CoinSpec, EnemySpec, Level
from game.sim.platforms import PlatformSpec
from game.sim.tuning import Tuning
from game.sim.world import EventKind, Measure, World

TILE = 16
KINDS = {"#": TileKind.SOLID, "-": TileKind.ONE_WAY, "^": TileKind.HAZARD}
# For tests that check max_penetration_px: the tick measures it only when asked.
MEASURED = Measure(penetration=True)


def level_from_ascii(rows: list[str], properties: dict[str, object] | None = None,
                     spawn: Box | None = None) -> Level:
    width = max(len(r) for r in rows)
    grid = TileGrid(width, len(rows), TILE, TILE)
    coins: list[CoinSpec] = []
    enemies: list[EnemySpec] = []
    exits: list[Box] = []
    found_spawn = spawn
    for row, line in enumerate(rows):
        for col, char in enumerate(line):
            x, y = col * TILE, row * TILE
            if char in KINDS:
                grid.put(col, row, TileShape(Box(x, y, TILE, TILE), KINDS[char], col, row))
            elif char == "P" and found_spawn is None:
                found_spawn = Box(x, y, 12, 14)
            elif char == "C":
                coins.append(CoinSpec(Box(x, y, 8, 8), 1))
            elif char == "E":
                enemies.append(EnemySpec(Box(x, y, 14, 12)))
            elif char == "D":
                exits.append(Box(x, y, TILE, TILE))
    assert found_spawn is not None, "a test level needs a P"
    return Level(path=Path("test.tmx"), grid=grid, spawn=found_spawn, coins=tuple(coins),
                 enemies=tuple(enemies), exits=tuple(exits), properties=properties or {})


TSX = """<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="t" tilewidth="16" tileheight="16"
 tilecount="4" columns="4">
 <tile id="0" {attr}="Solid"/>
 <tile id="1" {attr}="OneWay"/>
 <tile id="2" {attr}="Hazard"/>
</tileset>
"""

GIDS = {"#": 1, "-": 2, "^": 3}


def write_tmx(folder: Path, rows: list[str], name: str = "level.tmx",
              properties: dict[str, tuple[str, object]] | None = None,
              class_attr: str = "type", extra_objects: str = "") -> Path:
    """Write a Tiled map (CSV data, external tileset) drawn from ASCII; return its path."""
    width = max(len(r) for r in rows)
    rows = [r.ljust(width) for r in rows]
    (folder / "t.tsx").write_text(TSX.format(attr=class_attr), encoding="utf-8")
    data = ",\n".join(",".join(str(GIDS.get(c, 0)) for c in r) for r in rows)
    objects: list[str] = []
    next_id = 1
    for row, line in enumerate(rows):
        for col, char in enumerate(line):
            x, y = col * TILE, row * TILE
            shape = {"P": ("Player", 12, 14), "C": ("Coin", 8, 8), "E": ("Enemy", 14, 12),
                     "D": ("Exit", TILE, TILE)}.get(char)
            if shape:
                objects.append(f'  <object id="{next_id}" {class_attr}="{shape[0]}" x="{x}" '
                               f'y="{y}" width="{shape[1]}" height="{shape[2]}"/>')
                next_id += 1
    props = "".join(f'  <property name="{k}" type="{t}" value="{v}"/>\n'
                    for k, (t, v) in (properties or {}).items())
    text = f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down"
 width="{width}" height="{len(rows)}" tilewidth="16" tileheight="16" infinite="0"
 nextlayerid="3" nextobjectid="{next_id}">
 <properties>
{props} </properties>
 <tileset firstgid="1" source="t.tsx"/>
 <layer id="1" name="ground" width="{width}" height="{len(rows)}">
  <data encoding="csv">
{data}
</data>
 </layer>
 <objectgroup id="2" name="objects">
{chr(10).join(objects)}
{extra_objects}
 </objectgroup>
</map>
"""
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def level_from_boxes(cols: int, rows: int, solids: list[Box], spawn: Box, exits: list[Box],
                     one_ways: tuple[Box, ...] = (), platforms: tuple[PlatformSpec, ...] = (),
                     checkpoints: tuple[Box, ...] = (), hazards: tuple[Box, ...] = (),
                     enemies: tuple[EnemySpec, ...] = ()) -> Level:
    """A level whose solid, one-way and hazard ground is given in pixels (cut into the cells
    it covers), for edges that fall between tile lines: a gap of 76 px, a ledge 44 px high."""
    grid = TileGrid(cols, rows, TILE, TILE)
    for kind, boxes in ((TileKind.SOLID, solids), (TileKind.ONE_WAY, one_ways),
                        (TileKind.HAZARD, hazards)):
        for box in boxes:
            for col in range(math.floor(box.left / TILE), math.ceil(box.right / TILE)):
                for row in range(math.floor(box.top / TILE), math.ceil(box.bottom / TILE)):
                    x0, x1 = max(box.left, col * TILE), min(box.right, (col + 1) * TILE)
                    y0, y1 = max(box.top, row * TILE), min(box.bottom, (row + 1) * TILE)
                    if x1 > x0 and y1 > y0:
                        grid.put(col, row, TileShape(Box(x0, y0, x1 - x0, y1 - y0), kind,
                                                     col, row))
    return Level(path=Path("test.tmx"), grid=grid, spawn=spawn, exits=tuple(exits),
                 platforms=platforms, checkpoints=checkpoints, enemies=enemies)


# A ledge of seven tiles over nothing, the spawn near its left end: for running off an edge
# (coyote time) and jumping from it.
LEDGE = ["                              ",
         "                              ",
         "                              ",
         "                              ",
         "  P                           ",
         "#######                       ",
         "                              ",
         "                              ",
         "                              "]


# A block on the floor between the spawn and the Exit: a map whose only route jumps it, checked
# and solved in a moment with the default physics.
HOP_OVER = ["        ",
            "P   #  D",
            "########"]


# A four-tile ceiling (columns 5-8, row 2) over a floor: for jumps that clip its corners.
CEILING = ["                    ",
           "                    ",
           "     ####           ",
           "                    ",
           "                    ",
           "                    ",
           "####################"]


def settled(rows: list[str], spawn: Box | None = None, tuning: Tuning | None = None) -> World:
    """A world drawn from ASCII whose player has fallen onto its floor and stands still."""
    world = World(level_from_ascii(rows, spawn=spawn), tuning or Tuning(), measure=MEASURED)
    for _ in range(30):
        world.step(NOTHING)
    assert world.player.on_ground
    return world


def jump_under_the_ceiling_from(x: float) -> tuple[World, float]:
    """Jump straight up under :data:`CEILING` from ``x``; return the world and the highest
    its player's head got."""
    world = settled(CEILING, spawn=Box(x, 6 * 16 - 14, 12, 14))
    highest = world.player.box.top
    for _ in range(30):
        world.step(frozenset({Action.JUMP}))
        highest = min(highest, world.player.box.top)
    return world, highest


# A one-way shelf under the spawn, and the floor three tiles below it: for dropping through.
ONE_WAY_SHELF = ["          ",
                 "          ",
                 "  P       ",
                 "  ----    ",
                 "          ",
                 "          ",
                 "##########"]

# The spawn five tiles above a floor: for jumps pressed while falling (the jump buffer).
DROP = ["  P        ", "           ", "           ", "           ", "           ",
        "           ", "###########"]


def jump_pressed_before_landing(ticks_early: int, tuning: Tuning | None = None,
                                ) -> tuple[bool, int]:
    """Fall onto the floor of :data:`DROP` holding jump from ``ticks_early`` ticks before the
    first tick that starts on the ground. Returns whether a jump happened, and on which tick."""
    tuning = tuning or Tuning()
    probe = World(level_from_ascii(DROP), tuning)
    first_on_ground = 0
    while not probe.player.on_ground:
        probe.step(NOTHING)
        first_on_ground += 1
    world = World(level_from_ascii(DROP), tuning)
    jump = frozenset({Action.JUMP})
    for tick in range(first_on_ground + 3):
        events = world.step(jump if tick >= first_on_ground - ticks_early else NOTHING)
        if any(event.kind is EventKind.JUMP for event in events):
            return True, tick
    return False, -1
