"""Whole ticks of a level: standing, running, stomping, coins, hazards, the void, the exit."""

from __future__ import annotations

import itertools
import math
from dataclasses import replace
from pathlib import Path
from typing import Any

import pytest

from game.collision.aabb import Box
from game.sim.campaign import Campaign, Outcome
from game.sim.enemy import Squashed
from game.sim.fixed_step import FixedStep
from game.sim.inputs import NOTHING, Action
from game.sim.tuning import Tuning
from game.sim.world import EventKind, Measure, World
from tests.maps import MEASURED, level_from_ascii

RIGHT = frozenset({Action.RIGHT})
LEFT = frozenset({Action.LEFT})
JUMP = frozenset({Action.JUMP})
# Full run speed from the first tick: these tests are about collision, not acceleration.
INSTANT = Tuning(run_accel_time_s=0, run_stop_time_s=0, air_accel_time_s=0, air_stop_time_s=0)

FLAT = [
    "                    ",
    "                    ",
    "  P                 ",
    "####################",
]


def test_standing_for_600_ticks_never_moves_a_pixel_or_leaves_the_ground() -> None:
    world = World(level_from_ascii(FLAT), measure=MEASURED)
    for _ in range(5):
        world.step(NOTHING)  # fall the few pixels onto the floor
    resting = world.player.box
    for _ in range(600):
        world.step(NOTHING)
        assert world.player.box == resting
        assert world.player.rect.topleft == (resting.x, resting.y)
        assert world.player.on_ground
    assert world.max_penetration_px == 0.0


def test_running_across_the_floor_seams_never_stops() -> None:
    world = World(level_from_ascii(FLAT), replace(INSTANT, run_speed_px_s=60.0))
    for _ in range(10):
        world.step(NOTHING)
    xs = []
    for _ in range(200):
        world.step(RIGHT)
        xs.append(world.player.box.x)
        if world.player.box.right >= world.grid.width_px:
            break
        assert world.player.vx == 60.0 and world.player.on_ground
    assert all(b > a for a, b in itertools.pairwise(xs))


@pytest.mark.parametrize("action", [RIGHT, LEFT])
def test_a_tenth_of_a_pixel_per_tick_moves_the_player(action: frozenset[Action]) -> None:
    world = World(level_from_ascii(["          ", "    P     ", "##########"]),
                  replace(INSTANT, run_speed_px_s=6.0))          # 0.1 px per tick
    for _ in range(5):
        world.step(NOTHING)
    start = world.player.box.x
    for _ in range(600):
        world.step(action)
    sign = 1 if action == RIGHT else -1
    assert world.player.box.x == pytest.approx(start + sign * 60.0)
    assert world.player.rect.x == math.floor(world.player.box.x)


def test_landing_on_an_enemy_from_above_stomps_it_and_bounces() -> None:
    level = level_from_ascii([
        "   P    ",
        "        ",
        "        ",
        "   E    ",
        "########",
    ])
    world = World(level, replace(INSTANT, enemy_speed_px_s=0.0))
    events = []
    for _ in range(60):
        events += world.step(NOTHING)
        if any(e.kind is EventKind.STOMP for e in events):
            break
    assert [e.kind for e in events].count(EventKind.STOMP) == 1
    assert len(world.enemies) == 0
    assert world.player.vy < 0                      # bounced
    assert not any(e.kind is EventKind.HURT for e in events)


def test_walking_into_an_enemy_from_the_side_costs_a_life() -> None:
    level = level_from_ascii([
        "          ",
        " P    E   ",
        "##########",
    ])
    campaign = Campaign(Path("x.tmx"), replace(INSTANT, enemy_speed_px_s=0.0),
                        loader=lambda _: level)
    for _ in range(120):
        campaign.tick(RIGHT)
        if campaign.deaths:
            break
    assert campaign.deaths == 1 and campaign.lives == 2
    assert campaign.enemies_stomped == 0
    assert len(campaign.world.enemies) == 1
    assert campaign.world.player.box.x == level.spawn.x   # back at the spawn


TWO_COINS = level_from_ascii([
    "      ",
    " P CC ",
    "######",
], spawn=Box(16, 18, 12, 14))


def two_coins_at_one_tick_of_running() -> Campaign:
    """A campaign whose first tick of running right (40 px) passes over both its coins."""
    return Campaign(Path("x.tmx"), replace(INSTANT, run_speed_px_s=60 * 40.0),
                    loader=lambda _: TWO_COINS)


