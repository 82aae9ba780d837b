"""Game feel: each forgiving rule of the player's movement, pinned by the case it promises."""

from __future__ import annotations

from pathlib import Path

from game.sim.campaign import Campaign
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.maps import (
    LEDGE,
    ONE_WAY_SHELF,
    jump_pressed_before_landing,
    jump_under_the_ceiling_from,
    level_from_ascii,
    settled,
)

RIGHT: Actions = frozenset({Action.RIGHT})
JUMP: Actions = frozenset({Action.JUMP})
RIGHT_JUMP: Actions = frozenset({Action.RIGHT, Action.JUMP})
DOWN_JUMP: Actions = frozenset({Action.DOWN, Action.JUMP})
TUNING = Tuning()


FLOOR = ["                              ",
         "                              ",
         "                              ",
         "                              ",
         "                              ",
         "  P                           ",
         "##############################"]


def test_running_speeds_up_over_the_acceleration_time_then_holds() -> None:
    world = settled(FLOOR)
    speeds = []
    for _ in range(6):
        world.step(RIGHT)
        speeds.append(world.player.vx)
    ramp = round(TUNING.run_accel_time_s / TUNING.tick_s)
    assert speeds[0] == TUNING.run_speed_px_s / ramp
    assert speeds[ramp - 1] == TUNING.run_speed_px_s
    assert speeds[ramp:] == [TUNING.run_speed_px_s] * (6 - ramp)


def test_letting_go_stops_quicker_on_the_ground_than_in_the_air() -> None:
    world = settled(FLOOR)
    for _ in range(10):
        world.step(RIGHT)
    ground_ticks = 0
    while world.player.vx > 0:
        world.step(NOTHING)
        ground_ticks += 1
    world = settled(FLOOR)
    for _ in range(10):
        world.step(RIGHT)
    world.step(RIGHT_JUMP)
    air_ticks = 0
    while world.player.vx > 0:
        world.step(JUMP)
        air_ticks += 1
    assert not world.player.on_ground
    assert ground_ticks == round(TUNING.run_stop_time_s / TUNING.tick_s)
    assert air_ticks == round(TUNING.air_stop_time_s / TUNING.tick_s)


def apex_after_holding_jump_for(ticks: int) -> float:
    world = settled(FLOOR)
    floor_y = world.player.box.y
    highest = floor_y
    for tick in range(80):
        world.step(JUMP if tick < ticks else NOTHING)
        highest = min(highest, world.player.box.y)
    return floor_y - highest


def test_releasing_jump_early_gives_a_lower_apex_than_holding_it() -> None:
    short, full = apex_after_holding_jump_for(4), apex_after_holding_jump_for(60)
    assert short < full * 0.6
    assert full > 2 * 16                      # a held jump clears two tiles


def ticks_after_leaving_ledge_then_jump(delay: int) -> bool:
    """Run off the ledge, press jump ``delay`` ticks after the feet left it: did it jump?"""
    world = settled(LEDGE)
    while world.player.on_ground:
        world.step(RIGHT)
    for _ in range(delay - 1):
        world.step(RIGHT)
    events = world.step(RIGHT_JUMP)
    return any(e.kind is EventKind.JUMP for e in events)


def test_a_jump_pressed_5_ticks_after_running_off_a_ledge_still_happens() -> None:
    assert ticks_after_leaving_ledge_then_jump(5)


def test_a_jump_pressed_long_after_leaving_a_ledge_does_not_happen() -> None:
    assert not ticks_after_leaving_ledge_then_jump(TUNING.coyote_ticks + 2)


def test_a_jump_pressed_5_ticks_before_landing_happens_on_landing() -> None:
    assert jump_pressed_before_landing(5)[0]


def test_a_jump_pressed_long_before_landing_is_forgotten() -> None:
    assert not jump_pressed_before_landing(TUNING.jump_buffer_ticks + 3)[0]


def rise_under_ceiling_corner(overlap_px: float) -> tuple[World, float]:
    """Jump straight up with the head overlapping the ceiling's left corner by ``overlap_px``.

    Returns the world after the jump and the highest the head got.
    """
    return jump_under_the_ceiling_from(5 * 16 - 12 + overlap_px)


def test_a_jump_that_clips_a_ceiling_corner_by_3_px_slides_past_it() -> None:
    world, highest = rise_under_ceiling_corner(3)
    assert world.player.box.right == 5 * 16       # slid 3 px left, clear of the corner
    assert highest < 3 * 16                       # and rose past the ceiling's underside
    assert world.max_penetration_px == 0.0


def test_a_jump_that_hits_a_ceiling_squarely_bumps_its_head() -> None:
    world, highest = rise_under_ceiling_corner(6)
    assert highest == 3 * 16                      # stopped flush under the ceiling
    assert world.player.box.right == 5 * 16 - 12 + 6 + 12


def test_falling_never_exceeds_terminal_velocity() -> None:
    world = World(level_from_ascii(["P"] + [" "] * 60), TUNING)
    speeds = []
    for _ in range(120):
        world.step(NOTHING)
        speeds.append(world.player.vy)
    assert max(speeds) == TUNING.max_fall_speed_px_s


def test_down_and_jump_on_a_one_way_platform_drops_through_it() -> None:
    world = settled(ONE_WAY_SHELF)
    assert world.player.box.bottom == 3 * 16
    world.step(DOWN_JUMP)
    for _ in range(40):
        world.step(NOTHING)
    assert world.player.box.bottom == 6 * 16 and world.player.on_ground


def test_jump_alone_on_a_one_way_platform_jumps_up() -> None:
    world = settled(ONE_WAY_SHELF)
    events = world.step(JUMP)
    assert any(e.kind is EventKind.JUMP for e in events)
    assert world.player.vy < 0


def test_after_a_hit_the_player_cannot_be_hurt_again_for_a_moment() -> None:
    level = level_from_ascii(["           ", " P E       ", "###########"])
    campaign = Campaign(Path("x.tmx"), Tuning(enemy_speed_px_s=0.0), loader=lambda _: level)
    while not campaign.deaths:
        campaign.tick(RIGHT)
    for _ in range(20):                   # walk back into the enemy and stay there
        campaign.tick(RIGHT)
    for _ in range(TUNING.invulnerable_ticks - 22):
        campaign.tick(NOTHING)
    assert campaign.world.player.box.overlaps(next(iter(campaign.world.enemies)).box)
    assert campaign.deaths == 1           # touching the enemy, but still invulnerable
    for _ in range(4):
        campaign.tick(NOTHING)
    assert campaign.deaths == 2
