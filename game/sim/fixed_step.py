"""The fixed-step game loop: real time in, whole 1/60 s ticks out.

Where it sits: in the windowed app, between the clock and :meth:`Campaign.tick`.

What it teaches (Nystrom's *Game Programming Patterns*, "Game Loop"): the simulation always
advances by the same ``tick_s``, whatever the frame rate, so it behaves the same on every
machine and in every replay. Real time is banked in an accumulator and paid out in ticks.
Two guards keep a stall harmless: a frame is clamped to ``max_frame_s``, and at most
``max_ticks_per_frame`` ticks run per frame (the rest of the backlog is dropped), so the game
slows down instead of freezing in a "spiral of death". Because every tick sweeps its moves,
even a clamped catch-up never carries a body through a wall.

>>> clock = FixedStep()
>>> clock.advance(1 / 60)
1
>>> clock.advance(5.0)          # a 5-second stall: clamped, capped, backlog dropped
5
>>> clock.advance(0.0)
0
"""

from __future__ import annotations

from dataclasses import dataclass

from game.sim.tuning import TICK_S


@dataclass
class FixedStep:
    tick_s: float = TICK_S
    max_frame_s: float = 0.25
    max_ticks_per_frame: int = 5
    accumulator_s: float = 0.0

    def advance(self, frame_s: float) -> int:
        """Bank ``frame_s`` seconds of real time; return how many ticks to run now."""
        if not frame_s > 0:  # also refuses NaN
            return 0
        self.accumulator_s += min(frame_s, self.max_frame_s)
        ticks = int(self.accumulator_s / self.tick_s + 1e-9)
        if ticks > self.max_ticks_per_frame:
            ticks = self.max_ticks_per_frame
            self.accumulator_s = 0.0
        else:
            self.accumulator_s = max(0.0, self.accumulator_s - ticks * self.tick_s)
        return ticks
