"""Object templates (``.tx``): an object that says "like that one, but here".

Where it sits: :mod:`game.levels.objects` passes every ``<object template="...">`` through
:meth:`Templates.apply` before reading it, so a Coin placed from a template is a Coin.
(pytmx 3.32 does not read templates at all: such an object has no class and no size.)

What it teaches: a template instance stores only what differs from its template. Resolving
it is a merge where the instance wins: the template's attributes, then the instance's; the
template's properties, then the instance's by name; the instance's shape if it has one.
A tile template names a tile of its own tileset, so its GID is renumbered into the map's
(and that tileset is read, if the map does not list it).

>>> template = ET.fromstring('<object type="Coin" width="8" height="8"><properties>'
...     '<property name="value" type="int" value="1"/></properties><point/></object>')
>>> instance = ET.fromstring('<object id="7" template="coin.tx" x="16" y="32"><properties>'
...     '<property name="value" type="int" value="5"/></properties></object>')
>>> merged = merge(template, instance)
>>> sorted(merged.attrib.items())
[('height', '8'), ('id', '7'), ('type', 'Coin'), ('width', '8'), ('x', '16'), ('y', '32')]
>>> [p.get("value") for p in merged.iter("property")], merged.find("point") is not None
(['5'], True)
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from game.levels.attributes import whole
from game.levels.errors import Findings, within
from game.levels.paths import Sandbox, resolve
from game.levels.tiledata import FLAG_BITS, split
from game.levels.tiledxml import read_tiled_xml, refuse_json
from game.levels.tilesets import Tilesets, read_tileset_file


def merge(template: ET.Element, instance: ET.Element) -> ET.Element:
    """A new ``<object>``: the template overridden by the instance."""
    attributes = {**template.attrib, **instance.attrib}
    attributes.pop("template", None)
    merged = ET.Element("object", attributes)
    properties: dict[str, ET.Element] = {}
    for source in (template, instance):
        for prop in source.findall("properties/property"):
            properties[prop.get("name", "")] = prop
    block = ET.SubElement(merged, "properties")
    block.extend(properties.values())
    shapes = [child for child in instance if child.tag != "properties"]
    merged.extend(shapes or [child for child in template if child.tag != "properties"])
    return merged


class Templates:
    """The templates one map uses, each read once, their tiles renumbered for the map."""

    def __init__(self, map_path: Path, root: Sandbox, tilesets: Tilesets, findings: Findings,
                 check_images: bool) -> None:
        self.map_dir = map_path.parent
        self.root = root
        self.tilesets = tilesets
        self.findings = findings
        self.check_images = check_images
        self.cache: dict[Path, ET.Element] = {}

    def apply(self, node: ET.Element, where: str) -> ET.Element:
        """``node`` itself, or merged with its template if it names one."""
        reference = node.get("template")
        if reference is None:
            return node
        refuse_json(self.findings, where, "template", reference)
        path = resolve(reference, self.map_dir, self.root, self.findings, where, "template")
        if path not in self.cache:
            self.cache[path] = self._read(path, within(where, f"{where} (template {reference})"))
        return merge(self.cache[path], node)

    def _read(self, path: Path, where: str) -> ET.Element:
        """The template's ``<object>``, with a tile GID moved into the map's numbering."""
        root = read_tiled_xml(path, "template", self.findings, where)
        template = root.find("object")
        if template is None:
            self.findings.fail(where, "the template holds no object",
                               "make the template again from an object in Tiled")
        if "gid" not in template.attrib:
            return template
        tileset = root.find("tileset")
        if tileset is None or tileset.get("source") is None:
            self.findings.fail(where, "the template's tile has no tileset file",
                               "make the template again from a tile of an external tileset")
        source = resolve(tileset.get("source", ""), path.parent, self.root, self.findings,
                         where, "template's tileset")
        in_map = self.tilesets.by_source(source)
        if in_map is None:  # Tiled reads it with the template; so does the game
            in_map = read_tileset_file(tileset.get("source", ""), path.parent,
                                       self.tilesets.next_firstgid, self.root, self.findings,
                                       self.check_images, where)
            self.tilesets.add(in_map)
        raw = whole(template.attrib, "gid", self.findings, where, high=2**32 - 1)
        gid, flips = split(raw)
        local = gid - whole(tileset.attrib, "firstgid", self.findings, where, low=1,
                            high=FLAG_BITS)
        renumbered = ET.Element("object", {**template.attrib,
                                           "gid": str((in_map.firstgid + local) | flips)})
        renumbered.extend(list(template))
        return renumbered
