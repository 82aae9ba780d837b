"""The smaller rules of the collision path and of the player's feel, one test each.

The edges of the promised numbers are in ``test_edges.py``; these pin the rest of what the
sweeps, the tile grid, the boxes, the tunables and the player do, so that mutation testing
(README, "Mutation testing") finds no rule that a change could break unnoticed.
"""

from __future__ import annotations

import itertools
import math
import random

import pygame
import pytest

# Everything the tests use from the game, in one place.
from game.collision.aabb import RECT_MAX, RECT_MIN, Box, rects_overlap
from game.collision.axis_sweep import (
    SKY_LIMIT_PX,
    Hit,
    Move,
    Side,
    move_body,
    move_x,
    move_y,
    slide_past_ceiling_corner,
)
from game.collision.free_place import nearest_free_place, penetration_depth, touching
from game.collision.shapes import Entry, TileKind, TileShape
from game.collision.tile_grid import CountedGrid, TileGrid
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.platforms import Platform, PlatformIndex, PlatformSpec, Route
from game.sim.player import Player, approach, run_change_px_s
from game.sim.query_log import LoggedSource, Query, QueryLog
from game.sim.solids import LevelSolids, Lookups
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.maps import level_from_ascii

T = 16
SOLID, ONE_WAY, HAZARD = TileKind.SOLID, TileKind.ONE_WAY, TileKind.HAZARD
RIGHT: Actions = frozenset({Action.RIGHT})
LEFT: Actions = frozenset({Action.LEFT})
JUMP: Actions = frozenset({Action.JUMP})
TUNING = Tuning()


def grid_of(*shapes: tuple[int, int, Box, TileKind], cols: int = 10, rows: int = 10,
            ) -> TileGrid:
    grid = TileGrid(cols, rows, T, T)
    for col, row, box, kind in shapes:
        grid.put(col, row, TileShape(box, kind, col, row))
    return grid


def floor_grid() -> TileGrid:
    return grid_of(*((c, 5, Box(c * T, 5 * T, T, T), SOLID) for c in range(10)))


# --- Box ----------------------------------------------------------------------------------

def test_normalizing_keeps_a_box_of_positive_size_under_one_pixel() -> None:
    assert Box(3, 4, 0.5, 0.5).normalized() == Box(3, 4, 0.5, 0.5)
    assert Box(3, 4, -0.5, -0.5).normalized() == Box(2.5, 3.5, 0.5, 0.5)


def test_boxes_under_a_pixel_wide_still_touch_and_empty_boxes_never_do() -> None:
    thin = Box(0, 0, 0.5, 0.5)
    assert thin.touches(Box(0.5, 0, 4, 4)) and Box(0.5, 0, 4, 4).touches(thin)
    for empty in (Box(0, 0, 0, 4), Box(0, 0, 4, 0)):
        assert not empty.touches(Box(4, 0, 4, 4)) and not Box(4, 0, 4, 4).touches(empty)


def test_a_box_has_the_four_numbers_of_its_rect_and_rects_overlap_by_pygames_rule() -> None:
    assert Box.from_rect(pygame.Rect(3, 4, -5, 6)) == Box(3, 4, -5, 6)
    assert rects_overlap(Box(10, 10, -10, -10), Box(2, 2, 4, 4))
    assert not rects_overlap(Box(10, 10, -10, -10), Box(10, 2, 4, 4))


@pytest.mark.parametrize("field", range(4))
def test_a_box_with_any_field_not_finite_says_so_and_refuses_to_become_a_rect(
        field: int) -> None:
    assert Box(1, 2, 3, 4).is_finite()
    for bad in (math.nan, math.inf, -math.inf):
        box = Box(*(bad if i == field else 1.0 for i in range(4)))
        assert not box.is_finite()
        with pytest.raises(ValueError, match="non-finite box"):
            box.to_rect()


@pytest.mark.parametrize("empty", [Box(5, 2, 0, 6), Box(2, 5, 6, 0)])
def test_a_box_of_no_width_or_height_overlaps_nothing_even_inside_another(empty: Box) -> None:
    around = Box(0, 0, 10, 10)
    assert not empty.overlaps(around) and not around.overlaps(empty)


def test_a_box_of_no_width_touches_nothing_even_flush_against_it() -> None:
    line, tile = Box(4, 0, 0, 4), Box(0, 0, 4, 4)
    assert not line.touches(tile) and not tile.touches(line)


def test_boxes_apart_or_touching_have_no_penetration() -> None:
    assert Box(0, 0, 10, 10).penetration(Box(20, 20, 5, 5)) == 0.0
    assert Box(0, 0, 10, 10).penetration(Box(10, 0, 5, 5)) == 0.0
    assert Box(0, 0, 10, 10).penetration(Box(9.5, 0, 5, 5)) == 0.5


@pytest.mark.parametrize("box", [Box(RECT_MIN, RECT_MIN, 0, 0), Box(RECT_MAX, RECT_MAX, 0, 0),
                                 Box(0, 0, RECT_MAX, RECT_MAX)])
def test_a_box_whose_edges_are_at_the_limits_of_a_rect_still_becomes_one(box: Box) -> None:
    assert tuple(box.to_rect()) == tuple(int(v) for v in box)


@pytest.mark.parametrize("box", [Box(RECT_MIN - 1, 0, 1, 1), Box(0, RECT_MIN - 1, 1, 1),
                                 Box(RECT_MAX - 1, 0, 2, 1), Box(0, RECT_MAX - 1, 1, 2),
                                 Box(RECT_MIN, 0, -1, 1), Box(0, RECT_MIN, 1, -1)])
def test_a_box_with_an_edge_one_past_the_limits_of_a_rect_is_refused(box: Box) -> None:
    with pytest.raises(ValueError, match="outside"):
        box.to_rect()


# --- The swept moves ----------------------------------------------------------------------

