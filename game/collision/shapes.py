"""Solid shapes and the one question a mover asks of them: which ones lie in this region?

Where it sits: the vocabulary of :mod:`game.collision.axis_sweep` (the moves) and
:mod:`game.collision.tile_grid` (the tiles). A level's walls, its one-way ledges and its
spikes are :class:`TileShape` records; anything that can answer :class:`ShapeSource`'s
query can be swept against, whether a tile grid, a list of moving platforms or both
composed (the game composes them in :mod:`game.sim.solids`).

What it teaches:
  * **Kinds, not classes.** A shape is a box and what it does to a body
    (:class:`TileKind`): solid from every side, one-way from above, or a hazard that blocks
    nothing. The moves decide by kind; no shape has behaviour of its own.
  * **Ask for a region, get entries.** A move asks its source once per axis step for the
    shapes overlapping the region it sweeps (:meth:`ShapeSource.entries_in`). Each answer
    is an :class:`Entry`: the shape's four edges as plain floats, its kind, and the shape.
    The edges are worked out once, when the shape is filed, not on every query.
  * **A small protocol.** The moves need only that query and the map's size (its left and
    right edges are walls), so a learner can swap in any source, however it stores shapes.

>>> wall = TileShape(Box(32, 0, 16, 16), TileKind.SOLID)
>>> entry = Entry.of(wall)
>>> entry.left, entry.right, entry.kind
(32, 48, <TileKind.SOLID: 'Solid'>)
"""

from __future__ import annotations

from enum import Enum
from typing import NamedTuple, Protocol

from game.collision.aabb import Box


class TileKind(Enum):
    """What a shape does to a body (a tile's Class in Tiled)."""

    SOLID = "Solid"      # blocks from every side
    ONE_WAY = "OneWay"   # blocks only a body coming down onto its top
    HAZARD = "Hazard"    # hurts on touch, blocks nothing


class TileShape(NamedTuple):
    """One collision rectangle in map pixels: its box, its kind, and the cell it was filed
    in (``col``, ``row``). A shape that belongs to no cell (a moving platform's) has
    ``col == -1`` and a number of its owner's choosing as ``row``."""

    box: Box
    kind: TileKind
    col: int = 0
    row: int = 0


class Entry(NamedTuple):
    """A shape as the moves read it: its edges as plain floats, its kind, the shape."""

    left: float
    top: float
    right: float
    bottom: float
    kind: TileKind
    shape: TileShape

    @classmethod
    def of(cls, shape: TileShape) -> Entry:
        """The plain-float form of a shape, worked out once when the shape is filed."""
        x, y, w, h = shape.box
        return cls(x, y, x + w, y + h, shape.kind, shape)


class ShapeSource(Protocol):
    """The solid shapes a body can be swept against: a region query and the map's size.

    :class:`game.collision.tile_grid.TileGrid` is one; so is anything that wraps or
    composes sources (the game's tiles plus moving platforms, a logging wrapper).
    """

    @property
    def width_px(self) -> int:
        """The map's width: its left (0) and right edges stop a body like walls."""
        ...

    @property
    def height_px(self) -> int:
        """The map's height (nothing stops a body at its top or bottom)."""
        ...

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        """Every shape whose interior overlaps the region's interior (touching is not
        overlapping), as entries."""
        ...
