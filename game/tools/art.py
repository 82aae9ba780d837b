"""Procedurally draw every piece of the game's art and write it to ``assets/``.

All sprites, tiles and the background are drawn here with plain pygame
surface operations: small character maps for the characters and props, and a
few deterministic loops for the tileable textures. Nothing is downloaded and no
third-party art is used, so the output can be released as CC0.

Run from the repository root::

    python -m game.tools.art

This (re)writes, in ``assets/`` next to the ``game`` package:

* ``tiles.png`` and ``tiles.tsx``: the 16x16 tileset and its Tiled tileset file
* ``player.png``, ``enemy.png``, ``coin.png``: horizontal sprite-sheet strips
* ``exit.png``, ``heart.png``, ``background.png``: single images

No display is needed: everything is drawn on off-screen ``SRCALPHA`` surfaces.
The output is deterministic (noise comes from fixed-seed generators).
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Mapping, Sequence

import pygame

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
TILESET_ROWS = 4
TILE_COUNT = TILESET_COLUMNS * TILESET_ROWS

FRAME = 16  # player and enemy frames are FRAME x FRAME
PLAYER_FRAME_COUNT = 8  # 2 idle, 4 run, 1 jump, 1 fall
ENEMY_FRAME_COUNT = 5  # 2 walker walk, 1 walker squashed, 2 hopper
COIN_SIZE = 8
COIN_FRAME_COUNT = 4
HEART_SIZE = 8
EXIT_WIDTH, EXIT_HEIGHT = 16, 32
BACKGROUND_WIDTH, BACKGROUND_HEIGHT = 320, 180

PLANK_HEIGHT = 5  # one-way platform: only the top rows of its tile are drawn
SPIKE_TOP = 8  # spikes occupy rows SPIKE_TOP..TILE of their tile
SPIKE_HITBOX = (1, 8, 14, 8)  # x, y, width, height inside the spike tile

SEED = 20240611  # fixed seed: the art is identical on every run

# --------------------------------------------------------------------------
# Palette
# --------------------------------------------------------------------------

OUTLINE: RGB = (38, 30, 56)
WHITE: RGB = (255, 255, 255)

GRASS_LIGHT: RGB = (164, 230, 92)
GRASS: RGB = (96, 190, 64)
GRASS_DARK: RGB = (46, 130, 60)

DIRT_LIGHT: RGB = (196, 136, 84)
DIRT: RGB = (158, 100, 62)
DIRT_DARK: RGB = (114, 68, 48)
PEBBLE: RGB = (226, 196, 156)
PEBBLE_SHADE: RGB = (184, 148, 112)
BACK_DIRT_LIGHT: RGB = (104, 72, 70)
BACK_DIRT: RGB = (82, 56, 60)
BACK_DIRT_DARK: RGB = (62, 42, 52)

STONE_LIGHT: RGB = (190, 196, 214)
STONE: RGB = (140, 146, 172)
STONE_DARK: RGB = (96, 98, 130)
MORTAR: RGB = (70, 66, 96)
BACK_STONE_LIGHT: RGB = (104, 100, 136)
BACK_STONE: RGB = (84, 80, 114)
BACK_STONE_DARK: RGB = (66, 62, 94)
BACK_MORTAR: RGB = (48, 42, 70)

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
SKY_MID: RGB = (124, 180, 252)
SKY_LOW: RGB = (162, 208, 255)
SKY_HORIZON: RGB = (206, 234, 255)
HILL_FAR_LIGHT: RGB = (170, 216, 214)
HILL_FAR: RGB = (140, 196, 200)
HILL_NEAR_LIGHT: RGB = (124, 200, 124)
HILL_NEAR: RGB = (84, 168, 108)
HILL_NEAR_DARK: RGB = (62, 140, 98)
CLOUD_SHADE: RGB = (214, 230, 250)
SUN: RGB = (255, 244, 170)

# --------------------------------------------------------------------------
# Tile ids (row-major in tiles.png) and their Tiled classes
# --------------------------------------------------------------------------

GROUND = 0
DIRT_FILL = 1
STONE_BRICK = 2
GROUND_LEFT = 3
GROUND_RIGHT = 4
ONE_WAY = 5
SPIKES = 6
METAL_CRATE = 7
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
    STONE_BRICK: "Solid",
    GROUND_LEFT: "Solid",
    GROUND_RIGHT: "Solid",
    ONE_WAY: "OneWay",
    SPIKES: "Hazard",
    METAL_CRATE: "Solid",
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
    """Paint the grass cap (outline, highlight, blades) over a dirt tile."""
    paint(tile, GRASS_CAP, GRASS_COLORS)


def draw_ground(tile: pygame.Surface) -> None:
    """Tile 0: grass-topped ground."""
    draw_dirt(tile, GRASS_DEPTH, SEED)
    draw_grass_cap(tile)


def draw_dirt_fill(tile: pygame.Surface) -> None:
    """Tile 1: plain dirt with pebbles (goes under ground tiles)."""
    draw_dirt(tile, 0, SEED + 1)


# Left end of a grass platform: rounded corner, grass running down the side,
# and an outline along the left edge of the dirt.
GROUND_LEFT_CAP = (
    "..oo..oo..oo..oo",
    ".olllo.llo.llo.l",
    "olllllllllllllll",
    "olglggllggllggll",
    "ogDggggggggggggg",
    "ogDggDggDggDgggD",
    "ogD.D..D.DD.D..D",
    "oD..............",
    "oD..............",
    "o...............",
    "o...............",
    "o...............",
    "o...............",
    "o...............",
    "o...............",
    "o...............",
)


def draw_ground_left(tile: pygame.Surface) -> None:
    """Tile 3: grass-topped ground, left end (top-left corner)."""
    draw_dirt(tile, GRASS_DEPTH, SEED + 2)
    paint(tile, GROUND_LEFT_CAP, GRASS_COLORS)
    tile.set_at((0, 0), (0, 0, 0, 0))
    tile.set_at((1, 0), (0, 0, 0, 0))


def draw_ground_right(tile: pygame.Surface) -> None:
    """Tile 4: grass-topped ground, right end (mirror of the left end)."""
    left = new_surface(TILE, TILE)
    draw_ground_left(left)
    tile.blit(pygame.transform.flip(left, True, False), (0, 0))


BRICK_HEIGHT = 4  # one course of bricks, mortar row included
BRICK_WIDTH = 8  # one brick, mortar column included


def draw_bricks(tile: pygame.Surface, shades: tuple[RGB, RGB, RGB, RGB], seed: int) -> None:
    """Running-bond bricks with mortar lines, bevelled light/dark edges."""
    light, base, dark, mortar = shades
    rng = random.Random(seed)
    tile.fill(mortar)
    for course in range(TILE // BRICK_HEIGHT):
        top = course * BRICK_HEIGHT
        offset = (BRICK_WIDTH // 2) * (course % 2)
        for left in range(-BRICK_WIDTH, TILE, BRICK_WIDTH):
            x0 = left + offset
            face = pygame.Rect(x0, top, BRICK_WIDTH - 1, BRICK_HEIGHT - 1)
            tile.fill(base, face)
            tile.fill(light, (x0, top, BRICK_WIDTH - 1, 1))
            tile.fill(dark, (x0 + BRICK_WIDTH - 2, top + 1, 1, BRICK_HEIGHT - 2))
            tile.fill(dark, (x0 + 1, top + BRICK_HEIGHT - 2, BRICK_WIDTH - 2, 1))
    speckle(tile, rng, pygame.Rect(0, 0, TILE, TILE), (dark,), 0.04)
    # Mortar is drawn last so speckles never land on it.
    for course in range(TILE // BRICK_HEIGHT):
        tile.fill(mortar, (0, course * BRICK_HEIGHT + BRICK_HEIGHT - 1, TILE, 1))
        offset = (BRICK_WIDTH // 2) * (course % 2)
        for x in range(offset + BRICK_WIDTH - 1, TILE, BRICK_WIDTH):
            tile.fill(mortar, (x, course * BRICK_HEIGHT, 1, BRICK_HEIGHT))


def draw_stone_brick(tile: pygame.Surface) -> None:
    """Tile 2: grey stone bricks (solid)."""
    draw_bricks(tile, (STONE_LIGHT, STONE, STONE_DARK, MORTAR), SEED + 3)


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


def draw_one_way(tile: pygame.Surface) -> None:
    """Tile 5: bolted wooden plank in the top PLANK_HEIGHT rows (one-way)."""
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


SPIKE = (
    "...o...",
    "..olo..",
    "..olo..",
    ".olmdo.",
    ".olmdo.",
    "olmmddo",
)
SPIKE_PITCH = 4  # 4 spikes across a tile
SPIKE_BASE = ("dddddddddddddddd", "oooooooooooooooo")


def draw_spikes(tile: pygame.Surface) -> None:
    """Tile 6: four silver spikes on a metal strip in the lower half."""
    colors = {"o": OUTLINE, "l": METAL_LIGHT, "m": METAL, "d": METAL_DARK}
    for index in range(TILE // SPIKE_PITCH):
        paint(tile, SPIKE, colors, index * SPIKE_PITCH - 1, SPIKE_TOP)
    paint(tile, SPIKE_BASE, colors, 0, TILE - len(SPIKE_BASE))


CRATE_PANEL = pygame.Rect(3, 3, 10, 10)  # recessed centre of the crate
CRATE_RIVETS = ((2, 2), (13, 2), (2, 13), (13, 13))


def draw_metal_crate(tile: pygame.Surface) -> None:
    """Tile 7: riveted steel crate with a diagonal brace (solid)."""
    tile.fill(OUTLINE)
    face = pygame.Rect(1, 1, TILE - 2, TILE - 2)
    tile.fill(METAL, face)
    tile.fill(METAL_LIGHT, (face.left, face.top, face.width, 1))
    tile.fill(METAL_LIGHT, (face.left, face.top, 1, face.height))
    tile.fill(METAL_DARK, (face.left, face.bottom - 1, face.width, 1))
    tile.fill(METAL_DARK, (face.right - 1, face.top + 1, 1, face.height - 1))
    panel = CRATE_PANEL
    tile.fill(METAL_DARK, (panel.left, panel.top, panel.width, 1))
    tile.fill(METAL_DARK, (panel.left, panel.top, 1, panel.height))
    tile.fill(METAL_LIGHT, (panel.left + 1, panel.bottom - 1, panel.width - 1, 1))
    tile.fill(METAL_LIGHT, (panel.right - 1, panel.top + 1, 1, panel.height - 1))
    for step in range(1, panel.width - 1):  # brace from bottom-left to top-right
        x, y = panel.left + step, panel.bottom - 1 - step
        tile.set_at((x, y), METAL_LIGHT)
        if x + 1 < panel.right - 1:
            tile.set_at((x + 1, y), METAL_DARK)
    for x, y in CRATE_RIVETS:
        tile.set_at((x, y), WHITE)


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
    """Tile 14: darker bricks for background layers (decor)."""
    draw_bricks(tile, (BACK_STONE_LIGHT, BACK_STONE, BACK_STONE_DARK, BACK_MORTAR), SEED + 4)


def draw_back_dirt(tile: pygame.Surface) -> None:
    """Tile 15: dark dirt for background layers (decor)."""
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
    STONE_BRICK: draw_stone_brick,
    GROUND_LEFT: draw_ground_left,
    GROUND_RIGHT: draw_ground_right,
    ONE_WAY: draw_one_way,
    SPIKES: draw_spikes,
    METAL_CRATE: draw_metal_crate,
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


def draw_tileset() -> pygame.Surface:
    """Return the whole tileset image (TILESET_COLUMNS x TILESET_ROWS tiles)."""
    sheet = new_surface(TILE * TILESET_COLUMNS, TILE * TILESET_ROWS)
    for tile_id, painter in TILE_PAINTERS.items():
        tile = new_surface(TILE, TILE)
        painter(tile)
        row, col = divmod(tile_id, TILESET_COLUMNS)
        sheet.blit(tile, (col * TILE, row * TILE))
    return sheet


def tileset_tsx() -> str:
    """Return the Tiled (1.8) external tileset XML describing tiles.png."""
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<tileset version="1.8" tiledversion="1.8.2" name="tiles" tilewidth="{TILE}"'
        f' tileheight="{TILE}" tilecount="{TILE_COUNT}" columns="{TILESET_COLUMNS}">',
        f' <image source="tiles.png" width="{TILE * TILESET_COLUMNS}"'
        f' height="{TILE * TILESET_ROWS}"/>',
    ]
    for tile_id in sorted(TILE_CLASSES):
        tile_class = TILE_CLASSES[tile_id]
        hitbox = TILE_HITBOXES.get(tile_id)
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
    lines.append("</tileset>")
    return "\n".join(lines) + "\n"


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


# --------------------------------------------------------------------------
# Background
# --------------------------------------------------------------------------

BAYER_4X4 = (
    (0, 8, 2, 10),
    (12, 4, 14, 6),
    (3, 11, 1, 9),
    (15, 7, 13, 5),
)


def bayer_threshold(x: int, y: int) -> float:
    """Ordered-dither threshold in (0, 1) for pixel (x, y)."""
    size = len(BAYER_4X4)
    return (BAYER_4X4[y % size][x % size] + 0.5) / size**2


SKY_BANDS = (SKY_HIGH, SKY_MID, SKY_LOW, SKY_HORIZON)
SKY_BOTTOM = 130  # the sky gradient reaches SKY_HORIZON at this row


def draw_sky(surface: pygame.Surface) -> None:
    """Ordered-dithered vertical gradient through the SKY_BANDS colours."""
    band_height = SKY_BOTTOM / (len(SKY_BANDS) - 1)
    for y in range(BACKGROUND_HEIGHT):
        position = min(y / band_height, len(SKY_BANDS) - 1.0)
        band = min(int(position), len(SKY_BANDS) - 2)
        blend = position - band
        for x in range(BACKGROUND_WIDTH):
            color = SKY_BANDS[band + 1] if blend > bayer_threshold(x, y) else SKY_BANDS[band]
            surface.set_at((x, y), color)


def hill_height(x: int, base: float, waves: Sequence[tuple[int, float, float]]) -> int:
    """Height (row) of a hill line at column x; waves are (cycles, amplitude, phase).

    Every wave completes a whole number of cycles across the background, so the
    hills wrap around seamlessly when the background is scrolled.
    """
    angle = 2 * math.pi * x / BACKGROUND_WIDTH
    return round(base + sum(amp * math.sin(cycles * angle + phase) for cycles, amp, phase in waves))


def draw_hills(
    surface: pygame.Surface,
    base: float,
    waves: Sequence[tuple[int, float, float]],
    shades: tuple[RGB, RGB],
    rim: RGB | None = None,
) -> None:
    """Fill a range of hills down to the bottom, with a lighter top edge."""
    light, body = shades
    for x in range(BACKGROUND_WIDTH):
        top = hill_height(x, base, waves)
        surface.fill(body, (x, top, 1, BACKGROUND_HEIGHT - top))
        surface.fill(light, (x, top, 1, 2))
        if rim is not None:
            surface.set_at((x, top), rim)


def darken_towards_bottom(surface: pygame.Surface, color: RGB, shade: RGB, top: int) -> None:
    """Dither pixels of ``color`` into ``shade`` more and more below row ``top``."""
    target = pygame.Color(color)
    for y in range(top, BACKGROUND_HEIGHT):
        amount = (y - top) / (BACKGROUND_HEIGHT - top)
        for x in range(BACKGROUND_WIDTH):
            if amount > bayer_threshold(x, y) and surface.get_at((x, y)) == target:
                surface.set_at((x, y), shade)


CLOUD_PUFFS = ((0, 6, 7), (8, 0, 9), (19, 4, 7), (27, 8, 5))  # (x, y, radius)
NEAR_HILLS_SHADE_TOP = 150  # near hills get darker below this row
SUN_CENTRE, SUN_RADIUS = (192, 24), 12
BACKGROUND_CLOUDS = ((24, 18), (132, 38), (214, 12), (290, 48))


def draw_background_cloud(surface: pygame.Surface, x: int, y: int) -> None:
    """One puffy cloud made of circles with a flat, shaded underside."""
    cloud = new_surface(48, 24)
    for px, py, radius in CLOUD_PUFFS:
        pygame.draw.circle(cloud, CLOUD_SHADE, (px + 8, py + 8), radius)
    for px, py, radius in CLOUD_PUFFS:
        pygame.draw.circle(cloud, WHITE, (px + 8, py + 6), radius - 1)
    cloud.fill((0, 0, 0, 0), (0, 17, 48, 7))
    for dx in (-BACKGROUND_WIDTH, 0):  # draw twice so clouds wrap at the edge
        surface.blit(cloud, (x + dx, y))


def draw_sky_picture() -> pygame.Surface:
    """Return the opaque 320x180 sky: the dithered gradient and the one sun. The game draws
    it still, behind the scrolling clouds and hills, so the sun never repeats."""
    surface = pygame.Surface((BACKGROUND_WIDTH, BACKGROUND_HEIGHT))
    draw_sky(surface)
    pygame.draw.circle(surface, SKY_HORIZON, SUN_CENTRE, SUN_RADIUS + 3)
    pygame.draw.circle(surface, SUN, SUN_CENTRE, SUN_RADIUS)
    return surface


def draw_background() -> pygame.Surface:
    """Return the 320x180 parallax scenery over clear sky: clouds and two hill ranges. Every
    part wraps round at the edges, so copies side by side show no seam."""
    surface = new_surface(BACKGROUND_WIDTH, BACKGROUND_HEIGHT)
    for x, y in BACKGROUND_CLOUDS:
        draw_background_cloud(surface, x, y)
    draw_hills(surface, 112, ((2, 14, 0.3), (5, 6, 1.7), (9, 2, 0.4)), (HILL_FAR_LIGHT, HILL_FAR))
    draw_hills(
        surface,
        142,
        ((3, 10, 2.1), (7, 4, 0.2), (11, 2, 1.1)),
        (HILL_NEAR_LIGHT, HILL_NEAR),
        rim=HILL_NEAR_DARK,
    )
    darken_towards_bottom(surface, HILL_NEAR, HILL_NEAR_DARK, NEAR_HILLS_SHADE_TOP)
    return surface


# --------------------------------------------------------------------------
# Entry point
# --------------------------------------------------------------------------

# Every image this module writes, with the size the game code expects.
IMAGES: dict[str, tuple[Callable[[], pygame.Surface], tuple[int, int]]] = {
    "tiles.png": (draw_tileset, (TILE * TILESET_COLUMNS, TILE * TILESET_ROWS)),
    "player.png": (draw_player, (FRAME * PLAYER_FRAME_COUNT, FRAME)),
    "enemy.png": (draw_enemy, (FRAME * ENEMY_FRAME_COUNT, FRAME)),
    "coin.png": (draw_coin, (COIN_SIZE * COIN_FRAME_COUNT, COIN_SIZE)),
    "exit.png": (draw_exit, (EXIT_WIDTH, EXIT_HEIGHT)),
    "heart.png": (draw_heart, (HEART_SIZE, HEART_SIZE)),
    "sky.png": (draw_sky_picture, (BACKGROUND_WIDTH, BACKGROUND_HEIGHT)),
    "background.png": (draw_background, (BACKGROUND_WIDTH, BACKGROUND_HEIGHT)),
}


def main() -> None:
    """Draw every asset and write it into ASSETS."""
    ASSETS.mkdir(parents=True, exist_ok=True)
    for name, (draw, size) in IMAGES.items():
        surface = draw()
        if surface.get_size() != size:
            raise RuntimeError(f"{name} is {surface.get_size()}, expected {size}")
        pygame.image.save(surface, str(ASSETS / name))
    (ASSETS / "tiles.tsx").write_text(tileset_tsx(), encoding="utf-8")
    fonts = write_fonts(ASSETS)
    print(f"wrote {len(IMAGES) + 1 + len(fonts)} files to {ASSETS} "
          "(the credits are in assets/README.md)")


if __name__ == "__main__":
    main()
