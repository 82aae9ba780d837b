"""The targets: ratios measured side by side in one run, each with its 95 % interval.

Where it sits: after the charts in ``python -m game.bench``. Every target reads the rows a
chart was drawn from, so the table, the charts and the README print the same figures.

What it teaches:
  * **A claim is a ratio between two methods timed in the same rounds** on the same
    machine, next to a check that the two give the same answers. Absolute times change
    with the machine and its load; ratios of interleaved rounds mostly do not. A method set
    against itself (the tile lookup on a small and a big map, a tick with few and with many
    platforms) says how it *scales*. No target here is an absolute time.
  * **Each ratio has a bootstrap 95 % interval** from at least 30 interleaved rounds
    (:mod:`game.bench.intervals`), and passes only when the whole interval clears the
    limit, so a verdict does not flip between runs on noise.
  * **Baselines are the strongest of their kind**: beside ``groupcollide`` and
    ``spritecollide`` (pygame's sprite calls, a Python loop around a C test) stands
    ``Rect.collidelistall`` (the same brute force with its loop in C), and every target
    names the baseline it beats and by how much.
  * A target that needs an optional package (Arcade) says *skipped* when it is missing.

>>> from game.bench.intervals import Interval
>>> t = Target("grid vs groupcollide", Interval(21.4, 19.0, 23.5), ">=", 10.0, "x faster")
>>> t.passed, t.row()
(True, ['grid vs groupcollide', '21.4x faster [19.0, 23.5]', '>= 10x faster', 'pass'])
>>> Target("lookup 800x160 vs 50x10", Interval(1.4, 1.3, 1.6), "<=", 1.5, "x the time").passed
False
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from pathlib import Path

from game.bench import broad, charts, game_step, peer, tunnelling, walls
from game.bench.intervals import Interval, paired_ratio
from game.bench.records import Row, markdown_table, values
from game.bench.sizes import Sizes

CHART = "targets"
GRID_VS_COLLIDELISTALL = 1.0        # the grid beats the C loop at N = 1,000 ...
GRID_VS_GROUPCOLLIDE = 10.0         # ... and pygame's sprite call by this much
LOOKUP_VS_SPRITES = 30.0            # the tile lookup against spritecollide over every wall
LOOKUP_VS_RECTS = 2.0               # ... and against collidelistall over every wall
LOOKUP_GROWTH = 1.5                 # the lookup on the biggest map against the smallest
MOVES_VS_FLOOR = 1.5                # move_x + move_y against the plain-float sweep
STEP_VS_FLOOR = 3.0                 # World.step per body against the plain-float sweep
MOVES_VS_ARCADE = 10.0              # Arcade's update against move_x + move_y
PLATFORM_GROWTH = 1.3               # a tick with 100 platforms against one with 2
WIDTH_GROWTH = 1.5                  # a level 20x wider with the same bodies
DISCRETE_VS_ANALYTIC_PP = 1.0


@dataclass(frozen=True)
class Target:
    """One claim: the whole interval of ``measured`` must be ``comparison`` ``limit``."""

    claim: str
    measured: Interval
    comparison: str
    limit: float
    unit: str
    holds_also: bool = True    # a correctness condition that goes with it (same answers)
    note: str = ""
    skipped: str = ""          # why it could not be measured in this run ("" = it was)

    @property
    def passed(self) -> bool:
        return (not self.skipped and self.holds_also
                and self.measured.clears(self.comparison, self.limit))

    @property
    def verdict(self) -> str:
        return "skipped" if self.skipped else "pass" if self.passed else "FAIL"

    def measured_text(self) -> str:
        if self.skipped:
            return "—"
        m = self.measured
        text = f"{m.estimate:#.3g}{_gap(self.unit)}{self.unit}"
        return text if m.low == m.high else f"{text} [{m.low:#.3g}, {m.high:#.3g}]"

    def row(self) -> list[str]:
        note = self.skipped or self.note
        return [self.claim, self.measured_text(),
                f"{self.comparison} {self.limit:g}{_gap(self.unit)}{self.unit}",
                self.verdict + (f" ({note})" if note else "")]


def _gap(unit: str) -> str:
    return "" if unit.startswith("x") else " "


def broad_targets(rows: list[Row], sizes: Sizes) -> list[Target]:
    """The grid against both brute-force baselines at the target N, with equal pair sets."""
    n = str(sizes.target_n)
    same = all(v == 0 for v in values(rows, parameter=n, unit="pairs unlike the grid's"))
    pairs = values(rows, method=broad.GRID, parameter=n, unit="pairs found")[0]
    note = f"{pairs:.0f} pairs, " + ("identical sets" if same else "PAIR SETS DIFFER")

    def faster(baseline: str) -> Interval:
        return paired_ratio(values(rows, method=baseline, parameter=n, unit="ms/frame"),
                                values(rows, method=broad.GRID, parameter=n, unit="ms/frame"))

    return [Target(f"grid beats {name}, N = {sizes.target_n:,}", faster(name), ">=", limit,
                   "x faster", same, note)
            for name, limit in ((broad.COLLIDELISTALL, GRID_VS_COLLIDELISTALL),
                                (broad.GROUPCOLLIDE, GRID_VS_GROUPCOLLIDE))]


def wall_targets(rows: list[Row], sizes: Sizes) -> list[Target]:
    small, big = (f"{c}x{r}" for c, r in sizes.target_maps)
    middle = "{}x{}".format(*sizes.baseline_map)

    def times(method: str, wall_map: str) -> list[float]:
        return values(rows, method=method, parameter=wall_map, unit="µs/query")

    agree = all(values(rows, method="map", unit="methods agree (1 = yes)"))
    note = "same walls found" if agree else "ANSWERS DIFFER"
    count = values(rows, method="map", parameter=middle, unit="walls")[0]
    return [
        Target(f"tile lookup beats {walls.SPRITES}, {middle} map ({count:,.0f} walls)",
               paired_ratio(times(walls.SPRITES, middle), times(walls.LOOKUP, middle)),
               ">=", LOOKUP_VS_SPRITES, "x faster", agree, note),
        Target(f"tile lookup beats {walls.RECTS}, {middle} map",
               paired_ratio(times(walls.RECTS, middle), times(walls.LOOKUP, middle)),
               ">=", LOOKUP_VS_RECTS, "x faster", agree, note),
        Target(f"tile lookup stays flat: {big} map against {small}",
               paired_ratio(times(walls.LOOKUP, big), times(walls.LOOKUP, small)),
               "<=", LOOKUP_GROWTH, "x the time"),
    ]


def tunnelling_targets(rows: list[Row]) -> list[Target]:
    swept = max(values(rows, method=tunnelling.SWEPT, unit="% missed"))
    fastest = max(float(r.parameter) for r in rows if r.method == tunnelling.SWEPT)
    return [
        Target(f"swept AABB: tunnelled flights up to {fastest:g} tiles per tick",
               Interval.exact(swept), "<=", 0.0, "% of flights"),
        Target("self-check: discrete miss rate against 1 - (T + S) / v",
               Interval.exact(tunnelling.worst_gap(rows, tunnelling.DISCRETE,
                                                   tunnelling.ANALYTIC)),
               "<=", DISCRETE_VS_ANALYTIC_PP, "percentage points", note="worst speed"),
    ]


def peer_targets(rows: list[Row]) -> list[Target]:
    """The game's moves and tick against the plain-float floor, and against Arcade."""
    moves = peer.figure_of(rows, "The Summit", "recorded moves")
    alike = peer.figure_of(rows, peer.PLAIN, peer.SAME)
    same = alike == moves
    floor = peer.per_update(rows, peer.PLAIN)
    ours = peer.per_update(rows, peer.GAME)
    found = [
        Target("move_x + move_y against the plain-float sweep, same moves",
               paired_ratio(ours, floor), "<=", MOVES_VS_FLOOR, "x the time", same,
               f"same end position on {alike:.0f} of {moves:.0f} recorded moves"),
        Target("World.step per body (The Summit) against the plain-float sweep",
               paired_ratio(peer.per_update(rows, peer.STEP), floor), "<=",
               STEP_VS_FLOOR, "x the time"),
    ]
    claim = "move_x + move_y beats Arcade's PhysicsEnginePlatformer.update, same moves"
    if peer.skipped(rows):
        found.append(Target(claim, Interval.exact(0.0), ">=", MOVES_VS_ARCADE, "x faster",
                            skipped="Arcade not installed: pip install -e '.[peers]'"))
        return found
    through = peer.tunnelled(rows, peer.GAME)
    theirs = peer.tunnelled(rows, peer.ARCADE)
    found.append(Target(claim, paired_ratio(peer.per_update(rows, peer.ARCADE), ours),
                        ">=", MOVES_VS_ARCADE, "x faster", through == 0,
                        f"tunnelled flights at 8-64 px/tick: this game {through}, "
                        f"Arcade {theirs}"))
    return found