def test_two_coins_touched_in_one_tick_are_both_counted() -> None:
    campaign = two_coins_at_one_tick_of_running()
    campaign.tick(RIGHT)             # 40 px in one tick: over both coins at once
    assert campaign.coins_collected == 2
    assert campaign.score == 2
    assert len(campaign.world.coins) == 0


def test_falling_out_of_the_map_costs_a_life_and_the_last_life_ends_the_game() -> None:
    level = level_from_ascii(["P  ", "   ", "   "])
    campaign = Campaign(Path("x.tmx"), loader=lambda _: level)
    for _ in range(2000):
        campaign.tick(NOTHING)
        if campaign.outcome is not Outcome.RUNNING:
            break
    assert campaign.outcome is Outcome.GAME_OVER
    assert campaign.deaths == 3 and campaign.lives == 0


def test_retrying_after_game_over_plays_the_same_level_again_with_full_lives() -> None:
    level = level_from_ascii(["P  ", "   ", "   "])
    campaign = Campaign(Path("x.tmx"), loader=lambda _: level)
    while campaign.outcome is Outcome.RUNNING:
        campaign.tick(NOTHING)
    lost = campaign.world
    campaign.retry_level()
    assert campaign.outcome.value == Outcome.RUNNING.value  # (mypy narrowed it above)
    assert campaign.lives == campaign.tuning.start_lives and campaign.deaths == 3
    assert campaign.world is not lost and campaign.world.level is level
    assert campaign.world.player.box == campaign.world.spawn
    assert campaign.tick(NOTHING) == []  # the run goes on


def test_touching_a_hazard_costs_a_life() -> None:
    level = level_from_ascii(["     ", " P ^ ", "#####"])
    campaign = Campaign(Path("x.tmx"), loader=lambda _: level)
    for _ in range(100):
        campaign.tick(RIGHT)
        if campaign.deaths:
            break
    assert campaign.deaths == 1


def test_the_exit_completes_the_level_and_the_last_one_wins() -> None:
    first = level_from_ascii(["       ", " P   D ", "#######"])
    first = replace(first, next_level=Path("second.tmx"))
    second = level_from_ascii(["       ", " P  D  ", "#######"])
    levels = {Path("first.tmx"): first, Path("second.tmx"): second}
    campaign = Campaign(Path("first.tmx"), loader=levels.__getitem__)
    for _ in range(600):
        campaign.tick(RIGHT)
        if campaign.outcome is not Outcome.RUNNING:
            break
    assert campaign.levels_completed == 2
    assert campaign.outcome is Outcome.WON


def test_x_is_resolved_before_y_on_an_outer_corner_hit() -> None:
    # Moving down-right by the same amount on both axes into a block's top-left corner:
    # the x pass runs first with the body still above the block, so x goes the whole way;
    # then the y pass lands it on the block's top. Same result every run.
    # Corner of the body at (22, 24), corner of the block at (32, 32), a 12 px step on each
    # axis. y first would instead have stopped the body against the block's side.
    level = level_from_ascii(["P     ", "      ", "  ##  ", "######"],
                             spawn=Box(10, 10, 12, 14))
    world = World(level, replace(INSTANT, run_speed_px_s=720.0, gravity_px_s2=0.0,
                                max_fall_speed_px_s=720.0))
    world.player.vy = 720.0
    world.step(RIGHT)
    assert world.player.box.x == 22.0
    assert world.player.box.bottom == 32.0
    assert world.player.on_ground


def test_a_jump_leaves_the_ground_and_lands_again_flush() -> None:
    world = World(level_from_ascii(FLAT))
    for _ in range(5):
        world.step(NOTHING)
    floor_y = world.player.box.y
    world.step(JUMP)
    assert not world.player.on_ground and world.player.vy < 0
    highest = floor_y
    for _ in range(120):
        world.step(JUMP)
        highest = min(highest, world.player.box.y)
    assert world.player.box.y == floor_y and world.player.on_ground
    assert floor_y - highest > 16


def test_map_physics_properties_are_honoured_however_large() -> None:
    props: dict[str, object] = {"gravity": 1e7, "max_fall_speed": 9 * 16 * 60.0,
                                "run_speed": 9 * 16 * 60.0, "jump_speed": 1.0}
    level = level_from_ascii([
        "P                              ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                               ",
        "                              #",
        "###############################",
    ], props)
    world = World(level, INSTANT, measure=MEASURED)
    assert world.tuning.gravity_px_s2 == 1e7
    world.step(NOTHING)   # 9 tiles in one tick: lands flush on the floor at y = 176
    world.step(NOTHING)
    assert world.player.box.bottom == 11 * 16 and world.player.on_ground
    world.step(RIGHT)
    world.step(RIGHT)
    world.step(RIGHT)
    world.step(RIGHT)
    assert world.player.box.right == 30 * 16          # flush against the one-tile wall
    assert world.max_penetration_px == 0.0