@pytest.mark.parametrize("step", [math.inf, -math.inf, math.nan])
def test_a_step_that_is_not_a_finite_number_is_refused_with_its_value(step: float) -> None:
    grid = floor_grid()
    for move in (move_x, move_y):
        with pytest.raises(ValueError, match=f"finite number of pixels, not {step}"):
            move(grid, Box(0, 0, 12, 14), step)


def test_a_move_of_nothing_stays_put_with_no_hit_and_sweeps_only_the_box() -> None:
    grid, box = floor_grid(), Box(20, 66, 12, 14)
    for move in (move_x(grid, box, 0.0), move_y(grid, box, 0.0)):
        assert move.box == box and move.start == box and move.hit is None
        assert move.swept == box and move.path == box


@pytest.mark.parametrize("step", [10.0, -10.0])
def test_a_move_sweeps_the_start_and_the_box_it_asked_for(step: float) -> None:
    grid = grid_of(cols=20, rows=20)
    box = Box(100, 100, 12, 14)
    x_move, y_move = move_x(grid, box, step), move_y(grid, box, step)
    assert (x_move.dx, x_move.dy, y_move.dx, y_move.dy) == (step, 0.0, 0.0, step)
    assert x_move.swept == box.union(box.moved(dx=step))
    assert y_move.swept == box.union(box.moved(dy=step))


def test_a_stopped_move_sweeps_what_it_asked_for_and_travels_only_to_the_wall() -> None:
    grid = grid_of((5, 6, Box(80, 96, 16, 16), SOLID), cols=20, rows=20)
    move = move_x(grid, Box(60, 100, 12, 10), 40.0)
    assert move.box.right == 80
    assert move.swept == Box(60, 100, 52, 10)
    assert move.path == Box(60, 100, 20, 10) and move.path_edges == (60, 100, 80, 110)
    assert repr(move) == f"Move(box={move.box}, hit={move.hit}, start={move.start})"


def test_a_body_flush_against_the_right_side_of_the_map_cannot_move_past_it() -> None:
    grid = grid_of(cols=10, rows=4)
    move = move_x(grid, Box(148, 0, 12, 14), 1.0)
    assert move.box.right == 160 and move.hit == Hit(Side.RIGHT, 160, None)
    assert move_x(grid, Box(0, 0, 12, 14), -1.0).hit == Hit(Side.LEFT, 0, None)


def test_touching_lists_the_shapes_of_one_kind_that_overlap_the_box() -> None:
    spikes = TileShape(Box(40, 84, 8, 8), HAZARD, 2, 5)
    grid = floor_grid()
    grid.put(2, 5, spikes)
    assert touching(grid, Box(36, 78, 12, 14), HAZARD) == [spikes]
    assert touching(grid, Box(36, 70, 12, 14), HAZARD) == []       # above them
    assert touching(grid, Box(28, 78, 12, 14), HAZARD) == []       # left of them
    assert [s.col for s in touching(grid, Box(36, 78, 12, 14), SOLID)] == [2]


def test_penetration_depth_is_the_deepest_overlap_with_a_solid() -> None:
    grid = floor_grid()
    grid.put(2, 4, TileShape(Box(32, 78, 16, 2), HAZARD, 2, 4))
    assert penetration_depth(grid, Box(36, 69, 12, 14)) == 3.0
    assert penetration_depth(grid, Box(36, 66, 12, 14)) == 0.0


def test_the_corner_slide_tries_the_smaller_shift_first() -> None:
    grid = grid_of((3, 2, Box(48, 32, 6, 16), SOLID))
    slid = slide_past_ceiling_corner(grid, Box(50, 50, 4, 14), -10.0, 6.0)
    assert slid is not None and slid[0].box.x == 54          # 4 px right, not 6 px left


def test_the_corner_slide_takes_the_other_way_when_the_nearer_one_is_walled() -> None:
    grid = grid_of((3, 2, Box(48, 32, 6, 16), SOLID), (3, 3, Box(57, 48, 4, 16), SOLID))
    slid = slide_past_ceiling_corner(grid, Box(50, 50, 4, 14), -10.0, 6.0)
    assert slid is not None and slid[0].box.x == 44


def test_the_corner_slide_takes_a_clip_of_exactly_1_px() -> None:
    grid = grid_of((3, 2, Box(48, 32, 16, 16), SOLID))
    slid = slide_past_ceiling_corner(grid, Box(37, 50, 12, 14), -10.0, 4.0)
    assert slid is not None and slid[0].box.x == 36


def test_the_corner_slide_takes_a_clip_of_exactly_1_px_on_the_right() -> None:
    grid = grid_of((3, 2, Box(48, 32, 16, 16), SOLID))
    slid = slide_past_ceiling_corner(grid, Box(63, 50, 12, 14), -10.0, 4.0)
    assert slid is not None and slid[0].box.x == 64


def test_the_corner_slide_needs_a_rise_higher_than_the_bump() -> None:
    """Past the corner (3 px right) another ceiling hangs just as low: no slide."""
    grid = grid_of((2, 2, Box(32, 32, 16, 16), SOLID), (3, 2, Box(48, 40, 16, 8), SOLID))
    bump = move_y(grid, Box(45, 50, 12, 14), -10.0)
    assert bump.hit is not None and bump.hit.shape is not None and bump.hit.shape.col == 2
    assert move_y(grid, Box(48, 50, 12, 14), -10.0).box.top == bump.box.top == 48
    assert slide_past_ceiling_corner(grid, Box(45, 50, 12, 14), -10.0, 4.0) is None


# --- Nearest free place (a spawn inside a wall) --------------------------------------------

def test_a_box_in_a_free_place_stays_where_it_is() -> None:
    box = Box(40, 66, 12, 14)
    assert nearest_free_place(floor_grid(), box) is box


def test_a_box_sunk_into_a_floor_comes_up_onto_it() -> None:
    assert nearest_free_place(floor_grid(), Box(40, 70.5, 12, 14)) == Box(40, 66, 12, 14)


