"""One level in play, and the tick that advances it by 1/60 s.

Where it sits: the middle of the game. :meth:`World.step` is the whole update, in order: a
table of contents of its phases, each a short method below it; the campaign
(:mod:`game.sim.campaign`) calls it once per tick. The
renderer (:mod:`game.app.render`) reads what it leaves behind and changes nothing of it but
the sprites' pictures (each sprite's ``update``).

The order of a tick (``tests/test_tick_order.py`` checks that this list, the numbered
comments in :meth:`World.step` and the README's tour name the same steps in the same order):

1. **Intent**: the player reads the held actions, the enemies look ahead; each sets a velocity.
2. **Platforms**: each moving platform advances along its path, pushing the bodies in its way
   and carrying its riders through the same swept moves, so never into a wall (one whose
   route no body touches only advances; its box is worked out when next read).
3. **x pass**: each body moves along x, swept against the level's solids, stopping flush
   (one call of :func:`~game.collision.axis_sweep.move_body` makes a body's steps 3 and 4).
4. **y pass**: then along y the same way, and is placed; the floor it landed on, or else
   the 1-pixel probe, sets ``on_ground``.
5. **React**: bodies read what their moves hit (land, bump, turn round).
6. **Pickups**: the coins on the path the player travelled leave their group (``kill``),
   tested only on a tick when that path reaches a cell that holds a trigger.
7. **Contacts**: the pairs the player touches; a tracker turns them into start/end events
   (entering the exit completes the level); a checkpoint touched or passed over for the
   first time moves the respawn point there.
8. **Enemies and hazards**: a touch from above is a stomp, any other touch hurts, and so do
   spikes, for as long as they are touched.
9. **The void and the crush**: falling below the map, or being pushed into a wall by a
   platform, costs a life, and so does any touch of an enemy that is not a stomp: the player
   respawns at the checkpoint counted last, else the spawn. (With the ``no_damage``
   assist no touch hurts, and a fall or a crush respawns the player without a life lost.)
10. **Camera**: follows the player.

Before step 1 a squashed enemy's time on screen counts down; after step 9, when a report
asks for it, the deepest overlap of any body with a solid is measured (it should stay 0).

Solids never go through a trigger's test: walls only meet bodies in the movement code.
Each step asks the source of solids named for it in :class:`~game.sim.solids.Lookups`, and
the moves of steps 3 and 4 are handed on (to the reactions, the triggers, and in
``World.moves`` to the overlay), never left on the bodies to be read back.

Two things a tick writes down beyond the game itself only when asked (:class:`Measure`):
the deepest overlap of any body with a solid after resolution (the report's
``max_penetration_px``), and every lookup's purpose, cells and shapes (what the debug
overlay draws: the sources are then wrapped by :mod:`game.sim.query_log`). Neither changes
what happens, and a tick nobody measures does neither.
"""

from __future__ import annotations

import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from enum import Enum
from types import MappingProxyType

import pygame

from game.collision.aabb import Box
from game.collision.axis_sweep import BodyMoves, Edges, ground_under, move_body, move_x, move_y
from game.collision.contacts import ContactTracker
from game.collision.free_place import nearest_free_place, penetration_depth
from game.collision.shapes import ShapeSource, TileKind, TileShape
from game.sim.body import Body
from game.sim.camera import Camera
from game.sim.enemy import Enemy, EnemyKind, Squashed
from game.sim.inputs import Actions
from game.sim.level import Level
from game.sim.pickups import Checkpoint, Coin, Exit, Trigger, TriggerCells
from game.sim.platforms import Platform, PlatformIndex, push
from game.sim.player import Player
from game.sim.query_log import QueryLog, logged_lookups
from game.sim.solids import LevelSolids, Lookups
from game.sim.tuning import Tuning

SQUASH_TICKS = 20  # how long a stomped enemy stays on screen, flattened


ContactKey = tuple[str, int]  # ("player", 0), ("enemy", 3), ("exit", 0), ("hazard", cell)
PLAYER_KEY: ContactKey = ("player", 0)


class EventKind(Enum):
    COIN = "coin"
    STOMP = "stomp"
    HURT = "hurt"
    EXIT = "exit"
    JUMP = "jump"
    CHECKPOINT = "checkpoint"


@dataclass(frozen=True)
class Event:
    """Something that happened in a tick, for the campaign, the sounds and the HUD."""

    kind: EventKind
    value: int = 0
    where: Box | None = None


@dataclass
class TickStats:
    """What the last tick cost, recorded for the debug overlay and the report (the cells
    and shapes only while its lookups are logged, ``Measure.queries``; else 0)."""

    cells_visited: int = 0
    shapes_tested: int = 0
    collision_s: float = 0.0


