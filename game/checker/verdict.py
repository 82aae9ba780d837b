"""Can this map be won? Three honest answers: solved, impossible, or not decided.

Where it sits: between the checker's command line (:mod:`game.checker.cli`) and the
two tools that answer, :mod:`game.checker.reachable` (which can prove a map impossible) and
:mod:`game.checker.solver` (which can prove it solved, by finding a route that replays).

What it teaches: keep what was *proven* apart from what was merely *not found*.

* **Solved**: a route reaches an Exit when the game replays it (the solver's, or the
  designer's own recorded win given with ``--proof``).
* **Impossible**: no open path of cells joins the spawn and an Exit, or the Exit lies
  outside everything the player's jumps could touch: by the cell fill, or by the
  pixel-exact reach of :mod:`game.checker.jump_envelope` (a gap or a ledge one pixel past
  the measured limits; on a map with enemies or moving Platforms, only while none of them
  can ever come within touching distance of where the player can be). All are
  over-approximations, so they never call a winnable map impossible, and an Exit any of
  them leaves out is out of reach. A reach is a proof only when it bounds every mechanic
  on the way (:attr:`game.checker.reachable.Reach.unbounded`,
  :attr:`game.checker.jump_envelope.Exact.unbounded`): where one is left unbounded the map
  is not decided, and the line names the mechanic (for the pixel-exact reach, the enemy
  or the platform by the tile it starts at). Where one tile layer's Solid tiles
  close the way (taking them away opens it, to the same proof; for the pixel-exact reach,
  an Exit then comes in reach: a layer that only walls an enemy in is not named), the line
  names the layer and points at one of its tiles. Last, an enemy the reaches leave
  unbounded may still be proven to block the only way (:mod:`game.checker.enemy_barrier`:
  a walker in a passage too low to get over it, with no respawn place near enough to
  pass it while protected after a lost life); the line names it by its tile.
* **Not decided**: the search spent its budget (or its seconds) without a route, and
  nothing proved the map impossible. That is said as such, with the bound, the work done,
  the furthest place reached and how to search further; it never reads as solved.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from enum import Enum
from pathlib import Path

from game.checker.enemy_barrier import Barrier, blocking_enemy
from game.checker.jump_envelope import Exact, exact_reach, nearest_reached
from game.checker.reachable import Cell, Reach, open_path, reachable
from game.checker.solver import Effort, Solution, solve
from game.checker.wall_layers import closed_cells_by_layer
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.sim.campaign import Campaign
from game.sim.inputs import InputScript
from game.sim.level import Level
from game.sim.world import World

PROOF_GRACE_TICKS = 60 * 60  # a recorded win may end with keys held: play on this long


class Kind(Enum):
    SOLVED = "solved"
    IMPOSSIBLE = "impossible"
    UNDECIDED = "not decided"


@dataclass(frozen=True)
class Verdict:
    """One map's answer: its kind, the tile it points at, what was found and what to do."""

    kind: Kind
    tile: Cell | None
    finding: str
    advice: str
    solution: Solution | None = None
    reach: Reach | None = None
    layer: str | None = None  # the tile layer whose Solid tiles close the way, if one does


def _cell_of(level: Level, x: float, y: float) -> Cell:
    return math.floor(x / level.grid.tile_w), math.floor(y / level.grid.tile_h)


def prove_impossible(level: Level) -> tuple[Verdict | None, Reach | None]:
    """An IMPOSSIBLE verdict if the cells or the reach show no route can exist (else None),
    and the player's reach where it was worked out (the search is guided by its steps)."""
    impossible, reach, _ = _prove(level)
    return impossible, reach