def test_a_box_in_a_wall_goes_out_on_the_nearer_side() -> None:
    grid = grid_of(*((3, r, Box(48, r * T, T, T), SOLID) for r in range(10)))
    assert nearest_free_place(grid, Box(50, 40, 12, 14)) == Box(36, 40, 12, 14)
    assert nearest_free_place(grid, Box(54, 40, 12, 14)) == Box(64, 40, 12, 14)


def test_a_tie_goes_to_the_higher_then_the_more_left_place() -> None:
    grid = grid_of((3, 3, Box(48, 48, 16, 16), SOLID))
    assert nearest_free_place(grid, Box(50, 50, 12, 12)) == Box(50, 36, 12, 12)  # up 14 < 16
    # A 4x4 box in the middle of a 16x16 block: 8 px out every way; up wins, then left.
    assert nearest_free_place(grid, Box(54, 54, 4, 4)) == Box(54, 44, 4, 4)
    grid = grid_of(*((3, r, Box(48, r * T, T, T), SOLID) for r in range(10)))
    assert nearest_free_place(grid, Box(54, 40, 4, 4)) == Box(44, 40, 4, 4)


def test_deep_in_rock_the_search_grows_until_it_reaches_open_air() -> None:
    """Every cell solid: the first windows hold only rock, so the search widens until it
    reaches past the map, and of the four ways out (74 px up or left, 90 px down or right)
    the higher wins."""
    grid = grid_of(*((c, r, Box(c * T, r * T, T, T), SOLID) for c in range(10)
                     for r in range(10)))
    assert nearest_free_place(grid, Box(70, 70, 4, 4), search_px=4.0) == Box(70, -4, 4, 4)


def rock_with_pockets(cols: int, rows: int, pockets: set[tuple[int, int]]) -> TileGrid:
    """A map of solid cells but the free ones, the pockets."""
    return grid_of(*((c, r, Box(c * T, r * T, T, T), SOLID) for c in range(cols)
                     for r in range(rows) if (c, r) not in pockets), cols=cols, rows=rows)


def test_deep_in_rock_a_place_found_is_taken_only_once_none_can_be_nearer() -> None:
    """Rock but two cells: the first window to hold a free place holds one 169 px away, in
    the cell (18, 10); the search widens until it is sure, and the nearest is 161.5 px away,
    off the map's left side."""
    grid = rock_with_pockets(32, 32, {(18, 10), (19, 4)})
    assert nearest_free_place(grid, Box(149.5, 259.25, 12, 14)) == Box(-12, 259.25, 12, 14)


def test_the_search_finds_what_a_search_of_every_wall_finds() -> None:
    """Random rock maps with a few free cells, random boxes in them: from a small first
    window the search ends on the same place as from a first window holding the whole map,
    which tries every wall's faces."""
    rng = random.Random(1)
    for _ in range(12):
        cols, rows = rng.randint(10, 16), rng.randint(10, 16)
        pockets = {(rng.randrange(cols), rng.randrange(rows)) for _ in range(rng.randint(3, 8))}
        grid = rock_with_pockets(cols, rows, pockets)
        for _ in range(3):
            w, h = rng.randint(4, 24), rng.randint(4, 24)
            box = Box(rng.randrange(4 * (grid.width_px - w)) / 4,
                      rng.randrange(4 * (grid.height_px - h)) / 4, w, h)
            every_wall = nearest_free_place(grid, box, max(grid.width_px, grid.height_px))
            first_px = rng.choice([1.0, 4.0, 16.0, 64.0])
            assert nearest_free_place(grid, box, first_px) == every_wall, (pockets, box)


def test_a_way_out_just_past_the_first_window_is_taken_when_it_is_the_nearer() -> None:
    """All rock, a box 4 px wide and 14 high 82 px from the map's left side and 76 px from
    its top: the way out up, 90 px, is in the first window (64 px round the box) and the way
    out left, 86 px, only in the next; the nearer wins. Turned a quarter, the same holds
    with the two sides swapped."""
    grid = rock_with_pockets(20, 20, set())
    assert nearest_free_place(grid, Box(82, 76, 4, 14)) == Box(-4, 76, 4, 14)
    assert nearest_free_place(grid, Box(76, 82, 14, 4)) == Box(76, -4, 14, 4)


def test_a_box_larger_than_the_map_goes_to_the_nearest_place_beyond_the_window() -> None:
    """A box 400 px square over a map 32 px square with one solid tile: once the window
    holds the whole map, the nearest place it found (116 px right, as near as 116 px down
    and higher) is the answer, though it lies farther than the window reaches."""
    grid = grid_of((0, 0, Box(0, 0, T, T), SOLID), cols=2, rows=2)
    assert nearest_free_place(grid, Box(-100, -100, 400, 400)) == Box(16, -100, 400, 400)


# --- The tile grid ------------------------------------------------------------------------

@pytest.mark.parametrize(("col", "row"), [(-1, 0), (0, -1), (10, 0), (0, 4)])
def test_a_shape_is_refused_outside_the_map_with_its_cell_named(col: int, row: int) -> None:
    with pytest.raises(IndexError, match=fr"cell \({col}, {row}\) is outside a 10x4 map"):
        TileGrid(10, 4, T, T).put(col, row, TileShape(Box(0, 0, 1, 1), SOLID))


