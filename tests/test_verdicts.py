"""The checker's verdicts on maps whose truth is known by construction: gaps and ledges at and
past the player's measured limits, a drop through a one-way floor, a ferry over a pit, sealed
caves and caves sealed only by physics; and maps that need the game's finer rules: spikes
crossed only after losing a life, a checkpoint's respawn, a stomp's bounce, one exact jump
under spikes, jumps buffered before landing. Each of those is won by an input script written
here and played in the real game, which is what makes its truth known. No verdict may be
wrong: a winnable map is never called impossible, an unwinnable one never solved."""

from __future__ import annotations

import functools
import json
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path

import pytest

from game.checker.cli import EXIT_UNDECIDED, main
from game.checker.reach import DEFAULT_LIMITS, jump_path
from game.checker.reachable import jump_rise, open_path, reachable, starts
from game.checker.solver import Effort, replay
from game.checker.verdict import Kind, Verdict, judge
from game.collision.aabb import Box
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, Actions
from game.sim.level import EnemySpec, Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.maps import level_from_boxes, write_tmx

COLS, ROWS, TILE = 40, 14, 16
WIDTH, FLOOR = COLS * TILE, 10 * TILE  # the floor's top
EDGE = 12 * TILE  # where a gap or a ledge begins
SPAWN = Box(32, FLOOR - 14, 12, 14)
EFFORT = Effort(budget=6_000)  # small: these maps are short, and an undecided is honest


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


# Maps that need the game's finer rules. Each comes with an input script (a function from the
# tick to the keys held) that wins it when the real game plays it
# (test_each_script_wins_its_map_in_the_game).

Script = Callable[[int], Actions]
RIGHT, JUMP = Action.RIGHT, Action.JUMP
TUNING = Tuning()
RUN_PX_PER_TICK = TUNING.run_speed_px_s * TUNING.tick_s  # the fastest the player moves across
FULL_JUMP_TICKS = len(jump_rise(TUNING)) - 1  # the longest a jump from a floor stays up
SPIKES_PX = 16  # a row of spikes one tile high, lying on the floor
NEAR_SPIKES = (4 * TILE, 5 * TILE)  # where a row begins and how long it is, in px
FAR_SPIKES = (14 * TILE, 5 * TILE)


def spikes_on_the_floor(left: int, width: int, flags: tuple[Box, ...] = ()) -> Level:
    """Flat ground with a row of spikes ``width`` px long from ``left``; the Exit beyond."""
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64)], SPAWN, [exit_on(FLOOR)],
                            hazards=(Box(left, FLOOR - SPIKES_PX, width, SPIKES_PX),),
                            checkpoints=flags)


def spikes_crossed_after_a_life() -> Level:
    """Spikes five tiles long, starting two tiles from the spawn.

    No jump clears them (a jump from the flat stays up for FULL_JUMP_TICKS, too short to
    carry the body over), so they must be touched, and touching them costs a life unless the
    player is invulnerable, which only a respawn makes them. The respawn is at the spawn,
    close enough that the 1.5 s of protection carries the player across: the map is won
    only after losing a life (test_the_spikes_need_a_life_and_a_respawn_near_them)."""
    return spikes_on_the_floor(*NEAR_SPIKES)


FLAG = Box(12 * TILE, FLOOR - 32, 16, 32)  # a checkpoint two tiles before the spikes


def spikes_crossed_from_a_checkpoint(flag: bool = True) -> Level:
    """Spikes five tiles long, far from the spawn, with a checkpoint just before them.

    As above, they are crossed only while invulnerable after a respawn. From the spawn the
    protection runs out before the player even reaches them; from the checkpoint it carries
    the player across. So the map is won through the checkpoint's respawn, and without the
    flag (``flag=False``) it cannot be won at all."""
    return spikes_on_the_floor(*FAR_SPIKES, (FLAG,) if flag else ())


BOUNCE_LEDGE_PX = DEFAULT_LIMITS.ledge_px + 8  # higher than any jump from the floor