@dataclass
class Measure:
    """What a tick writes down beyond the game itself; both off unless something reads them.

    ``penetration``: the deepest overlap of any body with a solid after resolution, kept in
    ``World.max_penetration_px`` (the runner turns it on for ``--report``, tests for their
    checks). ``queries``: every lookup's purpose, cells and shapes, kept in
    ``World.query_log``, and their count in ``World.stats`` (the debug overlay turns it on).
    """

    penetration: bool = False
    queries: bool = False


def crossed(path: BodyMoves, thing: Trigger | Enemy, edges: Edges | None = None) -> bool:
    """Did the body's path this tick (its moves) overlap the thing? First, cheaply: does
    the thing overlap the whole path's ``edges`` (:meth:`BodyMoves.path_edges`)?"""
    (left, top, right, bottom), (x, y, w, h) = edges or path.path_edges(), thing.box
    return x < right and left < x + w and y < bottom and top < y + h and path.crosses(thing.box)


@dataclass
class World:
    """A level's live state: its bodies, its groups, its camera and its last tick's record."""

    level: Level
    tuning: Tuning = field(default_factory=Tuning)
    camera: Camera = field(default_factory=Camera)
    measure: Measure = field(default_factory=Measure)
    no_damage: bool = False  # the assist: enemies and spikes never hurt, a fall costs no life

    def __post_init__(self) -> None:
        self.tuning = self.tuning.with_map_properties(self.level.properties)
        self.platforms: pygame.sprite.Group[Platform] = pygame.sprite.Group(
            Platform(spec, number) for number, spec in enumerate(self.level.platforms))
        self._platform_list = tuple(self.platforms)  # by number; never changes
        self.platform_index = PlatformIndex(self.level.grid, self._platform_list)
        # The level's tiles with this world's platforms beside them: what every lookup asks.
        self.grid = self.level.grid
        self.solids = LevelSolids(self.grid, self.platform_index)
        self.map_w_px, self.map_h_px = self.grid.width_px, self.grid.height_px
        self.query_log = QueryLog()  # filled only while measure.queries is on
        self._plain = Lookups.plain(self.solids, self._platform_list)
        self._logged = logged_lookups(self.solids, self.query_log)
        self.moves: dict[Body, BodyMoves] = {}  # the last tick's moves (the overlay draws them)
        self.checkpoints: pygame.sprite.Group[Checkpoint] = pygame.sprite.Group(
            Checkpoint(box) for box in self.level.checkpoints)
        self._checkpoint_list = tuple(self.checkpoints)  # by number; a flag never leaves play
        self.checkpoint_reached: int | None = None
        self.checkpoints_counted: set[int] = set()  # each moves the respawn point once
        self.squashed: pygame.sprite.Group[Squashed] = pygame.sprite.Group()  # drawn only
        # A spawn drawn inside a wall is moved to the nearest free place before play starts.
        self.spawn = nearest_free_place(self.grid, self.level.spawn)
        self.player = Player(self.spawn, self.tuning)
        self.players: pygame.sprite.GroupSingle[Player] = pygame.sprite.GroupSingle(self.player)
        self.enemies: pygame.sprite.Group[Enemy] = pygame.sprite.Group(
            Enemy(nearest_free_place(self.grid, spec.box),
                  spec.speed_px_s if spec.speed_px_s is not None
                  else self.tuning.enemy_speed_px_s, EnemyKind(spec.kind))
            for spec in self.level.enemies)
        self.coins: pygame.sprite.Group[Coin] = pygame.sprite.Group(
            Coin(spec.box, spec.value) for spec in self.level.coins)
        self.exits: pygame.sprite.Group[Exit] = pygame.sprite.Group(
            Exit(box) for box in self.level.exits)
        # every enemy by number, stomped or not (read-only: a snapshot need not copy it)
        self.enemy_by_number = MappingProxyType(dict(enumerate(self.enemies)))
        self.trigger_cells = TriggerCells(self.grid.tile_w, self.grid.tile_h)
        for trigger in (*self.coins, *self.exits, *self.checkpoints):
            self.trigger_cells.file(trigger.box)
        self.hazard_cells = TriggerCells(self.grid.tile_w, self.grid.tile_h)  # spikes, alike
        for shape in self.grid.shapes():
            if shape.kind is TileKind.HAZARD:
                self.hazard_cells.file(shape.box)
        self.contacts: ContactTracker[ContactKey] = ContactTracker()
        self.stats = TickStats()
        self.max_penetration_px = 0.0
        self.probe_ground(self.player)
        self.camera.follow(self.player.box, self.grid.width_px, self.grid.height_px)

    def bodies(self) -> list[Body]:
        """Everything that moves, in the order it moves: the player, then enemies."""
        return [self.player, *self.enemies]

    def step(self, held: Actions) -> list[Event]:
        """Advance the level by one tick of ``tuning.tick_s`` seconds: the phases below, in
        order, each a method of its own."""
        lookups = self._lookups()  # the source of solids each step asks
        started = time.perf_counter()
        events: list[Event] = []
        for squash in self.squashed:  # a stomped enemy's time on screen counts down
            squash.fade()  # (a Group iterates over a copy: kill() is safe)
        bodies = self.bodies()
        before = {body: body.box for body in bodies}
        # 1. Intent: entities choose velocities; none of them moves itself.
        self._choose_velocities(held, lookups.ledges, events)
        # 2. Platforms: each moves along its path, pushing and carrying bodies.
        if self._platform_list:
            self._move_platforms(bodies, lookups.platforms)
        # 3. x pass: each body moves along x, stopping flush at the first solid face swept;
        # 4. y pass: then along y from there, is placed, and finds the ground under its feet.
        moves = self.moves = self._move_bodies(bodies, lookups.moving_bodies)
        # 5. React: each body reads what its own moves hit.
        for body, moved in moves.items():
            body.react(moved.x, moved.y)
        # 6. Pickups: the coins on the player's path, when it nears a trigger's cell.
        path = moves[self.player]
        edges = path.path_edges()
        near_trigger = self.trigger_cells.reached_by(*edges)
        if near_trigger:
            self._collect_coins(path, edges, events)
        # 7. Contacts: what the player touches now; entering the exit, checkpoints.
        touching = self._player_contacts(path, edges, near_trigger, lookups.hazards)
        self._enter_contacts(touching, before[self.player], edges, lookups, events)
        # 8. Enemies and hazards: a stomp from above; any other touch hurts.
        hurt = bool(touching) and self._meet_enemies_and_hazards(touching, before, events)
        # 9. The void and the crush: falling below the map or pushed into a wall.
        self._lose_lives(hurt, events)
        self._write_down(lookups, started)
        # 10. Camera: follow the player, inside the map.
        self.camera.follow(self.player.box, self.map_w_px, self.map_h_px)
        return events

    def _lookups(self) -> Lookups:
        """The sources this tick asks: plain, or each wrapped to write its lookups in a
        fresh :attr:`query_log` while ``measure.queries`` is on (the debug overlay). A log
        left from a measured tick is emptied on the first tick nobody measures."""
        if self.measure.queries or self.query_log.queries:
            self.query_log.clear()
        return self._logged if self.measure.queries else self._plain

    def _choose_velocities(self, held: Actions, ledges: ShapeSource,
                           events: list[Event]) -> None:
        """Step 1: the player reads the held actions, the enemies look ahead for a ledge."""
        if self.player.decide(held, self.tuning):
            events.append(Event(EventKind.JUMP))
        for enemy in self.enemies:
            enemy.decide(ledges, self.tuning)

    def _move_platforms(self, bodies: list[Body], lookups: Sequence[ShapeSource]) -> None:
        """Step 2: each platform moves along its path, pushing what is in its way and
        carrying what rides it, through the same swept moves (so never into a wall). Only
        the platforms a body could meet push or carry; the others only advance."""
        for body in bodies:
            body.crushed = False
        dt = self.tuning.tick_s
        awake = self._platforms_near(bodies)
        for platform in self._platform_list:
            if platform in awake:
                pushed = self._move_platform(platform, dt, bodies, lookups[platform.number])
                for body in pushed:
                    awake |= self._platforms_near([body])  # moved into another's way?
            else:
                platform.advance(dt)

    def _move_bodies(self, bodies: list[Body], solids: ShapeSource) -> dict[Body, BodyMoves]:
        """Steps 3 and 4: each body's move (:func:`move_body`: the x pass, then the y pass
        with its corner slide, then the probe under the feet); the body is placed, once a
        tick, and stands on what the move found."""
        dt = self.tuning.tick_s
        moves: dict[Body, BodyMoves] = {}
        for body in bodies:
            moved = moves[body] = move_body(
                solids, body.box, body.vx * dt, body.vy * dt,
                through_one_way=body.dropping_through, corner_px=body.corner_correction_px)
            body.box = moved.y.box  # the drawn rect is derived from the box when read
            self._stand(body, moved.ground)
        return moves

    def probe_ground(self, body: Body) -> None:
        """The one-pixel probe under the feet, away from a tick (a level start, a reload):
        what the body stands (or rides) on, if anything."""
        self._stand(body, ground_under(self.solids, body.box,
                                       through_one_way=body.dropping_through))

    def _stand(self, body: Body, ground: TileShape | None) -> None:
        """The body stands on ``ground`` (or is in the air), and rides it if it is a
        platform's."""
        body.standing_on = ground
        body.on_ground = ground is not None
        body.riding = (None if ground is None or ground.col != -1
                       else self.platform_index.platform_of(ground))

    def _collect_coins(self, path: BodyMoves, edges: Edges, events: list[Event]) -> None:
        """Step 6: coins leave their group (``kill``) as the player's path crosses them (a
        Group is walked over a copy, so a coin may leave it on the way)."""
        for coin in self.coins:
            if crossed(path, coin, edges):
                coin.kill()
                events.append(Event(EventKind.COIN, coin.value, coin.box))

    def _enter_contacts(self, touching: set[tuple[ContactKey, ContactKey]], was: Box,
                        edges: Edges, lookups: Lookups, events: list[Event]) -> None:
        """Step 7: the tracker reports only what changed, so entering the exit is one event
        however long the player stands in it. A checkpoint counts the first time the player
        touches it or passes over it (a jump over the flag counts; walking past below its
        foot, or along a floor more than the flag's height above its top, does not): the
        respawn point moves there, and never back to an earlier flag walked past again."""
        entered = [key for pair in self.contacts.update(touching).started for key in pair]
        events.extend(Event(EventKind.EXIT) for kind, _ in entered if kind == "exit")
        for number, flag in enumerate(self._checkpoint_list):
            if number not in self.checkpoints_counted and (
                    ("checkpoint", number) in entered or self._passed_over(was, edges, flag.box)):
                self.checkpoints_counted.add(number)
                self.spawn = self._checkpoint_spawn(number, lookups.checkpoint_spawn)
                self.checkpoint_reached = number
                for flag_number, other in enumerate(self.checkpoints):
                    other.reached = flag_number == number
                events.append(Event(EventKind.CHECKPOINT, number))

    def _meet_enemies_and_hazards(self, touching: set[tuple[ContactKey, ContactKey]],
                                  before: dict[Body, Box], events: list[Event]) -> bool:
        """Step 8: landing on top is a stomp; any other touch hurts. Spikes hurt for as long
        as they are touched (not only on contact), so standing in them when the
        invulnerability runs out still costs a life. True when the player is hurt."""
        hurt = False
        for _, (kind, number) in sorted(touching):
            if kind == "enemy":
                enemy = self.enemy_by_number[number]
                if self._came_from_above(before[self.player], before[enemy]):
                    enemy.kill()
                    self.squashed.add(Squashed(enemy.box, SQUASH_TICKS))
                    self.player.bounce(self.tuning.stomp_bounce_px_s)
                    events.append(Event(EventKind.STOMP, 1, enemy.box))
                elif not self.player.invulnerable:
                    hurt = True
            elif kind == "hazard" and not self.player.invulnerable:
                hurt = True
        return hurt

    def _lose_lives(self, hurt: bool, events: list[Event]) -> None:
        """Step 9: falling below the map, or being pushed into a wall by a platform, costs a
        life (and removes an enemy). A respawn leaves no path behind. With ``no_damage``
        (an assist) only a fall or a crush respawns the player, and it costs no life."""
        if self.no_damage:  # the assist: no touch hurts; a fall or a crush still respawns
            hurt = False
        if self.player.box.y >= self.map_h_px or self.player.crushed:
            hurt = True
        for enemy in self.enemies:  # a stomped one is out of play already
            if enemy.box.y >= self.map_h_px or enemy.crushed:
                enemy.kill()
        if hurt and not any(e.kind is EventKind.EXIT for e in events):
            lives = 0 if self.no_damage else 1  # the event's value: the lives it costs
            events.append(Event(EventKind.HURT, lives, self.player.box))
            self.player.respawn(self.spawn, self.tuning.invulnerable_ticks)
            del self.moves[self.player]

    def _write_down(self, lookups: Lookups, started: float) -> None:
        """After step 9: what the tick cost, and, when a report asks for it, the deepest
        overlap of any body with a solid (it should stay 0; its lookups are left out of
        the stats)."""
        counted = self.query_log.stats  # the work of the lookups, when they are written down
        self.stats = TickStats(counted.cells_visited, counted.shapes_tested,
                               time.perf_counter() - started)
        if self.measure.penetration:
            for body in self.bodies():
                self.max_penetration_px = max(self.max_penetration_px,
                                              penetration_depth(lookups.penetration, body.box))

    def _player_contacts(self, path: BodyMoves, edges: Edges, near_trigger: bool,
                         hazards: ShapeSource) -> set[tuple[ContactKey, ContactKey]]:
        """The pairs (player, thing) whose boxes the player's ``path`` overlapped this tick.

        ``edges`` bound the whole path: the spikes are looked up (in ``hazards``) only when
        they reach a cell that holds one; exits and checkpoints are tested only when the path
        is ``near_trigger``.
        """
        pairs: set[tuple[ContactKey, ContactKey]] = set()
        if near_trigger:
            pairs |= {(PLAYER_KEY, ("exit", number)) for number, goal in enumerate(self.exits)
                      if crossed(path, goal, edges)}
            pairs |= {(PLAYER_KEY, ("checkpoint", number))
                      for number, flag in enumerate(self.checkpoints)
                      if crossed(path, flag, edges)}
        pairs |= {(PLAYER_KEY, ("enemy", number))
                  for number, enemy in self.enemy_by_number.items()
                  if crossed(path, enemy, edges) and enemy.alive()}
        if not self.hazard_cells.reached_by(*edges):
            return pairs  # no spike anywhere near the path
        cols = self.grid.cols
        for move in (path.x, path.y):
            pairs |= {(PLAYER_KEY, ("hazard", entry.shape.row * cols + entry.shape.col))
                      for entry in hazards.entries_in(*move.path_edges)
                      if entry.kind is TileKind.HAZARD}
        return pairs

    def _platforms_near(self, bodies: list[Body]) -> set[Platform]:
        """The platforms a body could meet this tick: those whose route region it touches,
        and those it rides."""
        if not self._platform_list:
            return set()
        near = self.platform_index.near([body.box for body in bodies])
        for body in bodies:
            if body.riding is not None:
                near.add(body.riding)
        return near

    def _move_platform(self, platform: Platform, dt: float, bodies: list[Body],
                       others: ShapeSource) -> list[Body]:
        """Advance a platform one tick, one axis at a time, pushing bodies in its way and
        carrying its riders against ``others`` (the solids less this platform); return the
        bodies it moved."""
        x, y, w, h = platform.box
        platform.advance(dt)
        to_x, to_y = platform.box.x, platform.box.y
        dx, dy = to_x - x, to_y - y
        moved: list[Body] = []
        if dx == 0 and dy == 0:
            return moved
        riders = [body for body in bodies if body.riding is platform]
        for step, axis, at in ((dx, "x", Box(to_x, y, w, h)), (dy, "y", Box(to_x, to_y, w, h))):
            if step == 0:
                continue
            move = move_x if axis == "x" else move_y
            left, top, right, bottom = at.left, at.top, at.right, at.bottom
            solid = right > left and bottom > top
            for body in bodies:
                bx, by, bw, bh = body.box
                if (solid and bw > 0 and bh > 0 and bx < right and left < bx + bw
                        and by < bottom and top < by + bh):
                    pushed_to, body.crushed = push(others, body.box, at, axis, step)
                    body.place(pushed_to)
                    moved.append(body)
                elif body in riders:
                    body.place(move(others, body.box, step).box)
                    moved.append(body)
        return moved

    def _passed_over(self, was: Box, reach: Edges, flag: Box) -> bool:
        """Did the player's centre reach or cross the flag's centre line this tick, with its
        path within the flag's height of it: some of the path above the flag's foot (not
        below it), and some no higher than one flag height over its top (a jump over it,
        not a walk along a floor far above it)?"""
        centre = flag.x + flag.w / 2
        now = self.player.box
        crossed_line = (was.x + was.w / 2 - centre) * (now.x + now.w / 2 - centre) <= 0
        _, path_top, _, path_bottom = reach
        return crossed_line and path_top < flag.bottom and path_bottom > flag.top - flag.h

    def _checkpoint_spawn(self, number: int, solids: ShapeSource) -> Box:
        """Where the player comes back after touching checkpoint ``number``: standing in it."""
        flag = list(self.checkpoints)[number].box
        w, h = self.level.spawn.w, self.level.spawn.h
        return nearest_free_place(solids, Box(flag.x + (flag.w - w) / 2,
                                              flag.bottom - h, w, h))

    @staticmethod
    def _came_from_above(player_before: Box, enemy_before: Box) -> bool:
        """A stomp: the player's feet were at or above the enemy's head before this tick."""
        return player_before.bottom <= enemy_before.top
