"""Scene ``composite``: a concave shape as several boxes, against one box around it.

What it shows: a blue L-shaped crate made of two boxes
(:func:`~game.collision.composite.l_shape`) and a red coin you drag. One bounding box over the L
(:meth:`~game.collision.composite.Composite.bounds`, yellow) also covers the L's empty notch;
:meth:`~game.collision.composite.Composite.overlaps`
tests the parts. The coin starts in the notch, where the bounding box says "hit" and the
parts say "apart". Both answers and their cost are live.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.composite import Composite, l_shape
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Layer, Scene

L_SIZE_PX, L_THICK_PX = 220.0, 60.0
COIN_PX = 40.0


class CompositeScene(Scene):
    name = "composite"
    title = "a concave shape as several boxes"
    keys_help = "drag the L or the coin"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.PAIRS)

    def reset(self) -> None:
        self.pos = {"crate": (AREA.x + 180.0, AREA.y + 120.0),
                    "coin": (AREA.x + 300.0, AREA.y + 190.0)}
        self.meter = CostMeter()

    def crate(self) -> Composite:
        x, y = self.pos["crate"]
        return l_shape(x, y, width=L_SIZE_PX, height=L_SIZE_PX, thickness=L_THICK_PX)

    def coin(self) -> Box:
        return Box(*self.pos["coin"], COIN_PX, COIN_PX)

    def grab_boxes(self) -> dict[str, Box]:
        return {"crate": self.crate().bounds(), "coin": self.coin()}

    def refresh(self) -> None:
        crate, coin = self.crate(), self.coin()
        bounds = crate.bounds()
        self.bounds_hit = bounds.overlaps(coin)
        self.parts_hit = crate.overlaps(coin)
        self.part_hits = [part.overlaps(coin) for part in crate.world_parts()]
        self.meter.time("bounding box", lambda: bounds.overlaps(coin))
        self.meter.time("Composite.overlaps", lambda: crate.overlaps(coin))
        wrong = self.bounds_hit and not self.parts_hit
        hit_parts = ", ".join(str(i + 1) for i, hit in enumerate(self.part_hits) if hit)
        self.lines = [
            f"one bounding box:      {canvas.yes_no(self.bounds_hit)}",
            f"Composite.overlaps:    {canvas.yes_no(self.parts_hit)}",
            "  the bounding box is wrong: the notch" if wrong else "",
            "",
            f"parts: {len(crate.parts)}; hit by the coin: {hit_parts or 'none'}",
            "",
            "testing the parts takes "
            f"{self.meter.times('Composite.overlaps', 'bounding box')} one box",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        crate, coin = self.crate(), self.coin()
        if Layer.SHAPES in layers:
            for part in crate.world_parts():
                canvas.box(surface, part, canvas.STILL)
            canvas.box(surface, coin, canvas.MOVER)
        if Layer.PAIRS in layers:
            for part, hit in zip(crate.world_parts(), self.part_hits, strict=True):
                canvas.box(surface, part, canvas.EXACT if hit else canvas.TESTED, 2)
        if Layer.BOUNDS in layers:
            wrong = self.bounds_hit and not self.parts_hit
            canvas.box(surface, crate.bounds(), canvas.WRONG if wrong else canvas.BOUNDS, 2)
