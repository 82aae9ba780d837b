"""How the solver searches: the wait for a platform ends when the simulation says it comes,
a beam keeps one state a tile while others are left, a stuck beam goes back a few layers
and widens instead of starting again from the spawn, the air beside a cliff is left for the
stairs once crowded, a long maze of low corridors is solved by the best-first search
with a few moves a tile, an easy level by playing few of each state's moves, the beams
keep the jumps that clear a spike bed, and they lean along the level steps of a ride, and
the best-first search puts off a fall onto spikes."""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Iterator
from typing import cast

import pytest

from game.checker.reach import DEFAULT_LIMITS
from game.checker.solver import (
    BACK_MOVES,
    COMES_PX,
    LAST_COYOTE_TICK,
    MOVE_TICKS,
    UNTIL_A_PLATFORM_COMES,
    Effort,
    Node,
    _Search,
    plateau_distances,
    solve,
)
from game.collision.aabb import Box
from game.collision.shapes import TileKind, TileShape
from game.levels import FIRST_LEVEL
from game.sim.inputs import Action
from game.sim.level import Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.snapshot import Snapshot
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.maps import TILE, level_from_ascii, level_from_boxes
from tests.shipped_solves import solved, solved_shipped
from tests.test_verdicts import COLS, EDGE, FLOOR, ROWS, SPAWN, WIDTH, exit_on, ferry, gap


def ferry_coming_back(speed_px_s: float = 40.0, spawn: Box | None = None) -> Level:
    """The ferry starts on the far side of the pit; the spawn is at the near edge."""
    far = EDGE + 160
    ride = PlatformSpec(Route(((far - 48, FLOOR), (EDGE, FLOOR))), 48.0, 8.0, speed_px_s)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(far, FLOOR, WIDTH - far, 64)],
                            spawn or Box(EDGE - 14, FLOOR - 14, 12, 14), [exit_on(FLOOR)],
                            platforms=(ride,))


def test_the_wait_for_a_platform_ends_on_the_tick_it_comes() -> None:
    search = _Search(ferry_coming_back(), Effort())
    for _ in range(10):  # land at the spawn, standing still
        search.world.step(frozenset())
    assert search.waiting_helps()
    coming = search.ticks_until_a_platform_comes()
    assert coming is not None and coming > 10 * MOVE_TICKS  # a long wait, in one move
    (platform,) = search.world.platforms
    player = search.world.player
    for _ in range(coming - 1):
        search.world.step(frozenset())
        assert player.box.gap(platform.box) > COMES_PX
    search.world.step(frozenset())
    assert player.box.gap(platform.box) <= COMES_PX


def test_the_wait_is_one_child_that_counts_the_moves_its_ticks_take() -> None:
    search = _Search(ferry_coming_back(), Effort())
    for _ in range(10):
        search.world.step(frozenset())
    coming = search.ticks_until_a_platform_comes()
    assert coming is not None
    search.moves = [(frozenset(), UNTIL_A_PLATFORM_COMES)]
    (child,) = [node for _, _, node in
                search.children(Snapshot.of(search.world), None, 10, {})]
    assert child.ticks == 10 + coming
    assert search.moves_tried == -(-coming // MOVE_TICKS)
    # The same wait from the same place is not tried twice.
    assert not list(search.children(Snapshot.of(search.world), None, 10, {}))


def test_a_beam_keeps_one_state_a_tile_while_others_are_left() -> None:
    search = _Search(ferry(), Effort())
    snapshots = [cast(Snapshot, object()) for _ in range(5)]
    nodes = [Node(None, frozenset(), MOVE_TICKS) for _ in range(5)]
    children = [(float(score), order, snapshots[order], nodes[order])
                for order, score in enumerate((1, 2, 3, 4, 5))]
    cells = [(3, 4), (3, 4), (3, 4), (5, 4), (6, 4)]
    kept = search.diverse(children, cells, 3)
    assert [node for _, node in kept] == [nodes[0], nodes[3], nodes[4]]
    # With too few tiles, the best of the rest fill the beam.
    kept = search.diverse(children, cells, 4)
    assert [node for _, node in kept] == [nodes[0], nodes[3], nodes[4], nodes[1]]


def test_a_stuck_beam_goes_back_a_few_layers_not_to_the_spawn() -> None:
    # A fast ferry, met after a run from the far end of the map: one state wide, the
    # beam misses it.
    search = _Search(ferry_coming_back(80.0, SPAWN), Effort(width=1))
    layers: list[int] = []
    expand = search.children

    def recorded(snapshot: Snapshot, node: Node | None, ticks: int,
                 seen: dict[tuple[object, ...], int], layer: int = 0,
                 late_jumps: bool = False) -> Iterator[tuple[float, Snapshot, Node]]:
        layers.append(layer)
        return expand(snapshot, node, ticks, seen, layer, late_jumps)

    search.children = recorded  # type: ignore[method-assign]
    assert search.run() is not None
    back = [(stuck, again) for stuck, again in itertools.pairwise(layers) if again < stuck]
    assert back, "the narrow beam was never stuck: the map no longer tests going back"
    stuck, again = back[0]
    assert again == stuck - BACK_MOVES and again > 1


def test_in_the_air_every_move_steers_unless_it_carries_on_as_the_one_before() -> None:
    level = level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64)], SPAWN, [exit_on(FLOOR)])
    search = _Search(level, Effort())
    for _ in range(10):  # land at the spawn, standing still
        search.world.step(frozenset())
    on_ground = Snapshot.of(search.world)
    tried: list[frozenset[Action]] = []

    def try_move(snapshot: Snapshot, start: int, choice: frozenset[Action],
                 move_ticks: int = MOVE_TICKS) -> int:
        tried.append(choice)
        return 0  # the world stays where the snapshot put it
    search.try_move = try_move  # type: ignore[method-assign]
    list(search.children(on_ground, None, 10, {}))
    assert frozenset() in tried and frozenset({Action.JUMP}) in tried  # standing still is there

    search.world.step(frozenset({Action.JUMP}))
    assert not search.world.player.on_ground
    in_the_air = Snapshot.of(search.world)
    straight_up = Node(None, frozenset({Action.JUMP}), 11)
    tried.clear()
    list(search.children(in_the_air, straight_up, 11, {}))
    assert frozenset({Action.JUMP}) in tried  # carrying on as before
    assert frozenset() not in tried
    assert all(choice & {Action.LEFT, Action.RIGHT} or choice == straight_up.choice
               for choice in tried)


