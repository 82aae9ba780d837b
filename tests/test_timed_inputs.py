"""The solver's second stage and its budget: inputs timed to the tick where a map needs them
(a jump held for an exact number of ticks under spikes, a run lined up to the widest gap by a
hop), why no map needs the jump buffer itself, and a budget of moves that grows with the map
and is said when the search stops without a route."""

from __future__ import annotations

import dataclasses
import functools

import pytest

from game.checker.reach import DEFAULT_LIMITS
from game.checker.search_budget import MAX_BUDGET, MIN_BUDGET, MOVES_PER_CELL, map_budget
from game.checker.solver import (
    FIRST_PLAIN_SHARE,
    MOVE_TICKS,
    PLAIN_SHARE,
    Effort,
    Solution,
    replay,
    solve,
)
from game.checker.verdict import Kind, judge
from game.collision.aabb import Box
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action
from game.sim.level import EnemySpec, Level
from game.sim.platforms import PlatformSpec, Route
from tests.maps import level_from_boxes
from tests.test_verdicts import (
    BUFFERED_PRESSES,
    COLS,
    EDGE,
    FLOOR,
    RIGHT,
    ROWS,
    SPAWN,
    TUNING,
    WIDTH,
    Script,
    gap,
    hold,
    ledge,
    low_spikes_with_one_tile_between,
    pit_under_spikes,
    play,
)

# Where the spawn stands within a tick's run (1.5 px) decides where the last step before an
# edge falls: from these, a run from tick 0 and a jump pressed on the tick given crosses.
LAST_COYOTE_PLACE, LAST_COYOTE_PRESS = 0.75, 113  # the 76 px gap: the last coyote tick
COYOTE_PLACE, COYOTE_PRESS = 0.25, 112  # the 74 px gap: a coyote tick
# From the spawn at a whole pixel, the run from tick 0 never lines up with the 76 px gap's
# edge; a hop on the spot (jump for one tick, then run, speeding up in the air) does.
HOP_TICKS, LINED_UP_PRESS = 1, 116


def placed(level: Level, offset_px: float) -> Level:
    """``level`` with its spawn ``offset_px`` to the right."""
    return dataclasses.replace(level, spawn=Box(SPAWN.x + offset_px, SPAWN.y, SPAWN.w, SPAWN.h))


def beside_a_lift(level: Level, width_px: int) -> Level:
    """``level`` (a gap ``width_px`` wide) with a lift going up and down past the gap, above
    the player's head: the search cannot ride it across, but a map with moving platforms is
    searched by beams, which wait for platforms."""
    lift = PlatformSpec(Route(((EDGE + width_px + 64, FLOOR - 120),
                               (EDGE + width_px + 64, FLOOR - 60))), 32.0, 8.0, 40.0)
    return dataclasses.replace(level, platforms=(lift,))


def widest_gap() -> Level:
    return placed(gap(DEFAULT_LIMITS.coyote_gap_px), LAST_COYOTE_PLACE)


def coyote_gap() -> Level:
    return placed(gap(74), COYOTE_PLACE)


def hop_then(script: Script) -> Script:
    """``script``, but on its first :data:`HOP_TICKS` ticks jump on the spot, without a run."""
    def held(tick: int) -> frozenset[Action]:
        keys = script(tick)
        return keys - {RIGHT} if tick < HOP_TICKS else keys
    return held


def gap_to_the_left(width_px: int) -> Level:
    """:func:`gap` seen in a mirror: the spawn at a whole pixel on the right, the edge on a
    tile line, the Exit on the left."""
    edge = WIDTH - EDGE
    spawn = Box(WIDTH - SPAWN.right, SPAWN.y, SPAWN.w, SPAWN.h)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, edge - width_px, 64),
                                         Box(edge, FLOOR, WIDTH - edge, 64)],
                            spawn, [Box(32, FLOOR - 16, 16, 16)])


