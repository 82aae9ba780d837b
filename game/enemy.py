"""Enemies: walkers that patrol a floor and turn round at walls and ledges.

Where it sits: step 2 of a tick chooses each enemy's velocity; the enemies then move with
the same axis passes as the player (:mod:`game.movement`), and :meth:`Enemy.react` turns
them round when a wall stops them.
"""

from __future__ import annotations

from game.aabb import Box
from game.body import Body
from game.movement import Move
from game.tilegrid import TileGrid, TileKind
from game.tuning import Tuning

LEDGE_PROBE_PX = 1.0  # size of the square looked at just beyond the leading foot


class Enemy(Body):
    """A walker: patrols at ``speed_px_s``, starting towards the left."""

    def __init__(self, box: Box, speed_px_s: float) -> None:
        super().__init__(box)
        self.speed_px_s = speed_px_s
        self.direction = -1

    def decide(self, grid: TileGrid, tuning: Tuning) -> None:
        """Turn at a ledge, then walk on and fall."""
        if self.on_ground and not self._ground_ahead(grid):
            self.direction = -self.direction
        self.vx = self.direction * self.speed_px_s
        self.vy = min(self.vy + tuning.gravity_px_s2 * tuning.tick_s,
                      tuning.max_fall_speed_px_s)

    def _ground_ahead(self, grid: TileGrid) -> bool:
        box = self.box
        front = box.right if self.direction > 0 else box.left - LEDGE_PROBE_PX
        probe = Box(front, box.bottom, LEDGE_PROBE_PX, LEDGE_PROBE_PX)
        return any(s.kind is not TileKind.HAZARD for s in grid.shapes_in(probe))

    def react(self, x_move: Move, y_move: Move) -> None:
        if x_move.hit is not None:
            self.direction = -self.direction
        if y_move.hit is not None:
            self.vy = 0.0
