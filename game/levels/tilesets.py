"""Tilesets: which global tile id (GID) is which tile, what class it has, how it collides.

Where it sits: read right after the map header, embedded in the map or from a ``.tsx``
file; the collision grid, tile objects and pytmx's image loading all look tiles up here.

What it teaches:
  * A map numbers the tiles of all its tilesets in one sequence: a tileset owns the GIDs
    from its ``firstgid`` for as many tiles as it has. Two tilesets whose ranges overlap
    make some GIDs ambiguous, so that is refused.
  * A tile's Class (``Solid``, ``OneWay``, ``Hazard``) and its collision rectangles
    (drawn in Tiled's tile collision editor, stored as an ``<objectgroup>`` in the tile)
    are what the physics uses; everything else about a tile is drawing.
  * Paths inside a ``.tsx`` are relative to the ``.tsx``, not to the map.

>>> tiles = Tileset("tiles", "tileset 'tiles'", firstgid=1, span=32, tile_w=16, tile_h=16)
>>> props = Tileset("props", "tileset 'props'", firstgid=33, span=8, tile_w=16, tile_h=16)
>>> tilesets = Tilesets([props, tiles])
>>> [tilesets.find(gid).name for gid in (1, 32, 33)], tilesets.find(41)
(['tiles', 'tiles', 'props'], None)
"""

from __future__ import annotations

import bisect
import itertools
import xml.etree.ElementTree as ET
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path

from game.collision.aabb import Box
from game.levels.attributes import number, whole
from game.levels.budget import FIX_SHAPES, MAX_SHAPES_PER_TILE, MAX_TILES_CUT
from game.levels.classes import CLASSES, CLASSES_BY_NAME
from game.levels.errors import Findings, excerpt
from game.levels.header import MAX_TILE_PX
from game.levels.images import MAX_IMAGE_PX, charge_pixels, check_image
from game.levels.paths import Sandbox, resolve
from game.levels.properties import class_name, class_of
from game.levels.spelling import meant
from game.levels.tiledata import ROTATED_120
from game.levels.tiledxml import read_tiled_xml, refuse_json

SHAPE_TAGS = ("ellipse", "point", "polygon", "polyline", "text", "capsule")
MAX_FIRSTGID = ROTATED_120 - 1  # GIDs share their 32 bits with the flip flags
MAX_TILES = 1 << 18  # in one tileset: a 8192x8192 image of 16x16 tiles
MAX_MAP_TILES = 1 << 19  # in all the tilesets of one map together
MAX_TILESETS = 1_000  # real maps use a handful; thousands would only slow loading down

MAX_ANIMATION_FRAMES = 1_000
MAX_FRAME_MS = 3_600_000  # an hour: a longer frame is a typo
TILE_CLASSES = tuple(cls.name for cls in CLASSES if cls.use_as == "tile")


@dataclass(frozen=True)
class TileInfo:
    """What the game needs of one tile: its class, its collision boxes, its own image."""

    cls: str = ""
    boxes: tuple[Box, ...] = ()  # in the tile's pixels; empty: the whole cell
    image: Path | None = None  # image-collection tilesets: the tile's own picture
    image_size: tuple[int, int] = (0, 0)
    animation: tuple[tuple[int, int], ...] = ()  # (tile id, duration in ms) per frame


@dataclass(frozen=True)
class Tileset:
    """One tileset of a map, with the GID range it owns."""

    name: str
    place: str  # how messages name it: "tileset 'tiles' (../assets/tiles.tsx)"
    firstgid: int
    span: int  # GIDs owned: firstgid .. firstgid + span - 1
    tile_w: int
    tile_h: int
    columns: int = 0
    tilecount: int = 0
    spacing: int = 0
    margin: int = 0
    image: Path | None = None
    image_size: tuple[int, int] = (0, 0)
    trans: str | None = None
    tiles: Mapping[int, TileInfo] = field(default_factory=dict)
    source: Path | None = None  # the .tsx file; None when embedded in the map

    @property
    def last_gid(self) -> int:
        return self.firstgid + self.span - 1

    @property
    def cut(self) -> int:
        """The places of its image that are cut into tiles when the map is read."""
        if self.image is None:
            return 0
        return _cut(self.image_size, self.tile_w, self.tile_h, self.spacing)


