"""Load a Tiled ``.tmx`` map into a :class:`game.sim.level.Level`, or say clearly why not.

Where it sits: between Tiled's files and the game. :func:`load_level` is what the game
calls; :func:`check_level` is what ``python -m game.levels check`` calls, and also verifies
every image and lists every problem instead of stopping at the first.

What it teaches: the order of checks is the order of trust. First the file (is it XML, of
a sane size?), then the map header (orthogonal, finite, within limits), then the tilesets
and tile data it points to, then the objects, and only then pytmx, given a clean copy
(:mod:`game.levels.pytmx_bridge`). Each step reads one concept and lives in its own module:

==============================  ==============================================
:mod:`~game.levels.tiledxml`    open a Tiled XML file without trusting it
:mod:`~game.levels.header`      orientation, size and tile size
:mod:`~game.levels.paths`       which files a level may use
:mod:`~game.levels.tilesets`    GIDs, tile classes and collision rectangles
:mod:`~game.levels.layers`      layers in document order, through groups
:mod:`~game.levels.tiledata`    CSV and base64 tile data, and the GID flags
:mod:`~game.levels.solids`      tile layers into collision shapes
:mod:`~game.levels.templates`   object templates (``.tx``)
:mod:`~game.levels.objects`     objects as plain values
:mod:`~game.levels.entities`    objects into spawn, coins, enemies and exits
:mod:`~game.levels.classes`     the game's classes and their defaults
==============================  ==============================================

>>> from game.levels import FIRST_LEVEL
>>> level = load_level(FIRST_LEVEL)
>>> level.title, level.spawn, len(level.coins), [layer.name for layer in level.layers]
('First Steps', Box(x=34.0, y=114.0, w=12.0, h=14.0), 30, ['decor', 'ground'])
>>> check_level(FIRST_LEVEL).errors
[]
"""

from __future__ import annotations

import contextlib
import xml.etree.ElementTree as ET
from collections.abc import Mapping, Sequence
from pathlib import Path

from game.levels import pytmx_bridge
from game.levels.budget import MAX_ANIMATED_CELLS
from game.levels.classes import LEVEL, TILE_KINDS
from game.levels.entities import build_entities
from game.levels.errors import Findings, LevelError, excerpt, layer_place
from game.levels.header import MAX_TOTAL_CELLS, MapHeader, read_header
from game.levels.images import check_image
from game.levels.layers import LayerNode, walk_layers
from game.levels.objects import read_objects
from game.levels.paths import Sandbox, check_map_file, real, resolve, sandbox_for
from game.levels.properties import Value, read_properties
from game.levels.solids import build_grid
from game.levels.templates import Templates
from game.levels.tiledata import TileDataError, decode, split
from game.levels.tiledxml import is_json_name, read_tiled_xml
from game.levels.tilesets import Tilesets, read_tilesets
from game.sim.level import Level, TileLayer
from game.sim.tuning import Tuning

DecodedLayer = tuple[LayerNode, list[int]]
MAX_TITLE_CHARS = 60  # what fits on the screen in the level's banner, and then some
LEVEL_PROPERTY_NAMES = frozenset(member.name for member in LEVEL.members)


def _decode_layers(layers: Sequence[LayerNode], header: MapHeader,
                   findings: Findings) -> list[DecodedLayer]:
    tile_layers = [layer for layer in layers if layer.kind == "layer"]
    if len(tile_layers) * header.cells > MAX_TOTAL_CELLS:
        findings.fail("map", f"{len(tile_layers)} tile layers of {header.cols}x{header.rows} "
                      f"are more than the {MAX_TOTAL_CELLS:,} tiles the game reads",
                      "merge or delete tile layers, or make the map smaller")
    decoded: list[DecodedLayer] = []
    for layer in tile_layers:
        size = (layer.node.get("width", str(header.cols)),
                layer.node.get("height", str(header.rows)))
        if size != (str(header.cols), str(header.rows)):
            findings.fail(layer.place, f"the layer is {size[0]}x{size[1]} tiles but the map "
                          f"is {header.cols}x{header.rows}",
                          "undo the hand edit, or resize with Map > Resize Map")
        try:
            decoded.append((layer, decode(layer.node.find("data"), header.cells)))
        except TileDataError as error:
            findings.fail(layer.place, str(error), error.fix)
    return decoded


