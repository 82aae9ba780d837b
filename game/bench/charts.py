"""What every chart shares: a figure with a title, a footnote naming the machine, saved as PNG.

Where it sits: used by each bench module's ``draw`` function. Only matplotlib's
object-oriented API is used, on the Agg backend: no window, no pyplot global state, so the
bench runs headless and the game itself never imports matplotlib.

What it teaches: a chart is read without its author, so it carries its own title, axis
labels with units, and (in the footnote) the machine and versions that produced it.

>>> pareto_front([(1.0, 5.0), (2.0, 1.0), (3.0, 2.0), (4.0, 0.0)])
[(1.0, 5.0), (2.0, 1.0), (4.0, 0.0)]
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.layout_engine import ConstrainedLayoutEngine

from game.app.files import write_atomically

# One colour per method across every chart (matplotlib's colour-blind-friendly cycle).
PALETTE = ("#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7", "#56B4E9", "#000000",
           "#F0E442")
FRAME_BUDGET_MS = 1000 / 60   # one frame at 60 frames a second
TICK_SHARE_MS = 2.0           # the share of a frame the collision work may take
DPI = 110                     # dots per inch of every PNG


def new_figure(title: str, width_in: float = 9.0, height_in: float = 6.0) -> Figure:
    """A blank figure with its title (room is left at the bottom for the footnote)."""
    figure = Figure(figsize=(width_in, height_in), dpi=DPI,
                    layout=ConstrainedLayoutEngine(rect=(0, 0.03, 1, 0.97)))
    figure.suptitle(title, fontsize=13, fontweight="bold")
    return figure


def save(figure: Figure, path: Path, footnote: str) -> Path:
    """Add the footnote and write the PNG.

    The canvas draws the figure once, laying it out first; ``savefig`` would draw it twice
    (once drawing nothing, only to lay it out) for the same picture.
    """
    figure.text(0.005, 0.002, footnote, fontsize=7, color="#555555", ha="left", va="bottom")
    canvas = FigureCanvasAgg(figure)

    def write(tmp: Path) -> None:
        canvas.print_png(tmp)  # type: ignore[no-untyped-call]  # the Agg canvas has no hints

    write_atomically(path, write, ".png")
    return path


def colour(index: int) -> str:
    return PALETTE[index % len(PALETTE)]


def pareto_front(points: Iterable[tuple[float, float]]) -> list[tuple[float, float]]:
    """The points no other point beats on both axes (lower cost, lower error), by cost.

    A method is on the front when every faster method makes more mistakes.
    """
    front: list[tuple[float, float]] = []
    for cost, error in sorted(points):
        if not front or error < front[-1][1]:
            front.append((cost, error))
    return front


def table_figure(title: str, header: Sequence[str], body: Sequence[Sequence[str]],
                 first_column_share: float = 0.4) -> Figure:
    """A figure holding nothing but a table (for results that are a table, not a plot)."""
    figure = new_figure(title, width_in=10.0, height_in=1.4 + 0.4 * len(body))
    axes = figure.add_subplot()
    axes.axis("off")
    rest = (1 - first_column_share) / (len(header) - 1)
    table = axes.table(cellText=[list(r) for r in body], colLabels=list(header), loc="center",
                       cellLoc="left", colLoc="left",
                       colWidths=[first_column_share] + [rest] * (len(header) - 1))
    table.auto_set_font_size(False)
    table.set_fontsize(10)
    table.scale(1.0, 1.6)
    return figure
