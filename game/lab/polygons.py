"""Scene ``polygons``: convex polygons by the separating axis theorem, axis by axis.

What it shows: a red pentagon and a blue triangle you can drag. Every edge brings an axis
(:meth:`~game.collision.sat.Polygon.axes`), drawn as a short numbered arrow on the edge. One
axis at a time is drawn as a long line beside the shapes, with both shadows on it
(:meth:`~game.collision.sat.Polygon.project`): the separating axis while there is one, or the
axis Tab picks. The panel names the first axis whose shadows do not overlap, the separating
axis, when there is one; when there is not, :func:`~game.collision.sat.collide` returns the
push-out (minimum translation vector), drawn as a green arrow, and M applies it: afterwards the
shapes touch, give or take float rounding (the panel then shows the depth that rounding left,
a tiny fraction of a pixel).
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.sat import Mtv, Point, Polygon, collide
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Control, Layer, Scene

PENTAGON = ((0.0, -70.0), (66.0, -22.0), (41.0, 57.0), (-41.0, 57.0), (-66.0, -22.0))
TRIANGLE = ((0.0, -60.0), (70.0, 50.0), (-70.0, 50.0))
AREA_CENTRE = (AREA.centerx, AREA.centery)
LINE_AWAY_PX = 170.0  # the axis is drawn this far to one side of the shapes
SHADOW_OFFSET_PX = 5.0
AXIS_ARROW_PX = 18.0  # length of the drawn edge normals


def line_centre(axis: Point, middle: Point) -> Point:
    """A point on the drawn axis line: beside the shapes, on the side nearer the area's middle."""
    nx, ny = -axis[1], axis[0]
    sides = [(middle[0] + nx * s * LINE_AWAY_PX, middle[1] + ny * s * LINE_AWAY_PX)
             for s in (1, -1)]
    return min(sides, key=lambda p: (p[0] - AREA_CENTRE[0]) ** 2 + (p[1] - AREA_CENTRE[1]) ** 2)


def shadow_ends(axis: Point, through: Point, lo: float, hi: float,
                side: float) -> tuple[Point, Point]:
    """The two ends of a shadow ``[lo, hi]`` on the axis line through ``through``."""
    cx, cy = through
    base = cx * axis[0] + cy * axis[1]
    nx, ny = -axis[1] * side, axis[0] * side
    return ((cx + axis[0] * (lo - base) + nx, cy + axis[1] * (lo - base) + ny),
            (cx + axis[0] * (hi - base) + nx, cy + axis[1] * (hi - base) + ny))


