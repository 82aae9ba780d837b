"""Every number the README promises about feel and collision, tested just inside and just
outside its edge: coyote time and the jump buffer (6 ticks, not 7), the ceiling corner slide
(4 px, not 4.5), strict overlap in the tile grid's query as in ``Box``, one-way tops, the drop
through, the stomp and its bounce, variable jump height, flush stops, the run's speed-up and
stop times on the ground and in the air, and terminal velocity.

A test of the middle of a rule (5 ticks of coyote time) passes whether the rule stops at 6 or
at 60; these pin where each rule stops, so a change of the number fails a test.
"""

from __future__ import annotations

from collections.abc import Sequence

import pytest

# Everything the tests use from the game, in one place.
from game.collision.aabb import Box
from game.collision.axis_sweep import Side, ground_under, move_x, move_y, slide_past_ceiling_corner
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.platforms import FEW_PLATFORMS, Platform, PlatformIndex, PlatformSpec, Route
from game.sim.player import DROP_THROUGH_TICKS
from game.sim.query_log import LoggedSource, QueryLog
from game.sim.solids import LevelSolids
from game.sim.tuning import Tuning
from game.sim.world import Event, EventKind, World
from tests.maps import (
    DROP,
    LEDGE,
    ONE_WAY_SHELF,
    jump_pressed_before_landing,
    jump_under_the_ceiling_from,
    level_from_ascii,
    settled,
)
from tests.test_movement import glide

T = 16
TUNING = Tuning()
RIGHT: Actions = frozenset({Action.RIGHT})
JUMP: Actions = frozenset({Action.JUMP})
RIGHT_JUMP: Actions = frozenset({Action.RIGHT, Action.JUMP})
DOWN_JUMP: Actions = frozenset({Action.DOWN, Action.JUMP})
DOWN: Actions = frozenset({Action.DOWN})
SOLID, ONE_WAY = TileKind.SOLID, TileKind.ONE_WAY


def jumped(events: Sequence[Event]) -> bool:
    return any(e.kind is EventKind.JUMP for e in events)


# --- Coyote time: a jump pressed up to 6 ticks (0.1 s) after leaving a ledge ---------------


def jump_pressed_after_leaving_the_ledge(ticks: int) -> bool:
    """Run off the ledge; press jump on the ``ticks``-th tick after the first tick that ended
    with the feet in the air: did the jump happen?"""
    world = settled(LEDGE)
    while world.player.on_ground:
        world.step(RIGHT)
    for _ in range(ticks - 1):
        world.step(RIGHT)
    assert not world.player.on_ground
    return jumped(world.step(RIGHT_JUMP))


def test_the_promised_coyote_time_is_6_ticks() -> None:
    assert TUNING.coyote_ticks == 6


def test_a_jump_pressed_6_ticks_after_running_off_a_ledge_still_happens() -> None:
    assert jump_pressed_after_leaving_the_ledge(6)


def test_a_jump_pressed_7_ticks_after_running_off_a_ledge_does_not_happen() -> None:
    assert not jump_pressed_after_leaving_the_ledge(7)


def test_a_jump_pressed_1_tick_after_running_off_a_ledge_happens() -> None:
    assert jump_pressed_after_leaving_the_ledge(1)


# --- Jump buffer: a jump pressed up to 6 ticks before landing happens on landing ------------

def test_the_promised_jump_buffer_is_6_ticks() -> None:
    assert TUNING.jump_buffer_ticks == 6


def test_a_jump_pressed_6_ticks_before_landing_happens_on_the_first_tick_on_the_ground() -> None:
    happened, tick = jump_pressed_before_landing(6)
    assert happened
    assert tick == jump_pressed_before_landing(0)[1]   # the same tick as a press on landing


def test_a_jump_pressed_7_ticks_before_landing_is_forgotten() -> None:
    assert jump_pressed_before_landing(7) == (False, -1)


def test_a_jump_held_down_through_a_landing_does_not_jump_again() -> None:
    """Only a press starts a jump: holding the button from before the buffer does nothing."""
    world = World(level_from_ascii(DROP), TUNING)
    events = [e for _ in range(80) for e in world.step(JUMP)]
    assert not jumped(events)
    assert world.player.on_ground


# --- Ceiling corner correction: a head clipping a corner by up to 4 px slides past it ------


CEILING_LEFT, CEILING_RIGHT, CEILING_BOTTOM = 5 * T, 9 * T, 3 * T  # of maps.CEILING