def leftwards(script: Script) -> Script:
    """``script`` with left held wherever it holds right."""
    def held(tick: int) -> frozenset[Action]:
        keys = script(tick)
        return keys - {RIGHT} | {Action.LEFT} if RIGHT in keys else keys
    return held


def far_from_an_enemy(level: Level) -> Level:
    """``level`` with an enemy standing at the far left, well behind the spawn: it changes
    nothing, but the player can walk to it, so the pixel-exact proof does not cover it."""
    return dataclasses.replace(level, enemies=(EnemySpec(Box(2, FLOOR - 12, 14, 12), 0.0),))


PIT_UNDER_SPIKES = "pit under spikes, jump held 7 ticks"
WIDEST_FROM_A_WHOLE_PIXEL = "76 px gap from a spawn at a whole pixel, lined up by a hop"

# Known-truth maps, each with a script that wins it in the game.
KNOWN: dict[str, tuple[Level, Script]] = {
    WIDEST_FROM_A_WHOLE_PIXEL: (
        gap(DEFAULT_LIMITS.coyote_gap_px),
        hop_then(hold(jumps=[(0, HOP_TICKS), (LINED_UP_PRESS, 40)]))),
    "76 px gap to the left from a spawn at a whole pixel, lined up by a hop": (
        gap_to_the_left(DEFAULT_LIMITS.coyote_gap_px),
        leftwards(hop_then(hold(jumps=[(0, HOP_TICKS), (LINED_UP_PRESS, 40)])))),
    "76 px gap, jump on the last coyote tick": (
        widest_gap(), hold(jumps=[(LAST_COYOTE_PRESS, 40)])),
    "76 px gap beside a lift": (
        beside_a_lift(widest_gap(), DEFAULT_LIMITS.coyote_gap_px),
        hold(jumps=[(LAST_COYOTE_PRESS, 40)])),
    "74 px gap, coyote jump": (coyote_gap(), hold(jumps=[(COYOTE_PRESS, 40)])),
    "74 px gap beside a lift": (beside_a_lift(coyote_gap(), 74),
                                hold(jumps=[(COYOTE_PRESS, 40)])),
    "44 px ledge": (ledge(DEFAULT_LIMITS.ledge_px), hold(jumps=[(100, 40)])),
    PIT_UNDER_SPIKES: (pit_under_spikes(), hold(jumps=[(113, 7)])),
}


# Scripts a tick off the winning one, which lose: the map needs its timing to the tick.
LOSE: dict[str, list[Script]] = {
    "76 px gap, jump on the last coyote tick": [
        hold(jumps=[(LAST_COYOTE_PRESS - 1, 40)]), hold(jumps=[(LAST_COYOTE_PRESS + 1, 40)])],
    PIT_UNDER_SPIKES: [hold(jumps=[(113, 6)]), hold(jumps=[(113, 8)])],
    WIDEST_FROM_A_WHOLE_PIXEL: [
        *(hold(jumps=[(press, 40)]) for press in range(100, 130)),  # no hop: no press wins
        hop_then(hold(jumps=[(0, HOP_TICKS), (LINED_UP_PRESS - 1, 40)])),
        hop_then(hold(jumps=[(0, HOP_TICKS), (LINED_UP_PRESS + 1, 40)]))],
    "76 px gap to the left from a spawn at a whole pixel, lined up by a hop": [
        *(leftwards(hold(jumps=[(press, 40)])) for press in range(100, 130))],
}


@functools.cache  # the search is bounded by work, not time: one solving serves every test
def solved(name: str) -> tuple[Level, Solution]:
    """A known map, by name, and what :func:`solve` finds on it at the default effort."""
    level = KNOWN[name][0]
    return level, solve(level)


@pytest.mark.parametrize("name", sorted(KNOWN))
def test_each_known_map_is_won_by_its_script_and_solved_within_its_own_budget(
        name: str) -> None:
    level, script = KNOWN[name]
    assert play(level, script, ticks=2_000).won
    assert not any(play(level, late, ticks=2_000).won for late in LOSE.get(name, []))
    _, solution = solved(name)
    assert solution.found and solution.own_budget, solution.moves_tried
    assert solution.moves_tried <= solution.budget
    assert replay(level.path, solution.held, level)[0]


