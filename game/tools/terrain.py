"""Repaint the ground of Tiled maps with the terrain tileset, as Tiled's Terrain Brush would,
without changing what collides.

Run from the repository root::

    python -m game.tools.terrain levels/               # repaint every map in a folder
    python -m game.tools.terrain levels/01-first-steps.tmx
    python -m game.tools.terrain --check levels/       # say what would change; write nothing

Every cell of a tile layer that holds a ground tile (the grass, the dirt, the fieldstone
wall or the lone block of the game's ``tiles.tsx``, or any ground tile of its
``terrain.tsx``) gets the tile of ``terrain.tsx`` that fits its eight neighbours: grass and
an outline where it meets the air, sides, corners and inside corners. Every one-way plank
(of either tileset) gets the plank of ``terrain.tsx`` that fits its left and right
neighbours, ended with an outline where its row stops. A neighbour counts when it holds a
tile of the same kind in the same layer; past the map's left, right and bottom edges the
ground is taken to go on, so no outline is drawn along the edge of the world. Every ground
tile is Solid and every plank OneWay, so the set of solid, one-way and hazard cells is the
same before and after (``tests/test_terrain.py`` holds each shipped map to the grid it had).

Which of a map's tilesets are the game's is known by what they hold, not by their names: a
tileset is the game's ``tiles.tsx`` (or ``terrain.tsx``) when its tile size, tile count,
columns, image size and every tile's class and collision rectangles are those of the
game's own ``assets/tiles.tsx`` (``assets/terrain.tsx``), which :mod:`game.tools.art`
writes. A pack's own ``tiles.tsx``, whose tiles mean something else, is left alone.

A map with ground to repaint that has no terrain tileset yet gets the ``terrain.tsx``
beside its ``tiles.tsx`` added, after its last tileset, at the first free gid, as Tiled's
*Add External Tileset* would (no gid already in the map changes meaning), but only if that
file is there, inside the level's sandbox (:mod:`game.levels.paths`), and is the game's
terrain tileset with its image; else the map is left as it was, with a sentence. Only that
line and the CSV inside ``<data>`` are written, in the map's own text encoding.

What it promises, for each map it is given:
  * It repaints only maps inside the folder given (a map named alone: the folder it was
    named in). A map that is a symbolic link is refused, and one that leads out of the
    folder says so.
  * The map is loaded with the game's own loader (:func:`game.levels.loader.load_level`)
    before and after, the repainted text in memory: unless it loads and collides in every
    cell as it did, nothing is written. A map the game cannot load is left alone, with the
    loader's own sentence.
  * Every file is read through the one bounded open (:mod:`game.levels.reading`: a pipe is
    refused at once, nothing is waited for) and the map is written through the one atomic
    write (:func:`game.levels.outputs.replace_atomically`), so an error, a full disk or
    Ctrl-C leaves it as it was or wholly repainted, never in part.
  * One line per map on stdout says what changed (``--check``: what would change), and each
    problem is one sentence on stderr, ``PATH: what is wrong — how to fix``. Exit status 0
    when done (``--check``: nothing would change), 1 when a map is bad, refused or cannot
    be written (``--check``: or would change), 2 for bad usage, 130 for Ctrl-C.

Where it sits: a tool beside the game, for level designers; it changes maps only through
the loader's reading and the level tools' writing, and is pinned by ``tests/test_terrain.py``.

What it teaches: autotiling is a lookup. Eight neighbours make a byte; corners count only
when both edges beside them do (:func:`game.tools.art.blob_mask`), which leaves 47 looks;
a table turns each into a tile. Tiled's mixed Wang sets do the same as a designer paints.
And a tool that rewrites a user's file proves, before it writes, that it changed only what
it meant to.
"""

from __future__ import annotations

import argparse
import bisect
import contextlib
import os
import posixpath
import re
import signal
import sys
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from xml.sax.saxutils import quoteattr

