"""Enemies: walkers that patrol a floor, and hoppers that patrol it in hops.

Where it sits: step 1 of a tick chooses each enemy's velocity; the enemies then move with
the same axis passes as the player (:mod:`game.collision.axis_sweep`), and :meth:`Enemy.react` turns
them round when a wall stops them. Both kinds turn back at a ledge rather than fall off it.
A stomped enemy leaves play at once and a :class:`Squashed` sprite takes its place on
screen for a moment: drawn, never collided with.
"""

from __future__ import annotations

import math
from enum import Enum

import pygame

from game.collision.aabb import Box
from game.collision.axis_sweep import Move
from game.collision.shapes import ShapeSource, TileKind, TileShape
from game.sim.body import Body
from game.sim.sprite import BoxSprite, Strip, animation_index
from game.sim.tuning import Tuning

LEDGE_PROBE_PX = 1.0  # size of the square looked at just beyond the leading foot

# The enemy strip (assets/README.md): 0-1 walker walk, 2 squashed, 3-4 hopper; facing right.
WALK_FPS = 4
WALK_FRAMES = (0, 1)
SQUASHED_FRAME = 2
HOPPER_SITTING_FRAME = 3
HOPPER_AIRBORNE_FRAME = 4
WALK_PHASE_COL_PX = 16  # walkers that start a 16 px column apart step one frame apart


class EnemyKind(Enum):
    WALKER = "walker"
    HOPPER = "hopper"



class Enemy(Body):
    """Patrols at ``speed_px_s``, starting towards the left; a hopper only moves mid-hop."""

    def __init__(self, box: Box, speed_px_s: float, kind: EnemyKind = EnemyKind.WALKER,
                 ) -> None:
        super().__init__(box)
        self.speed_px_s = speed_px_s
        self.kind = kind
        self.direction = -1
        self.rest_ticks_left = 0
        self.phase = math.floor(box.x / WALK_PHASE_COL_PX)
        self.ground_seen: TileShape | None = None  # a tile the ledge look-ahead last found

    def decide(self, solids: ShapeSource, tuning: Tuning) -> None:
        """Turn at a ledge, then walk (or hop) on, and fall."""
        if self.on_ground and not self._ground_ahead(solids):
            self.direction = -self.direction
        self.vx = self.direction * self.speed_px_s
        if self.kind is EnemyKind.HOPPER:
            self._hop(tuning)
        self.vy = min(self.vy + tuning.gravity_px_s2 * tuning.tick_s,
                      tuning.max_fall_speed_px_s)

    def _hop(self, tuning: Tuning) -> None:
        if not self.on_ground:
            return
        if self.rest_ticks_left > 0:
            self.rest_ticks_left -= 1
            self.vx = 0.0
            return
        self.vy = -tuning.hopper_jump_speed_px_s
        self.rest_ticks_left = tuning.hopper_rest_ticks

    def _ground_ahead(self, solids: ShapeSource) -> bool:
        """Is there ground in the square just beyond the leading foot?

        Two tiles answer first, without a lookup: the one the feet stand on, and the one the
        last lookup found ahead. An enemy walks half a pixel a tick, so one of them still
        reaches under the square on almost every tick, and when one does, the lookup would
        say the same (a moving platform's shape is only used while it is stood on: it may
        have moved on since it was seen).
        """
        x, y, w, h = self.box
        ahead = x + w if self.direction > 0 else x - LEDGE_PROBE_PX
        feet = y + h
        for known in (self.standing_on, self.ground_seen):
            if known is not None:
                left, top, width, height = known.box
                if (left < ahead + LEDGE_PROBE_PX and ahead < left + width
                        and top < feet + LEDGE_PROBE_PX and feet < top + height):
                    return True
        for entry in solids.entries_in(ahead, feet, ahead + LEDGE_PROBE_PX,
                                       feet + LEDGE_PROBE_PX):
            if entry.kind is not TileKind.HAZARD:
                shape = entry.shape
                self.ground_seen = shape if shape.col != -1 else None
                return True
        return False

    def react(self, x_move: Move, y_move: Move) -> None:
        if x_move.hit is not None:
            self.direction = -self.direction
        if y_move.hit is not None:
            self.vy = 0.0

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        """A hopper sits or leaps; a walker steps. Either faces the way it goes."""
        if self.kind is EnemyKind.HOPPER:
            index = HOPPER_SITTING_FRAME if self.on_ground else HOPPER_AIRBORNE_FRAME
        else:
            index = animation_index(frame, WALK_FPS, WALK_FRAMES, self.phase)
        return strip.frame(index, self.direction)


class Squashed(BoxSprite):
    """Where an enemy was stomped: shown flattened for ``ticks_left`` more ticks, then gone."""

    def __init__(self, box: Box, ticks: int) -> None:
        super().__init__(box)
        self.ticks_left = ticks

    def fade(self) -> None:
        """One tick less on screen; leave every group when the time is up."""
        self.ticks_left -= 1
        if self.ticks_left <= 0:
            self.kill()

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        return strip.frame(SQUASHED_FRAME)