def ledge_above_a_hopper(hopper: bool = True) -> Level:
    """A ledge higher than the highest jump, with a hopper that hops on the spot at its foot.

    A jump from the floor rises at most ``DEFAULT_LIMITS.ledge_px`` (measured by the game),
    so no jump reaches the ledge. A stomp bounces the player up at ``stomp_bounce_px_s``
    (slower than a jump) from wherever the enemy's head is: from a hopper sitting on the
    floor, its head 12 px up, the bounce rises less than a jump would; from a hopper near the
    top of its hop it carries the feet above the ledge. A stomped enemy is gone, so the one
    way up is a stomp on the hopper in the air. Without it (``hopper=False``) the map is a
    ledge too high."""
    enemies = (EnemySpec(Box(EDGE - 14, FLOOR - 12, 14, 12), 0.0, "hopper"),) if hopper else ()
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64),
                                         Box(EDGE, FLOOR - BOUNCE_LEDGE_PX, WIDTH - EDGE,
                                             BOUNCE_LEDGE_PX)],
                            Box(EDGE - 60, SPAWN.y, SPAWN.w, SPAWN.h),
                            [exit_on(FLOOR - BOUNCE_LEDGE_PX)], enemies=enemies)


PIT_PX, SPIKE_CEILING_PX = 60, 40


def pit_under_spikes() -> Level:
    """A pit 60 px wide (the void below it) under a row of spikes 40 px above the floor,
    reaching three tiles past the pit on each side.

    The pit needs a running jump, and a full jump puts the head into the spikes, so the jump
    must be cut short by letting go of jump at the right tick. The script's jump leaves on
    one tick and is held for exactly 7: leaving a tick earlier or later, or holding it a
    tick less or more, loses (test_the_pit_under_spikes_needs_one_exact_jump)."""
    spikes = Box(EDGE - 3 * TILE, FLOOR - SPIKE_CEILING_PX - TILE, PIT_PX + 6 * TILE, TILE)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(EDGE + PIT_PX, FLOOR, WIDTH - EDGE - PIT_PX, 64)],
                            SPAWN, [exit_on(FLOOR)], hazards=(spikes,))


LOW_SPIKES_PX, LOW_SPIKES_WIDTH, SAFE_PX = 4, 40, 16
CORRIDOR_LEFT = 16 * TILE  # further from the spawn than a respawn's protection carries


def widest_low_row_cleared() -> float:
    """How long a row of low spikes the best jump clears, from the game's own jump at a run
    (:func:`jump_path`): on its first tick the body moves along x still on the floor, and it
    must be past the row by the first tick it comes down below the spikes' top. A full jump
    at full speed is the highest at every tick and the fastest across, so no jump does better.
    """
    path = jump_path(TUNING)
    take_off = path[0].bottom
    above = [tick for tick, box in enumerate(path) if take_off - box.bottom > LOW_SPIKES_PX]
    return path[above[-1] + 1].x - path[above[0]].x - TUNING.player_width_px


def low_spikes_with_one_tile_between(row_px: int = LOW_SPIKES_WIDTH) -> Level:
    """Three rows of low spikes (4 px high, 40 px long) with one clean tile between them.

    A jump at a run from before a row comes down on the clean tile beyond it, and the next
    row leaves the 12 px body little room there: the script's jumps leave the ground on the
    first tick after each landing, pressed while still in the air and kept by the game's
    jump buffer (``jump_buffer_s``). The same run with a jump leaving one tick later loses
    (test_the_low_spikes_need_jumps_pressed_before_landing). The corridor starts further
    from the spawn than the protection of a respawn carries, so no life buys a way across.

    Its twin has rows ``row_px`` one pixel longer than :func:`widest_low_row_cleared`: every
    jump touches them, so it cannot be won."""
    rows = tuple(Box(CORRIDOR_LEFT + n * (row_px + SAFE_PX), FLOOR - LOW_SPIKES_PX, row_px,
                     LOW_SPIKES_PX) for n in range(3))
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64)], SPAWN, [exit_on(FLOOR)],
                            hazards=rows)