def _is_file(path: Path) -> bool:
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def _map_properties(root_properties: dict[str, Value], path: Path, sandbox: Sandbox,
                    findings: Findings) -> dict[str, Value]:
    """The map's properties, with the ones the game reads checked against their types, and
    ``next_level`` checked like every other file the level uses."""
    properties = dict(root_properties)
    for member in LEVEL.members:
        if member.name in properties:
            try:
                properties[member.name] = member.coerce(properties[member.name])
            except ValueError as error:
                findings.error(f"map property '{member.name}'", str(error),
                               f"set '{member.name}' ({member.doc}) in Map > Map Properties")
    title = str(properties.get("title", ""))
    if len(title) > MAX_TITLE_CHARS:
        findings.warn("map property 'title'", f"the title is {len(title):,} characters long; "
                      f"the game shows its first {MAX_TITLE_CHARS}",
                      "give the level a shorter title in Map > Map Properties")
        properties["title"] = title[:MAX_TITLE_CHARS]
    next_level = str(properties.get("next_level") or "")
    where = "map property 'next_level'"
    if not next_level:
        return properties
    target = resolve(next_level, path.parent, sandbox, findings, where, "next level")
    if target == real(path):
        findings.error(where, "the level names itself as the next level, so finishing it "
                       "would start it again", "pick the level that follows this one, or "
                       "clear next_level if this is the last")
    elif is_json_name(next_level):
        findings.warn(where, f"{excerpt(next_level)} is a JSON map",
                      "save the next map as .tmx and pick that one")
    elif not _is_file(target):
        findings.warn(where, f"{excerpt(next_level)} does not exist or is not a file",
                      "pick the next map again in Map > Map Properties")
    return properties


def _check_image_layers(layers: Sequence[LayerNode], path: Path, root: Sandbox,
                        findings: Findings, check_images: bool) -> None:
    for layer in layers:
        if layer.kind != "imagelayer":
            continue
        image = layer.node.find("image")
        if image is not None and image.get("source"):
            source = resolve(image.get("source", ""), path.parent, root, findings,
                             layer.place, "layer image")
            if check_images:
                check_image(source, findings, layer.place, "layer image")
        findings.warn(layer.place, "the game does not draw image layers",
                      "paint the picture as tiles on a tile layer, or delete the layer")


def _collides(gids: Sequence[int], tilesets: Tilesets) -> bool:
    """Does any tile of the layer have a class that collides (Solid, OneWay, Hazard)?"""
    for gid in set(gids):
        if gid:
            tile = tilesets.tile(split(gid)[0])
            if tile is not None and tile.cls in TILE_KINDS:
                return True
    return False


def _warn_moved_colliding_layers(decoded: Sequence[DecodedLayer], tilesets: Tilesets,
                                 findings: Findings) -> None:
    """A layer that collides is drawn where it collides: its offset and parallax are not
    used, since the collision grid cannot move with them."""
    for layer, gids in decoded:
        if not _collides(gids, tilesets):
            continue
        if layer.offset != (0.0, 0.0):
            findings.warn(layer.place, f"its offset ({layer.offset[0]:g}, {layer.offset[1]:g}) "
                          "would move the drawing but not the collision, so the game draws "
                          "this colliding layer without it",
                          "set the layer's Offset to 0, 0 and move the tiles instead")
        if layer.parallax != (1.0, 1.0):
            findings.warn(layer.place, f"its parallax factor ({layer.parallax[0]:g}, "
                          f"{layer.parallax[1]:g}) would move the drawing but not the "
                          "collision, so the game scrolls this colliding layer at 1, 1",
                          "set Parallax Factor to 1, 1, or move the decoration to a layer "
                          "with no Solid, OneWay or Hazard tiles")


def _warn_layer_properties(root: ET.Element, findings: Findings) -> None:
    """The game reads properties of the map and of objects only; on a layer or a group
    they do nothing, and a physics property there was surely meant for the map."""
    for node in root.iter():
        if node.tag not in ("layer", "objectgroup", "imagelayer", "group"):
            continue
        place = layer_place(node.get("name", ""))
        for name in read_properties(node, findings, place):
            if name in LEVEL_PROPERTY_NAMES:
                findings.warn(place, f"property '{name}' on a layer does nothing; the game "
                              "reads it only from the map",
                              f"move '{name}' to Map > Map Properties")
            else:
                findings.warn(place, f"property '{name}' on a layer means nothing to the game",
                              "delete it, or keep it as a note")


def _split_by_objects(layers: Sequence[LayerNode], drawn: Sequence[TileLayer]
                      ) -> tuple[list[TileLayer], list[TileLayer]]:
    """Visible tile layers drawn behind the sprites, and those above the first object layer
    with objects, drawn in front of them."""
    behind: list[TileLayer] = []
    in_front: list[TileLayer] = []
    objects_seen = False
    tile_layers = iter(drawn)
    for layer in layers:
        if layer.kind == "objectgroup" and layer.node.find("object") is not None:
            objects_seen = True
        if layer.kind == "layer":
            tiles = next(tile_layers)
            if layer.visible:
                (in_front if objects_seen else behind).append(tiles)
    return behind, in_front


