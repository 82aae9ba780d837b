"""The game's own step per tick: on the largest shipped level, as maps grow wide, and as
moving platforms multiply.

Where it sits: a chart of ``python -m game.bench``. It plays the game headless through
:meth:`game.sim.world.World.step`, nothing stubbed.

What it teaches:
  * **The cost per tick, tick by tick.** The largest shipped level is played to its exit by
    its winning input script (``tests/scripts/<level>.txt``; a level still without a
    script is passed over, and the chart says so), and the CPU time of every tick is drawn
    with the 95th percentile *of that same line*.
    This is a picture of where the time goes, not a target: absolute times belong to the
    machine.
  * **Cost follows the bodies, not the map.** Every lookup in a tick goes through the tile
    grid, which only visits the cells a body covers, so a level twenty times wider with the
    same bodies should update in the same time. An arena 40 tiles wide, walled in on both
    sides, is built in memory, and the same arena followed by nineteen empty copies of
    itself (walls, ground, ledges; no bodies) beyond its right wall.
  * **Nor the platforms it is not near.** The wide arena again, with 2 and with 100 moving
    platforms gliding in the empty copies: a wall query should only meet the platforms
    near the body that asks.
  * The same bodies play the same input in every level, fresh worlds each round, the
    levels' ticks interleaved; each round gives one mean time per tick per level, and the
    ratios carry bootstrap intervals over the rounds.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace
from pathlib import Path
from statistics import median

from game.app.run import input_script
from game.bench import charts
from game.bench.intervals import Interval, paired_ratio
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import clock, collector_off, percentile
from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.levels import LEVELS_DIR, load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, Actions, InputScript
from game.sim.level import CoinSpec, EnemySpec, Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.world import World

CHART = "game_step"
SCRIPTS_DIR = LEVELS_DIR.parent / "tests" / "scripts"
AFTER_SCRIPT_TICKS = 600   # how long to keep playing after the script's last event
TILE_PX = 16
WIDTH_FACTOR = 20
NARROW, WIDE = "arena 40x12", f"arena {40 * WIDTH_FACTOR}x12"
FEW_PLATFORMS, MANY_PLATFORMS = 2, 100
FEW = f"{WIDE} with {FEW_PLATFORMS} platforms"
MANY = f"{WIDE} with {MANY_PLATFORMS} platforms"
PLATFORM_SPEED_PX_S = 30.0
TICK = "ms/tick (CPU time)"              # all of one campaign tick
UPDATE = "ms update/tick (round mean)"   # all of World.step

# The arena: walls on both sides, ground, platforms, a one-way ledge, spikes, bodies.
ARENA = [
    "#......................................#",
    "#......................................#",
    "#......................................#",
    "#.........C.............C..............#",
    "#.......#####.......---------....C.....#",
    "#..C..........................######...#",
    "#.....E.............E..................#",
    "#...#######.....#########.....E........#",
    "#.P.............................^^.....#",
    "#....C.....E........C.......E......C...#",
    "########################################",
    "########################################",
]
# What lies beyond the arena's right wall in the wide map: more arenas, empty of bodies.
BEYOND = [row.replace("P", ".").replace("E", ".").replace("C", ".") for row in ARENA]


def levels_by_size() -> list[Path]:
    """The shipped levels, the one with the most tiles first."""
    def tiles(path: Path) -> tuple[int, str]:
        grid = load_level(path).grid
        return grid.cols * grid.rows, path.name
    return sorted(LEVELS_DIR.glob("*.tmx"), key=tiles, reverse=True)


def level_to_play(by_size: Sequence[Path] | None = None) -> tuple[Path, Path]:
    """The largest shipped level that has a winning script, and that script.

    A level added without its script yet is passed over (and the target says so).
    ``by_size`` is :func:`levels_by_size` when the caller has it already (each level is
    loaded to be measured).
    """
    for level in levels_by_size() if by_size is None else by_size:
        script = SCRIPTS_DIR / f"{level.stem}.txt"
        if script.exists():
            return level, script
    raise FileNotFoundError(f"{SCRIPTS_DIR}: no winning input script for any shipped level; "
                            f"record one with python -m game --record FILE")


def play(level: Path, script: InputScript) -> tuple[list[float], bool]:
    """CPU seconds of each tick until the level is left; and whether it was won."""
    campaign = Campaign(level, loader=load_level)
    last = script.events[-1].tick if script.events else 0
    spent: list[float] = []
    with collector_off():
        for tick in range(last + AFTER_SCRIPT_TICKS):
            held = script.held_at(tick)
            started = clock()
            campaign.tick(held)
            spent.append(clock() - started)
            if campaign.levels_completed or campaign.outcome is not Outcome.RUNNING:
                break
    return spent, campaign.levels_completed > 0


def level_from_rows(rows: Sequence[str]) -> Level:
    """A level in memory from ASCII rows: ``#`` solid, ``-`` one-way, ``^`` hazard, ``P``
    the player, ``E`` an enemy, ``C`` a coin (the legend of ``tests/maps.py``)."""
    kinds = {"#": TileKind.SOLID, "-": TileKind.ONE_WAY, "^": TileKind.HAZARD}
    grid = TileGrid(max(len(r) for r in rows), len(rows), TILE_PX, TILE_PX)
    spawn = Box(0, 0, 12, 14)
    coins: list[CoinSpec] = []
    enemies: list[EnemySpec] = []
    for row, line in enumerate(rows):
        for col, char in enumerate(line):
            x, y = col * TILE_PX, row * TILE_PX
            if char in kinds:
                grid.put(col, row, TileShape(Box(x, y, TILE_PX, TILE_PX), kinds[char], col, row))
            elif char == "P":
                spawn = Box(x, y, 12, 14)
            elif char == "C":
                coins.append(CoinSpec(Box(x, y, 8, 8)))
            elif char == "E":
                enemies.append(EnemySpec(Box(x, y + 4, 14, 12)))
    return Level(Path("memory.tmx"), grid, spawn, tuple(coins), tuple(enemies))


def arena(width_factor: int) -> Level:
    """The arena alone (factor 1), or followed by ``width_factor - 1`` empty copies."""
    return level_from_rows([a + b * (width_factor - 1)
                            for a, b in zip(ARENA, BEYOND, strict=True)])


def held_at(tick: int) -> Actions:
    """A fixed input: run right and left in turn, jumping now and then."""
    held = {Action.RIGHT if (tick // 90) % 2 == 0 else Action.LEFT}
    if tick % 40 < 12:
        held.add(Action.JUMP)
    return frozenset(held)


def platforms_beyond(count: int) -> tuple[PlatformSpec, ...]:
    """``count`` platforms spread over the empty copies beyond the arena's right wall, each
    gliding back and forth over two tiles just under the sky."""
    first, last = 41 * TILE_PX, 40 * WIDTH_FACTOR * TILE_PX - 4 * TILE_PX
    spacing = (last - first) / MANY_PLATFORMS
    return tuple(PlatformSpec(Route(((first + k * spacing, 2.0 * TILE_PX),
                                     (first + k * spacing + 2 * TILE_PX, 2.0 * TILE_PX))),
                              2 * TILE_PX, TILE_PX / 2, PLATFORM_SPEED_PX_S)
                 for k in range(count))


def compared_levels() -> dict[str, Level]:
    """The arena, the wide arena, and the wide arena with few and with many platforms."""
    wide = arena(WIDTH_FACTOR)
    return {NARROW: arena(1), WIDE: wide,
            FEW: replace(wide, platforms=platforms_beyond(FEW_PLATFORMS)),
            MANY: replace(wide, platforms=platforms_beyond(MANY_PLATFORMS))}


def compare(levels: dict[str, Level], ticks: int, rounds: int) -> dict[str, list[float]]:
    """Per round, the mean seconds per ``World.step`` of each level: the same bodies and
    inputs, fresh worlds each round, the levels' ticks interleaved (the order turning
    round every tick)."""
    spent: dict[str, list[float]] = {name: [] for name in levels}
    names = list(levels)
    with collector_off():
        for _ in range(rounds):
            worlds = {name: World(level) for name, level in levels.items()}
            total = dict.fromkeys(names, 0.0)
            for tick in range(ticks):
                held = held_at(tick)
                shift = tick % len(names)
                for name in [*names[shift:], *names[:shift]]:
                    started = clock()
                    worlds[name].step(held)
                    total[name] += clock() - started
            for name in names:
                spent[name].append(total[name] / ticks)
    return spent


def measure(sizes: Sizes) -> list[Row]:
    by_size = levels_by_size()
    level, script = level_to_play(by_size)
    largest = by_size[0]
    played = level.name
    rows = [Row(CHART, f"largest level: {largest.name}", "is played", 0,
                float(level == largest), "1 = yes, 0 = it has no script yet")]
    for round_no in range(sizes.play_rounds):
        spent, won = play(level, input_script(script))
        rows += [Row(CHART, played, str(tick), round_no, s * 1e3, TICK)
                 for tick, s in enumerate(spent)]
        rows.append(Row(CHART, played, "won", round_no, float(won), "1 = reached the exit"))
    for name, per_round in compare(compared_levels(), sizes.width_ticks,
                                   sizes.verdict_rounds).items():
        rows += [Row(CHART, name, "round", r, s * 1e3, UPDATE) for r, s in enumerate(per_round)]
    return rows


def played_line(rows: list[Row]) -> tuple[str, list[int], list[float]]:
    """The level played, its ticks, and each tick's CPU time (median over the plays, ms)."""
    played = next(r.method for r in rows if r.parameter == "won")
    per_tick: dict[int, list[float]] = {}  # one pass over the rows, not one per tick
    for row in rows:
        if row.method == played and row.parameter.isdigit():
            spent = per_tick.setdefault(int(row.parameter), [])
            if row.unit == TICK:
                spent.append(row.value)
    ticks = sorted(per_tick)
    return played, ticks, [median(per_tick[t]) for t in ticks]