def test_shapes_with_no_area_are_kept_for_drawing_but_never_collide() -> None:
    grid = TileGrid(10, 4, T, T)
    line = TileShape(Box(16, 0, 0, 16), SOLID, 1, 0)
    flat = TileShape(Box(32, 8, 16, 0), SOLID, 2, 0)
    tile = TileShape(Box(16, 0, 16, 16), SOLID, 1, 0)
    for shape in (line, flat, tile):
        grid.put(shape.col, shape.row, shape)
    assert grid.shapes_in(Box(0, 0, 160, 64)) == [tile]
    assert grid.shapes_at(1, 0) == (tile, line) and grid.shapes_at(2, 0) == (flat,)
    assert grid.shapes_at(0, 0) == () and grid.shapes_at(-1, 0) == ()
    assert grid.shapes_at(10, 0) == ()
    assert grid.shapes_at(0, 4) == () and grid.shapes_at(0, -1) == ()
    first = TileShape(Box(0, 16, 16, 16), SOLID, 0, 1)
    grid.put(0, 1, first)
    assert grid.shapes_at(0, 1) == (first,) and grid.shapes_at(10, 0) == ()
    assert list(grid.shapes()) == [tile, first, line, flat]
    with_platforms = LevelSolids(grid, PlatformIndex(grid))   # a level with no platform
    assert with_platforms.shapes_in(Box(0, 0, 160, 64)) == [tile, first]
    assert with_platforms.width_px == 160 and with_platforms.height_px == 64


def test_the_cells_covering_a_region_follow_strict_overlap_and_stay_in_the_map() -> None:
    grid = TileGrid(10, 4, T, T)
    assert list(grid.cells_covering(Box(16, 16, 16, 16))) == [(1, 1)]
    assert list(grid.cells_covering(Box(15.5, 16, 1, 16.5))) == [(0, 1), (1, 1), (0, 2), (1, 2)]
    assert list(grid.cells_covering(Box(-40, -40, 60, 50))) == [(0, 0), (1, 0)]
    assert list(grid.cells_covering(Box(150, 60, 100, 100))) == [(9, 3)]
    assert list(grid.cells_covering(Box(160, 0, 10, 10))) == []
    assert list(grid.cells_covering(Box(0, 64, 10, 10))) == []
    assert list(grid.cells_covering(Box(20, 20, 0, 10))) == []
    assert list(grid.cells_covering(Box(20, 20, 10, -1))) == []
    assert list(grid.cells_covering(Box(20, 20, math.inf, 10))) == []
    assert grid.block_covering(15.5, 16, 16.5, 32.5) == (0, 1, 1, 2)
    assert grid.block_covering(-40, -40, 20, 10) == (0, 1, 0, 0)
    assert grid.block_covering(0, 0, math.nan, 10) is None
    assert grid.block_covering(0, 5, 10, 5) is None              # no height
    assert grid.block_covering(170, 0, 180, 10) is None          # right of the map only
    assert grid.block_covering(0, 70, 10, 80) is None            # below the map only


def test_the_block_a_query_visits_is_the_one_max_and_min_would_clamp_to() -> None:
    """:meth:`TileGrid.block_covering` keeps its block in the map by comparisons; its plain
    twin does it with max() and min(). Every region with edges among values on, beside,
    inside and beyond the map's edges (infinities and NaN too) gets the same block."""
    grid = TileGrid(10, 4, T, T)    # 160 x 64 px
    edges = [-math.inf, -1e300, -40, -16, -0.5, 0, 0.5, 15.5, 16, 16.5, 63.5, 64, 64.5, 80,
             159.5, 160, 160.5, 170, 1e300, math.inf, math.nan]
    blocks = set()
    for left, top, right, bottom in itertools.product(edges, repeat=4):
        block = grid.block_covering(left, top, right, bottom)
        assert block == grid.block_covering_plainly(left, top, right, bottom), (
            left, top, right, bottom)
        blocks.add(block)
    assert (0, 9, 0, 3) in blocks and (9, 9, 3, 3) in blocks and None in blocks


def test_a_query_counts_the_cells_it_visits_and_the_shapes_it_tests() -> None:
    plain = floor_grid()
    plain.put(2, 4, TileShape(Box(32, 72, 8, 8), HAZARD, 2, 4))
    grid = CountedGrid(plain)
    assert (grid.width_px, grid.height_px) == (plain.width_px, plain.height_px)
    found = grid.entries_in(20, 70, 50, 82)        # columns 1-3, rows 4-5
    assert grid.stats.cells_visited == 6 and grid.stats.shapes_tested == 4
    assert len(found) == 4 and found == plain.entries_in(20, 70, 50, 82)
    grid.entries_in(-50, -50, -10, -10)            # off the map: nothing visited
    assert grid.stats.cells_visited == 6 and grid.stats.shapes_tested == 4
    grid.stats.reset()
    assert (grid.stats.cells_visited, grid.stats.shapes_tested) == (0, 0)


def test_a_query_far_outside_the_map_clamps_to_its_edge_cells() -> None:
    grid = floor_grid()
    assert [s.col for s in grid.shapes_in(Box(-1000, 70, 1020, 20))] == [0, 1]
    assert [s.col for s in grid.shapes_in(Box(150, 70, 1000, 20))] == [9]
    assert grid.entries_in(-math.inf, 0, 10, 10) == []


def test_a_query_reaching_past_the_map_s_right_edge_in_its_last_row_finds_the_last_column() -> None:
    grid = grid_of(*((c, 5, Box(c * T, 5 * T, T, T), SOLID) for c in range(10)), rows=6)
    assert [s.col for s in grid.shapes_in(Box(150, 84, 20, 12))] == [9]   # last_col == cols
    assert [s.col for s in grid.shapes_in(Box(150, 84, 17, 12))] == [9]


def test_plain_lookups_ask_the_level_s_solids_and_each_platform_pushes_without_itself() -> None:
    grid = floor_grid()
    a, b = (Platform(PlatformSpec(Route(((x, 0.0),)), 4, 4, 0.0), n)
            for n, x in ((0, 0.0), (1, 8.0)))
    solids = LevelSolids(grid, PlatformIndex(grid, [a, b]))
    lookups = Lookups.plain(solids, [a, b])
    for source in (lookups.ledges, lookups.moving_bodies,
                   lookups.hazards, lookups.checkpoint_spawn, lookups.penetration):
        assert source is solids
    assert [s.without for s in lookups.platforms] == [a, b]  # type: ignore[attr-defined]
    assert [[e.shape for e in s.entries_in(0, 0, 12, 2)] for s in lookups.platforms] == [
        [b.shape], [a.shape]]


