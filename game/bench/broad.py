"""Chart 3, the broad phase: the time to find every overlapping pair in a crowd of N movers.

Where it sits: the third chart of ``python -m game.bench``; :mod:`game.bench.grid_cells`
reuses its crowds to choose the grid's cell size.

What it teaches:
  * **One frame** is: every item has moved a little (up to 2 px on each axis, like crates at
    120 px/s), the method is told where everything is now, then it returns every overlapping
    pair. For sprites "telling" is setting their rects; for the structures of
    :mod:`game.collision.broad.brute_force`, :mod:`game.collision.broad.spatial_grid`,
    :mod:`game.collision.broad.quadtree` and
    :mod:`game.collision.broad.sort_and_sweep` it is ``move()`` for each item, which is real work.
  * **The crowd** is N boxes of 8 to 24 px at whole-pixel positions, spread so that each has
    a 64 x 64 px patch of the world on average: about one box in five touches another. Whole
    pixels make ``Rect`` and ``Box`` agree, so every method must return *the same pair set*,
    and the bench checks that it does.
  * **Testing every pair** is ``groupcollide(G, G)`` (each sprite against the whole group,
    in a Python loop), ``Rect.collidelistall`` for each rect (the same, but the inner loop
    is C) and :class:`~game.collision.broad.brute_force.BruteForce` (both loops in Python). All
    grow as N².
  * **The structures** grow about as N, so a log-log chart shows them as shallower lines.
    The *crossover* is the N from which a structure beats brute force at every larger N;
    below it the simple loop wins, which is why a scene with a dozen things needs no grid.
  * **Frame budgets.** The lines at 16.7 ms (a whole frame at 60 Hz) and 2 ms (a fair share
    of it for collision) show the N each method can afford. A method is not run at an N
    where it would take more than the run's budget per frame (2 s in a full run), so the
    slow lines stop early.
"""

from __future__ import annotations

import math
import random
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from statistics import median
from typing import Protocol

import pygame

from game.bench import charts
from game.bench.intervals import Interval, paired_ratio
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import Case, interleaved
from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhase, BruteForce, pair_of
from game.collision.broad.quadtree import Quadtree
from game.collision.broad.sort_and_sweep import SortAndSweep
from game.collision.broad.spatial_grid import SpatialGrid
from game.collision.methods import GRID_CELL_SIZE_FACTOR

CHART = "broad_phase"
SEED = 3
ITEM_MIN_PX, ITEM_MAX_PX = 8, 24
BODY_PX = (ITEM_MIN_PX + ITEM_MAX_PX) / 2   # the typical body size the grid's cells follow
PATCH_PX = 64                               # each item has this square of world on average
JITTER_PX = 2                               # how far an item moves per frame, each axis

Pairs = set[tuple[int, int]]
PIXEL = pygame.Surface((1, 1))   # every sprite needs an image; none is ever drawn here


def crowd(n: int, seed: int = SEED) -> tuple[list[Box], list[Box]]:
    """N whole-pixel boxes, and the same boxes one frame later (each moved up to 2 px)."""
    rng = random.Random(f"{seed}:{n}")
    side = round(PATCH_PX * math.sqrt(n))
    now = [Box(rng.randrange(side), rng.randrange(side), rng.randint(ITEM_MIN_PX, ITEM_MAX_PX),
               rng.randint(ITEM_MIN_PX, ITEM_MAX_PX)) for _ in range(n)]
    later = [box.moved(rng.randint(-JITTER_PX, JITTER_PX), rng.randint(-JITTER_PX, JITTER_PX))
             for box in now]
    return now, later


class Stepper(Protocol):
    """A method holding a crowd: ``step`` tells it the new boxes and finds the pairs."""

    def step(self, boxes: list[Box]) -> Pairs | None: ...

    def pairs(self) -> Pairs: ...


class Item(pygame.sprite.Sprite):
    """A sprite for one box; ``index`` names it in the pair set."""

    image: pygame.Surface
    rect: pygame.Rect

    def __init__(self, index: int, box: Box) -> None:
        super().__init__()
        self.index = index
        self.image = PIXEL
        self.rect = box.to_rect()


class GroupCollide:
    """``pygame.sprite.groupcollide(G, G, False, False)``; every sprite also hits itself."""

    def __init__(self, boxes: list[Box]) -> None:
        self.items = [Item(i, box) for i, box in enumerate(boxes)]
        self.group: pygame.sprite.Group[Item] = pygame.sprite.Group(self.items)
        self.found: dict[Item, list[Item]] = {}

    def step(self, boxes: list[Box]) -> None:
        for item, box in zip(self.items, boxes, strict=True):
            item.rect.topleft = (int(box.x), int(box.y))
        self.found = pygame.sprite.groupcollide(self.group, self.group, False, False)

    def pairs(self) -> Pairs:
        return {pair_of(a.index, b.index) for a, hits in self.found.items()
                for b in hits if a is not b}


