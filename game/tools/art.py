"""Procedurally draw every piece of the game's art and write it to ``assets/``.

All sprites, tiles and the background are drawn here with plain pygame
surface operations: small character maps for the characters and props, and a
few deterministic loops for the tileable textures. Nothing is downloaded and no
third-party art is used, so the output can be released as CC0.

Run from the repository root::

    python -m game.tools.art

This (re)writes, in ``assets/`` next to the ``game`` package:

* ``tiles.png`` and ``tiles.tsx``: the 16x16 tileset of 32 tiles and its Tiled tileset file
  (ground, planks, spikes and decor, each id meaning what it always has)
* ``terrain.png`` and ``terrain.tsx``: the terrain tileset, a ground tile for each way a cell
  meets the air and planks with closed ends, with the terrain sets that let Tiled paint them
* ``player.png``, ``enemy.png``, ``coin.png``: horizontal sprite-sheet strips
* ``exit.png``, ``heart.png``: single images
* ``checkpoint.png``: the checkpoint's lantern on a post, unlit and lit (two frames)
* ``sky.png``, ``background.png`` and ``places/NAME-sky.png``, ``places/NAME-scenery.png``:
  each place's still sky and scrolling scenery (the meadow's twice: the title screen's)

The art direction every picture follows is written in ``assets/README.md``: one palette,
light from the top left, an outline where what is in play meets the air, crimson only for
what hurts, and a background without outlines that never reaches below the floor line.

No display is needed: everything is drawn on off-screen ``SRCALPHA`` surfaces.
The output is deterministic (noise comes from fixed-seed generators).
"""

from __future__ import annotations

import math
import random
import sys
from collections.abc import Callable, Mapping, Sequence
from functools import partial

import pygame

from game.app.files import save_image, write_text_atomically
from game.app.places import (
    DIRT,
    DIRT_DARK,
    DIRT_LIGHT,
    GRASS,
    GRASS_DARK,
    GRASS_LIGHT,
    PEBBLE,
    PEBBLE_SHADE,
    PLACES,
    SCENERY_FLOOR_ROW,
    Place,
)
from game.levels.closed_output import quiet_when_output_closes
from game.levels.shipped import ASSETS_DIR
from game.tools.pixel_font import write_fonts

ASSETS = ASSETS_DIR

RGB = tuple[int, int, int]
CharMap = Sequence[str]
Painter = Callable[[pygame.Surface], None]

# --------------------------------------------------------------------------
# Sizes and layouts (the game code depends on these)
# --------------------------------------------------------------------------

TILE = 16
TILESET_COLUMNS = 8
TILESET_ROWS = 4  # tiles.tsx: 32 tiles, the last 10 of them empty
TILE_COUNT = TILESET_COLUMNS * TILESET_ROWS
TERRAIN_COLUMNS = 8
TERRAIN_ROWS = 7  # terrain.tsx: 6 rows of ground looks, then a row of planks
TERRAIN_COUNT = TERRAIN_COLUMNS * TERRAIN_ROWS

FRAME = 16  # player and enemy frames are FRAME x FRAME
PLAYER_FRAME_COUNT = 8  # 2 idle, 4 run, 1 jump, 1 fall
ENEMY_FRAME_COUNT = 5  # 2 walker walk, 1 walker squashed, 2 hopper
COIN_SIZE = 8
COIN_FRAME_COUNT = 4
HEART_SIZE = 8
EXIT_WIDTH, EXIT_HEIGHT = 16, 32
CHECKPOINT_WIDTH, CHECKPOINT_HEIGHT = 16, 32  # one frame; the strip is unlit, then lit
CHECKPOINT_FRAME_COUNT = 2
BACKGROUND_WIDTH, BACKGROUND_HEIGHT = 320, 180

PLANK_HEIGHT = 5  # one-way platform: only the top rows of its tile are drawn
SPIKE_TOP = 8  # spikes occupy rows SPIKE_TOP..TILE of their tile (their collision box)
SPIKE_HITBOX = (1, 8, 14, 8)  # x, y, width, height inside the spike tile

SEED = 20240611  # fixed seed: the art is identical on every run

# --------------------------------------------------------------------------
# Palette
# --------------------------------------------------------------------------

OUTLINE: RGB = (38, 30, 56)
WHITE: RGB = (255, 255, 255)

# The grass and dirt colours come from game.app.places: each place swaps them for its own.
BACK_DIRT_LIGHT: RGB = (104, 72, 70)
BACK_DIRT: RGB = (82, 56, 60)
BACK_DIRT_DARK: RGB = (62, 42, 52)

STONE_LIGHT: RGB = (190, 196, 214)
STONE: RGB = (140, 146, 172)
STONE_DARK: RGB = (96, 98, 130)
BACK_STONE_LIGHT: RGB = (104, 100, 136)
BACK_STONE: RGB = (84, 80, 114)
BACK_STONE_DARK: RGB = (66, 62, 94)

WOOD_LIGHT: RGB = (226, 172, 104)
WOOD: RGB = (182, 122, 70)
WOOD_DARK: RGB = (124, 78, 48)

METAL_LIGHT: RGB = (236, 240, 250)
METAL: RGB = (176, 186, 206)
METAL_DARK: RGB = (110, 120, 150)

GOLD_LIGHT: RGB = (255, 240, 128)
GOLD: RGB = (250, 196, 44)
GOLD_DARK: RGB = (200, 124, 28)

RED_LIGHT: RGB = (255, 120, 120)
RED: RGB = (226, 58, 70)
RED_DARK: RGB = (156, 36, 56)
HAZARD_LIGHT: RGB = (255, 176, 196)  # what hurts: a hot crimson no safe tile uses
HAZARD: RGB = (246, 44, 96)
HAZARD_DARK: RGB = (176, 18, 70)
PINK: RGB = (255, 178, 190)
BLUE_LIGHT: RGB = (120, 176, 255)
BLUE: RGB = (60, 116, 226)
BLUE_DARK: RGB = (42, 72, 160)
NAVY: RGB = (52, 52, 104)
SKIN: RGB = (255, 208, 164)
HAIR: RGB = (122, 70, 40)

SLIME_LIGHT: RGB = (214, 150, 246)
SLIME: RGB = (160, 92, 214)
SLIME_DARK: RGB = (108, 56, 162)
FROG_LIGHT: RGB = (255, 196, 96)
FROG: RGB = (246, 136, 52)
FROG_DARK: RGB = (184, 80, 40)
CREAM: RGB = (255, 236, 196)

SKY_HIGH: RGB = (92, 150, 250)
CLOUD_SHADE: RGB = (214, 230, 250)

# --------------------------------------------------------------------------
# Tile ids (row-major in tiles.png) and their Tiled classes: maps made since the first
# version rely on them, so an id never changes meaning and the tileset never grows; the
# dark stone and dark dirt (14, 15), drawn as ground but first left without a class, are
# Solid, as they look
# --------------------------------------------------------------------------

GROUND = 0
DIRT_FILL = 1
FIELDSTONE = 2
GROUND_LEFT = 3
GROUND_RIGHT = 4
ONE_WAY = 5
SPIKES = 6
LONE_BLOCK = 7
BUSH = 8
FLOWER = 9
CLOUD_LEFT = 10
CLOUD_RIGHT = 11
GRASS_TUFT = 12
SIGNPOST = 13
BACK_WALL = 14
BACK_DIRT_FILL = 15
ROCK = 16
MUSHROOM = 17
FENCE = 18
BLUE_FLOWER = 19
PEBBLES = 20
TALL_GRASS = 21

TILE_CLASSES: dict[int, str] = {
    GROUND: "Solid",
    DIRT_FILL: "Solid",
    FIELDSTONE: "Solid",
    GROUND_LEFT: "Solid",
    GROUND_RIGHT: "Solid",
    ONE_WAY: "OneWay",
    SPIKES: "Hazard",
    LONE_BLOCK: "Solid",
    BACK_WALL: "Solid",
    BACK_DIRT_FILL: "Solid",
}
TILE_HITBOXES: dict[int, tuple[int, int, int, int]] = {SPIKES: SPIKE_HITBOX}

# --------------------------------------------------------------------------
# Drawing helpers
#
# Most sprites are "character maps": one string per pixel row, one character
# per pixel, where "." is transparent and every other character is looked up in
# a small per-sprite dict of palette colours ("o" is always the outline).
# --------------------------------------------------------------------------


def new_surface(width: int, height: int) -> pygame.Surface:
    """Return a fully transparent surface of the given size."""
    surface = pygame.Surface((width, height), pygame.SRCALPHA)
    surface.fill((0, 0, 0, 0))
    return surface


