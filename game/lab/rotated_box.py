"""Scene ``rotated-box``: turn a box and watch its bounding box grow; then ask SAT instead.

What it shows: a blue bar turned by the arrow keys, its axis-aligned bounding box
(:meth:`~game.collision.sat.Polygon.bounds`, yellow) growing to hold the corners, and a red
probe you drag. The panel gives both answers for the probe: the AABB test
(:meth:`~game.collision.aabb.Box.overlaps` against the bounds) and the exact oriented-box test
(:func:`~game.collision.sat.collide`). The orange dots are probe positions, sampled every
``SAMPLE_PX``, where the AABB says "hit" and SAT says "apart": the false hits in the empty
corners. Both tests are timed live.
"""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.collision.sat import Polygon, collide, oriented_box
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Control, Layer, Scene

HALF_W_PX, HALF_H_PX = 130.0, 26.0
PROBE_PX = 28.0
TURN_DEG = 5.0
SAMPLE_PX = 12.0


class RotatedBox(Scene):
    name = "rotated-box"
    title = "the rotated box: its AABB grows, SAT is exact"
    keys_help = "Left/Right turn the bar; drag bar or probe"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.PAIRS, Layer.CONTACTS)

    def reset(self) -> None:
        self.pos = {"bar": (AREA.x + 250, AREA.y + 210), "probe": (AREA.x + 280, AREA.y + 130)}
        self.angle_deg = 30.0
        self.meter = CostMeter()
        self._sampled: tuple[object, ...] = ()
        self.false_spots: list[tuple[float, float]] = []
        self.spots_sampled = 0

    def bar(self) -> Polygon:
        cx, cy = self.pos["bar"]
        return oriented_box(cx, cy, HALF_W_PX, HALF_H_PX, math.radians(self.angle_deg))

    def probe(self) -> Box:
        x, y = self.pos["probe"]
        return Box(x, y, PROBE_PX, PROBE_PX)

    def grab_boxes(self) -> dict[str, Box]:
        cx, cy = self.pos["bar"]
        return {"bar": Box(cx - 20, cy - 20, 40, 40), "probe": self.probe()}

    def controls(self) -> list[Control]:
        return [Control(f"turn the bar: {self.angle_deg:.0f} degrees",
                        (pygame.K_LEFT, pygame.K_RIGHT))]

    def on_key(self, key: int) -> None:
        if key == pygame.K_LEFT:
            self.angle_deg = (self.angle_deg - TURN_DEG) % 180
        elif key == pygame.K_RIGHT:
            self.angle_deg = (self.angle_deg + TURN_DEG) % 180

    def _sample_false_hits(self, bar: Polygon, bounds: Box) -> None:
        """Every probe position on a grid near the bar where the two tests disagree."""
        key = (self.angle_deg, self.pos["bar"])
        if key == self._sampled:
            return
        self._sampled = key
        self.false_spots = []
        self.spots_sampled = 0
        y = bounds.top - PROBE_PX
        while y < bounds.bottom:
            x = bounds.left - PROBE_PX
            while x < bounds.right:
                probe = Box(x, y, PROBE_PX, PROBE_PX)
                if probe.overlaps(bounds):
                    self.spots_sampled += 1
                    if collide(Polygon.from_box(probe), bar) is None:
                        self.false_spots.append(probe.center)
                x += SAMPLE_PX
            y += SAMPLE_PX

    def refresh(self) -> None:
        bar, probe = self.bar(), self.probe()
        bounds = bar.bounds()
        probe_poly = Polygon.from_box(probe)
        self.aabb_hit = probe.overlaps(bounds)
        self.mtv = collide(probe_poly, bar)
        self.sat_hit = self.mtv is not None
        self._sample_false_hits(bar, bounds)
        self.meter.time("AABB test", lambda: probe.overlaps(bounds))
        self.meter.time("SAT test", lambda: collide(probe_poly, bar))
        area = 4 * HALF_W_PX * HALF_H_PX
        verdict = ("AABB is wrong: a false hit in an empty corner"
                   if self.aabb_hit and not self.sat_hit else "both agree")
        self.lines = [
            f"angle: {self.angle_deg:.0f} degrees",
            f"bar {2 * HALF_W_PX:.0f} x {2 * HALF_H_PX:.0f}; AABB {bounds.w:.0f} x {bounds.h:.0f}",
            f"AABB area is {bounds.w * bounds.h / area:.1f}x the bar's",
            f"AABB test (Box.overlaps): {canvas.yes_no(self.aabb_hit)}",
            f"SAT (sat.collide):        {canvas.yes_no(self.sat_hit)}",
            verdict,
            "",
            "tests made for the probe: 1 AABB, 1 SAT;",
            f"  the dots took {self.spots_sampled} SAT tests",
            "  when the bar last turned or moved",
            f"one SAT test takes {self.meter.times('SAT test', 'AABB test')} an AABB test here",
            "",
            f"false hits: {len(self.false_spots)} of {self.spots_sampled} probe",
            "  spots touching the AABB"
            + (" (orange dots)" if Layer.PAIRS in self.layers else " (layer 3 shows them)"),
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        bar, probe = self.bar(), self.probe()
        if Layer.PAIRS in layers:
            for spot in self.false_spots:
                pygame.draw.circle(surface, canvas.WRONG, (round(spot[0]), round(spot[1])), 2)
        if Layer.SHAPES in layers:
            canvas.polygon(surface, bar.points, canvas.STILL)
            canvas.box(surface, probe, canvas.MOVER)
        if Layer.BOUNDS in layers:
            canvas.box(surface, bar.bounds(), canvas.BOUNDS, 2)
        if Layer.CONTACTS in layers and self.mtv is not None:
            cx, cy = probe.center
            dx, dy = self.mtv.vector
            canvas.arrow(surface, (cx, cy), (cx + dx, cy + dy), canvas.EXACT)
        outline = canvas.WRONG if self.aabb_hit and not self.sat_hit else (
            canvas.EXACT if self.sat_hit else canvas.DIM)
        canvas.box(surface, probe, outline, 3)
