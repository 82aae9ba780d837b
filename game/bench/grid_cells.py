"""The grid's cell size: time per frame of the same crowd for cells of several sizes.

Where it sits: after the broad-phase chart in ``python -m game.bench``, on the same crowds and
frames (:mod:`game.bench.broad`). Its result sets
:data:`game.collision.methods.GRID_CELL_SIZE_FACTOR`.

What it teaches: a spatial grid has one knob, and both ends of it are slow. Cells much smaller
than a body file every body under many cells (more bookkeeping per move, the same pair met
in several cells); cells much larger hold crowds that are tested pair by pair, brute force in
miniature. The sweet spot is a small multiple of the typical body, found by measuring.
"""

from __future__ import annotations

from pathlib import Path
from statistics import median

from game.bench import broad, charts
from game.bench.records import Row, values
from game.bench.sizes import Sizes

CHART = "grid_cells"
NEAR_FASTEST = 0.05   # a factor within 5 % of the fastest time counts as fast as it


def measure(sizes: Sizes) -> list[Row]:
    """The grid's time per frame at one N for each cell size (in typical body sizes)."""
    makers = {f"{factor:g}": broad.grid_factory(factor) for factor in sizes.grid_cell_factors}
    method = f"grid, N = {sizes.grid_cell_n:,}"
    return [Row(CHART, method, factor, r, s * 1e3, "ms/frame")
            for factor, seconds in broad.time_frames(makers, sizes.grid_cell_n, sizes,
                                                     sizes.verdict_rounds).items()
            for r, s in enumerate(seconds)]


def fastest(rows: list[Row]) -> str:
    """The smallest cell-size factor whose median time per frame is within
    ``NEAR_FASTEST`` of the fastest one's.

    The curve is flat around its bottom, so "the single fastest" would hop between
    neighbours from run to run on noise; the smallest factor that is as good as the
    fastest, within a stated tolerance, stays put.
    """
    ms = {f: median(values(rows, parameter=f)) for f in {r.parameter for r in rows}}
    best = min(ms.values())
    return min((f for f, t in ms.items() if t <= best * (1 + NEAR_FASTEST)), key=float)


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    method = rows[0].method
    factors = sorted({float(r.parameter) for r in rows})
    ms = [median(values(rows, parameter=f"{f:g}", unit="ms/frame")) for f in factors]
    figure = charts.new_figure(f"Spatial grid: time per frame against cell size ({method})",
                               width_in=7.5, height_in=4.5)
    axes = figure.add_subplot()
    axes.plot(factors, ms, marker="o", color=charts.colour(list(broad.METHODS).index(broad.GRID)))
    axes.set_xlabel(f"cell size (multiples of the typical body, {broad.BODY_PX:g} px)")
    axes.set_ylabel("time per frame, median (ms)")
    axes.set_ylim(bottom=0)
    axes.grid(True, alpha=0.3)
    return charts.save(figure, out / f"{CHART}.png", footnote)