def test_a_gap_past_a_running_jump_is_crossed_by_a_jump_on_the_last_coyote_tick() -> None:
    wide = gap(DEFAULT_LIMITS.coyote_gap_px - 1)  # wider than a running jump crosses
    assert DEFAULT_LIMITS.coyote_gap_px - 1 > DEFAULT_LIMITS.gap_px
    solution = solve(wide, Effort(budget=4_000))
    assert solution.found
    world = World(wide)
    for tick, held in enumerate(solution.held):
        if Action.JUMP in held and not world.player.on_ground:
            # the jump that crossed was pressed in the air: on the last coyote tick, so a
            # press one tick later is no jump at all
            assert world.player.coyote_ticks_left == LAST_COYOTE_TICK, tick
            pressed = Snapshot.of(world)
            assert any(e.kind is EventKind.JUMP for e in world.step(held))
            pressed.restore(world)
            world.step(frozenset({Action.RIGHT}))
            assert not any(e.kind is EventKind.JUMP for e in world.step(held))
            break
        world.step(held)
    else:
        raise AssertionError("the route never jumps off the edge")


# One-way stairs up beside a cliff: each stair is reached by a jump from the one two tiles
# below, zigzagging, and only the top stairs lead onto the cliff; the air beside the cliff
# is where the reach proof's steps lead, but no jump from below climbs it.
STAIRS_BESIDE_A_CLIFF = [
    "                           ",
    "                           ",
    "         --- ---  ######  D",
    "                  #########",
    "     ---          #########",
    "                  #########",
    "         ---      #########",
    "                  #########",
    "     ---          #########",
    "                  #########",
    "P ###             #########",
    "#####^^^^^^^^^^^^^#########",
]


def test_the_air_beside_a_cliff_is_left_for_the_stairs_once_it_is_crowded() -> None:
    """Every jump from the stairs into the air beside the cliff is a state of its own, and
    their tiles are nearer the Exit by the steps than the stair that leads on: scored by
    the steps alone, the best-first search tried them until the budget ran out. Found by
    the plain moves, within their share of the budget (after the timed inputs' first turn:
    the plain moves take more than their first turn here)."""
    level = level_from_ascii(STAIRS_BESIDE_A_CLIFF)
    solution = solve(level)
    assert solution.found and solution.own_budget, solution.moves_tried
    assert not solution.timed  # the plain moves found it, within PLAIN_SHARE of the budget


MAZE_CORRIDORS = 10  # corridors two tiles high, each run from one end to the other
MAZE_WIDTH = 32  # tiles across, the walls at both ends included
MOVES_PER_CORRIDOR_TILE = 14  # about 6 moves for each state carried on from, 2 states a tile


def serpentine_maze() -> Level:
    """Corridors two tiles high, one under the other; a hole at the far end of each floor
    drops into the next, which runs back the other way; the Exit is at the end of the last."""
    wall = "#" * MAZE_WIDTH
    inside = "#" + " " * (MAZE_WIDTH - 2) + "#"
    rows = [wall]
    for corridor in range(MAZE_CORRIDORS):
        rows += [inside, inside]
        hole = MAZE_WIDTH - 3 if corridor % 2 == 0 else 1  # two tiles at the far end
        rows.append(wall[:hole] + "  " + wall[hole + 2:])
    rows[-1] = wall
    rows[1] = "#P" + inside[2:]
    exit_col = 2 if MAZE_CORRIDORS % 2 == 0 else MAZE_WIDTH - 3
    rows[-2] = inside[:exit_col] + "D" + inside[exit_col + 1:]
    return level_from_ascii(rows)