def paint(
    surface: pygame.Surface,
    rows: CharMap,
    colors: Mapping[str, RGB],
    x: int = 0,
    y: int = 0,
) -> None:
    """Paint a character map onto ``surface`` with its top-left at (x, y).

    Each character is looked up in ``colors``; ``.`` (or any character not in
    the mapping) leaves the pixel untouched. Pixels outside the surface are
    clipped.
    """
    width, height = surface.get_size()
    for row_index, row in enumerate(rows):
        for col_index, char in enumerate(row):
            color = colors.get(char)
            px, py = x + col_index, y + row_index
            if color is not None and 0 <= px < width and 0 <= py < height:
                surface.set_at((px, py), color)


def paint_standing(tile: pygame.Surface, rows: CharMap, colors: Mapping[str, RGB],
                   x: int = 0) -> None:
    """Paint a character map standing on the tile's bottom edge, ``x`` px from its left."""
    paint(tile, rows, colors, x, TILE - len(rows))


def sprite(rows: CharMap, colors: Mapping[str, RGB]) -> pygame.Surface:
    """Return a new surface exactly the size of a rectangular character map."""
    width = len(rows[0])
    if any(len(row) != width for row in rows):
        raise ValueError("character map rows must all have the same length")
    surface = new_surface(width, len(rows))
    paint(surface, rows, colors)
    return surface


def strip(frames: Sequence[pygame.Surface]) -> pygame.Surface:
    """Lay equally sized frames out left to right in a single surface."""
    width, height = frames[0].get_size()
    sheet = new_surface(width * len(frames), height)
    for index, frame in enumerate(frames):
        sheet.blit(frame, (index * width, 0))
    return sheet


def speckle(
    surface: pygame.Surface,
    rng: random.Random,
    area: pygame.Rect,
    colors: Sequence[RGB],
    density: float,
) -> None:
    """Sprinkle single pixels of ``colors`` over ``area`` (texture noise)."""
    for x in range(area.left, area.right):
        for y in range(area.top, area.bottom):
            if rng.random() < density:
                surface.set_at((x, y), rng.choice(colors))


# --------------------------------------------------------------------------
# Tiles
# --------------------------------------------------------------------------

PEBBLE_BIG = (
    ".lp.",
    "lppd",
    ".dd.",
)
PEBBLE_SMALL = (
    "lp",
    "dd",
)
PEBBLE_SPOTS = ((2, 10, PEBBLE_BIG), (11, 7, PEBBLE_SMALL), (10, 13, PEBBLE_BIG))


def draw_dirt(
    tile: pygame.Surface,
    top: int,
    seed: int,
    shades: tuple[RGB, RGB, RGB] = (DIRT_LIGHT, DIRT, DIRT_DARK),
    pebbles: bool = True,
) -> None:
    """Fill rows ``top``..16 of ``tile`` with speckled dirt and a few pebbles."""
    light, base, dark = shades
    rng = random.Random(seed)
    area = pygame.Rect(0, top, TILE, TILE - top)
    tile.fill(base, area)
    speckle(tile, rng, area, (dark, dark, light), 0.12)
    if not pebbles:
        return
    colors = {"l": PEBBLE, "p": PEBBLE_SHADE, "d": dark}
    for x, y, pebble in PEBBLE_SPOTS:
        if y > top:
            paint(tile, pebble, colors, x, y)


# Grass cap, one character per pixel column: the top 7 rows of a ground tile.
# The pattern repeats every 4 pixels so neighbouring tiles join seamlessly.
GRASS_CAP = (
    "o..oo..oo..oo..o",
    "lo.llo.llo.llo.l",
    "llollllllllllllo",
    "gllggllggllggllg",
    "gggggggggggggggg",
    "DgggDggDggDgggDg",
    "D.D.D..D.DD.D..D",
)
GRASS_COLORS = {"o": OUTLINE, "l": GRASS_LIGHT, "g": GRASS, "D": GRASS_DARK}
GRASS_DEPTH = 5  # dirt starts at this row; the grass cap is painted over it


def draw_grass_cap(tile: pygame.Surface) -> None:
    """Paint the grass cap (outline, highlight, blades) over the top rows of a tile."""
    tile.fill((0, 0, 0, 0), (0, 0, TILE, GRASS_DEPTH))
    paint(tile, GRASS_CAP, GRASS_COLORS)


# The terrain: one tile for every way a ground cell can meet the air around it ("blob"
# tiles). A cell's neighbours are eight bits; a corner counts only when both edges beside it
# are ground too, which leaves 47 looks. Bit order follows Tiled's Wang ids.
NORTH, NORTH_EAST, EAST, SOUTH_EAST, SOUTH, SOUTH_WEST, WEST, NORTH_WEST = (
    1 << bit for bit in range(8))
EDGES = (NORTH, EAST, SOUTH, WEST)
CORNERS = ((NORTH_EAST, NORTH, EAST), (SOUTH_EAST, SOUTH, EAST), (SOUTH_WEST, SOUTH, WEST),
           (NORTH_WEST, NORTH, WEST))  # each corner with the two edges beside it
WANG_ORDER = (NORTH, NORTH_EAST, EAST, SOUTH_EAST, SOUTH, SOUTH_WEST, WEST, NORTH_WEST)


def blob_mask(neighbours: int) -> int:
    """``neighbours`` (a bit per solid neighbour) with each corner kept only where both edges
    beside it are solid: the 47 masks that look different.

    >>> corner = NORTH | EAST | NORTH_EAST
    >>> blob_mask(NORTH_EAST) == 0, blob_mask(corner) == corner
    (True, True)
    """
    mask = neighbours & (NORTH | EAST | SOUTH | WEST)
    for corner, edge_a, edge_b in CORNERS:
        if neighbours & corner and mask & edge_a and mask & edge_b:
            mask |= corner
    return mask


BLOB_MASKS = tuple(sorted({blob_mask(bits) for bits in range(256)}))  # 47, 0 first


def terrain_tile_id(mask: int) -> int:
    """The tile of ``terrain.png`` that draws a ground cell with these solid neighbours (any
    8-bit mask): the lone block (id 0) for none, then one id for each of the 47 looks.

    >>> terrain_tile_id(0), terrain_tile_id(0xFF)
    (0, 46)
    """
    return BLOB_MASKS.index(blob_mask(mask))


# Tile ids of terrain.png (row-major, 8 columns): the ground looks, then a row of planks.
TERRAIN_IDS = {terrain_tile_id(mask): mask for mask in BLOB_MASKS}  # 0-46
PLANK_LEFT = 48
PLANK_MIDDLE = 49
PLANK_RIGHT = 50
PLANK_LONE = 51
TERRAIN_NAME = "Ground"  # the Wang set and its one colour, as Tiled's Terrain Sets list them
TERRAIN_COLOR = "#8c6d46"
PLANKS_NAME = "Planks"
PLANKS_COLOR = "#c8a165"
PLANK_MASKS = {PLANK_MIDDLE: EAST | WEST, PLANK_LEFT: EAST, PLANK_RIGHT: WEST, PLANK_LONE: 0}
TERRAIN_CLASSES: dict[int, str] = {**{tile_id: "Solid" for tile_id in TERRAIN_IDS},
                                   **{tile_id: "OneWay" for tile_id in PLANK_MASKS}}


def plank_tile_id(mask: int) -> int:
    """The plank tile of ``terrain.png`` for a one-way cell with planks to its ``EAST``
    and/or ``WEST``."""
    mask &= EAST | WEST
    return next(tile_id for tile_id, tile_mask in PLANK_MASKS.items() if tile_mask == mask)
GRASS_SIDE = (  # where grass meets the open side of a top corner: it hangs over the edge
    "..oo",
    ".oll",
    "olll",
    "olgl",
    "ogDg",
    "ogDg",
    "ogD.",
    "oD..",
    "oD..",
)
INNER_LIP = (  # an inside corner under grass: the neighbour's grass turns the corner
    "oo",
    "lo",
    "go",
    "D.",
)


