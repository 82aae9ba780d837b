"""Where every enemy and every moving platform can ever be: what the pixel-exact reach must
keep clear of to stand on a map that has them.

Where it sits: :func:`game.checker.jump_envelope.exact_reach` asks it on a map with enemies or
moving Platforms, once the reach of its walls alone leaves every Exit out.

What it teaches: **a mechanic the player never touches changes nothing.** An enemy changes
the player's tick only by a touch (a stomp bounces, any other touch hurts), and a platform
only by a touch too (the player stands on it and rides, is pushed, carried or crushed, or
bumps into it); both go their own way whatever the player does. So if no place the
player's body can be in the game of walls alone ever comes within touching distance of
where a mechanic can be, the game with it plays exactly as the game without it, and the
proof of the walls alone stands. Each bound here is an over-approximation:

* **A platform** (:func:`platform_bounds`) is always somewhere on its route: its box lies in
  the route's box grown by its size (:func:`~game.sim.platforms.route_region`).
* **An enemy** (:func:`enemy_bounds`) meets only the walls and the platforms (they push and
  carry it). A walker standing on a floor it cannot leave (:func:`patrol_span`: an unbroken
  run of tops at its feet, with no wall, no other top and no platform's route in the band
  its body and its one-pixel look-ahead sweep, and a step shorter than its width) turns
  back at each end, so it is somewhere on that run, at most two steps past an end (its
  first step is taken before it looks ahead; :mod:`game.checker.enemy_barrier` proves
  with this bound that such a walker in a low passage blocks the way). Any other enemy
  can be anywhere in the cell fill of its own body
  (:func:`~game.checker.reachable.enemy_cells`: its own speed and hop, every ledge walked
  off rather than turned back at, every fall, every ride and push of a platform), each
  cell its feet can be in grown to the box its body covers there (below the last row,
  until it is wholly below the map and out of play). A stomp only takes it out of play,
  which leaves it nowhere. An enemy whose fill cannot be worked out (physics with no
  bound, or past the fill's budget of steps) is not bounded, and the
  reach then proves nothing.
* **Touching distance**: every bound is grown on each side by a corner correction's slide
  (``corner_correction_px``) and :data:`TOUCH_PX` more, past all the tick looks at beyond
  the body's box: the slide sideways, and the one-pixel probe under the feet (by which
  the player comes to stand on a platform).
* **Respawns** (:func:`respawn_moved_by`): the game works a counted Checkpoint's respawn
  place out with the platforms where they are then
  (:func:`~game.collision.free_place.nearest_free_place`). Asked of the walls alone, that
  search looks at some regions; when no platform's route comes into any of them, every one
  of its answers, and so its place, is the same wherever the platforms are. Otherwise the
  place may depend on a platform, and the reach proves nothing.

Its work is counted, never timed: the enemies' fills share one budget of steps
(:data:`~game.checker.reachable.MAX_FILL_STEPS`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from game.checker.reachable import FillTooBig, FillWork, enemy_cells
from game.collision.aabb import Box
from game.collision.free_place import nearest_free_place
from game.collision.shapes import Entry, ShapeSource, TileKind
from game.collision.tile_grid import TileGrid
from game.sim.enemy import LEDGE_PROBE_PX
from game.sim.platforms import route_region
from game.sim.world import World

TOUCH_PX = 2.0  # px added beyond the corner slide: the 1 px ground probe, and rounding
FEET_SLACK_PX = 0.5  # as the cell fill reads a feet height into a row (reachable.SLACK_PX)


@dataclass(frozen=True)
class Bound:
    """Every place one mechanic can be, grown by touching distance, and its name as the
    verdict's line says it when the player's reach comes into it."""

    name: str
    boxes: tuple[Box, ...]


def touch_px(world: World) -> float:
    """How far past a mechanic's box the player's box counts as touching it."""
    return world.tuning.corner_correction_px + TOUCH_PX


def _grown(box: Box, by: float) -> Box:
    return Box(box.x - by, box.y - by, box.w + 2 * by, box.h + 2 * by)


def _tile_of(world: World, box: Box) -> tuple[int, int]:
    grid = world.level.grid
    return math.floor(box.x / grid.tile_w), math.floor(box.y / grid.tile_h)


def platform_bounds(world: World) -> list[Bound]:
    """Each moving platform's route region, grown by touching distance."""
    found = []
    for spec in world.level.platforms:
        region = route_region(spec)
        col, row = _tile_of(world, Box(*spec.path.points[0], spec.width_px, spec.height_px))
        found.append(Bound(f"the moving Platform starting at tile ({col},{row}) (the "
                           "player's jumps come within its route: it pushes and carries)",
                           (_grown(region, touch_px(world)),)))
    return found


