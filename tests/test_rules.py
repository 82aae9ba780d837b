"""Rules a player feels, each pinned at its edge in a scene of its own (none relies on a
shipped level): the exit and a checkpoint count the path travelled at any speed, a flush
touch of spikes does not hurt, a lift carries its rider up, down and sideways, and where a
Solid and a OneWay top meet at the same height the feet stand on the Solid.
"""

from __future__ import annotations

import math
from dataclasses import replace

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.collision.axis_sweep import ground_under, move_y
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.level import Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.maps import level_from_ascii, level_from_boxes

T = 16
RIGHT: Actions = frozenset({Action.RIGHT})
DOWN_JUMP: Actions = frozenset({Action.DOWN, Action.JUMP})
SOLID, ONE_WAY, HAZARD = TileKind.SOLID, TileKind.ONE_WAY, TileKind.HAZARD


# --- The exit and a checkpoint count the path travelled, at any speed ----------------------

SHAFT_FLOOR_Y = 60 * T  # a shaft 60 tiles deep: a fall of up to 600 px a tick lands in it
THIN = Box(20, 200, 16, 2)  # an exit or flag 2 px tall, across the falling player's right side


def falling_at(px_a_tick: float, exits: tuple[Box, ...] = (),
               checkpoints: tuple[Box, ...] = ()) -> list[EventKind]:
    """Drop the player (12x14, at x = 16) down the shaft at ``px_a_tick`` from the first tick
    (gravity reaches the fall speed at once); the events until it has passed y = 400."""
    level = level_from_boxes(4, 61, [Box(0, SHAFT_FLOOR_Y, 4 * T, T)],
                             Box(16, 0, 12, 14), list(exits), checkpoints=checkpoints)
    speed = px_a_tick * 60
    world = World(level, Tuning(gravity_px_s2=speed * 60, max_fall_speed_px_s=speed))
    kinds: list[EventKind] = []
    while world.player.box.top < 400:
        kinds += [event.kind for event in world.step(NOTHING)]
    return kinds


@pytest.mark.parametrize("px_a_tick", [1.0, 2.5, 13.0, 50.0, 150.0, 199.0, 600.0])
def test_a_fall_through_a_thin_exit_finishes_the_level_at_any_speed(px_a_tick: float) -> None:
    assert falling_at(px_a_tick, exits=(THIN,)).count(EventKind.EXIT) == 1


def test_an_exit_the_falling_path_only_touches_is_not_reached() -> None:
    beside = THIN._replace(x=28)          # its left edge on the player's right edge
    assert EventKind.EXIT not in falling_at(100.0, exits=(beside,))
    assert EventKind.EXIT in falling_at(100.0, exits=(beside._replace(x=27.5),))


@pytest.mark.parametrize("px_a_tick", [1.0, 2.5, 13.0, 50.0, 150.0, 199.0, 600.0])
def test_a_fall_through_a_thin_flag_counts_the_checkpoint_at_any_speed(px_a_tick: float,
                                                                        ) -> None:
    # The flag's centre (x = 28) is not the player's (x = 22): only the path can count it.
    assert falling_at(px_a_tick, checkpoints=(THIN,)).count(EventKind.CHECKPOINT) == 1


def running_at(px_a_tick: float, exits: tuple[Box, ...] = ()) -> list[EventKind]:
    """Run right along a floor at ``px_a_tick`` from the first tick; the events until the
    player has passed x = 400."""
    level = level_from_boxes(80, 4, [Box(0, 3 * T, 80 * T, T)], Box(16, 3 * T - 14, 12, 14),
                             list(exits))
    speed = px_a_tick * 60
    world = World(level, Tuning(run_speed_px_s=speed, run_accel_time_s=0.0))
    kinds: list[EventKind] = []
    while world.player.box.left < 400:
        kinds += [event.kind for event in world.step(RIGHT)]
    return kinds


@pytest.mark.parametrize("px_a_tick", [1.5, 40.0, 300.0])
def test_a_run_through_a_thin_exit_finishes_the_level_at_any_speed(px_a_tick: float) -> None:
    assert running_at(px_a_tick, exits=(Box(200, 2 * T, 2, T),)).count(EventKind.EXIT) == 1


# --- Spikes hurt on overlap; a flush touch does not ----------------------------------------

def hurt_in(level: Level, ticks: int = 120) -> bool:
    """Stand still for ``ticks``: did anything hurt?"""
    world = World(level)
    return any(event.kind is EventKind.HURT
               for _ in range(ticks) for event in world.step(NOTHING))


SPIKE_ON_THE_FLOOR = ["      ", "   ^  ", "######"]   # spikes in cell (3, 1): x 48 to 64


def test_standing_flush_against_the_side_of_spikes_does_not_hurt() -> None:
    assert not hurt_in(level_from_ascii(SPIKE_ON_THE_FLOOR, spawn=Box(36, 18, 12, 14)))
    assert not hurt_in(level_from_ascii(SPIKE_ON_THE_FLOOR, spawn=Box(64, 18, 12, 14)))


def test_standing_half_a_pixel_into_spikes_hurts() -> None:
    assert hurt_in(level_from_ascii(SPIKE_ON_THE_FLOOR, spawn=Box(36.5, 18, 12, 14)), 1)
    assert hurt_in(level_from_ascii(SPIKE_ON_THE_FLOOR, spawn=Box(63.5, 18, 12, 14)), 1)