def hold(right_from: int = 0, jumps: Iterable[tuple[int, int]] = ()) -> Script:
    """A script: run right from tick ``right_from`` on; hold jump for each (first tick, ticks)."""
    spans = tuple(jumps)

    def held(tick: int) -> Actions:
        keys = {RIGHT} if tick >= right_from else set()
        if any(start <= tick < start + length for start, length in spans):
            keys.add(JUMP)
        return frozenset(keys)
    return held


@dataclass(frozen=True)
class Played:
    """How a script's run went: won or not, lives lost and enemies stomped on the way, and
    whether the player was in the air on each tick listed in ``asked``."""

    won: bool
    lives_lost: int
    stomps: int
    airborne: tuple[bool, ...] = ()


def play(level: Level, script: Script, asked: tuple[int, ...] = (),
         ticks: int = 1_200) -> Played:
    """Play ``script`` on ``level`` as the game does (a run with its lives) until it wins, is
    lost, or ``ticks`` pass."""
    campaign = Campaign(level.path, loader=lambda _path: level)
    airborne: dict[int, bool] = {}
    for tick in range(ticks):
        airborne[tick] = not campaign.world.player.on_ground  # as the tick will read it
        campaign.tick(script(tick))
        if campaign.levels_completed or campaign.outcome is not Outcome.RUNNING:
            break
    return Played(campaign.levels_completed > 0, campaign.deaths, campaign.enemies_stomped,
                  tuple(airborne.get(tick, False) for tick in asked))


# Maps won through a mechanic the proof of impossibility must bound: a push by a moving
# Platform's side, a stomp on an enemy far from where it starts, a respawn a Platform moves.
PUSHED_PIT_PX = 128  # wider than any jump: a gap of 7 tiles is proven impossible
WALL_SPEED_PX_S = 240.0  # faster than the player runs: 4 px a tick


def pushed_across_by_a_wall(wall: bool = True) -> Level:
    """A pit 8 tiles wide, and a wall 16 px wide and 80 px tall (a Platform) sliding right
    along the floor from the map's left edge to the pit's far side, faster than the player
    runs. Standing in its way, the player is pushed to the pit; jumping there, it stays in
    front of the wall, which carries it across. No jump rises onto the wall's top."""
    far = EDGE + PUSHED_PIT_PX
    platforms = (PlatformSpec(Route(((0, FLOOR - 80), (far - 16, FLOOR - 80))), 16.0, 80.0,
                              WALL_SPEED_PX_S),) if wall else ()
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(far, FLOOR, WIDTH - far, 64)],
                            SPAWN, [exit_on(FLOOR)], platforms=platforms)


HOP_PIT_PX = 112  # a gap of 7 tiles: proven impossible without the hopper
HOPPER_SPEED_PX_S = 240.0  # a hop carries it about 116 px: across the pit


def hopper_over_a_pit(hopper: bool = True) -> Level:
    """A pit 7 tiles wide, and a fast hopper on its far side that hops towards it and leaps
    out over it. A stomp on the hopper in mid-air, over the pit, bounces the player on to
    the far side; no jump from the edge gets there."""
    far = EDGE + HOP_PIT_PX
    enemies = (EnemySpec(Box(far + 158, FLOOR - 12, 14, 12), HOPPER_SPEED_PX_S,
                         "hopper"),) if hopper else ()
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(far, FLOOR, WIDTH - far, 64)],
                            Box(EDGE - 60, SPAWN.y, SPAWN.w, SPAWN.h), [exit_on(FLOOR)],
                            enemies=enemies)


CRUSHER = Box(192, 8, 144, 64)  # where it starts; it goes down until it meets the floor
HIGH_FLOOR = 16  # the top of the high ground beside the crusher's shaft, with the Exit


