"""A headless physics toy: crates sliding round a walled arena, bouncing off walls and each other.

Where it sits: a demo scene beside the game, not part of it (the player moves by
:mod:`game.collision.axis_sweep`, never by this). It ties the collision modules together
in the order every physics step uses, and it is small enough to test for the laws it should obey.

The order of :meth:`CrateScene.step`, written once:

1. **Drift**: each crate moves by its velocity times ``dt``. Nothing is checked yet, so
   crates may now overlap each other or a wall.
2. **Broad phase**: the structure learns the new boxes and returns the overlapping pairs.
   Unless you pass one, the scene picks it by its size with :mod:`game.collision.methods`: brute
   force for a handful of crates, a spatial grid past the measured crossover.
3. **Crates**: in a fixed order (sorted pairs, so a run is repeatable), each pair still
   overlapping is pushed apart by mass and trades momentum (:mod:`game.collision.response`).
4. **Walls**: the arena's four walls are static bodies, thick enough that nothing crosses
   one in a tick; a crate inside one is pushed out and bounces.
5. **Contacts**: the pairs that collided go to a :class:`~game.collision.contacts.ContactTracker`,
   which reports only the ones that started or ended.

What it teaches: with restitution 1 and no friction, crate-on-crate collisions conserve
momentum and kinetic energy; with less, energy only ever goes down, never up. A wrong sign
in the impulse, a push applied to velocity, or a pair handled twice breaks one of those
laws, and ``tests/test_response.py`` checks them. The same seed always gives the same run.

>>> scene = CrateScene.random(seed=7, tuning=CrateTuning(crate_count=6))
>>> before = scene.kinetic_energy()
>>> for _ in range(600):                    # ten seconds at 60 ticks a second
...     report = scene.step(1 / 60)
>>> scene.kinetic_energy() <= before
True
>>> any(c.box.overlaps(wall) for c in scene.crates.values() for wall in scene.walls)
False
"""

from __future__ import annotations

import math
import random
from collections.abc import Iterable
from dataclasses import dataclass

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhase, BroadPhaseStats
from game.collision.contacts import ContactChanges, ContactTracker
from game.collision.methods import build_broad_phase
from game.collision.response import ZERO, PointMass, Vec, exchange, push_out, separate


@dataclass(frozen=True)
class CrateTuning:
    """The scene's numbers, with their units."""

    arena_w_px: float = 320.0
    arena_h_px: float = 180.0
    crate_count: int = 12
    crate_min_px: float = 8.0            # each side of a crate is between these
    crate_max_px: float = 20.0
    spawn_gap_px: float = 4.0            # room around each crate's spawn slot
    density_kg_px2: float = 0.01         # mass = density * area
    max_speed_px_s: float = 120.0        # spawn speeds are up to this
    restitution: float = 0.9             # crate on crate: 1 perfectly bouncy, 0 not at all
    friction: float = 0.2                # crate on crate, Coulomb coefficient
    wall_restitution: float = 1.0        # walls have no friction

    @property
    def spawn_slot_px(self) -> float:
        return self.crate_max_px + self.spawn_gap_px


@dataclass
class Crate:
    """A box that moves: its key in the broad phase, its mass and its velocity."""

    key: int
    box: Box
    mass_kg: float
    velocity_px_s: Vec = ZERO

    @property
    def motion(self) -> PointMass:
        return PointMass(self.mass_kg, self.velocity_px_s)


@dataclass(frozen=True)
class StepReport:
    """What one step did: its broad-phase work, its collisions and its contact changes."""

    work: BroadPhaseStats
    crate_hits: int
    wall_hits: int
    changes: ContactChanges[int]


