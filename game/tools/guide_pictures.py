"""Make the pictures of the level designer's guide (``levels/README.md``) with the game.

Run from the repository root::

    python -m game.tools.guide_pictures

It (re)writes, in ``assets/guide/``:

* ``player-point.png``: a Player drawn as a point, and the hitbox the game hangs from it
  (its top-left corner on the point), over the game's own tiles;
* ``reach.png``: the path of the feet in a full running jump, recorded tick by tick from
  the real simulation (:func:`game.checker.reach.jump_path`), over a grid of 16 px tiles
  with ledges 3 and 2 tiles up;
* ``hop-along-tick-60.png`` and ``hop-along-tick-100.png``: the game's own screenshots of
  Hop Along at two ticks, where the pennant has waved on and the far clouds have scrolled
  half as far as the ground;
* ``route-first-steps.png``: ``python -m game.levels solve``'s picture of the route it
  found through the first level;
* ``terrain.png``: one shape of ground twice, on the left as one tile stamped everywhere,
  on the right painted with the terrain tileset's tiles by the rule Tiled's Terrain Brush
  follows (:func:`game.tools.terrain.repaint_rows`), with a spike pit.

Every picture is drawn by game code from game data; nothing is drawn by hand.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from pathlib import Path

import pygame

from game.app.files import load_image, save_image
from game.checker.reach import jump_path
from game.levels import FIRST_LEVEL, LEVELS_DIR
from game.levels.closed_output import quiet_when_output_closes
from game.sim.tuning import Tuning
from game.tools.art import DIRT_FILL, SPIKES, TILE_COUNT
from game.tools.terrain import repaint_rows

ROOT = Path(__file__).resolve().parents[2]
GUIDE = ROOT / "assets" / "guide"
TILE = 16
SCALE = 3  # the diagrams are drawn at 16 px a tile, then enlarged this many times
MAX_SHEET_BYTES = 4 * 1024 * 1024  # a tile sheet of the game's own is a few kB
SKY = (143, 211, 255)
GRID = (120, 180, 230)
HITBOX = (217, 83, 79)
POINT = (58, 123, 213)
PATH = (255, 255, 255)
PATH_EDGE = (30, 30, 60)
GROUND_TILE = 0  # ids in assets/tiles.png
TERRAIN_FIRST_GID = 1 + TILE_COUNT  # assets/terrain.png follows it, as in the shipped maps
TERRAIN_SHAPE = (  # "#" ground, "^" spikes, for terrain.png
    "..........",
    ".....###..",
    "..#.......",
    ".###...##.",
    "####^^####",
    "##########",
)


def _tile(sheet: pygame.Surface, tile_id: int) -> pygame.Surface:
    columns = sheet.get_width() // TILE
    row, col = divmod(tile_id, columns)
    return sheet.subsurface((col * TILE, row * TILE, TILE, TILE))


def _canvas(cols: int, rows: int) -> pygame.Surface:
    canvas = pygame.Surface((cols * TILE, rows * TILE))
    canvas.fill(SKY)
    for col in range(cols + 1):
        pygame.draw.line(canvas, GRID, (col * TILE, 0), (col * TILE, rows * TILE))
    for row in range(rows + 1):
        pygame.draw.line(canvas, GRID, (0, row * TILE), (cols * TILE, row * TILE))
    return canvas


def _save(canvas: pygame.Surface, name: str) -> None:
    big = pygame.transform.scale(canvas, (canvas.get_width() * SCALE,
                                          canvas.get_height() * SCALE))
    save_image(big, GUIDE / name)


def _paint(canvas: pygame.Surface, sheet: pygame.Surface, shape: tuple[str, ...],
           left: int = 0, terrain: bool = True) -> None:
    """Lay ``shape`` (``#`` ground, ``^`` spikes) on ``canvas`` from column ``left``: the
    ground painted with the terrain tileset's tiles, or (``terrain=False``) the dirt tile
    everywhere."""
    terrain_sheet = load_image(ROOT / "assets" / "terrain.png", MAX_SHEET_BYTES)
    gids = [[1 + DIRT_FILL if char == "#" else 0 for char in row] for row in shape]
    if terrain:
        gids = repaint_rows(gids, 1, TERRAIN_FIRST_GID)
    for row, line in enumerate(gids):
        for col, gid in enumerate(line):
            at = ((left + col) * TILE, row * TILE)
            if shape[row][col] == "^":
                canvas.blit(_tile(sheet, SPIKES), at)
            elif gid >= TERRAIN_FIRST_GID:
                canvas.blit(_tile(terrain_sheet, gid - TERRAIN_FIRST_GID), at)
            elif gid:
                canvas.blit(_tile(sheet, gid - 1), at)


def terrain(sheet: pygame.Surface) -> None:
    """The same ground, stamped with one tile (left) and painted as terrain (right)."""
    width = len(TERRAIN_SHAPE[0])
    canvas = _canvas(2 * width + 1, len(TERRAIN_SHAPE))
    _paint(canvas, sheet, TERRAIN_SHAPE, terrain=False)
    _paint(canvas, sheet, TERRAIN_SHAPE, left=width + 1)
    _save(canvas, "terrain.png")


def player_point(sheet: pygame.Surface) -> None:
    """A point at (40, 18): the 12x14 hitbox hangs below and right of it."""
    tuning = Tuning()
    canvas = _canvas(6, 3)
    for col in range(6):
        canvas.blit(_tile(sheet, GROUND_TILE), (col * TILE, 2 * TILE))
    x, y = 40, 2 * TILE - tuning.player_height_px
    pygame.draw.rect(canvas, HITBOX, (x, y, tuning.player_width_px,
                                      tuning.player_height_px), 1)
    pygame.draw.circle(canvas, POINT, (x, y), 2)
    _save(canvas, "player-point.png")


def reach(sheet: pygame.Surface) -> None:
    """A running jump from the left, with ledges 2 and 3 tiles above the floor."""
    cols, rows = 14, 6
    floor_row = rows - 1
    canvas = _canvas(cols, rows)
    shape = ["." * cols for _ in range(rows)]
    shape[floor_row - 3] = "." * 8 + "##" + "." * (cols - 10)
    shape[floor_row - 2] = "." * 11 + "##" + "." * (cols - 13)
    shape[floor_row] = "#" * cols
    _paint(canvas, sheet, tuple(shape))
    path = jump_path(Tuning())
    start_x, floor_y = path[0].x, path[0].bottom
    # The path of the feet (the middle of the hitbox's bottom edge), from the take-off.
    points = [(TILE + box.center[0] - start_x, floor_row * TILE - (floor_y - box.bottom))
              for box in path]
    pygame.draw.lines(canvas, PATH_EDGE, False, points, 3)
    pygame.draw.lines(canvas, PATH, False, points, 1)
    _save(canvas, "reach.png")


def screenshots() -> None:
    """Hop Along at ticks 60 and 100, running right with the winning script."""
    level = LEVELS_DIR / "03-hop-along.tmx"
    script = ROOT / "tests" / "scripts" / "03-hop-along.txt"
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    for ticks in (60, 100):
        subprocess.run([sys.executable, "-m", "game", "--headless", "--level", str(level),
                        "--inputs", str(script), "--ticks", str(ticks), "--screenshot",
                        str(GUIDE / f"hop-along-tick-{ticks}.png")], env=env, check=True)


def route() -> None:
    """The solver's route through the first level; its script goes to a file thrown away
    (``solve --out`` writes only regular files)."""
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy"}
    with tempfile.TemporaryDirectory() as folder:
        subprocess.run([sys.executable, "-m", "game.levels", "solve", str(FIRST_LEVEL),
                        "--out", str(Path(folder) / "route.txt"),
                        "--picture", str(GUIDE / "route-first-steps.png")], env=env, check=True)


def main() -> None:
    GUIDE.mkdir(parents=True, exist_ok=True)
    sheet = load_image(ROOT / "assets" / "tiles.png", MAX_SHEET_BYTES)
    player_point(sheet)
    reach(sheet)
    terrain(sheet)
    screenshots()
    route()


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
