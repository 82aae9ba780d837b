"""Tile layers into collision shapes: what a Solid, OneWay or Hazard tile blocks, and where.

Where it sits: the loader calls :func:`build_grid` with every decoded tile layer, hidden
ones included (a hidden layer is a common way to keep collision apart from decoration).
The result is the :class:`~game.collision.tile_grid.TileGrid` that the movement code queries.

What it teaches:
  * A tile's collision is its whole cell, unless rectangles were drawn for it in Tiled's
    tile collision editor; then exactly those rectangles, clipped to the cell.
  * A flipped or rotated tile has its rectangles flipped with it. Tiled applies the
    diagonal flip (a swap of x and y) first, then the horizontal and vertical flips, as
    :func:`flip_box` does: a spike drawn upside down hurts from the ceiling.
  * A tile larger than the grid stands on its cell's bottom-left corner, as Tiled draws it.
  * Layers are merged cell by cell, and a shape already in a cell is not put there again:
    ground painted on two identical layers is the same ground as on one.

>>> flip_box(Box(1, 8, 14, 8), FLIPPED_V, 16, 16)   # floor spikes hung from the ceiling
Box(x=1, y=0, w=14, h=8)
>>> flip_box(Box(0, 0, 4, 16), FLIPPED_D, 16, 16)   # a strip down the left side, on top
Box(x=0, y=0, w=16, h=4)
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.levels.budget import FIX_SHAPES, MAX_SHAPES
from game.levels.classes import TILE_KINDS
from game.levels.errors import Findings, tile_place
from game.levels.header import MapHeader
from game.levels.layers import LayerNode
from game.levels.tiledata import FLIPPED_D, FLIPPED_H, FLIPPED_V, split
from game.levels.tilesets import Tilesets

Offsets = tuple[tuple[TileKind, Box], ...]  # shapes relative to the cell's top-left corner


def flip_box(box: Box, flips: int, tile_w: float, tile_h: float) -> Box:
    """A rectangle in a ``tile_w`` x ``tile_h`` tile, after the tile's flips."""
    x, y, w, h = box
    if flips & FLIPPED_D:
        x, y, w, h = y, x, h, w
        tile_w, tile_h = tile_h, tile_w
    if flips & FLIPPED_H:
        x = tile_w - x - w
    if flips & FLIPPED_V:
        y = tile_h - y - h
    return Box(x, y, w, h)


def _clip(box: Box, cell: Box) -> Box | None:
    left, top = max(box.left, cell.left), max(box.top, cell.top)
    right, bottom = min(box.right, cell.right), min(box.bottom, cell.bottom)
    return Box(left, top, right - left, bottom - top) if right > left and bottom > top else None


def _shapes_of(raw: int, tilesets: Tilesets, header: MapHeader) -> Offsets | None:
    """The collision shapes of a raw GID relative to its cell; None if no tileset owns it."""
    gid, flips = split(raw)
    tileset = tilesets.find(gid)
    if tileset is None:
        return None
    tile = tileset.tiles.get(gid - tileset.firstgid)
    kind = TILE_KINDS.get(tile.cls) if tile else None
    if tile is None or kind is None:
        return ()
    cell = Box(0, 0, header.tile_w, header.tile_h)
    if not tile.boxes:
        return ((kind, cell),)
    drawn_h = tileset.tile_w if flips & FLIPPED_D else tileset.tile_h
    shapes = []
    for box in tile.boxes:
        placed = flip_box(box, flips, tileset.tile_w, tileset.tile_h).moved(
            dy=header.tile_h - drawn_h)  # tall tiles stand on the cell's bottom edge
        clipped = _clip(placed, cell)
        if clipped is not None:
            shapes.append((kind, clipped))
    return tuple(shapes)


def _new_in_cell(placed: dict[int, Offsets], index: int, shapes: Offsets) -> Offsets:
    """The shapes of ``shapes`` that cell ``index`` does not hold yet, noted as held: the
    same tile painted on two layers (a copy of the ground layer, say) is one wall, not two
    laid on each other, so nothing that adds up the cover of a cell counts it twice."""
    before = placed.get(index)
    if before is None:
        placed[index] = shapes
        return shapes
    if before is shapes:  # the same tile again: its shapes are worked out once, by id
        return ()
    fresh = tuple(shape for shape in shapes if shape not in before)
    placed[index] = before + fresh
    return fresh


def build_grid(header: MapHeader, layers: Sequence[tuple[LayerNode, Sequence[int]]],
               tilesets: Tilesets, findings: Findings) -> TileGrid:
    """The collision grid of all tile layers; a GID no tileset owns is an error.

    Every shape is counted, layer by layer, before the first one is made: a map past the
    budget is refused having made none. Counting goes by tile id, not by cell: a layer holds
    few different ids, and each id's shapes are worked out once. A shape painted on several
    layers in one cell is made once (:func:`_new_in_cell`), though the count before counts
    it on each layer: the budget is a bound on what is made."""
    cache: dict[int, Offsets | None] = {}
    made = 0  # shapes the layers counted so far will make
    for layer, gids in layers:
        uses = Counter(gids)
        uses.pop(0, None)  # 0 is an empty cell
        unknown: set[int] = set()
        for raw, count in uses.items():
            if raw not in cache:
                cache[raw] = _shapes_of(raw, tilesets, header)
            shapes = cache[raw]
            if shapes is None:
                unknown.add(raw)
            else:
                made += count * len(shapes)
        if made > MAX_SHAPES:
            findings.fail(layer.place, f"the map's tiles make more than {MAX_SHAPES:,} "
                          "collision shapes, the most the game builds for one map",
                          f"{FIX_SHAPES}, or paint fewer colliding tiles")
        if unknown:
            first = next(index for index, raw in enumerate(gids) if raw in unknown)
            row, col = divmod(first, header.cols)
            cells = sum(uses[raw] for raw in unknown)
            more = f" ({cells} cells in all)" if cells > 1 else ""
            findings.error(tile_place(col, row, layer.name),
                           f"tile id {split(gids[first])[0]} is in none of the map's "
                           f"tilesets{more}",
                           "erase those tiles, or add back the tileset they came from")
    grid = TileGrid(header.cols, header.rows, header.tile_w, header.tile_h)
    placed: dict[int, Offsets] = {}  # each cell's shapes so far, when several layers collide
    several = len(layers) > 1
    for _layer, gids in layers:
        for index, raw in enumerate(gids):
            shapes = cache[raw] if raw else None
            if not shapes:  # an empty cell, a tile that does not collide, or an unknown id
                continue
            if several:
                shapes = _new_in_cell(placed, index, shapes)
            row, col = divmod(index, header.cols)
            left, top = col * header.tile_w, row * header.tile_h
            for kind, (x, y, w, h) in shapes:
                grid.put(col, row, TileShape(Box(left + x, top + y, w, h), kind, col, row))
    return grid
