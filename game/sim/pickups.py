"""Things the player touches rather than collides with: coins, exits and checkpoints.

Where it sits: steps 6 and 7 of a tick (:meth:`game.sim.world.World.step`). These are triggers,
not solids: they never stop a body. Coins are taken with ``pygame.sprite.groupcollide``,
whose ``collided=`` test compares each coin's float ``box`` with the path the player swept
this tick (its ``rect`` is only the picture); exits and checkpoints go through the contact
tracker, which reports when a touch starts.

Each is a :class:`~game.sim.sprite.BoxSprite`: a coin spins, its picture centred on its box;
an exit or checkpoint is a flag standing on the bottom of its box, greyed until reached.
"""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.sim.sprite import Anchor, BoxSprite, Strip, animation_index

COIN_SPIN_FPS = 8  # spin frames per second
COIN_PHASE_COL_PX = 16  # neighbouring coins (by 16 px column) are one spin frame apart

CHECKPOINT_WAITING_FRAME = 0  # a checkpoint's strip: greyed, then reached
CHECKPOINT_REACHED_FRAME = 1


class Trigger(BoxSprite):
    """A box the player can touch; it never blocks. Drawn as a flag standing on its bottom."""


class Coin(Trigger):
    """A coin worth ``value`` points, spinning on the spot."""

    anchor = Anchor.CENTRE

    def __init__(self, box: Box, value: int) -> None:
        super().__init__(box)
        self.value = value
        self.phase = math.floor(box.x / COIN_PHASE_COL_PX)

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
