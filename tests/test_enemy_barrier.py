"""A walker that blocks the only way (game/checker/enemy_barrier.py): a passage one tile high,
the only way to the Exit, with a walker patrolling four tiles of its floor. Proven
impossible where the game's rules say no input gets past it; each near-miss twin, a pixel
or a mechanic away, is won by an input script the game plays here, and is never called
impossible.

The passage's floor runs from x = 192 to 256 between two notches 8 px wide (the walker,
14 px wide, turns back at them; the player, 12 px wide, walks over them), under a ceiling
from x = 160 to the map's right edge. The enemy is then somewhere in x = 191..257 (two of
its 0.5 px steps past an end at most), and a player is past it only once its box's left
edge is at 191 + 14 = 205 or more. After a lost life the player comes back standing at
the spawn, protected for 90 ticks, in which it runs at most 133.5 px (0.5 + 1 + 1.5 px a
tick from standing): so from a spawn at x < 205 - 133.5 = 71.5 no protected run gets past.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import pytest

from game.checker.enemy_barrier import MAX_FLOODS, protected_run_px
from game.checker.reachable import Reach, open_path
from game.checker.solver import Effort
from game.checker.verdict import Kind, judge, prove_impossible
from game.collision.aabb import Box
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, Actions
from game.sim.level import EnemySpec, Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.maps import level_from_boxes

COLS, ROWS, TILE = 40, 14, 16
WIDTH, FLOOR = COLS * TILE, 10 * TILE  # the floor's top
RUN = (192, 256)  # the walker's floor, between two notches
MOUTH = 160  # where the passage's ceiling begins
LOW_CEILING = 144  # the passage's ceiling: one tile over the floor
HOLE = 480  # a hole in the ceiling far beyond the walker
SLOT = 224  # a shaft through the ceiling, over the walker's floor, for a crusher
FIRST_SPAWN_OUT_OF_REACH = 71  # the furthest right a spawn is proven out of reach
MIRRORED_WAIT = 160  # mirrored, from x = 75: the tick the winning run sets off
RIGHT, JUMP = Action.RIGHT, Action.JUMP
Script = Callable[[int], Actions]


def passage(spawn_x: float = 32.0, ceiling: float = LOW_CEILING, flag_x: float | None = None,
            slot: bool = False, mirrored: bool = False, hole: bool = False) -> Level:
    """The passage map: the spawn at ``spawn_x``, the ceiling's underside at ``ceiling``, a
    Checkpoint at ``flag_x`` (if any), and (``slot``) a shaft through the ceiling over the
    walker's floor with a crusher (a Platform a tile square) going up and down in it;
    ``mirrored``: all of it mirrored left to right (the spawn on the right); ``hole``: a
    hole in the ceiling at x = 480, far beyond the walker, a way round it."""
    left, right = RUN
    solids = [Box(0, FLOOR, left - 8, 64), Box(left - 8, FLOOR + 16, 8, 48),
              Box(left, FLOOR, right - left, 64), Box(right, FLOOR + 16, 8, 48),
              Box(right + 8, FLOOR, WIDTH - right - 8, 64)]
    if slot:
        solids += [Box(MOUTH, 0, SLOT - MOUTH, ceiling),
                   Box(SLOT + TILE, 0, WIDTH - SLOT - TILE, ceiling)]
    elif hole:
        solids += [Box(MOUTH, 0, HOLE - MOUTH, ceiling),
                   Box(HOLE + TILE, 0, WIDTH - HOLE - TILE, ceiling)]
    else:
        solids.append(Box(MOUTH, 0, WIDTH - MOUTH, ceiling))
    crusher = PlatformSpec(Route(((SLOT, 64.0), (SLOT, FLOOR - 20.0))), TILE, TILE, 40.0)
    flags = [Box(flag_x, FLOOR - 32, 16, 32)] if flag_x is not None else []
    spawn, goal, walker = (Box(spawn_x, FLOOR - 14, 12, 14), Box(WIDTH - 48, FLOOR - 16, 16, 16),
                           Box(216.0, FLOOR - 12, 14, 12))

    def flip(box: Box) -> Box:
        return Box(WIDTH - box.right, box.y, box.w, box.h) if mirrored else box
    if mirrored:
        crusher = PlatformSpec(Route(tuple((WIDTH - x - TILE, y)
                                           for x, y in crusher.path.points)), TILE, TILE, 40.0)
    return level_from_boxes(COLS, ROWS, [flip(b) for b in solids], flip(spawn), [flip(goal)],
                            checkpoints=tuple(flip(b) for b in flags),
                            platforms=(crusher,) if slot else (),
                            enemies=(EnemySpec(flip(walker)),))


def right_from(first: int, jumps: tuple[int, int] | None = None) -> Script:
    """Hold right from tick ``first`` on, and jump for (first tick, ticks) if given."""
    def held(tick: int) -> Actions:
        keys = {RIGHT} if tick >= first else set()
        if jumps is not None and jumps[0] <= tick < jumps[0] + jumps[1]:
            keys.add(JUMP)
        return frozenset(keys)
    return held


def left_from(first: int) -> Script:
    """Hold left from tick ``first`` on."""
    return lambda tick: frozenset({Action.LEFT}) if tick >= first else frozenset()


def play(level: Level, script: Script, ticks: int = 1_200) -> tuple[bool, int, int]:
    """Play ``script`` as the game does, with its lives: won?, lives lost, enemies stomped."""
    campaign = Campaign(level.path, loader=lambda _path: level)
    for tick in range(ticks):
        campaign.tick(script(tick))
        if campaign.levels_completed or campaign.outcome is not Outcome.RUNNING:
            break
    return campaign.levels_completed > 0, campaign.deaths, campaign.enemies_stomped


def proven(level: Level) -> bool:
    verdict, _ = prove_impossible(level)
    return verdict is not None and verdict.kind is Kind.IMPOSSIBLE


def test_a_walker_in_the_only_low_passage_is_proven_to_block_it() -> None:
    """The verdict names the enemy, says what was proven, and needs no search."""
    verdict = judge(passage(), Effort(budget=6_000))
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.tile == (13, 9) and verdict.solution is None
    assert verdict.finding.startswith(
        "impossible: the enemy at tile (13,9) blocks the only way to the Exit, in a passage "
        "too low to jump over it or stomp it, and no place the player comes back to after "
        "losing a life is near enough to pass it while protected (for 90 ticks, at most "
        "134 px at a run)")
    assert play(passage(), right_from(0)) == (False, 3, 0)  # every life lost at the walker


def test_the_protected_run_is_the_game_s_own_run_from_standing() -> None:
    """The bound the proof uses is what the game's player runs, from standing, in the 90
    ticks of protection (to a hundred-thousandth of a pixel)."""
    level = passage(spawn_x=0.0, ceiling=FLOOR - 64)
    world = World(level)
    start = world.player.box.x
    for _ in range(Tuning().invulnerable_ticks):
        world.step(frozenset({RIGHT}))
    assert world.player.box.x - start == 133.5
    assert 133.5 <= protected_run_px(world.tuning) < 133.5 + 1e-3


def test_a_spawn_near_enough_for_the_protection_to_carry_the_player_past_is_not_proven(
        ) -> None:
    """From a spawn at x = 71 no protected run gets past the walker: proven. From 72 the
    proof's bound could: not proven. From 75 a run that loses a life at the walker comes
    back protected and runs through it to the Exit (from 72 to 74 no such run gets past,
    and the map stays not decided)."""
    assert proven(passage(spawn_x=FIRST_SPAWN_OUT_OF_REACH))
    assert not proven(passage(spawn_x=FIRST_SPAWN_OUT_OF_REACH + 1))
    near = passage(spawn_x=75)
    assert not proven(near)
    assert play(near, right_from(56)) == (True, 1, 0)


def test_the_same_edge_holds_mirrored() -> None:
    """Mirrored left to right (the spawn on the right, the walker first walking towards
    it), a spawn as far from the walker's floor is proven out of reach, one pixel nearer
    is not, and the twin won from x = 75 is won mirrored too."""
    assert proven(passage(spawn_x=FIRST_SPAWN_OUT_OF_REACH, mirrored=True))
    assert not proven(passage(spawn_x=FIRST_SPAWN_OUT_OF_REACH + 1, mirrored=True))
    assert play(passage(spawn_x=75, mirrored=True), left_from(MIRRORED_WAIT)) == (True, 1, 0)


def test_a_passage_a_pixel_taller_lets_the_player_stomp_the_walker() -> None:
    """A passage 25 px high leaves 13 px over the walker's 12 px: too little for the
    player's 14 px, proven. At 26 px a jump's feet reach the walker's head, a stomp: not
    proven, and won with no life lost."""
    assert proven(passage(ceiling=FLOOR - 25))
    taller = passage(ceiling=FLOOR - 26)
    assert not proven(taller)
    assert play(taller, right_from(0, jumps=(122, 3))) == (True, 0, 1)


def test_a_checkpoint_near_enough_to_the_walker_gives_a_respawn_that_passes_it() -> None:
    """A flag counted on the way puts the respawn at its foot, 2 px in from its left edge:
    the same edge as the spawn's. A flag at x = 69 (the player comes back at 71) is proven
    too far; at 70 it is not proven; at 73 (back at 75) a run that loses a life at the
    walker comes back protected and runs through. A flag on the walker's own floor is
    counted on the way in, and the player comes back beside the walker: won as well."""
    assert proven(passage(flag_x=FIRST_SPAWN_OUT_OF_REACH - 2))
    assert not proven(passage(flag_x=FIRST_SPAWN_OUT_OF_REACH - 1))
    near = passage(flag_x=73)
    assert not proven(near)
    assert play(near, right_from(27)) == (True, 1, 0)
    on_its_floor = passage(flag_x=RUN[0])
    assert not proven(on_its_floor)
    assert play(on_its_floor, right_from(0)) == (True, 1, 0)


def test_a_crusher_that_can_crush_the_walker_opens_the_way() -> None:
    """A crusher coming down a shaft through the ceiling onto the walker's floor crushes the
    walker, and the player walks through: not proven, and won with no life lost (without
    the shaft and its crusher, proven)."""
    assert proven(passage())
    crushed = passage(slot=True)
    assert not proven(crushed)
    assert play(crushed, right_from(0)) == (True, 0, 0)


def test_a_platform_that_could_carry_the_player_on_counts_in_the_protected_run() -> None:
    """A ferry (a Platform) shuttling over the spawn's side, short of the passage, may carry
    a protected player on faster than it runs: the proof lets the player be carried to the
    far end of its path and run on from there, so the map is not proven (without the
    ferry it is)."""
    level = passage()
    ferry = PlatformSpec(Route(((0.0, FLOOR - 36.0), (100.0, FLOOR - 36.0))), 32.0, 8.0,
                         120.0)
    assert proven(level) and not proven(replace(level, platforms=(ferry,)))


def test_the_proof_floods_the_map_at_most_a_bounded_number_of_times(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Forty walkers in a passage with a way round it (a hole in its ceiling beyond their
    floor): each could be the one that blocks it, and each costs a flood of the map's
    cells, but no more than :data:`MAX_FLOODS` are taken."""
    holed = passage(hole=True)
    assert proven(passage()) and not proven(holed)
    floods: list[int] = []
    counting = open_path

    def counted(world: World, **closed: frozenset[tuple[int, int]]) -> Reach:
        floods.append(1)
        return counting(world, **closed)
    monkeypatch.setattr("game.checker.enemy_barrier.open_path", counted)
    crowded = replace(holed, enemies=holed.enemies * 40)
    assert not proven(crowded)
    assert len(floods) == MAX_FLOODS


def test_an_enemy_the_proof_cannot_keep_to_its_floor_is_not_proven() -> None:
    """A hopper, in the walker's place, hops off its floor: the proof says nothing of it."""
    level = passage()
    hopper = EnemySpec(level.enemies[0].box, None, "hopper")
    assert proven(level) and not proven(replace(level, enemies=(hopper,)))
