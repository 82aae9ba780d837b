"""Enemies left out of a move (game.checker.enemy_timeline): a move the solver makes without
the enemies far from the player ends exactly as the same move made with every enemy, and a
player that comes close to one after all, or loses a life, has the move made again in full."""

from __future__ import annotations

import dataclasses
import random
from typing import Any

import pytest

from game.checker import enemy_timeline
from game.checker.enemy_timeline import CLOSE_PX, EnemyTimeline
from game.checker.solver import CHOICES, MOVE_TICKS, Effort, _Search
from game.collision.aabb import Box
from game.levels import LEVELS_DIR, load_level
from game.sim.inputs import Actions
from game.sim.level import EnemySpec, Level
from game.sim.snapshot import Snapshot, state_of
from game.sim.world import World
from tests.maps import level_from_boxes

SUMMIT = LEVELS_DIR / "06-the-summit.tmx"


def state(world: World) -> list[Any]:
    """What a move leaves behind: the player, and every enemy in play, in order."""
    def plain(thing: object) -> dict[str, Any]:
        return {name: value for name, value in state_of(thing).items()
                if name not in ("image", "_rect", "_fitted")}
    return [plain(world.player), world.spawn,
            [(number, plain(enemy)) for number, enemy in world.enemy_by_number.items()
             if enemy.alive()]]


class Counting(EnemyTimeline):
    """The timeline, counting the enemies it leaves out and the moves made again."""

    left_out = 0
    again = 0

    def leave_out(self, away: Any) -> None:
        Counting.left_out += len(away)
        super().leave_out(away)

    def clear_of(self, away: Any, tick: int) -> bool:
        clear = super().clear_of(away, tick)
        Counting.again += not clear
        return clear


def moves_agree(level: Level, routes: list[list[Actions]]) -> None:
    """Play each route from the spawn through the solver's moves (enemies left out where
    far) and through plain World.step; after every move the two must be the same."""
    search = _Search(level, Effort())
    search.timeline = Counting(search.world)
    for route in routes:
        search.start.restore(search.world)
        plain = World(level)
        for move, choice in enumerate(route):
            snapshot = Snapshot.of(search.world)
            search.try_move(snapshot, move * MOVE_TICKS, choice)
            for _ in range(MOVE_TICKS):
                plain.step(choice)
            assert state(search.world) == state(plain), f"move {move}"


def test_moves_without_far_enemies_end_as_moves_with_all_of_them() -> None:
    level = load_level(SUMMIT)
    assert len(level.enemies) >= 5
    rolls = random.Random(7)
    routes = [[rolls.choice(CHOICES[:6]) for _ in range(80)] for _ in range(4)]
    Counting.left_out = 0
    moves_agree(level, routes)
    assert Counting.left_out > 200  # the routes after the first left most enemies out


def near_the_spawn() -> Level:
    """A walker by the spawn, and a pit farther right than it could ever walk: a player who
    falls in comes back beside it."""
    floor = 160
    level = level_from_boxes(40, 14, [Box(0, floor, 320, 64), Box(400, floor, 240, 64),
                                      Box(0, floor - 64, 16, 64)],
                             Box(96, floor - 14, 12, 14), [Box(600, floor - 16, 16, 16)])
    walker = EnemySpec(Box(24, floor - 12, 14, 12), 30.0)
    return dataclasses.replace(level, enemies=(walker,))


def test_a_respawn_beside_an_enemy_left_out_makes_the_move_again_with_it() -> None:
    right = CHOICES[0]
    stand = CHOICES[4]
    # First wait by the spawn (the walker's places are written down), then run into the pit:
    # the walker is far by then and left out, and the respawn puts the player beside it.
    route = [stand] * 12 + [right] * 40 + [stand] * 6
    Counting.left_out = Counting.again = 0
    moves_agree(near_the_spawn(), [route, route])
    assert Counting.left_out > 0
    assert Counting.again > 0


def test_a_path_closer_than_close_px_to_an_enemy_left_out_is_not_clear() -> None:
    world = World(near_the_spawn())
    timeline = EnemyTimeline(world)
    for _ in range(30):  # the player and the walker settle on the floor
        world.step(frozenset())
    timeline.write_down(30)
    walker = world.enemy_by_number[0]
    written = timeline.states[30][0]["box"]
    standing_y = world.player.box.y
    timeline.leave_out([(0, walker)])  # as a move does: only its written place is compared
    for gap_px, clear in ((CLOSE_PX, True), (CLOSE_PX - 0.125, False)):
        world.player.place(Box(written.right + gap_px, standing_y, 12, 14))
        world.step(frozenset())  # standing still: the path is where it was placed
        assert world.player.box.x == written.right + gap_px
        assert timeline.clear_of([(0, walker)], 30) is clear, gap_px


def test_the_states_written_down_stop_at_their_bound(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(enemy_timeline, "MAX_STATES", 3)
    world = World(near_the_spawn())
    timeline = EnemyTimeline(world)
    for tick in range(1, 6):
        world.step(frozenset())
        timeline.write_down(tick)
    assert timeline.written == 3
    assert sorted(timeline.states) == [1, 2, 3]


def test_an_enemy_is_left_out_only_when_written_down_for_the_whole_move() -> None:
    world = World(near_the_spawn())
    timeline = EnemyTimeline(world)
    world.player.place(Box(600, 100, 12, 14))  # far from the walker
    assert timeline.away(0, MOVE_TICKS) == []  # nothing written down yet
    for tick in range(1, MOVE_TICKS):
        world.step(frozenset())
        timeline.write_down(tick)
    assert timeline.away(0, MOVE_TICKS) == []  # the move's last tick is missing
    world.step(frozenset())
    timeline.write_down(MOVE_TICKS)
    world.player.place(Box(600, 100, 12, 14))
    assert [number for number, _ in timeline.away(0, MOVE_TICKS)] == [0]

