"""The benchmark: what each collision method costs, how often it is wrong, and what to choose.

Run ``python -m game.bench`` (a few minutes) or ``python -m game.bench --quick`` (under a
minute); the CSVs, the PNG charts, the targets and a README that reads the charts go to
``assets/charts/`` unless ``--out DIR`` says otherwise; ``--check`` makes a failed target
exit with status 1; ``--redraw`` draws the charts, targets and README again from the CSVs a
run left in DIR, measuring nothing. matplotlib and numpy are needed here only: the game
never imports this package. Arcade, for the peer, comes with the optional extra
``pip install -e '.[peers]'``; without it the peer is skipped and the run says so.

Read it in this order, one concept per module:

* :mod:`~game.bench.timing`: fair timing (interleaved rounds, medians, the collector off).
* :mod:`~game.bench.intervals`: how sure a ratio is (a bootstrap 95 % interval).
* :mod:`~game.bench.peer`: this game's moves beside Arcade's platformer engine and the
  pygame tutorial loop, against :mod:`~game.bench.plain_sweep`, the floor.
* :mod:`~game.bench.narrow`: chart 1, cost against error of the narrow-phase tests.
* :mod:`~game.bench.tunnelling`: chart 2, fast bodies against thin walls.
* :mod:`~game.bench.broad`: chart 3, finding the pairs among N movers.
* :mod:`~game.bench.grid_cells`: the spatial grid's cell size.
* :mod:`~game.bench.walls`: chart 4, one body against a growing tile map.
* :mod:`~game.bench.caching`: chart 5, ``obj.rect`` against copies of it.
* :mod:`~game.bench.game_step`: the game's own collision step per tick.
* :mod:`~game.bench.targets`: the ratios the project promises, each passing only when its
  whole interval clears its limit.
* :mod:`~game.bench.run` runs them all; :mod:`~game.bench.records`,
  :mod:`~game.bench.charts`, :mod:`~game.bench.machine`, :mod:`~game.bench.sizes` and
  :mod:`~game.bench.readme` are the plumbing.

The thresholds the game uses (:mod:`game.collision.methods`) cite the committed run of this bench.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from game.bench.sizes import Sizes
    from game.bench.targets import Target


def main(argv: Sequence[str] | None = None) -> int:
    """Run the bench; 0 when done, 1 with ``--check`` and a failed target, 2 bad usage."""
    os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
    os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
    from game.bench.run import DEFAULT_OUT
    from game.bench.sizes import FULL, QUICK

    parser = argparse.ArgumentParser(
        prog="python -m game.bench",
        description="Measure the collision methods, draw the charts, check the targets.")
    parser.add_argument("--quick", action="store_true",
                        help="fewer rounds and a smaller top N: under a minute")
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT, metavar="DIR",
                        help=f"where the CSVs and charts go (default {DEFAULT_OUT})")
    parser.add_argument("--check", action="store_true",
                        help="exit with status 1 if any target fails")
    parser.add_argument("--redraw", action="store_true",
                        help="measure nothing: draw the charts, targets and README again from "
                             "the CSVs already in DIR (made by a run of the same size)")
    args = parser.parse_args(argv)
    from game.app.files import FileProblem, folder_problem

    if (problem := folder_problem(args.out)) is not None:
        parser.error(f"--out: {problem}")
    sizes = QUICK if args.quick else FULL
    echo = lambda line: print(line, flush=True)  # noqa: E731
    try:
        checked = _measure_or_redraw(args.redraw, sizes, args.out, echo)
    except FileProblem as problem:  # a file of DIR that cannot be read or written
        print(f"game.bench: {problem}", file=sys.stderr)
        return 1
    if checked is None:
        return 2
    width = max(len(t.claim) for t in checked)
    for target in checked:
        _, measured, limit, _ = target.row()
        note = target.skipped or target.note
        print(f"  {target.verdict:<7}  {target.claim:<{width}}  {measured}  (limit {limit})"
              + (f"  [{note}]" if note else ""))
    failed = [t for t in checked if t.verdict == "FAIL"]
    skipped = [t for t in checked if t.skipped]
    print(f"{sum(t.passed for t in checked)} of {len(checked)} targets met"
          + (f", {len(skipped)} skipped" if skipped else "") + ".")
    return 1 if args.check and failed else 0


def _measure_or_redraw(again: bool, sizes: Sizes, out: Path,
                       echo: Callable[[str], None]) -> list[Target] | None:
    """Measure into ``out`` (or, ``again``, redraw from its CSVs); the targets checked, or
    None when there is nothing to redraw from (said on stderr)."""
    from game.bench.run import CHARTS, redraw, run

    if again:
        missing = [c.name for c in CHARTS if not (out / f"{c.name}.csv").is_file()]
        if missing:
            print(f"game.bench: {out}: no {missing[0]}.csv to redraw from; run "
                  "python -m game.bench first", file=sys.stderr)
            return None
        print(f"game.bench: redrawing the {sizes.name} run in {out}", flush=True)
        return redraw(sizes, out, echo)[1]
    print(f"game.bench: {sizes.name} run, writing to {out}", flush=True)
    return run(sizes, out, echo)[1]
