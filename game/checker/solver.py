"""Prove a level can be won: search the game's own simulation for inputs that reach an Exit.

Where it sits: above the loader. ``python -m game.levels solve MAP`` prints what it finds
and ``python -m game.levels check`` runs it on every map it checks. It plays the real game:
the same :meth:`World.step`, the same tuning, the same map properties, so a route it finds
is a route a player can take, and the input script it writes wins the level when replayed
with ``python -m game --headless --level MAP --inputs SCRIPT``.

What it teaches: a **beam search** over a deterministic simulation.

* **Moves.** Every :data:`MOVE_TICKS` ticks the player picks one of a few held-input
  choices (:data:`CHOICES`: run left or right, with or without jump, stand, jump on the
  spot, and drop through a one-way floor). Holding jump into the next move keeps a jump
  rising; letting go cuts it, so short and long jumps are both there. In the air a move
  steers left or right, unless it carries on as the move before did (a jump straight up
  keeps rising straight up): that leaves two of the seven choices out of every airborne
  state, and every shipped level takes fewer moves to solve.
* **A macro-action for the widest jumps.** When a run goes off an edge, the best-first
  search (below) also tries the same run with jump pressed on the last tick coyote time
  allows, which a move every 6 ticks would rarely hit: that is how the widest gaps are
  crossed. The beams keep to the plain moves: with the late jumps, the five levels with
  moving platforms took 22,833 moves instead of 19,299 (Ferry Lines 8,887 instead of 5,004).
* **Two macro-actions: waits.** On a level with moving platforms, a player on the ground
  near a platform's route may also let go of the keys and stand for :data:`WAIT_TICKS`
  ticks in one move, or stand until a platform comes within :data:`COMES_PX` (worked out
  from the platforms' routes alone, since they go their ways whatever the player does), so
  a beam waiting for a ferry pays for one child instead of seven every 6 ticks. A wait
  counts as the moves its ticks would take, so the budget still measures the work done.
* **Two stages, taking turns: plain moves and timed inputs.** The moves above, held 6
  ticks each, may spend :data:`PLAIN_SHARE` of the budget. A second search, from the spawn,
  spends the rest, and also tries inputs timed to the tick
  (:meth:`_Search.timed_children`): on the ground near an edge, jump pressed on each tick
  from :data:`EARLY_TICKS` before the run leaves the ground to the last coyote tick, held
  for each number of ticks of the rise; in the air just before landing, jump pressed so
  the jump buffer makes it leave on the first tick on the ground. This stage tells apart
  places :data:`~game.checker.search_key.FINE_PLACE_PX` apart.
  The two take turns (:meth:`_Search.turns`): the plain moves for the first
  :data:`FIRST_PLAIN_SHARE` of the budget (every shipped level is solved there, The Last
  Peak in under a sixth of its budget), then the timed inputs for :data:`FIRST_TIMED_SHARE`,
  then the rest of the plain moves' share, then the rest of the budget; a stage carries on
  where its last turn ended, at the first state or layer past its share. So a map whose
  only route needs a jump timed to the tick does not wait for the plain moves' whole
  share: the five in ``tests/test_timed_inputs.py`` took 6,389 to 7,408 moves of their
  9,000 or 10,680 when the timed inputs came only after it, and take 2,789 to 3,709. A
  map whose plain route takes more than the first turn pays for the timed inputs' turn
  before it: stairs beside a cliff (``tests/test_solver_search.py``) took 5,429 moves of
  its 9,960, and takes 9,418.
* **Lining a run up.** On the ground the run's speed changes in steps of half a pixel a
  tick, so from a spawn at a whole pixel every run's last tick on the ground falls on the
  same few places, and the widest gap may need another. The timed stage also tries, once
  for each edge, a small hop before the run that changes the speed in the air (in finer
  steps), measures where each hop's run leaves the ground, and tries the edge's jumps from
  where the one furthest forward lands (:meth:`_Search.line_up`).
* **The budget grows with the map** (:mod:`game.checker.search_budget`): moves for each
  cell the reach proof's fill reached, unless ``--budget N`` gives one.
* **Snapshots** (:mod:`game.sim.snapshot`) make trying a move cheap: restore the parent's
  state, step the world, keep the child's state.
* **Enemies go their own way** (:mod:`game.checker.enemy_timeline`): where an enemy is at a
  tick does not depend on the player, so the first move through a tick writes the enemies
  down and later moves leave out those far from the player, putting them back afterwards.
* **A layer per move.** All children of the current beam are scored by how far they still
  are from an Exit, and the best :attr:`Effort.width` survive, at most :data:`PER_CELL` of
  them in any one tile while others are left: a beam whose states all stand in one place is
  one state wide, and stuck together. Two states with the same key
  (:mod:`game.checker.search_key`: about the same place and speed, the nearby moving
  platforms at the same point of their paths) are the same state: only the first is kept,
  so the beam cannot go round in circles.
* **The score** is the number of steps from the player's cell to an Exit along the moves
  of the reach proof (:func:`game.checker.reachable.steps_to_exit`): it knows that a ledge
  too high must be climbed from elsewhere, and a state from which no step leads on to an
  Exit (at the bottom of a pit) is dropped. A fall with no floor straight below, or with
  spikes (Hazard tiles) on the first floor below, counts more: a tile more for the
  best-first search (Spike Gauntlet took 4,777 moves before, and takes about 2,100), and
  :data:`PIT_PENALTY_TILES` for the beams, which score any other fall by where it lands:
  the steps of the tile above that floor, if more than its own. So standing at the edge
  of a pit waiting for a platform is better than jumping into it, a jump that comes down
  on a spike bed is not kept in place of one that clears it, and a jump on the spot beside
  a lift is not kept in place of a ride up it (the reach proof's steps are the same all
  along a ride).
  Where the steps are level, as all along a moving platform's ride, the beams' score also
  leans, by less than a step, towards the nearest cell beside one of fewer steps
  (:func:`plateau_distances`): along a ferry's route to its far end, up a lift to its
  top. Dusk Rhythm took 11,379 moves before the beams did both (they jumped into its
  short spike beds until every life was lost, and jumped on the spot under its lift), and
  takes about 2,200; the five levels with moving platforms took 40,136 together, and
  about 19,300.
* **Best first, then beams.** First a best-first search always carries on from the state
  with the best score (counting time a little); it is quick where no waiting is needed.
  It plays a state's moves one at a time (deferred evaluation): each waits in the queue
  with its state's score, the runs and their jumps first (:data:`TRY_ORDER`), and is
  played only when it comes out, the state it reaches going in with its own score. So a
  move that gets closer is carried on at once, and a state's next move is played only
  when nothing played since came closer: First Steps is solved in under 1,200 moves
  (``tests/test_solver_search.py`` keeps it so), where playing all seven of every state's
  moves took 2,510.
  Its score also counts where the feet are within their tile, leaning towards the
  neighbouring tiles' steps (:meth:`_Search.within_tile`), so a run that got further along
  a corridor goes first, not every state that stands in the same tile; and each state
  already kept in a tile puts the next one there :data:`CROWD_TILES` further back, so a
  place where the steps promise more than the game gives (the air beside a wall the steps
  climb, which only a jump from elsewhere clears) is left once it is crowded, for the
  tiles not yet tried. If it has not found a route after :attr:`Effort.greedy_moves`
  moves, or :data:`GREEDY_SHARE` of the stage's moves where that is more (a long maze),
  beams take over. On a level with moving platforms the beams go first: waiting for a
  platform never improves the score, so a best-first search would never wait.
* **Widening where stuck.** A narrow beam is fast but can throw away the one state that
  needed to wait. When a beam dies out, or gets no closer for a while, the search goes back
  :data:`BACK_MOVES` layers and carries on from there twice as wide (going back twice as
  far, and twice as wide again, each time it is stuck before coming closer than ever), and
  narrows again once a state on the ground (standing, or riding a platform) has come closer
  than any before: the work already done before the hard place is kept, not done again. A
  jump that rises into a nearer cell has not got past the hard place until it lands there:
  narrowing on it, The Last Peak's beams narrowed again each time a jump under its lift
  rose nearer its top (6,811 moves; it takes 6,752).
* **Losing a life** is allowed while lives remain (the game lets a player finish after one):
  the branch carries on from the respawn place, counting the life lost. A lost life adds
  nothing to the score: the respawn place's own distance to an Exit is what counts, so a
  route that needs a life lost (spikes crossed while the respawn's protection lasts) is not
  put off behind every state that kept its lives.

The search never proves a map *impossible*: :mod:`game.checker.reachable` does that, and
:mod:`game.checker.verdict` asks it first. Everything is deterministic: the search is bounded
by **work**, the moves it tries (:attr:`Effort.budget`), so the same map and options give the
same script and the same verdict on any machine, however loaded. On a crowded map a move
costs more (every enemy and platform is stepped each tick, every coin is looked at and
copied into each state kept), so there a move counts as several (:func:`move_weight`): on
a map with 100 enemies and 300 platforms, within its level's budget, 50,000 plain moves took
4.5 minutes and 800 MB. A wall-clock limit
(:attr:`Effort.seconds`) can be added on top; only then may the answer depend on the machine.
There is no limit on the length of a route in game time: a long route costs only moves.
When the search gives up it reports the furthest place it reached (closest to an Exit by the
score) and how many moves it tried.
"""

