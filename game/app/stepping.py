"""Step through a tick: freeze the simulation, advance it one tick at a time, or slow it down.

Where it sits: in the window's frame loop (:mod:`game.app.window`), between reading the
events and running the ticks; it decides how many ticks a frame runs. It works only while
the debug overlay is on, and the overlay lists its keys and says when play is frozen or slow.

What it teaches: because the simulation advances in whole fixed ticks
(:mod:`game.sim.fixed_step`), "one step" is well defined: F3 runs exactly one
:meth:`~game.sim.world.World.step`, so a reader can watch a sweep stop flush at a wall, a
stomp, or a corner correction happen one tick at a time, with the overlay showing what that
tick tested. Quarter speed banks a quarter of each frame's real time, so ticks come at
15 a second and the game plays exactly as it would at full speed, only slower.

>>> control = TickControl()
>>> control.press(FREEZE_KEY, overlay_on=True)
True
>>> [control.ticks_due(FixedStep(), 1 / 60, overlay_on=True) for _ in range(3)]
[0, 0, 0]
>>> control.press(STEP_KEY, overlay_on=True), control.press(STEP_KEY, overlay_on=True)
(True, True)
>>> control.ticks_due(FixedStep(), 1 / 60, overlay_on=True)
2
"""

from __future__ import annotations

from dataclasses import dataclass

import pygame

from game.sim.fixed_step import FixedStep

FREEZE_KEY = pygame.K_F2  # freeze or unfreeze the simulation
STEP_KEY = pygame.K_F3  # run exactly one tick (freezing first if need be)
SLOW_KEY = pygame.K_F4  # quarter speed on or off
SLOW_SPEED = 0.25  # the fraction of real time a slowed game plays at


def key_label(key: int) -> str:
    """How a key is written in the README and the overlay.

    >>> key_label(FREEZE_KEY), key_label(STEP_KEY), key_label(SLOW_KEY)
    ('F2', 'F3', 'F4')
    """
    return pygame.key.name(key).upper()


@dataclass
class TickControl:
    """Frozen or running, full or quarter speed, and the single ticks asked for."""

    frozen: bool = False
    slow: bool = False
    steps_asked: int = 0  # F3 presses since the last frame's ticks

    def press(self, key: int, *, overlay_on: bool) -> bool:
        """React to a key press; True if it was one of the stepping keys (and the overlay
        is on, without which they do nothing)."""
        if not overlay_on or key not in (FREEZE_KEY, STEP_KEY, SLOW_KEY):
            return False
        if key == FREEZE_KEY:
            self.frozen = not self.frozen
            self.steps_asked = 0
        elif key == STEP_KEY:
            self.frozen = True
            self.steps_asked += 1
        else:
            self.slow = not self.slow
            self.frozen = False
        return True

    def ticks_due(self, stepper: FixedStep, frame_s: float, *, overlay_on: bool) -> int:
        """How many ticks this frame runs. With the overlay off, play is always normal."""
        if not overlay_on:
            self.frozen = self.slow = False
            self.steps_asked = 0
        if self.frozen:
            stepper.advance(0.0)  # no real time is banked while frozen
            steps, self.steps_asked = self.steps_asked, 0
            return steps
        return stepper.advance(frame_s * (SLOW_SPEED if self.slow else 1.0))

    def lines(self, tick: int) -> tuple[str, ...]:
        """What the overlay says about stepping: the state, then the keys."""
        state = (f"frozen at tick {tick}" if self.frozen
                 else f"speed x{SLOW_SPEED:g}" if self.slow else "running")
        return (state, f"{key_label(FREEZE_KEY)} freeze {key_label(STEP_KEY)} step "
                       f"{key_label(SLOW_KEY)} slow")
