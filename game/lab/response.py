"""Scene ``response``: crates pushed apart, trading momentum, with restitution and friction.

What it shows: crates drifting in a walled box, in the order every physics step uses:
drift by velocity; find the overlapping pairs (the broad phase
:func:`~game.collision.methods.build_broad_phase` picks); push each pair apart in inverse
proportion to mass (:func:`~game.collision.response.separate`) and exchange an impulse along
the normal (:func:`~game.collision.response.exchange`); push out of the walls
(:func:`~game.collision.response.push_out`) and bounce. The arrows are this tick's pushes. The
panel prints total momentum and kinetic energy: with restitution 1 and no friction energy
stays, with less it only ever goes down. E and D change restitution, F and V friction.
Drag a crate to throw it.
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

import pygame

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhase
from game.collision.methods import build_broad_phase
from game.collision.response import ZERO, PointMass, Vec, exchange, push_out, separate
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, TICK_S, Control, Layer, Point, Scene

CRATES = 9
SEED = 4
DENSITY_KG_PX2 = 0.01
MAX_SPEED_PX_S = 220.0
THROW_MAX_PX_S = 600.0
ARENA = Box(AREA.x + 20, AREA.y + 20, AREA.w - 40, AREA.h - 40)
TUNING_STEP = 0.1


def walls_around(arena: Box) -> list[Box]:
    """Four static boxes, each as thick as the arena is big, so nothing crosses one in a tick."""
    thick = max(arena.w, arena.h)
    return [Box(arena.left - thick, arena.top - thick, thick, arena.h + 2 * thick),
            Box(arena.right, arena.top - thick, thick, arena.h + 2 * thick),
            Box(arena.left - thick, arena.top - thick, arena.w + 2 * thick, thick),
            Box(arena.left - thick, arena.bottom, arena.w + 2 * thick, thick)]


@dataclass
class Crate:
    box: Box
    mass_kg: float
    velocity_px_s: Vec


@dataclass(frozen=True)
class PushDrawn:
    """One correction this tick, to draw: where it started and the push (px)."""

    at: Point
    push: Vec


class Response(Scene):
    name = "response"
    title = "crates: push out, momentum, restitution, friction"
    keys_help = "E/D restitution, F/V friction; drag to throw"
    group = "response"
    draws = (Layer.SHAPES, Layer.CONTACTS)

    def reset(self) -> None:
        self.restitution = getattr(self, "restitution", 0.9)
        self.friction = getattr(self, "friction", 0.2)
        rng = random.Random(SEED)
        self.crates: dict[int, Crate] = {}
        cols = 3
        for key in range(CRATES):
            w, h = rng.uniform(36, 70), rng.uniform(36, 70)
            x = ARENA.x + 24 + (key % cols) * 140 + rng.uniform(0, 30)
            y = ARENA.y + 16 + (key // cols) * 110 + rng.uniform(0, 20)
            heading = rng.uniform(0, 2 * math.pi)
            speed = rng.uniform(60, MAX_SPEED_PX_S)
            self.crates[key] = Crate(Box(x, y, w, h), DENSITY_KG_PX2 * w * h,
                                     Vec(speed * math.cos(heading), speed * math.sin(heading)))
        self.walls = walls_around(ARENA)
        self.phase: BroadPhase[int] = build_broad_phase(CRATES, 50.0)
        for key, crate in self.crates.items():
            self.phase.insert(key, crate.box)
        self.pushes: list[PushDrawn] = []
        self.crate_hits = self.wall_hits = 0
        self.energy_before = self.energy_after = self.kinetic_energy()
        self.meter = CostMeter()

    def kinetic_energy(self) -> float:
        return sum(0.5 * c.mass_kg * c.velocity_px_s.dot(c.velocity_px_s)
                   for c in self.crates.values())

    def controls(self) -> list[Control]:
        return [Control(f"restitution {self.restitution:.1f}", (pygame.K_d, pygame.K_e)),
                Control(f"friction {self.friction:.1f}", (pygame.K_v, pygame.K_f))]

    def on_key(self, key: int) -> None:
        if key == pygame.K_e:
            self.restitution = min(1.0, round(self.restitution + TUNING_STEP, 2))
        elif key == pygame.K_d:
            self.restitution = max(0.0, round(self.restitution - TUNING_STEP, 2))
        elif key == pygame.K_f:
            self.friction = round(self.friction + TUNING_STEP, 2)
        elif key == pygame.K_v:
            self.friction = max(0.0, round(self.friction - TUNING_STEP, 2))

    def grab_boxes(self) -> dict[str, Box]:
        self.pos = {str(k): (c.box.x, c.box.y) for k, c in self.crates.items()}
        return {str(k): c.box for k, c in self.crates.items()}

    def drag_to(self, key: str, point: Point) -> None:
        crate = self.crates[int(key)]
        x = min(max(point[0], ARENA.left), ARENA.right - crate.box.w)
        y = min(max(point[1], ARENA.top), ARENA.bottom - crate.box.h)
        vx = max(-THROW_MAX_PX_S, min(THROW_MAX_PX_S, (x - crate.box.x) / TICK_S))
        vy = max(-THROW_MAX_PX_S, min(THROW_MAX_PX_S, (y - crate.box.y) / TICK_S))
        crate.box = crate.box._replace(x=x, y=y)
        crate.velocity_px_s = Vec(vx, vy)

    def step(self, dt_s: float) -> None:
        self.energy_before = self.kinetic_energy()
        self.pushes = []
        # 1. Drift: overlaps may appear here.
        for key, crate in self.crates.items():
            if self.dragging != str(key):
                crate.box = crate.box.moved(crate.velocity_px_s.x * dt_s,
                                            crate.velocity_px_s.y * dt_s)
        # 2. Broad phase: the overlapping pairs.
        for key, crate in self.crates.items():
            self.phase.move(key, crate.box)
        self.crate_hits = self.wall_hits = 0
        # 3. Crates: separate by mass, then exchange momentum along the normal.
        for a_key, b_key in sorted(self.phase.pairs()):
            a, b = self.crates[a_key], self.crates[b_key]
            apart = separate(a.box, b.box, a.mass_kg, b.mass_kg)
            if apart is None:
                continue
            self.pushes.append(PushDrawn(a.box.center, Vec(apart.a.x - a.box.x,
                                                          apart.a.y - a.box.y)))
            self.pushes.append(PushDrawn(b.box.center, Vec(apart.b.x - b.box.x,
                                                          apart.b.y - b.box.y)))
            a.box, b.box = apart.a, apart.b
            after_a, after_b = exchange(PointMass(a.mass_kg, a.velocity_px_s),
                                        PointMass(b.mass_kg, b.velocity_px_s), apart.normal,
                                        self.restitution, self.friction)
            a.velocity_px_s, b.velocity_px_s = after_a.velocity_px_s, after_b.velocity_px_s
            self.crate_hits += 1
        # 4. Walls: static, so the crate takes the whole push, and bounces.
        for crate in self.crates.values():
            for wall in self.walls:
                push = push_out(crate.box, wall)
                if push is None:
                    continue
                self.pushes.append(PushDrawn(crate.box.center, push.correction))
                crate.box = push.box
                after, _ = exchange(PointMass(crate.mass_kg, crate.velocity_px_s),
                                    PointMass(math.inf, ZERO), push.normal.opposite(), 1.0)
                crate.velocity_px_s = after.velocity_px_s
                self.wall_hits += 1
        self.energy_after = self.kinetic_energy()

    def refresh(self) -> None:
        momentum = ZERO
        energy = 0.0
        for crate in self.crates.values():
            momentum = momentum.plus(crate.velocity_px_s.scaled(crate.mass_kg))
            energy += 0.5 * crate.mass_kg * crate.velocity_px_s.dot(crate.velocity_px_s)
        self.energy = energy
        a, b = self.crates[0], self.crates[1]
        normal = Vec(1.0, 0.0)
        self.meter.time("a crate pair: separate + exchange", lambda: (
            separate(a.box, b.box, a.mass_kg, b.mass_kg),
            exchange(PointMass(a.mass_kg, a.velocity_px_s), PointMass(b.mass_kg,
                     b.velocity_px_s), normal, self.restitution, self.friction)))
        change = self.energy_after - self.energy_before
        share = change / self.energy_before if self.energy_before else 0.0
        self.lines = [
            f"restitution {self.restitution:.1f}  (E up, D down)",
            f"friction    {self.friction:.1f}  (F up, V down)",
            f"broad phase: {type(self.phase).__name__} ({CRATES} crates)",
            "",
            f"this tick: {self.crate_hits} crate pairs, {self.wall_hits} walls",
            f"momentum ({momentum.x:.1f}, {momentum.y:.1f}) kg px/s",
            f"kinetic energy {energy:.0f} kg px^2/s^2",
            f"energy in the last tick: {share:+.2%}"
            + (" (grew!)" if change > 1e-9 * max(1.0, self.energy_before) else
               " (kept)" if abs(share) < 1e-9 else " (lost to restitution and friction)"),
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        pygame.draw.rect(surface, canvas.DIM, ARENA.to_rect(), 1)
        if Layer.SHAPES in layers:
            for key, crate in self.crates.items():
                canvas.box(surface, crate.box, canvas.MOVER if self.dragging == str(key)
                           else (196, 146, 84))
                canvas.box(surface, crate.box, (100, 70, 40), 2)
        if Layer.CONTACTS in layers:
            for crate in self.crates.values():
                cx, cy = crate.box.center
                canvas.arrow(surface, (cx, cy), (cx + crate.velocity_px_s.x * 0.3,
                                                 cy + crate.velocity_px_s.y * 0.3), canvas.TEXT, 1)
            for drawn in self.pushes:
                end = (drawn.at[0] + drawn.push.x * 4, drawn.at[1] + drawn.push.y * 4)
                canvas.arrow(surface, drawn.at, end, canvas.EXACT, 2)
