"""A walker that blocks the only way: a proof of impossibility that follows an enemy.

Where it sits: :func:`game.checker.verdict.prove_impossible` asks it last, when the reaches
of :mod:`game.checker.reachable` and :mod:`game.checker.jump_envelope` leave an enemy
unbounded (it comes within touching distance of where the player can be).

What it teaches: **a separation that holds at every tick proves as much as a wall.** A
walker on a floor it cannot leave (:func:`~game.checker.mechanic_bounds.patrol_span`) is
always somewhere on its run, whatever the player does. Where that run lies in a passage
too low to get over it, the player gets past it only by walking through it, and a touch
that is not a stomp costs a life unless the player is still protected after losing one.
The proof holds when each of these holds, each checked from the map's own numbers:

* **A low passage** (:func:`_passage`). Over the enemy's whole run, widened by a tick's
  farthest move to each side, every cell of one row is Solid from its top down to the
  same height (the ceiling), with less than the player's height between it and the
  enemy's head; under the gate (below) every cell at the enemy's feet is wholly Solid.
  A player whose feet are in the passage is then wholly between ceiling and floor, so
  its box overlaps the enemy's wherever it overlaps it across; and no player's feet are
  ever at or above the enemy's head beside it (they would be in the ceiling), so no touch
  is a stomp.
* **A gate** (the passage's cells over a range of columns). A tick moves the player
  sideways at most a tick of full run speed and one corner correction's slide, and the
  enemy at most its own step, far less than their two widths together: so the player is
  never left of the enemy on one tick and right of it on the next without touching it.
  The gate's columns are chosen so that feet entering them from one side are on that
  side of the enemy wherever it is, and leave them only to that side.
* **The only way.** With the gate closed, the open cells joined to the spawn
  (:func:`~game.checker.reachable.open_path`, with each Checkpoint once its columns are
  met) reach no Exit, and beside the gate (in its rows: a tick's moves, along x then
  along y, pass through every cell between, so the feet enter and leave it only there)
  every open cell on one side and none on the other. No Exit and no respawn place is in
  the gate, no Checkpoint the gate could count is left uncounted, and no respawn place
  is moved by a moving Platform.
* **Nothing else moves it or the player there.** No moving Platform's route comes near
  the passage (it could push the player, or crush the enemy); the enemy cannot fall or
  be pushed off its floor; bodies do not meet one another.
* **No respawn near enough** (:func:`_protected_reach`). After a lost life the player is
  protected for ``tuning.invulnerable_ticks`` ticks, and may walk through the enemy. In
  that many ticks from each respawn place (the spawn, and each Checkpoint counted on its
  side), running from standing as fast as the tuning lets it, with every corner
  correction a ceiling's corners could give and a ride to the far end of every moving
  Platform's route it could reach, the player's box cannot reach the far side of the
  enemy even where the enemy is nearest, nor its feet the far side of the gate.

Then at every tick the player is unprotected, its feet are in the region joined to the
spawn or in the gate on the spawn's side of the enemy: a lost life only sends it back to
a respawn place, and no Exit is ever touched. Where any condition fails the proof says
nothing, and the map stays not decided, naming the enemy.

Its work is counted, never timed: a look at the cells of each walker's passage, and for
each walker in a low passage one flood of the map's open cells, at most
:data:`MAX_FLOODS` of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from game.checker.jump_envelope import SLACK_PX, ceilings
from game.checker.mechanic_bounds import patrol_span, touch_px
from game.checker.reachable import Cell, feet_cell, open_path, starts, target_cells
from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.sim.platforms import route_region
from game.sim.player import run_change_px_s
from game.sim.tuning import Tuning
from game.sim.world import World

MAX_FLOODS = 16  # floods of the map's open cells (one a walker in a low passage) a proof takes


@dataclass(frozen=True)
class Barrier:
    """An enemy proven to block the only way: its tile, the ticks a player is protected
    after losing a life and the farthest it runs in them, for the verdict's line."""

    tile: Cell
    protected_ticks: int
    protected_px: float


def _full_solid(grid: TileGrid, col: int, row: int, top: float, bottom: float) -> bool:
    """Is cell (col, row) Solid across its whole width from ``top`` down to ``bottom``?"""
    if not (0 <= col < grid.cols and 0 <= row < grid.rows):
        return False
    left, right = col * grid.tile_w, (col + 1) * grid.tile_w
    return any(s.kind is TileKind.SOLID and s.box.left <= left and s.box.right >= right
               and s.box.top <= top and s.box.bottom == bottom
               for s in grid.shapes_at(col, row))


