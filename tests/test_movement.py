"""The swept x and y passes against a tile grid: flush stops, seams, tunnelling, edges."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from game.collision.aabb import Box
from game.collision.axis_sweep import Move, Side, ground_under, move_x, move_y
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import CountedGrid, TileGrid

T = 16


def glide(move: Callable[[TileGrid, Box, float], Move], grid: TileGrid, box: Box,
          step_px: float, moves: int) -> Box:
    """Move ``box`` by ``step_px`` ``moves`` times along one axis; nothing may stop it."""
    for _ in range(moves):
        made = move(grid, box, step_px)
        assert made.hit is None, f"stopped at {made.box} by {made.hit}"
        box = made.box
    return box


def grid_with(cells: list[tuple[int, int]], kind: TileKind = TileKind.SOLID,
              cols: int = 200, rows: int = 200) -> TileGrid:
    grid = TileGrid(cols, rows, T, T)
    for col, row in cells:
        grid.put(col, row, TileShape(Box(col * T, row * T, T, T), kind, col, row))
    return grid


SPEEDS_PX = [0.1, 1.0, 7.5, 16.0, 40.0, 9 * T, 10 * T, 150 * T]


@pytest.mark.parametrize("speed", SPEEDS_PX)
def test_flush_stop_moving_right_into_a_one_tile_wall(speed: float) -> None:
    grid = grid_with([(100, 50)])
    start = Box(100 * T - 12 - speed / 2, 50 * T + 1, 12, 14)
    move = move_x(grid, start, speed)
    assert move.box.right == 100 * T
    assert move.hit is not None and move.hit.side is Side.RIGHT


@pytest.mark.parametrize("speed", SPEEDS_PX)
def test_flush_stop_moving_left_into_a_one_tile_wall(speed: float) -> None:
    grid = grid_with([(100, 50)])
    start = Box(101 * T + speed / 2, 50 * T + 1, 12, 14)
    move = move_x(grid, start, -speed)
    assert move.box.left == 101 * T
    assert move.hit is not None and move.hit.side is Side.LEFT


@pytest.mark.parametrize("speed", SPEEDS_PX)
def test_flush_stop_falling_onto_a_one_tile_floor(speed: float) -> None:
    grid = grid_with([(50, 100)])
    start = Box(50 * T + 2, 100 * T - 14 - speed / 2, 12, 14)
    move = move_y(grid, start, speed)
    assert move.box.bottom == 100 * T
    assert move.hit is not None and move.hit.side is Side.BOTTOM


@pytest.mark.parametrize("speed", SPEEDS_PX)
def test_flush_stop_rising_into_a_one_tile_ceiling(speed: float) -> None:
    grid = grid_with([(50, 100)])
    start = Box(50 * T + 2, 101 * T + speed / 2, 12, 14)
    move = move_y(grid, start, -speed)
    assert move.box.top == 101 * T
    assert move.hit is not None and move.hit.side is Side.TOP


@pytest.mark.parametrize("tiles_per_tick", [10, 50])
def test_no_tunnelling_at_many_tiles_per_tick_on_either_axis(tiles_per_tick: int) -> None:
    grid = grid_with([(60, 60)])
    dist = tiles_per_tick * T
    assert move_x(grid, Box(60 * T - 40, 60 * T, 12, 14), dist).box.right == 60 * T
    assert move_x(grid, Box(61 * T + 40, 60 * T, 12, 14), -dist).box.left == 61 * T
    assert move_y(grid, Box(60 * T, 60 * T - 40, 12, 14), dist).box.bottom == 60 * T
    assert move_y(grid, Box(60 * T, 61 * T + 40, 12, 14), -dist).box.top == 61 * T


def test_touching_edges_do_not_collide() -> None:
    grid = grid_with([(5, 5)])
    beside = Box(5 * T - 12, 5 * T, 12, 16)         # right edge on the tile's left face
    assert not beside.overlaps(Box(5 * T, 5 * T, T, T))
    # Moving along the touching face (vertically) is not blocked by it.
    assert move_y(grid, beside, 40).hit is None
    assert grid.shapes_in(beside) == []


def test_the_nearest_of_several_walls_stops_the_body() -> None:
    grid = grid_with([(20, 5), (12, 5), (30, 5)])
    move = move_x(grid, Box(0, 5 * T, 12, 14), 1000)
    assert move.box.right == 12 * T


def test_walking_across_100_tile_seams_on_a_floor_never_stops() -> None:
    grid = grid_with([(c, 10) for c in range(150)])
    box = Box(0.0, 10 * T - 14, 12, 14)
    box = glide(move_x, grid, box, 1.7, 1000)
    assert box.x == pytest.approx(1700)


def test_sliding_under_100_ceiling_seams_never_stops() -> None:
    grid = grid_with([(c, 10) for c in range(150)])
    box = Box(0.0, 11 * T, 12, 14)                 # head touching the ceiling's underside
    box = glide(move_x, grid, box, 16.0, 100)
    assert box.x == 1600


def test_sliding_down_a_wall_across_100_seams_never_stops() -> None:
    grid = grid_with([(10, r) for r in range(150)])
    box = Box(10 * T - 12, 0.0, 12, 14)            # right side touching the wall
    box = glide(move_y, grid, box, 16.0, 100)
    assert box.y == 1600


@pytest.mark.parametrize("step", [0.1, -0.1])
def test_sub_pixel_steps_add_up(step: float) -> None:
    grid = grid_with([])
    box = Box(500.0, 0.0, 12, 14)
    for _ in range(100):
        box = move_x(grid, box, step).box
    assert box.x == pytest.approx(500 + 100 * step)


def test_one_way_tiles_stop_a_fall_but_not_a_rise() -> None:
    grid = grid_with([(5, 5)], TileKind.ONE_WAY)
    assert move_y(grid, Box(5 * T, 5 * T - 20, 12, 14), 30).box.bottom == 5 * T
    assert move_y(grid, Box(5 * T, 6 * T + 2, 12, 14), -60).hit is None
    assert move_x(grid, Box(5 * T - 20, 5 * T, 12, 14), 60).hit is None


def test_the_map_sides_are_walls_and_never_wrap_round() -> None:
    grid = grid_with([(0, 3), (9, 3)], cols=10, rows=5)
    assert move_x(grid, Box(20, 0, 12, 14), -1000).box.x == 0
    assert move_x(grid, Box(100, 0, 12, 14), 1000).box.right == 160
    # A box hanging off the left edge sees nothing from the last column.
    assert grid.shapes_in(Box(-40, 3 * T, 20, 10)) == []


def test_the_ground_probe_needs_a_top_exactly_at_the_feet() -> None:
    grid = grid_with([(5, 5)])
    assert ground_under(grid, Box(5 * T, 5 * T - 14, 12, 14)) is not None
    assert ground_under(grid, Box(5 * T, 5 * T - 14.5, 12, 14)) is None
    assert ground_under(grid, Box(5 * T - 12, 5 * T - 14, 12, 14)) is None  # corner touch


def test_a_query_visits_only_the_cells_the_sweep_covers() -> None:
    grid = CountedGrid(grid_with([(c, 10) for c in range(200)]))
    move_x(grid, Box(97.0, 10 * T - 14, 12, 14), 3.0)
    assert grid.stats.cells_visited == 1   # x 97..112 ends on a border: column 6 only
    grid.stats.reset()
    move_x(grid, Box(100.0, 10 * T - 14, 12, 14), 3.0)
    assert grid.stats.cells_visited == 2   # x 100..115 reaches into column 7
    grid.stats.reset()
    move_y(grid, Box(100.0, 10 * T - 20, 12, 14), 10.0)
    assert grid.stats.cells_visited == 3   # y 140..164: rows 8, 9 and 10 of one column


def test_non_finite_steps_are_refused() -> None:
    grid = grid_with([])
    with pytest.raises(ValueError):
        move_x(grid, Box(0, 0, 1, 1), float("nan"))
    with pytest.raises(ValueError):
        move_y(grid, Box(0, 0, 1, 1), float("inf"))
