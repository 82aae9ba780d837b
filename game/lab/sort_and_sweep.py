"""Scene ``sort-and-sweep``: sort by left edge, sweep left to right, test only the x overlaps.

What it shows: a row of bodies drifting along x, kept sorted by a
:class:`~game.collision.broad.sort_and_sweep.SortAndSweep` (their order is numbered above
them). Move the mouse: the vertical line is the sweep line, and the bodies whose x interval
it crosses (the structure's own :meth:`~game.collision.broad.sort_and_sweep.SortAndSweep.query`
of a one-pixel strip) are the active list at that x. Their x intervals are drawn along the
bottom. The panel sets the sweep's pair tests against brute force's n(n-1)/2; S stacks every
body into one column, the worst case, where the sweep tests nearly every pair.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.broad.brute_force import BruteForce
from game.collision.broad.sort_and_sweep import SortAndSweep
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.crowd import Crowd, CrowdScene
from game.lab.scene import AREA, Control, Layer

BODIES = 24
SWEEP_AREA = Box(AREA.x + 8, AREA.y + 40, AREA.w - 16, AREA.h - 150)
AXIS_Y = AREA.bottom - 90
COLUMN_X = AREA.x + 290.0


class SortAndSweepScene(CrowdScene):
    name = "sort-and-sweep"
    title = "sort and sweep: test only boxes that meet on x"
    keys_help = "move the mouse: sweep line; S stack into a column; drag bodies"
    group = "broad phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.CONTACTS, Layer.CELLS)

    def reset(self) -> None:
        self.crowd = Crowd.random(5, BODIES, SWEEP_AREA, (14.0, 34.0), 30.0)
        self.sweep: SortAndSweep[int] = SortAndSweep()
        for key, box in self.crowd.boxes.items():
            self.sweep.insert(key, box)
        self.stacked = False
        self.meter = CostMeter(repeats=4)
        self.mouse = (AREA.x + 200.0, AREA.y + 100.0)

    def controls(self) -> list[Control]:
        return [Control(f"stacked in one column: {'yes' if self.stacked else 'no'}",
                        (pygame.K_s,))]

    def on_key(self, key: int) -> None:
        if key == pygame.K_s:
            self.stacked = not self.stacked
            for number, box in self.crowd.boxes.items():
                x = COLUMN_X if self.stacked else SWEEP_AREA.x + number * (SWEEP_AREA.w / BODIES)
                self.crowd.boxes[number] = box._replace(x=x)

    def refresh(self) -> None:
        for key, box in self.crowd.boxes.items():
            self.sweep.move(key, box)
        self.sweep.stats.reset()
        self.pairs = self.sweep.pairs()
        tests = self.sweep.stats.pair_tests
        brute: BruteForce[int] = BruteForce()
        for key, box in self.crowd.boxes.items():
            brute.insert(key, box)
        same = brute.pairs() == self.pairs
        brute_tests, n = brute.stats.pair_tests, len(self.crowd.boxes)
        self.active = self.sweep.query(Box(self.mouse[0], AREA.top, 1, AREA.h))
        self.order = sorted(self.crowd.boxes, key=lambda k: (self.crowd.boxes[k].left, k))
        self.meter.time("sort and sweep, all pairs", self.sweep.pairs)
        self.meter.time("brute force, all pairs", brute.pairs)
        self.lines = [
            f"bodies: {len(self.crowd.boxes)}" + ("  (stacked: worst case)" if self.stacked
                                                  else ""),
            f"sort and sweep: {tests} pair tests",
            f"brute force: {brute_tests} tests = n(n-1)/2 = {n * (n - 1) // 2}",
            f"pairs found: {len(self.pairs)}; same as brute force: {'yes' if same else 'NO'}",
            f"active at x = {self.mouse[0]:.0f}: {len(self.active)} bodies",
            "the sweep's pairs take "
            f"{self.meter.times('sort and sweep, all pairs', 'brute force, all pairs')}"
            " brute force's",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        if Layer.CELLS in layers:
            pygame.draw.line(surface, canvas.BOUNDS, (self.mouse[0], AREA.top),
                             (self.mouse[0], AREA.bottom), 1)
            pygame.draw.line(surface, canvas.DIM, (AREA.left, AXIS_Y), (AREA.right, AXIS_Y))
            canvas.text(surface, "x intervals, in sorted order", (AREA.x + 8, AXIS_Y - 20),
                        canvas.DIM, 18)
        for rank, key in enumerate(self.order):
            box = self.crowd.boxes[key]
            active = key in self.active
            if Layer.SHAPES in layers:
                canvas.box(surface, box, canvas.MOVER if active else canvas.STILL)
                canvas.text(surface, str(rank + 1), (round(box.x), round(box.y) - 16),
                            canvas.DIM, 16)
            if Layer.BOUNDS in layers:
                y = AXIS_Y + 4 + (rank % 20) * 4
                pygame.draw.line(surface, canvas.MOVER if active else canvas.BOUNDS,
                                 (box.left, y), (box.right, y), 3)
        if Layer.CONTACTS in layers:
            for a, b in self.pairs:
                canvas.box(surface, self.crowd.boxes[a], canvas.EXACT, 2)
                canvas.box(surface, self.crowd.boxes[b], canvas.EXACT, 2)
