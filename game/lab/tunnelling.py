"""Scene ``tunnelling``: one fast body, one thin wall, four ways to check the move.

What it shows: four lanes side by side, each a body flying right at the speed you set (Up and
Down) at a thin wall, one tick per step (N steps one tick, P runs them slowly). Each lane asks
:mod:`game.collision.swept` in its own way and draws exactly the boxes it tested this tick:

* **discrete** :func:`~game.collision.swept.discrete_hit`: the end position only;
* **sub-steps** :func:`~game.collision.swept.substep_hit`: ``steps`` positions along the move
  ([ and ] change how many);
* **speed clamp** :func:`~game.collision.swept.clamp_speed`, then the discrete test: never
  faster than ``CLAMP_PX_PER_TICK``, so it arrives late;
* **swept** :func:`~game.collision.swept.sweep`: the union of start and end box, and the exact
  time of impact; the body stops flush.

Raise the speed past the body's width plus the wall's: the discrete lane flies through the
wall while the swept lane still stops at it. The panel counts the tests each lane made and
times one test of each kind.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import pygame

from game.collision.aabb import Box
from game.collision.swept import (
    clamp_speed,
    discrete_hit,
    position_at,
    substep_hit,
    sweep,
)
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, TICK_S, Control, Layer, Scene

LANES = ("discrete", "sub-steps", "speed clamp", "swept")
LANE_H_PX = 88
BODY_PX = 20.0
WALL_W_PX = 8.0
WALL_X = AREA.x + 420.0
START_X = AREA.x + 30.0
SPEED_STEP_PX = 8.0
START_SPEED_PX_PER_TICK = 40.0
CLAMP_PX_PER_TICK = 16.0
START_SUBSTEPS = 2
TICKS_PER_STEP_RUNNING = 15  # while running, four ticks a second: slow motion
TICKS_A_SECOND_RUNNING = 1 / (TICKS_PER_STEP_RUNNING * TICK_S)


def lane_top(lane: int) -> float:
    return AREA.y + 8 + lane * (LANE_H_PX + 6)


def wall_of(lane: int, wall_x: float = WALL_X) -> Box:
    return Box(wall_x, lane_top(lane) + 20, WALL_W_PX, LANE_H_PX - 40)


@dataclass
class Flight:
    """One lane's body: where it is, what this tick tested, and how the flight ended."""

    box: Box
    tested: list[Box] = field(default_factory=list)
    trail: list[Box] = field(default_factory=list)
    outcome: str = "flying"
    tests: int = 0
    ticks: int = 0

    @property
    def done(self) -> bool:
        return self.outcome != "flying"


def inside(flight: Flight, wall: Box) -> str:
    """The outcome of a check that found the body already inside the wall."""
    return f"hit on tick {flight.ticks}, {flight.box.penetration(wall):g} px inside"


def verdict_color(lane: str, flight: Flight) -> canvas.Color:
    """The lab's verdict colours: the sweep is exact; the other lanes approximate, right when
    they stop the body (late or inside the wall), wrong when it tunnels."""
    if not flight.done:
        return canvas.DIM
    if flight.outcome.startswith("TUNNELLED"):
        return canvas.WRONG
    return canvas.EXACT if lane == "swept" else canvas.APPROX_RIGHT


