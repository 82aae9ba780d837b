"""Chart 1, the narrow phase: what each overlap test costs, and how often it is wrong.

Where it sits: the first chart of ``python -m game.bench``. It times the exact and the cheap
tests of :mod:`game.collision.aabb`, :mod:`game.collision.circles`, :mod:`game.collision.sat`,
:mod:`game.collision.masks` and
:mod:`game.collision.composite` on four families of shapes, and counts their mistakes against an
exact oracle.

What it teaches:
  * **Every method sees a shape through its own model.** A Rect sees the integer box around
    it, a circle test the circle around it, SAT a convex polygon (a circle becomes a
    12-sided one inside it, an L its convex hull), a mask the pixels whose centres lie
    inside, a composite a few boxes that cover it. The *oracle* is the exact test for the
    family: :meth:`Box.overlaps`, :meth:`Circle.overlaps`, SAT on the true polygon, and the
    L's own parts.
  * **Two kinds of wrong.** A *false hit* says "touching" when the shapes are apart (a coin
    collected from the empty corner of a bounding box); a *missed hit* says "apart" when they
    touch (a bullet through a pixel gap). Covering models only make false hits.
  * **Cost against error.** Each point is one method on one family: time per test (log
    scale) against the share of wrong answers on random pairs placed within reach of each
    other, where about half truly touch. The dashed line is the Pareto front: the methods
    that no other method beats on both counts. Anything off the front is never the right
    choice for that family.
  * **Colliders are built once.** Rects, polygons and masks are made before timing, as a
    game makes them once per sprite; only the test itself is timed.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from statistics import median
from typing import Any

import pygame

from game.bench import charts
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import Case, interleaved
from game.collision import masks
from game.collision.aabb import Box
from game.collision.circles import Circle, bounding_circle, precheck_then_rect
from game.collision.composite import Composite, l_shape
from game.collision.sat import Polygon, oriented_box
from game.collision.sat import collide as sat_collide

CHART = "narrow_phase"
SEED = 1
FAMILIES = ("boxes", "circles", "rotated bars", "L-shapes")
CIRCLE_SIDES = 12      # SAT's polygon for a circle
BAR_SLICES = 4         # boxes in the composite that covers a rotated bar
# How far apart a pair's centres may be, in units of their two reaches: set so that about
# half of the pairs of each family touch (the rest are near misses, where methods differ).
SPREAD = {"boxes": 0.95, "circles": 1.25, "rotated bars": 0.7, "L-shapes": 0.85}

Shape = Box | Circle | Polygon | Composite


def random_shape(family: str, rng: random.Random, cx: float, cy: float) -> Shape:
    """One shape of a family centred near ``(cx, cy)``, sizes in pixels."""
    if family == "boxes":
        w, h = rng.uniform(6, 40), rng.uniform(6, 40)
        return Box(cx - w / 2, cy - h / 2, w, h)
    if family == "circles":
        return Circle(cx, cy, rng.uniform(3, 20))
    if family == "rotated bars":
        return oriented_box(cx, cy, rng.uniform(10, 30), rng.uniform(1.5, 4),
                            rng.uniform(0, math.pi))
    w, h = rng.uniform(16, 48), rng.uniform(16, 48)
    return l_shape(cx - w / 2, cy - h / 2, width=w, height=h,
                   thickness=rng.uniform(4, 0.45 * min(w, h)))


def reach(shape: Shape) -> float:
    """The radius of the circle around the shape: how far away it can still touch."""
    return enclosing_circle(shape).r


def random_pairs(family: str, count: int, seed: int) -> list[tuple[Shape, Shape]]:
    """Pairs of one family placed within reach of each other (about half of them touch)."""
    rng = random.Random(f"{seed}:{family}")
    pairs: list[tuple[Shape, Shape]] = []
    for _ in range(count):
        a = random_shape(family, rng, rng.uniform(100, 300), rng.uniform(100, 300))
        ax, ay = centre(a)
        b_seed = rng.random()   # b's sizes: drawn once to size the spread, again in place
        b_reach = reach(random_shape(family, random.Random(b_seed), 0, 0))
        spread = SPREAD[family] * (reach(a) + b_reach)
        pairs.append((a, random_shape(family, random.Random(b_seed),
                                      ax + rng.uniform(-spread, spread),
                                      ay + rng.uniform(-spread, spread))))
    return pairs


# --- the models: each method's view of a shape ------------------------------------------------

def bounds(shape: Shape) -> Box:
    return shape if isinstance(shape, Box) else shape.bounds()


def centre(shape: Shape) -> tuple[float, float]:
    return (shape.cx, shape.cy) if isinstance(shape, Circle) else bounds(shape).center


def enclosing_circle(shape: Shape) -> Circle:
    """A circle around the shape: the corners' circle for boxes, the tightest for a bar."""
    if isinstance(shape, Circle):
        return shape
    if isinstance(shape, Polygon):
        cx = sum(x for x, _ in shape.points) / len(shape.points)
        cy = sum(y for _, y in shape.points) / len(shape.points)
        return Circle(cx, cy, max(math.hypot(x - cx, y - cy) for x, y in shape.points))
    return bounding_circle(bounds(shape))