def draw_terrain(tile: pygame.Surface, mask: int) -> None:
    """A ground cell whose solid neighbours are ``mask``: dirt inside; grass and an outline
    on top where it meets the air above; an outline with a lit rim (left) or a shaded rim
    (right, bottom) on every other open side; notches at the inside corners.

    Light comes from the top left, so the left rims are lighter and the right and bottom
    darker. Every tile uses the same dirt texture, so neighbours join without a seam.
    """
    draw_dirt(tile, 0, SEED + 1)
    clear = (0, 0, 0, 0)
    if not mask & WEST:
        tile.fill(OUTLINE, (0, 0, 1, TILE))
        tile.fill(DIRT_LIGHT, (1, 0, 1, TILE))
    if not mask & EAST:
        tile.fill(OUTLINE, (TILE - 1, 0, 1, TILE))
        tile.fill(DIRT_DARK, (TILE - 2, 0, 1, TILE))
    if not mask & SOUTH:
        tile.fill(OUTLINE, (0, TILE - 1, TILE, 1))
        tile.fill(DIRT_DARK, (1, TILE - 2, TILE - 2, 1))
        for open_side, x, inner_x in ((WEST, 0, 1), (EAST, TILE - 1, TILE - 2)):
            if not mask & open_side:  # round the bottom corner
                tile.set_at((x, TILE - 1), clear)
                tile.set_at((inner_x, TILE - 2), OUTLINE)
    if not mask & NORTH:
        draw_grass_cap(tile)
        if not mask & WEST:
            paint(tile, GRASS_SIDE, GRASS_COLORS)
            tile.set_at((0, 0), clear)
            tile.set_at((1, 0), clear)
        if not mask & EAST:
            paint(tile, [row[::-1] for row in GRASS_SIDE], GRASS_COLORS, TILE - 4)
            tile.set_at((TILE - 1, 0), clear)
            tile.set_at((TILE - 2, 0), clear)
    if mask & NORTH and mask & WEST and not mask & NORTH_WEST:
        paint(tile, [row[::-1] for row in INNER_LIP], GRASS_COLORS)
    if mask & NORTH and mask & EAST and not mask & NORTH_EAST:
        paint(tile, INNER_LIP, GRASS_COLORS, TILE - 2)
    if mask & SOUTH and mask & WEST and not mask & SOUTH_WEST:
        tile.set_at((0, TILE - 1), OUTLINE)
    if mask & SOUTH and mask & EAST and not mask & SOUTH_EAST:
        tile.set_at((TILE - 1, TILE - 1), OUTLINE)


def terrain_painter(mask: int) -> Painter:
    """A painter for :func:`draw_terrain` with ``mask``."""
    def draw(tile: pygame.Surface) -> None:
        draw_terrain(tile, mask)
    draw.__doc__ = f"Terrain tile for neighbour mask {mask}."
    return draw


def draw_ground(tile: pygame.Surface) -> None:
    """Tile 0: grass-topped ground with ground left, right and below (a terrain top)."""
    draw_terrain(tile, WEST | SOUTH_WEST | SOUTH | SOUTH_EAST | EAST)


def draw_dirt_fill(tile: pygame.Surface) -> None:
    """Tile 1: dirt with ground all round (the terrain's inside)."""
    draw_terrain(tile, 0xFF)


def draw_ground_left(tile: pygame.Surface) -> None:
    """Tile 3: grass-topped ground, left end (the terrain's top-left corner)."""
    draw_terrain(tile, EAST | SOUTH_EAST | SOUTH)


def draw_ground_right(tile: pygame.Surface) -> None:
    """Tile 4: grass-topped ground, right end (the terrain's top-right corner)."""
    draw_terrain(tile, WEST | SOUTH_WEST | SOUTH)


def draw_lone_block(tile: pygame.Surface) -> None:
    """Tile 7: a lone block of ground, open on every side (the terrain with no neighbour)."""
    draw_terrain(tile, 0)


FIELDSTONES = ((0, 0, 7, 5), (8, 1, 8, 5), (2, 6, 6, 5), (9, 7, 6, 4), (0, 12, 5, 4),
               (6, 12, 9, 4))  # x, y, width, height of each stone in a fieldstone wall


def draw_fieldstone(tile: pygame.Surface, shades: tuple[RGB, RGB, RGB], seed: int) -> None:
    """Rounded stones set in dirt, lit from the top left: the dirt's own pebbles, grown."""
    light, base, dark = shades
    draw_dirt(tile, 0, seed, (DIRT_LIGHT, DIRT, DIRT_DARK) if base == PEBBLE else
              (BACK_DIRT_LIGHT, BACK_DIRT, BACK_DIRT_DARK), pebbles=False)
    for x, y, width, height in FIELDSTONES:
        stone = pygame.Rect(x, y, width, height)
        tile.fill(base, stone.inflate(-2, 0))
        tile.fill(base, stone.inflate(0, -2))
        tile.fill(light, (stone.left + 1, stone.top, stone.width - 3, 1))
        tile.fill(light, (stone.left, stone.top + 1, 1, stone.height - 3))
        tile.fill(dark, (stone.left + 2, stone.bottom - 1, stone.width - 3, 1))
        tile.fill(dark, (stone.right - 1, stone.top + 2, 1, stone.height - 3))


def draw_fieldstone_wall(tile: pygame.Surface) -> None:
    """Tile 2: a fieldstone wall, pale stones in dirt (solid)."""
    draw_fieldstone(tile, (WHITE, PEBBLE, PEBBLE_SHADE), SEED + 3)


PLANK = (
    "oooooooooooooooo",
    "llllllllllllllll",
    "wwlwwwwlwwwwwlww",
    "dddddddddddddddd",
    "oooooooooooooooo",
)
PLANK_BOLT = (
    "nd",
    "dd",
)
PLANK_BOLT_COLUMNS = (2, 12)


PLANK_END = (  # the open end of a row of planks: outlined and rounded, over its left edge
    ".o",
    "ol",
    "ow",
    "od",
    ".o",
)


def draw_one_way(tile: pygame.Surface, open_left: bool = False,
                 open_right: bool = False) -> None:
    """Tile 5: bolted wooden plank in the top PLANK_HEIGHT rows (one-way), joined to more
    planks on both sides; ``open_left`` / ``open_right`` end it there with an outline."""
    if len(PLANK) != PLANK_HEIGHT:
        raise ValueError("PLANK must be PLANK_HEIGHT rows tall")
    colors = {"o": OUTLINE, "l": WOOD_LIGHT, "w": WOOD, "d": WOOD_DARK}
    paint(tile, PLANK, colors)
    bolt = {"n": METAL_LIGHT, "d": METAL_DARK}
    for x in PLANK_BOLT_COLUMNS:
        paint(tile, PLANK_BOLT, bolt, x, 2)
    # Joints between boards, so a row of planks reads as separate boards.
    tile.set_at((0, 2), WOOD_DARK)
    tile.set_at((TILE - 1, 2), WOOD_DARK)
    clear = (0, 0, 0, 0)
    if open_left:
        tile.fill(clear, (0, 0, 2, PLANK_HEIGHT))
        paint(tile, PLANK_END, colors)
    if open_right:
        tile.fill(clear, (TILE - 2, 0, 2, PLANK_HEIGHT))
        paint(tile, [row[::-1] for row in PLANK_END], colors, TILE - 2)


def draw_plank_left(tile: pygame.Surface) -> None:
    """Terrain tile 48: the left end of a row of planks (one-way)."""
    draw_one_way(tile, open_left=True)


def draw_plank_right(tile: pygame.Surface) -> None:
    """Terrain tile 50: the right end of a row of planks (one-way)."""
    draw_one_way(tile, open_right=True)


def draw_plank_lone(tile: pygame.Surface) -> None:
    """Terrain tile 51: one plank on its own, ended on both sides (one-way)."""
    draw_one_way(tile, open_left=True, open_right=True)


SPIKE = (
    "...ww...",
    "...wl...",
    "..wllr..",
    "..llrR..",
    ".llrrRR.",
    ".lrrrRR.",
    "lrrrrrRR",
)
SPIKE_PITCH = 8  # 2 big spikes across a tile: fewer, bolder teeth read at a glance
SPIKE_BASE = ("rrrrrrrrrrrrrrrr", "RRRRRRRRRRRRRRRR")
SPIKE_COLORS = {"o": OUTLINE, "w": WHITE, "l": HAZARD_LIGHT, "r": HAZARD, "R": HAZARD_DARK,
                "k": OUTLINE}


