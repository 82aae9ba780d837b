"""``python -m game.bench.drawing``: what a frame costs to draw, beside the tick it shows.

Where it sits: beside the bench's charts, on its own (it opens a display, headless through
SDL's dummy driver). It plays the level :mod:`game.bench.game_step` plays (the largest
shipped level with a winning input script) to its exit, and in every tick times, one
after the other: the tick itself, the frame (:class:`game.app.render.WorldRenderer` and the
HUD), and the debug overlay on top of it (:func:`game.app.debug_overlay.draw_debug`).

What it teaches: **compare side by side, report ratios.** All three are timed in the same
ticks, so a busy machine slows them alike; the medians and their ratios are what it prints.
The frame is cheap because the static tile layers are cached (each frame blits a few chunks)
and the sprites draw from their own ``image`` and ``rect``; the overlay is meant to cost no
more than the frame it sits on.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from statistics import median
from time import perf_counter

import pygame

from game.app.arguments import Parser, run_command, whole_number
from game.app.assets import load_assets
from game.app.debug_overlay import draw_debug
from game.app.hud import draw_hud
from game.app.render import WorldRenderer
from game.app.run import input_script
from game.bench.game_step import level_to_play
from game.bench.timing import collector_off
from game.levels import load_level
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Campaign, Outcome
from game.sim.world import Measure

MS_PER_S = 1000.0
MAX_TICKS = 60 * 60 * 60  # an hour of game time: the measured level ends long before
OVERLAY_FPS = 60.0  # the frame rate the overlay's panel is told (it only prints it)


@dataclass(frozen=True)
class DrawingCost:
    """Median milliseconds per tick of each part, over ``ticks`` ticks of ``level``."""

    level: str
    ticks: int
    tick_ms: float
    frame_ms: float
    overlay_ms: float

    def lines(self) -> list[str]:
        return [f"{self.level}, {self.ticks} ticks, medians per tick:",
                f"  tick     {self.tick_ms:.3f} ms  (keeping the overlay's query log)",
                f"  frame    {self.frame_ms:.3f} ms  (world and HUD)",
                f"  overlay  {self.overlay_ms:.3f} ms",
                f"  overlay / frame {self.overlay_ms / self.frame_ms:.2f}x, "
                f"frame / tick {self.frame_ms / self.tick_ms:.2f}x"]


def measure(max_ticks: int | None = None) -> DrawingCost:
    """Play the level to its end (or ``max_ticks``), timing tick, frame and overlay."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")  # no window needed
    pygame.display.init()
    pygame.font.init()
    target = pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    level_path, script_path = level_to_play()
    assets = load_assets()
    renderer = WorldRenderer(assets)
    # As in the window with the overlay on: the tick keeps the query log the overlay draws.
    campaign = Campaign(level_path, loader=lambda path: load_level(path, images=True),
                        measure=Measure(queries=True))
    script = input_script(script_path)
    ticks, frames, overlays = [], [], []
    with collector_off():
        while campaign.outcome is Outcome.RUNNING and (max_ticks is None
                                                       or campaign.ticks < max_ticks):
            started = perf_counter()
            campaign.tick(script.held_at(campaign.ticks))
            drawn = perf_counter()
            renderer.draw(target, campaign.world, campaign.ticks)
            draw_hud(target, campaign, assets)
            overlaid = perf_counter()
            draw_debug(target, campaign.world, assets, OVERLAY_FPS, 0.0)
            done = perf_counter()
            ticks.append(drawn - started)
            frames.append(overlaid - drawn)
            overlays.append(done - overlaid)
            if campaign.world.level.path != level_path:
                break  # the exit: the next level is not part of this measurement
    pygame.display.quit()
    return DrawingCost(level_path.name, len(ticks), median(ticks) * MS_PER_S,
                       median(frames) * MS_PER_S, median(overlays) * MS_PER_S)


def main(argv: list[str] | None = None) -> int:
    """``python -m game.bench.drawing``: checked numbers, Ctrl-C and a closed standard
    output each end it with a status, as every command does (:func:`run_command`)."""
    return run_command(lambda: _main(argv))


def _main(argv: list[str] | None) -> int:
    parser = Parser(prog="python -m game.bench.drawing",
                    description="Time a frame, its overlay and its tick.")
    parser.add_argument("--ticks", type=whole_number(1, MAX_TICKS, "ticks"), default=None,
                        metavar="N", help="stop after this many ticks")
    args = parser.parse_args(argv)
    print("\n".join(measure(args.ticks).lines()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
