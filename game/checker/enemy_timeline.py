"""Enemies go their own way: where each one is at each tick, written down once for a search.

Where it sits: inside :mod:`game.checker.solver`, around every move the search tries.

What it teaches: **leaving out what a choice cannot change.** An enemy meets only the walls,
the moving platforms and the player's stomp (:meth:`game.sim.world.World.step`): where it
walks does not depend on what the player does. So its state at a given tick is the same in
every branch of the search in which it is still alive. The first move to step through a tick
writes down the state of each enemy in play (:meth:`EnemyTimeline.write_down`); a later move
from the same tick leaves out of the world the enemies far from the player
(:meth:`EnemyTimeline.away`), steps without them, and puts them back as they were written
down (:meth:`EnemyTimeline.put_back`). Most enemies are far from the player most of the time,
so most of their steps are saved, while the rest of the tick is not.

It stays exact. After every tick of a move made without some enemies, the player's path that
tick is compared with the place written down for each of them (:meth:`EnemyTimeline.clear_of`);
if the two come within :data:`CLOSE_PX`, or the player loses a life (the respawn may put it
anywhere), the move is made again with every enemy in play. A touch is the only way an enemy
changes the player's tick, so a move that passed the comparison on every tick ends exactly as
it would have with every enemy. Every route the solver finds is replayed by the game as well.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from game.sim.enemy import Enemy
from game.sim.snapshot import put_state, state_of
from game.sim.world import World

AWAY_PX = 16.0  # an enemy is left out of a move only if this much farther off, along x or
#                 along y, than it and the player could close in during the move
CLOSE_PX = 1.0  # a player's path this close to a left-out enemy makes the move again in full
MAX_STATES = 200_000  # states written down at most (about 250 bytes each): bounds the memory

Away = Sequence[tuple[int, Enemy]]  # the enemies left out of a move, with their numbers


class EnemyTimeline:
    """The state of every enemy at every tick some move has stepped through, by number."""

    def __init__(self, world: World) -> None:
        self.world = world
        self.enemies = list(world.enemy_by_number.items())
        tuning = world.tuning
        walking = max((enemy.speed_px_s for _, enemy in self.enemies), default=0.0)
        rising = max(tuning.jump_speed_px_s, tuning.stomp_bounce_px_s)
        carried = 2 * max((platform.speed_px_s for platform in world.platforms), default=0.0)
        # how fast the player and an enemy may close in on each other, along x and along y
        self.closing_x_px_per_tick = (tuning.run_speed_px_s + walking + carried) * tuning.tick_s
        self.closing_y_px_per_tick = (max(rising, tuning.max_fall_speed_px_s)
                                      + max(tuning.hopper_jump_speed_px_s,
                                            tuning.max_fall_speed_px_s) + carried) * tuning.tick_s
        # tick: {number: attributes} of the enemies in play at that tick
        self.states: dict[int, dict[int, dict[str, Any]]] = {}
        self.written = 0  # states written down, in all

    def write_down(self, tick: int) -> None:
        """Write down the state of each enemy in play at ``tick``, unless known already."""
        row = self.states.get(tick)
        if row is None:
            if self.written >= MAX_STATES:
                return
            row = self.states[tick] = {}
        elif len(row) == len(self.enemies):
            return  # every enemy there is, written down already
        for number, enemy in self.enemies:
            if number not in row and enemy.alive() and self.written < MAX_STATES:
                row[number] = state_of(enemy)
                self.written += 1

    def away(self, start: int, ticks: int) -> list[tuple[int, Enemy]]:
        """The enemies a move of ``ticks`` ticks from tick ``start`` may leave out: in play,
        written down at every tick of the move, and too far from the player to meet it."""
        rows: list[dict[int, dict[str, Any]]] = []
        for tick in range(start + 1, start + ticks + 1):
            row = self.states.get(tick)
            if not row:
                return []  # a tick of the move not written down, or with no enemy in play
            rows.append(row)
        x, y, w, h = self.world.player.box
        apart_x = self.closing_x_px_per_tick * ticks + AWAY_PX
        apart_y = self.closing_y_px_per_tick * ticks + AWAY_PX
        away: list[tuple[int, Enemy]] = []
        for number, enemy in self.enemies:
            e_x, e_y, e_w, e_h = enemy.box
            if (enemy.alive()
                    and (e_x - (x + w) > apart_x or x - (e_x + e_w) > apart_x
                         or e_y - (y + h) > apart_y or y - (e_y + e_h) > apart_y)
                    and all(number in row for row in rows)):
                away.append((number, enemy))
        return away

    def leave_out(self, away: Away) -> None:
        """Take ``away`` out of play (out of the world's enemies) for a move."""
        self.world.enemies.remove(*(enemy for _, enemy in away))

    def clear_of(self, away: Away, tick: int) -> bool:
        """Did the player's path at ``tick`` keep more than :data:`CLOSE_PX` from where each
        enemy left out was then, without losing a life?"""
        path = self.world.moves.get(self.world.player)
        if path is None:  # a life was lost, and the player put back at a respawn place
            return False
        left, top, right, bottom = path.path_edges()
        for number, _ in away:
            x, y, w, h = self.states[tick][number]["box"]
            if (x - CLOSE_PX < right and left < x + w + CLOSE_PX
                    and y - CLOSE_PX < bottom and top < y + h + CLOSE_PX):
                return False
        return True

    def put_back(self, away: Away, tick: int) -> None:
        """Put ``away`` back in play as each was written down at ``tick``, in the order the
        world keeps its enemies."""
        for number, enemy in away:
            put_state(enemy, self.states[tick][number])
        back = {number for number, _ in away}
        in_play = [enemy for number, enemy in self.enemies if number in back or enemy.alive()]
        self.world.enemies.empty()
        self.world.enemies.add(*in_play)
