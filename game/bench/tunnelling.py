"""Chart 2, tunnelling: how often each method lets a fast body fly through a one-tile wall.

Where it sits: the second chart of ``python -m game.bench``. It flies a body head-on at a
wall with every method of :mod:`game.collision.swept` and counts what each one misses; no timing, so
its results are the same on every machine.

What it teaches:
  * **The set-up.** A body ``S`` = 12 px wide (the player's hitbox) flies along x at ``v``
    px per tick towards a wall ``T`` = 16 px thick (one tile), from four tiles away plus a
    random *phase*: where, within one tick's move, the flight happens to start.
  * **The discrete check** only looks at where the body is at the end of each tick. The body
    overlaps the wall while its left edge lies in an open interval ``T + S`` long, and the
    checked positions are ``v`` apart, so a random phase misses the interval with
    probability ``1 - (T + S) / v`` once ``v > T + S``. The bench compares its measured
    miss rate with that formula: a self-check that the flights are set up right.
  * **Sub-stepping** with ``k`` checks per tick misses once ``v / k > T + S``; with
    ``steps_needed`` (no step longer than the body) it misses nothing head-on, at the price
    of ``v / S`` tests per tick.
  * **Clamping the speed** to one body width per tick misses nothing either, but the body
    arrives late: the delay in ticks grows with the speed it was not allowed to reach.
  * **Swept AABB** finds the exact moment of contact: no misses, zero depth, zero delay.
  * **Depth at detection** is how far inside the wall the body was when a method noticed:
    what the resolution then has to push back out (and what shows on screen for a frame).
"""

from __future__ import annotations

import random
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

from game.bench import charts
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.collision.aabb import Box
from game.collision.swept import (
    clamp_speed,
    discrete_hit,
    position_at,
    steps_needed,
    substep_hit,
    sweep,
)

CHART = "tunnelling"
SEED = 2
TILE_PX = 16
BODY_W_PX, BODY_H_PX = 12.0, 14.0                 # S: the player's hitbox
WALL = Box(0.0, -1000.0, TILE_PX, 2000.0)         # T = 16 px thick, too tall to fly over
START_GAP_PX = 4.0 * TILE_PX                      # plus a random phase of up to one tick
CLAMP_PX_PER_TICK = BODY_W_PX                     # the clamp's terminal speed: one body width

Check = Callable[[Box, float], float | None]  # (box at tick start, dx) -> fraction of the tick


class Detection(NamedTuple):
    """When a flight's contact was noticed (ticks from the start) and how deep it was (px)."""

    time_ticks: float
    depth_px: float


@dataclass(frozen=True)
class Method:
    name: str
    check: Check
    max_px_per_tick: float | None = None   # a speed clamp, applied before flying


def _discrete(box: Box, dx: float) -> float | None:
    return 1.0 if discrete_hit(box, dx, 0.0, WALL) else None


def _substeps(steps: int) -> Check:
    return lambda box, dx: substep_hit(box, dx, 0.0, WALL, steps)


def _enough_substeps(box: Box, dx: float) -> float | None:
    return substep_hit(box, dx, 0.0, WALL, steps_needed(box.w, dx))


def _swept(box: Box, dx: float) -> float | None:
    contact = sweep(box, dx, 0.0, WALL)
    return None if contact is None else contact.t


METHODS = (
    Method("discrete", _discrete),
    Method("sub-steps x2", _substeps(2)),
    Method("sub-steps x4", _substeps(4)),
    Method("sub-steps (steps_needed)", _enough_substeps),
    Method(f"clamp to {CLAMP_PX_PER_TICK:g} px/tick", _discrete, CLAMP_PX_PER_TICK),
    Method("swept AABB", _swept),
)
SWEPT = METHODS[-1].name
DISCRETE = METHODS[0].name
ANALYTIC = "analytic 1 - (T + S) / v"


def analytic_miss_rate(speed_px: float) -> float:
    """The discrete check's chance of missing the wall, for a uniformly random phase.

    >>> analytic_miss_rate(14.0), analytic_miss_rate(56.0)
    (0.0, 0.5)
    """
    return max(0.0, 1.0 - (WALL.w + BODY_W_PX) / speed_px)


