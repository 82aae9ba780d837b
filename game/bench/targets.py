"""The targets: ratios measured side by side in one run, checked and written down.

Where it sits: after the charts in ``python -m game.bench``. Most targets read the rows the
charts were drawn from; the broad-phase targets time the grid against ``groupcollide(G, G)``
at N = 1,000 and 5,000 in rounds of their own (the quick run's chart stops short of 5,000).

What it teaches: a performance claim is a ratio between two methods measured in the same
rounds on the same machine, next to a correctness check that the two give the same answer.
Absolute times change with the machine; ratios mostly do not, and a target that compares a
method with itself (the tile lookup on a small and on a big map) says how it *scales*.

>>> t = Target("grid vs groupcollide at N = 1,000", 21.4, ">=", 15.0, "x faster")
>>> t.passed, t.row()
(True, ['grid vs groupcollide at N = 1,000', '21.4x faster', '>= 15x faster', 'pass'])
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from statistics import median

from game.bench import broad, game_step, tunnelling, walls
from game.bench.records import Row, markdown_table, values
from game.bench.sizes import Sizes

CHART = "targets"
GRID_VS_GROUPCOLLIDE = {1000: 15.0, 5000: 50.0}   # at the quick and full runs' target N
LOOKUP_VS_SPRITES = 30.0
LOOKUP_GROWTH = 1.5
DISCRETE_VS_ANALYTIC_PP = 1.0
P95_MS = 2.0
WIDTH_GROWTH = 1.5


@dataclass(frozen=True)
class Target:
    """One claim: ``measured`` must be ``comparison`` (``>=`` or ``<=``) ``limit``."""

    claim: str
    measured: float
    comparison: str
    limit: float
    unit: str
    holds_also: bool = True    # a correctness condition that goes with it (same answers)
    note: str = ""

    @property
    def passed(self) -> bool:
        in_limit = (self.measured >= self.limit if self.comparison == ">="
                    else self.measured <= self.limit)
        return in_limit and self.holds_also

    def row(self) -> list[str]:
        return [self.claim, f"{self.measured:#.3g}{_gap(self.unit)}{self.unit}",
                f"{self.comparison} {self.limit:g}{_gap(self.unit)}{self.unit}",
                ("pass" if self.passed else "FAIL") + (f" ({self.note})" if self.note else "")]


def _gap(unit: str) -> str:
    return "" if unit.startswith("x") else " "


def broad_targets(sizes: Sizes) -> tuple[list[Target], list[Row]]:
    """The grid against groupcollide(G, G), timed side by side, with equal pair sets."""
    targets: list[Target] = []
    rows: list[Row] = []
    makers = {name: broad.METHODS[name] for name in (broad.GRID, broad.GROUPCOLLIDE)}
    for n, limit in zip(sizes.target_ns, GRID_VS_GROUPCOLLIDE.values(), strict=True):
        found = broad.pair_sets(makers, n)
        same = found[broad.GRID] == found[broad.GROUPCOLLIDE]
        times = broad.time_frames(makers, n, sizes)
        rows += [Row(CHART, name, str(n), r, s * 1e3, "ms/frame")
                 for name, seconds in times.items() for r, s in enumerate(seconds)]
        ratio = median(times[broad.GROUPCOLLIDE]) / median(times[broad.GRID])
        targets.append(Target(
            f"grid vs groupcollide(G, G), N = {n:,}, same pair set", ratio, ">=", limit,
            "x faster", same, f"{len(found[broad.GRID])} pairs, "
            + ("identical sets" if same else "PAIR SETS DIFFER")))
    return targets, rows


def wall_targets(rows: list[Row], sizes: Sizes) -> list[Target]:
    small, big = (f"{c}x{r}" for c, r in sizes.target_maps)

    def cost(method: str, wall_map: str) -> float:
        return median(values(rows, method=method, parameter=wall_map, unit="µs/query"))

    agree = all(values(rows, method="map", unit="methods agree (1 = yes)"))
    return [
        Target(f"tile lookup vs spritecollide over all walls, {small} map",
               cost(walls.SPRITES, small) / cost(walls.LOOKUP, small), ">=",
               LOOKUP_VS_SPRITES, "x faster", agree, "same walls found" if agree
               else "ANSWERS DIFFER"),
        Target(f"tile lookup on {big} against {small}",
               cost(walls.LOOKUP, big) / cost(walls.LOOKUP, small), "<=", LOOKUP_GROWTH,
               "x the time"),
    ]


def tunnelling_targets(rows: list[Row]) -> list[Target]:
    swept = max(values(rows, method=tunnelling.SWEPT, unit="% missed"))
    fastest = max(float(r.parameter) for r in rows if r.method == tunnelling.SWEPT)
    return [
        Target(f"swept AABB: tunnelled flights up to {fastest:g} tiles per tick", swept, "<=",
               0.0, "% of flights"),
        Target("self-check: discrete miss rate against 1 - (T + S) / v",
               tunnelling.worst_gap(rows, tunnelling.DISCRETE, tunnelling.ANALYTIC), "<=",
               DISCRETE_VS_ANALYTIC_PP, "percentage points", note="worst speed"),
    ]


def game_targets(rows: list[Row]) -> list[Target]:
    level = next(r.method for r in rows if r.parameter == "p95")
    largest = next(r for r in rows if r.parameter == "is played")
    won = all(values(rows, parameter="won"))
    note = "played to the exit" if won else "THE SCRIPT DID NOT WIN"
    if not largest.value:
        note += f"; NOT THE LARGEST LEVEL: {largest.method.split(': ')[1]} has no script yet"
    return [
        Target(f"collision step per tick, 95th percentile, {level}", game_step.p95_ms(rows),
               "<=", P95_MS, "ms", won and bool(largest.value), note),
        Target(f"update time, level {game_step.WIDTH_FACTOR}x wider with the same bodies",
               game_step.width_ratio(rows), "<=", WIDTH_GROWTH, "x the time"),
    ]


HEADER = ["target", "measured", "limit", "result"]


def markdown(targets: list[Target]) -> str:
    return markdown_table(HEADER, [t.row() for t in targets])


def csv_text(targets: list[Target]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["target", "measured", "comparison", "limit", "unit", "passed", "note"])
    for t in targets:
        writer.writerow([t.claim, f"{t.measured:.6g}", t.comparison, f"{t.limit:g}", t.unit,
                         t.passed, t.note])
    return buffer.getvalue()
