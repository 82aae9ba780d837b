"""Scene ``circles``: circle against circle, circle against box, and the box around a circle.

What it shows: a red ball you drag, a blue ball and a blue box. The panel gives
:meth:`~game.collision.circles.Circle.overlaps` (squared distances, strict: touching circles do
not collide) and :meth:`~game.collision.circles.Circle.overlaps_box` (clamp the centre into the
box, then measure), and beside them the cheap answer an AABB-only engine would give, the
ball's square :meth:`~game.collision.circles.Circle.bounds` tested with
:meth:`~game.collision.aabb.Box.overlaps`. Near a corner the square says "hit" and the circle
does not: the panel says when. Every test is timed live.
"""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.collision.circles import Circle
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Layer, Scene

RADIUS_PX = 50.0
OTHER_RADIUS_PX = 60.0
BLOCK = Box(AREA.x + 290, AREA.y + 200, 160, 110)


class Circles(Scene):
    name = "circles"
    title = "squared distances; the square around a circle"
    keys_help = "drag the balls or the box"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.CONTACTS)

    def reset(self) -> None:
        self.pos = {"block": (BLOCK.x, BLOCK.y), "ball": (AREA.x + 250.0, AREA.y + 160.0),
                    "other": (AREA.x + 110.0, AREA.y + 130.0)}
        self.meter = CostMeter()

    def ball(self) -> Circle:
        return Circle(*self.pos["ball"], RADIUS_PX)

    def other(self) -> Circle:
        return Circle(*self.pos["other"], OTHER_RADIUS_PX)

    def block(self) -> Box:
        return BLOCK._replace(x=self.pos["block"][0], y=self.pos["block"][1])

    def grab_boxes(self) -> dict[str, Box]:
        return {"block": self.block(), "other": self.other().bounds(),
                "ball": self.ball().bounds()}

    def refresh(self) -> None:
        ball, other, block = self.ball(), self.other(), self.block()
        square = ball.bounds()
        self.ball_ball = ball.overlaps(other)
        self.ball_box = ball.overlaps_box(block)
        self.square_box = square.overlaps(block)
        self.square_ball = square.overlaps(other.bounds())
        self.meter.time("Circle.overlaps", lambda: ball.overlaps(other))
        self.meter.time("Circle.overlaps_box", lambda: ball.overlaps_box(block))
        self.meter.time("square: Box.overlaps", lambda: square.overlaps(block))
        centres = math.dist(self.pos["ball"], self.pos["other"])
        self.lines = [
            f"ball-ball  Circle.overlaps:     {canvas.yes_no(self.ball_ball)}",
            f"  centres {centres:.1f} px apart, radii sum {RADIUS_PX + OTHER_RADIUS_PX:.0f}",
            f"ball-box   Circle.overlaps_box: {canvas.yes_no(self.ball_box)}",
            "",
            "the ball's square (bounds) instead:",
            f"  vs box:  {canvas.yes_no(self.square_box)}"
            + ("  <- wrong: a corner" if self.square_box and not self.ball_box else ""),
            f"  vs ball: {canvas.yes_no(self.square_ball)}"
            + ("  <- wrong" if self.square_ball and not self.ball_ball else ""),
            "",
            "one circle-box test takes "
            f"{self.meter.times('Circle.overlaps_box', 'square: Box.overlaps')} the square's",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        ball, other = self.ball(), self.other()
        if Layer.SHAPES in layers:
            canvas.box(surface, self.block(), canvas.STILL)
            pygame.draw.circle(surface, canvas.STILL, self.pos["other"], other.r)
            pygame.draw.circle(surface, canvas.MOVER, self.pos["ball"], ball.r)
        if Layer.BOUNDS in layers:
            wrong = self.square_box and not self.ball_box
            canvas.box(surface, ball.bounds(), canvas.WRONG if wrong else canvas.BOUNDS, 2)
        if Layer.CONTACTS in layers:
            for hit, at in ((self.ball_box, self.block()), (self.ball_ball, other.bounds())):
                if hit:
                    canvas.box(surface, at, canvas.EXACT, 3)
            pygame.draw.line(surface, canvas.DIM, self.pos["ball"], self.pos["other"], 1)