def p95_ms(rows: list[Row]) -> float:
    """The 95th percentile of the plotted line: the per-tick medians over the plays."""
    return percentile(played_line(rows)[2], 95)


def ratio(rows: list[Row], level: str, reference: str) -> Interval:
    """How many times as long a tick of ``level`` took as one of ``reference``."""
    return paired_ratio(values(rows, method=level, unit=UPDATE),
                            values(rows, method=reference, unit=UPDATE))


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("The game's step per tick", width_in=15, height_in=5.5)
    left, middle, right = figure.subplots(1, 3, width_ratios=(2, 1, 1))
    played, ticks, per_tick = played_line(rows)
    left.plot(ticks, per_tick, linewidth=0.8, color=charts.colour(0),
              label="CPU time per tick (median over the plays)")
    left.axhline(p95_ms(rows), color=charts.colour(3), linestyle=":", linewidth=1.2,
                 label=f"95th percentile of this line: {p95_ms(rows):.3f} ms")
    left.axhline(charts.TICK_SHARE_MS, color="#888888", linestyle="--", linewidth=1,
                 label=f"{charts.TICK_SHARE_MS:g} ms: a fair share of a 16.7 ms frame")
    left.set_title(f"{played}, played to the exit by its script")
    left.set_xlabel("tick (1/60 s of game time)")
    left.set_ylabel("one tick, CPU time (ms)")
    left.set_ylim(bottom=0)
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8)
    for axes, (small, big, labels, title) in (
            (middle, (NARROW, WIDE, ("40 x 12", f"{40 * WIDTH_FACTOR} x 12"),
                      f"Map {WIDTH_FACTOR}x wider, same bodies")),
            (right, (FEW, MANY, (f"{FEW_PLATFORMS} platforms", f"{MANY_PLATFORMS} platforms"),
                     f"{MANY_PLATFORMS} moving platforms against {FEW_PLATFORMS}"))):
        data = [values(rows, method=name, unit=UPDATE) for name in (small, big)]
        axes.boxplot(data, showfliers=False)
        axes.set_xticks([1, 2], list(labels))
        axes.set_title(f"{title}:\n{ratio(rows, big, small).text()}x the time "
                       "[95 % interval]", fontsize=10)
        axes.set_ylabel("World.step, mean per tick of each round (ms)")
        axes.set_ylim(bottom=0)
        axes.grid(True, alpha=0.3)
    return charts.save(figure, out / f"{CHART}.png", footnote)