class Tilesets:
    """A map's tilesets, by GID."""

    def __init__(self, tilesets: Iterable[Tileset]) -> None:
        self.all = tuple(sorted(tilesets, key=lambda t: t.firstgid))

    def add(self, tileset: Tileset) -> None:
        """Add a tileset the map's objects need but the map does not list (a template's)."""
        self.all = tuple(sorted((*self.all, tileset), key=lambda t: t.firstgid))

    @property
    def next_firstgid(self) -> int:
        """The first GID after every tileset's range."""
        return max((t.last_gid + 1 for t in self.all), default=1)

    def find(self, gid: int) -> Tileset | None:
        """The tileset that owns ``gid`` (flags removed), or None."""
        index = bisect.bisect_right([t.firstgid for t in self.all], gid) - 1
        if index < 0 or gid > self.all[index].last_gid:
            return None
        return self.all[index]

    def tile(self, gid: int) -> TileInfo | None:
        """The tile ``gid`` names (an empty TileInfo if it has nothing special), or None."""
        tileset = self.find(gid)
        if tileset is None:
            return None
        return tileset.tiles.get(gid - tileset.firstgid, TileInfo())

    def by_source(self, path: Path) -> Tileset | None:
        """The map's tileset loaded from the ``.tsx`` at ``path``, if it has one."""
        return next((t for t in self.all if t.source == path), None)


def _collision_boxes(tile: ET.Element, findings: Findings, where: str) -> tuple[Box, ...]:
    boxes: list[Box] = []
    for shape in tile.findall("objectgroup/object"):
        if any(shape.find(tag) is not None for tag in SHAPE_TAGS) or (
                number(shape.attrib, "rotation", findings, where, 0.0) != 0.0):
            findings.warn(where, "only unrotated rectangles count as collision shapes; "
                          "its other shapes are ignored",
                          "redraw them with the Rectangle tool in the tile collision editor")
            continue
        x, y = (number(shape.attrib, a, findings, where, 0.0) for a in ("x", "y"))
        w, h = (number(shape.attrib, a, findings, where, 0.0) for a in ("width", "height"))
        if w > 0 and h > 0:
            boxes.append(Box(x, y, w, h))
            if len(boxes) > MAX_SHAPES_PER_TILE:
                findings.fail(where, f"the tile has more than {MAX_SHAPES_PER_TILE} collision "
                              "rectangles, the most the game reads for one tile", FIX_SHAPES)
    return tuple(boxes)


def _tile_info(tile: ET.Element, base: Path, root: Sandbox, findings: Findings, where: str,
               check_images: bool) -> TileInfo:
    image, size = None, (0, 0)
    image_node = tile.find("image")
    if image_node is not None:
        image = resolve(image_node.get("source", ""), base, root, findings, where, "tile image")
        size = (whole(image_node.attrib, "width", findings, where, 0, high=MAX_IMAGE_PX),
                whole(image_node.attrib, "height", findings, where, 0, high=MAX_IMAGE_PX))
        if check_images:
            size = check_image(image, findings, where, "tile image")
    return TileInfo(class_of(tile.attrib), _collision_boxes(tile, findings, where), image, size,
                    _animation(tile, findings, where))


def _animation(tile: ET.Element, findings: Findings, where: str) -> tuple[tuple[int, int], ...]:
    """The frames of a tile's animation (Tiled's Tile Animation Editor), checked."""
    node = tile.find("animation")
    if node is None:
        return ()
    frames = node.findall("frame")[:MAX_ANIMATION_FRAMES]
    return tuple((whole(frame.attrib, "tileid", findings, where, high=MAX_TILES - 1),
                  whole(frame.attrib, "duration", findings, where, low=1,
                        high=MAX_FRAME_MS)) for frame in frames)


def _image(node: ET.Element, base: Path, root: Sandbox, findings: Findings, where: str,
           check_images: bool) -> tuple[Path | None, tuple[int, int], str | None]:
    """The tileset's image, its size (read from the file if Tiled did not write it) and its
    transparent colour."""
    image_node = node.find("image")
    if image_node is None:
        return None, (0, 0), None
    image = resolve(image_node.get("source", ""), base, root, findings, where, "tileset image")
    declared = (whole(image_node.attrib, "width", findings, where, 0, high=MAX_IMAGE_PX),
                whole(image_node.attrib, "height", findings, where, 0, high=MAX_IMAGE_PX))
    size = declared
    size_unknown = 0 in declared and "tilecount" not in node.attrib  # Tiled before 0.13
    if check_images or size_unknown:
        size = check_image(image, findings, where, "tileset image")
        if 0 not in declared and (size[0] < declared[0] or size[1] < declared[1]):
            findings.fail(where, f"the image {image.name} is {size[0]}x{size[1]} but the "
                          f"tileset says {declared[0]}x{declared[1]}",
                          "pick the image again in Tiled's Tileset Properties")
    trans = image_node.get("trans")
    if trans is not None and not (len(trans) == 6 and all(
            c in "0123456789abcdefABCDEF" for c in trans)):
        findings.warn(where, f"the transparent colour {trans!r} is not RRGGBB; it is ignored",
                      "pick the colour again in the Tileset Properties")
        trans = None
    return image, size, trans