class CrateScene:
    """Crates in a walled arena, advanced by :meth:`step`; no window needed."""

    def __init__(self, crates: Iterable[Crate], tuning: CrateTuning | None = None,
                 broad_phase: BroadPhase[int] | None = None) -> None:
        self.tuning = tuning or CrateTuning()
        self.arena = Box(0.0, 0.0, self.tuning.arena_w_px, self.tuning.arena_h_px)
        self.walls = _walls_around(self.arena)
        self.crates = {crate.key: crate for crate in crates}
        self.broad_phase: BroadPhase[int] = (
            broad_phase if broad_phase is not None
            else build_broad_phase(len(self.crates),
                                   (self.tuning.crate_min_px + self.tuning.crate_max_px) / 2))
        for crate in self.crates.values():
            self.broad_phase.insert(crate.key, crate.box)
        self.contacts: ContactTracker[int] = ContactTracker()

    @classmethod
    def random(cls, seed: int, tuning: CrateTuning | None = None,
               broad_phase: BroadPhase[int] | None = None) -> CrateScene:
        """A scene of ``crate_count`` crates in random slots; the same seed, the same scene."""
        tuning = tuning or CrateTuning()
        rng = random.Random(seed)
        slot = tuning.spawn_slot_px
        cols, rows = math.floor(tuning.arena_w_px / slot), math.floor(tuning.arena_h_px / slot)
        if tuning.crate_count > cols * rows:
            raise ValueError(f"{tuning.crate_count} crates do not fit in a "
                             f"{tuning.arena_w_px}x{tuning.arena_h_px} px arena; "
                             f"it has room for {cols * rows}")
        crates = []
        for key, place in enumerate(rng.sample(range(cols * rows), tuning.crate_count)):
            w = rng.uniform(tuning.crate_min_px, tuning.crate_max_px)
            h = rng.uniform(tuning.crate_min_px, tuning.crate_max_px)
            x = (place % cols) * slot + rng.uniform(0.0, slot - w)  # inside its own slot
            y = (place // cols) * slot + rng.uniform(0.0, slot - h)
            heading = rng.uniform(0.0, 2 * math.pi)
            speed = rng.uniform(0.0, tuning.max_speed_px_s)
            velocity = Vec(speed * math.cos(heading), speed * math.sin(heading))
            crates.append(Crate(key, Box(x, y, w, h), tuning.density_kg_px2 * w * h, velocity))
        return cls(crates, tuning, broad_phase)

    def step(self, dt_s: float) -> StepReport:
        """Advance the scene by ``dt_s`` seconds, in the order given in the module notes."""
        if not (math.isfinite(dt_s) and dt_s >= 0):
            raise ValueError(f"a step must last a finite, non-negative time, not {dt_s}")
        tuning = self.tuning
        self.broad_phase.stats.reset()

        # 1. Drift: move by velocity; overlaps are allowed to happen here.
        for crate in self.crates.values():
            crate.box = crate.box.moved(crate.velocity_px_s.x * dt_s,
                                        crate.velocity_px_s.y * dt_s)

        # 2. Broad phase: the structure learns where everything is, and finds the pairs.
        for crate in self.crates.values():
            self.broad_phase.move(crate.key, crate.box)
        overlapping = self.broad_phase.pairs()

        # 3. Crates: push each pair apart by mass, then trade momentum along the normal.
        crate_hits = 0
        for a_key, b_key in sorted(overlapping):
            a, b = self.crates[a_key], self.crates[b_key]
            apart = separate(a.box, b.box, a.mass_kg, b.mass_kg)
            if apart is None:
                continue  # an earlier push this step already parted them
            a.box, b.box = apart.a, apart.b
            after_a, after_b = exchange(a.motion, b.motion, apart.normal,
                                        tuning.restitution, tuning.friction)
            a.velocity_px_s, b.velocity_px_s = after_a.velocity_px_s, after_b.velocity_px_s
            crate_hits += 1

        # 4. Walls: static bodies; push out and bounce. A crate clear of the walls' inner
        #    faces cannot overlap one (the same comparisons Box.overlaps makes): skip it.
        wall_hits = 0
        left, right, top, bottom = self.walls
        inner_left, inner_top = left.x + left.w, top.y + top.h
        for crate in self.crates.values():
            x, y, w, h = crate.box
            if inner_left <= x and x + w <= right.x and inner_top <= y and y + h <= bottom.y:
                continue
            for wall in self.walls:
                push = push_out(crate.box, wall)
                if push is None:
                    continue
                crate.box = push.box
                after, _ = exchange(crate.motion, PointMass(math.inf, ZERO),
                                    push.normal.opposite(), tuning.wall_restitution)
                crate.velocity_px_s = after.velocity_px_s
                wall_hits += 1

        # 5. Contacts: only the pairs that began or stopped colliding are news.
        changes = self.contacts.update(overlapping)
        work = BroadPhaseStats(self.broad_phase.stats.pair_tests,
                               self.broad_phase.stats.cells_visited)
        return StepReport(work, crate_hits, wall_hits, changes)

    def momentum(self) -> Vec:
        """Total momentum in kg·px/s."""
        total = ZERO
        for crate in self.crates.values():
            total = total.plus(crate.velocity_px_s.scaled(crate.mass_kg))
        return total

    def kinetic_energy(self) -> float:
        """Total kinetic energy, ½·m·v², in kg·px²/s²."""
        return sum(0.5 * c.mass_kg * c.velocity_px_s.dot(c.velocity_px_s)
                   for c in self.crates.values())


def _walls_around(arena: Box) -> list[Box]:
    """Four static boxes hugging the arena, each as thick as the arena is big.

    That thickness means a crate would have to travel a whole arena in one step to come out
    the far side of a wall, and the shortest way out of a wall is always back inside.
    """
    thick = max(arena.w, arena.h)
    return [
        Box(arena.left - thick, arena.top - thick, thick, arena.h + 2 * thick),  # left
        Box(arena.right, arena.top - thick, thick, arena.h + 2 * thick),         # right
        Box(arena.left - thick, arena.top - thick, arena.w + 2 * thick, thick),  # top
        Box(arena.left - thick, arena.bottom, arena.w + 2 * thick, thick),       # bottom
    ]