def test_an_attached_log_writes_down_each_query_under_its_purpose() -> None:
    grid = floor_grid()
    solids = LevelSolids(grid, PlatformIndex(grid))
    log = QueryLog()
    found = LoggedSource(solids, log, "x sweep").entries_in(20, 70, 50, 82)
    assert found == grid.entries_in(20, 70, 50, 82)
    LoggedSource(solids, log, "ground probe").entries_in(-40, -40, 20, 10)
    LoggedSource(solids, log, "hazards").entries_in(-50, -50, -10, -10)  # off the map
    assert log.queries == [Query("x sweep", 1, 3, 4, 5), Query("ground probe", 0, 1, 0, 0),
                           Query("hazards", 0, -1, 0, -1)]
    assert list(log.queries[0].cells()) == [(1, 4), (2, 4), (3, 4), (1, 5), (2, 5), (3, 5)]
    assert list(log.queries[2].cells()) == []
    assert list(Query("empty", 3, 2, 0, 0).cells()) == []
    assert log.stats.cells_visited == 6 + 2
    log.clear()
    assert log.queries == [] and (log.stats.cells_visited, log.stats.shapes_tested) == (0, 0)


def test_the_log_notes_the_moving_shapes_a_query_tested_beside_its_tiles() -> None:
    grid = floor_grid()
    a, b = (Platform(PlatformSpec(Route(((x, 0.0),)), 4, 4, 0.0), n)
            for n, x in ((0, 0.0), (1, 8.0)))
    solids = LevelSolids(grid, PlatformIndex(grid, [a, b]))
    log = QueryLog()
    LoggedSource(solids, log, "y sweep").entries_in(0, 20, 10, 30)   # near neither
    LoggedSource(solids, log, "y sweep").entries_in(0, 0, 12, 2)     # tests both
    LoggedSource(solids.leaving_out(a), log, "platforms").entries_in(0, 0, 12, 2)
    assert [q.extra for q in log.queries] == [(), (a.shape, b.shape), (b.shape,)]
    assert log.stats.shapes_tested == 2 + 1
    assert LoggedSource(solids, log, "").width_px == grid.width_px
    assert LoggedSource(solids, log, "").height_px == grid.height_px


# --- The tunables -------------------------------------------------------------------------

def test_a_level_sets_the_four_physics_numbers_and_nothing_else() -> None:
    tuned = Tuning().with_map_properties({"gravity": 100, "max_fall_speed": 200.5,
                                          "run_speed": 50, "jump_speed": 300,
                                          "coyote_time": 9, "title": "x"})
    assert (tuned.gravity_px_s2, tuned.max_fall_speed_px_s, tuned.run_speed_px_s,
            tuned.jump_speed_px_s) == (100.0, 200.5, 50.0, 300.0)
    assert isinstance(tuned.gravity_px_s2, float)
    assert tuned.coyote_time_s == TUNING.coyote_time_s


def test_a_level_property_that_is_not_a_number_is_ignored() -> None:
    tuned = Tuning().with_map_properties({"gravity": "fast", "run_speed": True,
                                          "jump_speed": None})
    assert tuned == Tuning()


def test_the_run_rate_comes_from_the_ground_or_air_time_of_speeding_up_or_stopping() -> None:
    tuning = Tuning(run_speed_px_s=60.0, run_accel_time_s=0.1, run_stop_time_s=0.2,
                    air_accel_time_s=0.25, air_stop_time_s=0.5)
    assert run_change_px_s(tuning, on_ground=True, speeding_up=True) == pytest.approx(10.0)
    assert run_change_px_s(tuning, on_ground=True, speeding_up=False) == pytest.approx(5.0)
    assert run_change_px_s(tuning, on_ground=False, speeding_up=True) == pytest.approx(4.0)
    assert run_change_px_s(tuning, on_ground=False, speeding_up=False) == pytest.approx(2.0)
    instant = Tuning(run_accel_time_s=0.0, air_stop_time_s=-1.0)
    assert run_change_px_s(instant, on_ground=True, speeding_up=True) == math.inf
    assert run_change_px_s(instant, on_ground=False, speeding_up=False) == math.inf


def test_the_tick_counts_are_worked_out_from_the_times() -> None:
    tuning = Tuning(coyote_time_s=0.2, jump_buffer_s=0.05, invulnerable_time_s=0.5,
                    hopper_rest_s=0.25)
    assert (tuning.coyote_ticks, tuning.jump_buffer_ticks, tuning.invulnerable_ticks,
            tuning.hopper_rest_ticks) == (12, 3, 30, 15)


# --- The player ---------------------------------------------------------------------------

def player_in_the_air() -> Player:
    return Player(Box(0, 0, 12, 14), TUNING)


def test_approach_moves_towards_the_target_by_at_most_the_step() -> None:
    assert approach(5.0, 5.0, 1.0) == 5.0
    assert approach(4.5, 5.0, 1.0) == 5.0 and approach(5.5, 5.0, 1.0) == 5.0
    assert approach(0.0, 5.0, 1.0) == 1.0 and approach(0.0, -5.0, 1.0) == -1.0


def test_holding_left_and_right_together_runs_nowhere() -> None:
    player = player_in_the_air()
    player.decide(frozenset({Action.LEFT, Action.RIGHT}), TUNING)
    assert player.vx == 0.0 and player.facing == 1


def test_the_player_faces_the_way_it_runs_and_starts_facing_right() -> None:
    player = player_in_the_air()
    assert player.facing == 1
    player.decide(LEFT, TUNING)
    assert player.facing == -1 and player.vx < 0
    player.decide(NOTHING, TUNING)
    assert player.facing == -1


def test_starting_to_run_in_the_air_uses_the_air_speed_up_time() -> None:
    player = player_in_the_air()
    assert player.decide(RIGHT, TUNING) is False
    assert player.vx == pytest.approx(TUNING.run_speed_px_s * TUNING.tick_s
                                      / TUNING.air_accel_time_s)