def test_a_jump_clipping_a_ceilings_left_corner_by_4_px_slides_past_it() -> None:
    world, highest = jump_under_the_ceiling_from(CEILING_LEFT - 12 + 4)
    assert world.player.box.right == CEILING_LEFT
    assert highest < CEILING_BOTTOM
    assert world.max_penetration_px == 0.0


def test_a_jump_clipping_a_ceilings_left_corner_by_4_and_a_half_px_bumps_its_head() -> None:
    world, highest = jump_under_the_ceiling_from(CEILING_LEFT - 12 + 4.5)
    assert highest == CEILING_BOTTOM
    assert world.player.box.right == CEILING_LEFT + 4.5


def test_a_jump_clipping_a_ceilings_right_corner_by_4_px_slides_past_it() -> None:
    world, highest = jump_under_the_ceiling_from(CEILING_RIGHT - 4)
    assert world.player.box.left == CEILING_RIGHT
    assert highest < CEILING_BOTTOM


def test_a_jump_clipping_a_ceilings_right_corner_by_4_and_a_half_px_bumps_its_head() -> None:
    world, highest = jump_under_the_ceiling_from(CEILING_RIGHT - 4.5)
    assert highest == CEILING_BOTTOM
    assert world.player.box.left == CEILING_RIGHT - 4.5


def corner_grid() -> TileGrid:
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(3, 2, TileShape(Box(48, 32, 16, 16), SOLID, 3, 2))
    return grid


@pytest.mark.parametrize("clip_px", [0.5, 4.0])
def test_the_corner_slide_takes_a_clip_up_to_its_limit_on_the_left(clip_px: float) -> None:
    slid = slide_past_ceiling_corner(corner_grid(), Box(36 + clip_px, 50, 12, 14), -10.0, 4.0)
    assert slid is not None
    side, rise = slid
    assert side.box.x == 36 and side.hit is None
    assert side.start.x == 36 + clip_px                # the sideways move starts at the body
    assert rise.box == Box(36, 40.0, 12, 14) and rise.hit is None


@pytest.mark.parametrize("clip_px", [4.5, 6.0])
def test_the_corner_slide_refuses_a_clip_past_its_limit_on_the_left(clip_px: float) -> None:
    assert slide_past_ceiling_corner(corner_grid(), Box(36 + clip_px, 50, 12, 14), -10.0,
                                     4.0) is None


@pytest.mark.parametrize("clip_px", [0.5, 4.0])
def test_the_corner_slide_takes_a_clip_up_to_its_limit_on_the_right(clip_px: float) -> None:
    slid = slide_past_ceiling_corner(corner_grid(), Box(64 - clip_px, 50, 12, 14), -10.0, 4.0)
    assert slid is not None
    assert slid[0].box.x == 64 and slid[1].box.y == 40.0


def test_the_corner_slide_refuses_a_clip_of_4_and_a_half_px_on_the_right() -> None:
    assert slide_past_ceiling_corner(corner_grid(), Box(59.5, 50, 12, 14), -10.0, 4.0) is None


def test_the_corner_slide_prefers_the_smaller_shift() -> None:
    """A body 8 px wide under a 10 px ceiling block, 3 px from its right end: slide right."""
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(3, 2, TileShape(Box(48, 32, 10, 16), SOLID, 3, 2))
    slid = slide_past_ceiling_corner(grid, Box(55, 50, 8, 14), -10.0, 9.0)
    assert slid is not None and slid[0].box.x == 58


def test_the_corner_slide_prefers_the_left_on_a_tie() -> None:
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(3, 2, TileShape(Box(48, 32, 8, 16), SOLID, 3, 2))
    slid = slide_past_ceiling_corner(grid, Box(50, 50, 4, 14), -10.0, 6.0)
    assert slid is not None and slid[0].box.x == 44


def test_the_corner_slide_does_not_slide_into_a_wall() -> None:
    grid = corner_grid()
    grid.put(2, 3, TileShape(Box(32, 48, 16, 16), SOLID, 2, 3))   # a wall where it would go
    assert slide_past_ceiling_corner(grid, Box(49, 50, 12, 14), -10.0, 4.0) is None


