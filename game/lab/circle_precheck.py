"""Scene ``circle-precheck``: the bounding-circle pre-check in front of a box test.

What it shows: a crowd of blue boxes and a red box you drag. For each blue box the pre-check
:func:`~game.collision.circles.circles_may_touch` compares the two boxes' bounding circles
(:func:`~game.collision.circles.bounding_circle`, drawn for the boxes that pass); only those
go on to ``Rect.colliderect``. The panel counts the box tests the pre-check skipped and the
hits, which are always the same as ``colliderect`` alone (the pre-check is a filter that may
say "maybe" too often, never "no" to a hit), and it times
:func:`~game.collision.circles.precheck_then_rect` against ``colliderect`` alone, per pair:
in Python the filter usually costs more than the C call it guards.
"""

from __future__ import annotations

import random

import pygame

from game.collision.aabb import Box
from game.collision.circles import bounding_circle, circles_may_touch, precheck_then_rect
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Layer, Scene

CROWD = 40
SEED = 16
PROBE_W_PX, PROBE_H_PX = 70, 44


PRE, RECT = "pre-check then rect", "colliderect alone"  # what is timed, per pair


class CirclePrecheck(Scene):
    name = "circle-precheck"
    title = "circles as a pre-check before the box test"
    keys_help = "drag the red box (or any blue one)"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.PAIRS, Layer.CONTACTS)

    def reset(self) -> None:
        rng = random.Random(SEED)
        self.crowd = [pygame.Rect(rng.randrange(AREA.left + 10, AREA.right - 60),
                                  rng.randrange(AREA.top + 10, AREA.bottom - 60),
                                  rng.randrange(14, 50), rng.randrange(14, 50))
                      for _ in range(CROWD)]
        self.pos = {"probe": (AREA.x + 260.0, AREA.y + 200.0)}
        self.meter = CostMeter(repeats=8)

    def probe(self) -> pygame.Rect:
        x, y = self.pos["probe"]
        return pygame.Rect(round(x), round(y), PROBE_W_PX, PROBE_H_PX)

    def grab_boxes(self) -> dict[str, Box]:
        for number, rect in enumerate(self.crowd):
            self.pos[str(number)] = (rect.x, rect.y)
        crowd = {str(number): Box.from_rect(rect) for number, rect in enumerate(self.crowd)}
        return {**crowd, "probe": Box.from_rect(self.probe())}

    def drag_to(self, key: str, point: tuple[float, float]) -> None:
        if key == "probe":
            super().drag_to(key, point)
        else:
            self.crowd[int(key)].topleft = (round(point[0]), round(point[1]))

    def refresh(self) -> None:
        probe = self.probe()
        mine = bounding_circle(Box.from_rect(probe))
        self.maybe = [rect for rect in self.crowd
                      if circles_may_touch(mine, bounding_circle(Box.from_rect(rect)))]
        self.hits = [rect for rect in self.crowd if precheck_then_rect(probe, rect)]
        self.rect_hits = [rect for rect in self.crowd if probe.colliderect(rect)]
        crowd = self.crowd
        self.meter.time(PRE, lambda: [precheck_then_rect(probe, r) for r in crowd], CROWD)
        self.meter.time(RECT, lambda: [probe.colliderect(r) for r in crowd], CROWD)
        pays = self.meter.median(PRE) < self.meter.median(RECT)
        skipped = CROWD - len(self.maybe)
        self.lines = [
            f"pairs: {CROWD} (red box against each blue)",
            f"pre-check said 'maybe': {len(self.maybe)}",
            f"box tests skipped by the pre-check: {skipped}",
            f"hits, pre-check then rect: {len(self.hits)}",
            f"hits, colliderect alone:   {len(self.rect_hits)}",
            "  same hits: " + ("yes" if self.hits == self.rect_hits else "NO"),
            "",
            f"per pair, pre-check then rect takes {self.meter.times(PRE, RECT)}",
            "  colliderect alone (medians, timed here):",
            "  the filter pays for itself here" if pays else
            "  the filter costs more than the C call it",
            "" if pays else "  guards: worth it only before a dearer",
            "" if pays else "  test (SAT, masks)",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        probe = self.probe()
        if Layer.SHAPES in layers:
            for rect in self.crowd:
                pygame.draw.rect(surface, canvas.STILL, rect, 0 if rect in self.hits else 2)
            pygame.draw.rect(surface, canvas.MOVER, probe)
        if Layer.BOUNDS in layers:
            for rect in [probe, *self.maybe]:
                circle = bounding_circle(Box.from_rect(rect))
                pygame.draw.circle(surface, canvas.BOUNDS, (circle.cx, circle.cy), circle.r, 1)
        if Layer.PAIRS in layers:
            for rect in self.maybe:
                pygame.draw.line(surface, canvas.TESTED, probe.center, rect.center, 1)
        if Layer.CONTACTS in layers:
            for rect in self.hits:
                pygame.draw.rect(surface, canvas.EXACT, rect, 3)