def test_the_pit_under_spikes_is_solved_by_a_jump_held_an_exact_number_of_ticks() -> None:
    """Its one winning jump is held 7 ticks (test_the_pit_under_spikes_needs_one_exact_jump):
    the plain moves hold jump for whole moves of 6 ticks and miss it; the second stage
    releases it on each tick of the rise."""
    level, solution = solved(PIT_UNDER_SPIKES)
    assert level == pit_under_spikes()
    assert play(level, hold(jumps=[(113, 7)])).won  # the witness
    assert solution.found and solution.own_budget
    assert solution.timed  # found by the stage with timed inputs, not by the plain moves
    assert replay(level.path, solution.held, level)[0]
    holds: list[int] = []
    run = 0  # how long each press of jump was held, in ticks
    for held in [*solution.held, frozenset()]:
        if Action.JUMP in held:
            run += 1
        elif run:
            holds, run = [*holds, run], 0
    assert any(length % MOVE_TICKS for length in holds)


def test_the_widest_gap_from_a_whole_pixel_is_solved_by_lining_up_the_run() -> None:
    """No run from the spawn at a whole pixel puts the last tick on the ground where a jump
    crosses the 76 px gap; the second stage lines the run up with a hop, and its route
    leaves the ground before the run to the edge."""
    level, solution = solved(WIDEST_FROM_A_WHOLE_PIXEL)
    assert level == gap(DEFAULT_LIMITS.coyote_gap_px)
    assert solution.found and solution.own_budget, solution.moves_tried
    assert solution.timed  # found by the stage with timed inputs, not by the plain moves
    pressed = [tick for tick, held in enumerate(solution.held)
               if Action.JUMP in held and (tick == 0 or Action.JUMP not in solution.held[tick - 1])]
    assert len(pressed) >= 2  # the hop, then the jump over the gap


# The known maps only the timed inputs solve, and the most moves each may take: the timed
# inputs' first turn comes after a fifth of the budget, not after the plain moves' whole
# share (three fifths), and finds each of these routes (with 9,000 moves, the plain moves
# spent 5,400 of them before; each took 6,389 to 7,408 moves, and takes 2,789 to 3,709).
NEED_TIMED_INPUTS = [WIDEST_FROM_A_WHOLE_PIXEL,
                     "76 px gap to the left from a spawn at a whole pixel, lined up by a hop",
                     "76 px gap beside a lift", "74 px gap beside a lift", PIT_UNDER_SPIKES]
TIMED_ROUTE_MOVES = 4_000


@pytest.mark.parametrize("name", NEED_TIMED_INPUTS)
def test_a_map_that_needs_timed_inputs_is_solved_in_their_first_turn(name: str) -> None:
    """The plain moves try the first :data:`FIRST_PLAIN_SHARE` of the budget, then the timed
    inputs take their turn, before the plain moves go on with the rest of their share."""
    _, solution = solved(name)
    assert solution.found and solution.timed
    assert solution.budget * FIRST_PLAIN_SHARE < solution.moves_tried < TIMED_ROUTE_MOVES
    assert solution.moves_tried < solution.budget * PLAIN_SHARE


def test_a_map_not_decided_says_the_budget_it_was_given_and_the_moves_it_tried() -> None:
    """A gap one pixel wider than the widest (which no jump crosses), with an enemy far
    behind the spawn, within the player's reach, which the pixel-exact proof does not
    cover: the search spends exactly this map's own budget, and says it."""
    level = far_from_an_enemy(gap(DEFAULT_LIMITS.coyote_gap_px + 1))
    verdict = judge(level, Effort())
    assert verdict.kind is Kind.UNDECIDED and verdict.solution is not None
    budget = verdict.solution.budget
    assert budget == MIN_BUDGET  # a small map gets the least budget
    assert budget <= verdict.solution.moves_tried <= budget + 10 * MOVE_TICKS
    assert f"this map's budget of {budget:,} moves" in verdict.finding
    assert f"--budget {verdict.solution.moves_tried * 4}" in verdict.advice