from __future__ import annotations

import heapq
import math
import time
from collections import deque
from collections.abc import Generator, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple, cast

from game.checker.enemy_timeline import Away, EnemyTimeline
from game.checker.reachable import steps_to_exit
from game.checker.search_budget import map_budget
from game.checker.search_key import (
    FINE_PLACE_PX,
    SAME_PLACE_PX,
    StateKey,
    route_box,
    route_is_near,
    state_key,
)
from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.levels.loader import load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, Actions, InputEvent, Recorder
from game.sim.level import Level
from game.sim.snapshot import Snapshot
from game.sim.world import EventKind, World

MOVE_TICKS = 6  # ticks one choice is held: 0.1 s, finer than a person presses keys
L, R, J, D = Action.LEFT, Action.RIGHT, Action.JUMP, Action.DOWN
CHOICES: tuple[Actions, ...] = (
    frozenset({R}), frozenset({R, J}), frozenset({L}), frozenset({L, J}),
    frozenset(), frozenset({J}), frozenset({D, J}))
DROP = CHOICES[-1]  # only tried while standing on a one-way floor
STEER = frozenset({L, R})  # in the air, a move steers, or carries on as the one before did
RUNS = (frozenset({R}), frozenset({L}))  # the moves that may run off an edge
LAST_COYOTE_TICK = 2  # coyote ticks left before the tick on which a jump is the last one
PIT_PENALTY_TILES = 6.0  # beams: falling with no floor below (or spikes on it) costs as
#                          much as this much distance
BEST_FIRST_PIT_TILES = 1.0  # best first: the same fall puts a state off this many tiles
STALL_MOVES = 60  # a beam that gets no closer for this many moves (plus a platform's
#                   round trip) is stuck
BACK_MOVES = 20  # a stuck beam goes back this many moves (doubling if stuck again) ...
HISTORY_LAYERS = 400  # ... but no further back than this (or else to the spawn)
PER_CELL = 1  # a beam keeps at most this many states in one tile while others are left
UNREACHABLE = math.inf
BEST_FIRST_WEIGHT = 3.0  # how much more a tile of distance counts than a tile's worth of time
CROWD_TILES = 0.2  # best first: each state kept in a tile puts the next there this many tiles
#                    further back
TRY_LATER_TILES = 0.001  # best first: each move of a state waits this many tiles behind the
#                          one before it in TRY_ORDER (a tie-break only) ...
TRY_ORDER: tuple[Actions, ...] = (  # ... rightwards first, each run before its jump, then
#                                     the moves on the spot; the waits after them all
    frozenset({R}), frozenset({R, J}), frozenset({L}), frozenset({L, J}),
    frozenset({J}), frozenset(), frozenset({D, J}))
GREEDY_SHARE = 0.5  # of a stage's moves, the best-first search may try at least this share
FEET_PX = 0.5  # the search scores the cell just above the middle of the feet
PLAIN_SHARE = 0.6  # of a map's budget, what the plain moves may spend in all
FIRST_PLAIN_SHARE = 0.2  # of a map's budget, the plain moves' first turn ...
FIRST_TIMED_SHARE = 1 / 3  # ... then the timed inputs' first turn, then each stage's rest
EARLY_TICKS = 16  # an edge's jumps are pressed from this many ticks before the run leaves it
EDGE_LOOK_PX = 48.0  # the edge's jumps are tried from the first state this close to an edge
MAX_RUN_TICKS = 60  # the run to an edge is given up after this many ticks
MAX_FALL_TICKS = 120  # a timed jump that has not landed after this many ticks is dropped
FULL_HOLD_TICKS = 10 * MOVE_TICKS  # jump held this long: the whole rise, on any physics
PHASES_PER_PX = 8  # an edge's jumps are tried again from a place 1/8 px further along a tick
LINE_UP_LOOK_PX = 160.0  # a run to an edge is lined up from the first state this close to it
LINE_UP_RUN_TICKS = 150  # a lining-up run that has not reached the edge by then is dropped
LET_GO_TICKS = 6  # a lining-up hop lets go of the keys in the air for up to this many ticks
WAIT_TICKS = 30  # the wait macro: stand still this long, for a moving platform to come round
UNTIL_A_PLATFORM_COMES = 0  # the other wait: stand still until a moving platform comes ...
COMES_PX = 16.0  # ... this close to the player
MAX_WAIT_TICKS = 36_000  # no wait is longer than this (10 minutes of play)
SURELY_BELOW = 1 - 1e-9  # a skip ahead rounds down, past any rounding of the floats
# What makes a move dearer, measured on a shared 2-core machine: a tick of a small level
# takes about 35 us and a state's snapshot, taken and restored, 20 to 80 us; each enemy or
# platform adds about 2.5 us a tick, each coin 0.3 us a tick and 2.5 us a snapshot (400
# bodies: 1 ms a tick; 5,000 coins: 1.4 ms a tick and 11 ms a snapshot).
BODIES_PER_MOVE = 16  # enemies and platforms that together make a move count one more
COINS_PER_MOVE = 32  # coins that together make a move count one more


def move_weight(level: Level) -> int:
    """How many moves of the budget one move on ``level`` counts for: 1 on a level with
    fewer than :data:`BODIES_PER_MOVE` enemies and platforms and :data:`COINS_PER_MOVE`
    coins (every shipped level), more as its bodies make every tick and state dearer.

    >>> from game.levels import FIRST_LEVEL
    >>> move_weight(load_level(FIRST_LEVEL))
    1
    """
    bodies = len(level.enemies) + len(level.platforms)
    return 1 + bodies // BODIES_PER_MOVE + len(level.coins) // COINS_PER_MOVE


@dataclass(frozen=True)
class Effort:
    """How hard to look: the beam's width where it is not stuck, and the limits on the work."""

    budget: int | None = None  # moves the whole search may try (None: the map's own budget,
    #                            :func:`game.checker.search_budget.map_budget`)
    greedy_moves: int = 14_000  # of those, the most the best-first search may try first
    #                             (or GREEDY_SHARE of the stage's moves, where that is more)
    width: int = 2  # the beam's width where it is not stuck
    seconds: float | None = None  # an extra wall-clock limit (None: none, the default)


@dataclass
class Node:
    """A state the search reached: the move that led here from its parent."""

    parent: Node | None
    choice: Actions
    ticks: int  # ticks since the start
    lives_lost: int = 0