def game_targets(rows: list[Row]) -> list[Target]:
    return [
        Target(f"a tick with {game_step.MANY_PLATFORMS} moving platforms against one with "
               f"{game_step.FEW_PLATFORMS}", game_step.ratio(rows, game_step.MANY,
                                                             game_step.FEW),
               "<=", PLATFORM_GROWTH, "x the time"),
        Target(f"a tick on a level {game_step.WIDTH_FACTOR}x wider with the same bodies",
               game_step.ratio(rows, game_step.WIDE, game_step.NARROW), "<=", WIDTH_GROWTH,
               "x the time"),
    ]


def check(results: dict[str, list[Row]], sizes: Sizes) -> list[Target]:
    """Every target, from the rows of one run's charts."""
    return [*peer_targets(results[peer.CHART]),
            *broad_targets(results[broad.CHART], sizes),
            *wall_targets(results[walls.CHART], sizes),
            *game_targets(results[game_step.CHART]),
            *tunnelling_targets(results[tunnelling.CHART])]


HEADER = ["target", "measured [95 % interval]", "limit", "result"]


def markdown(targets: list[Target]) -> str:
    return markdown_table(HEADER, [t.row() for t in targets])


def csv_text(targets: list[Target]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["target", "measured", "low", "high", "comparison", "limit", "unit",
                     "result", "note"])
    for t in targets:
        writer.writerow([t.claim, f"{t.measured.estimate:.6g}", f"{t.measured.low:.6g}",
                         f"{t.measured.high:.6g}", t.comparison, f"{t.limit:g}", t.unit,
                         t.verdict, t.skipped or t.note])
    return buffer.getvalue()