def draw_spikes(tile: pygame.Surface) -> None:
    """Tile 6: two big red spikes with white-hot tips on a crimson strip in the lower half. Red
    is kept for what hurts: no safe tile and no place's ground is drawn in it."""
    for index in range(TILE // SPIKE_PITCH):
        paint(tile, SPIKE, SPIKE_COLORS, index * SPIKE_PITCH, SPIKE_TOP)
    paint(tile, SPIKE_BASE, SPIKE_COLORS, 0, TILE - len(SPIKE_BASE))


BUSH_MAP = (
    "................",
    "................",
    "................",
    "................",
    "................",
    "......oooo......",
    "....oollllooo...",
    "...olllggllllo..",
    "..ollggggglggo..",
    "..olgggggggggDo.",
    ".olggllggggggDo.",
    ".olgglgggggggDo.",
    ".ogggggggggDgDo.",
    ".oDggggDgggDDDo.",
    "..oDDDDDDDDDDo..",
    "...oooooooooo...",
)


def draw_bush(tile: pygame.Surface) -> None:
    """Tile 8: round bush (decor)."""
    colors = {"o": OUTLINE, "l": GRASS_LIGHT, "g": GRASS, "D": GRASS_DARK}
    paint(tile, BUSH_MAP, colors)


FLOWER_MAP = (
    "................",
    "................",
    "................",
    "................",
    "......ooo.......",
    ".....owwwo......",
    "....oowyyoo.....",
    "...owwyYywwo....",
    "....oowyyoo.....",
    ".....owwwo......",
    "......ogo.ooo...",
    "..ooo.ogoollo...",
    "..ollooggllo....",
    "...ooolgoooo....",
    "......ogo.......",
    "......ogo.......",
)


def draw_flower(tile: pygame.Surface, petal: RGB = RED, centre: RGB = GOLD) -> None:
    """Tile 9: a flower on a leafy stem (decor)."""
    colors = {
        "o": OUTLINE,
        "w": petal,
        "y": centre,
        "Y": GOLD_LIGHT,
        "g": GRASS_DARK,
        "l": GRASS,
    }
    paint(tile, FLOWER_MAP, colors)


def draw_blue_flower(tile: pygame.Surface) -> None:
    """Tile 19: the flower again with blue petals (decor)."""
    draw_flower(tile, BLUE_LIGHT, WHITE)


CLOUD_MAP = (
    "................................",
    "................................",
    "................................",
    "...........oooooo...............",
    ".........oowwwwwwoo.............",
    "........owwwwwwwwwwo..oooo......",
    "....ooooowwwwwwwwwwwoowwwwoo....",
    "...owwwwwwwwwwwwwwwwwwwwwwwwo...",
    "..owwwwwwwwwwwwwwwwwwwwwwwwwwo..",
    ".owwwwwwwwwwwwwwwwwwwwwwwwwwwwo.",
    ".owwwwwwwwwwwwwwwwwwwwwwwwwwwwo.",
    ".owwwwwwwwwwwwwwwwwwwwwwwwwwwso.",
    "..osswwwwwwsssswwwwwwwwsssssso..",
    "...oossssssooosssssssssoooooo...",
    ".....oooooo...ooooooooo.........",
    "................................",
)


def draw_cloud_half(tile: pygame.Surface, half: int) -> None:
    """Tiles 10 and 11: left (half=0) or right (half=1) of a 32x16 cloud."""
    cloud = sprite(CLOUD_MAP, {"o": SKY_HIGH, "w": WHITE, "s": CLOUD_SHADE})
    tile.blit(cloud, (-half * TILE, 0))


def draw_cloud_left(tile: pygame.Surface) -> None:
    """Tile 10: left half of a cloud (decor)."""
    draw_cloud_half(tile, 0)


def draw_cloud_right(tile: pygame.Surface) -> None:
    """Tile 11: right half of a cloud (decor)."""
    draw_cloud_half(tile, 1)


TUFT_MAP = (
    "........o.......",
    "...o...olo...o..",
    "..olo..olo..olo.",
    "..olo.oolo..ol.o",
    "o.olooglgo.olgo.",
    "ooglglggglgolgo.",
    "oggglgggggggggo.",
)


def draw_grass_tuft(tile: pygame.Surface) -> None:
    """Tile 12: a tuft of grass blades standing on the tile's bottom edge."""
    paint_standing(tile, TUFT_MAP, {"o": OUTLINE, "l": GRASS_LIGHT, "g": GRASS})


SIGN_MAP = (
    "................",
    "................",
    "..oooooooooo....",
    ".ollllllllllo...",
    ".olwwwwwwOwwoo..",
    ".olwOOOOOOOwwwo.",
    ".olwwwwwwOwwwdo.",
    ".owwwwwwwwwwdo..",
    "..odddddddddo...",
    "...oooodooooo...",
    "......owdo......",
    "......owdo......",
    "......owdo......",
    "......owdo......",
    ".....oowddo.....",
    "....oooooooo....",
)


def draw_signpost(tile: pygame.Surface) -> None:
    """Tile 13: wooden signpost with an arrow pointing right (decor)."""
    colors = {"o": OUTLINE, "l": WOOD_LIGHT, "w": WOOD, "d": WOOD_DARK, "O": OUTLINE}
    paint(tile, SIGN_MAP, colors)


def draw_back_wall(tile: pygame.Surface) -> None:
    """Tile 14: a darker fieldstone wall (solid)."""
    draw_fieldstone(tile, (BACK_STONE_LIGHT, BACK_STONE, BACK_STONE_DARK), SEED + 4)


def draw_back_dirt(tile: pygame.Surface) -> None:
    """Tile 15: dark dirt (solid)."""
    draw_dirt(tile, 0, SEED + 5, (BACK_DIRT_LIGHT, BACK_DIRT, BACK_DIRT_DARK), pebbles=False)


ROCK_MAP = (
    ".....oooooo.....",
    "...oollllmmoo...",
    "..ollmmmmmmmdo..",
    ".olmmmmmmmmmddo.",
    ".olmmmmmmmmdmdo.",
    "ommmmmmmmmmmddo.",
    "odmmmmmmmddddddo",
    ".oddddddddddddo.",
    "..oooooooooooo..",
)


def draw_rock(tile: pygame.Surface) -> None:
    """Tile 16: a grey boulder (decor)."""
    paint_standing(tile, ROCK_MAP, {"o": OUTLINE, "l": STONE_LIGHT, "m": STONE, "d": STONE_DARK})


MUSHROOM_MAP = (
    "....oooooo......",
    "..oorrwwrroo....",
    ".orrwwrrrrRro...",
    "orrrrrrrwwrRRo..",
    "oRrrrrrrwwrRRo..",
    ".ooooooooooooo..",
    "....ocvco.......",
    "....ocvco.......",
    "...occvcco......",
    "...ooooooo......",
)


def draw_mushroom(tile: pygame.Surface) -> None:
    """Tile 17: a red spotted mushroom (decor)."""
    paint_standing(tile, MUSHROOM_MAP,
                   {"o": OUTLINE, "r": RED, "R": RED_DARK, "w": WHITE, "c": CREAM, "v": PEBBLE}, 1)


FENCE_MAP = (
    "..oo........oo..",
    ".olwo......olwo.",
    "oooooooooooooooo",
    "llllllllllllllll",
    "dddddddddddddddd",
    "oolwdoooooolwdoo",
    ".olwdo.....olwdo",
    "oooooooooooooooo",
    "llllllllllllllll",
    "dddddddddddddddd",
    "oolwdoooooolwdoo",
    ".olwdo.....olwdo",
    ".olwdo.....olwdo",
    ".oooo......oooo.",
)


def draw_fence(tile: pygame.Surface) -> None:
    """Tile 18: a wooden fence section that repeats horizontally (decor)."""
    paint_standing(tile, FENCE_MAP, {"o": OUTLINE, "l": WOOD_LIGHT, "w": WOOD, "d": WOOD_DARK})


PEBBLES_MAP = (
    ".......oo.......",
    "..oo..olmo......",
    ".olmo.ommdo..oo.",
    ".ommdo.ooo..olmo",
    "..ooo.......oooo",
)


def draw_pebbles(tile: pygame.Surface) -> None:
    """Tile 20: a few small stones lying on the ground (decor)."""
    paint_standing(tile, PEBBLES_MAP,
                   {"o": OUTLINE, "l": STONE_LIGHT, "m": STONE, "d": STONE_DARK})


TALL_GRASS_MAP = (
    ".....o......o...",
    "....olo....olo..",
    "....olo..o.olo..",
    "...ollo.olo.olo.",
    "...olgo.olo.olo.",
    "o..olgo.olgoolgo",
    "lo.olgo.olgoolgo",
    "lo.olgo.olgoolgo",
    "glooglgoolgolggo",
    "gglglggglggglggo",
)


def draw_tall_grass(tile: pygame.Surface) -> None:
    """Tile 21: tall grass blades (decor)."""
    paint_standing(tile, TALL_GRASS_MAP, {"o": OUTLINE, "l": GRASS_LIGHT, "g": GRASS})


TILE_PAINTERS: dict[int, Painter] = {
    GROUND: draw_ground,
    DIRT_FILL: draw_dirt_fill,
    FIELDSTONE: draw_fieldstone_wall,
    GROUND_LEFT: draw_ground_left,
    GROUND_RIGHT: draw_ground_right,
    ONE_WAY: draw_one_way,
    SPIKES: draw_spikes,
    LONE_BLOCK: draw_lone_block,
    BUSH: draw_bush,
    FLOWER: draw_flower,
    CLOUD_LEFT: draw_cloud_left,
    CLOUD_RIGHT: draw_cloud_right,
    GRASS_TUFT: draw_grass_tuft,
    SIGNPOST: draw_signpost,
    BACK_WALL: draw_back_wall,
    BACK_DIRT_FILL: draw_back_dirt,
    ROCK: draw_rock,
    MUSHROOM: draw_mushroom,
    FENCE: draw_fence,
    BLUE_FLOWER: draw_blue_flower,
    PEBBLES: draw_pebbles,
    TALL_GRASS: draw_tall_grass,
}
TERRAIN_PAINTERS: dict[int, Painter] = {
    **{tile_id: terrain_painter(mask) for tile_id, mask in TERRAIN_IDS.items()},
    PLANK_LEFT: draw_plank_left,
    PLANK_MIDDLE: draw_one_way,
    PLANK_RIGHT: draw_plank_right,
    PLANK_LONE: draw_plank_lone,
}


def draw_sheet(painters: Mapping[int, Painter], columns: int, rows: int) -> pygame.Surface:
    """A tileset image of ``columns`` x ``rows`` tiles, each id drawn by its painter."""
    sheet = new_surface(TILE * columns, TILE * rows)
    for tile_id, painter in painters.items():
        tile = new_surface(TILE, TILE)
        painter(tile)
        row, col = divmod(tile_id, columns)
        sheet.blit(tile, (col * TILE, row * TILE))
    return sheet


def draw_tileset() -> pygame.Surface:
    """Return the tileset image ``tiles.png`` (TILESET_COLUMNS x TILESET_ROWS tiles)."""
    return draw_sheet(TILE_PAINTERS, TILESET_COLUMNS, TILESET_ROWS)


def draw_terrain_tileset() -> pygame.Surface:
    """Return the terrain tileset image ``terrain.png`` (TERRAIN_COLUMNS x TERRAIN_ROWS)."""
    return draw_sheet(TERRAIN_PAINTERS, TERRAIN_COLUMNS, TERRAIN_ROWS)


def tileset_tsx() -> str:
    """Return the Tiled (1.8) external tileset XML describing tiles.png."""
    return tsx_text("tiles", TILESET_COLUMNS, TILESET_ROWS, TILE_CLASSES, TILE_HITBOXES, [])


def terrain_tsx() -> str:
    """Return the Tiled (1.8) external tileset XML describing terrain.png, with its
    terrain sets."""
    return tsx_text("terrain", TERRAIN_COLUMNS, TERRAIN_ROWS, TERRAIN_CLASSES, {},
                    wangsets_tsx())


def tsx_text(name: str, columns: int, rows: int, classes: Mapping[int, str],
             hitboxes: Mapping[int, tuple[int, int, int, int]], wangsets: list[str]) -> str:
    """A Tiled (1.8) external tileset for ``NAME.png``: each tile's class (and hitbox, where
    it has one), then its terrain sets."""
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<tileset version="1.8" tiledversion="1.8.2" name="{name}" tilewidth="{TILE}"'
        f' tileheight="{TILE}" tilecount="{columns * rows}" columns="{columns}">',
        f' <image source="{name}.png" width="{TILE * columns}" height="{TILE * rows}"/>',
    ]
    for tile_id in sorted(classes):
        tile_class = classes[tile_id]
        hitbox = hitboxes.get(tile_id)
        if hitbox is None:
            lines.append(f' <tile id="{tile_id}" type="{tile_class}"/>')
            continue
        x, y, width, height = hitbox
        lines += [
            f' <tile id="{tile_id}" type="{tile_class}">',
            '  <objectgroup draworder="index" id="2">',
            f'   <object id="1" x="{x}" y="{y}" width="{width}" height="{height}"/>',
            "  </objectgroup>",
            " </tile>",
        ]
    lines += wangsets
    lines.append("</tileset>")
    return "\n".join(lines) + "\n"


