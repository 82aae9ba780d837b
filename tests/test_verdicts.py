"""The checker's verdicts on maps whose truth is known by construction: gaps and ledges at and
past the player's measured limits, a drop through a one-way floor, a ferry over a pit, sealed
caves and caves sealed only by physics. No verdict may be wrong: a winnable map is never
called impossible, an unwinnable one never solved."""

from __future__ import annotations

import pytest

from game.collision.aabb import Box
from game.levels.reach import DEFAULT_LIMITS
from game.levels.reachable import jump_rise, open_path, reachable
from game.levels.solver import Effort
from game.levels.verdict import Kind, judge
from game.sim.level import Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.maps import level_from_boxes

COLS, ROWS, TILE = 40, 14, 16
WIDTH, FLOOR = COLS * TILE, 10 * TILE  # the floor's top
EDGE = 12 * TILE  # where a gap or a ledge begins
SPAWN = Box(32, FLOOR - 14, 12, 14)
EFFORT = Effort(budget=4_000)  # small: these maps are short, and an undecided is honest


def exit_on(top: float) -> Box:
    return Box(WIDTH - 48, top - 16, 16, 16)


def gap(width_px: int) -> Level:
    """Flat ground with a pit ``width_px`` wide; the pit's floor is the void below."""
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(EDGE + width_px, FLOOR, WIDTH - EDGE - width_px,
                                             64)], SPAWN, [exit_on(FLOOR)])


def ledge(height_px: int) -> Level:
    """Flat ground, then a step up ``height_px`` high with the Exit well back on it."""
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64),
                                         Box(EDGE, FLOOR - height_px, WIDTH - EDGE, height_px)],
                            SPAWN, [exit_on(FLOOR - height_px)])


def sealed_cave() -> Level:
    """The Exit inside a box of solid walls."""
    room = exit_on(FLOOR)
    walls = [Box(0, FLOOR, WIDTH, 64), Box(room.left - 32, FLOOR - 64, 16, 64),
             Box(room.right + 16, FLOOR - 64, 16, 64), Box(room.left - 32, FLOOR - 80, 80, 16)]
    return level_from_boxes(COLS, ROWS, walls, SPAWN, [room])


def drop_through() -> Level:
    """The spawn on a one-way shelf across the whole map; the Exit on the floor below."""
    shelf = Box(0, FLOOR - 64, WIDTH, 8)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64)],
                            Box(32, shelf.top - 14, 12, 14), [exit_on(FLOOR)],
                            one_ways=(shelf,))


def ferry() -> Level:
    """A pit ten tiles wide, crossed only on a platform that shuttles over it."""
    far = EDGE + 160
    ride = PlatformSpec(Route(((EDGE, FLOOR), (far - 48, FLOOR))), 48.0, 8.0, 40.0)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(far, FLOOR, WIDTH - far, 64)],
                            SPAWN, [exit_on(FLOOR)], platforms=(ride,))


WINNABLE = {
    "gap of 4 tiles": lambda: gap(64),
    "gap at the widest running jump": lambda: gap(DEFAULT_LIMITS.gap_px),
    "gap that needs a coyote jump": lambda: gap(DEFAULT_LIMITS.coyote_gap_px),
    "ledge of 2 tiles": lambda: ledge(32),
    "ledge at the highest jump": lambda: ledge(DEFAULT_LIMITS.ledge_px),
    "drop through a one-way floor": drop_through,
    "ferry over a pit": ferry,
}
UNWINNABLE = {
    "gap one pixel past the widest jump": lambda: gap(DEFAULT_LIMITS.coyote_gap_px + 1),
    "gap of 7 tiles": lambda: gap(112),
    "ledge one pixel over the highest jump": lambda: ledge(DEFAULT_LIMITS.ledge_px + 1),
    "ledge of 3 tiles": lambda: ledge(48),
    "sealed cave": sealed_cave,
}


@pytest.mark.parametrize("name", sorted(WINNABLE))
def test_a_winnable_map_is_never_called_impossible(name: str) -> None:
    verdict = judge(WINNABLE[name](), EFFORT)
    assert verdict.kind is not Kind.IMPOSSIBLE, verdict.finding


@pytest.mark.parametrize("name", sorted(UNWINNABLE))
def test_an_unwinnable_map_is_never_called_solved(name: str) -> None:
    verdict = judge(UNWINNABLE[name](), EFFORT)
    assert verdict.kind is not Kind.SOLVED, verdict.finding


@pytest.mark.parametrize("name", ["gap of 4 tiles", "ledge of 2 tiles",
                                  "drop through a one-way floor", "ferry over a pit",
                                  "gap at the widest running jump"])
def test_the_plain_winnable_maps_are_solved_by_a_route_that_replays(name: str) -> None:
    verdict = judge(WINNABLE[name](), EFFORT)  # solve() replays every route it returns
    assert verdict.kind is Kind.SOLVED, verdict.finding
    assert verdict.solution is not None and verdict.solution.found


@pytest.mark.parametrize("name", ["gap of 7 tiles", "ledge of 3 tiles", "sealed cave"])
def test_maps_far_past_the_reach_or_walled_off_are_proven_impossible(name: str) -> None:
    verdict = judge(UNWINNABLE[name](), EFFORT)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is None  # proven without a search
    assert verdict.tile is not None


def test_a_sealed_cave_is_blamed_on_the_walls_and_a_high_ledge_on_the_reach() -> None:
    sealed = judge(sealed_cave(), EFFORT)
    assert "no open path joins the spawn and an Exit" in sealed.finding
    high = judge(ledge(48), EFFORT)
    assert "outside everything the player's jumps can touch" in high.finding


def test_the_proof_of_impossibility_reaches_further_than_any_real_jump() -> None:
    """The fill's bound is the game's own jump: a ledge at the rise of a full jump is in
    the fill, one a pixel above the rise plus its rounding room is not."""
    rise = max(jump_rise(Tuning()))
    assert DEFAULT_LIMITS.ledge_px <= rise
    reach_in = reachable(World(ledge(DEFAULT_LIMITS.ledge_px)))
    assert reach_in is not None and reach_in.touches_exit
    reach_out = reachable(World(ledge(48)))
    assert reach_out is not None and not reach_out.touches_exit
    assert open_path(World(ledge(48))).touches_exit  # walls do not close it: physics does


def test_a_search_out_of_budget_is_not_decided_and_says_how_to_search_further() -> None:
    verdict = judge(gap(64), Effort(budget=5))
    assert verdict.kind is Kind.UNDECIDED
    assert "5 moves" in verdict.finding and "--budget" in verdict.advice
    assert verdict.tile is not None


def test_the_same_map_gets_the_same_verdict_and_work_every_time() -> None:
    first, second = judge(ferry(), EFFORT), judge(ferry(), EFFORT)
    assert first.kind is second.kind
    assert first.solution is not None and second.solution is not None
    assert first.solution.moves_tried == second.solution.moves_tried
    assert first.solution.script() == second.solution.script()