def test_the_corner_slide_does_not_slide_under_another_ceiling() -> None:
    grid = corner_grid()
    grid.put(2, 2, TileShape(Box(32, 32, 16, 16), SOLID, 2, 2))   # the ceiling goes on left
    slid = slide_past_ceiling_corner(grid, Box(62, 50, 12, 14), -10.0, 4.0)
    assert slid is not None and slid[0].box.x == 64                # so only right is free
    assert slide_past_ceiling_corner(grid, Box(38, 50, 12, 14), -10.0, 4.0) is None


def test_the_corner_slide_is_only_for_a_head_bump() -> None:
    grid = corner_grid()
    assert slide_past_ceiling_corner(grid, Box(40, 20, 12, 14), -10.0, 4.0) is None  # free
    assert slide_past_ceiling_corner(grid, Box(40, 10, 12, 14), 10.0, 4.0) is None   # falling
    assert slide_past_ceiling_corner(grid, Box(40, 50, 12, 14), -10.0, 0.0) is None  # no slide


def test_the_corner_slide_of_a_body_already_clear_of_the_corner_is_not_needed() -> None:
    grid = corner_grid()
    assert slide_past_ceiling_corner(grid, Box(36, 50, 12, 14), -10.0, 4.0) is None


def test_the_corner_slide_needs_the_rise_to_get_higher_than_the_bump() -> None:
    """Past the corner a second ceiling just as low: sliding would gain nothing."""
    grid = corner_grid()
    grid.put(2, 2, TileShape(Box(32, 40, 16, 8), SOLID, 2, 2))
    assert slide_past_ceiling_corner(grid, Box(39, 50, 12, 14), -10.0, 4.0) is None


# --- Strict overlap, in the tile grid's query as in Box ------------------------------------

# One sub-tile shape in the middle of cell (5, 5), as Tiled's collision editor makes them:
# its faces lie inside the cell, so the cells a region covers do not hide a touch.
SHAPE = Box(5 * T + 4, 5 * T + 4, 8, 8)      # x 84..92, y 84..92


def one_shape_grid(kind: TileKind = SOLID, box: Box = SHAPE) -> TileGrid:
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(5, 5, TileShape(box, kind, 5, 5))
    return grid


TOUCHING = {  # a region sharing only one face with SHAPE
    "left face": Box(80, 84, 4, 8),
    "right face": Box(92, 84, 4, 8),
    "top face": Box(84, 80, 8, 4),
    "bottom face": Box(84, 92, 8, 4),
}
OVERLAPPING = {  # the same region reaching half a pixel into SHAPE
    "left face": Box(80, 84, 4.5, 8),
    "right face": Box(91.5, 84, 4.5, 8),
    "top face": Box(84, 80, 8, 4.5),
    "bottom face": Box(84, 91.5, 8, 4.5),
}


@pytest.mark.parametrize("face", list(TOUCHING))
def test_the_grid_query_leaves_out_a_shape_that_a_region_only_touches(face: str) -> None:
    region = TOUCHING[face]
    assert not region.overlaps(SHAPE)
    assert one_shape_grid().shapes_in(region) == []


@pytest.mark.parametrize("face", list(OVERLAPPING))
def test_the_grid_query_finds_a_shape_that_a_region_overlaps_by_half_a_pixel(face: str) -> None:
    region = OVERLAPPING[face]
    assert region.overlaps(SHAPE)
    assert [s.box for s in one_shape_grid().shapes_in(region)] == [SHAPE]


@pytest.mark.parametrize("face", list(TOUCHING))
def test_box_overlap_is_strict_on_every_face(face: str) -> None:
    assert not TOUCHING[face].overlaps(SHAPE) and not SHAPE.overlaps(TOUCHING[face])
    assert OVERLAPPING[face].overlaps(SHAPE) and SHAPE.overlaps(OVERLAPPING[face])
    assert TOUCHING[face].touches(SHAPE) and not OVERLAPPING[face].touches(SHAPE)


def test_the_grid_query_leaves_out_a_shape_touched_only_at_a_corner() -> None:
    assert one_shape_grid().shapes_in(Box(80, 80, 4, 4)) == []
    assert len(one_shape_grid().shapes_in(Box(80, 80, 4.5, 4.5))) == 1


def test_an_empty_region_finds_nothing_even_inside_a_shape() -> None:
    grid = one_shape_grid()
    assert grid.shapes_in(Box(86, 86, 0, 4)) == []
    assert grid.shapes_in(Box(86, 86, 4, 0)) == []
    assert grid.shapes_in(Box(86, 86, -2, 4)) == []
    assert grid.entries_in(86, 86, 90, float("nan")) == []