def fly(method: Method, gap_px: float, speed_px: float) -> Detection | None:
    """One head-on flight from ``gap_px`` short of the wall; None if it passed through."""
    dx = speed_px
    if method.max_px_per_tick is not None:
        dx = clamp_speed(dx, 0.0, method.max_px_per_tick)[0]
    box = Box(WALL.left - gap_px - BODY_W_PX, 0.0, BODY_W_PX, BODY_H_PX)
    tick = 0
    while box.left < WALL.right:
        t = method.check(box, dx)
        if t is not None:
            return Detection(tick + t, position_at(box, dx, 0.0, t).right - WALL.left)
        box = box.moved(dx=dx)
        tick += 1
    return None


def gaps(speed_px: float, flights: int, seed: int) -> list[float]:
    """Start gaps with stratified random phases: one in each ``1/flights`` of a tick's move.

    Stratifying keeps the measured miss rate within ``1/flights`` of the true one, which is
    what lets the bench hold it to the formula.
    """
    rng = random.Random(f"{seed}:{speed_px}")
    return [START_GAP_PX + (i + rng.random()) / flights * speed_px for i in range(flights)]


def measure(sizes: Sizes) -> list[Row]:
    rows: list[Row] = []
    for tiles in sizes.tunnel_speeds:
        speed = tiles * TILE_PX
        parameter = f"{tiles:g}"
        starts = gaps(speed, sizes.tunnel_flights, SEED)
        rows.append(Row(CHART, ANALYTIC, parameter, 0, 100 * analytic_miss_rate(speed),
                        "% missed"))
        for method in METHODS:
            found = [(gap, fly(method, gap, speed)) for gap in starts]
            hits = [(gap, d) for gap, d in found if d is not None]
            missed = 100 * (len(found) - len(hits)) / len(found)
            rows.append(Row(CHART, method.name, parameter, 0, missed, "% missed"))
            if hits:
                depth = sum(d.depth_px for _, d in hits) / len(hits)
                late = sum(d.time_ticks - gap / speed for gap, d in hits) / len(hits)
                rows.append(Row(CHART, method.name, parameter, 0, depth, "px deep (mean)"))
                rows.append(Row(CHART, method.name, parameter, 0, late, "ticks late (mean)"))
    return rows


def worst_gap(rows: list[Row], method: str, reference: str) -> float:
    """The largest difference, in percentage points, between two methods' miss rates."""
    speeds = sorted({row.parameter for row in rows if row.method == reference})
    return max(abs(values(rows, method=method, parameter=s, unit="% missed")[0]
                   - values(rows, method=reference, parameter=s, unit="% missed")[0])
               for s in speeds)


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure(
        f"Tunnelling: a {BODY_W_PX:g} px body flying head-on at a {WALL.w:g} px wall",
        width_in=14, height_in=5.2)
    panels = figure.subplots(1, 3)
    units = (("% missed", "Missed contacts", "missed contacts (% of flights)"),
             ("px deep (mean)", "Depth at detection", "depth inside the wall, mean (px)"),
             ("ticks late (mean)", "Delay to contact", "detected minus true contact (ticks)"))
    for axes, (unit, title, label) in zip(panels, units, strict=True):
        axes.set_title(title)
        for index, method in enumerate(METHODS):
            speeds = [float(r.parameter) for r in rows if r.method == method.name and
                      r.unit == unit]
            axes.plot(speeds, values(rows, method=method.name, unit=unit), marker="o",
                      markersize=3, color=charts.colour(index), label=method.name)
        axes.set_xlabel("speed (tiles per tick; 1 tile = 16 px)")
        axes.set_ylabel(label)
        axes.grid(True, alpha=0.3)
    speeds = [float(r.parameter) for r in rows if r.method == ANALYTIC]
    panels[0].plot(speeds, values(rows, method=ANALYTIC), "k--", linewidth=1, label=ANALYTIC)
    panels[0].axvline((WALL.w + BODY_W_PX) / TILE_PX, color="#888888", linestyle=":")
    panels[0].annotate("v = T + S ", ((WALL.w + BODY_W_PX) / TILE_PX, 0.6), fontsize=8,
                       xycoords=("data", "axes fraction"), color="#555555", ha="right")
    panels[0].legend(fontsize=8)
    return charts.save(figure, out / f"{CHART}.png", footnote)
