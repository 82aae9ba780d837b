"""The player: turns held actions into a velocity, and reacts to what its moves hit.

Where it sits: step 1 of a tick chooses the velocity (:meth:`Player.decide`); steps 3-4
move it (:func:`game.collision.axis_sweep.move_body`); :meth:`Player.react` then reads the
hits. The player only ever chooses a velocity; its box changes in five places, each through
:meth:`~game.sim.sprite.BoxSprite.place`: the x and y passes of a tick (steps 3-4 of
:meth:`~game.sim.world.World.step`), a moving platform's push and its carry (step 2,
``World._move_platform``), a respawn after a lost life (step 9, :meth:`Player.respawn`) and
a reload of the map that keeps the player where it stood
(:meth:`~game.sim.campaign.Campaign.reload`, for ``--watch``).

What it teaches: the forgiving rules that make a platformer feel good, each a tunable in
:class:`game.sim.tuning.Tuning` (the drop's length is :data:`DROP_THROUGH_TICKS`, below) and
a test in ``tests/test_feel.py``, with its number pinned at its edge in ``tests/test_edges.py``:

* **Acceleration and friction**: the run speed approaches its target at a rate derived from
  a time to full speed (quicker on the ground than in the air).
* **Variable jump height**: letting go of jump while rising cuts the upward speed.
* **Coyote time**: a jump pressed a few ticks after running off a ledge still happens.
* **Jump buffering**: a jump pressed a few ticks before landing happens on landing.
* **Drop through**: down + jump on a one-way platform falls through it (not where the feet
  are partly on a Solid at the same height: that is an ordinary jump).
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.axis_sweep import Move, Side
from game.sim.body import Body
from game.sim.inputs import Action, Actions
from game.sim.sprite import ANIMATION_HZ, Strip, animation_index
from game.sim.tuning import Tuning

DROP_THROUGH_TICKS = 8  # how long one-way platforms are ignored after down + jump

# The player's strip (assets/README.md): 0-1 idle, 2-5 run, 6 jump, 7 fall; facing right.
IDLE_FPS = 2
IDLE_FRAMES = (0, 1)
RUN_FPS = 12
RUN_FRAMES = (2, 3, 4, 5)
JUMP_FRAME = 6  # rising
FALL_FRAME = 7
BLINK_HZ = 10  # while invulnerable after a hit, the player flickers at this rate


def approach(value: float, target: float, step: float) -> float:
    """Move ``value`` towards ``target`` by at most ``step``.

    >>> approach(0.0, 90.0, 30.0), approach(80.0, 90.0, 30.0), approach(10.0, 0.0, 30.0)
    (30.0, 90.0, 0.0)
    """
    if value < target:
        return min(value + step, target)
    return max(value - step, target)


def run_change_px_s(tuning: Tuning, on_ground: bool, speeding_up: bool) -> float:
    """How much the run speed may change in one tick (px/s), from the tuning's times.

    Rates are derived from the run speed, so a level that sets ``run_speed`` very high or
    very low keeps the same feel: full speed in the same number of ticks.
    """
    if on_ground:
        seconds = tuning.run_accel_time_s if speeding_up else tuning.run_stop_time_s
    else:
        seconds = tuning.air_accel_time_s if speeding_up else tuning.air_stop_time_s
    if seconds <= 0:
        return float("inf")
    return tuning.run_speed_px_s * tuning.tick_s / seconds


class Player(Body):
    """The hero. ``facing`` is +1 (right) or -1 (left), kept for drawing."""

    def __init__(self, box: Box, tuning: Tuning) -> None:
        super().__init__(box)
        self.corner_correction_px = tuning.corner_correction_px
        self.coyote_ticks = tuning.coyote_ticks            # the forgiving edges of a jump,
        self.jump_buffer_ticks = tuning.jump_buffer_ticks  # in ticks, from the tuning's times
        self.facing = 1
        self.coyote_ticks_left = 0       # ticks in which a jump still counts as from the ground
        self.jump_buffer_ticks_left = 0  # ticks in which an early jump press is remembered
        self.rising_from_jump = False    # a jump is under way and may still be cut short
        self.drop_ticks_left = 0         # ticks one-way platforms are ignored
        self.invulnerable_ticks_left = 0
        self._jump_was_held = False

    @property
    def invulnerable(self) -> bool:
        return self.invulnerable_ticks_left > 0

    def decide(self, held: Actions, tuning: Tuning) -> bool:
        """Set the velocity for this tick from the held actions; True if a jump started."""
        # Run: approach the target speed at the ground or air rate.
        direction = (Action.RIGHT in held) - (Action.LEFT in held)
        target = direction * tuning.run_speed_px_s
        speeding_up = direction != 0 and (self.vx * direction >= 0)
        self.vx = approach(self.vx, target, run_change_px_s(tuning, self.on_ground, speeding_up))
        if direction:
            self.facing = direction

        # Jump timers: the buffer remembers a press, coyote time remembers the ground.
        jump_held = Action.JUMP in held
        pressed = jump_held and not self._jump_was_held
        self._jump_was_held = jump_held
        self.jump_buffer_ticks_left = (self.jump_buffer_ticks + 1 if pressed
                                       else max(0, self.jump_buffer_ticks_left - 1))
        self.coyote_ticks_left = (self.coyote_ticks + 1 if self.on_ground
                                  else max(0, self.coyote_ticks_left - 1))
        self.drop_ticks_left = max(0, self.drop_ticks_left - 1)
        self.invulnerable_ticks_left = max(0, self.invulnerable_ticks_left - 1)

        jumped = False
        if pressed and Action.DOWN in held and self.on_ground_one_way:
            self.drop_ticks_left = DROP_THROUGH_TICKS
            self.jump_buffer_ticks_left = 0
        elif self.jump_buffer_ticks_left and self.coyote_ticks_left:
            self.vy = -tuning.jump_speed_px_s
            self.on_ground = False
            self.rising_from_jump = True
            self.jump_buffer_ticks_left = self.coyote_ticks_left = 0
            jumped = True
        self.dropping_through = self.drop_ticks_left > 0

        # Variable height: releasing jump while rising keeps only part of the speed.
        if self.rising_from_jump and (self.vy >= 0 or not jump_held):
            if self.vy < 0:
                self.vy *= tuning.jump_cut_ratio
            self.rising_from_jump = False

        self.vy = min(self.vy + tuning.gravity_px_s2 * tuning.tick_s,
                      tuning.max_fall_speed_px_s)
        return jumped

    def react(self, x_move: Move, y_move: Move) -> None:
        """Stop the velocity on the axis that hit something."""
        if x_move.hit is not None:
            self.vx = 0.0
        if y_move.hit is not None and (
            (y_move.hit.side is Side.BOTTOM and self.vy > 0)
            or (y_move.hit.side is Side.TOP and self.vy < 0)
        ):
            self.vy = 0.0
            self.rising_from_jump = False

    def bounce(self, speed_px_s: float) -> None:
        """Spring upwards (after a stomp)."""
        self.vy = -speed_px_s
        self.on_ground = False
        self.rising_from_jump = False

    def respawn(self, box: Box, invulnerable_ticks: int = 0) -> None:
        self.teleport(box)
        self.vx = self.vy = 0.0
        self.on_ground = False
        self.rising_from_jump = False
        self.coyote_ticks_left = self.jump_buffer_ticks_left = 0
        self.invulnerable_ticks_left = invulnerable_ticks

    def frame_image(self, strip: Strip, frame: int) -> pygame.Surface:
        """Jump or fall in the air, run or idle on the ground; flickering while invulnerable."""
        if self.invulnerable and (frame * 2 * BLINK_HZ // ANIMATION_HZ) % 2 == 1:
            return strip.blank
        if not self.on_ground:
            index = JUMP_FRAME if self.vy < 0 else FALL_FRAME
        elif self.vx != 0:
            index = animation_index(frame, RUN_FPS, RUN_FRAMES)
        else:
            index = animation_index(frame, IDLE_FPS, IDLE_FRAMES)
        return strip.frame(index, self.facing)