def test_starting_to_run_on_the_ground_uses_the_ground_speed_up_time() -> None:
    tuning = Tuning(run_accel_time_s=0.1, run_stop_time_s=0.2)
    player = Player(Box(0, 0, 12, 14), tuning)
    player.on_ground = True
    player.decide(RIGHT, tuning)
    assert player.vx == pytest.approx(15.0)      # 90 px/s reached in 0.1 s: 15 px/s a tick
    player.vx = -30.0
    player.decide(RIGHT, tuning)
    assert player.vx == pytest.approx(-30.0 + 7.5)           # turning round: the stop rate


def test_a_jump_leaves_the_ground_and_is_reported_once() -> None:
    player = player_in_the_air()
    player.on_ground = True
    assert player.decide(JUMP, TUNING) is True
    assert player.on_ground is False and player.rising_from_jump
    assert player.coyote_ticks_left == player.jump_buffer_ticks_left == 0   # spent on it
    assert player.vy == -TUNING.jump_speed_px_s + TUNING.gravity_px_s2 * TUNING.tick_s
    player.on_ground = True                                   # as if it landed at once
    assert player.decide(JUMP, TUNING) is False               # still held: no new press


def test_a_level_that_starts_on_the_ground_jumps_on_the_first_tick() -> None:
    world = World(level_from_ascii(["     ", "     ", "#####"],
                                   spawn=Box(16, 2 * T - 14, 12, 14)), TUNING)
    assert world.player.on_ground
    assert any(e.kind is EventKind.JUMP for e in world.step(JUMP))


def test_a_level_that_starts_on_a_one_way_tile_jumps_on_the_first_tick() -> None:
    world = World(level_from_ascii(["     ", "     ", "-----"],
                                   spawn=Box(16, 2 * T - 14, 12, 14)), TUNING)
    assert world.player.on_ground and not world.player.dropping_through
    assert any(e.kind is EventKind.JUMP for e in world.step(JUMP))


def test_a_cut_jump_is_cut_once() -> None:
    world = World(level_from_ascii(["     "] * 9 + ["#####"], spawn=Box(16, 9 * T - 14, 12, 14)),
                  TUNING)
    world.step(JUMP)
    world.step(JUMP)
    world.step(NOTHING)                                      # cut here
    cut = world.player.vy
    world.step(NOTHING)
    assert world.player.vy == cut + TUNING.gravity_px_s2 * TUNING.tick_s


def test_after_the_apex_a_held_jump_falls_at_the_plain_gravity() -> None:
    """A jump speed whose rise ends on a fraction of a pixel per second: the fall that
    follows is never cut, whether that first downward speed is under 1 px/s or not."""
    tuning = Tuning(jump_speed_px_s=284.5)
    world = World(level_from_ascii(["     "] * 9 + ["#####"], spawn=Box(16, 9 * T - 14, 12, 14)),
                  tuning)
    world.step(JUMP)
    speeds = [world.player.vy]
    for _ in range(25):
        world.step(JUMP)
        speeds.append(world.player.vy)
    steps = [after - before for before, after in itertools.pairwise(speeds) if after < 100]
    assert steps == pytest.approx([tuning.gravity_px_s2 * tuning.tick_s] * len(steps))
    assert 0.0 < min(v for v in speeds if v > 0) < 1.0 + 15.0


def move_with(hit: Hit | None) -> Move:
    box = Box(0, 0, 12, 14)
    return Move(box, hit, box)


def test_hitting_a_wall_stops_the_run() -> None:
    player = player_in_the_air()
    player.vx, player.vy = 90.0, 30.0
    player.react(move_with(Hit(Side.RIGHT, 12, None)), move_with(None))
    assert player.vx == 0.0 and player.vy == 30.0


@pytest.mark.parametrize(("side", "vy", "stopped"), [
    (Side.BOTTOM, 0.5, True), (Side.BOTTOM, -0.5, False), (Side.BOTTOM, 0.0, False),
    (Side.TOP, -0.5, True), (Side.TOP, 0.5, False), (Side.TOP, 0.0, False)])
def test_a_floor_stops_a_fall_and_a_ceiling_a_rise_but_neither_the_other(
        side: Side, vy: float, stopped: bool) -> None:
    player = player_in_the_air()
    player.vx, player.vy, player.rising_from_jump = 20.0, vy, True
    player.react(move_with(None), move_with(Hit(side, 0, None)))
    assert player.vx == 20.0
    assert player.vy == (0.0 if stopped else vy)
    assert player.rising_from_jump is (not stopped)


def test_a_bounce_is_a_fall_upwards_that_letting_go_does_not_cut() -> None:
    player = player_in_the_air()
    player.on_ground, player.rising_from_jump = True, True
    player.bounce(200.0)
    assert player.vy == -200.0 and player.on_ground is False and player.rising_from_jump is False
    player.decide(JUMP, TUNING)          # in the air after a bounce: a press is no jump
    assert player.vy == -200.0 + TUNING.gravity_px_s2 * TUNING.tick_s


def test_a_respawn_starts_still_in_the_air_with_no_jump_remembered() -> None:
    player = player_in_the_air()
    player.vx, player.vy, player.on_ground, player.rising_from_jump = 50.0, -80.0, True, True
    player.coyote_ticks_left = player.jump_buffer_ticks_left = 5
    player.respawn(Box(100, 10, 12, 14), invulnerable_ticks=90)
    assert player.box == Box(100, 10, 12, 14)
    assert (player.vx, player.vy, player.on_ground, player.rising_from_jump) == (0, 0, False,
                                                                                 False)
    assert player.coyote_ticks_left == player.jump_buffer_ticks_left == 0
    assert player.decide(JUMP, TUNING) is False               # no coyote time after it
    assert player.invulnerable_ticks_left == 89
    for _ in range(88):
        player.decide(NOTHING, TUNING)
    assert player.invulnerable
    player.decide(NOTHING, TUNING)
    assert not player.invulnerable


