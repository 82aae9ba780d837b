"""The solver's second stage and its budget: inputs timed to the tick where a map needs them
(a jump held for an exact number of ticks under spikes), and a budget of moves that grows
with the map and is said when the search stops without a route."""

from __future__ import annotations

from game.levels.reach import DEFAULT_LIMITS
from game.levels.search_budget import MIN_BUDGET, MOVES_PER_CELL, map_budget
from game.levels.solver import MOVE_TICKS, PLAIN_SHARE, Effort, replay, solve
from game.levels.verdict import Kind, judge
from game.sim.inputs import Action
from tests.test_verdicts import gap, hold, pit_under_spikes, play


def test_the_pit_under_spikes_is_solved_by_a_jump_held_an_exact_number_of_ticks() -> None:
    """Its one winning jump is held 7 ticks (test_the_pit_under_spikes_needs_one_exact_jump):
    the plain moves hold jump for whole moves of 6 ticks and miss it; the second stage
    releases it on each tick of the rise."""
    level = pit_under_spikes()
    assert play(level, hold(jumps=[(113, 7)])).won  # the witness
    solution = solve(level)
    assert solution.found and solution.own_budget
    assert solution.moves_tried > solution.budget * PLAIN_SHARE  # found in the second stage
    assert replay(level.path, solution.held, level)[0]
    holds: list[int] = []
    run = 0  # how long each press of jump was held, in ticks
    for held in [*solution.held, frozenset()]:
        if Action.JUMP in held:
            run += 1
        elif run:
            holds, run = [*holds, run], 0
    assert any(length % MOVE_TICKS for length in holds)


def test_a_map_not_decided_says_the_budget_it_was_given_and_the_moves_it_tried() -> None:
    """A gap a pixel past the widest jump is not proven impossible by the fill: the search
    spends exactly this map's own budget, and the line says it."""
    level = gap(DEFAULT_LIMITS.coyote_gap_px + 1)
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
    assert map_budget(10_000) == 10_000 * MOVES_PER_CELL
    assert map_budget(20_000) == 2 * map_budget(10_000)
