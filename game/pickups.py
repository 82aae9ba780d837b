"""Things the player touches rather than collides with: coins, exits and checkpoints.

Where it sits: step 5 of a tick. These are triggers, not solids: they never stop a body,
and they are found with ``pygame.sprite.groupcollide`` / ``spritecollideany`` on their
Rects, the cheapest exact test for a handful of boxes.
"""

from __future__ import annotations

import pygame

from game.aabb import Box


class Coin(pygame.sprite.Sprite):
    """A coin worth ``value`` points."""

    image: pygame.Surface  # a plain box; game.render draws the shared animated art
    rect: pygame.Rect

    def __init__(self, box: Box, value: int) -> None:
        super().__init__()
        self.box = box
        self.rect = box.to_rect()
        self.image = pygame.Surface(self.rect.size)
        self.value = value


class Exit(pygame.sprite.Sprite):
    """Touching it completes the level."""

    image: pygame.Surface
    rect: pygame.Rect

    def __init__(self, box: Box) -> None:
        super().__init__()
        self.box = box
        self.rect = box.to_rect()
        self.image = pygame.Surface(self.rect.size)


class Checkpoint(pygame.sprite.Sprite):
    """Touching it moves the player's respawn point here."""

    image: pygame.Surface
    rect: pygame.Rect

    def __init__(self, box: Box) -> None:
        super().__init__()
        self.box = box
        self.rect = box.to_rect()
        self.image = pygame.Surface(self.rect.size)