class Polygons(Scene):
    name = "polygons"
    title = "convex polygons by SAT: axes and the push-out"
    keys_help = "drag shapes; Tab next axis; M push out"
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.PAIRS, Layer.CONTACTS)

    def reset(self) -> None:
        self.pos = {"a": (AREA.x + 180.0, AREA.y + 200.0), "b": (AREA.x + 320.0, AREA.y + 220.0)}
        self.shown_axis = 0
        self.follow = True  # show the separating axis until Tab picks one by hand
        self.mtv: Mtv | None = None
        self.meter = CostMeter()

    def controls(self) -> list[Control]:
        push = ("push A out by the MTV" if self.mtv is not None
                else "push A out (apart: nothing to push)")
        return [Control(f"axis drawn: #{self.shown_axis + 1}", (pygame.K_TAB,)),
                Control(push, (pygame.K_m,))]

    def shape(self, key: str) -> Polygon:
        x, y = self.pos[key]
        return Polygon.of((x + px, y + py) for px, py in (PENTAGON if key == "a" else TRIANGLE))

    def grab_boxes(self) -> dict[str, Box]:
        return {key: self.shape(key).bounds() for key in ("a", "b")}

    def on_key(self, key: int) -> None:
        if key == pygame.K_TAB:
            self.follow = False
            self.shown_axis += 1
        elif key == pygame.K_m and self.mtv is not None:
            x, y = self.pos["a"]
            dx, dy = self.mtv.vector
            self.pos["a"] = (x + dx, y + dy)

    def refresh(self) -> None:
        a, b = self.shape("a"), self.shape("b")
        self.axes = a.axes() + b.axes()
        self.shown_axis %= len(self.axes)
        self.shadows = [(a.project(axis), b.project(axis)) for axis in self.axes]
        self.separating = next((i for i, ((a_lo, a_hi), (b_lo, b_hi))
                                in enumerate(self.shadows) if b_hi - a_lo <= 0
                                or a_hi - b_lo <= 0), None)
        self.mtv = collide(a, b)
        self.meter.time("sat.collide", lambda: collide(a, b))
        self.meter.time("bounding boxes", lambda: a.bounds().overlaps(b.bounds()))
        if self.follow and self.separating is not None:
            self.shown_axis = self.separating
        axis = self.axes[self.shown_axis]
        owner = "A" if self.shown_axis < len(a.points) else "B"
        self.lines = [f"axes to try: {len(a.points)} of A + {len(b.points)} of B",
                      f"sat.collide: {'colliding' if self.mtv else 'apart'}"]
        if self.separating is not None:
            sx, sy = self.axes[self.separating]
            self.lines.append(f"separating axis: #{self.separating + 1} ({sx:+.2f}, {sy:+.2f})")
            self.lines.append("  the shadows do not overlap on it")
        if self.mtv is not None and self.mtv.depth < 1e-6:
            self.lines.append(f"  depth {self.mtv.depth:.1e} px: float rounding")
        elif self.mtv is not None:
            dx, dy = self.mtv.vector
            self.lines.append(f"push-out for A: ({dx:+.1f}, {dy:+.1f}) px")
            self.lines.append(f"  depth {self.mtv.depth:.1f} px; M applies it")
        (a_lo, a_hi), (b_lo, b_hi) = self.shadows[self.shown_axis]
        self.lines += ["", f"drawn: axis #{self.shown_axis + 1} of {len(self.axes)} "
                           f"(edge of {owner}) ({axis[0]:+.2f}, {axis[1]:+.2f})",
                       f"  A's shadow {a_lo:.0f}..{a_hi:.0f}",
                       f"  B's shadow {b_lo:.0f}..{b_hi:.0f}"]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        a, b = self.shape("a"), self.shape("b")
        if Layer.SHAPES in layers:
            canvas.polygon(surface, a.points, canvas.MOVER, 0 if self.mtv is None else 3)
            canvas.polygon(surface, b.points, canvas.STILL, 0 if self.mtv is None else 3)
        if Layer.BOUNDS in layers:
            canvas.box(surface, a.bounds(), canvas.BOUNDS, 1)
            canvas.box(surface, b.bounds(), canvas.BOUNDS, 1)
        if Layer.PAIRS in layers:
            index = self.shown_axis
            axis = self.axes[index]
            ax, ay = self.pos["a"]
            bx, by = self.pos["b"]
            through = line_centre(axis, ((ax + bx) / 2, (ay + by) / 2))
            far = shadow_ends(axis, through, -2000.0, 2000.0, 0.0)
            line_color = canvas.EXACT if index == self.separating else canvas.DIM
            pygame.draw.line(surface, line_color, far[0], far[1], 1)
            (a_lo, a_hi), (b_lo, b_hi) = self.shadows[index]
            for lo, hi, color, side in ((a_lo, a_hi, canvas.MOVER, SHADOW_OFFSET_PX),
                                        (b_lo, b_hi, canvas.STILL, -SHADOW_OFFSET_PX)):
                start, end = shadow_ends(axis, through, lo, hi, side)
                pygame.draw.line(surface, color, start, end, 5)
            canvas.text(surface, f"axis #{index + 1}", (round(through[0]), round(through[1])),
                        line_color)
        if Layer.PAIRS in layers:  # every candidate axis: the normal of each edge, numbered
            number = 0
            for shape in (a, b):
                points = shape.points
                for i, (nx, ny) in enumerate(shape.axes()):
                    (x1, y1), (x2, y2) = points[i], points[(i + 1) % len(points)]
                    mid = ((x1 + x2) / 2, (y1 + y2) / 2)
                    tip = (mid[0] + nx * AXIS_ARROW_PX, mid[1] + ny * AXIS_ARROW_PX)
                    number += 1
                    color = canvas.EXACT if number - 1 == self.separating else canvas.DIM
                    canvas.arrow(surface, mid, tip, color, 1)
                    canvas.text(surface, str(number), (round(tip[0]) + 2, round(tip[1]) - 4),
                                color, 16)
        if Layer.CONTACTS in layers and self.mtv is not None:
            cx, cy = self.pos["a"]
            dx, dy = self.mtv.vector
            canvas.arrow(surface, (cx, cy), (cx + dx, cy + dy), canvas.EXACT, 3)
        canvas.text(surface, "A", (round(self.pos["a"][0]) - 5, round(self.pos["a"][1]) - 8))
        canvas.text(surface, "B", (round(self.pos["b"][0]) - 5, round(self.pos["b"][1]) - 8))