def wang_id(mask: int) -> str:
    """Tiled's Wang id of a terrain tile: ground (colour 1) or nothing (0) at its top, top
    right, right, bottom right, bottom, bottom left, left and top left.

    >>> wang_id(NORTH | EAST | NORTH_EAST)
    '1,1,1,0,0,0,0,0'
    """
    return ",".join("1" if mask & part else "0" for part in WANG_ORDER)


def wangsets_tsx() -> list[str]:
    """The terrain tileset's terrain sets (Tiled 1.8's ``<wangsets>``): ``Ground``, a *mixed*
    set, so Tiled's Terrain Brush picks each ground cell's tile from its eight neighbours; and
    ``Planks``, an *edge* set whose ends close where a row of planks stops. Every tile of the
    first is Solid and of the second OneWay, so painting never changes what collides."""
    top = terrain_tile_id(WEST | SOUTH_WEST | SOUTH | SOUTH_EAST | EAST)
    lines = [" <wangsets>",
             f'  <wangset name="{TERRAIN_NAME}" type="mixed" tile="{top}">',
             f'   <wangcolor name="{TERRAIN_NAME}" color="{TERRAIN_COLOR}" tile="{top}"'
             ' probability="1"/>']
    lines += [f'   <wangtile tileid="{tile_id}" wangid="{wang_id(mask)}"/>'
              for tile_id, mask in sorted(TERRAIN_IDS.items()) if mask]
    lines.append("  </wangset>")
    lines += [f'  <wangset name="{PLANKS_NAME}" type="edge" tile="{PLANK_MIDDLE}">',
              f'   <wangcolor name="{PLANKS_NAME}" color="{PLANKS_COLOR}" tile="{PLANK_MIDDLE}"'
              ' probability="1"/>']
    lines += [f'   <wangtile tileid="{tile_id}" wangid="{wang_id(mask)}"/>'
              for tile_id, mask in PLANK_MASKS.items() if mask]
    lines += ["  </wangset>", " </wangsets>"]
    return lines


# --------------------------------------------------------------------------
# Player: a kid in a red cap and blue shirt, facing right
# --------------------------------------------------------------------------

PLAYER_COLORS = {
    "o": OUTLINE,
    "r": RED,
    "R": RED_DARK,
    "w": RED_LIGHT,
    "h": HAIR,
    "s": SKIN,
    "c": PINK,
    "b": BLUE,
    "B": BLUE_DARK,
    "L": BLUE_LIGHT,
    "p": NAVY,
    "k": HAIR,  # boots share the hair's brown
}

# Head: rows y=2..8 of the frame (cap with a brim pointing right).
PLAYER_HEAD = (
    ".....oooooo.....",
    "....orrrrrwoooo.",
    "...orrrrrrrrRRRo",
    "..ohhsssssssooo.",
    "..ohhsssssosso..",
    "..ohssssssocso..",
    "...osssssssso...",
)
HEAD_TOP = 2

# Bodies: rows y=9..15 (collar, torso and arms, belt, legs, boots, soles).
BODY_IDLE = (
    "...oobbbbbboo...",
    "...obLbbBbbbo...",
    "...obLbbBbbbo...",
    "...oppppsppoo...",
    "...opppopppo....",
    "...okkkokkkko...",
    "...oooooooooo...",
)
BODY_RUN_1 = (
    "...oobbbbbboo...",
    "...obLbBBBsso...",
    "..osbLbbbbbbo...",
    "...oppppppppo...",
    "..opppooopppo...",
    ".okkko...okkkko.",
    ".ooooo...oooooo.",
)
BODY_RUN_2 = (
    "...oobbbbbboo...",
    "...obLbbBbbbo...",
    "...obLbbBbbbo...",
    "...oppppsppoo...",
    "...opppokkkko...",
    "...okkkooooo....",
    "...ooooo........",
)
BODY_RUN_3 = (
    "...oobbbbbboo...",
    "...obbbbbLbbo...",
    "..ossBbbbbbbo...",
    "...oppppppppo...",
    "..opppooopppo...",
    ".okkko...okkkko.",
    ".ooooo...oooooo.",
)
BODY_RUN_4 = (
    "...oobbbbbboo...",
    "...obLbbBbbbo...",
    "...obLbbBbbbo...",
    "...oppppsppoo...",
    "..okkkopppo.....",
    "..oooookkkko....",
    "......oooooo....",
)
BODY_JUMP = (
    "...oobbbbbbooo..",
    "...obLbbbbBBsso.",
    "...obLbbbbbooo..",
    "...oppppppppo...",
    "...opppoopkkko..",
    "...okkko.ooooo..",
    "...ooooo........",
)
BODY_FALL = (
    ".oooobbbbbbooo..",
    ".osBbLbbbbbbBso.",
    ".ooobLbbbbbbooo.",
    "...oppppppppo...",
    "...oppo..oppo...",
    "..okkko..okkko..",
    "..ooooo..ooooo..",
)
BODY_TOP = HEAD_TOP + len(PLAYER_HEAD)


