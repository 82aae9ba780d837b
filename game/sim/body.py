"""A moving body: a sprite with a velocity, whose exact position is a float box.

Where it sits: the base of :class:`game.sim.player.Player` and :class:`game.sim.enemy.Enemy`;
itself a :class:`~game.sim.sprite.BoxSprite`. Its ``box`` changes only through
:meth:`BoxSprite.place`: by the tick's moves, a platform's push or carry, and
:meth:`Body.teleport` for a respawn or a reload (the five places are listed in
:mod:`game.sim.player`); the drawn ``rect`` is derived from the box whenever it is read.

What it teaches: pygame 2.6 Rects hold integers, so ``rect.x += 0.4`` never moves anything.
The true position is the float :class:`~game.collision.aabb.Box`. A tick's two axis moves
are a :class:`~game.collision.axis_sweep.BodyMoves`, which the world hands to whatever needs
the path travelled (the body's own reaction, the triggers, the overlay): the body is not a
mailbox.
"""

from __future__ import annotations

from game.collision.aabb import Box
from game.collision.axis_sweep import Move
from game.collision.shapes import TileKind, TileShape
from game.sim.platforms import Platform
from game.sim.sprite import BoxSprite


class Body(BoxSprite):
    """A sprite with a float hitbox and a velocity in px/s."""

    def __init__(self, box: Box) -> None:
        super().__init__(box)
        self.vx = 0.0  # px/s, right is positive
        self.vy = 0.0  # px/s, down is positive
        self.on_ground = False
        self.standing_on: TileShape | None = None  # what the ground probe found
        self.riding: Platform | None = None  # the moving platform under the feet, if any
        self.crushed = False  # a platform pushed it into a wall this tick
        self.corner_correction_px = 0.0  # how far a head bump may slide past a corner
        self.dropping_through = False  # ignoring one-way platforms (the player's down + jump)

    def teleport(self, box: Box) -> None:
        """Place the body somewhere new (a respawn, a level start)."""
        self.place(box)

    @property
    def on_ground_one_way(self) -> bool:
        return self.standing_on is not None and self.standing_on.kind is TileKind.ONE_WAY

    def react(self, x_move: Move, y_move: Move) -> None:
        """Respond to what this tick's two axis moves hit; subclasses decide how."""