def respawn_on_a_crusher() -> Level:
    """A wide crusher (a Platform 144 x 64 px) that goes up and down between high ground
    and the floor, and a Checkpoint under its middle. Counted on the tick the crusher comes
    down into the place over the flag, the flag puts the respawn on the crusher's top (the
    nearest free place, nearer than either of its sides); crushed on that tick, the player
    comes back there, rides up and walks onto the high ground. No jump reaches the crusher's
    top, 64 px up even when it is down."""
    crusher = PlatformSpec(Route(((CRUSHER.x, CRUSHER.y), (CRUSHER.x, FLOOR - CRUSHER.h))),
                           CRUSHER.w, CRUSHER.h, 40.0)
    flag = Box(CRUSHER.x + CRUSHER.w / 2 - 8, FLOOR - 32, 16, 32)
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, WIDTH, 64),
                                         Box(CRUSHER.right, HIGH_FLOOR, WIDTH - CRUSHER.right,
                                             FLOOR - HIGH_FLOOR)],
                            SPAWN, [exit_on(HIGH_FLOOR)], platforms=(crusher,),
                            checkpoints=(flag,))


def right_during(*spans: tuple[int, int]) -> Script:
    """A script: hold right from each span's first tick up to (not including) its last."""
    def held(tick: int) -> Actions:
        return frozenset({RIGHT}) if any(a <= tick < b for a, b in spans) else frozenset()
    return held


CRUSHER_STEP = 371  # the player steps into the flag on the tick the crusher comes down


# The winning scripts, written by hand from the maps' measures (run right, jump here).
BUFFERED_PRESSES = (140, 176, 213)  # the last two while the player is still in the air
WON_BY_SCRIPT: dict[str, tuple[Callable[[], Level], Script]] = {
    "spikes crossed after losing a life": (spikes_crossed_after_a_life, hold()),
    "spikes crossed from a checkpoint": (spikes_crossed_from_a_checkpoint, hold()),
    "ledge reached by a stomp on a hopper": (ledge_above_a_hopper,
                                             hold(right_from=44, jumps=[(61, 200)])),
    "pit under spikes crossed by one exact jump": (pit_under_spikes,
                                                   hold(jumps=[(113, 7)])),
    "low spikes crossed with buffered jumps": (
        low_spikes_with_one_tile_between,
        hold(jumps=[(press, 20) for press in BUFFERED_PRESSES])),
    "pit crossed pushed by a moving wall": (pushed_across_by_a_wall,
                                            hold(right_from=80, jumps=[(36, 20)])),
    "pit crossed by a stomp on a hopper over it": (hopper_over_a_pit,
                                                   hold(right_from=27, jumps=[(72, 40)])),
    "high ground reached from a respawn a crusher moved": (
        respawn_on_a_crusher, right_during((60, 198), (CRUSHER_STEP, 10**6))),
}


WINNABLE: dict[str, Callable[[], Level]] = {
    "gap of 4 tiles": lambda: gap(64),
    "gap at the widest running jump": lambda: gap(DEFAULT_LIMITS.gap_px),
    "gap that needs a coyote jump": lambda: gap(DEFAULT_LIMITS.coyote_gap_px),
    "ledge of 2 tiles": lambda: ledge(32),
    "ledge at the highest jump": lambda: ledge(DEFAULT_LIMITS.ledge_px),
    "drop through a one-way floor": drop_through,
    "ferry over a pit": ferry,
    **{name: make for name, (make, _) in WON_BY_SCRIPT.items()},
}
UNWINNABLE: dict[str, Callable[[], Level]] = {
    "gap one pixel past the widest jump": lambda: gap(DEFAULT_LIMITS.coyote_gap_px + 1),
    "gap of 7 tiles": lambda: gap(112),
    "ledge one pixel over the highest jump": lambda: ledge(DEFAULT_LIMITS.ledge_px + 1),
    "ledge of 3 tiles": lambda: ledge(48),
    "sealed cave": sealed_cave,
    "spikes far from the spawn with no checkpoint":
        lambda: spikes_crossed_from_a_checkpoint(flag=False),
    "ledge over a jump, with no hopper to stomp": lambda: ledge_above_a_hopper(hopper=False),
    "low spikes a pixel longer than any jump clears":
        lambda: low_spikes_with_one_tile_between(math.floor(widest_low_row_cleared()) + 1),
    "pit of 8 tiles with no wall to push": lambda: pushed_across_by_a_wall(wall=False),
}