def draw(checked: list[Target], out: Path, footnote: str) -> Path:
    """Every ratio target as its estimate with the 95 % interval, beside its limit."""
    ratios = [t for t in checked if t.unit.startswith("x")]
    figure = charts.new_figure("Targets: each ratio with its 95 % interval, and its limit",
                               width_in=12, height_in=1.6 + 0.55 * len(ratios))
    axes = figure.add_subplot()
    for row, target in enumerate(ratios):
        colour = {"pass": "#009E73", "FAIL": "#D55E00"}.get(target.verdict, "#888888")
        axes.plot([target.limit], [row], marker="|", markersize=22, color="#333333")
        if target.skipped:
            axes.annotate(f"  skipped: {target.skipped}", (target.limit, row), va="center",
                          fontsize=8, color=colour)
            continue
        m = target.measured
        axes.errorbar([m.estimate], [row], xerr=[[m.estimate - m.low], [m.high - m.estimate]],
                      fmt="o", color=colour, capsize=4)
        axes.annotate(f"  {target.measured_text()}  ({target.comparison} {target.limit:g}: "
                      f"{target.verdict})", (max(m.high, target.limit), row), va="center",
                      fontsize=8, color=colour)
    axes.set_yticks(range(len(ratios)), [t.claim for t in ratios], fontsize=8)
    axes.invert_yaxis()
    axes.set_xscale("log")
    low = min([t.limit for t in ratios] + [t.measured.low for t in ratios if not t.skipped])
    high = max([t.limit for t in ratios] + [t.measured.high for t in ratios if not t.skipped])
    axes.set_xlim(low / 1.5, high * 12)
    axes.set_xlabel("ratio (log scale); | marks the limit, the bar the 95 % interval")
    axes.grid(True, axis="x", which="both", alpha=0.3)
    return charts.save(figure, out / f"{CHART}.png", footnote)