def _prove(level: Level) -> tuple[Verdict | None, Reach | None, list[str]]:
    """:func:`prove_impossible`, and the mechanics the pixel-exact reach does not bound
    (said when nothing proves the map impossible)."""
    world = World(level)
    if not level.exits:
        return None, None, []
    sealed = open_path(world)
    if not sealed.touches_exit and not sealed.unbounded:  # (a moved respawn may be anywhere)
        culprit = _closing_layer(world, lambda w: not open_path(w).touches_exit)
        blame = (f"; without the Solid tiles of layer '{culprit[0]}' there would be a way"
                 if culprit is not None else "")
        fix = (f"clear the Solid tiles of layer '{culprit[0]}' in the way (or give them another "
               "class)" if culprit is not None else
               "open a way through the Solid tiles between here and the Exit")
        return Verdict(Kind.IMPOSSIBLE, sealed.nearest_to_exit(),
                       "impossible: no open path joins the spawn and an Exit; Solid tiles "
                       f"close every way{blame}; this is the nearest open place to an Exit",
                       fix, reach=sealed), None, []
    guide = reachable(world, narrow=True)  # cheaper, and the tighter guide for a search
    reach = guide
    if guide is not None and not guide.touches_exit:  # (else the full fill does too)
        reach = reachable(world)
        if reach is not None and not reach.touches_exit and not reach.unbounded:
            culprit = _closing_layer(world, _fill_proves)
            return _out_of_reach(reach.nearest_to_exit(), culprit, reach), reach, []
    exact = exact_reach(world)
    if exact.proves:
        # a layer is to blame only where a way to an Exit opens without it (not where an
        # enemy or a platform it walls off would come near the player)
        culprit = _closing_layer(world, lambda w: not exact_reach(w).touches_exit)
        found = _out_of_reach(nearest_reached(exact, level), culprit, reach, exact)
        return found, reach, []
    barrier = blocking_enemy(world) if level.enemies else None
    if barrier is not None:
        return _blocked(barrier, reach), reach, []
    return None, reach, exact.unbounded


def _fill_proves(world: World) -> bool:
    reach = reachable(world)
    return reach is not None and not reach.touches_exit and not reach.unbounded


def _out_of_reach(tile: Cell | None, culprit: tuple[str, Cell] | None, reach: Reach | None,
                  exact: Exact | None = None) -> Verdict:
    """The IMPOSSIBLE verdict of a reach that leaves every Exit out (``exact``: the
    pixel-exact one, whose bounds the line gives)."""
    bounds = (f" (it crosses gaps of at most {exact.gap_px} px and lands on ledges at most "
              f"{exact.ledge_px} px high)" if exact is not None else "")
    if culprit is not None:
        name, tile = culprit
        return Verdict(Kind.IMPOSSIBLE, tile,
                       "impossible: the Exit lies outside everything the player's jumps can "
                       f"touch{bounds}; without the Solid tiles of layer '{name}' there would "
                       "be a way; this is one of them",
                       f"clear the Solid tiles of layer '{name}' in the way (or give them "
                       "another class)", reach=reach, layer=name)
    return Verdict(Kind.IMPOSSIBLE, tile,
                   "impossible: the Exit lies outside everything the player's jumps can "
                   f"touch{bounds}; this is the nearest place they reach",
                   "lower the ledges or narrow the gaps on the way (see the player's "
                   "reach in the summary), or move the Exit", reach=reach)


def _blocked(barrier: Barrier, reach: Reach | None) -> Verdict:
    """The IMPOSSIBLE verdict of an enemy that blocks the only way
    (:mod:`game.checker.enemy_barrier`)."""
    col, row = barrier.tile
    return Verdict(Kind.IMPOSSIBLE, barrier.tile,
                   f"impossible: the enemy at tile ({col},{row}) blocks the only way to the "
                   "Exit, in a passage too low to jump over it or stomp it, and no place "
                   "the player comes back to after losing a life is near enough to pass it "
                   f"while protected (for {barrier.protected_ticks} ticks, at most "
                   f"{math.ceil(barrier.protected_px)} px at a run); this is the enemy",
                   "raise the passage's ceiling over the enemy, open another way round it, "
                   "or put a Checkpoint near enough to it", reach=reach)


def _closing_layer(world: World, proves: Callable[[World], bool],
                   ) -> tuple[str, Cell] | None:
    """The tile layer whose Solid tiles alone close the way, if taking them away makes
    ``proves`` fail (of several, the one with the fewest such tiles: a stray wall, not the
    whole ground), and the one of its tiles nearest the spawn."""
    layers = closed_cells_by_layer(world.level.path) if world.level.path.is_file() else []
    openers: list[tuple[int, int, str, frozenset[Cell]]] = []
    for number, (name, cells) in enumerate(layers):
        others: set[Cell] = set()
        for other, (_, other_cells) in enumerate(layers):
            if other != number:
                others |= other_cells
        own = frozenset(cells - others)
        if own and not proves(_without(world, own)):
            openers.append((len(own), number, name, own))
    if not openers:
        return None
    _, _, name, own = min(openers, key=lambda found: found[:2])
    grid, spawn = world.level.grid, world.spawn
    here = (spawn.center[0] / grid.tile_w, spawn.center[1] / grid.tile_h)
    return name, min(sorted(own), key=lambda cell: math.dist(cell, here))