@functools.cache
def judged(name: str) -> tuple[Level, Verdict]:
    """A known map, by name, and its verdict at :data:`EFFORT` (the same every time: the
    search is bounded by work, so several tests may share one judging)."""
    level = {**WINNABLE, **UNWINNABLE}[name]()
    return level, judge(level, EFFORT)


@pytest.mark.parametrize("name", sorted(WINNABLE))
def test_a_winnable_map_is_never_called_impossible(name: str) -> None:
    """Solved with a route that replays, or honestly not decided: never impossible."""
    level, verdict = judged(name)
    assert verdict.kind is not Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is not None
    if verdict.kind is Kind.SOLVED:
        assert replay(level.path, verdict.solution.held, level)[0]
    else:
        assert not verdict.solution.found and verdict.finding.startswith("not decided")


@pytest.mark.parametrize("name", sorted(UNWINNABLE))
def test_an_unwinnable_map_is_never_called_solved(name: str) -> None:
    _, verdict = judged(name)
    assert verdict.kind is not Kind.SOLVED, verdict.finding


@pytest.mark.parametrize("name", ["gap of 4 tiles", "ledge of 2 tiles",
                                  "drop through a one-way floor", "ferry over a pit",
                                  "gap at the widest running jump",
                                  "low spikes crossed with buffered jumps",
                                  "spikes crossed after losing a life",
                                  "spikes crossed from a checkpoint"])
def test_these_winnable_maps_are_solved_by_a_route_that_replays(name: str) -> None:
    _, verdict = judged(name)  # solve() replays every route it returns
    assert verdict.kind is Kind.SOLVED, verdict.finding
    assert verdict.solution is not None and verdict.solution.found


@pytest.mark.parametrize("name", ["gap of 7 tiles", "ledge of 3 tiles", "sealed cave"])
def test_maps_far_past_the_reach_or_walled_off_are_proven_impossible(name: str) -> None:
    _, verdict = judged(name)
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
    (_, first), second = judged("ferry over a pit"), judge(ferry(), EFFORT)
    assert first.kind is second.kind
    assert first.solution is not None and second.solution is not None
    assert first.solution.moves_tried == second.solution.moves_tried
    assert first.solution.script() == second.solution.script()


@pytest.mark.parametrize("name", sorted(WON_BY_SCRIPT))
def test_each_script_wins_its_map_in_the_game(name: str) -> None:
    make, script = WON_BY_SCRIPT[name]
    assert play(make(), script).won


def test_the_spikes_need_a_life_and_a_respawn_near_them() -> None:
    """No jump clears the spikes; the respawn's protection carries the player across."""
    left, width = NEAR_SPIKES
    assert width + SPAWN.w > FULL_JUMP_TICKS * RUN_PX_PER_TICK  # a jump's whole flight
    assert left + width < SPAWN.left + TUNING.invulnerable_ticks * RUN_PX_PER_TICK
    played = play(spikes_crossed_after_a_life(), hold())
    assert played.won and played.lives_lost == 1


def test_without_its_checkpoint_the_far_spikes_cannot_be_crossed() -> None:
    """The protection after a respawn at the spawn runs out before the spikes begin, and no
    jump clears them: without the flag, every way across touches them unprotected."""
    left, width = FAR_SPIKES
    assert SPAWN.right + TUNING.invulnerable_ticks * RUN_PX_PER_TICK < left
    assert width + SPAWN.w > FULL_JUMP_TICKS * RUN_PX_PER_TICK
    with_flag = play(spikes_crossed_from_a_checkpoint(), hold())
    assert with_flag.won and with_flag.lives_lost == 1
    assert not play(spikes_crossed_from_a_checkpoint(flag=False), hold()).won