from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.levels.errors import Findings, LevelError, escaped, excerpt
from game.levels.loader import load_level
from game.levels.outputs import DISK_FULL, Refused, replace_atomically
from game.levels.paths import Sandbox, real, sandbox_for
from game.levels.reading import ReadProblem, read_bounded, reason
from game.levels.shipped import ASSETS_DIR
from game.levels.tiledata import TileDataError, decode_csv
from game.levels.tiledxml import MAX_FILE_BYTES
from game.levels.tilesets import Tileset, Tilesets, read_tileset_file, read_tilesets
from game.sim.level import Level
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
TILESET_NAME = "tiles.tsx"  # the game's two tilesets, in its assets/ folder
TERRAIN_TILESET_NAME = "terrain.tsx"
NEIGHBOURS = {bit: offset for bit, offset in zip(WANG_ORDER, (
    (0, -1), (1, -1), (1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1)), strict=True)}
FLIP_BITS = 0xF0000000  # Tiled's flip flags in the high bits of a gid
MAX_MAPS = 1_000  # maps one run repaints at most; a folder with more is given in parts
MAX_FOLDER_ENTRIES = 100_000  # names looked at in the folders given, at most

NOT_MARKUP_RE = re.compile(r"<!--.*?-->|<!\[CDATA\[.*?\]\]>|<\?.*?\?>", re.S)  # left as is
TILESET_RE = re.compile(r"<tileset\b[^>]*?(/?)>")
LAYER_RE = re.compile(r"(<layer\b[^>]*>(?:(?!</layer>|<layer\b).)*?<data\b([^>]*)>)(.*?)"
                      r"(</data>)", re.S)
CSV_RE = re.compile(r"""\bencoding\s*=\s*["']csv["']""")
DECLARED_RE = re.compile(rb"""\A(?:\xef\xbb\xbf)?\s*<\?xml[^>]*?\bencoding\s*=\s*["']"""
                         rb"""([A-Za-z][A-Za-z0-9._-]{0,39})["']""")

EXIT_OK = 0
EXIT_BAD = 1  # a map is bad, refused or cannot be written; --check: or would change
EXIT_USAGE = 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for Ctrl-C
FIX_TERRAIN = ("put the game's terrain.tsx and terrain.png beside the map's tiles.tsx, or "
               "add the game's assets/terrain.tsx in Tiled (Map > Add External Tileset)")


class TerrainError(Exception):
    """A map the tool leaves as it was; the message is the whole line to print."""


class UsageError(Exception):
    """A command line that names no maps to repaint; the message is the line to print."""


class Changed(Refused):
    """The map on the disk is no longer the one that was read and repainted."""


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

    @cache  # a layer holds few different gids: each is looked at once
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

    kinds = [[kind(gid) for gid in line] for line in rows]

    def of(wanted: str, col: int, row: int) -> bool:
        return 0 <= row < height and 0 <= col < width and kinds[row][col] == wanted

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


def named(path: Path) -> str:
    """``path`` as a message shows it, with anything that could forge output escaped."""
    return escaped(os.fsdecode(path))


def sentence(path: Path, problem: str, fix: str) -> str:
    """One line in the level tools' form: ``PATH: what is wrong — how to fix``."""
    return f"{named(path)}: {problem} — {fix}"


def cells_text(count: int) -> str:
    """``1 cell``, ``12 cells``."""
    return f"{count:,} cell{'s' * (count != 1)}"


# -- The text: only the CSV of tile layers, and one tileset line, are rewritten -------------

def _outside_markup(text: str) -> list[tuple[int, int]]:
    """The spans of ``text`` that are comments, CDATA or processing instructions: what
    looks like a layer or a tileset there is not one, and is never rewritten."""
    return [match.span() for match in NOT_MARKUP_RE.finditer(text)]


def _in(spans: Sequence[tuple[int, int]], position: int) -> bool:
    """Is ``position`` inside one of ``spans`` (sorted, apart)?"""
    index = bisect.bisect_right(spans, (position, sys.maxsize)) - 1
    return index >= 0 and spans[index][0] <= position < spans[index][1]


