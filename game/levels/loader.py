"""Load a Tiled ``.tmx`` map into a :class:`game.level.Level`, or say clearly why not.

Where it sits: between Tiled's files and the game. pytmx parses the tilesets, the tile data
(CSV or base64, plain, zlib or gzip) and the images; this module reads the rest straight
from the XML, because pytmx 3.32 loses two things the game needs: the document order of
layers (it regroups them by kind) and Tiled 1.9's ``class=`` attribute.

What it teaches:
  * Tile classes become collision shapes: ``Solid``, ``OneWay`` and ``Hazard`` (Tiled writes
    the class as ``type=``; Tiled 1.9 wrote ``class=``; both are read, in any case). A tile
    with rectangles drawn in Tiled's collision editor uses those rectangles instead of its
    whole cell.
  * Objects become entities by class: one ``Player`` (its rectangle is the hitbox; a point
    gets the default hitbox with its top-left corner at the point), ``Coin`` (``value``),
    ``Enemy`` (``speed``) and ``Exit`` (a rectangle).
  * Every failure becomes a :class:`LevelError` naming the file, the place and the fix.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pygame
import pytmx

from game.aabb import Box
from game.level import CoinSpec, EnemySpec, Level, TileLayer
from game.levels.errors import LevelError
from game.tilegrid import TileGrid, TileKind, TileShape
from game.tuning import Tuning

MAX_MAP_CELLS = 4_000_000     # a 2000x2000 map; larger is refused rather than left to hang
MAX_TILE_PX = 1024
PHYSICS_PROPERTIES = ("gravity", "max_fall_speed", "run_speed", "jump_speed")
DEFAULT_COIN_PX = 8


def class_of(attributes: Mapping[str, Any]) -> str:
    """The Tiled class of a tile or object, from ``type=`` or Tiled 1.9's ``class=``, lower case.

    >>> class_of({"class": "OneWay"}), class_of({"type": "SOLID"}), class_of({})
    ('oneway', 'solid', '')
    """
    value = attributes.get("type") or attributes.get("class") or ""
    return str(value).strip().lower()


TILE_KINDS = {kind.value.lower(): kind for kind in TileKind}


@dataclass(frozen=True)
class MapObject:
    """An object read from the XML, with its class and typed custom properties."""

    id: int
    name: str
    cls: str
    box: Box
    is_point: bool
    properties: dict[str, Any]

    @property
    def place(self) -> str:
        return f"object #{self.id} '{self.name}'"


def _number(text: str | None, default: float, path: Path, where: str, what: str) -> float:
    if text is None:
        return default
    try:
        value = float(text)
    except ValueError:
        raise LevelError(path, where, f"{what} is {text!r}, not a number",
                         "type a number in the Properties panel") from None
    if not math.isfinite(value):
        raise LevelError(path, where, f"{what} is {text}, not a finite number",
                         "type an ordinary number in the Properties panel")
    return value


def _properties(node: ET.Element, path: Path, where: str) -> dict[str, Any]:
    """Custom properties of a node, cast by their Tiled type."""
    values: dict[str, Any] = {}
    props = node.find("properties")
    if props is None:
        return values
    for prop in props.findall("property"):
        name = prop.get("name", "")
        kind = prop.get("type", "string")
        text = prop.get("value", prop.text or "")
        what = f"property '{name}'"
        if kind == "int":
            number = _number(text, 0, path, where, what)
            if number != int(number):
                raise LevelError(path, where, f"{what} is {text!r}, not a whole number",
                                 "type a whole number in the Properties panel")
            values[name] = int(number)
        elif kind == "float":
            values[name] = _number(text, 0.0, path, where, what)
        elif kind == "bool":
            values[name] = text == "true"
        elif kind in ("class", "list"):
            continue  # nested values: nothing the game reads
        else:
            values[name] = text
    return values


def _walk(node: ET.Element, path: Path, offset: tuple[float, float], opacity: float,
          visible: bool) -> Iterator[tuple[ET.Element, tuple[float, float], float, bool]]:
    """Layers in Tiled's document order, descending into groups (offsets and opacity add up)."""
    for child in node:
        if child.tag not in ("layer", "objectgroup", "imagelayer", "group"):
            continue
        where = f"layer '{child.get('name', '')}'"
        ox = offset[0] + _number(child.get("offsetx"), 0.0, path, where, "offsetx")
        oy = offset[1] + _number(child.get("offsety"), 0.0, path, where, "offsety")
        alpha = opacity * _number(child.get("opacity"), 1.0, path, where, "opacity")
        shown = visible and child.get("visible", "1") != "0"
        if child.tag == "group":
            yield from _walk(child, path, (ox, oy), alpha, shown)
        else:
            yield child, (ox, oy), alpha, shown


