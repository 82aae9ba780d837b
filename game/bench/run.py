"""One bench run: every measurement in order, its CSV and chart, then the targets and README.

Where it sits: called by ``python -m game.bench`` (:mod:`game.bench.__main__`) and by the
tests with tiny sizes. It owns the order of the run and the files written; each chart's
module owns what it measures and how it is drawn.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from time import perf_counter, process_time

from game.app.files import write_text_atomically
from game.bench import (
    broad,
    caching,
    game_step,
    grid_cells,
    machine,
    narrow,
    peer,
    readme,
    targets,
    tunnelling,
    walls,
)
from game.bench.records import Row, read_csv, write_csv
from game.bench.sizes import Sizes

DEFAULT_OUT = Path(__file__).resolve().parent.parent.parent / "assets" / "charts"


@dataclass(frozen=True)
class Chart:
    """A chart's name (its CSV and PNG), how to measure it and how to draw it."""

    name: str
    measure: Callable[[Sizes], list[Row]]
    draw: Callable[[list[Row], Path, str], Path]


CHARTS = (
    Chart(peer.CHART, peer.measure, peer.draw),
    Chart(narrow.CHART, narrow.measure, narrow.draw),
    Chart(tunnelling.CHART, tunnelling.measure, tunnelling.draw),
    Chart(broad.CHART, broad.measure, broad.draw),
    Chart(grid_cells.CHART, grid_cells.measure, grid_cells.draw),
    Chart(walls.CHART, walls.measure, walls.draw),
    Chart(caching.CHART, caching.measure, caching.draw),
    Chart(game_step.CHART, game_step.measure, game_step.draw),
)


def command(sizes: Sizes) -> str:
    """The command that makes a run of these sizes."""
    return "python -m game.bench" + ("" if sizes.name == "full" else f" --{sizes.name}")


def run(sizes: Sizes, out: Path, echo: Callable[[str], None] = print,
        ) -> tuple[dict[str, list[Row]], list[targets.Target]]:
    """Measure, write ``<chart>.csv`` and ``<chart>.png`` for every chart, then the targets
    (``targets.csv``, ``targets.md``, ``targets.png``) and ``README.md``."""
    out.mkdir(exist_ok=True)
    footnote = f"{machine.footnote()} · made by {command(sizes)}"
    results: dict[str, list[Row]] = {}
    for chart in CHARTS:
        started, cpu = perf_counter(), process_time()
        write_csv(out / f"{chart.name}.csv", chart.measure(sizes))
        # The charts and targets are drawn from the rows as written (six digits), so a
        # redraw from the CSVs gives the same figures to the last digit printed.
        rows = results[chart.name] = read_csv(out / f"{chart.name}.csv", just_written=True)
        chart.draw(rows, out, footnote)
        echo(f"{chart.name:>14}: {perf_counter() - started:5.1f} s ({process_time() - cpu:4.1f} s "
             f"CPU)  -> {chart.name}.png, .csv")
    return results, conclude(results, sizes, out, footnote, echo)


def redraw(sizes: Sizes, out: Path, echo: Callable[[str], None] = print,
           ) -> tuple[dict[str, list[Row]], list[targets.Target]]:
    """Draw the charts, the targets and the README again from the CSVs already in ``out``
    (measured by a run of these sizes on this machine), measuring nothing."""
    footnote = f"{machine.footnote()} · made by {command(sizes)}"
    results = {chart.name: read_csv(out / f"{chart.name}.csv") for chart in CHARTS}
    for chart in CHARTS:
        chart.draw(results[chart.name], out, footnote)
        echo(f"{chart.name:>14}: redrawn from {chart.name}.csv")
    return results, conclude(results, sizes, out, footnote, echo)


def conclude(results: dict[str, list[Row]], sizes: Sizes, out: Path, footnote: str,
             echo: Callable[[str], None]) -> list[targets.Target]:
    """Check the targets and write them, their chart and the README; note any threshold of
    :mod:`game.collision.methods` this run disagrees with."""
    started = perf_counter()
    checked = targets.check(results, sizes)
    write_text_atomically(out / "targets.csv", targets.csv_text(checked))
    write_text_atomically(out / "targets.md", targets.markdown(checked) + "\n")
    targets.draw(checked, out, footnote)
    write_text_atomically(out / "README.md", readme.text(results, checked, sizes, footnote))
    echo(f"{'targets':>14}: {perf_counter() - started:5.1f} s  -> targets.csv, .md, .png, "
         "README.md")
    for name, in_code, measured in readme.choices(results):
        if in_code != measured:
            echo(f"note: game/collision/methods.py has {name} = {in_code}; "
                 f"this run measured {measured}")
    return checked
