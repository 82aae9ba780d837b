"""How deep a box sits in the solids, and the nearest place where it sits in none.

Where it sits: beside :mod:`game.collision.axis_sweep`, outside the tick's moves. A world
moves a spawn (or an enemy) drawn inside a wall to the nearest free place before play
starts; a report measures how deep any body sits in a solid after resolution (it should
stay 0). Both ask the same :class:`~game.collision.shapes.ShapeSource` as the moves.

What it teaches: around axis-aligned walls the nearest free position has each coordinate
either where it was or flush with some wall face, so a handful of candidates decide it: no
search pixel by pixel.

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
    """The closest position to ``box`` where it overlaps no solid: a spawn inside a wall.

    Each coordinate is tried where it was and flush with every wall face in a window round
    the box; the window grows until some combination is free. Ties go to the higher, then
    the more left, position.
    """
    if penetration_depth(solids, box) == 0.0:
        return box
    limit = max(solids.width_px, solids.height_px) + box.w + box.h
    while True:
        window = Box(box.x - search_px, box.y - search_px,
                     box.w + 2 * search_px, box.h + 2 * search_px)
        walls = touching(solids, window, TileKind.SOLID)
        xs = {box.x} | {s.box.left - box.w for s in walls} | {s.box.right for s in walls}
        ys = {box.y} | {s.box.top - box.h for s in walls} | {s.box.bottom for s in walls}
        free = [box._replace(x=x, y=y) for x in xs for y in ys
                if penetration_depth(solids, box._replace(x=x, y=y)) == 0.0]
        if free:
            return min(free, key=lambda b: ((b.x - box.x) ** 2 + (b.y - box.y) ** 2, b.y, b.x))
        if search_px > limit:
            return box._replace(y=-box.h)  # a map solid everywhere: stand on top of it
        search_px *= 2