def test_a_five_second_stall_runs_a_capped_number_of_ticks_and_passes_no_wall() -> None:
    world = World(level_from_ascii(["        ", "P    #  ", "########"]),
                  replace(INSTANT, run_speed_px_s=3000.0), measure=MEASURED)
    clock = FixedStep()
    ticks = clock.advance(5.0)
    assert ticks == clock.max_ticks_per_frame
    for _ in range(ticks):
        world.step(RIGHT)
    assert world.player.box.right == 5 * 16
    assert world.max_penetration_px == 0.0
    assert clock.advance(1 / 60) == 1           # the backlog was dropped, not replayed


@pytest.mark.parametrize("frame_s", [0.0, -1.0, float("nan")])
def test_frames_of_zero_or_negative_time_run_no_ticks(frame_s: float) -> None:
    assert FixedStep().advance(frame_s) == 0


def test_enemies_turn_at_walls_and_ledges() -> None:
    level = level_from_ascii([
        "P               ",
        "                ",
        "      E    #    ",
        "   #########    ",
        "                ",
    ])
    world = World(level, replace(INSTANT, enemy_speed_px_s=120.0))
    enemy = next(iter(world.enemies))
    xs = []
    for _ in range(400):
        world.step(NOTHING)
        xs.append(enemy.box.x)
    assert min(xs) >= 3 * 16 - 1e-9            # never walked off the left ledge
    assert max(xs) + enemy.box.w <= 11 * 16     # never walked into the wall on the right
    assert min(xs) < 4 * 16 and max(xs) > 9 * 16   # but did patrol the whole floor


def test_a_hopper_patrols_in_hops_and_rests_between_them() -> None:
    level = level_from_ascii([
        "P                   ",
        "                    ",
        "                    ",
        "          E         ",
        "####################",
    ])
    spec = level.enemies[0]
    level = replace(level, enemies=(replace(spec, kind="hopper"),))
    world = World(level, replace(INSTANT, enemy_speed_px_s=60.0), measure=MEASURED)
    hopper = next(iter(world.enemies))
    airborne, xs_on_ground = 0, set()
    for _ in range(300):
        world.step(NOTHING)
        if hopper.on_ground:
            xs_on_ground.add(hopper.box.x)
        else:
            airborne += 1
    assert airborne > 60                          # it spends real time in the air
    assert len(xs_on_ground) > 2                  # and lands somewhere new each hop
    assert world.max_penetration_px == 0.0


def test_a_body_flung_at_absurd_speeds_keeps_a_rect_pygame_can_hold() -> None:
    props: dict[str, object] = {"gravity": 1e15, "max_fall_speed": 1e14, "jump_speed": 1e14}
    level = level_from_ascii(["P   ", "    ", "####"], props)
    campaign = Campaign(Path("x.tmx"), INSTANT, loader=lambda _: level, measure=MEASURED)
    for tick in range(20):
        campaign.tick(JUMP if tick % 4 == 0 else NOTHING)
        assert campaign.world.player.box.is_finite()
    assert campaign.world.max_penetration_px == 0.0


def test_a_player_spawned_inside_a_wall_is_pushed_out_to_the_nearest_free_place() -> None:
    level = level_from_ascii(["        ", "   ##   ", "   ##   ", "########"],
                             spawn=Box(66, 20, 12, 14))   # 2 px in from the block's right
    world = World(level, INSTANT, measure=MEASURED)
    assert world.player.box == Box(80, 20, 12, 14)        # out through the nearest face
    assert world.max_penetration_px == 0.0
    world.step(NOTHING)
    assert world.max_penetration_px == 0.0


def test_a_respawn_uses_the_freed_spawn_too() -> None:
    level = level_from_ascii(["P       ", "#       ", "        "], spawn=Box(2, 10, 12, 14))
    campaign = Campaign(Path("x.tmx"), INSTANT, loader=lambda _: level)
    free_spawn = campaign.world.player.box
    assert free_spawn.bottom == 16
    while not campaign.deaths:
        campaign.tick(RIGHT)
    assert campaign.world.player.box == free_spawn