def half_tiles(cells: list[tuple[int, int]], inset: Box) -> TileGrid:
    """Shapes smaller than their tile: ``inset`` is the shape relative to its cell."""
    grid = TileGrid(200, 200, T, T)
    for col, row in cells:
        box = Box(col * T + inset.x, row * T + inset.y, inset.w, inset.h)
        grid.put(col, row, TileShape(box, SOLID, col, row))
    return grid


def test_walking_across_100_seams_of_half_height_floor_tiles_never_stops() -> None:
    grid = half_tiles([(c, 10) for c in range(150)], Box(0, 8, T, 8))   # the lower half
    box = Box(0.0, 10 * T + 8 - 14, 12, 14)                           # feet on their top
    box = glide(move_x, grid, box, 1.7, 1000)
    assert box.x == pytest.approx(1700)


def test_sliding_under_100_seams_of_half_height_ceiling_tiles_never_stops() -> None:
    grid = half_tiles([(c, 10) for c in range(150)], Box(0, 0, T, 8))   # the upper half
    box = Box(0.0, 10 * T + 8, 12, 14)                                # head on their bottom
    box = glide(move_x, grid, box, 16.0, 100)
    assert box.x == 1600


def test_falling_past_100_seams_of_half_width_tiles_on_the_left_never_stops() -> None:
    grid = half_tiles([(10, r) for r in range(150)], Box(0, 0, 8, T))   # the left half
    box = Box(10 * T + 8, 0.0, 12, 14)                                # left side on them
    box = glide(move_y, grid, box, 16.0, 100)
    assert box.y == 1600


def test_falling_past_100_seams_of_half_width_tiles_on_the_right_never_stops() -> None:
    grid = half_tiles([(10, r) for r in range(150)], Box(8, 0, 8, T))   # the right half
    box = Box(10 * T + 8 - 12, 0.0, 12, 14)                           # right side on them
    box = glide(move_y, grid, box, 16.0, 100)
    assert box.y == 1600


def test_standing_on_a_half_height_tile_the_player_runs_over_its_seams() -> None:
    """The whole tick, not only the sweep: a floor of half-height tiles under a running player."""
    level = level_from_ascii(["P" + " " * 39, " " * 40, " " * 40])
    grid = level.grid
    for col in range(40):
        grid.put(col, 2, TileShape(Box(col * T, 2 * T + 8, T, 8), SOLID, col, 2))
    world = World(level, TUNING)
    for _ in range(30):
        world.step(NOTHING)
    assert world.player.on_ground
    for _ in range(120):
        world.step(RIGHT)
        assert world.player.vx == TUNING.run_speed_px_s or world.player.vx > 0
    assert world.player.box.x > 150


def platform_at(number: int, box: Box) -> Platform:
    """A platform standing still at ``box`` (a route of one point), numbered ``number``."""
    spec = PlatformSpec(Route(((box.x, box.y),)), box.w, box.h, 0.0)
    return Platform(spec, number)


# Platforms parked in the top-left cell, far from every query below: with them a level has
# more than FEW_PLATFORMS, so its index walks the cells a query covers instead of testing
# each route's block. Every rule below holds either way.
PARKED = [platform_at(100 + k, Box(2, 2, 4, 4)) for k in range(FEW_PLATFORMS)]
HOW_MANY = pytest.mark.parametrize("parked", [0, FEW_PLATFORMS], ids=["few", "many"])


def solids_with(*platforms: Platform, parked: int = 0,
                tiles: TileGrid | None = None) -> LevelSolids:
    """The tiles (an empty 10x10 map unless given) and the platforms, asked as one."""
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T) if tiles is None else tiles
    index = PlatformIndex(grid, [*platforms, *PARKED[:parked]])
    assert (len(index.routes) > FEW_PLATFORMS) is (parked > 0)
    return LevelSolids(grid, index)


@HOW_MANY
@pytest.mark.parametrize("face", list(TOUCHING))
def test_the_platforms_query_leaves_out_a_platform_that_a_region_only_touches(
        face: str, parked: int) -> None:
    solids = solids_with(platform_at(0, SHAPE), parked=parked)
    assert solids.shapes_in(TOUCHING[face]) == []
    x, y, w, h = TOUCHING[face]
    assert solids.platforms.entries_in(x, y, x + w, y + h) == []


