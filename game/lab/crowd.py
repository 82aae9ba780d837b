"""A crowd of boxes drifting round the scene area: the input every broad-phase scene shares.

Where it sits: under the ``party-grid``, ``quadtree``, ``sort-and-sweep`` and ``contacts``
scenes. It only moves boxes (bouncing off the area's edges) and never tests them against
each other: finding pairs is the broad phase's job, and the scenes ask the reference.

>>> crowd = Crowd.random(seed=1, count=3, area=Box(0, 0, 100, 100), sizes_px=(10, 20))
>>> len(crowd.boxes), crowd.boxes == Crowd.random(1, 3, Box(0, 0, 100, 100), (10, 20)).boxes
(3, True)
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

from game.collision.aabb import Box
from game.lab.scene import Point, Scene


@dataclass
class Crowd:
    """Boxes by key, each with a velocity in px/s, kept inside ``area``."""

    area: Box
    boxes: dict[int, Box]
    velocities: dict[int, tuple[float, float]]

    @classmethod
    def random(cls, seed: int, count: int, area: Box, sizes_px: tuple[float, float],
               max_speed_px_s: float = 40.0) -> Crowd:
        """``count`` boxes at random places and speeds; the same seed, the same crowd."""
        rng = random.Random(seed)
        boxes, velocities = {}, {}
        for key in range(count):
            w, h = rng.uniform(*sizes_px), rng.uniform(*sizes_px)
            boxes[key] = Box(rng.uniform(area.left, area.right - w),
                             rng.uniform(area.top, area.bottom - h), w, h)
            velocities[key] = (rng.uniform(-max_speed_px_s, max_speed_px_s),
                               rng.uniform(-max_speed_px_s, max_speed_px_s))
        return cls(area, boxes, velocities)

    def drift(self, dt_s: float) -> None:
        """Move every box by its velocity; a box reaching the area's edge turns back."""
        for key, box in self.boxes.items():
            vx, vy = self.velocities[key]
            moved = box.moved(vx * dt_s, vy * dt_s)
            if moved.left < self.area.left or moved.right > self.area.right:
                vx = -vx
                moved = box.moved(0, vy * dt_s)
            if moved.top < self.area.top or moved.bottom > self.area.bottom:
                vy = -vy
                moved = moved._replace(y=box.y)
            self.boxes[key] = moved
            self.velocities[key] = (vx, vy)

    def key_at(self, point: tuple[float, float], reach_px: float = 0.0) -> int | None:
        """The topmost box under the pixel at ``point``; failing that, the box whose middle is
        nearest, if it is within ``reach_px`` (so a hover need not be pixel-exact)."""
        spot = Box(point[0], point[1], 1, 1)
        under = next((key for key in reversed(list(self.boxes))
                      if self.boxes[key].overlaps(spot)), None)
        if under is not None or not self.boxes:
            return under
        nearest = min(self.boxes, key=lambda k: math.dist(self.boxes[k].center, point))
        return nearest if math.dist(self.boxes[nearest].center, point) <= reach_px else None


class CrowdScene(Scene):
    """A scene whose draggable shapes are the boxes of :attr:`crowd` (set it in ``reset``)."""

    crowd: Crowd

    def grab_boxes(self) -> dict[str, Box]:
        self.pos = {str(key): (box.x, box.y) for key, box in self.crowd.boxes.items()}
        return {str(key): box for key, box in self.crowd.boxes.items()}

    def drag_to(self, key: str, point: Point) -> None:
        number = int(key)
        box = self.crowd.boxes[number]
        area = self.crowd.area
        x = min(max(point[0], area.left), area.right - box.w)
        y = min(max(point[1], area.top), area.bottom - box.h)
        self.crowd.boxes[number] = box._replace(x=x, y=y)

    def step(self, dt_s: float) -> None:
        if self.dragging is None:
            self.crowd.drift(dt_s)