def repaint_text(text: str, cols: int, rows: int, tiles_first: int | None,
                 terrain_first: int) -> tuple[str, int]:
    """The text of a map (``cols`` x ``rows`` cells) with each CSV tile layer's ground
    repainted (:func:`repaint_rows`), and how many cells got another tile. A layer in
    another format, or with nothing to change, is left exactly as it was written."""
    skipped = _outside_markup(text)
    changed = 0

    def layer(match: re.Match[str]) -> str:
        nonlocal changed
        attributes = match.group(2)
        if _in(skipped, match.start()) or not CSV_RE.search(attributes) or (
                "compression" in attributes):
            return match.group(0)
        try:
            gids = decode_csv(match.group(3), cols * rows)
        except TileDataError:
            return match.group(0)  # the loader read this map, so this is not its layer
        grid = [gids[row * cols:(row + 1) * cols] for row in range(rows)]
        painted = repaint_rows(grid, tiles_first, terrain_first)
        count = sum(old != new for before, after in zip(grid, painted, strict=True)
                    for old, new in zip(before, after, strict=True))
        if not count:
            return match.group(0)
        changed += count
        body = ",\n".join(",".join(str(gid) for gid in line) for line in painted)
        return f"{match.group(1)}\n{body}\n{match.group(4)}"

    return LAYER_RE.sub(layer, text), changed


def add_tileset(text: str, source: str, firstgid: int) -> str:
    """``text`` with an external tileset ``source`` added after its last tileset, starting
    at ``firstgid``, as Tiled's *Add External Tileset* writes it.

    >>> print(add_tileset('<map>\\n <tileset firstgid="1" source="a.tsx"/>\\n</map>', "b.tsx", 33))
    <map>
     <tileset firstgid="1" source="a.tsx"/>
     <tileset firstgid="33" source="b.tsx"/>
    </map>
    """
    skipped = _outside_markup(text)
    tilesets = [match for match in TILESET_RE.finditer(text) if not _in(skipped, match.start())]
    unlike_tiled = ValueError("the map's tilesets are not written as Tiled writes them")
    if not tilesets:
        raise unlike_tiled
    last = tilesets[-1]
    end = last.end()
    if not last.group(1):  # a tileset kept in the map: it ends at its closing tag
        closing = text.find("</tileset>", end)
        if closing < 0:
            raise unlike_tiled
        end = closing + len("</tileset>")
    indent = text[text.rfind("\n", 0, last.start()) + 1:last.start()]
    indent = indent if not indent.strip() else " "
    return (f'{text[:end]}\n{indent}<tileset firstgid="{firstgid}" '
            f"source={quoteattr(source)}/>{text[end:]}")


def text_encoding(data: bytes) -> str:
    """The text encoding the map's XML declaration names (UTF-8 if none): the map is
    written back in it, so a Latin-1 map stays Latin-1.

    >>> text_encoding(b'<?xml version="1.0" encoding="ISO-8859-1"?>\\n<map/>')
    'ISO-8859-1'
    >>> text_encoding(b"<map/>")
    'utf-8'
    """
    declared = DECLARED_RE.match(data)
    return declared.group(1).decode("ascii") if declared else "utf-8"


# -- Which tilesets are the game's: by what their tiles are, not by their names -------------

Meaning = tuple[object, ...]


def meaning(tileset: Tileset) -> Meaning:
    """What a tileset's tiles are to the game: everything but its name, its file and where
    its gids start (its tile size and count, columns, spacing, margin, image size, and each
    tile's class, collision rectangles and animation)."""
    return (tileset.tile_w, tileset.tile_h, tileset.tilecount, tileset.columns,
            tileset.spacing, tileset.margin, tileset.image_size,
            tuple(sorted(tileset.tiles.items(), key=lambda item: item[0])))


@cache
def game_tilesets() -> tuple[Meaning, Meaning]:
    """The meanings of the game's own ``assets/tiles.tsx`` and ``assets/terrain.tsx``."""
    sandbox = Sandbox((ASSETS_DIR,))
    tiles, terrain = (meaning(read_tileset_file(name, ASSETS_DIR, 1, sandbox,
                                                Findings(ASSETS_DIR / name), False,
                                                f"the game's {name}"))
                      for name in (TILESET_NAME, TERRAIN_TILESET_NAME))
    return tiles, terrain


def first_gid_of(tilesets: Tilesets, wanted: Meaning) -> int | None:
    """The first gid of the map's first tileset that means ``wanted``, if any."""
    return next((t.firstgid for t in tilesets.all if meaning(t) == wanted), None)