@HOW_MANY
@pytest.mark.parametrize("face", list(OVERLAPPING))
def test_the_platforms_query_finds_a_platform_a_region_overlaps_by_half_a_pixel(
        face: str, parked: int) -> None:
    solids = solids_with(platform_at(0, SHAPE), parked=parked)
    assert [s.box for s in solids.shapes_in(OVERLAPPING[face])] == [SHAPE]


@HOW_MANY
def test_a_platform_with_no_area_is_never_found(parked: int) -> None:
    for box in (Box(86, 84, 0, 8), Box(84, 86, 8, 0)):
        solids = solids_with(platform_at(0, box), parked=parked)
        assert solids.shapes_in(Box(80, 80, 16, 16)) == []
        assert solids.platforms.entries_in(80, 80, 96, 96) == []


@HOW_MANY
def test_the_level_query_finds_platforms_after_the_tiles_in_number_order(parked: int) -> None:
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(4, 5, TileShape(Box(64, 80, 16, 16), SOLID, 4, 5))
    platforms = [platform_at(0, Box(84, 84, 4, 4)), platform_at(1, Box(88, 88, 4, 4)),
                 platform_at(2, Box(70, 70, 4, 4))]
    if parked:  # the cells' walk meets number 2 first (cell (4, 4)); it must sort them
        platforms.reverse()
    solids = solids_with(*platforms, parked=parked, tiles=grid)
    found = [(s.col, s.row) for s in solids.shapes_in(Box(60, 60, 40, 40))]
    assert found == [(4, 5), (-1, 0), (-1, 1), (-1, 2)]


@HOW_MANY
def test_the_query_skips_the_platform_it_is_asked_to_leave_out(parked: int) -> None:
    platform = platform_at(0, SHAPE)
    solids = solids_with(platform, parked=parked)
    assert solids.leaving_out(platform).entries_in(80, 80, 96, 96) == []
    assert solids.platforms.entries_in(80, 80, 96, 96, platform) == []
    assert len(solids.entries_in(80, 80, 96, 96)) == 1


@HOW_MANY
def test_a_platform_filed_in_several_cells_is_found_and_tested_once(parked: int) -> None:
    solids = solids_with(platform_at(0, Box(90, 84, 12, 4)), parked=parked)
    assert len(solids.entries_in(80, 80, 112, 96)) == 1
    log = QueryLog()
    LoggedSource(solids, log, "x sweep").entries_in(80, 80, 112, 96)
    assert log.stats.shapes_tested == 1
    assert [q.extra for q in log.queries] == [(solids.platforms.platforms[0].shape,)]


@HOW_MANY
def test_platforms_off_the_map_are_tested_by_every_query(parked: int) -> None:
    near = platform_at(0, Box(84, 84, 4, 4))
    far = platform_at(7, Box(-40, 4, 8, 8))
    solids = solids_with(near, far, parked=parked)
    assert solids.platforms.outside == [far]
    assert [s.row for s in solids.shapes_in(Box(-44, 8, 200, 100))] == [0, 7]
    assert solids.leaving_out(far).entries_in(-44, 0, 1, 16) == []  # nothing else out there
    assert solids.entries_in(-44, 0, 1, 16) == [far.entry]


# --- Flush stops --------------------------------------------------------------------------

@pytest.mark.parametrize(("gap", "moved", "hit"), [(0.0, 0.0, True), (0.5, 0.5, True),
                                                   (3.0, 3.0, False), (4.0, 3.0, False)])
def test_a_move_stops_flush_at_a_face_within_reach_and_not_before(
        gap: float, moved: float, hit: bool) -> None:
    """A wall ``gap`` px ahead and a step of 3 px: the body stops flush on it when it lies
    within the step; a face exactly where the step ends is reached, not hit."""
    grid = one_shape_grid(box=Box(84, 80, 8, 16))
    for sign, start, face in ((1, 84 - gap - 12, 84), (-1, 92 + gap, 92)):
        move = move_x(grid, Box(start, 82, 12, 10), sign * 3.0)
        assert move.box == Box(start + sign * moved, 82, 12, 10)
        assert (move.hit is not None) is hit
        if move.hit is not None:
            assert move.hit.face == face and move.hit.shape is not None
            assert move.hit.side is (Side.RIGHT if sign > 0 else Side.LEFT)