def player_frame(body: CharMap, bob: int = 0) -> pygame.Surface:
    """One player frame: ``body`` with the head on top, lowered by ``bob`` px."""
    frame = new_surface(FRAME, FRAME)
    paint(frame, body, PLAYER_COLORS, 0, BODY_TOP)
    paint(frame, PLAYER_HEAD, PLAYER_COLORS, 0, HEAD_TOP + bob)
    return frame


def draw_player() -> pygame.Surface:
    """Return the player strip: 2 idle, 4 run, 1 jump, 1 fall (16x16 each)."""
    frames = [
        player_frame(BODY_IDLE),
        player_frame(BODY_IDLE, bob=1),
        player_frame(BODY_RUN_1),
        player_frame(BODY_RUN_2, bob=1),
        player_frame(BODY_RUN_3),
        player_frame(BODY_RUN_4, bob=1),
        player_frame(BODY_JUMP),
        player_frame(BODY_FALL),
    ]
    return strip(frames)


# --------------------------------------------------------------------------
# Enemies: a grumpy slime (walker) and a spring-frog (hopper)
# --------------------------------------------------------------------------

SLIME_COLORS = {
    "o": OUTLINE,
    "l": SLIME_LIGHT,
    "m": SLIME,
    "d": SLIME_DARK,
    "w": WHITE,
}

# Slime bodies (full 16x16 frames) and the face painted over them.
SLIME_TALL = (
    "................",
    "................",
    "................",
    "................",
    "......oooo......",
    "....oowlmmoo....",
    "...ollmmmmmmo...",
    "..olmmmmmmmmmo..",
    "..olmmmmmmmmmo..",
    ".olmmmmmmmmmmdo.",
    ".olmmmmmmmmmmdo.",
    ".ommmmmmmmmmmdo.",
    ".ommmmmmmmmmmdo.",
    ".odmmmmmmmmmddo.",
    ".oddddddddddddo.",
    "..oooooooooooo..",
)
SLIME_WIDE = (
    "................",
    "................",
    "................",
    "................",
    "................",
    ".....oooooo.....",
    "...oowllmmmoo...",
    "..olmmmmmmmmmo..",
    ".olmmmmmmmmmmmo.",
    "olmmmmmmmmmmmmdo",
    "olmmmmmmmmmmmmdo",
    "ommmmmmmmmmmmmdo",
    "ommmmmmmmmmmmmdo",
    "odmmmmmmmmmmmddo",
    "oddddddddddddddo",
    ".oooooooooooooo.",
)
SLIME_FACE = (
    ".....o......o...",
    "......oo..oo....",
    "......wo..wo....",
    "......wo..wo....",
    "................",
    ".......oooo.....",
    "......o.w..o....",
)
SLIME_FACE_TOP = 7  # row of the brows on the tall frame
SLIME_SQUASHED = (
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "................",
    "....oooooooo....",
    "..oowllmmmmmoo..",
    ".olmmoommmoommo.",
    "odmmmmmmmmmmmmdo",
    ".oooooooooooooo.",
)


def slime_frame(body: CharMap, face_top: int) -> pygame.Surface:
    """A walker frame: slime ``body`` with the grumpy face at row ``face_top``."""
    frame = sprite(body, SLIME_COLORS)
    paint(frame, SLIME_FACE, SLIME_COLORS, 0, face_top)
    return frame


FROG_COLORS = {
    "o": OUTLINE,
    "l": FROG_LIGHT,
    "f": FROG,
    "d": FROG_DARK,
    "w": WHITE,
    "c": CREAM,
    "n": METAL_LIGHT,
    "m": METAL,
    "k": METAL_DARK,
}

# The hopper: an orange frog riding a coil spring.
FROG_BODY = (
    "......ooo.ooo...",
    ".....owwwowwwo..",
    "...ooowowowowoo.",
    "..ollffffffffffo",
    ".olffffffffffffo",
    ".olffffffoooooo.",
    ".offfffffcccco..",
    ".oddfffffccco...",
    "..odddddoooo....",
    "...ooooo........",
)
FROG_UNDERSIDE = 8  # row of FROG_BODY that rests on the spring
SPRING_COMPRESSED = (
    "........onnnno..",
    ".......onnnnnko.",
    ".......oooooooo.",
)
SPRING_EXTENDED = (
    "........onnnno..",
    ".........omko...",
    "........onnnno..",
    ".........omko...",
    "........onnnno..",
    ".......onnnnnko.",
    ".......oooooooo.",
)


def frog_frame(spring: CharMap) -> pygame.Surface:
    """A hopper frame: the frog sitting on top of ``spring``."""
    frame = new_surface(FRAME, FRAME)
    spring_top = FRAME - len(spring)
    paint(frame, spring, FROG_COLORS, 0, spring_top)
    paint(frame, FROG_BODY, FROG_COLORS, 0, spring_top - FROG_UNDERSIDE - 1)
    return frame


def draw_enemy() -> pygame.Surface:
    """Return the enemy strip: slime walk x2, slime squashed, frog hop x2."""
    frames = [
        slime_frame(SLIME_TALL, SLIME_FACE_TOP),
        slime_frame(SLIME_WIDE, SLIME_FACE_TOP + 1),
        sprite(SLIME_SQUASHED, SLIME_COLORS),
        frog_frame(SPRING_COMPRESSED),
        frog_frame(SPRING_EXTENDED),
    ]
    return strip(frames)


# --------------------------------------------------------------------------
# Pickups, HUD and goal
# --------------------------------------------------------------------------

COIN_COLORS = {"o": OUTLINE, "l": GOLD_LIGHT, "g": GOLD, "d": GOLD_DARK, "w": WHITE}

COIN_FULL = (
    "..oooo..",
    ".owllgo.",
    "owlgggdo",
    "olgldgdo",
    "olgldgdo",
    "olgggddo",
    ".oddddo.",
    "..oooo..",
)
COIN_NARROW = (
    "..oooo..",
    ".owlgdo.",
    ".olgldo.",
    ".olgldo.",
    ".olgldo.",
    ".olggdo.",
    ".oddddo.",
    "..oooo..",
)
COIN_EDGE = (
    "...oo...",
    "..owdo..",
    "..oldo..",
    "..oldo..",
    "..oldo..",
    "..oldo..",
    "..oldo..",
    "...oo...",
)


def draw_coin() -> pygame.Surface:
    """Return the 4-frame spinning coin strip: full, narrow, edge, narrow."""
    narrow = sprite(COIN_NARROW, COIN_COLORS)
    frames = [
        sprite(COIN_FULL, COIN_COLORS),
        narrow,
        sprite(COIN_EDGE, COIN_COLORS),
        pygame.transform.flip(narrow, True, False),
    ]
    return strip(frames)


HEART_MAP = (
    ".oo..oo.",
    "owroorRo",
    "owrrrrRo",
    "orrrrrRo",
    ".orrrRo.",
    "..orRo..",
    "...oo...",
    "........",
)


def draw_heart() -> pygame.Surface:
    """Return the 8x8 HUD heart."""
    return sprite(HEART_MAP, {"o": OUTLINE, "r": RED, "R": RED_DARK, "w": WHITE})


FLAG_MAP = (
    ".oooo...........",
    "oyYyyo..........",
    "oyyydo..........",
    ".oddoooooooooo..",
    "..omlogggggggGo.",
    "..omloggggwggGGo",
    "..omloggwwwwwgGo",
    "..omlogggwwwggGo",
    "..omlogggwgwgGo.",
    "..omlogggggggGo.",
    "..omloGGGGGGGGo.",
    "..omlooooooooo..",
)
FLAG_POLE = "..omlo.........."
FLAG_BASE = (
    ".oooooooo.......",
    "obbbbbbbbko.....",
    "obsssssssko.....",
    "okkkkkkkkko.....",
    "ooooooooooo.....",
)
EXIT_COLORS = {
    "o": OUTLINE,
    "y": GOLD,
    "Y": GOLD_LIGHT,
    "d": GOLD_DARK,
    "g": GRASS,
    "G": GRASS_DARK,
    "w": WHITE,
    "m": METAL_DARK,
    "l": METAL_LIGHT,
    "b": STONE_LIGHT,
    "s": STONE,
    "k": STONE_DARK,
}


