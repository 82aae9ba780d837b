"""A moving body: a sprite with a velocity, whose exact position is a float box.

Where it sits: the base of :class:`game.sim.player.Player` and :class:`game.sim.enemy.Enemy`;
itself a :class:`~game.sim.sprite.BoxSprite`. Its ``box`` changes only through
:meth:`BoxSprite.place`: by the tick's moves, a platform's push or carry, and
:meth:`Body.teleport` for a respawn or a reload (the five places are listed in
:mod:`game.sim.player`); the drawn ``rect`` is derived from the box whenever it is read.

What it teaches: pygame 2.6 Rects hold integers, so ``rect.x += 0.4`` never moves anything.
The true position is the float :class:`~game.collision.aabb.Box`. A tick's two axis moves
are a :class:`BodyMoves`, which the world hands to whatever needs the path travelled (the
body's own reaction, the probe, the triggers, the overlay): the body is not a mailbox.
"""

from __future__ import annotations

from typing import NamedTuple

from game.collision.aabb import Box
from game.collision.axis_sweep import Edges, Move
from game.collision.shapes import TileKind, TileShape
from game.sim.platforms import Platform
from game.sim.sprite import BoxSprite


class BodyMoves(NamedTuple):
    """One body's moves in one tick: along x, then along y from where that ended."""

    x: Move
    y: Move

    def reach(self) -> Edges:
        """Left, top, right and bottom of all this tick's path: a first, cheap test before
        :meth:`crosses`."""
        left, top, right, bottom = self.x.path_edges
        left_y, top_y, right_y, bottom_y = self.y.path_edges
        # Speed, kept: min and max written as comparisons, as in Move.path_edges.
        return (left_y if left_y < left else left, top_y if top_y < top else top,
                right_y if right_y > right else right, bottom_y if bottom_y > bottom else bottom)

    def crosses(self, region: Box) -> bool:
        """Did this tick's path (the x step, then the y step) overlap ``region``?

        Testing the path, not just the final box, means a fast body cannot skip over a coin
        or a spike in one tick: the trigger version of "sweep every move".
        """
        x, y, w, h = region
        if not (w > 0 and h > 0):
            return False
        right, bottom = x + w, y + h
        for move in self:
            left, top, p_right, p_bottom = move.path_edges  # worked out once per move
            if left < right and x < p_right and top < bottom and y < p_bottom:
                return True
        return False


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

    def teleport(self, box: Box) -> None:
        """Place the body somewhere new (a respawn, a level start)."""
        self.place(box)

    @property
    def dropping_through(self) -> bool:
        """True while the body ignores one-way platforms (the player's down + jump)."""
        return False

    @property
    def on_ground_one_way(self) -> bool:
        return self.standing_on is not None and self.standing_on.kind is TileKind.ONE_WAY

    def react(self, x_move: Move, y_move: Move) -> None:
        """Respond to what this tick's two axis moves hit; subclasses decide how."""