def _cut(image_size: tuple[int, int], tile_w: int, tile_h: int, spacing: int) -> int:
    """The places pytmx visits when it cuts an image into tiles (once per mention)."""
    return ((image_size[0] + spacing) // (tile_w + spacing)) * (
        (image_size[1] + spacing) // (tile_h + spacing))


def _grid(node: ET.Element, tile_w: int, tile_h: int, image_size: tuple[int, int],
          findings: Findings, where: str) -> tuple[int, int, int, int]:
    """Spacing, margin, columns and tile count, derived from the image where Tiled left them
    out."""
    spacing = whole(node.attrib, "spacing", findings, where, 0, high=MAX_TILE_PX)
    margin = whole(node.attrib, "margin", findings, where, 0, high=MAX_TILE_PX)
    fit_x = max(0, (image_size[0] - 2 * margin + spacing) // (tile_w + spacing))
    fit_y = max(0, (image_size[1] - 2 * margin + spacing) // (tile_h + spacing))
    cut = _cut(image_size, tile_w, tile_h, spacing)
    if cut > MAX_TILES:
        findings.fail(where, f"its {image_size[0]}x{image_size[1]} image cuts into {cut:,} "
                      f"tiles of {tile_w}x{tile_h}, more than the {MAX_TILES:,} the game reads",
                      "use larger tiles or a smaller image in the Tileset Properties")
    columns = whole(node.attrib, "columns", findings, where, fit_x, high=MAX_TILES)
    tilecount = whole(node.attrib, "tilecount", findings, where, fit_x * fit_y, high=MAX_TILES)
    return spacing, margin, columns, tilecount


def _tileset(node: ET.Element, firstgid: int, base: Path, path: Path | None, where: str,
             root: Sandbox, findings: Findings, check_images: bool) -> Tileset:
    """Read a ``<tileset>`` element; ``base`` is the folder its paths are relative to."""
    tile_w = whole(node.attrib, "tilewidth", findings, where)
    tile_h = whole(node.attrib, "tileheight", findings, where)
    if not (1 <= tile_w <= MAX_TILE_PX and 1 <= tile_h <= MAX_TILE_PX):
        findings.fail(where, f"a {tile_w}x{tile_h} tile size is not usable",
                      f"set a tile size of 1 to {MAX_TILE_PX} pixels in the Tileset Properties")
    image, image_size, trans = _image(node, base, root, findings, where, check_images)
    spacing, margin, columns, tilecount = _grid(node, tile_w, tile_h, image_size, findings,
                                                where)
    tiles: dict[int, TileInfo] = {}
    unknown: dict[str, list[int]] = {}  # class as written: the tiles that have it
    for tile in node.findall("tile"):
        tile_id = whole(tile.attrib, "id", findings, where, high=MAX_TILES - 1)
        info = _tile_info(tile, base, root, findings, f"{where} tile {tile_id}", check_images)
        if info != TileInfo():
            tiles[tile_id] = info
        written = class_name(tile.attrib)
        if info.cls and info.cls not in CLASSES_BY_NAME:
            slip = meant(written, TILE_CLASSES)
            if slip is not None:
                findings.error(f"{where} tile {tile_id}", f"class '{written}' is not a class "
                               f"the game knows; it looks like '{slip}' misspelt, and as it "
                               "is these tiles collide with nothing",
                               f"set the tile's Class to {slip} in the tileset editor")
            else:
                unknown.setdefault(written, []).append(tile_id)
    for written, ids in unknown.items():
        numbers = ", ".join(map(str, ids[:5])) + (", ..." if len(ids) > 5 else "")
        findings.warn(f"{where} tile{'s' * (len(ids) > 1)} {numbers}",
                      f"class '{written}' means nothing to the game, so "
                      f"{'these tiles do' if len(ids) > 1 else 'the tile does'} not collide",
                      "use Solid, OneWay or Hazard, or clear the class")
    span = max(tilecount, max(tiles, default=-1) + 1)
    for tile_id, info in tiles.items():
        missing = [frame for frame, _ in info.animation if frame >= span]
        if missing:
            findings.error(f"{where} tile {tile_id}", f"its animation shows tile {missing[0]}, "
                           f"which the tileset does not have (it has {span})",
                           "pick the frames again in Tiled's Tile Animation Editor")
    return Tileset(node.get("name", ""), where, firstgid, span, tile_w, tile_h, columns,
                   tilecount, spacing, margin, image, image_size, trans, tiles, path)


def read_tileset_file(source: str, relative_to: Path, firstgid: int, root: Sandbox,
                      findings: Findings, check_images: bool, where: str,
                      cache: dict[Path, Tileset] | None = None) -> Tileset:
    """Read the ``.tsx`` file that ``source`` names, as a tileset starting at ``firstgid``.

    With a ``cache``, a file is read once however often the map names it: a later mention
    is the same tileset renumbered (its images still count against the level's pixels,
    since each mention is drawn from its own copy)."""
    refuse_json(findings, where, "tileset", source)
    path = resolve(source, relative_to, root, findings, where, "tileset file")
    cached = cache.get(path) if cache is not None else None
    if cached is not None:
        if check_images:
            for image, (width, height) in _images_of(cached):
                charge_pixels(findings, cached.place, image, width, height)
        return replace(cached, firstgid=firstgid)
    node = read_tiled_xml(path, "tileset", findings, where)
    tileset = _tileset(node, firstgid, path.parent, path, f"tileset "
                       f"{excerpt(node.get('name', ''))} ({excerpt(source)})", root, findings,
                       check_images)
    if cache is not None:
        cache[path] = tileset
    return tileset


def _images_of(tileset: Tileset) -> list[tuple[Path, tuple[int, int]]]:
    """Every image a tileset draws from, with its size."""
    images = [(tile.image, tile.image_size) for tile in tileset.tiles.values()
              if tile.image is not None]
    if tileset.image is not None:
        images.append((tileset.image, tileset.image_size))
    return images


def _read_tileset(element: ET.Element, map_dir: Path, root: Sandbox, findings: Findings,
                  check_images: bool, cache: dict[Path, Tileset]) -> Tileset:
    """A map's ``<tileset>``: embedded, or naming a ``.tsx`` file."""
    source = element.get("source")
    where = f"tileset {excerpt(source)}" if source is not None else \
        f"tileset {excerpt(element.get('name', ''))}"
    firstgid = whole(element.attrib, "firstgid", findings, where, low=1, high=MAX_FIRSTGID)
    if source is not None:
        return read_tileset_file(source, map_dir, firstgid, root, findings, check_images,
                                 where, cache)
    return _tileset(element, firstgid, map_dir, None, where, root, findings, check_images)


def read_tilesets(map_root: ET.Element, map_path: Path, root: Sandbox, findings: Findings,
                  check_images: bool) -> Tilesets:
    """Every tileset of the map, checked, with non-overlapping GID ranges."""
    elements = map_root.findall("tileset")
    if len(elements) > MAX_TILESETS:
        findings.fail("map", f"it uses {len(elements):,} tilesets, more than the "
                      f"{MAX_TILESETS:,} the game reads",
                      "merge tilesets, and remove unused ones with Map > Remove Tileset")
    cache: dict[Path, Tileset] = {}
    tilesets = Tilesets(_read_tileset(element, map_path.parent, root, findings, check_images,
                                      cache) for element in elements)
    cut = sum(tileset.cut for tileset in tilesets.all)
    if cut > MAX_TILES_CUT:
        findings.fail("map", f"its tilesets cut {cut:,} tiles out of their images, each "
                      f"time a tileset is named; the game cuts at most {MAX_TILES_CUT:,} "
                      "for one map", "name each tileset once, and use larger tiles or "
                      "smaller images in the Tileset Properties")
    total = sum(tileset.span for tileset in tilesets.all)
    if total > MAX_MAP_TILES:
        findings.fail("map", f"its tilesets hold {total:,} tiles, more than the "
                      f"{MAX_MAP_TILES:,} the game reads for one map",
                      "remove unused tilesets with Map > Remove Tileset, or merge them")
    for before, after in itertools.pairwise(tilesets.all):
        if after.firstgid <= before.last_gid:
            findings.fail(after.place, f"its tile ids start at {after.firstgid}, inside the "
                          f"range {before.firstgid}-{before.last_gid} of {before.place}",
                          "open the map in Tiled and save it again; Tiled renumbers tilesets")
    return tilesets