def convex_hull(points: Sequence[tuple[float, float]]) -> Polygon:
    """Andrew's monotone chain; collinear points are dropped so the polygon stays strict."""
    pts = sorted(set(points))

    def half(chain_points: list[tuple[float, float]]) -> list[tuple[float, float]]:
        chain: list[tuple[float, float]] = []
        for p in chain_points:
            while len(chain) >= 2 and ((chain[-1][0] - chain[-2][0]) * (p[1] - chain[-2][1])
                                       - (chain[-1][1] - chain[-2][1]) * (p[0] - chain[-2][0])
                                       ) <= 0:
                chain.pop()
            chain.append(p)
        return chain[:-1]

    return Polygon.of(half(pts) + half(pts[::-1]))


def as_polygon(shape: Shape) -> Polygon:
    if isinstance(shape, Polygon):
        return shape
    if isinstance(shape, Circle):
        return Polygon.of((shape.cx + shape.r * math.cos(2 * math.pi * k / CIRCLE_SIDES),
                           shape.cy + shape.r * math.sin(2 * math.pi * k / CIRCLE_SIDES))
                          for k in range(CIRCLE_SIDES))
    boxes = shape.world_parts() if isinstance(shape, Composite) else (shape,)
    return convex_hull([corner for b in boxes for corner in
                        ((b.left, b.top), (b.right, b.top), (b.right, b.bottom),
                         (b.left, b.bottom))])


def as_mask(shape: Shape) -> masks.Masked:
    if isinstance(shape, Circle):
        return masks.circle_mask(shape)
    if isinstance(shape, Composite):
        whole = bounds(shape)
        x0, y0 = math.floor(whole.x), math.floor(whole.y)
        mask = pygame.mask.Mask((math.ceil(whole.right) - x0, math.ceil(whole.bottom) - y0))
        for part in shape.world_parts():
            piece = masks.polygon_mask(Polygon.from_box(part))
            mask.draw(piece.mask, (piece.x - x0, piece.y - y0))
        return masks.Masked(mask, x0, y0)
    return masks.polygon_mask(as_polygon(shape))


def as_composite(shape: Shape) -> Composite:
    """Boxes that cover the shape: itself for boxes and Ls, three bands for a circle,
    ``BAR_SLICES`` boxes each around one slice of a bar."""
    if isinstance(shape, Composite):
        return shape
    if isinstance(shape, Box):
        return Composite(shape.x, shape.y, (Box(0, 0, shape.w, shape.h),))
    if isinstance(shape, Circle):
        r, chord = shape.r, shape.r * math.sqrt(3) / 2   # half-width of the circle at r / 2
        return Composite(shape.cx, shape.cy, (Box(-r, -r / 2, 2 * r, r),
                                              Box(-chord, -r, 2 * chord, r / 2),
                                              Box(-chord, r / 2, 2 * chord, r / 2)))
    (ax, ay), (bx, by), (cx, cy), (dx, dy) = shape.points[:4]   # an oriented box: a-b-c-d
    parts: list[Box] = []
    for k in range(BAR_SLICES):
        s, e = k / BAR_SLICES, (k + 1) / BAR_SLICES
        corners = [(ax + (bx - ax) * t, ay + (by - ay) * t) for t in (s, e)]
        corners += [(dx + (cx - dx) * t, dy + (cy - dy) * t) for t in (s, e)]
        xs, ys = [p[0] for p in corners], [p[1] for p in corners]
        parts.append(Box(min(xs), min(ys), max(xs) - min(xs), max(ys) - min(ys)))
    return Composite(0, 0, tuple(parts))


@dataclass(frozen=True)
class Method:
    """A test and the model it needs: ``build`` makes the collider, ``test`` compares two."""

    name: str
    build: Callable[[Shape], Any]
    test: Callable[[Any, Any], object]   # truthy means "they overlap"