@pytest.mark.parametrize(("gap", "hit"), [(0.0, True), (0.5, True), (3.0, False)])
def test_a_vertical_move_stops_flush_at_a_face_within_reach(gap: float, hit: bool) -> None:
    grid = one_shape_grid(box=Box(80, 84, 16, 8))
    down = move_y(grid, Box(82, 84 - gap - 10, 12, 10), 3.0)
    up = move_y(grid, Box(82, 92 + gap, 12, 10), -3.0)
    assert down.box.bottom == 84 - gap + min(gap, 3.0)
    assert up.box.top == 92 + gap - min(gap, 3.0)
    assert (down.hit is not None) is hit and (up.hit is not None) is hit
    if hit:
        assert down.hit is not None and down.hit.side is Side.BOTTOM and down.hit.face == 84
        assert up.hit is not None and up.hit.side is Side.TOP and up.hit.face == 92


def test_a_wall_behind_the_body_does_not_stop_it() -> None:
    grid = one_shape_grid(box=Box(84, 80, 8, 16))
    assert move_x(grid, Box(92, 82, 12, 10), 3.0).hit is None      # wall touching its back
    assert move_x(grid, Box(72, 82, 12, 10), -3.0).hit is None
    assert move_y(grid, Box(82, 92, 12, 10), 3.0).hit is None      # ceiling on its head
    assert move_y(grid, Box(82, 74, 12, 10), -3.0).hit is None     # floor under its feet


def test_the_map_edge_is_a_wall_exactly_at_its_edge() -> None:
    grid = TileGrid(cols=10, rows=4, tile_w=T, tile_h=T)
    to_right = move_x(grid, Box(147.5, 0, 12, 14), 1.0)
    assert to_right.box.right == 160 and to_right.hit is not None
    assert to_right.hit.side is Side.RIGHT and to_right.hit.shape is None
    assert move_x(grid, Box(147, 0, 12, 14), 1.0).hit is None       # ends exactly on it
    to_left = move_x(grid, Box(0.5, 0, 12, 14), -1.0)
    assert to_left.box.x == 0 and to_left.hit is not None and to_left.hit.side is Side.LEFT
    assert move_x(grid, Box(1, 0, 12, 14), -1.0).hit is None
    assert move_x(grid, Box(0, 0, 12, 14), -1.0).box.x == 0         # already on the edge


# --- One-way tops: they stop only a body whose feet start at or above them ---------------

def test_a_one_way_top_stops_feet_that_start_exactly_on_it() -> None:
    grid = one_shape_grid(ONE_WAY, Box(80, 84, 16, 8))
    move = move_y(grid, Box(82, 70, 12, 14), 5.0)
    assert move.box.bottom == 84 and move.hit is not None and move.hit.side is Side.BOTTOM


def test_a_one_way_top_lets_feet_half_a_pixel_below_it_fall_through() -> None:
    grid = one_shape_grid(ONE_WAY, Box(80, 84, 16, 8))
    move = move_y(grid, Box(82, 70.5, 12, 14), 5.0)
    assert move.hit is None and move.box.y == 75.5


def test_a_one_way_top_is_ignored_when_dropping_through() -> None:
    grid = one_shape_grid(ONE_WAY, Box(80, 84, 16, 8))
    assert move_y(grid, Box(82, 70, 12, 14), 5.0, through_one_way=True).hit is None
    assert move_y(grid, Box(82, 60, 12, 14), 30.0, through_one_way=True).box.y == 90
    assert ground_under(grid, Box(82, 70, 12, 14), through_one_way=True) is None
    assert ground_under(grid, Box(82, 70, 12, 14)) is not None


def test_a_solid_top_stops_a_body_dropping_through_one_way_tiles() -> None:
    grid = one_shape_grid(SOLID, Box(80, 84, 16, 8))
    assert move_y(grid, Box(82, 60, 12, 14), 30.0, through_one_way=True).box.bottom == 84
    assert ground_under(grid, Box(82, 70, 12, 14), through_one_way=True) is not None


def test_a_one_way_tile_never_stops_a_rise_or_a_run() -> None:
    grid = one_shape_grid(ONE_WAY, Box(80, 84, 16, 8))
    assert move_y(grid, Box(82, 94, 12, 14), -30.0).hit is None
    assert move_x(grid, Box(60, 82, 12, 14), 40.0).hit is None
    assert move_x(grid, Box(100, 82, 12, 14), -40.0).hit is None