def test_the_ledge_is_reached_only_by_a_stomp_in_the_air() -> None:
    _, script = WON_BY_SCRIPT["ledge reached by a stomp on a hopper"]
    assert DEFAULT_LIMITS.ledge_px < BOUNCE_LEDGE_PX
    played = play(ledge_above_a_hopper(), script)
    assert played.won and played.stomps == 1 and played.lives_lost == 0
    assert not play(ledge_above_a_hopper(hopper=False), script).won  # the same keys


def test_the_pit_under_spikes_needs_one_exact_jump() -> None:
    """The winning jump leaves on tick 113 and is held 7 ticks: a tick either way loses."""
    level = pit_under_spikes()
    assert play(level, hold(jumps=[(113, 7)])).won
    for take_off, ticks in ((112, 7), (114, 7), (113, 6), (113, 8)):
        assert not play(level, hold(jumps=[(take_off, ticks)])).won, (take_off, ticks)


def test_the_low_spikes_need_jumps_pressed_before_landing() -> None:
    """The script presses jump a tick or two before each landing, in the air (the buffer
    keeps the press); pressed so that the second jump leaves a tick later, it loses."""
    level = low_spikes_with_one_tile_between()
    assert SPAWN.right + TUNING.invulnerable_ticks * RUN_PX_PER_TICK < CORRIDOR_LEFT
    first, second, third = BUFFERED_PRESSES
    played = play(level, hold(jumps=[(p, 20) for p in BUFFERED_PRESSES]),
                  asked=(second, third))
    assert played.won and played.lives_lost == 0 and played.airborne == (True, True)
    late = (first, second + 3, third + 3)  # the second jump leaves on tick 179, not 178
    assert not play(level, hold(jumps=[(p, 20) for p in late])).won


def test_the_low_spikes_are_shorter_than_the_widest_row_a_jump_clears() -> None:
    """And their twin's, one pixel longer than that, are not (see UNWINNABLE)."""
    assert LOW_SPIKES_WIDTH < widest_low_row_cleared() == 42


ASCII_WIDTH = 40


def ascii_floor(spikes: range = range(0), gap: range = range(0)) -> list[str]:
    """Rows of a map in whole tiles: the spawn at column 2, the Exit at column 37, a floor
    four rows deep with ``gap`` columns open, and spikes on the floor in ``spikes``."""
    above = [" " * ASCII_WIDTH for _ in range(9)]
    row9 = "".join("P" if c == 2 else "D" if c == 37 else "^" if c in spikes else " "
                   for c in range(ASCII_WIDTH))
    floor = "".join(" " if c in gap else "#" for c in range(ASCII_WIDTH))
    return [*above, row9, floor, floor, floor, floor]