def _open(grid: TileGrid, col: int, row: int) -> bool:
    """Is cell (col, row) open to the cell fill (in the map and not wholly one Solid tile)?"""
    return 0 <= col < grid.cols and 0 <= row < grid.rows and not any(
        s.kind is TileKind.SOLID and s.box.w >= grid.tile_w and s.box.h >= grid.tile_h
        for s in grid.shapes_at(col, row))


def _passage(grid: TileGrid, cols: range, head: float, feet: float,
             player_h: float) -> tuple[int, float] | None:
    """The row of the passage's ceiling over ``cols`` and its underside (None unless every
    one of those cells is Solid from the row's top down to one height, above ``head`` by
    less than ``player_h``)."""
    col = cols.start
    for row in range(math.floor((head - SLACK_PX) / grid.tile_h), -1, -1):
        bottoms = [s.box.bottom for s in grid.shapes_at(col, row) if s.kind is TileKind.SOLID
                   and s.box.bottom <= head]
        if bottoms:
            ceiling = max(bottoms)
            break
    else:
        return None
    if not head - ceiling < player_h:
        return None
    top = row * grid.tile_h
    if not all(_full_solid(grid, c, row, top, ceiling) for c in cols):
        return None
    return row, ceiling


def blocking_enemy(world: World) -> Barrier | None:
    """The first enemy proven to block every way to an Exit (the conditions of this
    module), or None; after :data:`MAX_FLOODS` floods it stops and proves nothing more."""
    floods = 0
    for number in range(len(world.level.enemies)):
        gate = _gate(world, number)
        if gate is None:
            continue
        if floods == MAX_FLOODS:
            return None
        floods += 1
        barrier = _blocks(world, gate)
        if barrier is not None:
            return barrier
    return None


@dataclass(frozen=True)
class _Gate:
    """A walker in a low passage (what :func:`_gate` checks before any flood): where it can
    be, its width, and the gate's cells, columns and rows."""

    number: int
    span: Box
    width: float
    cells: frozenset[Cell]
    cols: range
    rows: range


