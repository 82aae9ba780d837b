"""Repaint the ground of Tiled maps with the terrain tileset, as Tiled's Terrain Brush would,
without changing what collides.

Run from the repository root::

    python -m game.tools.terrain levels/*.tmx          # rewrite the maps' tile data
    python -m game.tools.terrain --check levels/*.tmx  # exit 1 if any would change

Every cell of a tile layer that holds a ground tile (the grass, the dirt, the fieldstone
wall or the lone block of ``assets/tiles.tsx``, or any ground tile of ``assets/terrain.tsx``)
gets the tile of ``terrain.tsx`` that fits its eight neighbours: grass and an outline where
it meets the air, sides, corners and inside corners. Every one-way plank (of either tileset)
gets the plank of ``terrain.tsx`` that fits its left and right neighbours, ended with an
outline where its row stops. A neighbour counts when it holds a tile of the same kind in the
same layer; past the map's left, right and bottom edges the ground is taken to go on, so no
outline is drawn along the edge of the world. Every ground tile is Solid and every plank
OneWay, so the set of solid, one-way and hazard cells is the same before and after
(``tests/test_terrain.py`` holds each shipped map to the grid it had).

A map that uses ``tiles.tsx`` but not yet ``terrain.tsx`` gets ``terrain.tsx`` added, from
the same folder, after its last tileset, at the first free gid, as Tiled's *Add External
Tileset* would: no gid already in the map changes meaning. Only that line and the CSV inside
``<data>`` are written; objects and properties are untouched.

What it teaches: autotiling is a lookup. Eight neighbours make a byte; corners count only
when both edges beside them do (:func:`game.tools.art.blob_mask`), which leaves 47 looks;
a table turns each into a tile. Tiled's mixed Wang sets do the same as a designer paints.
"""

from __future__ import annotations

import argparse
import re
import sys
import xml.etree.ElementTree as ET
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
    ONE_WAY,
    PLANK_MASKS,
    TERRAIN_COUNT,
    TERRAIN_IDS,
    TILE_COUNT,
    WANG_ORDER,
    WEST,
    plank_tile_id,
    terrain_tile_id,
)

TILES_GROUND = frozenset({GROUND, DIRT_FILL, FIELDSTONE, GROUND_LEFT, GROUND_RIGHT, LONE_BLOCK})
TILES_PLANKS = frozenset({ONE_WAY})  # tile ids of tiles.tsx the terrain repaints
TERRAIN_GROUND = frozenset(TERRAIN_IDS)
TERRAIN_PLANKS = frozenset(PLANK_MASKS)  # one-way planks: their ends close where a row stops
TILESET_NAME = "tiles.tsx"
TERRAIN_TILESET_NAME = "terrain.tsx"
NEIGHBOURS = {bit: offset for bit, offset in zip(WANG_ORDER, (
    (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)), strict=True)}
TILESET_RE = re.compile(r'<tileset firstgid="(\d+)"([^>]*?)(/?)>')
SOURCE_RE = re.compile(r'source="([^"]+)"')
TILECOUNT_RE = re.compile(r'tilecount="(\d+)"')
LAYER_RE = re.compile(r'(<layer [^>]*width="(\d+)" height="(\d+)"[^>]*>\s*<data encoding="csv">)'
                      r'(.*?)(</data>)', re.S)
FLIP_BITS = 0xF0000000  # Tiled's flip flags in the high bits of a gid


class TerrainError(Exception):
    """A map the tool cannot repaint, said in one sentence."""