def test_the_check_summary_never_counts_a_map_as_solved_that_was_not(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """Written as Tiled files and checked as a folder: a plain gap (winnable), spikes crossed
    after a life (winnable, as above) and spikes far from the spawn (not winnable). At the
    small budget here the gap is solved and the others are not decided."""
    winnable = {"gap.tmx": ascii_floor(gap=range(12, 16)),
                "spikes_after_a_life.tmx": ascii_floor(spikes=range(4, 9))}
    unwinnable = {"spikes_out_of_reach.tmx": ascii_floor(spikes=range(14, 19))}
    for name, rows in {**winnable, **unwinnable}.items():
        write_tmx(tmp_path, rows, name)
    status = main(["check", "--budget", "1000", "--jobs", "1",
                   "--format", "json", str(tmp_path)])
    report = json.loads(capsys.readouterr().out)
    verdicts = {Path(m["path"]).name: m["verdict"] for m in report["maps"]}
    assert verdicts["gap.tmx"] == "solved"
    assert verdicts["spikes_after_a_life.tmx"] in ("solved", "not decided")
    assert verdicts["spikes_out_of_reach.tmx"] in ("impossible", "not decided")
    solved = [name for name, verdict in verdicts.items() if verdict == "solved"]
    assert set(solved) <= set(winnable)
    summary = report["summary"]
    assert f"{len(solved)} solved" in summary and "all playable" not in summary
    undecided = sum(verdict == "not decided" for verdict in verdicts.values())
    if undecided:
        assert f"{undecided} not decided" in summary
    assert status != 0 and (status == EXIT_UNDECIDED) == ("impossible" not in verdicts.values())


def test_the_wall_carries_the_player_across_a_pit_no_jump_crosses() -> None:
    """The same keys without the wall lose, and the map without it is proven impossible."""
    _, script = WON_BY_SCRIPT["pit crossed pushed by a moving wall"]
    assert DEFAULT_LIMITS.coyote_gap_px < PUSHED_PIT_PX
    assert TUNING.run_speed_px_s < WALL_SPEED_PX_S
    assert play(pushed_across_by_a_wall(), script).won
    assert not play(pushed_across_by_a_wall(wall=False), script).won
    assert judge(pushed_across_by_a_wall(wall=False), EFFORT).kind is Kind.IMPOSSIBLE


def test_the_pit_is_crossed_only_by_a_stomp_on_the_hopper_in_the_air() -> None:
    _, script = WON_BY_SCRIPT["pit crossed by a stomp on a hopper over it"]
    played = play(hopper_over_a_pit(), script)
    assert played.won and played.stomps == 1 and played.lives_lost == 0
    assert not play(hopper_over_a_pit(hopper=False), script).won
    assert judge(hopper_over_a_pit(hopper=False), EFFORT).kind is Kind.IMPOSSIBLE


def test_the_crusher_moves_the_respawn_only_when_the_flag_counts_under_it() -> None:
    """Stepping into the flag one tick earlier, before the crusher reaches the place over
    it, counts the flag with the respawn standing at its foot: the crusher comes down on
    the player there at once, each time it comes back, and every life goes in three ticks."""
    level = respawn_on_a_crusher()
    won = play(level, right_during((60, 198), (CRUSHER_STEP, 10**6)))
    assert won.won and won.lives_lost == 1
    campaign = Campaign(level.path, loader=lambda _path: level)
    script = right_during((60, 198), (CRUSHER_STEP - 1, 10**6))
    lost_on: list[int] = []
    for tick in range(CRUSHER_STEP + 60):
        before = campaign.deaths
        campaign.tick(script(tick))
        if campaign.deaths > before:
            lost_on.append(tick)
    assert campaign.outcome is Outcome.GAME_OVER
    assert len(lost_on) == TUNING.start_lives and lost_on[-1] - lost_on[0] == 2


FLAG_BY_THE_LIFT = Box(64, FLOOR - 32, 16, 32)
LIFT = PlatformSpec(Route(((56, FLOOR - 48), (56, FLOOR - 8))), 32.0, 8.0, 40.0)


def pit_with_a_lift_over_a_flag() -> Level:
    """A pit of 7 tiles (proven impossible on its own), with a Checkpoint near the spawn
    that a lift comes down over: where the flag puts the player depends on where the lift is
    when it counts."""
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(EDGE + 112, FLOOR, WIDTH - EDGE - 112, 64)],
                            SPAWN, list(gap(112).exits), platforms=(LIFT,),
                            checkpoints=(FLAG_BY_THE_LIFT,))


def test_every_respawn_the_game_puts_under_a_lift_lies_in_the_bound_the_proof_uses() -> None:
    """The game's own respawn for the flag, counted on each tick of the lift's round trip
    and more, is inside the range the proof starts the player from."""
    level = pit_with_a_lift_over_a_flag()
    (_, start) = starts(World(level))
    assert start.moved is not None
    world = World(level)
    seen = set()
    for _ in range(300):
        world.step(frozenset())
        place = world._checkpoint_spawn(0, world.solids)
        seen.add((place.x, place.y))
        assert start.moved.left <= place.x <= start.moved.right, place
        assert start.moved.top <= place.y <= start.moved.bottom, place
    assert len(seen) > 10  # the lift moves it about