def test_a_hazard_stops_nothing_and_is_no_ground() -> None:
    grid = one_shape_grid(TileKind.HAZARD, Box(80, 84, 16, 8))
    assert move_y(grid, Box(82, 60, 12, 14), 30.0).hit is None
    assert move_x(grid, Box(60, 82, 12, 14), 40.0).hit is None
    assert move_y(grid, Box(82, 94, 12, 14), -30.0).hit is None
    assert ground_under(grid, Box(82, 70, 12, 14)) is None


def test_the_ground_probe_finds_a_sub_tile_top_exactly_at_the_feet_and_nothing_else() -> None:
    grid = one_shape_grid(SOLID, Box(84, 84, 8, 8))
    assert ground_under(grid, Box(82, 70, 12, 14)) is not None
    assert ground_under(grid, Box(82, 69.5, 12, 14)) is None       # half a pixel above
    assert ground_under(grid, Box(82, 70.5, 12, 14)) is None       # sunk half a pixel
    assert ground_under(grid, Box(72, 70, 12, 14)) is None         # corner to corner
    assert ground_under(grid, Box(72.5, 70, 12, 14)) is not None   # half a pixel over it


def test_the_ground_probe_looks_past_a_shape_it_cannot_stand_on() -> None:
    grid = TileGrid(cols=10, rows=10, tile_w=T, tile_h=T)
    grid.put(5, 5, TileShape(Box(80, 84, 8, 8), TileKind.HAZARD, 5, 5))
    grid.put(5, 5, TileShape(Box(88, 84, 8, 8), SOLID, 5, 5))
    found = ground_under(grid, Box(82, 70, 12, 14))
    assert found is not None and found.kind is SOLID


# --- Drop through: down + jump on a one-way tile ignores one-way tiles for 8 ticks ---------

def test_down_and_jump_on_a_one_way_tile_drops_for_8_ticks_without_jumping() -> None:
    world = settled(ONE_WAY_SHELF)
    events = world.step(DOWN_JUMP)
    assert not jumped(events)
    ticks_dropping = 1
    while world.player.dropping_through:
        assert not jumped(world.step(DOWN_JUMP))
        ticks_dropping += 1
    assert ticks_dropping == DROP_THROUGH_TICKS + 1 == 9   # the press, then 8 more decides
    assert world.player.vy >= 0


def test_down_and_jump_on_solid_ground_is_an_ordinary_jump() -> None:
    world = settled(["     ", "  P  ", "#####"])
    assert jumped(world.step(DOWN_JUMP))
    assert not world.player.dropping_through and world.player.vy < 0


def test_holding_down_and_jump_on_a_one_way_tile_drops_only_on_the_press() -> None:
    world = settled(ONE_WAY_SHELF)
    world.step(DOWN)
    assert not world.player.dropping_through
    world.step(JUMP)          # jump pressed without down: a jump, not a drop
    assert not world.player.dropping_through and world.player.vy < 0


# --- Variable jump height: letting go while rising keeps half the upward speed -------------

def test_letting_go_of_jump_while_rising_halves_the_upward_speed() -> None:
    world = settled(["     "] * 8 + ["  P  ", "#####"])
    world.step(JUMP)
    world.step(JUMP)
    rising = world.player.vy
    assert rising == -TUNING.jump_speed_px_s + 2 * TUNING.gravity_px_s2 * TUNING.tick_s
    world.step(NOTHING)
    assert world.player.vy == rising * 0.5 + TUNING.gravity_px_s2 / 60   # half is kept


def test_holding_jump_keeps_the_full_upward_speed() -> None:
    world = settled(["     "] * 8 + ["  P  ", "#####"])
    world.step(JUMP)
    for tick in range(2, 10):
        world.step(JUMP)
        assert world.player.vy == pytest.approx(-TUNING.jump_speed_px_s
                                                + tick * TUNING.gravity_px_s2 / 60)


def test_letting_go_of_jump_after_the_apex_changes_nothing() -> None:
    world = settled(["     "] * 8 + ["  P  ", "#####"])
    world.step(JUMP)
    while world.player.vy < 0:
        world.step(JUMP)
    falling = world.player.vy
    world.step(NOTHING)
    assert world.player.vy == falling + TUNING.gravity_px_s2 / 60