def _terrain_to_add(path: Path, root: ET.Element, tiles_first: int, firstgid: int) -> str:
    """The source of the ``terrain.tsx`` to add to the map: beside the map's ``tiles.tsx``,
    inside the level's sandbox, the game's terrain tileset, its image there too; else
    :class:`TerrainError`."""
    tiles = next((node for node in root.findall("tileset")
                  if node.get("firstgid") == str(tiles_first) and node.get("source")), None)
    if tiles is None:
        raise TerrainError(sentence(path, "its ground needs the terrain tileset, which the "
                                    "map does not have, and its tiles.tsx is kept inside "
                                    "the map, so there is no terrain.tsx beside it to add",
                                    FIX_TERRAIN))
    source = posixpath.join(posixpath.dirname(tiles.get("source", "")), TERRAIN_TILESET_NAME)
    try:
        terrain = read_tileset_file(source, path.parent, firstgid, sandbox_for(path),
                                    Findings(path), True, f"tileset {excerpt(source)}")
    except LevelError as error:
        raise TerrainError(sentence(path, f"its ground needs the terrain tileset, which the "
                                    f"map does not have, and {excerpt(source)} cannot be "
                                    f"added: {error.problem}", FIX_TERRAIN)) from None
    if meaning(terrain) != game_tilesets()[1]:
        raise TerrainError(sentence(path, f"its ground needs the terrain tileset, which the "
                                    f"map does not have, and {excerpt(source)} beside its "
                                    "tiles.tsx is not the game's terrain tileset (its tiles "
                                    "are not those of assets/terrain.tsx)", FIX_TERRAIN))
    return source


# -- One map: read, load, repaint, load again, compare ---------------------------------------

Identity = tuple[int, int, int, int]  # device, inode, time of change (ns), size


def identity_of(path: Path) -> Identity | None:
    """The file at ``path`` as it is now, to see whether it changes before it is written."""
    try:
        status = os.stat(path)
    except (OSError, ValueError):
        return None
    return (status.st_dev, status.st_ino, status.st_mtime_ns, status.st_size)


@dataclass(frozen=True)
class Painting:
    """One map, repainted in memory: what the tool would write, and what it would change."""

    path: Path
    data: bytes  # the map's new bytes (its old bytes when nothing changes)
    cells: int  # cells given another tile
    added: str | None = None  # the terrain tileset added, as the map names it
    firstgid: int = 0  # the first gid of the added tileset
    uses_game_tiles: bool = True  # does the map use either of the game's tilesets?
    identity: Identity | None = None  # the file as it was read

    def says(self, check: bool) -> str:
        """The line printed for this map: what changed, or what would."""
        if not self.cells:
            why = ("its ground is painted with the terrain tiles" if self.uses_game_tiles
                   else "it uses neither of the game's tilesets")
            return f"{named(self.path)}: unchanged: {why}"
        tileset = (f" and {'add' if check else 'added'} {self.added} at gid {self.firstgid}"
                   if self.added else "")
        if check:
            return sentence(self.path, f"would repaint {cells_text(self.cells)}{tileset}",
                            "run python -m game.tools.terrain on it")
        return f"{named(self.path)}: repainted {cells_text(self.cells)}{tileset}"


def _refuse_links(path: Path, folder: Path) -> None:
    """Refuse a map that is a symbolic link, or that leads out of ``folder``."""
    try:
        inside = real(path).is_relative_to(real(folder))
        link = path.is_symlink()
    except (OSError, ValueError):
        return  # a name the system refuses: reading it will say so
    if not inside:
        raise TerrainError(sentence(path, f"the map leads outside {named(folder)}, the folder "
                                    "it was given in, and only maps inside it are repainted",
                                    "copy the map itself into the folder instead of "
                                    "linking to it"))
    if link:
        raise TerrainError(sentence(path, "the map is a symbolic link, which is never "
                                    "replaced", "give the path of the map it leads to"))


def _load(path: Path, data: bytes, repainted: bool) -> Level:
    """The map as the game loads it, from ``data``; :class:`TerrainError` if it does not."""
    try:
        return load_level(path, data=data)
    except LevelError as error:
        if not repainted:
            raise TerrainError(str(error)) from None
        place = f"{error.where}: " if error.where else ""
        raise TerrainError(sentence(path, f"the repainted map would not load ({place}"
                                    f"{error.problem}), so it is left as it was",
                                    "paint its ground in Tiled with the Terrain Brush "
                                    "instead")) from None


Collision = dict[tuple[int, int], list[tuple[TileKind, Box]]]


