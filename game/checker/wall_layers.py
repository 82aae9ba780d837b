"""Which tile layer closes the way? The cells each layer's Solid tiles fill, read again.

Where it sits: :mod:`game.checker.verdict` asks it when no open path joins the spawn and an
Exit, to name the layer to look at. The game itself merges every tile layer into one grid
(:func:`game.levels.solids.build_grid`); here each layer is built on its own, with the same
readers, so a Solid tile painted on a layer meant for decoration (say one named
"background (no collision)") is found by name.

What it teaches: to blame a part, take it away and ask again: the layer whose tiles, once
removed, would open the way is the one that closes it.

A layer's name is a promise the game does not read: :func:`says_it_does_not_collide` tells
a name that promises no collision (the words of :data:`QUIET_WORDS`: "no collision",
"background", "backdrop", "decor", "decoration", "scenery", "bg", in any case, with
spaces, hyphens or underscores), so the checker can warn about the colliding tiles on such
a layer even where they close nothing.

>>> [says_it_does_not_collide(name) for name in ("background (no collision)", "Decor_2",
...                                                "ground", "backgrounds", "debug")]
[True, True, False, False, False]
"""

from __future__ import annotations

import re
from pathlib import Path

from game.collision.shapes import TileKind
from game.levels.errors import Findings, LevelError
from game.levels.header import read_header
from game.levels.layers import walk_layers
from game.levels.paths import sandbox_for
from game.levels.solids import build_grid
from game.levels.tiledata import decode
from game.levels.tiledxml import read_tiled_xml
from game.levels.tilesets import read_tilesets

Cell = tuple[int, int]
# Words in a layer's name that say its tiles are not meant to collide, each a whole word of
# the name once "_" and "-" are read as spaces ("no collision" also written together).
QUIET_WORDS = ("no collision", "no collisions", "nocollision", "non colliding", "background",
               "backdrop", "decor", "decoration", "decorations", "scenery", "bg")
_QUIET = re.compile(r"\b(?:" + "|".join(re.escape(w) for w in QUIET_WORDS) + r")\b")


def says_it_does_not_collide(name: str) -> bool:
    """Does the layer's name say its tiles do not collide (one of :data:`QUIET_WORDS`)?"""
    return _QUIET.search(re.sub(r"[\s_-]+", " ", name.lower())) is not None


def closed_cells_by_layer(path: Path) -> list[tuple[str, set[Cell]]]:
    """Each tile layer's name with the cells its Solid tiles fill wholly, in document order;
    an empty list when the map cannot be read again."""
    findings = Findings(path)
    try:
        root = read_tiled_xml(path, "map", findings)
        header = read_header(root, findings)
        tilesets = read_tilesets(root, path, sandbox_for(path), findings, False)
        found: list[tuple[str, set[Cell]]] = []
        for layer in walk_layers(root, findings):
            if layer.kind != "layer":
                continue
            gids = decode(layer.node.find("data"), header.cells)
            grid = build_grid(header, [(layer, gids)], tilesets, findings)
            found.append((layer.name, {
                (s.col, s.row) for s in grid.shapes() if s.kind is TileKind.SOLID
                and s.box.w >= grid.tile_w and s.box.h >= grid.tile_h}))
        return found
    except (LevelError, ValueError, OSError):
        return []