METHODS = (
    Method("AABB (Rect.colliderect)", lambda s: bounds(s).to_rect(), pygame.Rect.colliderect),
    Method("Box.overlaps", bounds, Box.overlaps),
    Method("circle test", enclosing_circle, Circle.overlaps),
    Method("circle pre-check + rect", lambda s: bounds(s).to_rect(), precheck_then_rect),
    Method("SAT", as_polygon, sat_collide),
    Method("masks (rect guard)", as_mask, masks.collide),
    Method("composite boxes", as_composite, Composite.overlaps),
)


def oracle(a: Shape, b: Shape) -> bool:
    """The exact answer for two shapes of the same family."""
    if isinstance(a, Polygon) and isinstance(b, Polygon):
        return sat_collide(a, b) is not None
    if isinstance(a, Circle) and isinstance(b, Circle):
        return a.overlaps(b)
    if isinstance(a, Composite):
        return a.overlaps(b if isinstance(b, Box | Composite) else bounds(b))
    if isinstance(a, Box) and isinstance(b, Box):
        return a.overlaps(b)
    raise TypeError(f"no oracle for {type(a).__name__} against {type(b).__name__}")


def measure(sizes: Sizes) -> list[Row]:
    """Error rates for every method and family, then their timings, all families interleaved."""
    rows: list[Row] = []
    cases: list[Case] = []
    for family in FAMILIES:
        pairs = random_pairs(family, sizes.narrow_pairs, SEED)
        truth = [oracle(a, b) for a, b in pairs]
        for method in METHODS:
            built = [(method.build(a), method.build(b)) for a, b in pairs]
            said = [bool(method.test(a, b)) for a, b in built]
            false_hits = sum(s and not t for s, t in zip(said, truth, strict=True))
            missed = sum(t and not s for s, t in zip(said, truth, strict=True))
            rows.append(Row(CHART, method.name, family, 0, 100 * false_hits / len(pairs),
                            "% false hits"))
            rows.append(Row(CHART, method.name, family, 0, 100 * missed / len(pairs),
                            "% missed hits"))
            cases.append(_timed(f"{method.name}|{family}", method.test,
                                built[:sizes.narrow_timed_pairs]))
    for name, seconds in interleaved(cases, sizes.rounds, sizes.min_s).items():
        method_name, family = name.split("|")
        rows += [Row(CHART, method_name, family, r, s * 1e9, "ns/test")
                 for r, s in enumerate(seconds)]
    return rows


def _timed(name: str, test: Callable[[Any, Any], object], pairs: list[tuple[Any, Any]]) -> Case:
    def run() -> None:
        for a, b in pairs:
            test(a, b)
    return Case(name, run, ops=len(pairs))


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("Narrow phase: cost against error, by shape family",
                               width_in=12, height_in=8.5)
    grid = figure.subplots(2, 2)
    for axes, family in zip(grid.flat, FAMILIES, strict=True):
        points: list[tuple[float, float]] = []
        for index, method in enumerate(METHODS):
            cost = median(values(rows, method=method.name, parameter=family, unit="ns/test"))
            false_hits = values(rows, method=method.name, parameter=family,
                                unit="% false hits")[0]
            missed = values(rows, method=method.name, parameter=family,
                            unit="% missed hits")[0]
            points.append((cost, false_hits + missed))
            axes.scatter([cost], [false_hits + missed], s=60, color=charts.colour(index),
                         label=method.name, zorder=3)
            axes.annotate(f"{false_hits:.1f} / {missed:.1f}", (cost, false_hits + missed),
                          textcoords="offset points", xytext=(6, 4), fontsize=7)
        front = charts.pareto_front(points)
        axes.plot([p[0] for p in front], [p[1] for p in front], "--", color="#888888",
                  drawstyle="steps-post", label="Pareto front", zorder=2)
        axes.set_xscale("log")
        axes.set_title(family)
        axes.set_xlabel("time per test (ns, log scale)")
        axes.set_ylabel("wrong answers (% of pairs)")
        top = max(error for _, error in points) * 1.15 + 0.5
        axes.set_ylim(-0.04 * top, top)
        axes.grid(True, which="both", alpha=0.3)
    handles, labels = grid.flat[0].get_legend_handles_labels()
    figure.legend(handles, labels, loc="outside right upper", fontsize=8,
                  title="labels: % false / % missed", title_fontsize=8)
    return charts.save(figure, out / f"{CHART}.png", footnote)
