"""Life on screen: dust, squash and stretch, a shake and a burst on a stomp, a pop on a coin,
a glow as a checkpoint's lantern lights, and a beat of gathering light on a respawn.

Where it sits: in the window, beside the renderer. After every tick the window hands the
tick's events to :meth:`Effects.observe`; every frame it lets :meth:`Effects.advance` age
what is on screen; the :class:`game.app.render.WorldRenderer` it is given to draws the world
:meth:`Effects.shake_offset` off the camera (the shake of a stomp), and calls
:meth:`Effects.dress` before it draws the sprites (squash and stretch) and
:meth:`Effects.draw` after them (particles).

All of it is drawing only. Nothing here moves a box, changes a velocity or decides anything
in the simulation: it reads the events a tick returned and the player's state, and it
changes pictures (the player's ``image``, re-anchored on its unchanged box) and pixels. A
headless run never makes an :class:`Effects`, and its reports cannot tell whether one ran.
The shake can be turned off (``"screen_shake": false`` in ``settings.json``).

What it teaches:
  * **Juice is feedback for an event.** Each effect answers one thing that happened: a
    jump leaves dust and stretches the hero upwards; a landing squashes him a little (two
    pixels lower and wider: still a hero on his feet, not one knocked flat) and puffs
    dust to both sides; a stomp bursts the slime and shakes the screen; a coin pops; a
    checkpoint's lantern flares as it lights; and on a respawn a ring of lantern light
    closes in on the hero where he comes back (:data:`RESPAWN_BEAT_S`), so a player sees
    where play goes on. The beat is drawn only: the simulation runs on through it, exactly
    as it does headless, so every recorded run and every replay stays the same.
  * **Squash and stretch keep the feet planted.** The picture is scaled, never the hitbox,
    and it is anchored bottom-centre on the box, so the hero squashes *onto* the floor.
  * **Effects age in game time.** The window advances them by the ticks each frame runs
    (seconds, not ticks, so their tunables read in seconds): a pause, a freeze of the
    debug overlay's stepping or its quarter speed holds or slows them with the sprites.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field

import pygame

from game.collision.aabb import Box
from game.sim.world import Event, EventKind, World

Color = tuple[int, int, int]

GRAVITY_PX_S2 = 300.0  # particles fall, a little more gently than the hero
DUST_COLOR: Color = (226, 214, 186)
STOMP_COLORS: tuple[Color, ...] = ((150, 98, 214), (190, 140, 240), (110, 70, 170))
COIN_COLOR: Color = (255, 214, 90)
COIN_SPARK_COLOR: Color = (255, 248, 200)

JUMP_DUST_COUNT = 4
LAND_DUST_COUNT = 6
LAND_MIN_SPEED_PX_S = 120.0  # a landing slower than this (a step down) raises no dust
DUST_SPEED_PX_S = 30.0
DUST_LIFE_S = 0.3
STOMP_PARTICLE_COUNT = 10
STOMP_SPEED_PX_S = 90.0
STOMP_LIFE_S = 0.45
COIN_SPARK_COUNT = 4
COIN_SPARK_SPEED_PX_S = 50.0
COIN_POP_S = 0.25  # the ring round a taken coin grows for this long
COIN_POP_RADIUS_PX = (2, 9)  # from, to
LANTERN_COLOR: Color = (255, 240, 128)  # a checkpoint's light: the lit lantern's gold
LANTERN_GLOW_S = 0.4  # the ring round a lantern that lights grows for this long
LANTERN_GLOW_RADIUS_PX = (4, 20)  # from, to
LANTERN_SPARK_COUNT = 6
LANTERN_SPARK_SPEED_PX_S = 40.0
RESPAWN_BEAT_S = 0.5  # the ring of light closes in on a respawned hero over this long
RESPAWN_RADIUS_PX = (28, 2)  # from, to
RESPAWN_SPARK_COUNT = 8  # specks of light drawn in with the ring
LANTERN_GLASS_ABOVE_FOOT_PX = 24  # the lantern's glass is this far above its post's foot

STRETCH = (0.8, 1.25)  # width and height scale at the start of a jump
SQUASH = (1.125, 0.875)  # on a hard landing: 2 px lower and wider, a landing, not a fall flat
SQUASH_S = 0.15  # squash or stretch fades back to the plain picture over this long
SHAKE_S = 0.2
SHAKE_PX = 2  # the largest shake offset, at its start
SHAKE_HZ = 30.0  # how fast the shake swings from side to side
EFFECTS_SEED = 7  # particles scatter the same way on every run


@dataclass
class Particle:
    """One speck in map pixels: where it is, how it moves, how long it has."""

    x: float
    y: float
    vx: float
    vy: float
    life_s: float
    color: Color
    age_s: float = 0.0
    gravity: bool = True


@dataclass
class Pop:
    """A ring growing round where a coin was taken."""

    x: float
    y: float
    age_s: float = 0.0


@dataclass
class Ring:
    """A circle of light whose radius runs from ``radius_px[0]`` to ``radius_px[1]`` over
    ``life_s``: growing from a lit lantern, or closing in on a respawned hero."""

    x: float
    y: float
    life_s: float
    radius_px: tuple[int, int]
    age_s: float = 0.0


@dataclass
class Effects:
    """What is on screen for show, and how it ages. One per window."""

    shake_on: bool = True
    particles: list[Particle] = field(default_factory=list)
    pops: list[Pop] = field(default_factory=list)
    rings: list[Ring] = field(default_factory=list)
    squash: tuple[float, float] = (1.0, 1.0)  # the scale a squash or stretch started from
    squash_left_s: float = 0.0
    shake_left_s: float = 0.0
    world: World | None = None
    was_on_ground: bool = True
    fall_speed_px_s: float = 0.0  # the player's last speed downwards while in the air
    rng: random.Random = field(default_factory=lambda: random.Random(EFFECTS_SEED))

    # -- What happened ------------------------------------------------------------------

    def observe(self, world: World, events: list[Event]) -> None:
        """Read one tick: its events, and whether the player has just landed."""
        player = world.player
        if world is not self.world:  # a new level or a restart: nothing carries over
            self.clear()
            self.world = world
            self.was_on_ground = player.on_ground
        for event in events:
            if event.kind is EventKind.JUMP:
                self._dust(player.box, JUMP_DUST_COUNT, upwards=True)
                self._start_squash(STRETCH)
            elif event.kind is EventKind.STOMP and event.where is not None:
                self._burst(event.where)
                self.shake_left_s = SHAKE_S
            elif event.kind is EventKind.COIN and event.where is not None:
                self._pop(event.where)
            elif event.kind is EventKind.CHECKPOINT:
                self._glow(list(world.checkpoints)[event.value].box)
            elif event.kind is EventKind.HURT:  # the player is back at the respawn point
                self._beat(player.box)
        landed = player.on_ground and not self.was_on_ground
        if landed and self.fall_speed_px_s >= LAND_MIN_SPEED_PX_S:
            self._dust(player.box, LAND_DUST_COUNT, upwards=False)
            self._start_squash(SQUASH)
        if not player.on_ground:
            self.fall_speed_px_s = max(0.0, player.vy)
        self.was_on_ground = player.on_ground

    def clear(self) -> None:
        self.particles.clear()
        self.pops.clear()
        self.rings.clear()
        self.squash_left_s = self.shake_left_s = 0.0

    def _start_squash(self, scale: tuple[float, float]) -> None:
        self.squash, self.squash_left_s = scale, SQUASH_S

    def _dust(self, feet_of: Box, count: int, *, upwards: bool) -> None:
        """Puffs at the feet: drifting up after a jump, out to both sides on a landing."""
        for number in range(count):
            side = -1 if number % 2 else 1
            spread = self.rng.uniform(0.4, 1.0)
            vx = side * DUST_SPEED_PX_S * spread * (0.5 if upwards else 1.0)
            vy = -DUST_SPEED_PX_S * (0.6 if upwards else 0.25) * spread
            x = feet_of.x + feet_of.w / 2 + side * self.rng.uniform(0.0, feet_of.w / 2)
            self.particles.append(Particle(x, feet_of.bottom - 1, vx, vy,
                                           DUST_LIFE_S * spread, DUST_COLOR, gravity=False))

    def _burst(self, where: Box) -> None:
        """The slime splashes: drops thrown up and out, falling back."""
        cx, cy = where.x + where.w / 2, where.y + where.h / 2
        for number in range(STOMP_PARTICLE_COUNT):
            angle = math.pi * (number + self.rng.random()) / STOMP_PARTICLE_COUNT
            speed = STOMP_SPEED_PX_S * self.rng.uniform(0.5, 1.0)
            self.particles.append(Particle(
                cx, cy, math.cos(angle) * speed, -math.sin(angle) * speed,
                STOMP_LIFE_S, STOMP_COLORS[number % len(STOMP_COLORS)]))

    def _pop(self, where: Box) -> None:
        cx, cy = where.x + where.w / 2, where.y + where.h / 2
        self.pops.append(Pop(cx, cy))
        for number in range(COIN_SPARK_COUNT):
            angle = math.pi / 4 + number * math.pi / 2
            self.particles.append(Particle(
                cx, cy, math.cos(angle) * COIN_SPARK_SPEED_PX_S,
                math.sin(angle) * COIN_SPARK_SPEED_PX_S, COIN_POP_S, COIN_SPARK_COLOR,
                gravity=False))

    def _glow(self, lantern: Box) -> None:
        """A lantern lights: a ring of its light grows, and sparks rise from its glass."""
        cx, cy = lantern.x + lantern.w / 2, lantern.bottom - LANTERN_GLASS_ABOVE_FOOT_PX
        self.rings.append(Ring(cx, cy, LANTERN_GLOW_S, LANTERN_GLOW_RADIUS_PX))
        for number in range(LANTERN_SPARK_COUNT):
            angle = math.pi * (number + 0.5) / LANTERN_SPARK_COUNT  # a fan, upwards
            self.particles.append(Particle(
                cx, cy, math.cos(angle) * LANTERN_SPARK_SPEED_PX_S,
                -math.sin(angle) * LANTERN_SPARK_SPEED_PX_S, LANTERN_GLOW_S, LANTERN_COLOR,
                gravity=False))

    def _beat(self, hero: Box) -> None:
        """The hero is back: a ring of light and specks close in on him from all round."""
        cx, cy = hero.x + hero.w / 2, hero.y + hero.h / 2
        self.rings.append(Ring(cx, cy, RESPAWN_BEAT_S, RESPAWN_RADIUS_PX))
        start, end = RESPAWN_RADIUS_PX
        speed = (start - end) / RESPAWN_BEAT_S
        for number in range(RESPAWN_SPARK_COUNT):
            angle = 2 * math.pi * number / RESPAWN_SPARK_COUNT
            dx, dy = math.cos(angle), math.sin(angle)
            self.particles.append(Particle(cx + dx * start, cy + dy * start, -dx * speed,
                                           -dy * speed, RESPAWN_BEAT_S, LANTERN_COLOR,
                                           gravity=False))

    # -- Time ---------------------------------------------------------------------------

    def advance(self, game_s: float) -> None:
        """Age everything by ``game_s`` seconds of game time; drop what has run its course."""
        for p in self.particles:
            p.age_s += game_s
            if p.gravity:
                p.vy += GRAVITY_PX_S2 * game_s
            p.x += p.vx * game_s
            p.y += p.vy * game_s
        self.particles = [p for p in self.particles if p.age_s < p.life_s]
        for pop in self.pops:
            pop.age_s += game_s
        self.pops = [pop for pop in self.pops if pop.age_s < COIN_POP_S]
        for ring in self.rings:
            ring.age_s += game_s
        self.rings = [ring for ring in self.rings if ring.age_s < ring.life_s]
        self.squash_left_s = max(0.0, self.squash_left_s - game_s)
        self.shake_left_s = max(0.0, self.shake_left_s - game_s)

    # -- Drawing ------------------------------------------------------------------------

    def scale_now(self) -> tuple[float, float]:
        """The player's picture scale now: the squash or stretch, fading back to 1.

        >>> fx = Effects()
        >>> fx._start_squash(SQUASH)
        >>> fx.scale_now() == SQUASH
        True
        >>> fx.advance(SQUASH_S)
        >>> fx.scale_now()
        (1.0, 1.0)
        """
        left = self.squash_left_s / SQUASH_S
        return (1.0 + (self.squash[0] - 1.0) * left, 1.0 + (self.squash[1] - 1.0) * left)

    def dress(self, world: World) -> None:
        """Squash or stretch the player's picture for this frame (its box stays as it is)."""
        if world is not self.world or self.squash_left_s <= 0.0:
            return
        player = world.player
        scale_x, scale_y = self.scale_now()
        width, height = player.image.get_size()
        size = (max(1, round(width * scale_x)), max(1, round(height * scale_y)))
        if size != (width, height):
            player.show(pygame.transform.scale(player.image, size))

    def draw(self, target: pygame.Surface, offset: tuple[int, int]) -> None:
        """The particles and coin rings, in map pixels minus the camera's ``offset``."""
        off_x, off_y = offset
        for p in self.particles:
            target.fill(p.color, (math.floor(p.x) - off_x, math.floor(p.y) - off_y, 1, 1))
        for pop in self.pops:
            low, high = COIN_POP_RADIUS_PX
            radius = round(low + (high - low) * pop.age_s / COIN_POP_S)
            centre = (math.floor(pop.x) - off_x, math.floor(pop.y) - off_y)
            pygame.draw.circle(target, COIN_COLOR, centre, radius, width=1)
        for ring in self.rings:
            start, end = ring.radius_px
            radius = round(start + (end - start) * ring.age_s / ring.life_s)
            centre = (math.floor(ring.x) - off_x, math.floor(ring.y) - off_y)
            pygame.draw.circle(target, LANTERN_COLOR, centre, max(1, radius), width=1)

    def shake_offset(self) -> tuple[int, int]:
        """How far the picture is shaken now: a swing that dies away; none if turned off.

        >>> fx = Effects(shake_left_s=SHAKE_S)
        >>> max(abs(v) for v in fx.shake_offset()) <= SHAKE_PX
        True
        >>> Effects(shake_on=False, shake_left_s=SHAKE_S).shake_offset()
        (0, 0)
        """
        if not self.shake_on or self.shake_left_s <= 0.0:
            return 0, 0
        strength = SHAKE_PX * self.shake_left_s / SHAKE_S
        phase = 2 * math.pi * SHAKE_HZ * (SHAKE_S - self.shake_left_s)
        return round(strength * math.cos(phase)), round(strength * math.sin(2 * phase) / 2)
