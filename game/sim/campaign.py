"""A run of the game: the current level, lives, score, and moving on from level to level.

Where it sits: above :class:`game.sim.world.World`. The world says what happened in a tick
(coins, stomps, hurts, the exit); the campaign keeps the score and decides what follows:
the next level (the map property ``next_level``), the win, or game over. A campaign told
to play a number of levels (``levels_to_play``) is won when it has finished that many, and
loads no level after them.

The score: each coin adds its ``value``, each stomp adds ``Tuning.stomp_points``. Each finished
level leaves a :class:`LevelResult` (its time, coins of its total, stomps) in
``Campaign.results``, for the level-end banner and the win screen to show.

The assists (``no_damage``, and ``slowed``, which the app sets when it plays the game slower
than real time) are the player's to turn on; a level played with one on at any time is
marked ``assisted`` in its result, and the app keeps no best time of it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum
from pathlib import Path

from game.collision.free_place import penetration_depth
from game.sim.inputs import Actions
from game.sim.level import Level
from game.sim.tuning import Tuning
from game.sim.world import Event, EventKind, Measure, World


class Outcome(Enum):
    RUNNING = "running"
    WON = "won"
    GAME_OVER = "game_over"


LevelLoader = Callable[[Path], Level]


@dataclass(frozen=True)
class LevelResult:
    """One level finished: how long it took in ticks, what was taken of what it held."""

    path: Path
    title: str
    ticks: int
    coins: int
    coins_total: int
    stomps: int
    enemies_total: int
    score: int  # points scored in this level
    assisted: bool = False  # an assist was on at some time in the level (no best time then)


def totals(results: list[LevelResult]) -> tuple[int, int, int, int, int]:
    """Ticks, coins, coins on offer, stomps and score, summed over ``results``.

    >>> one = LevelResult(Path("a.tmx"), "A", 600, 3, 5, 1, 2, 8)
    >>> totals([one, one])
    (1200, 6, 10, 2, 16)
    """
    return (sum(r.ticks for r in results), sum(r.coins for r in results),
            sum(r.coins_total for r in results), sum(r.stomps for r in results),
            sum(r.score for r in results))


class Campaign:
    """Plays levels in order from ``first_level`` until the last exit or the last life."""

    def __init__(self, first_level: Path, tuning: Tuning | None = None, *,
                 loader: LevelLoader, measure: Measure | None = None,
                 no_damage: bool = False, levels_to_play: int | None = None) -> None:
        self.tuning = tuning or Tuning()
        self.levels_to_play = levels_to_play  # None: every level next_level leads on to
        self.loader = loader
        # What every level's world writes down beyond the game (shared: turning the overlay's
        # query log on or off reaches the level in play and every level after it).
        self.measure = measure or Measure()
        self.no_damage = no_damage  # the assist every level's world plays with
        self.slowed = False  # the app plays the game slower than real time (an assist)
        self.world = self._world(loader(first_level))
        self.outcome = Outcome.RUNNING
        self.ticks = 0
        self.lives = self.tuning.start_lives
        self.deaths = 0
        self.score = 0
        self.coins_collected = 0
        self.enemies_stomped = 0
        self.levels_completed = 0
        self.max_penetration_px = 0.0
        self.last_events: list[Event] = []
        self.results: list[LevelResult] = []  # one per level finished, in order
        self._begin_level()

    def _world(self, level: Level) -> World:
        return World(level, self.tuning, measure=self.measure, no_damage=self.no_damage)

    def _begin_level(self) -> None:
        """Start counting the level now in ``self.world`` afresh."""
        self.level_started_tick = self.ticks
        self.level_coins = self.level_stomps = self.level_score = 0
        self.level_assisted = self.assisted

    @property
    def assisted(self) -> bool:
        """An assist is on now: no damage, or the game played slower."""
        return self.no_damage or self.slowed

    def set_assist(self, *, no_damage: bool, slowed: bool) -> None:
        """Turn the assists on or off, from the next tick; a level played with one on at
        any time is marked assisted in its result."""
        self.no_damage, self.slowed = no_damage, slowed
        self.world.no_damage = no_damage
        self.level_assisted = self.level_assisted or self.assisted

    def tick(self, held: Actions) -> list[Event]:
        """Advance one tick; does nothing once the run has been won or lost."""
        if self.outcome is not Outcome.RUNNING:
            return []
        events = self.world.step(held)
        self.ticks += 1
        self.max_penetration_px = max(self.max_penetration_px, self.world.max_penetration_px)
        for event in events:
            if event.kind is EventKind.COIN:
                self.coins_collected += 1
                self.level_coins += 1
                self._add_points(event.value)
            elif event.kind is EventKind.STOMP:
                self.enemies_stomped += 1
                self.level_stomps += 1
                self._add_points(self.tuning.stomp_points)
            elif event.kind is EventKind.HURT and event.value:  # no damage: a free respawn
                self.deaths += 1
                self.lives -= event.value
                if self.lives <= 0:
                    self.outcome = Outcome.GAME_OVER
            elif event.kind is EventKind.EXIT:
                self._complete_level()
        self.last_events = events
        return events

    def _add_points(self, points: int) -> None:
        self.score += points
        self.level_score += points

    def _complete_level(self) -> None:
        self.levels_completed += 1
        level = self.world.level
        self.results.append(LevelResult(
            level.path, level.title, self.ticks - self.level_started_tick, self.level_coins,
            len(level.coins), self.level_stomps, len(level.enemies), self.level_score,
            self.level_assisted))
        next_level = level.next_level
        if next_level is None or self.levels_completed == self.levels_to_play:
            self.outcome = Outcome.WON
        else:
            self.world = self._world(self.loader(next_level))
            self._begin_level()

    def reload(self, level: Level) -> None:
        """Swap in a new version of the current level (``--watch``), keeping the run going.

        The player keeps its place and speed where the new map leaves that place free;
        otherwise it starts again at the new spawn. Coins and enemies come from the new map,
        all of them, so what this level had counted so far is taken back.
        """
        old = self.world.player
        self._take_back_level()
        self.world = self._world(level)
        player = self.world.player
        if (penetration_depth(self.world.solids, old.box) == 0.0
                and old.box.top < level.grid.height_px):
            player.teleport(old.box)
            player.vx, player.vy, player.facing = old.vx, old.vy, old.facing
            self.world.probe_ground(player)

    def restart_level(self) -> None:
        """Start the current level again from its spawn (the pause menu's Restart), with its
        coins and enemies all back, and what it had counted so far taken back."""
        self._take_back_level()
        self.world = self._world(self.world.level)
        self._begin_level()

    def retry_level(self) -> None:
        """After game over: the level lost starts again from its spawn, as
        :meth:`restart_level` does, with the lives a run starts with. The deaths and the
        levels finished before it stay counted."""
        self.restart_level()
        self.lives = self.tuning.start_lives
        self.outcome = Outcome.RUNNING

    def _take_back_level(self) -> None:
        """Take the current level's coins, stomps and points out of the run's totals (its
        coins and enemies are about to be back in play, to be counted again)."""
        self.coins_collected -= self.level_coins
        self.enemies_stomped -= self.level_stomps
        self.score -= self.level_score
        self.level_coins = self.level_stomps = self.level_score = 0
