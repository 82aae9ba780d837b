"""Scene ``contacts``: report when a touch starts and ends, not that it goes on.

What it shows: a red slider gliding back and forth through a row of blue boxes (drag it, or
any box). Every tick the overlapping pairs, found by brute force, go to a
:class:`~game.collision.contacts.ContactTracker`; its bounded log (the newest events last) is
what the panel shows. Beside it, the count of lines a "print every collision every tick"
loop would have written by now: the flood the tracker avoids.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.broad.brute_force import BruteForce
from game.collision.contacts import ContactTracker
from game.lab import canvas
from game.lab.scene import AREA, Layer, Scene

LOG_SHOWN = 10
SLIDER_W_PX, SLIDER_H_PX = 60.0, 60.0
SLIDER_SPEED_PX_S = 90.0
SLIDER_LEFT_X = AREA.x + 20.0
SLIDER_RIGHT_X = AREA.x + 430.0
BOXES = [Box(AREA.x + 90 + i * 70, AREA.y + 150 + (i % 2) * 40, 50, 70) for i in range(5)]


class Contacts(Scene):
    name = "contacts"
    title = "starts and ends: a log that does not flood"
    keys_help = "drag the slider or a box"
    group = "response"
    draws = (Layer.SHAPES, Layer.CONTACTS)
    timing_note = ("what this scene teaches is how many lines a log writes, counted "
                   "exactly above; a time would only measure Python's sets")

    def reset(self) -> None:
        self.pos = {str(i): (box.x, box.y) for i, box in enumerate(BOXES)}
        self.pos["slider"] = (AREA.x + 240.0 - SLIDER_W_PX / 2, AREA.y + 170.0)
        self.slider_vx = SLIDER_SPEED_PX_S
        self.tracker: ContactTracker[str] = ContactTracker(log_size=LOG_SHOWN)
        self.flood_lines = 0
        self.events = 0

    def boxes(self) -> dict[str, Box]:
        boxes = {key: Box(x, y, 50, 70) for key, (x, y) in self.pos.items() if key != "slider"}
        boxes["slider"] = Box(*self.pos["slider"], SLIDER_W_PX, SLIDER_H_PX)
        return boxes

    def grab_boxes(self) -> dict[str, Box]:
        return self.boxes()

    def step(self, dt_s: float) -> None:
        if self.dragging != "slider":
            x, y = self.pos["slider"]
            x += self.slider_vx * dt_s
            if not SLIDER_LEFT_X <= x <= SLIDER_RIGHT_X:
                self.slider_vx = -self.slider_vx
                x = min(max(x, SLIDER_LEFT_X), SLIDER_RIGHT_X)
            self.pos["slider"] = (x, y)
        phase: BruteForce[str] = BruteForce()
        for key, box in self.boxes().items():
            phase.insert(key, box)
        touching = phase.pairs()
        self.flood_lines += len(touching)
        changes = self.tracker.update(touching)
        self.events += len(changes.started) + len(changes.ended)

    def refresh(self) -> None:
        log = [str(event) for event in self.tracker.log]
        self.lines = [
            f"tick {self.tracker.tick}; pairs touching now: {len(self.tracker.touching)}",
            f"events so far: {self.events} (starts and ends)",
            f"'print every tick' would have printed {self.flood_lines} lines",
            f"log (last {LOG_SHOWN}, a bounded deque):",
            *[f"  {line}" for line in log],
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        boxes = self.boxes()
        touching = {key for pair in self.tracker.touching for key in pair}
        if Layer.SHAPES in layers:
            for key, box in boxes.items():
                canvas.box(surface, box, canvas.MOVER if key == "slider" else canvas.STILL)
                canvas.text(surface, key, (round(box.x) + 4, round(box.y) + 4), canvas.WHITE, 18)
        if Layer.CONTACTS in layers:
            for key in touching:
                canvas.box(surface, boxes[key], canvas.EXACT, 3)
        fresh = [e for e in self.tracker.log if e.tick == self.tracker.tick]
        for row, event in enumerate(fresh):
            canvas.text(surface, str(event), (AREA.x + 16, AREA.y + 16 + row * 20), canvas.TEXT)
