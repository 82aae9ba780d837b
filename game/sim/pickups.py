"""Things the player touches rather than collides with: coins, exits and checkpoints.

Where it sits: steps 6 and 7 of a tick (:meth:`game.sim.world.World.step`). These are triggers,
not solids: they never stop a body. Coins are taken with ``pygame.sprite.groupcollide``;
exits and checkpoints go through the contact tracker, which reports when a touch starts.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box


class Trigger(pygame.sprite.Sprite):
    """A box the player can touch: it has a Rect for ``groupcollide`` and never blocks."""

    image: pygame.Surface  # a plain box; game.app.render draws the shared art
    rect: pygame.Rect

    def __init__(self, box: Box) -> None:
        super().__init__()
        self.box = box
        self.rect = box.to_rect()
        self.image = pygame.Surface(self.rect.size)


class Coin(Trigger):
    """A coin worth ``value`` points."""

    def __init__(self, box: Box, value: int) -> None:
        super().__init__(box)
        self.value = value


class Exit(Trigger):
    """Touching it completes the level."""


class Checkpoint(Trigger):
    """Touching it moves the player's respawn point here."""
