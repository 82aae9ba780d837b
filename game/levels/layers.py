"""Layers in the order Tiled draws them, found inside groups too.

Where it sits: the loader reads tile layers, object layers and image layers in the order
this yields. (pytmx 3.32 regroups layers by kind, so a tile layer drawn over the objects in
Tiled would come out under them; and it does not look into groups for this order.)

What it teaches: a Tiled map is a tree. Groups nest; a group's offset moves everything in
it, its opacity multiplies and a hidden group hides its children. Walking the tree once,
depth first, gives each leaf layer in document order with those settings already combined.
Numbers are checked where they are combined: a layer's offset and its groups' may each be
finite and their sum overflow to infinity, so the sum is what is checked.

>>> from pathlib import Path
>>> root = ET.fromstring('<map><layer name="sky"/><group name="g" offsetx="2.5" opacity="0.5">'
...     '<objectgroup name="things" offsetx="1"/></group><layer name="front"/></map>')
>>> [(layer.name, layer.offset, layer.opacity) for layer in
...  walk_layers(root, Findings(Path("a.tmx")))]
[('sky', (0.0, 0.0), 1.0), ('things', (3.5, 0.0), 0.5), ('front', (0.0, 0.0), 1.0)]
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass

from game.levels.attributes import number
from game.levels.errors import Findings, Place, layer_place

LEAF_TAGS = ("layer", "objectgroup", "imagelayer")
MAX_GROUP_DEPTH = 32
MAX_LAYERS = 1_000
MAX_OFFSET_PX = 1_000_000  # a layer moved further is off every map the game reads
MAX_PARALLAX = 100.0  # a factor further from 0 than this scrolls a layer off in a blink


@dataclass(frozen=True)
class LayerNode:
    """One tile, object or image layer, with its group's settings folded in."""

    node: ET.Element
    name: str
    offset: tuple[float, float]
    opacity: float
    visible: bool
    parallax: tuple[float, float] = (1.0, 1.0)

    @property
    def kind(self) -> str:
        return self.node.tag

    @property
    def place(self) -> Place:
        return layer_place(self.name)


def _walk(parent: ET.Element, findings: Findings, offset: tuple[float, float],
          opacity: float, visible: bool, depth: int,
          parallax: tuple[float, float] = (1.0, 1.0)) -> Iterator[LayerNode]:
    if depth > MAX_GROUP_DEPTH:
        findings.fail("", f"groups are nested more than {MAX_GROUP_DEPTH} deep",
                      "move the layers out of some groups in Tiled's Layers panel")
    for child in parent:
        if child.tag not in (*LEAF_TAGS, "group"):
            continue
        name = child.get("name", "")
        where = layer_place(name)
        ox = offset[0] + number(child.attrib, "offsetx", findings, where, 0.0)
        oy = offset[1] + number(child.attrib, "offsety", findings, where, 0.0)
        if not (abs(ox) <= MAX_OFFSET_PX and abs(oy) <= MAX_OFFSET_PX):  # inf and nan too
            findings.fail(where, f"its offset, added to its groups', is ({ox:g}, {oy:g}), "
                          f"further than the {MAX_OFFSET_PX:,} px a layer may be moved",
                          "set the Offset of the layer and of its groups back to 0, 0 in "
                          "Tiled's Layer Properties")
        alpha = opacity * min(1.0, max(0.0, number(child.attrib, "opacity", findings, where,
                                                   1.0)))
        shown = visible and child.get("visible", "1") != "0"
        # Tiled multiplies a layer's parallax factors by its groups'.
        factors = (parallax[0] * _factor(child, "parallaxx", findings, where),
                   parallax[1] * _factor(child, "parallaxy", findings, where))
        if child.tag == "group":
            yield from _walk(child, findings, (ox, oy), alpha, shown, depth + 1, factors)
        else:
            yield LayerNode(child, name, (ox, oy), alpha, shown, factors)


def _factor(node: ET.Element, name: str, findings: Findings, where: str) -> float:
    """A parallax factor, kept within what makes sense on screen."""
    return min(MAX_PARALLAX, max(-MAX_PARALLAX, number(node.attrib, name, findings, where,
                                                       1.0)))


def walk_layers(root: ET.Element, findings: Findings) -> list[LayerNode]:
    """Every leaf layer of the map, in Tiled's document (drawing) order."""
    layers = list(_walk(root, findings, (0.0, 0.0), 1.0, True, 0))
    if len(layers) > MAX_LAYERS:
        findings.fail("map", f"it has {len(layers):,} layers, more than the {MAX_LAYERS:,} "
                      "the game reads", "merge layers in Tiled's Layers panel")
    return layers
