"""Each map's collision as text, one character per cell: what painting terrain must not change.

``python -m tests.collision_grids > tests/data/collision-grids.txt`` writes the grids of every
shipped map; ``tests/test_terrain.py`` compares the maps against that file. The file was written
from the maps as they were before their ground was repainted with terrain tiles.
"""

from __future__ import annotations

from pathlib import Path

from game.collision.shapes import TileKind
from game.levels import LEVELS_DIR
from game.levels.loader import load_level

EMPTY = "."
CELL_CHARS = {  # (kind, box relative to its cell) -> the character written
    (TileKind.SOLID, (0.0, 0.0, 16.0, 16.0)): "#",
    (TileKind.ONE_WAY, (0.0, 0.0, 16.0, 16.0)): "-",
    (TileKind.HAZARD, (1.0, 8.0, 14.0, 8.0)): "^",
}
OTHER = "?"  # any other kind or box: never in a shipped map


def shipped_maps() -> list[Path]:
    return sorted(LEVELS_DIR.glob("*.tmx")) + sorted(LEVELS_DIR.glob("showcase/*.tmx"))


def collision_grid(path: Path) -> list[str]:
    """The map's cells, a row a line: what each cell's tiles do when a body touches them."""
    grid = load_level(path).grid
    lines = []
    for row in range(grid.rows):
        line = ""
        for col in range(grid.cols):
            shapes = grid.shapes_at(col, row)
            if not shapes:
                line += EMPTY
                continue
            chars = {CELL_CHARS.get((shape.kind, (shape.box.x - col * grid.tile_w,
                                                  shape.box.y - row * grid.tile_h,
                                                  shape.box.w, shape.box.h)), OTHER)
                     for shape in shapes}
            line += chars.pop() if len(chars) == 1 else OTHER
        lines.append(line)
    return lines


def all_grids() -> str:
    parts = []
    for path in shipped_maps():
        parts.append(f"# {path.relative_to(LEVELS_DIR).as_posix()}")
        parts += collision_grid(path)
    return "\n".join(parts) + "\n"


if __name__ == "__main__":
    print(all_grids(), end="")
