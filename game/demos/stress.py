"""``python -m game.demos.stress``: thousands of crates, and the broad phase the scene picks for
them.

Where it sits: a demo beside the game, like :mod:`game.demos.crates`, which it drives. It builds a
crate scene big enough for the crowd (the arena grows with the count), lets
:mod:`game.collision.methods` choose the broad phase, steps it, and prints what the choice cost per
tick: pair tests, against the ``n(n-1)/2`` brute force would make. ``--screenshot`` draws
the scene with the method named on it.

What it teaches: **model no more than a scene needs.** Eight crates get brute force;
two thousand get a spatial grid, and test a few thousand pairs a tick instead of two million.

>>> small, crowd = run(8, ticks=3), run(2000, ticks=3)
>>> small.method, crowd.method
('BruteForce', 'SpatialGrid')
>>> small.pair_tests == 8 * 7 // 2
True
>>> crowd.pair_tests < crowd.brute_force_tests // 100
True
"""

from __future__ import annotations

import argparse
import math
import statistics
import sys
from dataclasses import dataclass
from pathlib import Path

from game.app.arguments import Parser, run_command, whole_number
from game.app.files import FileProblem, output_problem, save_image
from game.demos.crates import CrateScene, CrateTuning
from game.sim.tuning import TICK_S

MAX_CRATES = 20_000  # about 80 MB and 0.15 s a tick on one core here; more is a typo
MAX_TICKS = 100_000
EXIT_BAD_FILE = 1
ARENA_PX_PER_CRATE = 48.0 * 48.0  # room per crate, so a crowd has space to move
ASPECT = 16 / 9


@dataclass(frozen=True)
class StressResult:
    """What a stress run chose and did, per tick (the median over the run)."""

    crates: int
    method: str
    pair_tests: int
    brute_force_tests: int
    hits: int


def scene_for(crates: int, seed: int = 1) -> CrateScene:
    area = crates * ARENA_PX_PER_CRATE
    height = max(180.0, math.sqrt(area / ASPECT))
    tuning = CrateTuning(arena_w_px=height * ASPECT, arena_h_px=height, crate_count=crates)
    return CrateScene.random(seed=seed, tuning=tuning)


def run(crates: int, ticks: int, seed: int = 1) -> StressResult:
    scene = scene_for(crates, seed)
    tests, hits = [], 0
    for _ in range(ticks):
        report = scene.step(TICK_S)
        tests.append(report.work.pair_tests)
        hits += report.crate_hits
    return StressResult(crates, type(scene.broad_phase).__name__,
                        int(statistics.median(tests)), crates * (crates - 1) // 2, hits)


def screenshot(scene: CrateScene, path: Path) -> None:
    """Draw ``scene`` and save it at ``path`` through the one atomic write
    (:func:`game.app.files.save_image`); a FileProblem if it cannot be written."""
    import os

    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    import pygame

    pygame.font.init()
    surface = pygame.Surface((round(scene.arena.w), round(scene.arena.h)))
    surface.fill((24, 26, 40))
    for crate in scene.crates.values():
        pygame.draw.rect(surface, (214, 160, 90), crate.box.to_rect())
        pygame.draw.rect(surface, (90, 60, 30), crate.box.to_rect(), width=1)
    label = f"{len(scene.crates)} crates: {type(scene.broad_phase).__name__}"
    surface.blit(pygame.font.Font(None, 28).render(label, True, (255, 255, 255)), (8, 8))
    save_image(surface, path)


def main(argv: list[str] | None = None) -> int:
    return run_command(lambda: _main(argv))


def _main(argv: list[str] | None) -> int:
    parser = Parser(prog="python -m game.demos.stress", description=__doc__,
                    formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--crates", type=whole_number(1, MAX_CRATES, "crates"), nargs="+",
                        default=[8, 100, 2000], metavar="N")
    parser.add_argument("--ticks", type=whole_number(1, MAX_TICKS, "ticks"), default=60,
                        metavar="N")
    parser.add_argument("--screenshot", type=Path, help="draw the last scene to this PNG")
    args = parser.parse_args(argv)
    if args.screenshot and (problem := output_problem(args.screenshot)) is not None:
        parser.error(f"--screenshot: {problem}")
    for count in args.crates:
        result = run(count, args.ticks)
        print(f"{count:6d} crates: {result.method:12s} {result.pair_tests:9,d} pair tests "
              f"a tick (brute force: {result.brute_force_tests:,d})")
    if args.screenshot:
        scene = scene_for(args.crates[-1])
        for _ in range(args.ticks):
            scene.step(TICK_S)
        try:
            screenshot(scene, args.screenshot)
        except FileProblem as error:
            print(error, file=sys.stderr)
            return EXIT_BAD_FILE
    return 0


if __name__ == "__main__":
    sys.exit(main())