def _gate(world: World, number: int) -> _Gate | None:
    """The gate of walker ``number``, when it is on a floor it cannot leave in a low
    passage with no Platform near, and no Exit in the gate."""
    span = patrol_span(world, number)
    if span is None:
        return None
    level, tuning, grid = world.level, world.tuning, world.level.grid
    tw, th = grid.tile_w, grid.tile_h
    pw, ph = world.spawn.w, world.spawn.h
    enemy = world.enemy_by_number[number].box
    ew = enemy.w
    low, high, head, feet = span.left, span.right, span.top, span.bottom
    if feet % th:
        return None
    floor_row = int(feet // th)
    step = tuning.run_speed_px_s * tuning.tick_s + SLACK_PX  # the farthest run in a tick
    tick_px = step + tuning.corner_correction_px  # and a corner correction's slide
    spec = level.enemies[number]
    speed = tuning.enemy_speed_px_s if spec.speed_px_s is None else spec.speed_px_s
    if not (tick_px + abs(speed) * tuning.tick_s < pw + ew and tick_px < tw):
        return None  # a tick could carry the player from one side of it (or a column) past
    first = math.floor((low + ew + pw / 2 - tick_px) / tw)
    last = max(first, math.floor((high - ew - pw / 2 + tick_px) / tw))
    covered = range(min(first, math.floor((low - tick_px) / tw)),
                    max(last, math.floor((high + tick_px) / tw)) + 1)
    found = _passage(grid, covered, head, feet, ph)
    if found is None:
        return None
    ceiling_row, _ = found
    gate_cols, gate_rows = range(first, last + 1), range(ceiling_row, floor_row)
    if not all(_full_solid(grid, col, floor_row, feet, feet + th) for col in gate_cols):
        return None
    gate = frozenset((col, row) for col in gate_cols for row in gate_rows)
    near = Box(covered.start * tw - tw - pw, (ceiling_row - 1) * th - ph,
               (len(covered) + 2) * tw + 2 * pw, (floor_row - ceiling_row + 2) * th + 2 * ph)
    grow = touch_px(world)
    if any(route_region(p).overlaps(Box(near.x - grow, near.y - grow, near.w + 2 * grow,
                                        near.h + 2 * grow)) for p in level.platforms):
        return None
    if target_cells(level, world.spawn) & gate:
        return None
    return _Gate(number, span, ew, gate, gate_cols, gate_rows)


def _blocks(world: World, found: _Gate) -> Barrier | None:
    """A :class:`Barrier` when no way to an Exit passes the gate (the rest of the
    conditions: the flood, the Checkpoints, the side, the protected runs)."""
    tuning, grid = world.tuning, world.level.grid
    tw, pw = grid.tile_w, world.spawn.w
    gate, gate_cols, gate_rows, ew = found.cells, found.cols, found.rows, found.width
    low, high = found.span.left, found.span.right
    first, last = gate_cols.start, gate_cols.stop - 1
    reach = open_path(world, closed=gate)
    if reach.touches_exit or reach.unbounded:
        return None
    counted = reach.counted
    if any(start.moved is not None or start.unbounded is not None for start in counted):
        return None
    uncounted = [start for start in starts(world) if start not in counted]
    if any(set(start.columns) & set(gate_cols) for start in uncounted):
        return None
    # The feet leave and enter the gate only across its sides, in its rows (each tick's
    # moves, along x then along y, pass through the cells between): every open cell beside
    # it on the spawn's side is joined to the spawn, and none on the other side is.
    beside = [[(col, row) for row in gate_rows if _open(grid, col, row)]
              for col in (first - 1, last + 1)]
    joined = [[cell in reach.cells for cell in cells] for cells in beside]
    left_side, right_side = any(joined[0]), any(joined[1])
    if left_side == right_side or not all(joined[0] if left_side else joined[1]):
        return None
    run = protected_run_px(tuning)
    shortcuts = _shortcuts(world, pw)
    for start in counted:
        box = start.box
        if feet_cell(grid, box.x + box.w / 2, box.bottom) in gate:
            return None
        if left_side:
            furthest = _furthest(box.x, run, shortcuts.rightwards)
            if not (furthest < low + ew and furthest + pw / 2 < (last + 1) * tw):
                return None
        else:
            furthest = -_furthest(-box.x, run, shortcuts.leftwards)
            if not (furthest + pw > high - ew and furthest + pw / 2 >= first * tw):
                return None
    enemy = world.enemy_by_number[found.number].box
    tile = (math.floor(enemy.x / tw), math.floor(enemy.y / grid.tile_h))
    return Barrier(tile, tuning.invulnerable_ticks, run)


def protected_run_px(tuning: Tuning) -> float:
    """The farthest a player runs (with :data:`SLACK_PX` a tick to spare) in the ticks it is
    protected after losing a life: it comes back standing still, and each tick its speed
    changes by at most the fastest of the tuning's rates (speeding up or stopping, on the
    ground or in the air), up to the run speed."""
    rate = max(run_change_px_s(tuning, ground, speeding) for ground in (True, False)
               for speeding in (True, False))
    top = tuning.run_speed_px_s
    return sum(min(top, tick * rate) * tuning.tick_s + SLACK_PX
               for tick in range(1, tuning.invulnerable_ticks + 1))


@dataclass(frozen=True)
class _Shortcuts:
    """Where a box's left edge may be put beyond its own run, each as (the least it must
    have reached, where it is put): rightwards, and leftwards with x read as -x."""

    rightwards: list[tuple[float, float]]
    leftwards: list[tuple[float, float]]


def _shortcuts(world: World, width: float) -> _Shortcuts:
    """A corner correction's slide leaves the box flush with an end of a run of ceiling
    bottoms (:func:`~game.checker.jump_envelope.ceilings`) it was within
    ``corner_correction_px`` of; a moving Platform carries or pushes it anywhere along the
    box its route spans (touching it there, within touching distance)."""
    corner, grow = world.tuning.corner_correction_px + SLACK_PX, touch_px(world)
    right, left = [], []
    for run in ceilings(world.level.grid):
        right.append((run.right - corner, run.right))
        left.append((-(run.left + corner - width), -(run.left - width)))
    for platform in world.level.platforms:
        region = route_region(platform)
        right.append((region.left - grow - width, region.right + grow))
        left.append((-(region.right + grow), -(region.left - grow - width)))
    return _Shortcuts(sorted(right), sorted(left))


def _furthest(x: float, run: float, shortcuts: list[tuple[float, float]]) -> float:
    """The furthest right a box's left edge at ``x`` can be while it runs ``run`` px, where
    each shortcut it reaches may put it further, from where it runs on (``shortcuts``
    sorted by the least each needs reached)."""
    furthest = x + run
    for needs, put in shortcuts:
        if needs > furthest:
            break
        furthest = max(furthest, put + run)
    return furthest