def _read_xml(path: Path) -> ET.Element:
    if not path.is_file():
        raise LevelError(path, "", "the file does not exist",
                         "check the path, or save the map from Tiled first")
    if path.suffix.lower() != ".tmx":
        raise LevelError(path, "", "this is not a Tiled map (.tmx) file",
                         "open the map in Tiled and use File > Save As… with the .tmx format")
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        line, column = error.position
        raise LevelError(path, f"line {line}, column {column}", "the XML is damaged",
                         "open the map in Tiled and save it again, or undo the hand edit"
                         ) from None
    except OSError as error:
        raise LevelError(path, "", f"the file cannot be read ({error.strerror})",
                         "check that the file exists and is readable") from None
    if root.tag != "map":
        raise LevelError(path, "", f"the file holds a <{root.tag}>, not a map",
                         "pass a .tmx map; tilesets (.tsx) are loaded through their map")
    return root


def _check_map_header(path: Path, root: ET.Element) -> None:
    orientation = root.get("orientation", "orthogonal")
    if orientation != "orthogonal":
        raise LevelError(path, "", f"{orientation} maps are not supported",
                         "make an Orthogonal map (Map > Map Properties > Orientation)")
    if root.get("infinite", "0") == "1":
        raise LevelError(path, "", "infinite maps are not supported",
                         "untick Map > Map Properties > Infinite to make the map finite")
    where = "map"
    cols = _number(root.get("width"), 0, path, where, "width")
    rows = _number(root.get("height"), 0, path, where, "height")
    tile_w = _number(root.get("tilewidth"), 0, path, where, "tilewidth")
    tile_h = _number(root.get("tileheight"), 0, path, where, "tileheight")
    if cols < 1 or rows < 1 or cols * rows > MAX_MAP_CELLS:
        raise LevelError(path, where, f"a {cols:g}x{rows:g} map is outside the playable size "
                         f"(1 to {MAX_MAP_CELLS:,} tiles)",
                         "resize it with Map > Resize Map")
    if not (1 <= tile_w <= MAX_TILE_PX and 1 <= tile_h <= MAX_TILE_PX):
        raise LevelError(path, where, f"a {tile_w:g}x{tile_h:g} tile size is not playable",
                         "set a tile size of 1 to 1024 pixels in Map > Map Properties")


def _parse_with_pytmx(path: Path, images: bool) -> Any:
    loader = pytmx.util_pygame.pygame_image_loader if images else pytmx.pytmx.default_image_loader
    try:
        return pytmx.TiledMap(str(path), image_loader=loader, allow_duplicate_names=True)
    except FileNotFoundError as error:
        raise LevelError(path, "", f"a file it uses is missing ({error.filename})",
                         "fix the path in Tiled (Map > Tileset, or the layer's image)") from None
    except pygame.error as error:
        raise LevelError(path, "", f"an image cannot be loaded ({error})",
                         "re-export the tileset image as PNG and point the tileset at it"
                         ) from None
    except Exception as error:  # pytmx raises bare Exceptions for many malformed files
        raise LevelError(path, "", f"Tiled data that cannot be read ({error or type(error)})",
                         "open the map in Tiled, fix what it reports, and save it again"
                         ) from None


def _collision_boxes(props: Mapping[str, Any], col: int, row: int,
                     tile_w: int, tile_h: int) -> list[Box]:
    """The tile's collision rectangles in map pixels, clipped to its cell."""
    cell = Box(col * tile_w, row * tile_h, tile_w, tile_h)
    colliders = props.get("colliders")
    if not colliders:
        return [cell]
    boxes: list[Box] = []
    for shape in colliders:
        if getattr(shape, "points", None) is not None or getattr(shape, "ellipse", None):
            continue
        left = max(cell.left, cell.left + float(shape.x))
        top = max(cell.top, cell.top + float(shape.y))
        right = min(cell.right, cell.left + float(shape.x) + float(shape.width))
        bottom = min(cell.bottom, cell.top + float(shape.y) + float(shape.height))
        if right > left and bottom > top:
            boxes.append(Box(left, top, right - left, bottom - top))
    return boxes or [cell]


def _read_object(node: ET.Element, path: Path) -> MapObject:
    object_id = int(_number(node.get("id"), 0, path, "object", "id"))
    name = node.get("name", "")
    where = f"object #{object_id} '{name}'"
    if node.get("template"):
        raise LevelError(path, where, "uses a template, which the game does not read",
                         "export with File > Export As… and tick 'Detach templates', "
                         "or detach it (right-click > Detach)")
    x = _number(node.get("x"), 0.0, path, where, "x")
    y = _number(node.get("y"), 0.0, path, where, "y")
    w = _number(node.get("width"), 0.0, path, where, "width")
    h = _number(node.get("height"), 0.0, path, where, "height")
    if node.get("gid"):
        y -= h  # tile objects are anchored at their bottom-left corner
    is_point = node.find("point") is not None or (w == 0 and h == 0)
    return MapObject(object_id, name, class_of(node.attrib), Box(x, y, w, h), is_point,
                     _properties(node, path, where))


