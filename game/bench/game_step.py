"""The whole collision step of the game, per tick: on the shipped level, and as maps grow wide.

Where it sits: the last chart of ``python -m game.bench``. It plays the game headless through
:class:`game.sim.campaign.Campaign` and :meth:`game.sim.world.World.step`, nothing stubbed.

What it teaches:
  * **The budget is per tick, at the tail.** A game that is fast on average but slow one tick
    in twenty stutters, so the figure that matters is the 95th percentile of the collision
    time per tick (``world.stats.collision_s``: steps 1-7 of a tick), measured while the
    largest shipped level is played to its exit by its winning input script
    (``tests/scripts/<level>.txt``; a level still without a script is passed over, and the
    target then says so).
  * **Cost follows the bodies, not the map.** Every lookup in a tick goes through the tile
    grid, which only visits the cells a body covers, so a level twenty times wider with the
    same bodies should update in the same time. Two levels are built in memory: an arena
    40 tiles wide walled in on both sides, and the same arena followed by nineteen empty
    copies of itself (walls, ground, platforms; no bodies) beyond its right wall. The same
    bodies play the same input in both, ticks interleaved, and the update time per tick is
    compared.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from statistics import median
from time import perf_counter

from game.bench import charts
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import collector_off, percentile
from game.collision.aabb import Box
from game.levels import LEVELS_DIR, load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, Actions, InputScript
from game.sim.level import CoinSpec, EnemySpec, Level
from game.sim.tilegrid import TileGrid, TileKind, TileShape
from game.sim.world import World

CHART = "game_step"
SCRIPTS_DIR = LEVELS_DIR.parent / "tests" / "scripts"
AFTER_SCRIPT_TICKS = 600   # how long to keep playing after the script's last event
TILE_PX = 16
WIDTH_FACTOR = 20
NARROW, WIDE = "arena 40x12", f"arena {40 * WIDTH_FACTOR}x12"
COLLISION, UPDATE = "ms collision/tick", "ms update/tick"   # world.stats; all of World.step

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


def level_to_play() -> tuple[Path, Path]:
    """The largest shipped level that has a winning script, and that script.

    A level added without its script yet is passed over (and the target says so).
    """
    for level in levels_by_size():
        script = SCRIPTS_DIR / f"{level.stem}.txt"
        if script.exists():
            return level, script
    raise FileNotFoundError(f"{SCRIPTS_DIR}: no winning input script for any shipped level; "
                            f"record one with python -m game --record FILE")


def play(level: Path, script: InputScript) -> tuple[list[float], bool]:
    """Seconds of collision work per tick until the level is left; and whether it was won."""
    campaign = Campaign(level, loader=load_level)
    last = script.events[-1].tick if script.events else 0
    spent: list[float] = []
    with collector_off():
        for tick in range(last + AFTER_SCRIPT_TICKS):
            world = campaign.world
            campaign.tick(script.held_at(tick))
            spent.append(world.stats.collision_s)
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


def compare_widths(ticks: int, rounds: int) -> dict[str, list[list[float]]]:
    """Per round, the seconds each tick's update took in the narrow and the wide level."""
    levels = {NARROW: arena(1), WIDE: arena(WIDTH_FACTOR)}
    spent: dict[str, list[list[float]]] = {name: [] for name in levels}
    with collector_off():
        for _ in range(rounds):
            worlds = {name: World(level) for name, level in levels.items()}
            for name in worlds:
                spent[name].append([])
            for tick in range(ticks):
                held = held_at(tick)
                order = list(worlds) if tick % 2 == 0 else list(worlds)[::-1]
                for name in order:
                    started = perf_counter()
                    worlds[name].step(held)
                    spent[name][-1].append(perf_counter() - started)
    return spent


def measure(sizes: Sizes) -> list[Row]:
    level, script = level_to_play()
    largest = levels_by_size()[0]
    played = level.name
    rows = [Row(CHART, f"largest level: {largest.name}", "is played", 0,
                float(level == largest), "1 = yes, 0 = it has no script yet")]
    for round_no in range(sizes.play_rounds):
        spent, won = play(level, InputScript.load(script))
        rows += [Row(CHART, played, str(tick), round_no, s * 1e3, COLLISION)
                 for tick, s in enumerate(spent)]
        rows.append(Row(CHART, played, "p95", round_no, percentile(spent, 95) * 1e3,
                        COLLISION))
        rows.append(Row(CHART, played, "won", round_no, float(won), "1 = reached the exit"))
    for name, per_round in compare_widths(sizes.width_ticks, sizes.play_rounds).items():
        rows += [Row(CHART, name, str(tick), round_no, s * 1e3, UPDATE)
                 for round_no, spent in enumerate(per_round) for tick, s in enumerate(spent)]
    return rows


def p95_ms(rows: list[Row]) -> float:
    """The played level's 95th-percentile collision time per tick (median over rounds)."""
    return median(values(rows, parameter="p95", unit=COLLISION))


def width_ratio(rows: list[Row]) -> float:
    """Median update time per tick of the wide level over the narrow one."""
    return (median(values(rows, method=WIDE, unit=UPDATE))
            / median(values(rows, method=NARROW, unit=UPDATE)))


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("The game's collision step per tick", width_in=13, height_in=5.5)
    left, right = figure.subplots(1, 2, width_ratios=(2, 1))
    played = next(r.method for r in rows if r.parameter == "p95")
    ticks = sorted({int(r.parameter) for r in rows if r.method == played and
                    r.parameter.isdigit()})
    per_tick = [median(values(rows, method=played, parameter=str(t), unit=COLLISION))
                for t in ticks]
    left.plot(ticks, per_tick, linewidth=0.8, color=charts.colour(0),
              label="collision time (median over plays)")
    left.axhline(charts.TICK_SHARE_MS, color="#888888", linestyle="--", linewidth=1,
                 label=f"budget: {charts.TICK_SHARE_MS:g} ms at the 95th percentile")
    left.axhline(p95_ms(rows), color=charts.colour(3), linestyle=":", linewidth=1.2,
                 label=f"95th percentile: {p95_ms(rows):.3f} ms")
    left.set_title(f"{played}, played to the exit by its script")
    left.set_xlabel("tick (1/60 s of game time)")
    left.set_ylabel("collision step (ms per tick)")
    left.set_ylim(bottom=0)
    left.grid(True, alpha=0.3)
    left.legend(fontsize=8)
    data = [values(rows, method=name, unit=UPDATE) for name in (NARROW, WIDE)]
    right.boxplot(data, showfliers=False)
    right.set_xticks([1, 2], ["40 x 12\n(narrow)", f"{40 * WIDTH_FACTOR} x 12\n(wide)"])
    right.set_title(f"Same bodies, map {WIDTH_FACTOR}x wider: {width_ratio(rows):.2f}x the time")
    right.set_xlabel("level (tiles), same bodies and input")
    right.set_ylabel("World.step update (ms per tick)")
    right.set_ylim(bottom=0)
    right.grid(True, alpha=0.3)
    return charts.save(figure, out / f"{CHART}.png", footnote)