def collision(level: Level) -> Collision:
    """Each cell's solid, one-way and hazard shapes, in the order the layers put them."""
    cells: Collision = {}
    for shape in level.grid.shapes():
        cells.setdefault((shape.col, shape.row), []).append((shape.kind, shape.box))
    return cells


def _same_collision(path: Path, before: Level, after: Level) -> None:
    """Refuse the repaint if any cell collides otherwise than it did."""
    if list(before.grid.shapes()) == list(after.grid.shapes()):
        return  # the usual case, quickly: the same shapes, cell by cell, in the same order
    old, new = collision(before), collision(after)
    changed = sorted((row, col) for col, row in old.keys() | new.keys()
                     if old.get((col, row)) != new.get((col, row)))
    if changed:
        row, col = changed[0]
        raise TerrainError(sentence(path, f"tile ({col},{row}): repainting would change what "
                                    f"collides there ({len(changed):,} cells in all), so the "
                                    "map is left as it was", "check that its tilesets give "
                                    "each tile the class the game's own give it"))


def paint(path: Path, folder: Path) -> Painting:
    """The map at ``path`` (given in ``folder``) repainted in memory, proven to load and to
    collide as before; :class:`TerrainError` says why not."""
    _refuse_links(path, folder)
    identity = identity_of(path)
    try:
        data = read_bounded(path, MAX_FILE_BYTES, "the map", updated=True,
                            too_big_fix="split the level into smaller maps")
    except ReadProblem as problem:
        raise TerrainError(sentence(path, problem.problem, problem.fix)) from None
    before = _load(path, data, repainted=False)
    encoding = text_encoding(data)
    try:
        text = data.decode(encoding)
    except (LookupError, UnicodeDecodeError):
        raise TerrainError(sentence(path, f"the map is not {excerpt(encoding)} text, as its "
                                    "first line says", "open it in Tiled and save it again"))\
            from None
    root = ET.fromstring(data)  # the loader has just read these very bytes
    try:
        tilesets = read_tilesets(root, path, sandbox_for(path), Findings(path), False)
    except LevelError as error:
        raise TerrainError(str(error)) from None
    tiles, terrain = game_tilesets()
    tiles_first, terrain_first = first_gid_of(tilesets, tiles), first_gid_of(tilesets, terrain)
    if tiles_first is None and terrain_first is None:
        return Painting(path, data, 0, uses_game_tiles=False, identity=identity)
    firstgid = terrain_first if terrain_first is not None else tilesets.next_firstgid
    painted, cells = repaint_text(text, before.grid.cols, before.grid.rows, tiles_first,
                                  firstgid)
    if not cells:
        return Painting(path, data, 0, identity=identity)
    added = None
    if terrain_first is None and tiles_first is not None:
        added = _terrain_to_add(path, root, tiles_first, firstgid)
        try:
            painted = add_tileset(painted, added, firstgid)
        except ValueError as error:
            raise TerrainError(sentence(path, f"{error}, so {excerpt(added)} cannot be added "
                                        "to them", FIX_TERRAIN)) from None
    new_data = painted.encode(encoding, errors="xmlcharrefreplace")
    _same_collision(path, before, _load(path, new_data, repainted=True))
    return Painting(path, new_data, cells, added, firstgid if added else 0, identity=identity)


def write(painting: Painting) -> None:
    """Put the repainted map in place of the old one, atomically; :class:`TerrainError` if
    it cannot be (the old map is then as it was)."""
    path = painting.path

    def put(tmp: Path) -> None:
        if identity_of(path) != painting.identity:
            raise Changed("it changed on the disk while it was being repainted")
        tmp.write_bytes(painting.data)

    try:
        replace_atomically(path, put)
    except (OSError, ValueError) as error:
        full = isinstance(error, OSError) and error.errno in DISK_FULL
        fix = ("free some space" if full else "run the tool again" if isinstance(
            error, Changed) else "run the tool again on this map alone" if isinstance(
            error, Refused) else "check that the folder may be written to")
        raise TerrainError(sentence(path, f"the repainted map cannot be written "
                                    f"({reason(error)}), so it is left as it was", fix)) \
            from None


# -- The command ----------------------------------------------------------------------------

