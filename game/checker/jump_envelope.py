"""The pixel-exact reach: a proof of impossibility that is exact at the measured limits.

Where it sits: :func:`game.checker.verdict.prove_impossible` asks it when the cell fill of
:mod:`game.checker.reachable` reaches an Exit. The fill works in whole cells, so it lets a
jump go about a tile further than the game does; this proof works in pixels, so a gap one
pixel wider than the widest the player crosses (:func:`game.checker.reach.measure_limits`)
or a ledge one pixel higher than the highest it lands on is proven out of reach. Both are
over-approximations: a map is impossible when either leaves the Exit out.

What it teaches: bound what the game can do, tick by tick, by measuring it with the game's
own :meth:`~game.sim.world.World.step`, then let walls only ever help the proof's player:

* **The air envelope** (:func:`air_envelope`). From the last tick the body stood on
  something (its fall speed is then 0), the game is played with jump pressed on each tick
  where it still starts a jump (the first, then every coyote tick, held to the top) and
  with no jump at all. After ``k`` ticks in the air the feet are no higher than the
  highest of those (letting go of jump, or a head bump, only lowers them), and the body
  has moved at most ``k`` ticks of full run speed to either side (no input moves it
  faster), or, where a ceiling is near, from a corner of it (below).
* **Launches** (:func:`surfaces`). A body stands while any of its width overlaps the top of
  a Solid or OneWay shape, and may walk the whole of a run of tops at one height (walls are
  left out: they only stop it). So a run of tops from ``L`` to ``R`` is one launch, with
  the body's left edge anywhere in ``(L - width, R)``, summed sideways from its furthest
  floats (:class:`Sweep`). A body whose feet stop exactly on a OneWay top while rising
  stands there still rising, so a launch from a OneWay top is bounded by a second
  envelope that leaves at a jump's speed.
* **Landing** on a top needs the body's box to overlap it after the tick's sideways move,
  with the feet at or above it the tick before (or exactly on it after the move).
* **Corner corrections.** A rising head that clips a ceiling's corner slides past it and
  is left flush with that corner, so a jump that slid is, after its last slide, at a
  corner of a ceiling it could meet, and runs on from there (:func:`_corners`).
* **Touching** an Exit (or counting a Checkpoint: touching it or jumping over it) needs the
  box anywhere in the envelope to overlap it; falls are followed until the body is below
  the map, where it loses a life and comes back to a start.
* **Starts**: the spawn, and each Checkpoint's respawn place once the flag can be counted.
  Lives and spikes only send the player back to a start, so they widen nothing.

* **Enemies and moving Platforms** are left out of the reach: they change the player's
  tick only by a touch (a stomp bounces, a touch hurts; a platform is stood on, pushes,
  carries, crushes), and go their own way whatever the player does. So the reach is
  worked out with the walls alone, then every launch's envelope is tested against where
  each of them can ever be, grown by touching distance (:mod:`game.checker.mechanic_bounds`):
  if none comes near, the game with them plays as the game without them wherever the
  player can be, and the proof stands. Each one the envelope comes near, each enemy with
  no bound, and a counted Checkpoint whose respawn place a platform's route could move,
  makes it prove nothing and is named (:attr:`Exact.unbounded`); the cell fill of
  :mod:`game.checker.reachable`, which follows stomps and rides, may still prove the map,
  and so may :mod:`game.checker.enemy_barrier`, for a walker that blocks the only way.

Heights get :data:`SLACK_PX` more than measured (the game's float sums at another height
may round apart by far less); sideways moves are the game's own float sums, so the widest
gap is exact even where a jump carries a whole number of pixels. Its work is counted,
never timed: past :data:`MAX_PAIRS` pairs of a launch and a place to land or touch (an
Exit, a flag, or a box of an enemy's or a platform's bound), it proves nothing.

>>> from game.sim.tuning import Tuning
>>> envelope = air_envelope(Tuning())
>>> envelope.widest_gap_px(), envelope.highest_ledge_px()
(76, 44)
"""

from __future__ import annotations

import bisect
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from itertools import pairwise
from pathlib import Path

from game.checker.mechanic_bounds import enemy_bounds, platform_bounds, respawn_moved_by
from game.checker.reachable import Cell, FillWork, jump_rise, starts
from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import Action
from game.sim.level import Level
from game.sim.player import run_change_px_s
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World

SLACK_PX = 1e-6  # rounding room on every comparison (the game's float sums differ by ~1e-10)
ENVELOPE_TILE_PX = 16  # the tiles of the test level the envelope is measured on
MAX_ENVELOPE_TICKS = 60 * 60  # ticks measured per jump (a jump in any map's physics lands)
MAX_PAIRS = 1_000_000  # launch and top (or Exit, or flag) pairs one proof may look at