def repaint_rows(rows: Sequence[Sequence[int]], tiles_first: int | None,
                 terrain_first: int) -> list[list[int]]:
    """``rows`` of gids with every ground and plank cell (of ``tiles.tsx``, whose first gid
    is ``tiles_first``, or ``terrain.tsx``, whose first gid is ``terrain_first``) replaced by
    the terrain tile its neighbours call for.

    >>> from game.tools.art import EAST, SOUTH, SOUTH_EAST, SOUTH_WEST, WEST
    >>> top = 33 + terrain_tile_id(WEST | SOUTH_WEST | SOUTH | SOUTH_EAST | EAST)
    >>> repaint_rows([[0, 0, 0], [2, 1, 3]], 1, 33) == [[0, 0, 0], [top, top, top]]
    True
    """
    height, width = len(rows), len(rows[0]) if rows else 0

    def kind(gid: int) -> str:
        """``"ground"``, ``"plank"`` or ``""`` (anything else) for one gid."""
        if not gid or gid & FLIP_BITS:
            return ""
        if tiles_first is not None and 0 <= gid - tiles_first < TILE_COUNT:
            tile_id, ground, planks = gid - tiles_first, TILES_GROUND, TILES_PLANKS
        elif 0 <= gid - terrain_first < TERRAIN_COUNT:
            tile_id, ground, planks = gid - terrain_first, TERRAIN_GROUND, TERRAIN_PLANKS
        else:
            return ""
        return "ground" if tile_id in ground else "plank" if tile_id in planks else ""

    def of(wanted: str, col: int, row: int) -> bool:
        return 0 <= row < height and 0 <= col < width and kind(rows[row][col]) == wanted

    def ground(col: int, row: int) -> bool:
        if row >= height or col < 0 or col >= width:
            return row >= 0  # beyond the left, right and bottom edges the ground goes on
        return of("ground", col, row)

    painted = [list(line) for line in rows]
    for row in range(height):
        for col in range(width):
            if of("ground", col, row):
                mask = sum(bit for bit, (dx, dy) in NEIGHBOURS.items()
                           if ground(col + dx, row + dy))
                painted[row][col] = terrain_first + terrain_tile_id(mask)
            elif of("plank", col, row):
                mask = (EAST if of("plank", col + 1, row) else 0) | (
                    WEST if of("plank", col - 1, row) else 0)
                painted[row][col] = terrain_first + plank_tile_id(mask)
    return painted


def tile_count(tag: str, folder: Path | None) -> int:
    """How many tiles the ``<tileset>`` opening ``tag`` holds: its own ``tilecount``, or that
    of the external file it names, read from ``folder`` (the map's)."""
    source = SOURCE_RE.search(tag)
    if source is None:
        count = TILECOUNT_RE.search(tag)
        if count is None:
            raise TerrainError(f"the tileset {tag} does not say how many tiles it has")
        return int(count.group(1))
    name = source.group(1)
    if folder is None:
        raise TerrainError(f"cannot read the tileset {name} without the map's folder")
    try:
        root = ET.parse(folder / name).getroot()
        return int(root.get("tilecount", ""))
    except (OSError, ET.ParseError, ValueError):
        raise TerrainError(f"the tileset {name} cannot be read or does not say how many tiles "
                           f"it has, so the first free gid for {TERRAIN_TILESET_NAME} is not "
                           f"known; fix it, or add {TERRAIN_TILESET_NAME} in Tiled (Map > "
                           "Add External Tileset)") from None


def repaint_map(text: str, folder: Path | None = None) -> str:
    """The text of a ``.tmx`` with its ground repainted (unchanged if it does not use the
    game's tilesets or keeps its tile data other than as CSV). A map without
    ``terrain.tsx`` gets it added at the first free gid; ``folder`` is where the map lives,
    to read its other tilesets' sizes (:class:`TerrainError` if one cannot be read)."""
    tilesets = list(TILESET_RE.finditer(text))

    def first_of(name: str) -> int | None:
        return next((int(m.group(1)) for m in tilesets
                     if (s := SOURCE_RE.search(m.group(2))) and s.group(1).endswith(name)),
                    None)

    tiles_first, terrain_first = first_of(TILESET_NAME), first_of(TERRAIN_TILESET_NAME)
    if terrain_first is None and tiles_first is None:
        return text
    adding = terrain_first is None
    if terrain_first is None:
        terrain_first = max(int(m.group(1)) + tile_count(m.group(0), folder) for m in tilesets)

    def layer(match: re.Match[str]) -> str:
        width = int(match.group(2))
        lines = [line.strip().rstrip(",") for line in match.group(4).strip().splitlines()]
        rows = [[int(value) for value in line.split(",")] for line in lines if line]
        if any(len(line) != width for line in rows):
            return match.group(0)
        painted = repaint_rows(rows, tiles_first, terrain_first)
        body = ",\n".join(",".join(str(gid) for gid in line) for line in painted)
        return f"{match.group(1)}\n{body}\n{match.group(5)}"

    painted = LAYER_RE.sub(layer, text)
    if not adding or painted == text:
        return painted
    last = tilesets[-1]
    end = last.end() if last.group(3) else painted.index("</tileset>", last.end()) + 11
    tiles_source = next(s.group(1) for m in tilesets if (s := SOURCE_RE.search(m.group(2)))
                        and s.group(1).endswith(TILESET_NAME))
    source = tiles_source[:-len(TILESET_NAME)] + TERRAIN_TILESET_NAME
    indent = painted[painted.rfind("\n", 0, last.start()) + 1:last.start()]
    return (f'{painted[:end]}\n{indent}<tileset firstgid="{terrain_first}" '
            f'source="{source}"/>{painted[end:]}')


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
        try:
            painted = repaint_map(text, path.parent)
        except TerrainError as error:
            print(f"{path}: {error}", file=sys.stderr)
            return 1
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