class Try(NamedTuple):
    """One move the search may try from a state, as :meth:`_Search.choices_here` finds it."""

    choice: Actions
    move_ticks: int
    wait: tuple[float, float, int] | None = None  # a wait's (place, tick a platform comes)
    late: bool = False  # the run's jump on the last coyote tick off the edge ahead


@dataclass
class Solution:
    """What the search found: a route to an Exit, or how far it got."""

    level: Level
    found: bool
    held: list[Actions]  # the input of every tick, from tick 0 to the one that reached the Exit
    furthest: Box  # the player's hitbox at the place closest to an Exit
    route: list[Box] = field(default_factory=list)  # the hitbox after every tick
    moves_tried: int = 0
    timed_out: bool = False
    budget: int = 0  # the moves it might have tried: ``--budget N``, or the map's own
    states: int = 0  # distinct states the search kept
    own_budget: bool = True  # the budget is the map's own (no ``--budget N`` given)
    timed: bool = False  # the route was found by the stage with inputs timed to the tick

    @property
    def out_of_budget(self) -> bool:
        return self.moves_tried >= self.budget

    @property
    def exit_tick(self) -> int:
        return len(self.held)

    def script(self) -> str:
        """The route as an input script in the game's format."""
        recorder = Recorder()
        for tick, held in enumerate(self.held):
            recorder.observe(tick, held)
        recorder.observe(len(self.held), frozenset())
        title = self.level.title or self.level.path.stem
        lines = [f"# Wins '{title}' by reaching its Exit (found by python -m game.levels solve)."]
        lines += [str(event) for event in _tidy(recorder.events)]
        lines.append(f"# reaches the exit at tick {self.exit_tick}")
        return "\n".join(lines) + "\n"

    def furthest_tile(self) -> tuple[int, int]:
        grid = self.level.grid
        x, y = self.furthest.center
        return math.floor(x / grid.tile_w), math.floor(y / grid.tile_h)


def _tidy(events: Sequence[InputEvent]) -> list[InputEvent]:
    """Releases before presses within a tick, so a script reads as a person's keys would."""
    return sorted(events, key=lambda e: (e.tick, e.pressed, e.action.value))


def distances_to_exit(level: Level) -> dict[tuple[int, int], int]:
    """Steps through open cells (4-neighbours) from every cell to the nearest Exit's cells.

    Cells above the map count as open, since the sky is; cells filled by a whole Solid tile
    are closed. This ignores gravity: it is a guide for the search, not a route.
    """
    grid = level.grid
    closed = {(s.col, s.row) for s in grid.shapes()
              if s.kind is TileKind.SOLID and s.box.w >= grid.tile_w and s.box.h >= grid.tile_h}
    sky_rows = 4
    steps: dict[tuple[int, int], int] = {}
    queue: deque[tuple[int, int]] = deque()
    for goal in level.exits:
        for col in range(math.floor(goal.left / grid.tile_w),
                         math.ceil(goal.right / grid.tile_w)):
            for row in range(math.floor(goal.top / grid.tile_h),
                             math.ceil(goal.bottom / grid.tile_h)):
                if (col, row) not in steps:
                    steps[(col, row)] = 0
                    queue.append((col, row))
    while queue:
        col, row = queue.popleft()
        for near in ((col + 1, row), (col - 1, row), (col, row + 1), (col, row - 1)):
            if (0 <= near[0] < grid.cols and -sky_rows <= near[1] < grid.rows
                    and near not in closed and near not in steps):
                steps[near] = steps[(col, row)] + 1
                queue.append(near)
    return steps


def plateau_distances(steps: dict[tuple[int, int], int]) -> dict[tuple[int, int], int]:
    """For every cell of ``steps``, the fewest moves to a neighbouring cell (4-neighbours)
    that keep to cells of its own steps and end in a cell beside one of fewer steps: 0
    where the steps go down next door."""
    distances: dict[tuple[int, int], int] = {}
    queue: deque[tuple[int, int]] = deque()
    for (col, row), here in steps.items():
        if any(steps.get(near, here) < here for near in _neighbours(col, row)):
            distances[(col, row)] = 0
            queue.append((col, row))
    while queue:
        col, row = queue.popleft()
        here = steps[(col, row)]
        for near in _neighbours(col, row):
            if near not in distances and steps.get(near) == here:
                distances[near] = distances[(col, row)] + 1
                queue.append(near)
    return distances


def _neighbours(col: int, row: int) -> tuple[tuple[int, int], ...]:
    return (col + 1, row), (col - 1, row), (col, row + 1), (col, row - 1)