def test_a_jump_is_as_high_as_its_speed_allows_when_held() -> None:
    """Held to the apex, the rise is the sum of the per-tick steps, to the pixel."""
    world = settled(["     "] * 8 + ["  P  ", "#####"])
    floor_y = world.player.box.y
    highest = floor_y
    for _ in range(60):
        world.step(JUMP)
        highest = min(highest, world.player.box.y)
    vy, rise = -TUNING.jump_speed_px_s, 0.0
    while vy + TUNING.gravity_px_s2 / 60 < 0:
        vy += TUNING.gravity_px_s2 / 60
        rise -= vy / 60
    assert floor_y - highest == pytest.approx(rise)


# --- Stomp: feet at or above the enemy's head before the tick; then a 200 px/s bounce ------

def enemy_and_player(feet_below_head_px: float) -> World:
    """A still enemy on the floor, and the player above it with its feet
    ``feet_below_head_px`` below the enemy's head (negative: above it), falling 1.25 px a
    tick."""
    level = level_from_ascii(["          ", "          ", "P   E     ", "##########"])
    world = World(level, Tuning(enemy_speed_px_s=0.0))
    for _ in range(20):
        world.step(NOTHING)
    enemy = next(iter(world.enemies))
    world.player.teleport(Box(enemy.box.x, enemy.box.top - 14 + feet_below_head_px, 12, 14))
    world.player.vy = 60.0
    return world


def test_feet_exactly_on_the_enemys_head_stomp_it_and_bounce_at_200_px_s() -> None:
    world = enemy_and_player(0.0)
    enemy = next(iter(world.enemies))
    kinds = [e.kind for e in world.step(NOTHING)]
    assert EventKind.STOMP in kinds and EventKind.HURT not in kinds
    assert not enemy.alive()
    assert world.player.vy == -TUNING.stomp_bounce_px_s == -200.0


def test_feet_half_a_pixel_below_the_enemys_head_hurt_the_player() -> None:
    world = enemy_and_player(0.5)
    kinds = [e.kind for e in world.step(NOTHING)]
    assert EventKind.HURT in kinds and EventKind.STOMP not in kinds


# --- Run and air speed-up and stop times, and terminal velocity: the promised numbers ------
# Full run speed is 90 px/s. On the ground a run takes 0.05 s (3 ticks) to reach it and as
# long to stop; in the air 0.10 s (6 ticks) to reach it and 0.20 s (12 ticks) to stop. A fall
# gains 15 px/s a tick (900 px/s²) and never goes faster than 360 px/s, reached on tick 24.

def run_speeds(air: bool, speed_up_ticks: int, stop_ticks: int) -> tuple[list[float], list[float]]:
    """Hold right for ``speed_up_ticks`` from standing (on the floor, or falling from rest
    in open air), then let go for ``stop_ticks``: the run speed after each tick of each."""
    world = (World(level_from_ascii(["  P  "] + ["     "] * 60)) if air
             else settled(["     ", "  P  ", "#####"]))
    speeding_up = []
    for _ in range(speed_up_ticks):
        world.step(RIGHT)
        speeding_up.append(world.player.vx)
    stopping = []
    for _ in range(stop_ticks):
        world.step(NOTHING)
        stopping.append(world.player.vx)
    assert world.player.on_ground is not air
    return speeding_up, stopping


def test_on_the_ground_a_run_reaches_90_px_s_on_its_3rd_tick_and_stops_on_the_3rd() -> None:
    speeding_up, stopping = run_speeds(air=False, speed_up_ticks=4, stop_ticks=4)
    assert speeding_up == pytest.approx([30.0, 60.0, 90.0, 90.0], abs=1e-9)
    assert stopping == pytest.approx([60.0, 30.0, 0.0, 0.0], abs=1e-9)


def test_in_the_air_a_run_reaches_90_px_s_on_its_6th_tick_and_stops_on_the_12th() -> None:
    speeding_up, stopping = run_speeds(air=True, speed_up_ticks=7, stop_ticks=13)
    assert speeding_up == pytest.approx([15.0, 30.0, 45.0, 60.0, 75.0, 90.0, 90.0], abs=1e-9)
    assert stopping == pytest.approx([90.0 - 7.5 * k for k in range(1, 13)] + [0.0], abs=1e-9)


def test_a_fall_reaches_360_px_s_on_its_24th_tick_and_never_goes_faster() -> None:
    world = World(level_from_ascii(["P"] + [" "] * 80))
    speeds = []
    for _ in range(40):
        world.step(NOTHING)
        speeds.append(world.player.vy)
    assert speeds[22:25] == pytest.approx([345.0, 360.0, 360.0], abs=1e-9)
    assert max(speeds) == 360.0