def _without(world: World, cells: frozenset[Cell]) -> World:
    """``world``'s level played again without the Solid tiles in ``cells``."""
    grid = world.level.grid
    opened = TileGrid(grid.cols, grid.rows, grid.tile_w, grid.tile_h)
    for shape in grid.shapes():
        if shape.kind is not TileKind.SOLID or (shape.col, shape.row) not in cells:
            opened.put(shape.col, shape.row, shape)
    return World(replace(world.level, grid=opened), world.tuning)


def judge(level: Level, effort: Effort, command: str = "python -m game.levels") -> Verdict:
    """Prove ``level`` impossible, else search it: solved, or honestly not decided."""
    impossible, reach, exact_unbounded = _prove(level)
    if impossible is not None:
        return impossible
    # No reach (physics with no bound, or a fill past its budget of steps), or one that
    # missed the Exit but met a mechanic it does not bound: the search is guided by open
    # cells alone, and does not try the fill again.
    unbounded = reach.unbounded if reach is not None and not reach.touches_exit else []
    guide = reach.steps if reach is not None and not unbounded else {}
    solution = solve(level, effort, guide)
    if solution.found:
        return Verdict(Kind.SOLVED, None, f"solved: a route reaches an Exit at tick "
                       f"{solution.exit_tick}", "", solution)
    col, row = solution.furthest_tile()
    if solution.timed_out and effort.seconds is not None:
        bound = f"its {effort.seconds:g} s"
    elif solution.out_of_budget:
        whose = "this map's budget" if solution.own_budget else "its budget"
        bound = f"{whose} of {solution.budget:,} moves"
    else:
        bound = "every move its beams kept"
    more = max(solution.budget * 4, solution.moves_tried * 4)
    why = (f"the proof of impossibility does not cover {' nor '.join(unbounded)}"
           if unbounded else "nothing proves the map impossible")
    if exact_unbounded:
        why += (f" (the pixel-exact reach, which proves gaps and ledges one pixel past the "
                f"limits, does not cover {' nor '.join(exact_unbounded)})")
    return Verdict(
        Kind.UNDECIDED, (col, row),
        f"not decided: the search found no route within {bound} ({solution.moves_tried:,} "
        f"moves tried, {solution.states:,} states kept) and {why}; this is the furthest "
        "place reached",
        f"search further with --budget {more}, see how far it got with {command} solve "
        f"MAP --picture route.png, or prove it winnable with --proof SCRIPT "
        "(a win recorded with python -m game --record)",
        solution)


def replay_proof(level: Level, script: InputScript) -> tuple[bool, int]:
    """Play a recorded script on ``level`` as the game does; did it finish the level, and at
    which tick?"""
    campaign = Campaign(level.path, loader=lambda _path: level)
    last = script.events[-1].tick if script.events else 0
    for tick in range(last + PROOF_GRACE_TICKS):
        campaign.tick(script.held_at(tick))
        if campaign.levels_completed:
            return True, tick + 1
        if campaign.outcome.value != "running":
            break
    return False, campaign.ticks


def judge_proof(level: Level, script_path: Path, script: InputScript) -> Verdict:
    """SOLVED when the recorded script wins the level; else a finding about the script.
    ``script``: the script read from ``script_path`` (through the one bounded open,
    :func:`game.checker.checking.read_proof`)."""
    won, ticks = replay_proof(level, script)
    if won:
        return Verdict(Kind.SOLVED, None, f"solved: the recorded win {script_path.name} "
                       f"reaches an Exit at tick {ticks}", "")
    x, y = World(level).player.box.center
    return Verdict(Kind.UNDECIDED, _cell_of(level, x, y),
                   f"not decided: the recorded script {script_path.name} does not finish the "
                   f"level (played for {ticks} ticks)",
                   "record the win again on this version of the map with python -m game "
                   "--level MAP --record SCRIPT, or leave out --proof to search")