class _Search:
    """One level's search state: the world it steps, the score and what it has seen."""

    def __init__(self, level: Level, effort: Effort,
                 steps: dict[tuple[int, int], int] | None = None, timed: bool = False,
                 ) -> None:
        self.level = level
        self.effort = effort
        self.world = World(level)
        self.timeline = EnemyTimeline(self.world)
        self.steps = (steps if steps is not None else steps_to_exit(World(level))
                      ) or distances_to_exit(level)
        self.start = Snapshot.of(self.world)
        self.goal_cells = [cell for cell, steps in self.steps.items() if steps == 0]
        self.lives = self.world.tuning.start_lives
        self.lost_in_move = 0  # lives the last move lost (:meth:`hold`)
        self.routes = [route_box(platform) for platform in self.world.platforms]
        self.moves: list[tuple[Actions, int]] = [(choice, MOVE_TICKS) for choice in CHOICES]
        if self.world.platforms and WAIT_TICKS:
            self.moves[:0] = [(frozenset(), UNTIL_A_PLATFORM_COMES), (frozenset(), WAIT_TICKS)]
        # (place, tick a platform comes) of each wait tried, with the layer it was tried at
        self.waits: dict[tuple[float, float, int], int] = {}
        self.moves_tried = 0
        self.budget = (effort.budget if effort.budget is not None
                       else map_budget(len(self.steps)))
        self.limit = self.budget  # the moves this stage of the search may reach (run())
        self.turn_ends: float = math.inf  # ... and those it may reach before it pauses
        self.timed = timed  # the stage with timed inputs: they are tried too
        self.timed_stage: _Search | None = None  # turns() makes it, for the plain stage
        self.found_timed = False  # run() found its route in the timed stage
        # (edge cell, direction, place within a tick's run) of each edge's jumps tried
        self.edges_tried: set[tuple[tuple[int, int], int, int]] = set()
        # (edge cell, direction) of each run to an edge lined up (line_up())
        self.lined_up: set[tuple[tuple[int, int], int]] = set()
        self.weight = move_weight(level)  # moves of the budget each move counts for
        self.states = 0
        self.beaming = False  # the beams set it: see score()
        self.plateau = plateau_distances(self.steps)
        self.plateau_span = max(self.plateau.values(), default=0) + 1
        periods = [2 * p.spec.path.length / p.spec.speed_px_s for p in self.world.platforms
                   if p.spec.speed_px_s > 0]
        self.round_trip_ticks = math.ceil(min(max(periods, default=0.0) / self.world.tuning.tick_s,
                                              MAX_WAIT_TICKS))
        round_trip_moves = max(periods, default=0.0) / (MOVE_TICKS * self.world.tuning.tick_s)
        self.stall_moves = STALL_MOVES + math.ceil(min(round_trip_moves, 100_000))
        self.deadline = (time.monotonic() + effort.seconds if effort.seconds is not None
                         else None)
        self.best: tuple[float, Box, Node | None] = (
            self.score() if self.goal_cells else UNREACHABLE, self.world.player.box, None)

    def score(self) -> float:
        """How far the player still is from an Exit, in tiles (lower is better). A fall with
        no floor below, or spikes on it (:meth:`landing_cell`), counts
        :data:`BEST_FIRST_PIT_TILES` more; the beams (:attr:`beaming`) count
        :data:`PIT_PENALTY_TILES` more for it, score any other fall by where it lands, and
        lean across level steps (:meth:`plateau_lean`)."""
        cell = self.cell()
        steps = self.steps.get(cell)
        if steps is None:
            return UNREACHABLE
        player = self.world.player
        landing = self.landing_cell() if not player.on_ground and player.vy > 0 else cell
        if not self.beaming:
            return steps + (BEST_FIRST_PIT_TILES if landing is None else 0.0)
        if landing is None:
            return steps + PIT_PENALTY_TILES + self.plateau_lean(cell)
        landed = self.steps.get(landing)
        if landed is not None:
            steps, cell = max(steps, landed), landing
        return steps + self.plateau_lean(cell)

    def landing_cell(self) -> tuple[int, int] | None:
        """The tile the feet would stand in on the first floor straight below the player
        (a Solid or OneWay tile, or a moving platform where it is now), or None if there
        is none, or spikes (a Hazard tile) lie on it."""
        world, grid = self.world, self.level.grid
        box = world.player.box
        below = Box(box.x, box.bottom, box.w, max(1.0, grid.height_px - box.bottom))
        shapes = world.solids.shapes_in(below)
        floor = min((s.box.top for s in shapes if s.kind is not TileKind.HAZARD),
                    default=math.inf)
        if floor == math.inf or any(s.box.top <= floor for s in shapes
                                    if s.kind is TileKind.HAZARD):
            return None
        return self.cell()[0], math.floor((floor - FEET_PX) / grid.tile_h)

    def plateau_lean(self, cell: tuple[int, int]) -> float:
        """Less than a step: how far ``cell`` is, through cells of its own steps, from one
        beside a cell of fewer steps (:func:`plateau_distances`), as a share of the
        furthest any cell is. Where the steps are level (a moving platform's whole ride is
        one step from its way off), this points along the ride to where it leads on."""
        return self.plateau.get(cell, 0) / self.plateau_span

    def key(self, choice: Actions) -> StateKey:
        """What makes two states the same for the search (:mod:`game.checker.search_key`)."""
        return state_key(self.world, choice, self.routes,
                         FINE_PLACE_PX if self.timed else SAME_PLACE_PX)

    def ticks_until_a_platform_comes(self) -> int | None:
        """How long a player standing here must wait for a moving platform (one not within
        :data:`COMES_PX` now) to come within :data:`COMES_PX`, or None if none comes within
        a round trip. Found from the platforms' routes alone: a platform goes its way
        whatever the player does."""
        box, dt = self.world.player.box, self.world.tuning.tick_s
        soonest: int | None = None
        for platform, region in zip(self.world.platforms, self.routes, strict=True):
            if (platform.speed_px_s <= 0 or not route_is_near(box, region)
                    or box.gap(platform.box) <= COMES_PX):
                continue
            step = platform.speed_px_s * dt
            ticks, last = 1, min(self.round_trip_ticks, soonest or MAX_WAIT_TICKS)
            while ticks <= last:
                gap = box.gap(platform.box_at(platform.travelled_px + step * ticks))
                if gap <= COMES_PX:
                    soonest = ticks
                    break
                # It comes at most ``step`` px nearer a tick: no tick before this one can do.
                ticks += max(1, math.floor((gap - COMES_PX) / step * SURELY_BELOW))
        return soonest

    def waiting_helps(self) -> bool:
        """On the ground with a moving platform's route nearby (a player still running
        stops first: waiting only lets go of the keys)."""
        player = self.world.player
        return player.on_ground and any(
            route_is_near(player.box, region) for region in self.routes)

    def out_of_time(self) -> bool:
        """The search must stop: its budget of moves is spent, or its seconds are up."""
        return self.moves_tried >= self.limit or self.past_deadline()

    def past_deadline(self) -> bool:
        return self.deadline is not None and time.monotonic() > self.deadline

    def run(self) -> Node | None:
        """Both stages, taking turns (:meth:`turns`), until one finds a route or the budget
        is spent; :attr:`timed_stage` keeps the stage with timed inputs and its work, once
        it has had a turn."""
        self.limit = max(1, math.floor(self.budget * PLAIN_SHARE))
        return self.turns()

    def turns(self) -> Node | None:
        """The plain moves (this search) for :data:`FIRST_PLAIN_SHARE` of the budget, then
        the timed inputs (:attr:`timed_stage`, a search of its own from the spawn, made at
        its first turn: most maps never get there) for :data:`FIRST_TIMED_SHARE`, then the
        rest of the plain moves' :data:`PLAIN_SHARE`, then the rest of the budget for the
        timed inputs. A stage that pauses carries on where it was (:meth:`paused`); one
        that ends early leaves its moves to the other."""
        stages = {self: self.stage()}
        schedule = ((False, math.floor(self.budget * FIRST_PLAIN_SHARE)),
                    (True, math.floor(self.budget * FIRST_TIMED_SHARE)),
                    (False, math.inf), (True, math.inf))
        for timed_turn, turn_ends in schedule:
            if self.past_deadline():
                break
            if timed_turn and self.timed_stage is None:
                timed = self.timed_stage = _Search(self.level, self.effort, self.steps,
                                                   timed=True)
                timed.deadline, timed.limit = self.deadline, self.budget - self.limit
                stages[timed] = timed.stage()
            search, other = ((self.timed_stage, self) if timed_turn
                             else (self, self.timed_stage))
            if search is None or search not in stages:
                continue
            if other is not None and other not in stages:  # the other is over: the rest
                search.limit = self.budget - other.moves_tried  # of the budget is this one's
            search.turn_ends = turn_ends
            try:
                next(stages[search])
            except StopIteration as over:
                del stages[search]
                if over.value is not None:
                    self.found_timed = timed_turn
                    return cast(Node, over.value)
        return None

    def paused(self) -> bool:
        """This stage's turn is over (:meth:`turns`), though its own moves are not."""
        return self.moves_tried >= self.turn_ends and not self.out_of_time()

    def stage(self) -> Generator[None, None, Node | None]:
        """Best first (on a level without moving platforms), then beams that widen where
        they are stuck, until a route is found or this stage's share is spent; it yields
        where its turn is over (:meth:`paused`), and carries on from there."""
        # Waiting never looks better to a best-first search: on a level with moving
        # platforms, only the timed inputs' stage searches best first, for half its share
        # (a beam drops a timed jump while it is over a pit, as it drops every fall)
        if not self.world.platforms or self.timed:
            share = self.limit - self.moves_tried
            greedy = max(self.effort.greedy_moves, math.floor(share * GREEDY_SHARE))
            found = yield from self.best_first(self.moves_tried + min(
                greedy, share // 2 if self.world.platforms else share))
            if found is not None or self.out_of_time():
                return found
        return (yield from self.beams())

    def choices_here(self, node: Node | None, ticks: int) -> list[Try]:
        """The moves worth trying from the state the world is in (reached by ``node`` at
        tick ``ticks``), in the order of :attr:`moves`: in the air steer (or carry on as
        the move before did), DROP only on a one-way floor, waits only where waiting helps
        (and one that waits for a platform only if one comes)."""
        player = self.world.player
        choices: list[Try] = []
        for choice, move_ticks in self.moves:
            if choice is DROP and not player.on_ground_one_way:
                continue
            if (not choice & STEER and move_ticks == MOVE_TICKS and not player.on_ground
                    and (node is None or node.choice != choice)):
                continue  # in the air, steer (or carry on straight up or down as before)
            if move_ticks != MOVE_TICKS and not self.waiting_helps():
                continue
            if move_ticks == UNTIL_A_PLATFORM_COMES:
                coming = self.ticks_until_a_platform_comes()
                if coming is None:
                    continue  # none comes
                box = player.box
                choices.append(Try(choice, coming, (box.x, box.y, ticks + coming)))
                continue
            choices.append(Try(choice, move_ticks))
        return choices

    def children(self, snapshot: Snapshot, node: Node | None, ticks: int,
                 seen: dict[StateKey, int], layer: int = 0, late_jumps: bool = False,
                 ) -> Iterator[tuple[float, Snapshot, Node]]:
        """Every new state one move from ``snapshot``, and with ``late_jumps``, the jump on
        the last coyote tick off each edge a run went over; stops early at an Exit (its
        Node comes with an infinitely good score of minus infinity)."""
        ledges: list[Actions] = []  # runs that went off an edge: try them with a late jump
        if self.timed:
            for found in self.timed_children(snapshot, node, ticks, seen, layer):
                yield found
                if found[0] == -math.inf:
                    return
        snapshot.restore(self.world)
        moved = False  # the world has stepped on from ``snapshot`` since it was restored
        for choice, move_ticks, wait, _ in self.choices_here(node, ticks):
            if self.out_of_time():
                return
            if wait is not None:
                if wait in self.waits:
                    continue  # a wait here already met this platform
                self.waits[wait] = layer
            if moved:
                snapshot.restore(self.world)
            outcome = self.try_move(snapshot, ticks, choice, move_ticks)
            moved = True
            if late_jumps and outcome == 0 and choice in RUNS and self.ran_off_an_edge():
                ledges.append(choice)
            child = self.child(snapshot, node, choice, ticks, move_ticks, outcome, seen, layer)
            if child is not None:
                yield child
                if child[0] == -math.inf:
                    return
        for run in ledges:
            if self.out_of_time():
                return
            child = self.late_jump(snapshot, node, ticks, run, seen, layer)
            if child is not None:
                yield child
                if child[0] == -math.inf:
                    return

    def late_jump(self, snapshot: Snapshot, node: Node | None, ticks: int, run: Actions,
                  seen: dict[StateKey, int], layer: int,
                  ) -> tuple[float, Snapshot, Node] | None:
        """The state after the jump on the last coyote tick off the edge ``run`` goes over
        from ``snapshot`` (:meth:`jump_on_the_last_coyote_tick`), scored as :meth:`child`
        scores it."""
        jump = self.jump_on_the_last_coyote_tick(snapshot, node, ticks, run)
        if jump is None:
            return None
        ran, outcome = jump
        return self.child(snapshot, ran, run | {J}, ran.ticks, MOVE_TICKS, outcome, seen, layer)

    def child(self, snapshot: Snapshot, parent: Node | None, choice: Actions, start: int,
              move_ticks: int, outcome: int, seen: dict[StateKey, int], layer: int,
              ) -> tuple[float, Snapshot, Node] | None:
        """The new state the world is in after a move from ``parent`` (``outcome``: as
        :meth:`try_move` gives it), scored, or None if it was seen before or leads nowhere."""
        lost = (parent.lives_lost if parent is not None else 0) + self.lost_in_move
        if lost >= self.lives:
            return None  # the game is over before the move ends (or reaches the Exit)
        child = Node(parent, choice, start + (outcome if outcome > 0 else move_ticks), lost)
        if outcome > 0:
            return -math.inf, snapshot, child
        key = (*self.key(choice), lost)
        if key in seen:
            return None
        seen[key] = layer
        score = self.score()
        if score == UNREACHABLE:
            return None  # no way on to an Exit from here, by the proof of reachable
        self.states += 1
        if score < self.best[0]:
            self.best = (score, self.world.player.box, child)
        return score, Snapshot.of(self.world), child

    def timed_children(self, snapshot: Snapshot, node: Node | None, ticks: int,
                       seen: dict[StateKey, int], layer: int,
                       ) -> Iterator[tuple[float, Snapshot, Node]]:
        """The timed inputs, tried in the search's timed stage where they matter: on the
        ground near an edge, jumps pressed on each tick of the run to it and of coyote time
        after it, each held for each number of ticks of the rise (:meth:`edge_jumps`), and
        the same after a small hop that lines the run up (:meth:`line_up`); in the air just
        before landing, jump pressed so the jump buffer makes it leave on the
        first tick on the ground (:meth:`landing_jump`)."""
        snapshot.restore(self.world)
        if self.world.player.on_ground:
            yield from self.edge_jumps(snapshot, node, ticks, seen, layer)
            yield from self.line_up(snapshot, node, ticks, seen, layer)
        elif self.lands_soon():
            yield from self.landing_jump(snapshot, node, ticks, seen, layer)

    def edge_ahead(self, direction: int, look_px: float = EDGE_LOOK_PX,
                   ) -> tuple[int, int] | None:
        """The cell where the floor under the player's feet ends within ``look_px`` ahead
        in ``direction`` (+1 right, -1 left), if it does."""
        world, grid = self.world, self.level.grid
        box = world.player.box
        step = 2.0  # px between the places looked at, narrower than any gap worth a jump
        front = box.right if direction > 0 else box.left
        for place in range(math.ceil(look_px / step) + 1):
            x = front + direction * (place * step + 0.5)
            if not any(shape.kind is not TileKind.HAZARD
                       for shape in world.solids.shapes_in(Box(x - 0.5, box.bottom, 1.0, 1.0))):
                return math.floor(x / grid.tile_w), math.floor(box.bottom / grid.tile_h)
        return None

    def edge_jumps(self, snapshot: Snapshot, node: Node | None, ticks: int,
                   seen: dict[StateKey, int], layer: int, runs: Sequence[Actions] = RUNS,
                   ) -> Iterator[tuple[float, Snapshot, Node]]:
        """Once for each edge, direction and place within a tick's run (where the last step
        before the edge falls changes how far a jump carries, to 1/:data:`PHASES_PER_PX`
        px): run to the edge from here, and press jump on each tick from
        :data:`EARLY_TICKS` before the run leaves the ground to the last tick of coyote time,
        latest first; hold it for the whole rise, or, with something overhead
        (:meth:`overhead`), for each number of ticks until the rise ends (a longer hold is
        the same jump); then hold the run until the player lands (:meth:`run_until_landing`).
        """
        world, player = self.world, self.world.player
        lives = node.lives_lost if node is not None else 0
        step = world.tuning.run_speed_px_s * world.tuning.tick_s  # px a tick at a run
        for run in runs:
            snapshot.restore(world)
            direction = 1 if R in run else -1
            edge = self.edge_ahead(direction)
            # where the run's last step before the edge falls changes how far a jump carries:
            # each edge is tried from each place within a tick's run, to 1/PHASES_PER_PX px
            phase = math.floor(player.box.x % step * PHASES_PER_PX)
            if edge is None or (edge, direction, phase) in self.edges_tried:
                continue
            self.edges_tried.add((edge, direction, phase))
            states = [snapshot]
            left_at: int | None = None
            for tick in range(1, MAX_RUN_TICKS + 1):
                events = world.step(run)
                self.timeline.write_down(ticks + tick)
                if any(e.kind in (EventKind.EXIT, EventKind.HURT) for e in events):
                    break
                states.append(Snapshot.of(world))
                if left_at is None and not player.on_ground:
                    left_at = tick
                if left_at is not None and not player.coyote_ticks_left:
                    break
            self.moves_tried += math.ceil(len(states) / MOVE_TICKS) * self.weight
            if left_at is None:
                continue
            holds = (range(1, FULL_HOLD_TICKS) if self.overhead(snapshot, states[left_at])
                     else range(FULL_HOLD_TICKS, FULL_HOLD_TICKS + 1))
            # the latest presses first: the widest jumps are the late ones
            for press in range(len(states) - 1, max(0, left_at - EARLY_TICKS) - 1, -1):
                ran = Node(node, run, ticks + press, lives) if press else node
                for hold in holds:
                    if self.out_of_time():
                        return
                    states[press].restore(world)
                    outcome = self.try_move(states[press], ticks + press, run | {J}, hold)
                    if outcome > 0:
                        found = self.child(states[press], ran, run | {J}, ticks + press, hold,
                                           outcome, seen, layer)
                        if found is not None:
                            yield found
                            return
                    if outcome != 0:
                        break
                    rising = player.rising_from_jump
                    jumped = Node(ran, run | {J}, ticks + press + hold, lives)
                    landed = self.run_until_landing(jumped.ticks, run)
                    if landed is None:  # fell to a life lost, or still falling
                        if not rising:
                            break
                        continue
                    found = self.child(states[press], jumped, run, jumped.ticks, landed[0],
                                       landed[1], seen, layer)
                    if found is not None:
                        yield found
                        if found[0] == -math.inf:
                            return
                    if not rising:
                        break  # the rise has ended: holding longer is the same jump

    def line_up(self, snapshot: Snapshot, node: Node | None, ticks: int,
                seen: dict[StateKey, int], layer: int,
                ) -> Iterator[tuple[float, Snapshot, Node]]:
        """Once for each edge within :data:`LINE_UP_LOOK_PX` and direction: line the run up
        to the edge. On the ground the run's speed changes in steps of half a pixel a tick,
        so from a spawn at a whole pixel every run's last tick on the ground falls on the
        same places; in the air it changes in steps of an eighth of a pixel. So before the
        run, a small hop (jump pressed for one tick, standing or running) that lets go of
        the keys for 0 to :data:`LET_GO_TICKS` ticks in the air and then runs on: each is
        played to the edge, and where its last tick on the ground falls is measured
        (:meth:`last_ground_place`). The hop whose last tick on the ground is furthest
        forward, if further than the plain run's, is played again, and the edge's jumps
        (:meth:`edge_jumps`) are tried from its run, :data:`EARLY_TICKS` before it leaves
        the ground (or from its landing, if later)."""
        world = self.world
        lives = node.lives_lost if node is not None else 0
        for run in RUNS:
            snapshot.restore(world)
            direction = 1 if R in run else -1
            edge = self.edge_ahead(direction, LINE_UP_LOOK_PX)
            if edge is None or (edge, direction) in self.lined_up:
                continue
            self.lined_up.add((edge, direction))
            best = self.last_ground_place(snapshot, ticks, run, [])
            if best is None:
                continue
            chosen: list[Actions] | None = None
            for hop in (frozenset({J}), run | {J}):
                for let_go in range(LET_GO_TICKS + 1):
                    if self.out_of_time():
                        return
                    prefix = [hop, *[frozenset()] * let_go]
                    measured = self.last_ground_place(snapshot, ticks, run, prefix)
                    if measured is not None and measured[0] > best[0]:
                        best, chosen = measured, prefix
            if chosen is None:
                continue
            # play the best hop and its run again, and try the edge's jumps from the run
            handover = max(best[1], best[2] - EARLY_TICKS - 2)
            snapshot.restore(world)
            parent = node
            for tick, held in enumerate(chosen, start=1):
                world.step(held)
                self.timeline.write_down(ticks + tick)
                if tick == len(chosen) or chosen[tick] != held:
                    parent = Node(parent, held, ticks + tick, lives)
            for tick in range(len(chosen) + 1, handover + 1):
                world.step(run)
                self.timeline.write_down(ticks + tick)
            ran = Node(parent, run, ticks + handover, lives)
            self.moves_tried += math.ceil(handover / MOVE_TICKS) * self.weight
            yield from self.edge_jumps(Snapshot.of(world), ran, ran.ticks, seen, layer, (run,))

    def last_ground_place(self, snapshot: Snapshot, start: int, run: Actions,
                          prefix: Sequence[Actions]) -> tuple[float, int, int] | None:
        """From ``snapshot`` (at tick ``start``), hold ``prefix`` tick by tick, then ``run``
        until the player has landed on the floor it stood on and run off its edge: how far
        along the run the player was on the last tick on the ground (px, larger is further
        forward), the tick it stood again after ``prefix`` and the tick it left the ground
        (counted from ``start``). None if the run ended otherwise (a life lost, an Exit,
        another floor, or no edge within :data:`LINE_UP_RUN_TICKS` of running)."""
        snapshot.restore(self.world)
        player = self.world.player
        floor = player.box.bottom
        direction = 1 if R in run else -1
        landed: int | None = None
        place = 0.0
        tick = 0
        for tick in range(1, len(prefix) + MAX_FALL_TICKS + LINE_UP_RUN_TICKS + 1):
            held = prefix[tick - 1] if tick <= len(prefix) else run
            box = player.box
            events = self.world.step(held)
            self.timeline.write_down(start + tick)
            if any(e.kind in (EventKind.EXIT, EventKind.HURT) for e in events):
                break
            if tick <= len(prefix):
                continue
            if landed is None:
                if player.on_ground:
                    if player.box.bottom != floor:
                        break  # landed on another floor
                    landed = tick
                elif tick > len(prefix) + MAX_FALL_TICKS:
                    break
            elif not player.on_ground:
                place = box.x * direction  # where the last tick on the ground left it
                self.moves_tried += math.ceil(tick / MOVE_TICKS) * self.weight
                return place, landed, tick
            elif tick > landed + LINE_UP_RUN_TICKS:
                break
        self.moves_tried += math.ceil(tick / MOVE_TICKS) * self.weight
        return None

    def overhead(self, start: Snapshot, edge: Snapshot) -> bool:
        """Is anything (a ceiling, spikes) above the way from ``start`` to where the run
        leaves the ground at ``edge``, and a full jump beyond, lower than a full jump rises?
        Only then is a jump cut short worth trying at each tick."""
        tuning = self.world.tuning
        rise_px = tuning.jump_speed_px_s ** 2 / (2 * tuning.gravity_px_s2)
        beyond_px = 2 * tuning.jump_speed_px_s / tuning.gravity_px_s2 * tuning.run_speed_px_s
        edge.restore(self.world)
        there = self.world.player.box
        start.restore(self.world)
        here = self.world.player.box
        left = min(here.left, there.left) - beyond_px
        right = max(here.right, there.right) + beyond_px
        top = min(here.top, there.top)
        region = Box(left, top - rise_px, right - left, rise_px)
        return bool(self.world.solids.shapes_in(region))

    def run_until_landing(self, start: int, run: Actions) -> tuple[int, int] | None:
        """Hold ``run`` from tick ``start`` until the player stands or reaches an Exit: the
        ticks it took and the outcome (as :meth:`try_move` gives it); None if a life was lost
        on the way, or the player fell where no step leads on to an Exit, or
        :data:`MAX_FALL_TICKS` passed in the air. A timed jump that falls into
        a pit is not kept: each of them would make a tree of falling states."""
        player = self.world.player
        for tick in range(1, MAX_FALL_TICKS + 1):
            outcome = self.hold(run, start + tick - 1, 1, ()) or 0  # (no enemy left out)
            if outcome or player.on_ground:
                break
            if self.cell() not in self.steps:
                outcome = -1  # no way on to an Exit from here (the reach proof's steps)
                break
        self.moves_tried += math.ceil(tick / MOVE_TICKS) * self.weight
        if outcome < 0 or not (outcome or player.on_ground):
            return None
        return tick, tick if outcome else 0

    def lands_soon(self) -> bool:
        """Falling, with a floor under the feet within the fall of one move."""
        world = self.world
        player, tuning = world.player, world.tuning
        if player.vy <= 0:
            return False
        box = player.box
        fall = tuning.max_fall_speed_px_s * tuning.tick_s * (MOVE_TICKS + 1)
        return any(shape.kind is not TileKind.HAZARD
                   for shape in world.solids.shapes_in(Box(box.x, box.bottom, box.w, fall)))

    def landing_jump(self, snapshot: Snapshot, node: Node | None, ticks: int,
                     seen: dict[StateKey, int], layer: int,
                     ) -> Iterator[tuple[float, Snapshot, Node]]:
        """Steer on as the move before did, jump let go, and press jump again on the tick
        the player lands (while still in the air: the jump buffer keeps it), so the next
        jump leaves on the first tick on the ground; hold it for one move."""
        world, player = self.world, self.world.player
        steer = (node.choice if node is not None else frozenset()) - {J}
        lives = node.lives_lost if node is not None else 0
        for tick in range(1, 2 * MOVE_TICKS + 1):
            events = world.step(steer)
            self.timeline.write_down(ticks + tick)
            if any(e.kind in (EventKind.EXIT, EventKind.HURT) for e in events):
                return
            if player.on_ground:
                break
        else:
            return
        self.moves_tried += math.ceil(tick / MOVE_TICKS) * self.weight
        if tick < 2:
            return  # no tick to let go of jump on before the press
        snapshot.restore(world)
        outcome = self.try_move(snapshot, ticks, steer, tick - 1)
        if outcome != 0:
            return
        let_go = Node(node, steer, ticks + tick - 1, lives)
        after = Snapshot.of(world)
        outcome = self.try_move(after, let_go.ticks, steer | {J})
        found = self.child(after, let_go, steer | {J}, let_go.ticks, MOVE_TICKS, outcome,
                           seen, layer)
        if found is not None:
            yield found

    def ran_off_an_edge(self) -> bool:
        """After a run: in the air without a jump, with coyote time left beyond the next
        tick (so a jump at the start of the next move would not be the latest one)."""
        player = self.world.player
        return (not player.on_ground and not player.rising_from_jump and player.vy >= 0
                and player.coyote_ticks_left > LAST_COYOTE_TICK)

    def jump_on_the_last_coyote_tick(self, snapshot: Snapshot, parent: Node | None,
                                     start: int, run: Actions) -> tuple[Node, int] | None:
        """The macro-action of the widest jumps: from ``snapshot``, hold ``run`` off the edge
        ahead, then press jump on the last tick coyote time allows and hold it one move.
        Returns the run's Node and the jump's outcome (as :meth:`try_move` gives it), or
        None if the run ended otherwise (it reached an Exit or lost a life: the run alone
        was tried already)."""
        snapshot.restore(self.world)
        player = self.world.player
        for tick in range(1, 2 * MOVE_TICKS + 1):
            events = self.world.step(run)
            self.timeline.write_down(start + tick)
            if any(event.kind in (EventKind.EXIT, EventKind.HURT) for event in events):
                return None
            if not player.on_ground and player.coyote_ticks_left == LAST_COYOTE_TICK:
                break  # the next tick is the last a jump still counts as from the ground
        else:
            return None
        # the jump's own move counts itself
        self.moves_tried += math.ceil(tick / MOVE_TICKS) * self.weight
        ran = Node(parent, run, start + tick, parent.lives_lost if parent is not None else 0)
        after_the_run = Snapshot.of(self.world)
        return ran, self.try_move(after_the_run, ran.ticks, run | {J})

    def best_first(self, max_moves: int) -> Generator[None, None, Node | None]:
        """Always carry on from the state closest to an Exit, counting time a little
        (weighted A*): quick on levels that need no waiting. Closest counts the place
        within the tile (:meth:`within_tile`) and the states kept in the tile before
        (:data:`CROWD_TILES` each).

        A state's moves are played one at a time (deferred evaluation): each waits in the
        queue with its state's priority, in the order of :data:`TRY_ORDER`, each
        :data:`TRY_LATER_TILES` behind the one before, and is played only when it comes
        out; the state it reaches goes in with its own priority. So a move that gets closer
        is carried on at once, and a state's next move is played only when nothing played
        since came closer. A run that went off an edge puts in its jump on the last coyote
        tick, behind the state's other moves. In the timed stage a state's timed inputs
        (:meth:`timed_children`) are all tried when the state comes out."""
        grid, tuning = self.level.grid, self.world.tuning
        tiles_per_tick = tuning.run_speed_px_s * tuning.tick_s / grid.tile_w
        seen: dict[StateKey, int] = {}
        crowd: dict[tuple[int, int], int] = {}  # the states kept in each tile
        # (priority, order, state, its Node, the move to try from it or None for the state
        # itself, the state's moves worth trying)
        queue: list[tuple[float, int, Snapshot, Node | None, Try | None, list[Try]]] = []
        order = 0

        def keep(score: float, child_state: Snapshot, child: Node) -> None:
            """Put a new state in the queue (the world is in its state)."""
            nonlocal order
            order += 1
            cell = self.cell()
            kept = crowd.get(cell, 0)
            crowd[cell] = kept + 1
            priority = (score + self.within_tile() + kept * CROWD_TILES
                        + child.ticks * tiles_per_tick / BEST_FIRST_WEIGHT)
            heapq.heappush(queue, (priority, order, child_state, child, None,
                                   self.choices_here(child, child.ticks)))

        self.start.restore(self.world)
        queue.append((0.0, 0, self.start, None, None, self.choices_here(None, 0)))
        while queue and self.moves_tried < max_moves:
            while self.paused():
                yield
            priority, _, snapshot, node, trying, choices = heapq.heappop(queue)
            ticks = node.ticks if node is not None else 0
            if trying is None:  # a state comes out: its moves go in, to be tried one by one
                if self.timed:
                    for timed in self.timed_children(snapshot, node, ticks, seen, 0):
                        if timed[0] == -math.inf:
                            return timed[2]
                        keep(*timed)
                ranked = sorted(choices, key=lambda c: (
                    TRY_ORDER.index(c.choice) if c.move_ticks == MOVE_TICKS else len(TRY_ORDER)))
                for rank, move in enumerate(ranked):
                    order += 1
                    heapq.heappush(queue, (priority + rank * TRY_LATER_TILES, order, snapshot,
                                           node, move, []))
                if self.out_of_time():
                    return None
                continue
            if trying.late:  # (it restores the state itself)
                found = self.late_jump(snapshot, node, ticks, trying.choice, seen, 0)
            else:
                if trying.wait is not None:
                    if trying.wait in self.waits:
                        continue  # a wait here already met this platform
                    self.waits[trying.wait] = 0
                snapshot.restore(self.world)
                outcome = self.try_move(snapshot, ticks, trying.choice, trying.move_ticks)
                if outcome == 0 and trying.choice in RUNS and self.ran_off_an_edge():
                    order += 1
                    heapq.heappush(queue, (priority + TRY_LATER_TILES * len(TRY_ORDER), order,
                                           snapshot, node,
                                           Try(trying.choice, MOVE_TICKS, late=True), []))
                found = self.child(snapshot, node, trying.choice, ticks, trying.move_ticks,
                                   outcome, seen, 0)
            if found is not None:
                if found[0] == -math.inf:
                    return found[2]
                keep(*found)
            if self.out_of_time():
                return None
        return None

    def beams(self) -> Generator[None, None, Node | None]:
        """Beam search that widens where it is stuck and narrows again once past: when the
        beam dies out, or gets no closer for a while, it goes back :data:`BACK_MOVES` layers
        and carries on from there twice as wide (going back twice as far each time it fails
        again at the same place); a beam with a state on the ground that is closer than any
        before narrows again (a jump in the air has not got there until it lands)."""
        self.beaming = True  # a narrow beam must not fill up with falls
        base = width = self.effort.width
        layers: list[list[tuple[Snapshot, Node | None]] | None] = [[(self.start, None)]]
        seen: dict[StateKey, int] = {}  # each key, with the layer it was first met at
        record = UNREACHABLE  # the closest any state on the ground has come to an Exit
        failures = 0  # beams that failed since the last record
        closest, since_closer = UNREACHABLE, 0
        started_at, dropped = 0, False
        while not self.out_of_time():
            while self.paused():
                yield
            depth = len(layers) - 1
            beam = layers[depth]
            assert beam is not None  # the newest layer is always kept
            children: list[tuple[float, int, Snapshot, Node]] = []
            cells: list[tuple[int, int]] = []
            standing = UNREACHABLE  # the best score of a child standing (or riding)
            for snapshot, node in beam:
                for score, child_state, child in self.children(
                        snapshot, node, node.ticks if node is not None else 0, seen,
                        depth + 1):
                    if score == -math.inf:
                        return child
                    children.append((score, len(children), child_state, child))
                    cells.append(self.cell())
                    if self.world.player.on_ground:
                        standing = min(standing, score)
            if self.out_of_time():
                return None
            if children and since_closer <= self.stall_moves:
                dropped = dropped or len(children) > width
                children.sort(key=lambda c: (c[0], c[1]))
                layers.append(self.diverse(children, cells, width))
                if len(layers) > HISTORY_LAYERS + 1:
                    layers[-HISTORY_LAYERS - 2] = None  # layer 0 (the spawn) is always kept
                best = children[0][0]
                if best < closest:
                    closest, since_closer = best, 0
                else:
                    since_closer += 1
                if standing < record:
                    record, failures, width = standing, 0, base
                continue
            if not children and started_at == 0 and not dropped:
                return None  # it kept every state it met, and all ended: wider cannot help
            failures += 1  # stuck: go back, and try again wider
            width = base * 2 ** failures
            back = max(0, depth - BACK_MOVES * 2 ** (failures - 1))
            started_at = next(layer for layer in range(back, depth + 1)
                              if layers[layer] is not None) if back else 0
            del layers[started_at + 1:]
            seen = {key: layer for key, layer in seen.items() if layer <= started_at}
            self.waits = {wait: layer for wait, layer in self.waits.items()
                          if layer <= started_at}
            closest, since_closer, dropped = UNREACHABLE, 0, False
        return None

    def within_tile(self) -> float:
        """How much nearer an Exit (negative) or further (positive) than their tile's steps
        the feet are, at most half a step each way along each axis: from the middle of the
        tile, the steps lean towards those of the neighbouring tile the feet are nearer
        (a step at most, however far that tile's own way is)."""
        grid, box = self.level.grid, self.world.player.box
        x, y = box.center[0] / grid.tile_w, (box.bottom - FEET_PX) / grid.tile_h
        col, row = math.floor(x), math.floor(y)
        here = self.steps.get((col, row))
        if here is None:
            return 0.0
        lean = 0.0
        for off, near in ((x - col - 0.5, (col + (1 if x - col > 0.5 else -1), row)),
                          (y - row - 0.5, (col, row + (1 if y - row > 0.5 else -1)))):
            there = self.steps.get(near)
            if there is not None:
                lean += abs(off) * max(-1, min(1, there - here))
        return lean

    def cell(self) -> tuple[int, int]:
        """The tile the middle of the player's feet is in."""
        grid, box = self.level.grid, self.world.player.box
        return (math.floor(box.center[0] / grid.tile_w),
                math.floor((box.bottom - FEET_PX) / grid.tile_h))

    def diverse(self, children: list[tuple[float, int, Snapshot, Node]],
                cells: list[tuple[int, int]], width: int) -> list[tuple[Snapshot, Node | None]]:
        """The best ``width`` children, at most :data:`PER_CELL` of them in any one tile
        while others are left: a beam full of states in one place is stuck together."""
        kept: list[tuple[Snapshot, Node | None]] = []
        per_cell: dict[tuple[int, int], int] = {}
        later: list[tuple[Snapshot, Node | None]] = []
        for _, order, snapshot, node in children:
            cell = cells[order]
            if per_cell.get(cell, 0) < PER_CELL:
                per_cell[cell] = per_cell.get(cell, 0) + 1
                kept.append((snapshot, node))
                if len(kept) == width:
                    return kept
            elif len(later) < width:
                later.append((snapshot, node))
        return kept + later[:width - len(kept)]

    def try_move(self, snapshot: Snapshot, start: int, choice: Actions,
                 move_ticks: int = MOVE_TICKS) -> int:
        """Hold ``choice`` for one move from ``snapshot`` (taken at tick ``start``, and
        restored already): +ticks if an Exit was reached on that tick, else -1 if a life was
        lost on the way (the world has put the player back), 0 if not. The lives lost on
        the way (each tick of a crush takes one) are left in :attr:`lost_in_move`.

        Enemies far from the player are left out while it steps (:mod:`.enemy_timeline`);
        if the player comes close to one after all, the move is made again with all of them.
        """
        # a wait counts the moves its ticks would take
        self.moves_tried += math.ceil(move_ticks / MOVE_TICKS) * self.weight
        away = self.timeline.away(start, move_ticks)
        if away:
            outcome = self.hold(choice, start, move_ticks, away)
            if outcome is not None:
                return outcome
            snapshot.restore(self.world)
        outcome = self.hold(choice, start, move_ticks, ())
        assert outcome is not None  # with no enemy left out, nothing is made again
        return outcome

    def hold(self, choice: Actions, start: int, move_ticks: int, away: Away) -> int | None:
        """Step the world ``move_ticks`` ticks holding ``choice``, with the enemies ``away``
        left out of play: the outcome of :meth:`try_move`, or None if the player came close
        to an enemy left out."""
        timeline = self.timeline
        if away:
            timeline.leave_out(away)
        self.lost_in_move = 0  # a crush can take a life on each tick of one move
        for tick in range(1, move_ticks + 1):
            events = self.world.step(choice)
            if away and not timeline.clear_of(away, start + tick):
                return None
            timeline.write_down(start + tick)
            for event in events:
                if event.kind is EventKind.EXIT:
                    if away:
                        timeline.put_back(away, start + tick)
                    return tick
                self.lost_in_move += event.kind is EventKind.HURT
        if away:
            timeline.put_back(away, start + move_ticks)
        return -1 if self.lost_in_move else 0


def _held_per_tick(node: Node | None) -> list[Actions]:
    """The input of every tick on the way to ``node``."""
    moves: list[Node] = []
    while node is not None:
        moves.append(node)
        node = node.parent
    held: list[Actions] = []
    for move in reversed(moves):
        held.extend([move.choice] * (move.ticks - len(held)))
    return held


def replay(level_path: Path, held: Sequence[Actions], level: Level | None = None,
           ) -> tuple[bool, list[Box]]:
    """Play ``held`` from the spawn as ``python -m game`` does; did it finish the level
    (lives may be lost on the way, as in play), and where was the player after each tick?"""
    campaign = Campaign(level_path, loader=lambda path: level or load_level(path))
    route: list[Box] = []
    for actions in held:
        campaign.tick(actions)
        if campaign.levels_completed or campaign.outcome is not Outcome.RUNNING:
            break
        route.append(campaign.world.player.box)
    return campaign.levels_completed > 0, route


def solve(level: Level, effort: Effort | None = None,
          steps: dict[tuple[int, int], int] | None = None) -> Solution:
    """Search ``level`` for a route from the spawn to an Exit (``steps``: the reach proof's
    :attr:`~game.checker.reachable.Reach.steps`, when worked out already; empty when it gave
    none, so the score is the open cells' :func:`distances_to_exit`)."""
    search = _Search(level, effort or Effort(), steps)
    found = search.run() if level.exits else None
    stages = [search] if search.timed_stage is None else [search, search.timed_stage]
    moves_tried = sum(stage.moves_tried for stage in stages)
    states = sum(stage.states for stage in stages)
    held = _held_per_tick(found)
    if found is not None:
        won, route = replay(level.path, held, level)
        if not won:  # the search and a replay disagree: the snapshot missed some state
            raise AssertionError(f"{level.path}: the route found does not replay")
        return Solution(level, True, held, route[-1], route, moves_tried,
                        budget=search.budget, states=states,
                        own_budget=search.effort.budget is None,
                        timed=search.found_timed)
    best = min((stage.best for stage in stages), key=lambda best: best[0])
    furthest_held = _held_per_tick(best[2])
    _, route = replay(level.path, furthest_held, level)
    timed_out = search.deadline is not None and time.monotonic() > search.deadline
    return Solution(level, False, furthest_held, best[1], route, moves_tried,
                    timed_out=timed_out, budget=search.budget, states=states,
                    own_budget=search.effort.budget is None)