@pytest.mark.slow
def test_a_long_maze_of_low_corridors_is_solved_with_a_few_moves_a_tile() -> None:
    """A route of thousands of ticks: in a corridor two tiles high every jump meets the
    ceiling and ends in the tile a run ends in, so a score by tiles alone ties them all and
    the best-first search carries on from each; counting the place within the tile, it
    carries on from the run that got furthest, and it may spend half the moves of a budget
    this large before the beams take over."""
    level = serpentine_maze()
    solution = solve(level)
    assert solution.found and solution.own_budget
    tuning = Tuning()
    run_px_per_tick = tuning.run_speed_px_s * tuning.tick_s
    hole_to_hole_px = (MAZE_WIDTH - 6) * level.grid.tile_w  # the least run along a corridor
    assert solution.exit_tick > MAZE_CORRIDORS * hole_to_hole_px / run_px_per_tick > 2_000
    tiles = MAZE_CORRIDORS * (MAZE_WIDTH - 2)
    assert solution.moves_tried <= MOVES_PER_CORRIDOR_TILE * tiles, solution.moves_tried


EASY_LEVEL_MOVES = 1_200  # First Steps' route is about 350 moves long


def test_an_easy_level_is_solved_playing_few_of_each_state_s_moves() -> None:
    """The best-first search plays a state's next move only when nothing played since came
    closer: playing all seven moves of every state it carried on from, it took 2,510 moves
    to solve First Steps."""
    solution = solved(FIRST_LEVEL)
    assert solution.found and solution.own_budget
    assert solution.moves_tried < EASY_LEVEL_MOVES, solution.moves_tried


SPIKE_BEDS = 5  # beds two spikes wide, on the way to the Exit
SPIKE_BED_MOVES = 1_500  # the route is about 95 moves long


def spike_beds() -> Level:
    """Short spike beds (the shipped spikes: 14x8 px at the foot of their cell) on a flat
    floor, and a moving platform in a far corner, so the beams search first."""
    row = "P" + "      ^^" * SPIKE_BEDS + "      D  "
    level = level_from_ascii(["", "", "", "", row.replace("^", " "), "#" * len(row)])
    for col, char in enumerate(row):
        if char == "^":
            level.grid.put(col, 4, TileShape(Box(col * TILE + 1, 4 * TILE + 8, 14, 8),
                                             TileKind.HAZARD, col, 4))
    corner = PlatformSpec(Route(((0.0, 0.0), (32.0, 0.0))), 16.0, 8.0, 20.0)
    return dataclasses.replace(level, platforms=(corner,))


def test_the_beams_keep_the_jumps_that_clear_a_spike_bed() -> None:
    """A jump that comes down on spikes scores as a fall into a pit: scored by its tile
    alone, the jumps that went furthest before landing on the spikes filled the beam, and
    every life was lost (5,876 moves)."""
    solution = solve(spike_beds())
    assert solution.found and solution.own_budget
    assert solution.moves_tried < SPIKE_BED_MOVES, solution.moves_tried


def test_level_steps_lead_to_the_cell_beside_fewer_steps() -> None:
    # a ride of five cells, all 3 steps from the Exit, whose far end is beside a cell of 2
    steps = {(col, 0): 3 for col in range(5)} | {(5, 0): 2, (6, 0): 1, (6, 1): 0}
    distances = plateau_distances(steps)
    assert [distances[(col, 0)] for col in range(7)] == [4, 3, 2, 1, 0, 0, 0]
    assert distances.get((6, 1), 0) == 0  # the Exit's cell: nowhere to lean


DUSK_RHYTHM_MOVES = 3_000  # its route is about 250 moves long


def test_the_beams_ride_a_lift_up_and_a_ferry_along() -> None:
    """Dusk Rhythm's lift and ferry are level steps (the reach proof joins a ride's cells
    in one step); beside its lift, the beams kept jumps on the spot under it in place of
    the ride up it, until widened (7,411 moves, and 11,379 while they also jumped onto
    its spike beds)."""
    solution = solved_shipped("11-dusk-rhythm")
    assert solution.found and solution.own_budget
    assert solution.moves_tried < DUSK_RHYTHM_MOVES, solution.moves_tried


SPIKE_GAUNTLET_MOVES = 3_000  # its route is about 190 moves long


def test_the_best_first_search_puts_off_a_fall_onto_spikes() -> None:
    """Spike Gauntlet's spike beds, scored by the tiles alone: every jump over a bed, and
    every steer in the air, looked as close as the one that clears it, and the best-first
    search tried them all (4,777 moves)."""
    solution = solved_shipped("05-spike-gauntlet")
    assert solution.found and solution.own_budget
    assert solution.moves_tried < SPIKE_GAUNTLET_MOVES, solution.moves_tried


LAST_PEAK_MOVES = 6_800  # its route is about 550 moves long


@pytest.mark.slow
def test_a_jump_under_a_lift_does_not_narrow_the_beams_again() -> None:
    """A beam widened at The Last Peak's lift narrows again only once a state on the ground
    comes closer than any before: narrowing each time a jump under the lift rose nearer
    its top, the beams took 6,811 moves."""
    solution = solved_shipped("12-the-last-peak")
    assert solution.found and solution.own_budget
    assert solution.moves_tried < LAST_PEAK_MOVES, solution.moves_tried