class Tunnelling(Scene):
    name = "tunnelling"
    title = "discrete, sub-steps, speed clamp and swept, side by side"
    keys_help = "Up/Down speed; [ ] sub-steps; N one tick; drag a wall"
    group = "motion"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.PAIRS)

    def reset(self) -> None:
        self.wall_x = WALL_X
        self.speed_px = getattr(self, "speed_px", START_SPEED_PX_PER_TICK)
        self.steps = getattr(self, "steps", START_SUBSTEPS)
        self.meter = CostMeter()
        self.frames = 0
        self.launch()

    def walls(self) -> list[Box]:
        return [wall_of(lane, self.wall_x) for lane in range(len(LANES))]

    def grab_boxes(self) -> dict[str, Box]:
        walls = self.walls()
        self.pos = {f"wall{lane}": (wall.x, wall.y) for lane, wall in enumerate(walls)}
        return {f"wall{lane}": wall.moved(-6).union(wall.moved(6))
                for lane, wall in enumerate(walls)}

    def drag_to(self, key: str, point: tuple[float, float]) -> None:
        """Every lane's wall moves together, and the flights start again."""
        self.wall_x = min(max(point[0], START_X + 2 * BODY_PX), AREA.right - 40.0)
        self.launch()

    def launch(self) -> None:
        """Every body back to the start, at the current speed."""
        self.flights = [Flight(Box(START_X, lane_top(lane) + LANE_H_PX / 2 - BODY_PX / 2,
                                   BODY_PX, BODY_PX)) for lane in range(len(LANES))]

    def controls(self) -> list[Control]:
        return [Control(f"speed {self.speed_px:g} px a tick",
                        (pygame.K_DOWN, pygame.K_UP)),
                Control(f"sub-steps {self.steps}",
                        (pygame.K_LEFTBRACKET, pygame.K_RIGHTBRACKET))]

    def on_key(self, key: int) -> None:
        if key == pygame.K_UP:
            self.speed_px += SPEED_STEP_PX
        elif key == pygame.K_DOWN:
            self.speed_px = max(SPEED_STEP_PX, self.speed_px - SPEED_STEP_PX)
        elif key == pygame.K_RIGHTBRACKET:
            self.steps += 1
        elif key == pygame.K_LEFTBRACKET:
            self.steps = max(1, self.steps - 1)
        else:
            return
        self.launch()

    def step(self, dt_s: float) -> None:
        self.frames += 1
        if self.frames % TICKS_PER_STEP_RUNNING == 0:
            self.tick()

    def single_step(self) -> None:
        self.tick()

    def tick(self) -> None:
        """One game tick for every lane still flying."""
        dx = self.speed_px
        for lane, flight in enumerate(self.flights):
            if flight.done:
                continue
            wall, box = wall_of(lane, self.wall_x), flight.box
            flight.ticks += 1
            flight.trail.append(box)
            if LANES[lane] == "discrete":
                flight.tested = [position_at(box, dx, 0, 1.0)]
                flight.tests += 1
                flight.box = flight.tested[0]
                if discrete_hit(box, dx, 0, wall):
                    flight.outcome = inside(flight, wall)
            elif LANES[lane] == "sub-steps":
                flight.tested = [position_at(box, dx, 0, k / self.steps)
                                 for k in range(1, self.steps + 1)]
                t = substep_hit(box, dx, 0, wall, self.steps)
                flight.tests += self.steps if t is None else round(t * self.steps)
                flight.box = position_at(box, dx, 0, 1.0 if t is None else t)
                if t is not None:
                    flight.outcome = inside(flight, wall)
            elif LANES[lane] == "speed clamp":
                cdx, _ = clamp_speed(dx, 0, CLAMP_PX_PER_TICK)
                flight.tested = [position_at(box, cdx, 0, 1.0)]
                flight.tests += 1
                flight.box = flight.tested[0]
                if discrete_hit(box, cdx, 0, wall):
                    flight.outcome = inside(flight, wall)
            else:
                flight.tested = [box.union(position_at(box, dx, 0, 1.0))]
                flight.tests += 1
                contact = sweep(box, dx, 0, wall)
                flight.box = position_at(box, dx, 0, 1.0 if contact is None else contact.t)
                if contact is not None:
                    flight.outcome = f"hit on tick {flight.ticks}, flush (t = {contact.t:.2f})"
            if not flight.done and flight.box.left >= wall.right:
                flight.outcome = f"TUNNELLED through on tick {flight.ticks}"

    def refresh(self) -> None:
        box, wall = self.flights[0].box, wall_of(0, self.wall_x)
        self.meter.time("discrete_hit", lambda: discrete_hit(box, self.speed_px, 0, wall))
        self.meter.time("substep_hit", lambda: substep_hit(box, self.speed_px, 0, wall,
                                                           self.steps))
        self.meter.time("sweep", lambda: sweep(box, self.speed_px, 0, wall))
        self.lines = [f"SLOW MOTION: {TICKS_A_SECOND_RUNNING:g} ticks a second while running "
                      f"(the game: {1 / TICK_S:g})",
                      f"speed {self.speed_px:g} px a tick (body {BODY_PX:g}, wall {WALL_W_PX:g})",
                      f"sub-steps {self.steps}; clamp at {CLAMP_PX_PER_TICK:g} px a tick", ""]
        for lane, flight in enumerate(self.flights):
            self.lines.append(f"{LANES[lane]}: {flight.outcome}")
            self.lines.append(f"   {flight.tests} tests in {flight.ticks} ticks")
        self.lines += ["", f"one call each (substep_hit with {self.steps} steps):",
                       f"  a sweep takes {self.meter.times('sweep', 'discrete_hit')} a discrete "
                       "test"]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        for lane, flight in enumerate(self.flights):
            top = lane_top(lane)
            pygame.draw.rect(surface, canvas.BACKGROUND,
                             (AREA.x + 4, top, AREA.w - 8, LANE_H_PX), 1)
            canvas.text(surface, LANES[lane], (AREA.x + 10, round(top) + 4), canvas.DIM, 18)
            canvas.box(surface, wall_of(lane, self.wall_x), canvas.STILL)
            if Layer.BOUNDS in layers:
                for past in flight.trail:
                    canvas.box(surface, past, canvas.GRID, 1)
            if Layer.PAIRS in layers:
                for tested in flight.tested:
                    canvas.box(surface, tested, canvas.TESTED, 2)
            if Layer.SHAPES in layers:
                canvas.box(surface, flight.box, canvas.MOVER)
            color = verdict_color(LANES[lane], flight)
            canvas.text(surface, flight.outcome, (AREA.x + 130, round(top) + 4), color, 18)