def test_a_respawn_asked_for_no_safe_time_gives_none() -> None:
    player = player_in_the_air()
    player.respawn(Box(100, 10, 12, 14))
    assert player.invulnerable_ticks_left == 0 and not player.invulnerable


# --- a body's whole move ------------------------------------------------------------------

def test_a_path_crosses_only_a_region_it_overlaps_with_area() -> None:
    """The path (x 20..40, y 20..30) crosses a region only by strict overlap: a region of no
    width or height inside it, or one touching any of its four sides, is not crossed; one
    under a pixel wide or high inside it is."""
    moves = move_body(TileGrid(10, 10, T, T), Box(20, 20, 10, 10), 10.0, 0.0)
    assert moves.x.path_edges == (20, 20, 40, 30)
    for empty in (Box(25, 22, 0, 5), Box(25, 22, 5, 0), Box(25, 22, 0, 0)):
        assert not moves.crosses(empty), empty
    for thin in (Box(25, 22, 0.5, 5), Box(25, 22, 5, 0.5)):
        assert moves.crosses(thin), thin
    for touching_a_side in (Box(10, 22, 10, 5), Box(40, 22, 5, 5), Box(25, 10, 5, 10),
                            Box(25, 30, 5, 5)):
        assert not moves.crosses(touching_a_side), touching_a_side


def test_a_move_by_default_lands_on_a_one_way_top_and_slides_past_no_corner() -> None:
    one_way = grid_of(*((c, 5, Box(c * T, 5 * T, T, T), ONE_WAY) for c in range(10)))
    landed = move_body(one_way, Box(20, 60, 12, 14), 0.0, 10.0)
    assert landed.y.box.y == 66 and landed.ground is not None
    ceiling = grid_of((3, 2, Box(48, 32, 16, 16), SOLID))
    bumped = move_body(ceiling, Box(63.5, 50, 12, 14), 0.0, -10.0)   # clipped by 0.5 px
    assert bumped.x.box.x == 63.5 and bumped.y.hit is not None
    assert bumped.y.hit.side is Side.TOP


def test_below_the_map_a_fall_stops_at_its_bottom_edge_and_the_sky_ends_far_above() -> None:
    grid = TileGrid(10, 10, T, T)
    fell = move_body(grid, Box(20, 150, 12, 14), 0.0, 30.0)
    assert fell.y.box.y == grid.height_px and fell.y.hit is None and fell.ground is None
    assert fell.y.start == Box(20, 150, 12, 14) and fell.y.swept == Box(20, 150, 12, 44)
    flung = move_body(grid, Box(20, -SKY_LIMIT_PX + 5, 12, 14), 0.0, -30.0)
    assert flung.y.box == Box(20, -SKY_LIMIT_PX, 12, 14)
    assert flung.y.swept == Box(20, -SKY_LIMIT_PX - 25, 12, 44)
    inside = move_body(grid, Box(20, 100, 12, 14), 0.0, 10.0)
    assert inside.y.box.y == 110


def test_a_move_the_void_or_the_sky_cuts_short_still_says_what_stopped_it() -> None:
    """A platform whose route leaves the map can lie below its bottom edge or past the sky:
    a move that ends on it there is held at that edge, and still names the platform as what
    stopped it."""
    grid = TileGrid(10, 10, T, T)
    below, above = (Platform(PlatformSpec(Route(((0.0, y),)), 160, 16, 0.0), n)
                    for n, y in ((0, 200.0), (1, -SKY_LIMIT_PX - 100)))
    solids = LevelSolids(grid, PlatformIndex(grid, [below, above]))
    fell = move_body(solids, Box(20, 150, 12, 14), 0.0, 60.0)
    assert fell.y.box.y == grid.height_px
    assert fell.y.hit == Hit(Side.BOTTOM, 200.0, below.shape)
    flung = move_body(solids, Box(20, 0, 12, 14), 0.0, -2 * SKY_LIMIT_PX)
    assert flung.y.box.y == -SKY_LIMIT_PX
    assert flung.y.hit == Hit(Side.TOP, -SKY_LIMIT_PX - 84, above.shape)


def test_a_corner_slide_keeps_the_wall_the_run_hit_and_sweeps_both_steps() -> None:
    """Running right into a wall while rising into a ceiling's corner: the slide goes left,
    and the x move still says it hit the wall (so the run stops) and sweeps the run and the
    slide."""
    grid = grid_of((3, 2, Box(60, 32, 4, 16), SOLID), (4, 2, Box(64, 32, 12, 16), SOLID),
                   (4, 3, Box(64, 48, 16, 16), SOLID))
    moves = move_body(grid, Box(50, 50, 12, 14), 5.0, -10.0, corner_px=4.0)
    assert moves.x.box.x == 48 and moves.y.box.y == 40 and moves.y.hit is None
    assert moves.x.hit is not None and moves.x.hit.side is Side.RIGHT and moves.x.hit.face == 64
    assert moves.x.swept == Box(48, 50, 19, 14)


def test_a_fall_onto_a_floor_s_edge_is_no_corner_slide() -> None:
    """A fall clipping a floor's corner by 3 px is not slid past it, not even onto a
    higher ledge beside it (which a slide would make the fall end sooner on)."""
    grid = grid_of((3, 5, Box(48, 80, 16, 16), SOLID), (4, 4, Box(74, 76, 6, 4), SOLID))
    assert slide_past_ceiling_corner(grid, Box(61, 60, 12, 14), 10.0, 4.0) is None


def test_the_gap_between_boxes_is_along_the_farther_axis_and_none_when_they_touch() -> None:
    box = Box(0, 0, 10, 10)
    assert box.gap(Box(25, 3, 10, 10)) == 15                  # to the right
    assert box.gap(Box(-17, 3, 10, 10)) == 7                  # to the left
    assert box.gap(Box(3, 14, 10, 10)) == 4                   # below
    assert box.gap(Box(3, -22, 10, 10)) == 12                 # above
    assert box.gap(Box(16, -30, 10, 10)) == 20                # the farther axis counts
    assert box.gap(Box(10, 0, 10, 10)) == 0.0 and box.gap(Box(5, 5, 2, 2)) == 0.0