@dataclass(frozen=True)
class AirEnvelope:
    """How far a body can go in the air, tick by tick, measured for one tuning."""

    step_px: float  # the farthest sideways move in one tick: full run speed
    heights: tuple[float, ...]  # the highest the feet can be above take-off after k ticks
    fall_px: float  # the least the feet drop each tick after the last measured one
    rising_ticks: int  # the most ticks a jump rises (a corner slide needs a rise)
    last_rise: int  # the last tick on which any jump still rises
    rise_start_px: float  # the lowest the feet are below take-off when a rise starts
    corner_px: float  # the farthest one corner correction slides
    width_px: int  # the body's size
    height_px: int
    # for each measured tick k, minus the highest the feet can be on tick k - 1 or later
    # (never falling with k: what :meth:`last_tick_at` searches)
    lowest_after: tuple[float, ...]

    def height(self, ticks: int) -> float:
        """The highest the feet can be above take-off ``ticks`` ticks after leaving it."""
        last = len(self.heights) - 1
        if ticks <= last:
            return self.heights[ticks]
        return self.heights[last] - (ticks - last) * self.fall_px

    def last_tick_at(self, rise_px: float) -> int:
        """The last tick ``k`` where the feet can be ``rise_px`` above take-off on tick
        ``k - 1`` or ``k`` (-1: never). The measured ticks are searched in
        :attr:`lowest_after`; past them the feet only fall."""
        least = rise_px - SLACK_PX
        last = len(self.heights) - 1
        if self.heights[last] >= least:
            return last + 2 + math.floor((self.heights[last] - least) / self.fall_px)
        ticks = bisect.bisect_right(self.lowest_after, -least) - 1
        return ticks if ticks >= 1 else -1

    def widest_gap_px(self, edge_px: float = 192.0) -> int:
        """The widest gap after a top ending at ``edge_px`` this envelope lets a body cross
        to a top at the same height: the bound the proof uses, in whole pixels."""
        sweep = Sweep(self, self.width_px, edge_px, edge_px, standing=True, corners=None)
        _, high = sweep.at(self.last_tick_at(0.0))
        return math.ceil((high + self.width_px) - edge_px) - 1

    def highest_ledge_px(self) -> int:
        """The highest ledge (over the take-off's top) this envelope lets a body land on."""
        return math.floor(max(self.heights) + SLACK_PX)


@lru_cache(maxsize=16)
def air_envelope(tuning: Tuning, rising: bool = False) -> AirEnvelope | None:
    """The envelope for ``tuning``, played in the game's own tick (None when it cannot be
    measured: a jump that does not come down within :data:`MAX_ENVELOPE_TICKS`).

    ``rising``: from a OneWay top the body may have come up through it, its feet stopping
    exactly on the top: it then stands there (coyote time starts) while still rising. So
    the body leaves such a top rising as fast as a jump sends it (no body rises faster),
    which bounds every speed it may have had."""
    if tuning.gravity_px_s2 <= 0 or tuning.max_fall_speed_px_s <= 0:
        return None
    rise = jump_rise(tuning)
    ticks = min(MAX_ENVELOPE_TICKS, len(rise) * (2 if rising else 1) + tuning.coyote_ticks + 4)
    depth = ticks * tuning.max_fall_speed_px_s * tuning.tick_s + 4 * ENVELOPE_TILE_PX
    rows = 2 + math.ceil(depth / ENVELOPE_TILE_PX)
    tile = ENVELOPE_TILE_PX
    first = min(run_change_px_s(tuning, True, True), tuning.run_speed_px_s) * tuning.tick_s
    if not first > 0:
        return None
    # the first tick's step, then the air slows it to a stop: room for the drift
    drift = first * (tuning.air_stop_time_s / tuning.tick_s + 2)
    grid = TileGrid(4 + math.ceil(drift / tile), rows, tile, tile)
    grid.put(0, 1, TileShape(Box(0, tile, tile, tile), TileKind.SOLID, 0, 1))
    spawn = Box(tile - min(1.0, first / 2), tile - tuning.player_height_px,
                tuning.player_width_px, tuning.player_height_px)
    level = Level(Path("envelope"), grid, spawn)
    paths: list[list[float]] = []
    for press in [None, *range(1, tuning.coyote_ticks + 3)]:
        world = World(level, tuning)
        if not world.player.on_ground:
            return None
        if rising:
            world.player.vy = -tuning.jump_speed_px_s
        heights = [0.0]
        for tick in range(1, ticks + 1):
            held = {Action.RIGHT} if tick == 1 else set()
            if press is not None and tick >= press:
                held.add(Action.JUMP)
            events = world.step(frozenset(held))
            moved = world.moves.get(world.player)
            if (any(e.kind is EventKind.HURT for e in events) or world.player.on_ground
                    or moved is None or moved.x.hit is not None or moved.y.hit is not None):
                return None  # left the test level's open air: nothing measured
            heights.append(tile - world.player.box.bottom)
        paths.append(heights)
    last = [path[-1] - path[-2] for path in paths]  # each path's last move up (< 0: down)
    if max(last) >= 0 or max(path[-1] for path in paths) >= 0:
        return None  # still rising, or not yet below the take-off, when measuring stopped
    risings = [sum(1 for a, b in pairwise(path) if b > a)
               for path in paths]
    last_rises = [max((i for i in range(1, len(path)) if path[i] > path[i - 1]), default=0)
                  for path in paths]
    starts_at = [-path[i - 1] for path in paths for i in range(1, len(path))
                 if path[i] > path[i - 1]] or [0.0]
    heights = [max(path[k] for path in paths) + SLACK_PX for k in range(ticks + 1)]
    after = [-math.inf] * (ticks + 1)
    highest = -math.inf
    for k in range(ticks, 0, -1):
        highest = max(highest, heights[k], heights[k - 1])
        after[k] = -highest
    return AirEnvelope(
        tuning.run_speed_px_s * tuning.tick_s, tuple(heights), -max(last) * (1 - 1e-9),
        max(risings), max(last_rises), max(starts_at) + SLACK_PX, tuning.corner_correction_px,
        tuning.player_width_px, tuning.player_height_px, tuple(after))