def test_a_diagonal_move_into_an_inner_corner_ends_flush_against_both_faces() -> None:
    level = level_from_ascii(["P      ", "      #", "      #", "#######"],
                             spawn=Box(60, 10, 12, 14))
    world = World(level, replace(INSTANT, run_speed_px_s=3000.0, gravity_px_s2=0.0,
                                 max_fall_speed_px_s=3000.0), measure=MEASURED)
    world.player.vy = 3000.0
    world.step(RIGHT)
    assert world.player.box.right == 6 * 16 and world.player.box.bottom == 3 * 16
    assert world.player.on_ground and world.max_penetration_px == 0.0


def test_a_stomp_scores_its_points_and_each_finished_level_leaves_its_tally() -> None:
    level = level_from_ascii([
        "   P    ",
        "        ",
        "  C     ",
        "   E   D",
        "########",
    ])
    tuning = replace(INSTANT, enemy_speed_px_s=0.0, stomp_points=7)
    campaign = Campaign(Path("x.tmx"), tuning, loader=lambda _: level)
    while campaign.enemies_stomped == 0:
        campaign.tick(NOTHING)
        assert campaign.ticks < 120, "the drop never stomped the enemy"
    assert campaign.score == 7 and campaign.coins_collected == 0
    while campaign.outcome is Outcome.RUNNING:
        campaign.tick(RIGHT)
        assert campaign.ticks < 600, "the walk never reached the exit"
    [result] = campaign.results
    assert (result.coins, result.coins_total, result.stomps, result.enemies_total) == (0, 1, 1, 1)
    assert result.ticks == campaign.ticks and result.score == campaign.score == 7


def test_enemies_falling_into_the_void_in_the_same_tick_all_leave_play() -> None:
    level = level_from_ascii([
        "  EEEE",
        "      ",
        "      ",
        "P     ",
        "#     ",
    ])
    world = World(level, replace(INSTANT, enemy_speed_px_s=0.0))
    for _ in range(120):
        world.step(NOTHING)
        if len(world.enemies) < 4:
            break
    assert len(world.enemies) == 0   # all in that tick, not one in two as a list loop leaves


def test_stomped_enemies_that_fade_in_the_same_tick_all_leave_the_screen() -> None:
    world = World(level_from_ascii(["P     ", "######"]))
    for x in range(4):
        world.squashed.add(Squashed(Box(x * 16.0, 0.0, 14, 12), ticks=3))
    for _ in range(3):
        world.step(NOTHING)
    assert len(world.squashed) == 0


def test_penetration_is_measured_only_when_asked_and_then_catches_a_body_left_in_a_wall(
        ) -> None:
    level = level_from_ascii(["      ", "  P   ", "######"])
    sunk = Box(32, 24, 12, 14)  # feet 6 px below the floor's top: no sweep can undo that
    deepest: dict[str, float] = {}
    for name, measure in (("measured", MEASURED), ("unmeasured", Measure())):
        world = World(level, INSTANT, measure=measure)
        world.player.teleport(sunk)
        world.step(NOTHING)
        deepest[name] = world.max_penetration_px
    assert deepest["measured"] >= 6.0
    assert deepest["unmeasured"] == 0.0  # nothing asked for it, so nothing was measured


def test_a_run_that_writes_a_report_measures_penetration_and_one_that_does_not_skips_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from game.app import run as runner
    from game.app.cli import parser

    made: list[Campaign] = []

    class Recorded(Campaign):
        def __init__(self, *args: Any, **kwargs: Any) -> None:
            super().__init__(*args, **kwargs)
            made.append(self)

    monkeypatch.setattr(runner, "Campaign", Recorded)
    for extra in ([], ["--report", str(tmp_path / "report.json")]):
        args = parser().parse_args(["--headless", "--ticks", "2", *extra])
        assert runner.run(args, lambda _: 0) == runner.EXIT_OK
    assert [c.measure.penetration for c in made] == [False, True]


@pytest.mark.parametrize("again", ["restart", "reload"])
def test_a_restart_or_a_reload_takes_back_what_the_level_had_counted(again: str) -> None:
    campaign = two_coins_at_one_tick_of_running()
    campaign.tick(RIGHT)             # both coins in one tick
    assert (campaign.coins_collected, campaign.score, campaign.level_coins) == (2, 2, 2)
    if again == "restart":
        campaign.restart_level()
    else:
        campaign.reload(TWO_COINS)
    assert len(campaign.world.coins) == 2          # back in play...
    assert (campaign.coins_collected, campaign.score, campaign.level_coins) == (0, 0, 0)
    campaign.restart_level()                      # from the spawn, over both again
    campaign.tick(RIGHT)
    assert campaign.coins_collected == 2          # ...and counted once, not twice