def test_a_body_standing_still_or_dropping_through_finds_its_ground_by_the_probe() -> None:
    """A move that does not fall (none at all, or a rise) asks the probe for the ground:
    the floor under still feet, none under rising ones, and no one-way top under feet
    dropping through it."""
    assert move_body(floor_grid(), Box(20, 66, 12, 14), 3.0, 0.0).ground is not None
    assert move_body(floor_grid(), Box(20, 66, 12, 14), 0.0, -5.0).ground is None
    one_way = grid_of(*((c, 5, Box(c * T, 5 * T, T, T), ONE_WAY) for c in range(10)))
    assert move_body(one_way, Box(20, 66, 12, 14), 0.0, 0.0).ground is not None
    assert move_body(one_way, Box(20, 66, 12, 14), 0.0, 0.0, through_one_way=True).ground is None


def test_a_new_player_is_still_and_remembers_no_jump_no_drop_and_no_safe_time() -> None:
    player = Player(Box(0, 0, 12, 14), TUNING)
    assert (player.vx, player.vy, player.facing) == (0.0, 0.0, 1)
    assert (player.coyote_ticks_left, player.jump_buffer_ticks_left, player.drop_ticks_left,
            player.invulnerable_ticks_left) == (0, 0, 0, 0)
    assert player.rising_from_jump is False and not player.invulnerable
    assert (player.coyote_ticks, player.jump_buffer_ticks) == (TUNING.coyote_ticks,
                                                               TUNING.jump_buffer_ticks)


def test_dropping_through_a_one_way_top_spends_the_jump_press() -> None:
    player = player_in_the_air()
    player.on_ground = True
    player.standing_on = TileShape(Box(0, 14, T, T), ONE_WAY, 0, 1)
    down_jump: Actions = frozenset({Action.DOWN, Action.JUMP})
    assert player.decide(down_jump, TUNING) is False
    assert player.dropping_through and player.jump_buffer_ticks_left == 0


def test_a_held_jump_whose_rise_ends_on_exactly_0_px_s_is_no_longer_rising() -> None:
    """Jump speed 300 px/s and gravity 15 px/s a tick: the rise ends on exactly 0 px/s, and
    from that tick on the jump can no longer be cut: it is over."""
    tuning = Tuning(jump_speed_px_s=300.0, gravity_px_s2=900.0)
    player = Player(Box(0, 0, 12, 14), tuning)
    player.on_ground = True
    player.decide(JUMP, tuning)
    player.on_ground = False
    while player.vy < 0:
        assert player.rising_from_jump
        player.decide(JUMP, tuning)
    assert player.vy == 0.0 and player.rising_from_jump       # the last rising tick
    player.decide(JUMP, tuning)
    assert player.rising_from_jump is False and player.vy == 15.0


def test_deep_in_rock_the_nearer_of_two_far_free_places_is_taken() -> None:
    """Rock everywhere but a few pockets: the body is 96 px from open air off the map's left
    side and 97.5 px from a pocket up and to the right, and goes to the nearer."""
    pockets = {(11, 5), (13, 9), (14, 9), (14, 14), (14, 15), (15, 15)}
    grid = grid_of(*((c, r, Box(c * T, r * T, T, T), SOLID) for c in range(16)
                     for r in range(16) if (c, r) not in pockets), cols=16, rows=16)
    assert nearest_free_place(grid, Box(84, 114.25, 12, 14)) == Box(-12, 114.25, 12, 14)


def test_a_shape_one_pixel_wide_or_high_collides() -> None:
    grid = grid_of((2, 2, Box(32, 32, 1, 16), SOLID), (4, 2, Box(64, 32, 16, 1), SOLID))
    assert [e.shape.col for e in grid.entries_in(0, 0, 160, 160)] == [2, 4]


def test_a_fall_onto_a_one_way_top_with_a_solid_below_it_names_the_one_way_top() -> None:
    grid = grid_of((2, 5, Box(32, 80, 16, 16), ONE_WAY), (2, 6, Box(32, 96, 16, 16), SOLID))
    move = move_y(grid, Box(34, 60, 12, 14), 40.0)
    assert move.hit is not None and move.hit.face == 80
    assert move.hit.shape is not None and move.hit.shape.kind is ONE_WAY


class SolidEverywhere:
    """A source whose every query is answered by a solid a little larger than the region."""

    width_px, height_px = 160, 160

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        return [Entry.of(TileShape(Box(left - 1, top - 1, right - left + 2, bottom - top + 2),
                                   SOLID))]


def test_where_no_place_is_free_the_search_ends_standing_the_box_on_the_map() -> None:
    assert nearest_free_place(SolidEverywhere(), Box(30, 40, 12, 14)) == Box(30, -14, 12, 14)


def test_a_move_sweeps_what_it_is_given_or_else_its_start_and_step() -> None:
    start = Box(10, 20, 12, 14)
    assert Move(start, None, start).swept == start                   # a step of nothing
    assert Move(start, None, start, 3.0, -4.0).swept == Box(10, 16, 15, 18)
    given = Box(0, 0, 50, 50)
    assert Move(start.moved(3, 0), None, start, swept=given).swept == given


def test_the_path_of_a_move_left_or_up_runs_from_where_it_ended_to_where_it_started() -> None:
    start = Box(40, 40, 12, 14)
    left = move_x(TileGrid(10, 10, T, T), start, -15.0)
    up = move_y(TileGrid(10, 10, T, T), start, -15.0)
    assert left.path_edges == (25, 40, 52, 54) and left.path == Box(25, 40, 27, 14)
    assert up.path_edges == (40, 25, 52, 54)
