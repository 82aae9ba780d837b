"""The player: turns held actions into a velocity, and reacts to what its moves hit.

Where it sits: step 1 of a tick chooses the velocity (:meth:`Player.decide`); steps 3-4 move
it (:mod:`game.movement`); :meth:`Player.react` then reads the hits. The player never moves
itself, so there is exactly one place positions change.
"""

from __future__ import annotations

from game.aabb import Box
from game.body import Body
from game.inputs import Action, Actions
from game.movement import Move, Side
from game.tuning import Tuning


class Player(Body):
    """The hero. ``facing`` is +1 (right) or -1 (left), kept for drawing."""

    def __init__(self, box: Box) -> None:
        super().__init__(box)
        self.facing = 1
        self._jump_was_held = False

    def decide(self, held: Actions, tuning: Tuning) -> None:
        """Set the velocity for this tick from the held actions: run, jump, fall."""
        direction = (Action.RIGHT in held) - (Action.LEFT in held)
        self.vx = direction * tuning.run_speed_px_s
        if direction:
            self.facing = direction
        jump_held = Action.JUMP in held
        if jump_held and not self._jump_was_held and self.on_ground:
            self.vy = -tuning.jump_speed_px_s
            self.on_ground = False
        self._jump_was_held = jump_held
        self.vy = min(self.vy + tuning.gravity_px_s2 * tuning.tick_s,
                      tuning.max_fall_speed_px_s)

    def react(self, x_move: Move, y_move: Move) -> None:
        """Stop the velocity on the axis that hit something."""
        if x_move.hit is not None:
            self.vx = 0.0
        if y_move.hit is not None and (
            (y_move.hit.side is Side.BOTTOM and self.vy > 0)
            or (y_move.hit.side is Side.TOP and self.vy < 0)
        ):
            self.vy = 0.0

    def bounce(self, speed_px_s: float) -> None:
        """Spring upwards (after a stomp)."""
        self.vy = -speed_px_s
        self.on_ground = False

    def respawn(self, box: Box) -> None:
        self.teleport(box)
        self.vx = self.vy = 0.0
        self.on_ground = False