class Sweep:
    """The furthest left and right the body's left edge can be, tick by tick, after leaving
    a launch. Sideways the game moves a box by float sums (:func:`~game.collision.axis_sweep.
    move_x`: ``x + w``, plus the step, less ``w``; leftwards ``x`` plus the step), each
    rounded to the nearest float, which never turns a smaller sum into a larger one: so
    the same sums at full run speed from the furthest place the body stands are the
    furthest it can be, to the last bit. A corner correction's slide, where a ceiling is
    near, is added on each rising tick, with :data:`SLACK_PX` to spare."""

    def __init__(self, envelope: AirEnvelope, width: float, low: float, high: float,
                 standing: bool, corners: tuple[float, float] | None) -> None:
        """``low``/``high``: the launch's ends, as a surface's (``standing``: a body
        ``width`` wide stands while ``x + width > low`` and ``x < high``) or as a start's
        (the body is at ``low == high``)."""
        self.envelope, self.width, self.corners = envelope, width, corners
        w = width
        if standing:
            high = math.nextafter(high, -math.inf)  # the last float left of the end
            end, low = low, low - w  # then the first float whose box passes the left end
            while low + w <= end:
                low = math.nextafter(low, math.inf)
            while math.nextafter(low, -math.inf) + w > end:
                low = math.nextafter(low, -math.inf)
        self.left, self.right = [low], [high]

    def at(self, ticks: int) -> tuple[float, float]:
        """The least and the most the left edge can be ``ticks`` ticks after leaving."""
        envelope, w = self.envelope, self.width
        step = envelope.step_px
        while len(self.right) <= ticks:
            right, left = self.right[-1], self.left[-1]
            self.right.append(max(right, ((right + w) + step) - w))  # (or it stays put)
            self.left.append(min(left, left + -step))
        low, high = self.left[ticks], self.right[ticks]
        if self.corners is not None and ticks >= 1:  # the last slide's corner, then runs
            run = (ticks - 1) * step + SLACK_PX * (ticks + 1)
            low = min(low, self.corners[0] - run)
            high = max(high, self.corners[1] + run)
        return low, high

    def overlaps(self, ticks: int, left: float, right: float) -> bool:
        """Can the box overlap ``left``..``right`` (strictly, as the game's lookups ask)
        ``ticks`` ticks after leaving?"""
        low, high = self.at(ticks)
        return left < high + self.width and low < right


@dataclass(frozen=True)
class Surface:
    """A run of tops at one height: the body stands on it with its left edge in
    ``(left - width, right)``."""

    left: float
    right: float
    top: float
    one_way: bool = False  # some of it is a OneWay top (a body may stand there rising)


