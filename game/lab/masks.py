"""Scene ``masks``: pixel-perfect collision, and the first pixel two masks share.

What it shows: a red ball (:func:`~game.collision.masks.circle_mask`) and a blue bar turned
45 degrees (:func:`~game.collision.masks.polygon_mask`), each a mask of solid pixels drawn
at 1:1 with its rect, the cheap guard, in yellow. Drag either. The panel gives the rect
guard's answer, :func:`~game.collision.masks.collide`'s answer, the first overlapping pixel
(:func:`~game.collision.masks.contact_point`, marked with a cross) and
:func:`~game.collision.masks.overlap_area`, and the counts of
:class:`~game.collision.masks.MaskStats`: how often the guard let a mask test through. Where the
rects overlap and no pixel does, the rect alone would be wrong. Both tests are timed live.
"""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.collision.circles import Circle
from game.collision.masks import (
    Masked,
    MaskStats,
    circle_mask,
    collide,
    contact_point,
    overlap_area,
    polygon_mask,
)
from game.collision.sat import oriented_box
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Layer, Scene

BALL_R_PX = 48.0
BAR_HALF_W_PX, BAR_HALF_H_PX = 120.0, 14.0
BAR_ANGLE_RAD = math.pi / 4


class Masks(Scene):
    name = "masks"
    title = "pixel masks: the first overlapping pixel"
    keys_help = "drag the ball or the bar"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.CONTACTS)

    def reset(self) -> None:
        self.pos = {"bar": (AREA.x + 330.0, AREA.y + 250.0),
                    "ball": (AREA.x + 420.0, AREA.y + 130.0)}
        self.stats = MaskStats()
        self.meter = CostMeter()
        self.bar_shape = polygon_mask(oriented_box(0.0, 0.0, BAR_HALF_W_PX, BAR_HALF_H_PX,
                                                   BAR_ANGLE_RAD))
        self.ball_shape = circle_mask(Circle(0.0, 0.0, BALL_R_PX))

    def placed(self, key: str) -> Masked:
        shape = self.bar_shape if key == "bar" else self.ball_shape
        x, y = self.pos[key]
        return Masked.at(shape.mask, x + shape.x, y + shape.y)

    def grab_boxes(self) -> dict[str, Box]:
        return {key: Box.from_rect(self.placed(key).rect) for key in ("bar", "ball")}

    def refresh(self) -> None:
        ball, bar = self.placed("ball"), self.placed("bar")
        self.stats.reset()
        self.rects_hit = ball.rect.colliderect(bar.rect)
        self.pixel_hit = collide(ball, bar, self.stats)
        self.first = contact_point(ball, bar, self.stats)
        self.area = overlap_area(ball, bar, self.stats)
        self.meter.time("rect guard", lambda: ball.rect.colliderect(bar.rect))
        self.meter.time("masks.collide", lambda: collide(ball, bar))
        wrong = self.rects_hit and not self.pixel_hit
        self.lines = [
            f"rect guard (colliderect): {canvas.yes_no(self.rects_hit)}",
            f"masks.collide:            {canvas.yes_no(self.pixel_hit)}",
            "  the rects alone are wrong here" if wrong else "",
            f"first overlapping pixel: {self.first if self.first else 'none'}",
            f"pixels solid in both: {self.area}",
            "",
            f"this frame: {self.stats.rect_checks} rect guards, "
            f"{self.stats.mask_checks} mask tests",
            f"ball {self.ball_shape.mask.count()} px solid, bar {self.bar_shape.mask.count()}",
            "",
            f"a mask test takes {self.meter.times('masks.collide', 'rect guard')} a rect guard",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        if Layer.SHAPES in layers:
            for key, color in (("bar", canvas.STILL), ("ball", canvas.MOVER)):
                placed = self.placed(key)
                image = placed.mask.to_surface(setcolor=(*color, 255), unsetcolor=(0, 0, 0, 0))
                surface.blit(image, (placed.x, placed.y))
        if Layer.BOUNDS in layers:
            for key in ("bar", "ball"):
                pygame.draw.rect(surface, canvas.BOUNDS, self.placed(key).rect, 1)
        if Layer.CONTACTS in layers and self.first is not None:
            ball, bar = self.placed("ball"), self.placed("bar")
            both = ball.mask.overlap_mask(bar.mask, (bar.x - ball.x, bar.y - ball.y))
            image = both.to_surface(setcolor=(*canvas.EXACT, 255), unsetcolor=(0, 0, 0, 0))
            surface.blit(image, (ball.x, ball.y))
            canvas.cross(surface, (self.first[0] + 0.5, self.first[1] + 0.5), canvas.WHITE, 8)
