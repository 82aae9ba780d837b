"""The map element itself: its orientation, its size and its tile size, within limits.

Where it sits: checked right after the file is parsed, before any tile data is read, so a
100000x100000 map is refused in microseconds instead of filling the memory.

What it teaches: the game plays orthogonal, finite maps. Tiled can also make isometric,
staggered and hexagonal maps (a different grid geometry) and infinite maps (stored as
chunks); each is refused with the Map Properties setting that changes it.

>>> from pathlib import Path
>>> root = ET.fromstring('<map orientation="orthogonal" width="84" height="12" '
...                      'tilewidth="16" tileheight="16" infinite="0"/>')
>>> read_header(root, Findings(Path("a.tmx")))
MapHeader(cols=84, rows=12, tile_w=16, tile_h=16, background=None)
>>> read_header(ET.fromstring('<map orientation="isometric"/>'), Findings(Path("a.tmx")))
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: a.tmx: map: isometric maps are not supported — \
make an Orthogonal map (Map > Map Properties > Orientation)
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass

from game.levels.attributes import whole
from game.levels.errors import Findings

MAX_MAP_CELLS = 250_000      # per layer: 500x500 tiles, 8000 px square at 16 px a tile
MAX_TOTAL_CELLS = 1_000_000  # over all tile layers together: a few seconds to load
MAX_TILE_PX = 1024
FIX_SIZE = "change it in Map > Resize Map"


@dataclass(frozen=True)
class MapHeader:
    """What the ``<map>`` element says about the grid."""

    cols: int
    rows: int
    tile_w: int
    tile_h: int
    background: str | None

    @property
    def cells(self) -> int:
        return self.cols * self.rows


def read_header(root: ET.Element, findings: Findings) -> MapHeader:
    """Check the ``<map>`` element's attributes and return the grid they describe."""
    orientation = root.get("orientation", "orthogonal")
    if orientation != "orthogonal":
        findings.fail("map", f"{orientation} maps are not supported",
                      "make an Orthogonal map (Map > Map Properties > Orientation)")
    if root.get("infinite", "0") not in ("0", ""):
        findings.fail("map", "infinite maps are not supported",
                      "untick Map > Map Properties > Infinite to make the map finite")
    cols = whole(root.attrib, "width", findings, "map")
    rows = whole(root.attrib, "height", findings, "map")
    tile_w = whole(root.attrib, "tilewidth", findings, "map")
    tile_h = whole(root.attrib, "tileheight", findings, "map")
    if cols < 1 or rows < 1 or cols * rows > MAX_MAP_CELLS:
        findings.fail("map", f"a {cols}x{rows} map is outside the playable size "
                      f"(1 to {MAX_MAP_CELLS:,} tiles)", FIX_SIZE)
    if not (1 <= tile_w <= MAX_TILE_PX and 1 <= tile_h <= MAX_TILE_PX):
        findings.fail("map", f"a {tile_w}x{tile_h} tile size is not playable",
                      f"set a tile size of 1 to {MAX_TILE_PX} pixels in Map > Map Properties")
    return MapHeader(cols, rows, tile_w, tile_h, root.get("backgroundcolor"))
