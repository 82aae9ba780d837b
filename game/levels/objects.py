"""Objects on object layers, as plain values: id, name, class, box, shape and properties.

Where it sits: between the XML and :mod:`game.levels.entities`, which decides what each
object is in the game. Templates are resolved first (:mod:`game.levels.templates`).

What it teaches:
  * Tiled's object coordinates are the top-left corner, except for tile objects (objects
    with a ``gid``), which are anchored at their bottom-left, like a tile standing on the
    ground. Both become a top-left :class:`~game.collision.aabb.Box` here, moved by the layer's
    offset so the object is where the designer sees it.
  * A tile object without a class of its own takes its tile's class, as in Tiled.
  * Every number is checked: ``x="nan"`` would make a Rect at -2147483648.

>>> MapObject(1, "hero", "player", Box(32, 48, 0, 0), "rectangle").is_point  # a 0x0 rectangle
True
>>> MapObject(7, "gem", "coin", Box(32, 48, 8, 8), "ellipse").place
"object #7 'gem'"
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

from game.collision.aabb import Box
from game.levels.attributes import number, parse_number, whole
from game.levels.errors import Findings, Place, excerpt, object_place, within
from game.levels.layers import LayerNode
from game.levels.properties import Value, class_name, class_of, read_properties
from game.levels.templates import Templates
from game.levels.tiledata import split
from game.levels.tilesets import Tilesets

SHAPES = ("point", "ellipse", "polygon", "polyline", "text", "capsule")
FIX_PLACE = "move or resize the object in Tiled, or type ordinary numbers in its Properties"
MAX_COORDINATE_PX = 1e9  # pygame Rects hold 32-bit integers
MAX_OBJECTS = 20_000
MAX_POINTS = 1_000  # on one polyline or polygon


@dataclass(frozen=True)
class MapObject:
    """One object, read and checked, in map pixels."""

    id: int
    name: str
    cls: str  # lower case, for lookups; "" for none
    box: Box
    shape: str  # "rectangle", "tile", or one of SHAPES
    rotation: float = 0.0
    properties: dict[str, Value] = field(default_factory=dict)
    class_name: str = ""  # as the designer typed it, for messages
    points: tuple[tuple[float, float], ...] = ()  # a polyline's or polygon's, in map pixels

    @property
    def place(self) -> Place:
        return object_place(self.id, self.name)

    @property
    def is_point(self) -> bool:
        return self.shape == "point" or (self.shape == "rectangle" and self.box.w == 0
                                         and self.box.h == 0)


def _shape(node: ET.Element) -> str:
    if node.get("gid"):
        return "tile"
    return next((tag for tag in SHAPES if node.find(tag) is not None), "rectangle")


def read_object(node: ET.Element, layer: LayerNode, tilesets: Tilesets,
                templates: Templates, findings: Findings) -> MapObject:
    """Read one ``<object>`` of ``layer``."""
    object_id = whole(node.attrib, "id", findings, within(layer.place,
                                                          f"an object on {layer.place}"), 0)
    where = object_place(object_id, node.get("name", ""))
    node = templates.apply(node, where)
    x, y, w, h, rotation = (number(node.attrib, name, findings, where, 0.0)
                            for name in ("x", "y", "width", "height", "rotation"))
    x, y = x + layer.offset[0], y + layer.offset[1]
    if w < 0 or h < 0 or max(abs(x), abs(y), w, h) > MAX_COORDINATE_PX:
        findings.fail(where, f"its place or size ({x:g}, {y:g}, {w:g}x{h:g}) is out of range",
                      FIX_PLACE)
    cls = class_of(node.attrib)
    written = class_name(node.attrib)
    if node.get("gid"):
        gid, _flips = split(whole(node.attrib, "gid", findings, where, high=2**32 - 1))
        tile = tilesets.tile(gid)
        if tile is None:
            findings.fail(where, f"its tile (gid {gid}) is in none of the map's tilesets",
                          "delete the object, or add back the tileset it came from")
        cls, written = cls or tile.cls, written or tile.cls
        y -= h  # tile objects hang from their bottom-left corner
    return MapObject(object_id, node.get("name", ""), cls, Box(x, y, w, h), _shape(node),
                     rotation, read_properties(node, findings, where), written,
                     _points(node, x, y, findings, where))


def _points(node: ET.Element, x: float, y: float, findings: Findings,
            where: str) -> tuple[tuple[float, float], ...]:
    """A polyline's or polygon's points in map pixels (Tiled stores them relative to x, y)."""
    shape = node.find("polyline")
    if shape is None:
        shape = node.find("polygon")
    if shape is None:
        return ()
    points: list[tuple[float, float]] = []
    pairs = shape.get("points", "").split()
    if len(pairs) > MAX_POINTS:
        findings.fail(where, f"its line has {len(pairs):,} points, more than the "
                      f"{MAX_POINTS:,} the game reads", "redraw the line with fewer points")
    for pair in pairs:
        numbers = [parse_number(v) for v in pair.split(",", 2)]
        if len(numbers) != 2 or numbers[0] is None or numbers[1] is None:
            findings.fail(where, f"its point {excerpt(pair)} is not two finite numbers",
                          "redraw the line in Tiled")
        px, py = numbers[0], numbers[1]
        if max(
                abs(x + px), abs(y + py)) > MAX_COORDINATE_PX:
            findings.fail(where, f"its point {excerpt(pair)} is out of range",
                          "redraw the line in Tiled")
        points.append((x + px, y + py))
    return tuple(points)


def read_objects(layers: list[LayerNode], tilesets: Tilesets, templates: Templates,
                 findings: Findings) -> list[MapObject]:
    """Every object on every object layer, in document order."""
    nodes = [(layer, node) for layer in layers if layer.kind == "objectgroup"
             for node in layer.node.findall("object")]
    if len(nodes) > MAX_OBJECTS:
        findings.fail("map", f"it has {len(nodes):,} objects, more than the {MAX_OBJECTS:,} "
                      "the game reads", "delete objects, or split the level into two maps")
    return [read_object(node, layer, tilesets, templates, findings) for layer, node in nodes]
