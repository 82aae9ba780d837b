"""The floor: the game's axis sweeps written in plain floats, with no objects at all.

Where it sits: a yardstick for :mod:`game.bench.peer`. It answers exactly what
:func:`game.collision.axis_sweep.move_x` and :func:`~game.collision.axis_sweep.move_y`
answer against solid tiles (the same swept region, the same strict cell range and overlap
test, the same nearest face, the same map edges), but it takes and returns bare floats and
reads walls stored as tuples of floats: no ``Box``, ``Move`` or ``Hit`` is built, no method
is called per wall. The bench checks that it lands every recorded move exactly where the
game's code does.

What it teaches: how much of a move's cost is the arithmetic and how much is the objects
around it. The targets measure the game's own moves, and its whole tick per body, against
this floor; Python cannot do the same sweep in much less.

>>> walls = PlainWalls({(5, 0): ((80.0, 0.0, 96.0, 16.0),)}, 16, 16, 10, 4)
>>> sweep_x(walls, 10.0, 2.0, 12.0, 12.0, 500.0)     # stops flush at the wall's face
68.0
>>> sweep_y(walls, 84.0, -40.0, 4.0, 4.0, 100.0)     # lands on its top
-4.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid

Edges = tuple[float, float, float, float]   # left, top, right, bottom


@dataclass(frozen=True)
class PlainWalls:
    """Solid shapes as edge tuples, bucketed by tile cell, and the map's size in cells."""

    cells: dict[tuple[int, int], tuple[Edges, ...]]
    tile_w: int
    tile_h: int
    cols: int
    rows: int

    @classmethod
    def from_grid(cls, grid: TileGrid) -> PlainWalls:
        """The grid's solid shapes (one-way and hazard shapes are left out)."""
        cells: dict[tuple[int, int], list[Edges]] = {}
        for shape in grid.shapes():
            if shape.kind is TileKind.SOLID:
                b = shape.box
                cells.setdefault((shape.col, shape.row), []).append(
                    (b.x, b.y, b.x + b.w, b.y + b.h))
        return cls({cell: tuple(edges) for cell, edges in cells.items()}, grid.tile_w,
                   grid.tile_h, grid.cols, grid.rows)


def _walls_in(walls: PlainWalls, left: float, top: float, right: float,
              bottom: float) -> list[Edges]:
    """The walls whose interior overlaps the region (the tile grid's cell range and test)."""
    first_col = max(0, math.floor(left / walls.tile_w))
    last_col = min(walls.cols - 1, math.ceil(right / walls.tile_w) - 1)
    first_row = max(0, math.floor(top / walls.tile_h))
    last_row = min(walls.rows - 1, math.ceil(bottom / walls.tile_h) - 1)
    found = []
    cells = walls.cells
    for row in range(first_row, last_row + 1):
        for col in range(first_col, last_col + 1):
            for edges in cells.get((col, row), ()):
                if edges[0] < right and left < edges[2] and edges[1] < bottom and top < edges[3]:
                    found.append(edges)
    return found


def sweep_x(walls: PlainWalls, x: float, y: float, w: float, h: float, dx: float) -> float:
    """The new ``x`` after moving ``dx`` along x: flush at the nearest wall or map edge."""
    if dx == 0:
        return x
    left = min(x, x + dx)
    region_right = left + (max(x + w, x + dx + w) - left)
    near = _walls_in(walls, left, y, region_right, y + h)
    right = x + w
    if dx > 0:
        stop = right + dx
        for edges in near:
            if right <= edges[0] < stop:
                stop = edges[0]
        width_px = walls.cols * walls.tile_w
        if right <= width_px < stop:
            stop = width_px
        return stop - w
    stop = x + dx
    for edges in near:
        if stop < edges[2] <= x:
            stop = edges[2]
    if stop < 0 <= x:
        stop = 0
    return stop


def sweep_y(walls: PlainWalls, x: float, y: float, w: float, h: float, dy: float) -> float:
    """The new ``y`` after moving ``dy`` along y (down is positive): flush at the nearest
    wall; the map has no floor or ceiling of its own."""
    if dy == 0:
        return y
    top = min(y, y + dy)
    region_bottom = top + (max(y + h, y + dy + h) - top)
    near = _walls_in(walls, x, top, x + w, region_bottom)
    bottom = y + h
    if dy > 0:
        stop = bottom + dy
        for edges in near:
            if bottom <= edges[1] < stop:
                stop = edges[1]
        return stop - h
    stop = y + dy
    for edges in near:
        if stop < edges[3] <= y:
            stop = edges[3]
    return stop