def _check_animated_cells(layers: Sequence[TileLayer], animations: Mapping[int, object],
                          findings: Findings) -> None:
    """Fail if the drawn layers hold more animated cells than a frame can look at."""
    if not animations:
        return
    count = sum(gid in animations for layer in layers for row in layer.gids for gid in row)
    if count > MAX_ANIMATED_CELLS:
        findings.fail("map", f"its drawn layers hold {count:,} animated tiles, more than the "
                      f"{MAX_ANIMATED_CELLS:,} the game animates in one level",
                      "paint most of them with a still tile, or split the level")


def _read(path: Path, findings: Findings, images: bool, check_images: bool,
          tuning: Tuning, folder: Path | None, data: bytes | None = None) -> Level:
    """Every step of loading, in order of trust; raises LevelError at the end if any step
    recorded an error."""
    # 1. The file (if it lies in its own sandbox), and the grid its header describes.
    sandbox = sandbox_for(path, folder)
    check_map_file(path, sandbox, findings)
    root = read_tiled_xml(path, "map", findings, data=data)
    header = read_header(root, findings)

    # 2. Tilesets and tile layers: what collides where.
    tilesets = read_tilesets(root, path, sandbox, findings, check_images)
    layers = walk_layers(root, findings)
    decoded = _decode_layers(layers, header, findings)
    grid = build_grid(header, decoded, tilesets, findings)
    _check_image_layers(layers, path, sandbox, findings, check_images)
    _warn_moved_colliding_layers(decoded, tilesets, findings)
    _warn_layer_properties(root, findings)

    # 3. Objects and properties: the spawn, coins, enemies, exits and physics.
    templates = Templates(path, sandbox, tilesets, findings, check_images)
    objects = read_objects(layers, tilesets, templates, findings)
    properties = _map_properties(read_properties(root, findings, "map properties"), path,
                                 sandbox, findings)
    entities = build_entities(objects, header, grid, tuning, findings)
    findings.raise_errors()

    # 4. Only now pytmx, on a clean copy: tile ids for drawing, and the tile images.
    tmx = pytmx_bridge.parse(path, pytmx_bridge.clean_map(header, tilesets, decoded),
                             images, findings)
    colliding = [_collides(gids, tilesets) for _layer, gids in decoded]
    behind, in_front = _split_by_objects(layers, pytmx_bridge.drawn_layers(
        tmx, [layer for layer, _gids in decoded], colliding))
    animated = pytmx_bridge.animated_tiles(tmx, [*behind, *in_front])
    _check_animated_cells([*behind, *in_front], animated.animations, findings)
    next_level = properties.get("next_level")
    return Level(
        path=path, grid=grid, spawn=entities.spawn, coins=entities.coins,
        enemies=entities.enemies, exits=entities.exits, platforms=entities.platforms,
        checkpoints=entities.checkpoints,
        title=str(properties.get("title") or path.stem),
        next_level=path.parent / str(next_level) if next_level else None,
        properties=properties, layers=tuple(behind), foreground=tuple(in_front),
        tile_images=pytmx_bridge.tile_images(tmx, [*behind, *in_front], animated)
        if images else {},
        animations=animated.animations, background_color=header.background)


def load_level(path: Path | str, *, images: bool = False, tuning: Tuning | None = None,
               folder: Path | None = None, data: bytes | None = None) -> Level:
    """Read a map; raise :class:`LevelError` if the game cannot play it.

    ``images=True`` also loads and verifies the tile images (it needs a display mode set);
    without it no image file is opened, which is what headless runs want. ``tuning`` gives
    the defaults of the classes (an Enemy's speed, a point Player's hitbox). ``folder`` is
    where the map's files must be (default: see :mod:`game.levels.paths`). ``data`` is
    the map's text when it is not yet in the file at ``path`` (the terrain tool loads a
    repainted map before it writes it); the map's tilesets and templates are still read
    from beside ``path``.
    """
    path = Path(path)
    return _read(path, Findings(path), images, images, tuning or Tuning(), folder, data)


def check_level(path: Path | str, folder: Path | None = None) -> Findings:
    """Everything wrong with a map, as the checker prints it: images are verified too, and
    every error that does not stop the reading is listed. Never raises LevelError."""
    path = Path(path)
    findings = Findings(path)
    with contextlib.suppress(LevelError):  # its errors are in findings
        _read(path, findings, images=False, check_images=True, tuning=Tuning(), folder=folder)
    return findings


def files_read(path: Path | str, folder: Path | None = None) -> tuple[Path, ...]:
    """Every file reading the map at ``path`` opens, as the checker reads it (images
    included), in the order they were opened; as far as it got when the map is bad. This is
    what ``--watch`` watches: the loader's own list, through the loader's own rules."""
    path = Path(path)
    findings = Findings(path)
    with contextlib.suppress(LevelError):
        _read(path, findings, images=False, check_images=True, tuning=Tuning(), folder=folder)
    return (path, *(file for file in findings.files if file != path))