def draw_exit() -> pygame.Surface:
    """Return the 16x32 goal flag: gold knob, green pennant, pole, stone base."""
    surface = new_surface(EXIT_WIDTH, EXIT_HEIGHT)
    paint(surface, FLAG_MAP, EXIT_COLORS)
    base_top = EXIT_HEIGHT - len(FLAG_BASE)
    for y in range(len(FLAG_MAP), base_top):
        paint(surface, (FLAG_POLE,), EXIT_COLORS, 0, y)
    paint(surface, FLAG_BASE, EXIT_COLORS, 0, base_top)
    return surface


# The checkpoint is a lantern on a wooden post: nothing like the goal's flag on its metal
# pole and stone base, so no one takes one for the other. Unlit, its glass is dark and cold;
# lit (the respawn point is here), it glows gold round a white-hot flame.
LANTERN_MAP = (
    "......oooo......",
    ".....om..mo.....",
    "....oooooooo....",
    "...ollllllllo...",
    "...ommmmmmmmo...",
    "....oMggggMo....",
    "....oMgffgMo....",
    "....oMfFFfMo....",
    "....oMfFFfMo....",
    "....oMgffgMo....",
    "....oMggggMo....",
    "...ommmmmmmmo...",
    "....oooooooo....",
)
LANTERN_POST = "......oWwo......"
LANTERN_BASE = (
    ".....oWWwwo.....",
    "....oWWWwwwo....",
    "...oookkkkooo...",
    "....oooooooo....",
)
LANTERN_COLORS = {
    "o": OUTLINE,
    "l": METAL_LIGHT,
    "m": METAL,
    "M": METAL_DARK,
    "W": WOOD_LIGHT,
    "w": WOOD_DARK,
    "k": WOOD,
}
UNLIT_GLASS = {"g": (58, 64, 104), "f": (74, 82, 126), "F": (92, 100, 146)}  # cold, dark
LIT_GLASS = {"g": GOLD, "f": GOLD_LIGHT, "F": WHITE}  # a flame, bright to its heart


def draw_checkpoint_frame(glass: Mapping[str, RGB]) -> pygame.Surface:
    """One 16x32 checkpoint: the lantern with ``glass`` colours on its post."""
    surface = new_surface(CHECKPOINT_WIDTH, CHECKPOINT_HEIGHT)
    colors = {**LANTERN_COLORS, **glass}
    paint(surface, LANTERN_MAP, colors)
    base_top = CHECKPOINT_HEIGHT - len(LANTERN_BASE)
    for y in range(len(LANTERN_MAP), base_top):
        paint(surface, (LANTERN_POST,), colors, 0, y)
    paint(surface, LANTERN_BASE, colors, 0, base_top)
    return surface


def draw_checkpoint() -> pygame.Surface:
    """Return the checkpoint's strip: the lantern unlit (not reached), then lit."""
    return strip([draw_checkpoint_frame(UNLIT_GLASS), draw_checkpoint_frame(LIT_GLASS)])


# --------------------------------------------------------------------------
# Background: each place's still sky and its scrolling scenery
# --------------------------------------------------------------------------
#
# The background follows three rules, so it never reads as something to stand on: it has no
# outlines (only the things in play do), its colours lean towards the sky's, and its shapes
# rise from SCENERY_FLOOR, the row the renderer lines up with the level's floor line. Below
# that line the scenery is only seen behind the ground; in a pit the renderer draws darkness.

SKY_BOTTOM = 130  # the sky's bands reach the horizon colour at this row
SCENERY_FLOOR = SCENERY_FLOOR_ROW  # the scenery's shapes end here; the game puts it on the floor
SKY_HORIZON: RGB = PLACES["meadow"].sky[-1]
SUN: RGB = PLACES["meadow"].sun or WHITE
SUN_CENTRE, SUN_RADIUS = (192, 24), 12
Wave = tuple[int, float, float]  # cycles across the picture, amplitude in px, phase


def draw_sky(surface: pygame.Surface, bands: Sequence[RGB]) -> None:
    """A vertical gradient in flat bands, one per colour, down to SKY_BOTTOM: no dither, so it
    stays clean however large the window scales it."""
    band_h = SKY_BOTTOM / len(bands)
    for y in range(BACKGROUND_HEIGHT):
        surface.fill(bands[min(int(y / band_h), len(bands) - 1)], (0, y, BACKGROUND_WIDTH, 1))


def wave_height(x: int, base: float, waves: Sequence[Wave]) -> float:
    """Height (row) of a wavy line at column x. Every wave completes a whole number of cycles
    across the picture, so the line wraps round when the scenery is scrolled."""
    angle = 2 * math.pi * x / BACKGROUND_WIDTH
    return base + sum(amp * math.sin(cycles * angle + phase) for cycles, amp, phase in waves)


def hill_height(x: int, base: float, waves: Sequence[Wave]) -> int:
    """:func:`wave_height`, rounded to a whole row."""
    return round(wave_height(x, base, waves))


def fill_skyline(surface: pygame.Surface, tops: Sequence[int], shades: tuple[RGB, RGB],
                 bottom: int = BACKGROUND_HEIGHT) -> None:
    """Fill each column x from ``tops[x]`` down to ``bottom`` (a lighter 2 px rim on top)."""
    light, body = shades
    for x, top in enumerate(tops):
        if top < bottom:
            surface.fill(body, (x, top, 1, bottom - top))
            surface.fill(light, (x, top, 1, min(2, bottom - top)))


def wavy(base: float, waves: Sequence[Wave]) -> list[int]:
    return [hill_height(x, base, waves) for x in range(BACKGROUND_WIDTH)]


def stepped(base: int, seed: int, steps: int, rise: int) -> list[int]:
    """A skyline of flat tops and sheer sides (cliffs, mesas): ``steps`` ledges across the
    picture at heights up to ``rise`` above ``base``, the same at both ends so it wraps."""
    rng = random.Random(seed)
    edges = sorted(rng.sample(range(8, BACKGROUND_WIDTH - 8), steps - 1))
    heights = [base - rng.randrange(rise) for _ in range(steps)]
    heights[-1] = heights[0]
    tops = []
    for x in range(BACKGROUND_WIDTH):
        ledge = sum(1 for edge in edges if x >= edge)
        tops.append(heights[ledge] + (1 if (x * 7 + ledge) % 11 == 0 else 0))  # crumbly rims
    return tops


def peaked(base: int, peaks: Sequence[tuple[int, int, int]]) -> list[int]:
    """A skyline of straight-sided peaks: (centre x, height, half width), wrapping round."""
    tops = [base] * BACKGROUND_WIDTH
    for centre, height, half in peaks:
        for dx in range(-half, half + 1):
            x = (centre + dx) % BACKGROUND_WIDTH
            tops[x] = min(tops[x], base - height + round(height * abs(dx) / half))
    return tops


def snow_caps(surface: pygame.Surface, tops: Sequence[int], snow: RGB, depth: int,
              line: int) -> None:
    """Whiten the parts of a skyline above row ``line``, ``depth`` px deep, with a ragged edge."""
    for x, top in enumerate(tops):
        if top < line:
            surface.fill(snow, (x, top, 1, min(depth + (x * 5) % 3, line - top)))


