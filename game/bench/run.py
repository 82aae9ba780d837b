"""One bench run: every measurement in order, its CSV and chart, then the targets and README.

Where it sits: called by ``python -m game.bench`` (:mod:`game.bench.__main__`) and by the
tests with tiny sizes. It owns the order of the run and the files written; each chart's
module owns what it measures and how it is drawn.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from time import perf_counter

from game.bench import (
    broad,
    caching,
    game_step,
    grid_cells,
    machine,
    narrow,
    readme,
    targets,
    tunnelling,
    walls,
)
from game.bench.records import Row, write_csv
from game.bench.sizes import Sizes

DEFAULT_OUT = Path(__file__).resolve().parent.parent.parent / "assets" / "charts"


@dataclass(frozen=True)
class Chart:
    """A chart's name (its CSV and PNG), how to measure it and how to draw it."""

    name: str
    measure: Callable[[Sizes], list[Row]]
    draw: Callable[[list[Row], Path, str], Path]


CHARTS = (
    Chart(narrow.CHART, narrow.measure, narrow.draw),
    Chart(tunnelling.CHART, tunnelling.measure, tunnelling.draw),
    Chart(broad.CHART, broad.measure, broad.draw),
    Chart(grid_cells.CHART, grid_cells.measure, grid_cells.draw),
    Chart(walls.CHART, walls.measure, walls.draw),
    Chart(caching.CHART, caching.measure, caching.draw),
    Chart(game_step.CHART, game_step.measure, game_step.draw),
)


def run(sizes: Sizes, out: Path, echo: Callable[[str], None] = print,
        ) -> tuple[dict[str, list[Row]], list[targets.Target]]:
    """Measure, write ``<chart>.csv`` and ``<chart>.png`` for every chart, then the targets
    (``targets.csv``, ``targets.md``, ``target_runs.csv``) and ``README.md``."""
    out.mkdir(parents=True, exist_ok=True)
    footnote = f"{machine.footnote()} · {sizes.name} run"
    results: dict[str, list[Row]] = {}
    for chart in CHARTS:
        started = perf_counter()
        rows = chart.measure(sizes)
        results[chart.name] = rows
        write_csv(out / f"{chart.name}.csv", rows)
        chart.draw(rows, out, footnote)
        echo(f"{chart.name:>14}: {perf_counter() - started:5.1f} s  -> {chart.name}.png, .csv")
    started = perf_counter()
    broad_checked, target_rows = targets.broad_targets(sizes)
    checked = [*broad_checked,
               *targets.wall_targets(results[walls.CHART], sizes),
               *targets.tunnelling_targets(results[tunnelling.CHART]),
               *targets.game_targets(results[game_step.CHART])]
    write_csv(out / "target_runs.csv", target_rows)
    (out / "targets.csv").write_text(targets.csv_text(checked), encoding="utf-8")
    (out / "targets.md").write_text(targets.markdown(checked) + "\n", encoding="utf-8")
    (out / "README.md").write_text(readme.text(results, checked, sizes, footnote),
                                   encoding="utf-8")
    echo(f"{'targets':>14}: {perf_counter() - started:5.1f} s  -> targets.csv, .md, README.md")
    for name, in_code, measured in readme.choices(results):
        if in_code != measured:
            echo(f"note: game/collision/methods.py has {name} = {in_code}; "
                 f"this run measured {measured}")
    return results, checked
