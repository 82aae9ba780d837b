"""How high and how far the player can jump, measured by the game itself.

Where it sits: ``python -m game.levels check`` prints it for the maps it checks, and the
level designer's guide (``levels/README.md``) quotes it, so a designer knows which ledges
are in reach before drawing them.

What it teaches: measure, don't derive by hand. The height of a jump is not simply
``v² / 2g``: the tick applies gravity before it moves, speeds are capped, and letting go of
jump cuts the rise. So :func:`measure_reach` builds a flat test level, runs the player up to
full speed, holds jump until it lands, and reads the highest point and the landing place off
the real :meth:`World.step` with the given tuning.

How far the feet travel is not the widest gap, though: the body is 12 px wide and stands on
a ledge while any of it is over the ledge, and coyote time lets a jump start a few ticks
after the feet have left it. So :func:`measure_limits` plays the real thing, with the jump
pressed on every tick near the edge: ledges from the height of a full jump down, until one
is landed on; and jumps over a pit, where the tick the feet fall past the floor's top tells
the widest gap each would have crossed, then confirmed by landing across that gap and
missing one a pixel wider (plain: jump pressed while on the ground; coyote: pressed on any
tick, the last coyote tick included).

Every measurement is bounded by work, counted in ticks of play: the test levels are sized
from the jump the tuning gives (worked out with :func:`game.checker.reachable.jump_rise`),
at most :data:`MAX_START_PLACES` start places are tried across one tick's run (and, for
the gaps, the one whose run stands last just short of the edge: the furthest any run
leaves from, so the widest gap is the bound :mod:`game.checker.jump_envelope` proves), and
:func:`limits_of` stops a measurement after :data:`MAX_MEASURE_TICKS` ticks and says so
(the default physics take about 28,000; a floaty jump, 30 s in the air, takes more; making
a test level counts too, a tick for every :data:`CELLS_PER_TICK` of its cells). The
checker's summary (:func:`own_reaches`) gives the reach on at most :data:`MAX_OWN_PHYSICS`
maps that set their own physics, within :data:`SUMMARY_MEASURE_TICKS` ticks in all.

>>> reach = measure_reach(Tuning())
>>> round(reach.height_px, 1), round(reach.distance_px, 1)
(44.3, 57.0)
>>> reach.describe(16)
'jumps 2.8 tiles high and 3.6 tiles across at a run (16 px tiles)'
>>> measure_limits(Tuning())
Limits(ledge_px=44, gap_px=68, coyote_gap_px=76)
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from contextvars import ContextVar
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from game.checker.reachable import jump_rise
from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import Action, Actions
from game.sim.level import Level
from game.sim.snapshot import Snapshot
from game.sim.tuning import Tuning
from game.sim.world import World

TEST_TILE_PX = 16
TEST_COLS, TEST_ROWS = 400, 40  # the test levels' least size in tiles; a long jump gets more
RUN_UP_TICKS = 30  # long enough to reach full speed with any tuning a map may set
MAX_AIR_TICKS = 60 * 60  # a jump in the physics a map may set lands within 30 s
MAX_START_PLACES = 8  # start places tried across one tick's run (a quarter pixel apart
#                       up to 2 px a tick, spread evenly when a tick runs further)
MAX_MEASURE_TICKS = 1_000_000  # ticks of play one measurement of the limits may step
CELLS_PER_TICK = 100  # cells of a test level that cost as much to make as a tick to play
SUMMARY_MEASURE_TICKS = 300_000  # ticks of play a check's summary may spend on them in all
MAX_OWN_PHYSICS = 4  # maps with their own physics whose reach a check's summary gives


class TooMuchWork(Exception):
    """A measurement would step more ticks of play than its budget."""


class _Meter:
    """The ticks of play a measurement has stepped, against its budget."""

    def __init__(self, budget: int | None) -> None:
        self.budget = budget
        self.ticks = 0

    def charge(self, ticks: int) -> None:
        self.ticks += ticks
        if self.budget is not None and self.ticks > self.budget:
            raise TooMuchWork(f"more than {self.budget:,} ticks of play")

    def step(self, world: World, held: Actions) -> None:
        self.charge(1)
        world.step(held)


_METER: ContextVar[_Meter | None] = ContextVar("reach_meter", default=None)


def _step(world: World, held: Actions) -> None:
    """One tick of a test level, counted by the measurement under way (if it counts)."""
    meter = _METER.get()
    if meter is None:
        world.step(held)
    else:
        meter.step(world, held)


def _test_grid(cols: int, rows: int) -> TileGrid:
    """An empty test level, counted before it is made as a tick for every
    :data:`CELLS_PER_TICK` of its cells (making it and its world visits every cell)."""
    meter = _METER.get()
    if meter is not None:
        meter.charge(math.ceil(cols * rows / CELLS_PER_TICK))
    return TileGrid(cols, rows, TEST_TILE_PX, TEST_TILE_PX)


@dataclass(frozen=True)
class Reach:
    """A full jump at a run: how much higher the feet get, and how far it carries."""

    height_px: float
    distance_px: float

    def describe(self, tile_px: int) -> str:
        return (f"jumps {self.height_px / tile_px:.1f} tiles high and "
                f"{self.distance_px / tile_px:.1f} tiles across at a run ({tile_px} px tiles)")


def _tiles(px: float) -> int:
    return math.ceil(px / TEST_TILE_PX)


def jump_path(tuning: Tuning) -> list[Box]:
    """The hitbox at take-off and after every tick of a full jump at a run, until it lands,
    on a flat floor with nothing overhead (as long as the run and the jump need)."""
    rise = jump_rise(tuning)
    step = tuning.run_speed_px_s * tuning.tick_s
    cols = max(TEST_COLS, _tiles(step * (RUN_UP_TICKS + len(rise) + 2)) + 4)
    floor_row = TEST_ROWS - 1  # a jump may rise above the test level: nothing is there
    grid = _test_grid(cols, TEST_ROWS)
    for col in range(cols):
        grid.put(col, floor_row, TileShape(
            Box(col * TEST_TILE_PX, floor_row * TEST_TILE_PX, TEST_TILE_PX, TEST_TILE_PX),
            TileKind.SOLID, col, floor_row))
    spawn = Box(TEST_TILE_PX, floor_row * TEST_TILE_PX - tuning.player_height_px,
                tuning.player_width_px, tuning.player_height_px)
    world = World(Level(Path("reach"), grid, spawn), tuning)
    run, jump = frozenset({Action.RIGHT}), frozenset({Action.RIGHT, Action.JUMP})
    for _ in range(RUN_UP_TICKS):
        _step(world, run)
    path = [world.player.box]
    for _ in range(MAX_AIR_TICKS):
        _step(world, jump)
        path.append(world.player.box)
        if world.player.on_ground:
            break
    return path


def measure_reach(tuning: Tuning) -> Reach:
    """The reach of a full jump with ``tuning``: the highest point and the landing place of
    :func:`jump_path`."""
    path = jump_path(tuning)
    take_off = path[0]
    highest = min(box.y for box in path)
    return Reach(take_off.y - highest, path[-1].x - take_off.x)


LEDGE_ROW = 30  # the floor's top row in the test levels of measure_limits (at least)
RUN_COL = 2  # where the player starts its run
EDGE_COL = 12  # where the floor ends (a gap) or the ledge starts (at least)
FLOOR_ROWS = 6  # how deep the floors go under their top
EARLY_PRESSES = 8  # jump presses tried before the edge or the wall is reached
EDGE_SHAVE_PX = 1 / 4096  # how far short of the edge the furthest run stands last


@dataclass(frozen=True)
class _Bench:
    """The test levels of :func:`measure_limits` for one tuning, in tiles: high enough for
    its highest ledge, a run-up long enough to reach full speed, and room for its longest
    jump beyond the edge."""

    ledge_row: int  # the floor's top row
    edge_col: int
    cols: int
    rows: int

    @property
    def top_px(self) -> int:
        return self.ledge_row * TEST_TILE_PX

    @property
    def edge_px(self) -> int:
        return self.edge_col * TEST_TILE_PX

    @property
    def floor_bottom_px(self) -> int:
        return (self.ledge_row + FLOOR_ROWS) * TEST_TILE_PX

    def grid(self) -> TileGrid:
        return _test_grid(self.cols, self.rows)


def _bench(tuning: Tuning) -> _Bench:
    rise = jump_rise(tuning)
    step = tuning.run_speed_px_s * tuning.tick_s
    ledge_row = max(LEDGE_ROW, _tiles(max(rise)) + 4)
    edge_col = RUN_COL + max(EDGE_COL - RUN_COL, _tiles(4 * step))
    carry = step * (len(rise) + tuning.coyote_ticks + EARLY_PRESSES + 4)
    cols = max(TEST_COLS // 4, edge_col + _tiles(carry + tuning.player_width_px) + 4)
    return _Bench(ledge_row, edge_col, cols, ledge_row + FLOOR_ROWS + 4)


@dataclass(frozen=True)
class Limits:
    """The highest ledge landed on and the widest gaps crossed, in whole pixels."""

    ledge_px: int
    gap_px: int  # jump pressed while standing
    coyote_gap_px: int  # jump pressed on any tick, the last coyote tick included

    def describe(self) -> str:
        return (f"the highest ledge it lands on is {self.ledge_px} px, the widest gap it "
                f"crosses {self.gap_px} px with a running jump and {self.coyote_gap_px} px "
                "with a coyote jump (pressed just after running off the edge)")


# measure_limits(Tuning()), kept here because measuring takes seconds; the doctest above
# and tests/test_solver.py measure it again and fail if it changes.
DEFAULT_LIMITS = Limits(ledge_px=44, gap_px=68, coyote_gap_px=76)


@dataclass(frozen=True)
class Unmeasured:
    """Limits that were not measured: measuring them would step more ticks than allowed."""

    budget_ticks: int

    def describe(self) -> str:
        return (f"its highest ledge and widest gaps were not measured within the "
                f"{self.budget_ticks:,} ticks of play allowed for it")


def limits_of(tuning: Tuning, budget_ticks: int = MAX_MEASURE_TICKS) -> Limits | Unmeasured:
    """The limits for ``tuning``: the kept figures for the default physics, else measured
    within ``budget_ticks`` ticks of play (or :class:`Unmeasured`, when that is too few)."""
    return _limits_within(tuning, _Meter(budget_ticks))


def _limits_within(tuning: Tuning, meter: _Meter) -> Limits | Unmeasured:
    if tuning == Tuning():
        return DEFAULT_LIMITS
    token = _METER.set(meter)
    try:
        return measure_limits(tuning)
    except TooMuchWork:
        return Unmeasured(meter.budget or 0)
    finally:
        _METER.reset(token)


@dataclass(frozen=True)
class OwnReach:
    """The reach and the limits on one map that sets its own physics."""

    path: Path
    reach: Reach
    limits: Limits | Unmeasured


def own_reaches(own: Sequence[tuple[Path, Tuning]]) -> tuple[list[OwnReach], int]:
    """The reach on the first :data:`MAX_OWN_PHYSICS` maps of ``own``, with their limits
    measured within :data:`SUMMARY_MEASURE_TICKS` ticks of play in all (maps with the same
    physics share one measurement), and how many maps are left out. Each map may spend an
    even share of the ticks left, so a costly one does not leave the others none."""
    shown: list[OwnReach] = []
    left = SUMMARY_MEASURE_TICKS
    first = own[:MAX_OWN_PHYSICS]
    for number, (path, tuning) in enumerate(first):
        meter = _Meter(left // (len(first) - number))
        shown.append(OwnReach(path, measure_reach(tuning), _limits_within(tuning, meter)))
        left -= min(meter.ticks, meter.budget or 0)
    return shown, len(own) - len(shown)


def measured_ticks(tuning: Tuning) -> int:
    """How many ticks of play measuring the limits for ``tuning`` steps (not cached)."""
    meter = _Meter(None)
    token = _METER.set(meter)
    try:
        measure_limits.__wrapped__(tuning)
    finally:
        _METER.reset(token)
    return meter.ticks


def _floor(grid: TileGrid, left_px: float, right_px: float, top_px: float,
           bottom_px: float) -> None:
    """Solid ground from ``left_px`` to ``right_px`` with its top at ``top_px``, down to
    ``bottom_px`` (partial tiles at the edges)."""
    tile = TEST_TILE_PX
    for col in range(math.floor(left_px / tile), math.ceil(right_px / tile)):
        x0, x1 = max(left_px, col * tile), min(right_px, (col + 1) * tile)
        for row in range(math.floor(top_px / tile), math.ceil(bottom_px / tile)):
            y0 = max(top_px, row * tile)
            if x1 > x0 and (row + 1) * tile > y0:
                grid.put(col, row, TileShape(Box(x0, y0, x1 - x0, (row + 1) * tile - y0),
                                             TileKind.SOLID, col, row))


@dataclass(frozen=True)
class _Attempt:
    """One jump of :func:`_attempts`."""

    grounded: bool  # on the ground when jump was pressed
    landed: bool  # came to stand on the target's top, right of its left edge
    falling_right_px: float | None  # the right edge on the tick the feet fell past that top


def _attempts(tuning: Tuning, bench: _Bench, grid: TileGrid, target_top: float,
              target_left: float, offset_px: float) -> Iterator[_Attempt]:
    """Run right from RUN_COL (plus ``offset_px``) and press jump on each tick worth trying,
    from a few before the run leaves the ground or meets the wall to the end of coyote time,
    and say how each went."""
    spawn = Box(RUN_COL * TEST_TILE_PX + offset_px, bench.top_px - tuning.player_height_px,
                tuning.player_width_px, tuning.player_height_px)
    level = Level(Path("limits"), grid, spawn)
    run, jump = frozenset({Action.RIGHT}), frozenset({Action.RIGHT, Action.JUMP})
    world = World(level, tuning)
    leaves = 0
    for leaves in range(MAX_AIR_TICKS):  # noqa: B007  (the tick it leaves is wanted)
        _step(world, run)
        moved = world.moves.get(world.player)
        if not world.player.on_ground or (moved is not None and moved.x.hit is not None):
            break
    first = max(0, leaves - EARLY_PRESSES)
    world = World(level, tuning)
    for _ in range(first):
        _step(world, run)
    start = Snapshot.of(world)
    for press in range(first, leaves + tuning.coyote_ticks + 2):
        start.restore(world)
        for _ in range(press - first):
            _step(world, run)
        grounded, landed, falling_right = world.player.on_ground, False, None
        for tick in range(MAX_AIR_TICKS):
            _step(world, jump)
            box = world.player.box
            if tick > 0 and world.player.on_ground:
                landed = box.bottom == target_top and box.right > target_left
                break
            if tick > 0 and world.player.vy > 0 and box.bottom > target_top:
                falling_right = box.right  # falling past the top it meant to land on
                break
        yield _Attempt(grounded, landed, falling_right)


def _crosses(tuning: Tuning, gap_px: int) -> tuple[bool, bool]:
    """Can a gap of ``gap_px`` be crossed: by a jump pressed standing, and by any jump?"""
    bench = _bench(tuning)
    grid = bench.grid()
    top, edge, bottom = bench.top_px, bench.edge_px, bench.floor_bottom_px
    _floor(grid, 0, edge, top, bottom)
    _floor(grid, edge + gap_px, grid.width_px, top, bottom)
    plain = anyhow = False
    for offset in _offsets(tuning) + _edge_offsets(tuning, bench):
        for attempt in _attempts(tuning, bench, grid, top, edge + gap_px, offset):
            plain = plain or (attempt.landed and attempt.grounded)
            anyhow = anyhow or attempt.landed
            if plain:
                return True, True
    return plain, anyhow


def _climbs(tuning: Tuning, ledge_px: int) -> bool:
    """Does a jump land on a ledge ``ledge_px`` above the floor (a wall at the edge, the
    ledge's top beyond it)?"""
    bench = _bench(tuning)
    grid = bench.grid()
    top, edge, bottom = bench.top_px, bench.edge_px, bench.floor_bottom_px
    _floor(grid, 0, edge, top, bottom)
    _floor(grid, edge, edge + TEST_TILE_PX, top - ledge_px, bottom)  # the wall, to the floor
    _floor(grid, edge + TEST_TILE_PX, grid.width_px, top - ledge_px,  # and the ledge's top:
           min(bottom, top - ledge_px + FLOOR_ROWS * TEST_TILE_PX))   # nothing reaches under
    return any(attempt.landed for offset in _offsets(tuning)
               for attempt in _attempts(tuning, bench, grid, top - ledge_px, edge, offset))


def _offsets(tuning: Tuning) -> list[float]:
    """Start places across one tick's run, a quarter pixel apart (at most
    :data:`MAX_START_PLACES` of them, spread evenly, when a tick runs further): where the
    last step before the edge falls changes how far the jump carries."""
    step = tuning.run_speed_px_s * tuning.tick_s
    quarters = max(1, math.ceil(step * 4))
    if quarters <= MAX_START_PLACES:
        return [quarter / 4 for quarter in range(quarters)]
    return [step * place / MAX_START_PLACES for place in range(MAX_START_PLACES)]


def _edge_offsets(tuning: Tuning, bench: _Bench) -> list[float]:
    """The start place whose run stands last with its left edge :data:`EDGE_SHAVE_PX` short
    of the edge: the furthest any run leaves from, so the furthest any jump off it carries
    (the quarter pixels of :func:`_offsets` may miss it by up to a quarter pixel)."""
    grid = bench.grid()
    _floor(grid, 0, bench.edge_px, bench.top_px, bench.floor_bottom_px)
    spawn = Box(RUN_COL * TEST_TILE_PX, bench.top_px - tuning.player_height_px,
                tuning.player_width_px, tuning.player_height_px)
    world = World(Level(Path("limits"), grid, spawn), tuning)
    run = frozenset({Action.RIGHT})
    last = world.player.box.x
    for _ in range(MAX_AIR_TICKS):
        _step(world, run)
        if not world.player.on_ground:
            break
        last = world.player.box.x
    offset = bench.edge_px - EDGE_SHAVE_PX - last
    step = tuning.run_speed_px_s * tuning.tick_s
    return [offset] if 0 < offset <= step else []


def _gaps_foreseen(tuning: Tuning) -> tuple[int, int]:
    """The widest gaps (plain, any jump) foreseen from jumps over a pit with no far side.

    The far side's top is the near side's, so a jump meets it only on the tick its feet
    fall past that top, after that tick's move on x: it lands when its right edge is then
    past the far side's left edge (a touch is no overlap), and a landing is never a corner
    slide. So a jump whose right edge is at ``r`` then crosses every gap narrower than
    ``r - edge``: the widest is ``ceil(r - edge) - 1``."""
    bench = _bench(tuning)
    grid = bench.grid()
    top, edge = bench.top_px, bench.edge_px
    _floor(grid, 0, edge, top, bench.floor_bottom_px)
    plain = anyhow = 0
    for offset in _offsets(tuning) + _edge_offsets(tuning, bench):
        for attempt in _attempts(tuning, bench, grid, top, grid.width_px, offset):
            if attempt.falling_right_px is None:
                continue
            widest = math.ceil(attempt.falling_right_px - edge) - 1
            anyhow = max(anyhow, widest)
            if attempt.grounded:
                plain = max(plain, widest)
    return plain, anyhow


@lru_cache(maxsize=16)
def measure_limits(tuning: Tuning) -> Limits:
    """The highest ledge and the widest gaps, played out in the game's own tick: from the
    height of a full jump down, the first ledge the player lands on; the widest gaps as
    :func:`_gaps_foreseen` foresees them, each then landed across and missed one pixel
    wider. Should a check ever disagree, every gap from the length of a full jump plus the
    body's width down is played instead, and the first crossed is kept. Every tick it plays
    is counted (:func:`limits_of` gives it a budget)."""
    reach = measure_reach(tuning)
    ledge = math.floor(reach.height_px)
    while ledge > 0 and not _climbs(tuning, ledge):
        ledge -= 1
    plain_gap, coyote_gap = _gaps_foreseen(tuning)
    if (_crosses(tuning, plain_gap)[0] and not _crosses(tuning, plain_gap + 1)[0]
            and _crosses(tuning, coyote_gap)[1] and not _crosses(tuning, coyote_gap + 1)[1]):
        return Limits(ledge, plain_gap, coyote_gap)
    widest = math.ceil(reach.distance_px + tuning.player_width_px
                       + tuning.run_speed_px_s * tuning.tick_s * (tuning.coyote_ticks + 2))
    plain_gap = coyote_gap = 0
    for gap in range(max(0, widest), 0, -1):
        plain, anyhow = _crosses(tuning, gap)
        if anyhow and not coyote_gap:
            coyote_gap = gap
        if plain:
            plain_gap = gap
            break
    return Limits(ledge, plain_gap, max(coyote_gap, plain_gap))