class CollideListAll:
    """``rect.collidelistall(rects)`` for every rect: brute force with a C inner loop."""

    def __init__(self, boxes: list[Box]) -> None:
        self.rects = [box.to_rect() for box in boxes]
        self.found: list[list[int]] = []

    def step(self, boxes: list[Box]) -> None:
        rects = self.rects
        for rect, box in zip(rects, boxes, strict=True):
            rect.topleft = (int(box.x), int(box.y))
        self.found = [rect.collidelistall(rects) for rect in rects]

    def pairs(self) -> Pairs:
        return {(i, j) for i, hits in enumerate(self.found) for j in hits if i < j}


class Structure:
    """Any :class:`~game.collision.broad.brute_force.BroadPhase`: ``move`` every item, then
    ``pairs()``."""

    def __init__(self, phase: BroadPhase[int], boxes: list[Box]) -> None:
        self.phase = phase
        self.found: Pairs = set()
        for i, box in enumerate(boxes):
            phase.insert(i, box)

    def step(self, boxes: list[Box]) -> None:
        move = self.phase.move
        for i, box in enumerate(boxes):
            move(i, box)
        self.found = self.phase.pairs()

    def pairs(self) -> Pairs:
        return self.found


def world_bounds(boxes: list[Box]) -> Box:
    """A square around every box, with room for the jitter (the quadtree's root)."""
    side = max(max(b.right for b in boxes), max(b.bottom for b in boxes)) + 2 * JITTER_PX
    return Box(-JITTER_PX, -JITTER_PX, side + JITTER_PX, side + JITTER_PX)


def grid_factory(cell_factor: float) -> Callable[[list[Box]], Stepper]:
    return lambda boxes: Structure(SpatialGrid(cell_size_px=cell_factor * BODY_PX), boxes)


GRID = "grid"
BRUTE = "brute force (BroadPhase)"
GROUPCOLLIDE = "groupcollide(G, G)"
COLLIDELISTALL = "Rect.collidelistall per item"
TARGETED = (GRID, GROUPCOLLIDE, COLLIDELISTALL)   # the methods the targets compare
METHODS: dict[str, Callable[[list[Box]], Stepper]] = {
    GROUPCOLLIDE: GroupCollide,
    COLLIDELISTALL: CollideListAll,
    BRUTE: lambda boxes: Structure(BruteForce(), boxes),
    GRID: grid_factory(GRID_CELL_SIZE_FACTOR),
    "quadtree": lambda boxes: Structure(Quadtree(world_bounds(boxes)), boxes),
    "sort and sweep": lambda boxes: Structure(SortAndSweep(), boxes),
}


@dataclass
class Frames:
    """A case's state: the method and which of the two position sets comes next."""

    stepper: Stepper
    positions: tuple[list[Box], list[Box]]
    turn: int = 0

    def frame(self) -> None:
        self.turn ^= 1
        self.stepper.step(self.positions[self.turn])


def pair_sets(makers: dict[str, Callable[[list[Box]], Stepper]], n: int) -> dict[str, Pairs]:
    """Every method's pairs for the same crowd, one frame in (for the equality check)."""
    now, later = crowd(n)
    found: dict[str, Pairs] = {}
    for name, make in makers.items():
        stepper = make(now)
        stepper.step(later)
        found[name] = stepper.pairs()
    return found


def time_frames(makers: dict[str, Callable[[list[Box]], Stepper]], n: int, sizes: Sizes,
                rounds: int | None = None) -> dict[str, list[float]]:
    """Seconds per frame for each method at one N, all methods in the same rounds."""
    now, later = crowd(n)
    cases = [Case(name, Frames(make(now), (now, later)).frame) for name, make in makers.items()]
    return interleaved(cases, rounds or sizes.rounds, sizes.min_s)


