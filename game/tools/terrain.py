"""Repaint the ground of Tiled maps with the tileset's terrain tiles, as Tiled's Terrain Brush
would, without changing what collides.

Run from the repository root::

    python -m game.tools.terrain levels/*.tmx          # rewrite the maps' tile data
    python -m game.tools.terrain --check levels/*.tmx  # exit 1 if any would change

Every cell of a tile layer that holds a ground tile of ``assets/tiles.tsx`` (the grass, the
dirt, the old stone wall, the lone block or any terrain tile) gets the terrain tile that fits
its eight neighbours: grass and an outline where it meets the air, sides, corners and inside
corners. Every one-way plank gets the plank that fits its left and right neighbours, ended
with an outline where its row stops. A neighbour counts when it holds a tile of the same
kind in the same layer; past the map's left, right and bottom edges the ground is taken to
go on, so no outline is drawn along the edge of the world. Every ground tile is Solid and
every plank OneWay, so the set of solid, one-way and hazard cells is the same before and
after (``tests/test_terrain.py`` holds each shipped map to the grid it had). Only the CSV
inside ``<data>`` is rewritten; objects and properties are untouched.

What it teaches: autotiling is a lookup. Eight neighbours make a byte; corners count only
when both edges beside them do (:func:`game.tools.art.blob_mask`), which leaves 47 looks;
a table turns each into a tile. Tiled's mixed Wang sets do the same as a designer paints.
"""

from __future__ import annotations

import argparse
import re
import sys
from collections.abc import Sequence
from pathlib import Path

from game.tools.art import (
    DIRT_FILL,
    EAST,
    FIELDSTONE,
    GROUND,
    GROUND_LEFT,
    GROUND_RIGHT,
    LONE_BLOCK,
    PLANK_MASKS,
    TERRAIN_IDS,
    WANG_ORDER,
    WEST,
    plank_tile_id,
    terrain_tile_id,
)

GROUND_FAMILY = frozenset({GROUND, DIRT_FILL, FIELDSTONE, GROUND_LEFT, GROUND_RIGHT,
                           LONE_BLOCK, *TERRAIN_IDS})  # tile ids the terrain repaints
PLANK_FAMILY = frozenset(PLANK_MASKS)  # one-way planks: their ends close where a row stops
TILESET_NAME = "tiles.tsx"
NEIGHBOURS = {bit: offset for bit, offset in zip(WANG_ORDER, (
    (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)), strict=True)}
TILESET_RE = re.compile(r'<tileset firstgid="(\d+)" source="([^"]+)"')
LAYER_RE = re.compile(r'(<layer [^>]*width="(\d+)" height="(\d+)"[^>]*>\s*<data encoding="csv">)'
                      r'(.*?)(</data>)', re.S)
FLIP_BITS = 0xF0000000  # Tiled's flip flags in the high bits of a gid


def repaint_rows(rows: Sequence[Sequence[int]], firstgid: int,
                 end: int | None = None) -> list[list[int]]:
    """``rows`` of gids with every ground cell (of the tileset whose gids run from
    ``firstgid`` up to ``end``, the next tileset's first) replaced by the terrain tile its
    neighbours call for.

    >>> from game.tools.art import EAST, SOUTH, SOUTH_EAST, SOUTH_WEST, WEST
    >>> top = 1 + terrain_tile_id(WEST | SOUTH_WEST | SOUTH | SOUTH_EAST | EAST)
    >>> repaint_rows([[0, 0, 0], [2, 1, 3]], 1) == [[0, 0, 0], [top, top, top]]
    True
    """
    height, width = len(rows), len(rows[0]) if rows else 0

    def of(family: frozenset[int], col: int, row: int) -> bool:
        if not (0 <= row < height and 0 <= col < width):
            return False
        gid = rows[row][col]
        if not gid or gid & FLIP_BITS or (end is not None and gid >= end):
            return False
        return gid - firstgid in family

    def ground(col: int, row: int) -> bool:
        if row >= height or col < 0 or col >= width:
            return row >= 0  # beyond the left, right and bottom edges the ground goes on
        return of(GROUND_FAMILY, col, row)

    painted = [list(line) for line in rows]
    for row in range(height):
        for col in range(width):
            if of(GROUND_FAMILY, col, row):
                mask = sum(bit for bit, (dx, dy) in NEIGHBOURS.items()
                           if ground(col + dx, row + dy))
                painted[row][col] = firstgid + terrain_tile_id(mask)
            elif of(PLANK_FAMILY, col, row):
                mask = (EAST if of(PLANK_FAMILY, col + 1, row) else 0) | (
                    WEST if of(PLANK_FAMILY, col - 1, row) else 0)
                painted[row][col] = firstgid + plank_tile_id(mask)
    return painted


def repaint_map(text: str) -> str:
    """The text of a ``.tmx`` with its ground repainted (unchanged if it does not use the
    game's tileset or keeps its tile data other than as CSV)."""
    tilesets = [(int(m.group(1)), m.group(2)) for m in TILESET_RE.finditer(text)]
    firstgid = next((first for first, source in tilesets if source.endswith(TILESET_NAME)),
                    None)
    if firstgid is None:
        return text
    end = min((first for first, _ in tilesets if first > firstgid), default=None)

    def layer(match: re.Match[str]) -> str:
        width = int(match.group(2))
        lines = [line.strip().rstrip(",") for line in match.group(4).strip().splitlines()]
        rows = [[int(value) for value in line.split(",")] for line in lines if line]
        if any(len(line) != width for line in rows):
            return match.group(0)
        painted = repaint_rows(rows, firstgid, end)
        body = ",\n".join(",".join(str(gid) for gid in line) for line in painted)
        return f"{match.group(1)}\n{body}\n{match.group(5)}"

    return LAYER_RE.sub(layer, text)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m game.tools.terrain",
                                     description="Repaint maps' ground with terrain tiles.")
    parser.add_argument("maps", nargs="+", type=Path)
    parser.add_argument("--check", action="store_true",
                        help="change nothing; exit 1 if any map is not painted this way")
    args = parser.parse_args(argv)
    stale = []
    for path in args.maps:
        text = path.read_text(encoding="utf-8")
        painted = repaint_map(text)
        if painted == text:
            continue
        stale.append(path)
        if not args.check:
            path.write_text(painted, encoding="utf-8")
            print(f"{path}: repainted")
    if args.check and stale:
        for path in stale:
            print(f"{path}: its ground is not painted with the terrain tiles; "
                  "run python -m game.tools.terrain on it")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
