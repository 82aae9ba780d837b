"""Things the player touches rather than collides with: coins, exits and checkpoints.

Where it sits: steps 6 and 7 of a tick (:meth:`game.sim.world.World.step`). These are triggers,
not solids: they never stop a body. A coin is taken (it leaves its group) when the path the
player swept this tick crosses its float ``box`` (its ``rect`` is only the picture); exits
and checkpoints go through the contact tracker, which reports when a touch starts.

Each is a :class:`~game.sim.sprite.BoxSprite`: a coin spins, its picture centred on its box;
an exit is a flag and a checkpoint a lantern (unlit until reached), each standing on the
bottom of its box.

Triggers never move, so the tile cells they lie in are found once (:class:`TriggerCells`),
and a tick tests the player's path against them only when that path reaches one of those
cells: a broad phase as small as a set of cells. On most ticks it reaches none, and no
trigger is tested at all.

>>> cells = TriggerCells(16, 16)
>>> cells.file(Box(40, 40, 8, 8))                  # one coin, in cell (2, 2)
>>> cells.reached_by(0, 0, 30, 30), cells.reached_by(30, 30, 34, 34)
(False, True)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from math import floor

import pygame

from game.collision.aabb import Box
from game.sim.sprite import Anchor, BoxSprite, Strip, animation_index

COIN_SPIN_FPS = 8  # spin frames per second
COIN_PHASE_COL_PX = 16  # neighbouring coins (by 16 px column) are one spin frame apart

NO_ROWS: frozenset[int] = frozenset()  # the rows filed in a column that holds no trigger
CHECKPOINT_WAITING_FRAME = 0  # a checkpoint's strip: unlit, then lit (reached)
CHECKPOINT_REACHED_FRAME = 1


@dataclass
class TriggerCells:
    """The tile cells that hold a trigger: where a path must reach for any to be tested.

    A box is filed from the cell of its left (top) edge to the cell of its right (bottom)
    edge, both by ``floor``, and a path is looked up the same way. The rule never decreases,
    so a trigger and a path that overlap always share a cell, however the floats round (a
    box whose edge lies on a border is filed one cell further than it reaches; the exact
    test afterwards turns such a near miss away).

    The cells are kept column by column (``rows``: the rows filed in each column), so a
    path, a column or two wide, looks up its columns and finds most of them hold nothing:
    fewer lookups than one for each ``(col, row)`` cell the path covers.
    """

    tile_w: int
    tile_h: int
    rows: dict[int, set[int]] = field(default_factory=dict)

    def file(self, box: Box) -> None:
        x, y, w, h = box
        first_col, last_col = floor(x / self.tile_w), floor((x + w) / self.tile_w)
        first_row, last_row = floor(y / self.tile_h), floor((y + h) / self.tile_h)
        for col in range(first_col, last_col + 1):
            self.rows.setdefault(col, set()).update(range(first_row, last_row + 1))

    def reached_by(self, left: float, top: float, right: float, bottom: float) -> bool:
        """Does the region reach a cell that holds a trigger? (Every tick asks this twice,
        for the triggers and for the spikes, so it is a plain loop: ``any()`` would make a
        generator on every call.)"""
        try:
            cols: Sequence[int] = range(floor(left / self.tile_w), floor(right / self.tile_w) + 1)
            rows = range(floor(top / self.tile_h), floor(bottom / self.tile_h) + 1)
        except (ValueError, OverflowError):
            return True  # a region with no cells to name: let the exact tests decide
        if len(cols) > len(self.rows):  # wider than all the filed columns
            cols = [col for col in self.rows if col in cols]
        for col in cols:  # noqa: SIM110  (see the docstring)
            if not self.rows.get(col, NO_ROWS).isdisjoint(rows):
                return True
        return False


class Trigger(BoxSprite):
    """A box the player can touch; it never blocks. Drawn as a flag standing on its bottom."""


class Coin(Trigger):
    """A coin worth ``value`` points, spinning on the spot."""

    anchor = Anchor.CENTRE

    def __init__(self, box: Box, value: int) -> None:
        super().__init__(box)
        self.value = value
        self.phase = floor(box.x / COIN_PHASE_COL_PX)

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        return strip.frame(animation_index(frame, COIN_SPIN_FPS, range(len(strip.right)),
                                           self.phase))


class Exit(Trigger):
    """Touching it completes the level."""


class Checkpoint(Trigger):
    """Touching or passing it the first time moves the player's respawn point here; the one
    counted last is lit."""

    def __init__(self, box: Box) -> None:
        super().__init__(box)
        self.reached = False  # the respawn point is here (set by the world)

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        return strip.frame(CHECKPOINT_REACHED_FRAME if self.reached
                           else CHECKPOINT_WAITING_FRAME)