def enemy_bounds(world: World, work: FillWork) -> tuple[list[Bound], list[str]]:
    """Each enemy's bound (its cell fill, each row's run of cells one box), and the enemies
    with none (what the reach then does not cover)."""
    found: list[Bound] = []
    unbounded: list[str] = []
    grid, margin = world.level.grid, touch_px(world)
    for number, spec in enumerate(world.level.enemies):
        col, row = _tile_of(world, spec.box)
        name = f"the enemy starting at tile ({col},{row})"
        said = (f"{name} (the player's jumps come within where it can go: a stomp bounces "
                "the player)")
        span = patrol_span(world, number)
        if span is not None:
            found.append(Bound(said, (_grown(span, margin),)))
            continue
        try:
            cells = enemy_cells(world, number, work)
        except FillTooBig:
            cells = None
        if cells is None:
            unbounded.append(f"{name} (no bound was found on where it can go)")
            continue
        w, h = spec.box.w, spec.box.h
        boxes = []
        for left, right, cell_row in _runs(cells):
            # the feet's middle anywhere in the run, their height anywhere in the row (from
            # the last row, on down until the whole body is below the map and out of play)
            top = cell_row * grid.tile_h + FEET_SLACK_PX - h
            tall = grid.tile_h + h + (h if cell_row >= grid.rows - 1 else 0)
            box = Box(left * grid.tile_w - w / 2, top, (right - left) * grid.tile_w + w, tall)
            boxes.append(_grown(box, margin))
        found.append(Bound(said, tuple(boxes)))
    return found, unbounded


def patrol_span(world: World, number: int) -> Box | None:
    """Every place walker ``number`` can be, when it stands on a floor it cannot leave: a
    run of tops at its feet's height, unbroken, with nothing else (no wall, no other top,
    no platform's route) in the band its body and its look-ahead sweep along it. None
    when it is not so (a hopper, a walker in the air, or one whose first step, taken
    before it looks ahead, could leave the floor)."""
    spec, tuning, grid = world.level.enemies[number], world.tuning, world.level.grid
    speed = tuning.enemy_speed_px_s if spec.speed_px_s is None else spec.speed_px_s
    x, y, w, h = world.enemy_by_number[number].box
    step, feet = speed * tuning.tick_s, y + h
    if spec.kind != "walker" or not 0 <= step < w:  # (a negative speed looks back)
        return None
    if (feet - h) + h != feet:  # landed flush, its feet would not be read as on the top
        return None
    spans = sorted((s.box.left, s.box.right) for s in grid.shapes_in(Box(0, feet, grid.width_px, 1))
                   if s.kind is not TileKind.HAZARD and s.box.top == feet)
    runs: list[tuple[float, float]] = []
    for left, right in spans:
        if runs and left <= runs[-1][1]:
            runs[-1] = (runs[-1][0], max(runs[-1][1], right))
        else:
            runs.append((left, right))
    under = [(left, right) for left, right in runs if left < x + w and x < right]
    if len(under) != 1:
        return None
    (left, right), = under
    if not (x - step + w > left and x + step < right):  # the first step keeps it on
        return None
    low, high = min(x, left) - 2 * step, max(x + w, right) + 2 * step
    band = Box(low - LEDGE_PROBE_PX, feet - h - LEDGE_PROBE_PX,
               high - low + 2 * LEDGE_PROBE_PX, h + 2 * LEDGE_PROBE_PX)
    for shape in grid.shapes_in(band):
        box = shape.box
        if shape.kind is not TileKind.HAZARD and not (
                box.top == feet and left <= box.left and box.right <= right):
            return None
    near = _grown(band, touch_px(world))
    if any(route_region(platform).overlaps(near) for platform in world.level.platforms):
        return None
    return Box(low, feet - h, high - low, h)


def _runs(cells: set[tuple[int, int]]) -> list[tuple[int, int, int]]:
    """The cells as runs along each row: (first column, one past the last, row)."""
    runs: list[tuple[int, int, int]] = []
    for col, row in sorted(cells, key=lambda cell: (cell[1], cell[0])):
        if runs and runs[-1][2] == row and runs[-1][1] == col:
            runs[-1] = (runs[-1][0], col + 1, row)
        else:
            runs.append((col, col + 1, row))
    return runs


class _Watched:
    """The walls, with every region asked of them written down."""

    def __init__(self, grid: TileGrid) -> None:
        self.grid = grid
        self.asked: list[Box] = []

    @property
    def width_px(self) -> int:
        return self.grid.width_px

    @property
    def height_px(self) -> int:
        return self.grid.height_px

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        self.asked.append(Box(left, top, right - left, bottom - top))
        return self.grid.entries_in(left, top, right, bottom)


def respawn_moved_by(world: World, flag: Box) -> str | None:
    """The platform that may move the respawn place of the Checkpoint ``flag`` (the game
    looks for it with the platforms where they are when the flag counts), or None when the
    place is the same wherever they are."""
    level = world.level
    if not level.platforms:
        return None
    w, h = level.spawn.w, level.spawn.h
    watched = _Watched(level.grid)
    solids: ShapeSource = watched
    nearest_free_place(solids, Box(flag.x + (flag.w - w) / 2, flag.bottom - h, w, h))
    margin = touch_px(world)
    for bound in platform_bounds(world):
        (region,) = bound.boxes
        if any(_grown(asked, margin).overlaps(region) for asked in watched.asked):
            col, row = _tile_of(world, flag)
            return (f"a respawn moved by a moving Platform (the Checkpoint at tile ({col},"
                    f"{row}) may be counted while a Platform is where the game looks for "
                    "the place the player comes back to)")
    return None