def test_a_budget_given_with_budget_n_is_said_as_such() -> None:
    verdict = judge(gap(64), Effort(budget=5))
    assert verdict.kind is Kind.UNDECIDED
    assert "its budget of 5 moves" in verdict.finding


def test_the_budget_grows_with_the_cells_a_route_may_pass_through() -> None:
    assert map_budget(1) == MIN_BUDGET
    assert map_budget(2_000) == 2_000 * MOVES_PER_CELL
    assert map_budget(4_000) == 2 * map_budget(2_000)
    assert map_budget(10**9) == MAX_BUDGET


def boxes(level: Level, script: Script, ticks: int = 600) -> tuple[bool, list[Box]]:
    """Play ``script`` as the game does: won or not, and the player's box after each tick."""
    campaign = Campaign(level.path, loader=lambda _path: level)
    route: list[Box] = []
    for tick in range(ticks):
        campaign.tick(script(tick))
        route.append(campaign.world.player.box)
        if campaign.levels_completed or campaign.outcome is not Outcome.RUNNING:
            break
    return campaign.levels_completed > 0, route


def first_tick_on_the_ground(level: Level, script: Script, after: int) -> int:
    """The first tick from ``after`` on which the game reads the player as standing."""
    campaign = Campaign(level.path, loader=lambda _path: level)
    for tick in range(after + 200):
        if tick >= after and campaign.world.player.on_ground:
            return tick
        campaign.tick(script(tick))
    raise AssertionError("the player never landed")


def test_a_jump_buffered_before_landing_is_the_jump_pressed_on_the_first_tick_on_the_ground(
        ) -> None:
    """No map needs the jump buffer: a jump pressed 1 to ``jump_buffer_ticks`` ticks before
    landing leaves on the first tick on the ground, and so does one pressed on that tick;
    the player's box is the same after every tick. So the low spikes' buffered presses
    (:data:`BUFFERED_PRESSES`) moved to the first tick on the ground win the same way, and
    a search that presses jump just before landing (``landing_jump``) finds what a press on
    the ground would."""
    level = low_spikes_with_one_tile_between()
    buffered = hold(jumps=[(press, 20) for press in BUFFERED_PRESSES])
    won, route = boxes(level, buffered)
    assert won
    _, second, third = BUFFERED_PRESSES
    landings = [first_tick_on_the_ground(level, buffered, press) for press in (second, third)]
    assert landings[0] > second and landings[1] > third  # the presses were in the air
    on_the_ground = hold(jumps=[(BUFFERED_PRESSES[0], 20),
                                *((landing, 20 - (landing - press))
                                  for press, landing in zip((second, third), landings,
                                                            strict=True))])
    assert boxes(level, on_the_ground) == (True, route)
    # every depth of the buffer, on a hop on the spot and its landing
    flat = gap(64)
    first = (0, 8)  # a short hop, let go well before the next press
    hop = hold(right_from=10_000, jumps=[first])
    landing = first_tick_on_the_ground(flat, hop, 1)
    assert landing - TUNING.jump_buffer_ticks - 1 > sum(first)
    won, pressed_there = boxes(flat, hold(right_from=10_000, jumps=[first, (landing, 40)]), 200)
    assert pressed_there[landing].y < pressed_there[landing - 1].y  # it jumped again there
    for early in range(1, TUNING.jump_buffer_ticks + 1):
        script = hold(right_from=10_000, jumps=[first, (landing - early, 40 + early)])
        assert boxes(flat, script, 200) == (won, pressed_there), early
    too_early = landing - TUNING.jump_buffer_ticks - 1
    assert boxes(flat, hold(right_from=10_000, jumps=[first, (too_early, 60)]),
                 200) != (won, pressed_there)