def _covered(grid: TileGrid, shape: TileShape, above: bool) -> bool:
    """Is the top of ``shape`` (``above``; else its bottom) wholly against a Solid shape on
    its other side? No body is ever there: it would overlap that Solid."""
    box = shape.box
    face = box.top if above else box.bottom
    for row in (shape.row - 1, shape.row) if above else (shape.row, shape.row + 1):
        for other in grid.shapes_at(shape.col, row):
            o = other.box
            if (other is not shape and other.kind is TileKind.SOLID
                    and (o.bottom if above else o.top) == face
                    and o.left <= box.left and o.right >= box.right):
                return True
    return not above and face >= grid.height_px  # a head that high is below the map


def surfaces(grid: TileGrid, width: float) -> list[Surface]:
    """The runs of Solid and OneWay tops a body can stand on (a top under a Solid is a
    wall's inside: no body is ever there), tops the body's width joins merged."""
    tops: dict[float, list[tuple[float, float, bool]]] = {}
    for shape in grid.shapes():
        if shape.kind is not TileKind.HAZARD and not _covered(grid, shape, True):
            tops.setdefault(shape.box.top, []).append(
                (shape.box.left, shape.box.right, shape.kind is TileKind.ONE_WAY))
    found: list[Surface] = []
    for top, spans in tops.items():
        spans.sort()
        left, right, one_way = spans[0]
        for s_left, s_right, s_one_way in spans[1:]:
            if s_left - width <= right:  # a body can stand across the join
                right, one_way = max(right, s_right), one_way or s_one_way
            else:
                found.append(Surface(left, right, top, one_way))
                left, right, one_way = s_left, s_right, s_one_way
        found.append(Surface(left, right, top, one_way))
    return found


def ceilings(grid: TileGrid) -> list[Surface]:
    """The runs of Solid bottoms a rising head can meet (a bottom wholly against a Solid
    under it is met by no body), bottoms that touch merged, sorted by height."""
    bottoms: dict[float, list[tuple[float, float]]] = {}
    for shape in grid.shapes():
        if shape.kind is TileKind.SOLID and not _covered(grid, shape, False):
            bottoms.setdefault(shape.box.bottom, []).append((shape.box.left, shape.box.right))
    found: list[Surface] = []
    for bottom, spans in sorted(bottoms.items()):
        spans.sort()
        left, right = spans[0]
        for s_left, s_right in spans[1:]:
            if s_left <= right:
                right = max(right, s_right)
            else:
                found.append(Surface(left, right, bottom))
                left, right = s_left, s_right
        found.append(Surface(left, right, bottom))
    return found


@dataclass
class Exact:
    """What the pixel-exact reach found: whether an Exit is touched, the runs of tops
    reached, and what it does not bound: the enemies and platforms it comes within
    touching distance of, or could not bound (while there is any, it proves nothing)."""

    touches_exit: bool
    reached: list[Surface] = field(default_factory=list)
    unbounded: list[str] = field(default_factory=list)
    gap_px: int = 0  # the bounds it used, as the summary prints them
    ledge_px: int = 0

    @property
    def proves(self) -> bool:
        return not self.touches_exit and not self.unbounded


@dataclass(frozen=True)
class _Launch:
    """Where a jump may leave from: a surface's ends (``standing``), or a start's place
    (``low == high``), with the feet at ``top``."""

    low: float
    high: float
    top: float
    standing: bool = False
    rising: bool = False  # a OneWay top: the body may leave it rising (a jump's speed)