def draw_pines(surface: pygame.Surface, base: int, spacing: int, shade: RGB, seed: int) -> None:
    """A row of pine-tree silhouettes standing on row ``base``, wrapping round."""
    rng = random.Random(seed)
    for left in range(0, BACKGROUND_WIDTH, spacing):
        height = rng.randrange(18, 34)
        trunk_x = left + rng.randrange(spacing // 2)
        for dy in range(height):
            half = 1 + (dy % 6) // 2 + dy // 5  # three-tier crown, wider as it goes down
            y = base - height + dy
            for dx in range(-half, half + 1):
                surface.set_at(((trunk_x + dx) % BACKGROUND_WIDTH, y), shade)
        surface.fill(shade, (trunk_x, base, 1, SCENERY_FLOOR - base))


def draw_stalactites(surface: pygame.Surface, shade: RGB, light: RGB, seed: int) -> None:
    """Rock teeth hanging from the top of a cave, with a lit left edge."""
    rng = random.Random(seed)
    surface.fill(shade, (0, 0, BACKGROUND_WIDTH, 6))
    x = 0
    while x < BACKGROUND_WIDTH - 10:
        half, length = rng.randrange(3, 9), rng.randrange(10, 44)
        for dy in range(length):
            width = max(0, round(half * (1 - dy / length)))
            surface.fill(shade, (x + half - width, 6 + dy, 2 * width + 1, 1))
            surface.set_at((x + half - width, 6 + dy), light)
        x += 2 * half + rng.randrange(2, 14)


CLOUD_PUFFS = ((0, 6, 7), (8, 0, 9), (19, 4, 7), (27, 8, 5))  # (x, y, radius)
BACKGROUND_CLOUDS = ((24, 18), (132, 38), (214, 12), (290, 48))


def draw_background_cloud(surface: pygame.Surface, x: int, y: int,
                          colors: tuple[RGB, RGB] = (WHITE, CLOUD_SHADE)) -> None:
    """One puffy cloud made of circles with a flat, shaded underside."""
    face, shade = colors
    cloud = new_surface(48, 24)
    for px, py, radius in CLOUD_PUFFS:
        pygame.draw.circle(cloud, shade, (px + 8, py + 8), radius)
    for px, py, radius in CLOUD_PUFFS:
        pygame.draw.circle(cloud, face, (px + 8, py + 6), radius - 1)
    cloud.fill((0, 0, 0, 0), (0, 17, 48, 7))
    for dx in (-BACKGROUND_WIDTH, 0):  # draw twice so clouds wrap at the edge
        surface.blit(cloud, (x + dx, y))


def mix(a: RGB, b: RGB, amount: float) -> RGB:
    """``a`` moved ``amount`` (0..1) of the way towards ``b``."""
    return (round(a[0] + (b[0] - a[0]) * amount), round(a[1] + (b[1] - a[1]) * amount),
            round(a[2] + (b[2] - a[2]) * amount))


def draw_place_sky(place: Place) -> pygame.Surface:
    """The opaque 320x180 still sky of ``place``: its bands and its one sun (or none)."""
    surface = pygame.Surface((BACKGROUND_WIDTH, BACKGROUND_HEIGHT))
    draw_sky(surface, place.sky)
    if place.sun is not None:
        centre = SUN_CENTRE if place.shapes != "dunes" else (120, 96)  # dusk: low and large
        radius = SUN_RADIUS if place.shapes != "dunes" else 2 * SUN_RADIUS
        pygame.draw.circle(surface, mix(place.sun, place.sky[-1], 0.6), centre, radius + 3)
        pygame.draw.circle(surface, place.sun, centre, radius)
    return surface


def draw_place_scenery(place: Place) -> pygame.Surface:
    """The 320x180 scenery of ``place`` over clear sky, ending at SCENERY_FLOOR; it wraps
    round at the edges, so copies side by side show no seam."""
    surface = new_surface(BACKGROUND_WIDTH, BACKGROUND_HEIGHT)
    far, (near_light, near, near_dark) = place.far, place.near
    clouds = (mix(WHITE, place.sky[-1], 0.2), mix(CLOUD_SHADE, place.sky[2], 0.3))
    if place.shapes in ("hills", "cliffs", "pines", "peaks", "dunes"):
        for x, y in BACKGROUND_CLOUDS:
            draw_background_cloud(surface, x, y, clouds if place.shapes != "hills"
                                  else (WHITE, CLOUD_SHADE))
    if place.shapes == "hills":
        fill_skyline(surface, wavy(112, ((2, 14, 0.3), (5, 6, 1.7), (9, 2, 0.4))), far)
        fill_skyline(surface, wavy(132, ((3, 10, 2.1), (7, 4, 0.2), (11, 2, 1.1))),
                     (near_light, near))
    elif place.shapes == "cliffs":
        fill_skyline(surface, stepped(100, SEED + 10, 7, 40), far)
        fill_skyline(surface, stepped(130, SEED + 11, 9, 24), (near_light, near))
    elif place.shapes == "pines":
        fill_skyline(surface, wavy(104, ((2, 10, 1.0), (5, 5, 0.2))), far)
        draw_pines(surface, 126, 14, mix(near, far[1], 0.4), SEED + 12)
        fill_skyline(surface, wavy(134, ((4, 4, 0.7), (9, 2, 2.0))), (near_light, near))
        draw_pines(surface, 140, 22, near_dark, SEED + 13)
    elif place.shapes == "caves":
        fill_skyline(surface, stepped(96, SEED + 14, 10, 30), far)
        draw_stalactites(surface, near_dark, near_light, SEED + 15)
        fill_skyline(surface, peaked(SCENERY_FLOOR, ((40, 36, 14), (150, 26, 10),
                                                      (250, 44, 16))), (near_light, near))
    elif place.shapes == "dunes":
        fill_skyline(surface, wavy(116, ((1, 12, 0.5), (3, 6, 2.2))), far)
        fill_skyline(surface, wavy(136, ((2, 8, 1.3), (5, 3, 0.1))), (near_light, near))
    elif place.shapes == "peaks":
        tops = peaked(SCENERY_FLOOR, ((30, 70, 50), (120, 92, 60), (210, 60, 44),
                                      (280, 80, 52)))
        fill_skyline(surface, tops, far)
        snow_caps(surface, tops, WHITE, 10, SCENERY_FLOOR - 40)
        fill_skyline(surface, wavy(134, ((3, 6, 0.4), (7, 3, 1.9))), (near_light, near))
    else:  # pragma: no cover (places.py names only these shapes)
        raise ValueError(f"no scenery drawn for {place.shapes!r}")
    return surface


def draw_sky_picture() -> pygame.Surface:
    """The meadow's sky (``sky.png``): the title screen's, and any level's without a setting."""
    return draw_place_sky(PLACES["meadow"])


def draw_background() -> pygame.Surface:
    """The meadow's scenery (``background.png``): clouds and two hill ranges."""
    return draw_place_scenery(PLACES["meadow"])


def place_images() -> dict[str, Callable[[], pygame.Surface]]:
    """Each place's two pictures, by the name they are written under in ``assets/places/``."""
    images: dict[str, Callable[[], pygame.Surface]] = {}
    for name, place in PLACES.items():
        images[f"places/{name}-sky.png"] = partial(draw_place_sky, place)
        images[f"places/{name}-scenery.png"] = partial(draw_place_scenery, place)
    return images


# --------------------------------------------------------------------------
# Entry point
# --------------------------------------------------------------------------

# Every image this module writes, with the size the game code expects.
IMAGES: dict[str, tuple[Callable[[], pygame.Surface], tuple[int, int]]] = {
    "tiles.png": (draw_tileset, (TILE * TILESET_COLUMNS, TILE * TILESET_ROWS)),
    "terrain.png": (draw_terrain_tileset, (TILE * TERRAIN_COLUMNS, TILE * TERRAIN_ROWS)),
    "player.png": (draw_player, (FRAME * PLAYER_FRAME_COUNT, FRAME)),
    "enemy.png": (draw_enemy, (FRAME * ENEMY_FRAME_COUNT, FRAME)),
    "coin.png": (draw_coin, (COIN_SIZE * COIN_FRAME_COUNT, COIN_SIZE)),
    "exit.png": (draw_exit, (EXIT_WIDTH, EXIT_HEIGHT)),
    "checkpoint.png": (draw_checkpoint,
                       (CHECKPOINT_WIDTH * CHECKPOINT_FRAME_COUNT, CHECKPOINT_HEIGHT)),
    "heart.png": (draw_heart, (HEART_SIZE, HEART_SIZE)),
    "sky.png": (draw_sky_picture, (BACKGROUND_WIDTH, BACKGROUND_HEIGHT)),
    "background.png": (draw_background, (BACKGROUND_WIDTH, BACKGROUND_HEIGHT)),
    **{name: (draw, (BACKGROUND_WIDTH, BACKGROUND_HEIGHT))
       for name, draw in place_images().items()},
}


def main() -> None:
    """Draw every asset and write it into ASSETS."""
    (ASSETS / "places").mkdir(parents=True, exist_ok=True)
    for name, (draw, size) in IMAGES.items():
        surface = draw()
        if surface.get_size() != size:
            raise RuntimeError(f"{name} is {surface.get_size()}, expected {size}")
        save_image(surface, ASSETS / name)
    write_text_atomically(ASSETS / "tiles.tsx", tileset_tsx())
    write_text_atomically(ASSETS / "terrain.tsx", terrain_tsx())
    fonts = write_fonts(ASSETS)
    print(f"wrote {len(IMAGES) + 2 + len(fonts)} files to {ASSETS} "
          "(the credits are in assets/README.md)")


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