def test_standing_on_a_floor_beside_spikes_level_with_it_does_not_hurt() -> None:
    # Half the feet over the spikes, on their top: the floor holds him, the spikes only touch.
    level = level_from_ascii(["      ", "      ", "##^^##"], spawn=Box(26, 18, 12, 14))
    assert not hurt_in(level)


def test_standing_under_spikes_that_touch_the_head_does_not_hurt() -> None:
    level = level_from_boxes(6, 4, [Box(0, 3 * T, 6 * T, T)], Box(36, 3 * T - 14, 12, 14), [],
                             hazards=(Box(32, 3 * T - 14 - 8, 16, 8),))
    assert not hurt_in(level)
    sunk = level_from_boxes(6, 4, [Box(0, 3 * T, 6 * T, T)], Box(36, 3 * T - 14, 12, 14), [],
                            hazards=(Box(32, 3 * T - 14 - 7.5, 16, 8),))
    assert hurt_in(sunk, 1)


# --- A lift carries its rider up, down and sideways, feet on its top every tick ------------

def riding_a_lift(rise: float, across: float, speed: float) -> World:
    """The player standing on a platform (48x8) whose route climbs ``rise`` px (down first
    when negative) and goes ``across`` px sideways, at ``speed`` px/s."""
    top = 40.0 * T / 2
    level = level_from_ascii([" " * 60] * 40, spawn=Box(120, top - 14, 12, 14))
    route = Route(((100.0, top), (100.0 + across, top - rise)))
    return World(replace(level, platforms=(PlatformSpec(route, 48, 8, speed),)))


@given(rise=st.floats(-300, 300).filter(lambda v: abs(v) >= 1),
       across=st.sampled_from([0.0, 0.0, 37.5, -120.0]), speed=st.floats(20, 180))
@example(rise=-200.0, across=0.0, speed=60.0)    # down first, then up
@example(rise=200.0, across=0.0, speed=60.0)     # up first, then down
@example(rise=-100.0, across=100.0, speed=90.0)  # down and sideways
@settings(max_examples=25, deadline=None)
def test_a_lift_carries_its_rider_up_down_and_sideways_with_the_feet_on_its_top(
        rise: float, across: float, speed: float) -> None:
    world = riding_a_lift(rise, across, speed)
    lift = next(iter(world.platforms))
    player = world.player
    offset = player.box.x - lift.box.x
    for _ in range(math.floor(2 * lift.spec.path.length / speed * 60)):   # there and back
        world.step(NOTHING)
        assert player.box.bottom == lift.box.top
        assert player.on_ground and player.riding is lift
        assert player.box.x - lift.box.x == pytest.approx(offset, abs=1e-9)


def test_a_lift_going_down_carries_its_rider_on_the_first_tick() -> None:
    world = riding_a_lift(-200.0, 0.0, 60.0)
    lift = next(iter(world.platforms))
    world.step(NOTHING)
    assert lift.box.top == 321 and world.player.box.bottom == 321 and world.player.on_ground


# --- A tie of faces: where a Solid and a OneWay top meet at one height, the Solid wins -----

def floor_of(kinds: tuple[TileKind, ...]) -> TileGrid:
    """A row of tiles, one of each kind in order from x = 64, their tops at y = 64."""
    grid = TileGrid(cols=10, rows=6, tile_w=T, tile_h=T)
    for n, kind in enumerate(kinds):
        grid.put(4 + n, 4, TileShape(Box((4 + n) * T, 4 * T, T, T), kind, 4 + n, 4))
    return grid


def one_cell_floor_of(kinds: tuple[TileKind, ...]) -> TileGrid:
    """Half-tile shapes side by side in the one cell (4, 4), in order, tops at y = 64."""
    grid = TileGrid(cols=10, rows=6, tile_w=T, tile_h=T)
    for n, kind in enumerate(kinds):
        grid.put(4, 4, TileShape(Box(4 * T + n * 8, 4 * T, 8, T), kind, 4, 4))
    return grid


STRADDLING = Box(74, 50, 12, 14)   # across x = 80: half on the first tile, half on the second
ACROSS_ONE_CELL = Box(66, 50, 12, 14)   # across x = 72, in cell (4, 4)


@pytest.mark.parametrize("grid, feet", [
    (floor_of((ONE_WAY, SOLID)), STRADDLING), (floor_of((SOLID, ONE_WAY)), STRADDLING),
    (one_cell_floor_of((ONE_WAY, SOLID)), ACROSS_ONE_CELL),
    (one_cell_floor_of((SOLID, ONE_WAY)), ACROSS_ONE_CELL)])
def test_the_ground_probe_and_a_landing_report_the_solid_on_a_tie_with_a_one_way(
        grid: TileGrid, feet: Box) -> None:
    under = ground_under(grid, feet)
    assert under is not None and under.kind is SOLID
    landing = move_y(grid, feet.moved(0, -10), 30.0)
    assert landing.hit is not None and landing.hit.shape is not None
    assert landing.box == feet and landing.hit.shape.kind is SOLID


@pytest.mark.parametrize("floor", ["----####", "####----"])
def test_a_player_half_on_a_solid_and_half_on_a_one_way_jumps_instead_of_dropping(
        floor: str) -> None:
    level = level_from_ascii(["        ", "        ", "        ", floor],
                             spawn=Box(58, 34, 12, 14))   # across x = 64, on y = 48
    world = World(level)
    world.step(NOTHING)
    assert world.player.on_ground and world.player.standing_on is not None
    assert world.player.standing_on.kind is SOLID
    events = world.step(DOWN_JUMP)
    assert any(event.kind is EventKind.JUMP for event in events)
    assert not world.player.dropping_through and world.player.vy < 0
