"""How deep a box sits in the solids, and the nearest place where it sits in none.

Where it sits: beside :mod:`game.collision.axis_sweep`, outside the tick's moves. A world
moves a spawn (or an enemy) drawn inside a wall to the nearest free place before play
starts; a report measures how deep any body sits in a solid after resolution (it should
stay 0). Both ask the same :class:`~game.collision.shapes.ShapeSource` as the moves.

What it teaches: around axis-aligned walls the nearest free position has each coordinate
either where it was or flush with some wall face, so a handful of candidates decide it: no
search pixel by pixel. A search in a window stops only when no place outside it can be nearer.

>>> from game.collision.tile_grid import TileGrid
>>> grid = TileGrid(cols=10, rows=10, tile_w=16, tile_h=16)
>>> for col in range(10):
...     grid.put(col, 5, TileShape(Box(col * 16, 80, 16, 16), TileKind.SOLID))
>>> penetration_depth(grid, Box(40, 70, 12, 14))
4
>>> nearest_free_place(grid, Box(40, 70, 12, 14))    # sunk 4 px into a floor: up it goes
Box(x=40, y=66, w=12, h=14)
"""

from __future__ import annotations

import math

from game.collision.aabb import Box
from game.collision.shapes import ShapeSource, TileKind, TileShape


def touching(solids: ShapeSource, box: Box, kind: TileKind) -> list[TileShape]:
    """The shapes of one kind that overlap the box (hazards, for instance)."""
    x, y, w, h = box
    return [entry.shape for entry in solids.entries_in(x, y, x + w, y + h)
            if entry.kind is kind]


def penetration_depth(solids: ShapeSource, box: Box) -> float:
    """How deep the box sits inside any solid shape: 0.0 after a correct resolution."""
    return max((box.penetration(s.box) for s in touching(solids, box, TileKind.SOLID)),
               default=0.0)


def nearest_free_place(solids: ShapeSource, box: Box, search_px: float = 64.0) -> Box:
    """The nearest position to ``box`` where it overlaps no solid: a spawn inside a wall.

    Exact when every solid lies on the map: no free position is nearer (in a straight
    line), and of equally near ones the higher, then the more left, is taken. Where no
    position is free, even off the map, the box stands on top of the map.

    The nearest place has each coordinate where it was or flush with a face of a wall it
    touches, so every combination of those, for the walls in a window ``search_px`` round
    the box, is tried. A place at most ``search_px`` away lies in the window, and so does
    the wall it is flush with: if the nearest place tried is that near, no place is nearer.
    If not, the window doubles, until it holds the whole map and with it every wall.
    """
    if penetration_depth(solids, box) == 0.0:
        return box
    whole_map = max(solids.width_px, solids.height_px)  # px: a window so far round holds it
    while True:
        window = Box(box.x - search_px, box.y - search_px,
                     box.w + 2 * search_px, box.h + 2 * search_px)
        walls = touching(solids, window, TileKind.SOLID)
        xs = {box.x} | {s.box.left - box.w for s in walls} | {s.box.right for s in walls}
        ys = {box.y} | {s.box.top - box.h for s in walls} | {s.box.bottom for s in walls}
        free = [box._replace(x=x, y=y) for x in xs for y in ys
                if penetration_depth(solids, box._replace(x=x, y=y)) == 0.0]
        nearest = min(free, default=None,
                      key=lambda b: ((b.x - box.x) ** 2 + (b.y - box.y) ** 2, b.y, b.x))
        if nearest is not None and math.hypot(nearest.x - box.x, nearest.y - box.y) <= search_px:
            return nearest  # no place is nearer: each nearer one was tried
        if search_px >= whole_map:  # each place was tried: none is nearer, or none is free
            return box._replace(y=-box.h) if nearest is None else nearest
        search_px *= 2
