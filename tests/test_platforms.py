"""Moving platforms and checkpoints: carry, push, crush, never through a wall."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.sim import platforms
from game.sim.campaign import Campaign
from game.sim.inputs import NOTHING, Action
from game.sim.level import Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.solids import LevelSolids
from game.sim.tuning import Tuning
from game.sim.world import EventKind, Measure, World
from tests.maps import MEASURED, level_from_ascii

RIGHT = frozenset({Action.RIGHT})


def with_platform(rows: list[str], points: tuple[tuple[float, float], ...], speed: float,
                  spawn: Box | None = None, width: float = 48) -> Level:
    level = level_from_ascii(rows, spawn=spawn)
    spec = PlatformSpec(Route(points), width, 8, speed)
    return replace(level, platforms=(spec,))


OPEN = ["                        ",
        "                        ",
        "                        ",
        "                        ",
        "                        ",
        "                        ",
        "                        ",
        "                        ",
        "                        "]


def test_a_player_standing_on_a_platform_is_carried_along_with_it() -> None:
    level = with_platform(OPEN, ((32.0, 80.0), (232.0, 80.0)), speed=60.0,
                          spawn=Box(40, 66, 12, 14))
    world = World(level)
    world.step(NOTHING)
    assert world.player.riding is not None
    start_gap = world.player.box.x - next(iter(world.platforms)).box.x
    for _ in range(60):
        world.step(NOTHING)
        platform = next(iter(world.platforms))
        assert world.player.box.bottom == platform.box.top
        assert world.player.box.x - platform.box.x == start_gap
    assert world.player.box.x > 90


def test_a_platform_rising_under_the_player_lifts_it() -> None:
    level = with_platform(OPEN, ((32.0, 120.0), (32.0, 20.0)), speed=60.0,
                          spawn=Box(40, 100, 12, 14))
    world = World(level, measure=MEASURED)
    for _ in range(40):
        world.step(NOTHING)
    platform = next(iter(world.platforms))
    assert platform.box.top < 100
    assert world.player.box.bottom == platform.box.top and world.player.on_ground
    assert world.max_penetration_px == 0.0


def test_a_platform_pushes_a_player_in_its_way() -> None:
    level = with_platform(OPEN, ((0.0, 110.0), (300.0, 110.0)), speed=120.0,
                          spawn=Box(100, 100, 12, 14))
    world = World(level, Tuning(gravity_px_s2=0.0))
    for _ in range(30):
        world.step(NOTHING)
    platform = next(iter(world.platforms))
    assert world.player.box.left == platform.box.right       # pushed, flush, not inside


def test_a_platform_never_carries_a_rider_through_a_wall() -> None:
    rows = list(OPEN)
    rows[3] = "          #             "
    rows[4] = "          #             "
    level = with_platform(rows, ((32.0, 80.0), (300.0, 80.0)), speed=90.0,
                          spawn=Box(60, 66, 12, 14))
    world = World(level, measure=MEASURED)
    for _ in range(100):
        world.step(NOTHING)
        assert world.player.box.right <= 10 * 16 or world.player.box.left >= 11 * 16
    assert world.max_penetration_px == 0.0


def test_a_player_pushed_into_a_wall_by_a_platform_is_crushed() -> None:
    rows = ["       ", "       ", "  #    ", "  #    ", "  #    ", "       "]
    level = with_platform(rows, ((90.0, 40.0), (0.0, 40.0)), speed=60.0,
                          spawn=Box(50, 40, 12, 14), width=16)
    level = replace(level, platforms=(replace(level.platforms[0], height_px=32),))
    campaign = Campaign(Path("x.tmx"), Tuning(gravity_px_s2=0.0), loader=lambda _: level)
    for _ in range(60):
        campaign.tick(NOTHING)
        if campaign.deaths:
            break
    assert campaign.deaths == 1


def test_touching_a_checkpoint_moves_the_respawn_point_there() -> None:
    level = level_from_ascii(["                    ",
                              " P                  ",
                              "########   #########"])
    level = replace(level, checkpoints=(Box(64, 0, 16, 32),))
    campaign = Campaign(Path("x.tmx"), Tuning(), loader=lambda _: level)
    checkpoint_seen = False
    for _ in range(300):
        events = campaign.tick(RIGHT)
        checkpoint_seen |= any(e.kind is EventKind.CHECKPOINT for e in events)
        if campaign.deaths:
            break
    assert checkpoint_seen and campaign.deaths == 1
    player = campaign.world.player.box
    assert player.x >= 64 and player.right <= 80 and player.bottom == 32


WIDE = ["P" + " " * 199, *([" " * 200] * 8), "#" * 200]


def gliders(count: int) -> tuple[PlatformSpec, ...]:
    """``count`` platforms gliding over two tiles, far to the right of the player."""
    return tuple(PlatformSpec(Route(((800.0 + 20 * k, 32.0), (832.0 + 20 * k, 32.0))),
                              16, 8, 30.0) for k in range(count))


def test_a_hundred_far_platforms_add_no_lookup_work_to_a_tick() -> None:
    work = {}
    for count in (2, 100):
        world = World(replace(level_from_ascii(WIDE), platforms=gliders(count)),
                      measure=Measure(queries=True))   # the lookups' work is counted
        tested = []
        for tick in range(120):
            world.step(RIGHT if tick % 60 < 30 else NOTHING)
            tested.append((world.stats.cells_visited, world.stats.shapes_tested))
        work[count] = tested
    assert work[2] == work[100]
    assert all(cells > 0 for cells, _ in work[2])


def test_a_platform_nobody_is_near_is_where_its_route_puts_it_whenever_it_is_read() -> None:
    world = World(replace(level_from_ascii(WIDE), platforms=gliders(3)))
    for tick in range(1, 200):
        world.step(NOTHING)
        platform = list(world.platforms)[tick % 3]
        x, y = platform.spec.path.point_at(30.0 * tick / 60)
        assert platform.box == Box(x, y, 16, 8)
        assert platform.rect.topleft == (math.floor(x), math.floor(y))


def _two_flags_level(slime: bool) -> Level:
    """A floor with two checkpoints, and maybe a slime between them."""
    level = level_from_ascii(["                    ",
                              "                    ",
                              " P        " + ("E" if slime else " ") + "         ",
                              "####################"], spawn=Box(16, 34, 12, 14))
    return replace(level, checkpoints=(Box(96, 16, 16, 32), Box(224, 16, 16, 32)))


def test_a_checkpoint_jumped_over_still_counts_and_a_slime_sends_the_player_back_to_it(
        ) -> None:
    level = _two_flags_level(slime=True)
    world = World(level, replace(Tuning(), enemy_speed_px_s=0.0))
    world.player.teleport(Box(40, 34, 12, 14))     # on the floor, running right
    counted_at = []
    for tick in range(300):   # a jump held from tick 16 to 35 clears the flag, touching nothing
        events = world.step(RIGHT | {Action.JUMP} if 16 <= tick < 36 else RIGHT)
        counted_at += [world.player.box for e in events if e.kind is EventKind.CHECKPOINT]
        if any(e.kind is EventKind.HURT for e in events):
            break
    assert len(counted_at) == 1 and counted_at[0].bottom < level.checkpoints[0].top
    assert world.player.box.x >= 96 and world.player.box.right <= 112   # back at that flag


def test_walking_back_past_an_earlier_flag_keeps_the_later_respawn_point() -> None:
    world = World(_two_flags_level(slime=False), Tuning())
    counted = []
    for held in (RIGHT, frozenset({Action.LEFT})):
        for _ in range(200):
            counted += [e.value for e in world.step(held) if e.kind is EventKind.CHECKPOINT]
            if held is RIGHT and world.player.box.x > 250:
                break
    assert counted == [0, 1] and world.checkpoint_reached == 1
    assert world.player.box.x < 96                     # walked back past the first flag
    assert world.spawn.x >= 224


def _flags_counted_walking_right(flag: Box) -> list[int]:
    """Walk right along the floor of the two-flag level, under or through ``flag`` (the
    only flag); the flags counted on the way."""
    level = replace(_two_flags_level(slime=False), checkpoints=(flag,))
    world = World(level, Tuning())
    counted: list[int] = []
    for _ in range(120):
        counted += [e.value for e in world.step(RIGHT) if e.kind is EventKind.CHECKPOINT]
    assert world.player.box.x > flag.right and world.player.box.top == 34  # walked past it
    return counted


def test_walking_under_a_flag_high_above_the_floor_does_not_count_it() -> None:
    assert _flags_counted_walking_right(Box(96, -200, 16, 32)) == []


def test_a_flag_counts_only_when_the_path_passes_within_its_height() -> None:
    # The player walks with its top at y = 34: a flag ending exactly there only touches the
    # path (outside), one ending half a pixel lower overlaps it (just inside).
    assert _flags_counted_walking_right(Box(96, 2, 16, 32)) == []
    assert _flags_counted_walking_right(Box(96, 2.5, 16, 32)) == [0]


def test_a_flag_far_below_the_path_does_not_count_and_one_within_its_height_does() -> None:
    # The player walks with its bottom at y = 48. Passing over a flag counts while the feet
    # are no more than the flag's height (32 px) above its top: a flag whose top is 80 px
    # down is exactly that far (outside), one whose top is half a pixel higher is inside.
    assert _flags_counted_walking_right(Box(96, 80.5, 16, 32)) == []
    assert _flags_counted_walking_right(Box(96, 79.5, 16, 32)) == [0]
    assert _flags_counted_walking_right(Box(96, 400, 16, 32)) == []   # buried far below


@given(st.floats(-40, 700), st.floats(-40, 200), st.floats(0.5, 120), st.floats(0.5, 120))
@settings(max_examples=300, deadline=None)
def test_a_few_platforms_are_found_by_their_routes_as_the_cells_would_find_them(
        x: float, y: float, w: float, h: float) -> None:
    world = World(replace(level_from_ascii(WIDE), platforms=(
        *gliders(2), PlatformSpec(Route(((40.0, 20.0), (40.0, 100.0))), 16, 8, 30.0))))
    index = world.platform_index
    by_routes = index.tested_in(x, y, x + w, y + h)
    box = Box(x, y, w, h)
    near_by_routes = index.near([box])
    assert index.routes_touching(x, y, x + w, y + h) == index.cells_touching(x, y, x + w, y + h)
    solids = [LevelSolids(world.grid, index, without) for without in (None, *world.platforms)]
    found_by_routes = [source.entries_in(x, y, x + w, y + h) for source in solids]
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(platforms, "FEW_PLATFORMS", 0)   # every query walks the cells
        assert index.tested_in(x, y, x + w, y + h) == by_routes
        assert index.near([box]) == near_by_routes
        walked = [LevelSolids(world.grid, index, s.without) for s in solids]
        assert [source.entries_in(x, y, x + w, y + h) for source in walked] == found_by_routes


FLOOR_Y = 144.0  # the top of the floor of :func:`wall_sliding_along_the_floor`


def wall_sliding_along_the_floor(length: float, speed: float, start: float, gap: float,
                                 leftwards: bool) -> World:
    """A wall (a platform 16 px wide, 64 tall) standing on a flat floor with a route of
    ``length`` px starting at x = ``start`` (rightwards) or ending there (leftwards), and a
    player standing on the floor ``gap`` px ahead of it, with room to be pushed all the way."""
    cols = math.ceil((start + length + 16 + 12 + 16) / 16) + 1
    level = level_from_ascii([" " * cols] * 9 + ["#" * cols],
                             spawn=Box(0, FLOOR_Y - 14, 12, 14))
    near, end = (start, start + length) if not leftwards else (start + length, start)
    spec = PlatformSpec(Route(((near, FLOOR_Y - 64), (end, FLOOR_Y - 64))), 16, 64, speed)
    world = World(replace(level, platforms=(spec,)))
    x = near + 16 + gap if not leftwards else near - gap - 12
    world.player.teleport(Box(x, FLOOR_Y - 14, 12, 14))
    return world


@given(length=st.floats(16, 600), speed=st.floats(30, 240), start=st.floats(12, 100),
       ahead=st.floats(0, 0.9), leftwards=st.booleans())
@example(length=360.0, speed=30.0, start=0.0, ahead=24 / 360, leftwards=False)
@example(length=360.0, speed=120.0, start=0.0, ahead=24 / 360, leftwards=False)
@example(length=300.0, speed=75.0, start=16.0, ahead=0.0, leftwards=True)
@settings(max_examples=40, deadline=None)
def test_a_wall_pushing_a_standing_player_with_room_along_the_floor_never_crushes_him(
        length: float, speed: float, start: float, ahead: float, leftwards: bool) -> None:
    """The player starts ``ahead`` of the way along the route in front of the wall."""
    world = wall_sliding_along_the_floor(length, speed, start, ahead * length, leftwards)
    wall = next(iter(world.platforms))
    for _ in range(math.floor(length / speed * 60)):   # one trip, not yet turning back
        events = world.step(NOTHING)
        assert not world.player.crushed
        assert not any(event.kind is EventKind.HURT for event in events)
        assert not world.player.box.overlaps(wall.box)
    player = world.player.box
    if wall.travelled_px > ahead * length:   # pushed: flush against the wall's face
        assert (player.left == wall.box.right if not leftwards
                else player.right <= wall.box.left < player.right + 1e-9)
    assert player.bottom == FLOOR_Y and world.player.on_ground