def _maps_in(folder: Path) -> list[Path]:
    """The ``.tmx`` maps in ``folder`` and its subfolders, folder by folder in name order;
    hidden names and links to folders are passed over, and at most MAX_FOLDER_ENTRIES names
    are looked at (a loop of folders or a deep tree cannot keep the tool busy)."""
    found: list[Path] = []
    looked = 0
    waiting = [folder]  # folders still to look in, the next one last
    while waiting:
        top = waiting.pop()
        try:
            with os.scandir(top) as listing:
                entries = sorted(listing, key=lambda entry: entry.name)
        except OSError:
            continue  # a folder that may not be read holds no map we can repaint
        subfolders = []
        for entry in entries:
            looked += 1
            if looked > MAX_FOLDER_ENTRIES:
                raise UsageError(f"{named(folder)}: the folder holds more than "
                                 f"{MAX_FOLDER_ENTRIES:,} files and folders — give the "
                                 "folders that hold the maps")
            if entry.name.startswith("."):
                continue
            try:
                is_folder = entry.is_dir(follow_symlinks=False)
            except OSError:
                is_folder = False
            if is_folder:
                subfolders.append(top / entry.name)
            elif entry.name.endswith(".tmx"):
                found.append(top / entry.name)
        waiting += reversed(subfolders)
    return found


def maps_given(argument: Path) -> list[tuple[Path, Path]]:
    """The maps a command-line path stands for, each with the folder it was given in: a
    folder stands for the ``.tmx`` maps in it and in its subfolders; a file for itself,
    in the folder it was named in."""
    try:
        is_folder = argument.is_dir()
    except (OSError, ValueError):
        is_folder = False
    if not is_folder:
        return [(argument, argument.parent)]
    found = _maps_in(argument)
    if len(found) > MAX_MAPS:
        raise UsageError(f"{named(argument)}: the folder holds {len(found):,} maps, more "
                         f"than the {MAX_MAPS:,} repainted in one run — give its "
                         "subfolders one at a time")
    if not found:
        raise UsageError(f"{named(argument)}: the folder holds no .tmx maps — give a map "
                         "or a folder of maps")
    return [(map_path, argument) for map_path in found]


def _given_path(text: str) -> Path:
    """A path from the command line; an empty one, which would stand for the current
    folder and every map below it, names nothing."""
    if not text:
        raise argparse.ArgumentTypeError("an empty path names no map")
    return Path(text)


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python -m game.tools.terrain",
        description="Repaint the ground of Tiled maps with the game's terrain tiles, as "
                    "Tiled's Terrain Brush would, without changing what collides.")
    parser.add_argument("maps", nargs="+", type=_given_path, metavar="MAP_OR_FOLDER",
                        help="a .tmx map, or a folder: every .tmx map in it")
    parser.add_argument("--check", action="store_true",
                        help="write nothing; say what would change, and exit 1 if anything "
                             "would")
    return parser


def _main(argv: list[str] | None) -> int:
    args = _parser().parse_args(argv)
    try:
        given = [pair for argument in args.maps for pair in maps_given(argument)]
    except UsageError as error:
        print(error, file=sys.stderr)
        return EXIT_USAGE
    status, seen = EXIT_OK, set()
    for path, folder in given:
        key = real(path)
        if key in seen:
            continue
        seen.add(key)
        try:
            painting = paint(path, folder)
            if painting.cells and not args.check:
                write(painting)
        except (TerrainError, LevelError) as error:
            print(error, file=sys.stderr)
            status = EXIT_BAD
            continue
        print(painting.says(args.check))
        if painting.cells and args.check:
            status = EXIT_BAD
    return status


def main(argv: list[str] | None = None) -> int:
    """Repaint the maps named; Ctrl-C stops with exit status 130 and one line, each map as
    it was or wholly repainted (the one being written is replaced whole or not at all)."""
    try:
        if __name__ == "__main__":  # from here Ctrl-C is a KeyboardInterrupt, caught below
            signal.signal(signal.SIGINT, signal.default_int_handler)
        return _main(argv)
    except KeyboardInterrupt:
        print("stopped by Ctrl-C; each map is as it was or wholly repainted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:  # whoever read the lines stopped reading (| head): stop too
        with contextlib.suppress(OSError, ValueError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_BAD


if __name__ == "__main__":
    sys.exit(main())
