"""A sprite whose truth is a float box: its picture is drawn where the box says, never elsewhere.

Where it sits: the base of everything in a level that is drawn: the player and enemies
(:mod:`game.sim.body`), coins, exits and checkpoints (:mod:`game.sim.pickups`), moving
platforms (:mod:`game.sim.platforms`) and squashed enemies (:mod:`game.sim.enemy`). The
tick moves boxes; before a frame is drawn, the app hands each sprite its pictures once
(:meth:`BoxSprite.dress`) and calls :meth:`BoxSprite.update`; a camera-aware group
(:class:`game.app.render.CameraGroup`) then blits every ``image`` at its ``rect``.

What it teaches:
  * **Float box, derived Rect, in one place.** pygame 2.6 Rects hold integers, so the exact
    position is the float :class:`~game.collision.aabb.Box`, and :attr:`BoxSprite.rect` is
    the one place the drawn rectangle is derived from it (``math.floor``, inside
    ``Box.to_rect``). It is worked out when read and kept until the box or the picture
    changes, so the picture can never lag the box ("ghost rects"), and a tick that nobody
    draws (headless, tests, the bench) never pays for it.
  * **``image`` and ``rect`` are what is drawn.** ``Group.draw`` blits ``image`` at
    ``rect.topleft``, so ``rect`` is the picture's rectangle, not the hitbox. The art may
    be bigger than the box (hair, ears, a flag's pole); the sprite's :class:`Anchor` says
    how picture and box line up: feet on the box's bottom, centred, or filling it.
  * **Animation is drawing, not simulation.** :meth:`update` picks a frame from the
    sprite's own state (on the ground? facing left?) and the frame count; it changes only
    ``image`` and ``rect``, never where anything is or what it does next. The simulation
    never calls it, and without pictures (headless, tests) a sprite is a plain box.

>>> sprite = BoxSprite(Box(10.5, 20.25, 12, 14))
>>> sprite.rect                                # no pictures yet: the box itself, floored
<rect(10, 20, 12, 14)>
>>> sprite.dress(Strip.of([pygame.Surface((16, 16))]))
>>> sprite.update(0)
>>> sprite.rect                                # a 16x16 picture standing on the box's bottom
<rect(8, 18, 16, 16)>
>>> sprite.place(Box(30.0, 20.25, 12, 14))      # the rect follows when next read
>>> sprite.rect.topleft
(28, 18)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum
from typing import Any

import pygame

from game.collision.aabb import Box

ANIMATION_HZ = 60  # the frame count passed to ``update`` advances this many times a second


def animation_index(frame: int, fps: int, frames: Sequence[int], phase: int = 0) -> int:
    """The strip frame to show at ``frame`` for a loop of ``frames`` played at ``fps``.

    >>> [animation_index(f, 8, (2, 3, 4, 5)) for f in (0, 7, 8, 15, 23, 30)]
    [2, 2, 3, 4, 5, 2]
    """
    step = frame * fps // ANIMATION_HZ + phase
    return frames[step % len(frames)]


class Anchor(Enum):
    """How a picture sits on its box."""

    BOTTOM_CENTRE = "bottom-centre"  # its bottom on the box's bottom, centred across
    CENTRE = "centre"                # centred both ways
    TOP_LEFT = "top-left"            # its top-left corner on the box's (a picture the box's size)


def anchored_box(box: Box, size: tuple[int, int], anchor: Anchor) -> Box:
    """Where a picture of ``size`` goes on ``box``, in exact (float) map pixels.

    >>> anchored_box(Box(10, 20, 12, 14), (16, 16), Anchor.BOTTOM_CENTRE)
    Box(x=8.0, y=18, w=16, h=16)
    >>> anchored_box(Box(10, 20, 12, 12), (8, 8), Anchor.CENTRE)
    Box(x=12.0, y=22.0, w=8, h=8)
    """
    w, h = size
    x, y, box_w, box_h = box
    if anchor is Anchor.TOP_LEFT:
        return Box(x, y, w, h)
    left = x + (box_w - w) / 2
    top = y + box_h - h if anchor is Anchor.BOTTOM_CENTRE else y + (box_h - h) / 2
    return Box(left, top, w, h)


@dataclass(frozen=True)
class Strip:
    """A sprite's pictures: its frames facing right, the same mirrored, and a blank one.

    The mirrored frames are made once here, not flipped again every frame; the blank one
    (fully transparent, the size of the first frame) is what a blinking sprite shows.
    """

    right: tuple[pygame.Surface, ...]
    left: tuple[pygame.Surface, ...]
    blank: pygame.Surface

    @classmethod
    def of(cls, frames: Sequence[pygame.Surface]) -> Strip:
        if not frames:
            raise ValueError("a strip needs at least one frame")
        blank = pygame.Surface(frames[0].get_size(), pygame.SRCALPHA)
        return cls(tuple(frames),
                   tuple(pygame.transform.flip(frame, True, False) for frame in frames), blank)

    def frame(self, index: int, facing: int = 1) -> pygame.Surface:
        """Frame ``index``, mirrored when ``facing`` is negative (towards the left)."""
        return (self.left if facing < 0 else self.right)[index]


class BoxSprite(pygame.sprite.Sprite):
    """A sprite at a float ``box``, drawn as ``image`` at ``rect`` (derived from the two)."""

    image: pygame.Surface
    anchor = Anchor.BOTTOM_CENTRE

    def __init__(self, box: Box) -> None:
        super().__init__()
        self.strip: Strip | None = None  # the pictures, once the app has handed them over
        self.box = box
        self.image = pygame.Surface((max(1, math.ceil(box.w)), max(1, math.ceil(box.h))))
        self._fitted: tuple[Box, pygame.Surface] | None = None  # what ``_rect`` was made for
        self._rect = pygame.Rect(0, 0, 0, 0)

    def place(self, box: Box) -> None:
        """Set the exact position; the picture follows (``rect`` is derived when read)."""
        self.box = box

    def show(self, image: pygame.Surface) -> None:
        """Draw ``image`` from now on, anchored on the box."""
        self.image = image

    @property
    def rect(self) -> pygame.Rect:
        """The one place ``rect`` is derived: the picture's rectangle anchored on the box,
        worked out again only when the box or the picture is a new one."""
        box, image = self.box, self.image
        fitted = self._fitted
        if fitted is None or fitted[0] is not box or fitted[1] is not image:
            self._rect = anchored_box(box, image.get_size(), self.anchor).to_rect()
            self._fitted = (box, image)
        return self._rect

    @rect.setter
    def rect(self, rect: pygame.Rect) -> None:
        """Draw at ``rect`` until the box or the picture changes (pygame's groups may set it)."""
        self._rect = rect
        self._fitted = (self.box, self.image)

    def dress(self, strip: Strip) -> None:
        """Take the pictures to draw with (the app does this once, before the first frame)."""
        self.strip = strip

    def update(self, frame: int = 0, *args: Any, **kwargs: Any) -> None:
        """Show the picture for animation frame ``frame`` (drawing only: nothing moves)."""
        if self.strip is not None:
            self.show(self.frame_image(self.strip, frame))

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        """Which picture to show at ``frame``; a single still picture unless overridden."""
        return strip.frame(0)