def load_level(path: Path | str, *, images: bool = False, tuning: Tuning | None = None) -> Level:
    """Read a map. ``images=True`` also loads tile images (needs a display mode set)."""
    path = Path(path)
    tuning = tuning or Tuning()
    root = _read_xml(path)
    _check_map_header(path, root)
    tmx = _parse_with_pytmx(path, images)
    tile_w, tile_h = int(tmx.tilewidth), int(tmx.tileheight)
    grid = TileGrid(int(tmx.width), int(tmx.height), tile_w, tile_h)

    pytmx_layers = iter(layer for layer in tmx.layers
                        if isinstance(layer, pytmx.TiledTileLayer))
    background: list[TileLayer] = []
    foreground: list[TileLayer] = []
    objects: list[MapObject] = []
    used_gids: set[int] = set()
    for node, offset, opacity, visible in _walk(root, path, (0.0, 0.0), 1.0, True):
        if node.tag == "objectgroup":
            objects.extend(_read_object(o, path) for o in node.findall("object"))
        if node.tag != "layer":
            continue
        layer = next(pytmx_layers)
        rows: list[tuple[int, ...]] = []
        for row_index, row in enumerate(layer.data):
            rows.append(tuple(row))
            for col_index, gid in enumerate(row):
                if not gid:
                    continue
                used_gids.add(gid)
                props = tmx.get_tile_properties_by_gid(gid) or {}
                kind = TILE_KINDS.get(class_of(props))
                if kind is None:
                    continue
                for box in _collision_boxes(props, col_index, row_index, tile_w, tile_h):
                    grid.put(col_index, row_index, TileShape(box, kind, col_index, row_index))
        if visible:
            drawn = TileLayer(node.get("name", ""), tuple(rows), opacity, offset)
            (foreground if objects else background).append(drawn)

    level_properties = _properties(root, path, "map properties")
    for key in PHYSICS_PROPERTIES:
        value = level_properties.get(key)
        if value is not None and not isinstance(value, (int, float)):
            level_properties[key] = _number(str(value), 0.0, path, "map properties",
                                            f"property '{key}'")
    next_level = level_properties.get("next_level")
    tile_images: dict[int, pygame.Surface] = {}
    if images:
        for gid in used_gids:
            image = tmx.get_tile_image_by_gid(gid)
            if image is not None:
                tile_images[gid] = image
    return Level(
        path=path,
        grid=grid,
        spawn=_spawn(objects, path, tuning),
        coins=tuple(_coins(objects, path)),
        enemies=tuple(_enemies(objects, tuning)),
        exits=tuple(_exits(objects, path)),
        title=str(level_properties.get("title") or path.stem),
        next_level=(path.parent / str(next_level)) if next_level else None,
        properties=level_properties,
        layers=tuple(background),
        foreground=tuple(foreground),
        tile_images=tile_images,
        background_color=root.get("backgroundcolor"),
    )


def _spawn(objects: list[MapObject], path: Path, tuning: Tuning) -> Box:
    players = [o for o in objects if o.cls == "player"]
    if not players:
        raise LevelError(path, "", "this map has no Player object",
                         "add a point or rectangle with Class 'Player' on an object layer")
    if len(players) > 1:
        extra = players[1]
        raise LevelError(path, extra.place, f"{len(players)} Player objects",
                         "keep exactly one object with Class 'Player'")
    spawn = players[0]
    if spawn.is_point:
        return Box(spawn.box.x, spawn.box.y, tuning.player_width_px, tuning.player_height_px)
    if spawn.box.w <= 0 or spawn.box.h <= 0:
        raise LevelError(path, spawn.place, "the Player rectangle has no area",
                         "draw the Player as a point or as a rectangle with a size")
    return spawn.box


def _coins(objects: list[MapObject], path: Path) -> Iterator[CoinSpec]:
    for o in objects:
        if o.cls != "coin":
            continue
        value = o.properties.get("value", 1)
        if not isinstance(value, int) or isinstance(value, bool):
            raise LevelError(path, o.place, f"the coin's value {value!r} is not a whole number",
                             "set the 'value' property to an int")
        box = o.box if not o.is_point and o.box.w > 0 and o.box.h > 0 else Box(
            o.box.x, o.box.y, DEFAULT_COIN_PX, DEFAULT_COIN_PX)
        yield CoinSpec(box, value)


def _enemies(objects: list[MapObject], tuning: Tuning) -> Iterator[EnemySpec]:
    for o in objects:
        if o.cls != "enemy":
            continue
        speed = o.properties.get("speed")
        box = o.box if not o.is_point and o.box.w > 0 and o.box.h > 0 else Box(
            o.box.x, o.box.y, tuning.enemy_width_px, tuning.enemy_height_px)
        yield EnemySpec(box, float(speed) if isinstance(speed, (int, float)) else None)


def _exits(objects: list[MapObject], path: Path) -> Iterator[Box]:
    for o in objects:
        if o.cls != "exit":
            continue
        if o.is_point or o.box.w <= 0 or o.box.h <= 0:
            raise LevelError(path, o.place, "an Exit must be a rectangle",
                             "draw the Exit with the Rectangle tool")
        yield o.box