def exact_reach(world: World) -> Exact:
    """The pixel-exact reach of ``world``'s level with its tuning, from the spawn and every
    Checkpoint's respawn place once that flag can be counted: worked out with the walls
    alone, then kept clear of every enemy and moving platform
    (:mod:`game.checker.mechanic_bounds`); each it comes within touching distance of is
    named in :attr:`Exact.unbounded`."""
    level, tuning = world.level, world.tuning
    envelope, rising = air_envelope(tuning), air_envelope(tuning, rising=True)
    if envelope is None or rising is None:
        return Exact(False, unbounded=["this map's physics (a jump could not be measured "
                                       f"within {MAX_ENVELOPE_TICKS:,} ticks)"])
    grid = level.grid
    w, h = world.spawn.w, world.spawn.h  # the player's box (a Player object sets its size)
    tops = surfaces(grid, w)
    ceiling_runs = ceilings(grid)
    ceiling_heights = [run.top for run in ceiling_runs]
    exits = list(level.exits)
    flags = [(Box(f.x - 1, f.top - f.h, f.w + 2, 2 * f.h), f, start) for f, start
             in zip(level.checkpoints, starts_of(world)[1:], strict=False)]
    queue = [_Launch(b.x, b.x, b.bottom) for b in starts_of(world)[:1]]
    left = list(tops)
    reached: list[Surface] = []
    result = Exact(False, reached, gap_px=envelope.widest_gap_px(),
                   ledge_px=envelope.highest_ledge_px())
    touchers: list[Callable[[Box], bool]] = []  # each launch's test: can its body overlap?
    pairs = 0
    while queue:
        launch = queue.pop()
        pairs += len(left) + len(exits) + len(flags)
        if pairs > MAX_PAIRS:
            return _too_many()
        air = rising if launch.rising else envelope
        corners = _corners(ceiling_runs, ceiling_heights, launch, w, h, air)
        sweep = Sweep(air, w, launch.low, launch.high, launch.standing, corners)

        def touches(region: Box, launch: _Launch = launch, sweep: Sweep = sweep,
                    air: AirEnvelope = air) -> bool:
            ticks = air.last_tick_at(launch.top - h - region.bottom)
            return ticks >= 0 and sweep.overlaps(ticks, region.left, region.right)

        touchers.append(touches)
        if any(touches(goal) for goal in exits):
            result.touches_exit = True
            return result
        for region, flag, start in list(flags):
            if touches(region):
                moved = respawn_moved_by(world, flag)
                if moved is not None:
                    return Exact(False, unbounded=[moved])
                flags.remove((region, flag, start))
                queue.append(_Launch(start.x, start.x, start.bottom))
        for surface in list(left):
            ticks = air.last_tick_at(launch.top - surface.top)
            if ticks >= 0 and sweep.overlaps(ticks, surface.left, surface.right):
                left.remove(surface)
                reached.append(surface)
                queue.append(_Launch(surface.left, surface.right, surface.top, True,
                                     surface.one_way))
    if level.enemies or level.platforms:
        bounds, result.unbounded = enemy_bounds(world, FillWork())
        bounds += platform_bounds(world)
        pairs += len(touchers) * sum(len(bound.boxes) for bound in bounds)
        if pairs > MAX_PAIRS:
            return _too_many()
        result.unbounded += [bound.name for bound in bounds
                             if any(touches(box) for box in bound.boxes for touches in touchers)]
    return result


def _too_many() -> Exact:
    return Exact(False, unbounded=[f"a map with more than {MAX_PAIRS:,} pairs of a place to "
                                   "jump from and a place to land on, touch or keep clear of"])


def starts_of(world: World) -> list[Box]:
    """The spawn, then each Checkpoint's respawn place, found with the tiles alone (where a
    platform could move one, :func:`~game.checker.mechanic_bounds.respawn_moved_by` says
    so before it is used)."""
    return [start.box for start in starts(world)]


def _corners(ceilings: list[Surface], heights: list[float], launch: _Launch, width: float,
             height: float, envelope: AirEnvelope) -> tuple[float, float] | None:
    """Where a corner correction may put the body's left edge on a jump from ``launch``:
    the least and the most, or None when no ceiling is near. A slide leaves the body
    flush with a corner of a run of Solid bottoms its rising head meets, so after the last
    slide it is at a corner and moves on from there. The runs are those at the heights a
    head rising from the launch passes, within the sideways reach of a rise (``heights``:
    the runs' bottoms, for :mod:`bisect`)."""
    head = launch.top - height
    first = bisect.bisect_left(heights, head - max(envelope.heights) - SLACK_PX)
    last = bisect.bisect_right(heights, head + envelope.rise_start_px)
    reach = (envelope.step_px * envelope.last_rise + envelope.corner_px
             * envelope.rising_ticks + 1.0)
    near = [run for run in ceilings[first:last]
            if run.left < launch.high + width + reach and launch.low - width - reach < run.right]
    if not near:
        return None
    return min(run.left for run in near) - width, max(run.right for run in near)


def nearest_reached(exact: Exact, level: Level) -> Cell | None:
    """The tile just over the reached top nearest (as the crow flies) to an Exit."""
    if not exact.reached or not level.exits:
        return None
    grid = level.grid

    def distance(surface: Surface) -> float:
        return min(math.dist((min(max(goal.x + goal.w / 2, surface.left), surface.right),
                              surface.top), (goal.x + goal.w / 2, goal.y + goal.h / 2))
                   for goal in level.exits)

    best = min(exact.reached, key=lambda s: (distance(s), s.top, s.left))
    goal = level.exits[0]
    x = min(max(goal.x + goal.w / 2, best.left), best.right - 0.5)
    return math.floor(x / grid.tile_w), math.floor((best.top - 0.5) / grid.tile_h)