def test_a_respawn_deep_in_rock_lies_in_the_bound_the_proof_uses() -> None:
    """A flag deep in rock, a small lift's route crossing its foot: the game puts a player
    coming back at the nearest free place, 161.5 px left, off the map's side; a place free
    of the tiles and of the route, 169 px away up and to the right, is what the proof finds
    first, and the range it starts the player from still holds the game's place, wherever
    the lift is on its round trip (the place is worked out from the tiles and the lift: it
    is asked once for each place the lift takes)."""
    pockets = {(18, 10), (19, 4)}
    rock = [Box(c * TILE, r * TILE, TILE, TILE) for c in range(32) for r in range(32)
            if (c, r) not in pockets]
    lift = PlatformSpec(Route(((150.0, 250.0), (150.0, 262.0))), 8.0, 8.0, 40.0)
    level = level_from_boxes(32, 32, rock, Box(290, 162, 12, 14), [Box(304, 64, 16, 16)],
                             platforms=(lift,), checkpoints=(Box(149.5, 241.25, 12, 32),))
    (_, start) = starts(World(level))
    assert start.moved is not None
    world = World(level)
    round_trip = round(2 * 12 / (40.0 * TUNING.tick_s))  # ticks: 12 px down and back up
    lift_places: set[Box] = set()
    for _ in range(round_trip):
        world.step(frozenset())
        (moving,) = world.platforms
        if moving.box in lift_places:
            continue  # the same tiles and lift as on a tick checked before
        lift_places.add(moving.box)
        place = world._checkpoint_spawn(0, world.solids)
        assert place == Box(-12, 259.25, 12, 14)
        assert start.moved.left <= place.x <= start.moved.right
        assert start.moved.top <= place.y <= start.moved.bottom
    (moving,) = world.platforms
    assert moving.box.y == 250.0  # back where it started, every place between taken
    assert len(lift_places) > round_trip // 2


def test_a_respawn_a_platform_may_move_without_a_bound_leaves_the_map_not_decided(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Where no bound is found for where the flag may put the player, the proof says so
    instead of calling the map impossible."""
    monkeypatch.setattr("game.checker.reachable.moved_respawns", lambda *_: None)
    verdict = judge(pit_with_a_lift_over_a_flag(), Effort(budget=500))
    assert verdict.kind is Kind.UNDECIDED
    assert "the proof of impossibility does not cover a respawn moved by a moving Platform " \
        "(the Checkpoint at tile (4,8)" in verdict.finding
    assert judge(gap(112), EFFORT).kind is Kind.IMPOSSIBLE


WON_THROUGH_A_MECHANIC = ("pit crossed pushed by a moving wall",
                          "pit crossed by a stomp on a hopper over it",
                          "high ground reached from a respawn a crusher moved")


@pytest.mark.parametrize("name", WON_THROUGH_A_MECHANIC)
def test_a_map_won_through_a_mechanic_is_not_called_impossible_when_the_search_stops_short(
        name: str) -> None:
    """With no budget to search, the verdict is the proof's alone: it covers the push, the
    stomp anywhere on the hopper's way and the respawn a crusher moves, so it proves nothing."""
    make, script = WON_BY_SCRIPT[name]
    assert play(make(), script).won
    verdict = judge(make(), Effort(budget=1))
    assert verdict.kind is Kind.UNDECIDED, verdict.finding


def test_a_search_counts_every_life_a_crush_takes_within_one_move() -> None:
    """Under the crusher, lives go one a tick: a move of the search may lose all of them,
    and a route found must still win when the game replays it (solve() replays every route
    it returns, and fails loudly on one that does not win). The search is the one the
    crusher's map gets when it is judged at :data:`EFFORT` (:func:`judged`, shared with
    test_a_winnable_map_is_never_called_impossible)."""
    level, verdict = judged("high ground reached from a respawn a crusher moved")
    assert level == respawn_on_a_crusher()
    solution = verdict.solution
    assert solution is not None and solution.moves_tried > 0  # searched, not proven
    assert not solution.found or replay(level.path, solution.held, level)[0]
