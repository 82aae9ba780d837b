"""A moving body: a sprite with a velocity, whose exact position is a float box.

Where it sits: the base of :class:`game.sim.player.Player` and :class:`game.sim.enemy.Enemy`;
itself a :class:`~game.sim.sprite.BoxSprite`. Only the movement code changes ``box`` (through
:meth:`BoxSprite.place`; the drawn ``rect`` is derived from the box whenever it is read).

What it teaches: pygame 2.6 Rects hold integers, so ``rect.x += 0.4`` never moves anything.
The true position is the float :class:`~game.collision.aabb.Box`, and a body's moves are
recorded (``last_x``, ``last_y``) so that triggers can test the whole path it travelled.
"""

from __future__ import annotations

from game.collision.aabb import Box
from game.sim.movement import Move
from game.sim.platforms import Platform
from game.sim.sprite import BoxSprite
from game.sim.tilegrid import TileKind, TileShape


class Body(BoxSprite):
    """A sprite with a float hitbox, a velocity in px/s and its last two axis moves."""

    def __init__(self, box: Box) -> None:
        super().__init__(box)
        self.vx = 0.0  # px/s, right is positive
        self.vy = 0.0  # px/s, down is positive
        self.on_ground = False
        self.standing_on: TileShape | None = None  # what the ground probe found
        self.riding: Platform | None = None  # the moving platform under the feet, if any
        self.crushed = False  # a platform pushed it into a wall this tick
        self.corner_correction_px = 0.0  # how far a head bump may slide past a corner
        self.last_x: Move | None = None  # recorded for the debug overlay
        self.last_y: Move | None = None

    def teleport(self, box: Box) -> None:
        """Place the body somewhere new with no path behind it (a respawn, a level start)."""
        self.place(box)
        self.last_x = self.last_y = None

    @property
    def dropping_through(self) -> bool:
        """True while the body ignores one-way platforms (the player's down + jump)."""
        return False

    @property
    def on_ground_one_way(self) -> bool:
        return self.standing_on is not None and self.standing_on.kind is TileKind.ONE_WAY

    def react(self, x_move: Move, y_move: Move) -> None:
        """Respond to what this tick's two axis moves hit; subclasses decide how."""

    def reach(self) -> tuple[float, float, float, float]:
        """Left, top, right and bottom of all this tick's path covered (the box itself
        when it made no move): a first, cheap test before :meth:`travelled_through`."""
        last_x, last_y = self.last_x, self.last_y
        if last_x is None or last_y is None:
            paths = [move.path_edges for move in (last_x, last_y) if move is not None]
            if not paths:
                x, y, w, h = self.box
                return (x, y, x + w, y + h)
            return paths[0]
        left, top, right, bottom = last_x.path_edges
        left_y, top_y, right_y, bottom_y = last_y.path_edges
        return (min(left, left_y), min(top, top_y), max(right, right_y), max(bottom, bottom_y))

    def travelled_through(self, region: Box) -> bool:
        """Did this tick's path (the x step, then the y step) overlap ``region``?

        Testing the path, not just the final box, means a fast body cannot skip over a coin
        or a spike in one tick: the trigger version of "sweep every move".
        """
        x, y, w, h = region
        if not (w > 0 and h > 0):
            return False
        right, bottom = x + w, y + h
        last_x, last_y = self.last_x, self.last_y
        if last_x is None and last_y is None:
            return self.box.overlaps(region)
        if last_x is not None:
            left, top, p_right, p_bottom = last_x.path_edges  # worked out once per move
            if left < right and x < p_right and top < bottom and y < p_bottom:
                return True
        if last_y is not None:
            left, top, p_right, p_bottom = last_y.path_edges
            if left < right and x < p_right and top < bottom and y < p_bottom:
                return True
        return False