def measure(sizes: Sizes) -> list[Row]:
    """Time per frame against N. A method is not run at an N where its last time, grown as
    N², would exceed the budget (brute force grows as N²; the structures grow slower). At
    the targets' N the methods the targets compare always run, in ``verdict_rounds``
    rounds of their own; the rest in the usual rounds."""
    rows: list[Row] = []
    last: dict[str, tuple[int, float]] = {}   # method -> (N, seconds per frame) last measured
    for n in sizes.broad_ns:
        running = {name: make for name, make in METHODS.items()
                   if name not in last or last[name][1] * (n / last[name][0]) ** 2
                   <= sizes.broad_budget_s or (n == sizes.target_n and name in TARGETED)}
        if not running:
            break
        reference = pair_sets({GRID: METHODS[GRID]}, n)[GRID]
        for name, found in pair_sets(running, n).items():
            rows.append(Row(CHART, name, str(n), 0, len(found ^ reference),
                            "pairs unlike the grid's"))
        rows.append(Row(CHART, GRID, str(n), 0, len(reference), "pairs found"))
        groups = [(running, sizes.rounds)]
        if n == sizes.target_n:
            groups = [({m: running[m] for m in TARGETED}, sizes.verdict_rounds),
                      ({m: f for m, f in running.items() if m not in TARGETED}, sizes.rounds)]
        for makers, rounds in groups:
            for name, seconds in time_frames(makers, n, sizes, rounds).items():
                rows += [Row(CHART, name, str(n), r, s * 1e3, "ms/frame")
                         for r, s in enumerate(seconds)]
                last[name] = (n, median(seconds))
    return rows


def medians(rows: list[Row], method: str) -> dict[int, float]:
    """Median ms per frame at each N measured for a method."""
    ns = sorted({int(r.parameter) for r in rows if r.method == method and r.unit == "ms/frame"})
    return {n: median(values(rows, method=method, parameter=str(n), unit="ms/frame"))
            for n in ns}


def verdict_n(rows: list[Row]) -> int | None:
    """The N at which the grid was timed in more rounds than elsewhere (the targets' N)."""
    counts = Counter(int(r.parameter) for r in rows if r.method == GRID and r.unit == "ms/frame")
    if len(set(counts.values())) < 2:
        return None
    return max(counts, key=lambda n: (counts[n], n))


def faster_than(rows: list[Row], baseline: str, n: int) -> Interval:
    """How many times faster the grid was than ``baseline`` at N, with its interval."""
    return paired_ratio(values(rows, method=baseline, parameter=str(n), unit="ms/frame"),
                            values(rows, method=GRID, parameter=str(n), unit="ms/frame"))


def crossover(rows: list[Row], structure: str, baseline: str) -> int | None:
    """The smallest N from which ``structure`` is faster than ``baseline`` at every larger N.

    Where the baseline was retired (too slow to run), the structure counts as faster.
    """
    mine, theirs = medians(rows, structure), medians(rows, baseline)
    winning_from: int | None = None
    for n, ms in mine.items():
        if n in theirs and ms >= theirs[n]:
            winning_from = None
        elif winning_from is None:
            winning_from = n
    return winning_from


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("Broad phase: time to find every overlapping pair among N movers",
                               width_in=10, height_in=6.5)
    axes = figure.add_subplot()
    for index, method in enumerate(METHODS):
        points = medians(rows, method)
        axes.plot(list(points), list(points.values()), marker="o", markersize=4,
                  color=charts.colour(index), label=method)
    for ms, label in ((charts.FRAME_BUDGET_MS, "16.7 ms: a whole frame at 60 Hz"),
                      (charts.TICK_SHARE_MS, "2 ms: collision's share of a frame")):
        axes.axhline(ms, color="#888888", linestyle="--", linewidth=1)
        axes.annotate(label, (0.01, ms), xycoords=("axes fraction", "data"), fontsize=8,
                      color="#555555", va="bottom")
    grid_colour = charts.colour(list(METHODS).index(GRID))
    n = crossover(rows, GRID, BRUTE)
    if n is not None:
        axes.axvline(n, color=grid_colour, linestyle=":")
        axes.annotate(f" crossover: the grid beats brute force from N = {n:,}", (n, 0.93),
                      xycoords=("data", "axes fraction"), fontsize=9)
    others = [(name, crossover(rows, GRID, name)) for name in (GROUPCOLLIDE, COLLIDELISTALL)]
    lines = [f" the grid beats {name} from N = {at:,}" if at else
             f" the grid never beats {name} here" for name, at in others]
    target_n = verdict_n(rows)
    if target_n is not None:
        lines += [f" at N = {target_n:,}, the grid is {faster_than(rows, name, target_n).text()}x "
                  f"faster than {name} [95 % interval]" for name in (GROUPCOLLIDE, COLLIDELISTALL)]
    axes.annotate("\n".join(lines), (n or 10, 0.80), xycoords=("data", "axes fraction"),
                  fontsize=8, color="#444444", va="top")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("N, movers in the scene (log scale)")
    axes.set_ylabel("time per frame, median (ms, log scale)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=8, loc="lower right")
    return charts.save(figure, out / f"{CHART}.png", footnote)
