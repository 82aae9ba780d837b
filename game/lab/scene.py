"""The scene framework: what every lab scene is, and the mouse and key handling they share.

Where it sits: under every scene of :mod:`game.lab`; the :mod:`game.lab.testbed` feeds it
events and frames. Nothing in the game imports it.

What it teaches (about testbeds more than collision):
  * **A scene only draws the reference's inputs and outputs.** Its state is a few named
    positions (:attr:`Scene.pos`); :meth:`Scene.refresh` calls the collision functions on
    them and keeps their answers; :meth:`Scene.status` prints those answers, and
    :meth:`Scene.draw` draws them. Tests read the same status the reader sees.
  * **Dragging is generic.** A scene names the boxes that can be grabbed
    (:meth:`Scene.grab_boxes`); a press inside one remembers where it was held, and every
    motion puts that shape's anchor under the mouse with the same offset.
  * **Held keys come from events, not from polling**, so a posted ``KEYDOWN`` drives a scene
    exactly as a finger does, with or without a window.
  * **Time advances only in** :meth:`Scene.step`, so pause and single step are the testbed's
    business and a paused scene still answers every drag.
  * **Nothing hidden.** A scene names its group, the debug layers it draws (:attr:`Scene.draws`;
    the legend lists only those, all on when the scene opens) and its parameters
    (:meth:`Scene.controls`, each shown with its value and clickable); it times what it
    teaches with :attr:`Scene.meter`, or says in :attr:`Scene.timing_note` why a time would
    mean nothing there.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import ClassVar

import pygame

from game.collision.aabb import Box
from game.lab.cost import CostMeter

LAB_W_PX, LAB_H_PX = 800, 450  # the lab's own screen: 2x on 1920x1080, like the game's window
TOP_PX = 28  # below the title line
AREA = pygame.Rect(0, TOP_PX, 496, 392)  # where scenes draw their shapes; the panel is to its right
PANEL = pygame.Rect(AREA.right + 6, TOP_PX, LAB_W_PX - AREA.right - 10, 394)  # status, costs,
# parameters, layers: every row inside it, above the help line
TICK_S = 1 / 60  # one frame of scene time

Point = tuple[float, float]


class Layer(Enum):
    """The debug layers a reader can switch on and off (keys 1 to 5)."""

    SHAPES = "shapes"
    BOUNDS = "bounding boxes"
    PAIRS = "pairs tested"
    CONTACTS = "contacts and normals"
    CELLS = "cells or nodes"


GROUPS = ("narrow phase", "broad phase", "motion", "response", "game")  # in the list's order

LAYER_KEYS = {pygame.K_1: Layer.SHAPES, pygame.K_2: Layer.BOUNDS, pygame.K_3: Layer.PAIRS,
              pygame.K_4: Layer.CONTACTS, pygame.K_5: Layer.CELLS}


@dataclass(frozen=True)
class Control:
    """A parameter or switch of a scene: what it is now, in words, and the keys that change
    it (each drawn as a button that does what the key does)."""

    text: str
    keys: tuple[int, ...]


def key_label(key: int) -> str:
    """How a key is written on a button.

    >>> key_label(pygame.K_UP), key_label(pygame.K_z), key_label(pygame.K_RIGHTBRACKET)
    ('Up', 'Z', ']')
    """
    name = pygame.key.name(key)
    return name.upper() if len(name) == 1 else name.capitalize()


def inside(box: Box, point: Point) -> bool:
    """Is the pixel under ``point`` inside ``box``? (The strict overlap of a 1 px box.)"""
    return box.overlaps(Box(point[0], point[1], 1, 1))


class Scene:
    """One interactive lesson. Subclasses set the class attributes and override the hooks."""

    name: ClassVar[str]  # letters, digits and hyphens: what ``--scene`` takes
    title: ClassVar[str]  # one line saying what the scene shows
    keys_help: ClassVar[str] = "drag the shapes"  # this scene's own keys, for the help line
    group: ClassVar[str]  # one of :data:`GROUPS`
    draws: ClassVar[tuple[Layer, ...]] = (Layer.SHAPES,)  # the layers its ``draw`` reads
    timing_note: ClassVar[str] = ""  # why this scene times nothing (when its meter is empty)

    def __init__(self) -> None:
        self.layers: set[Layer] = set(self.draws)  # the layers shown: all, to begin with
        self.meter = CostMeter()  # what the scene times each frame (``reset`` may replace it)
        self.pos: dict[str, Point] = {}
        self.mouse: Point = (0.0, 0.0)
        self.held: set[int] = set()
        self.dragging: str | None = None
        self._grab_offset: Point = (0.0, 0.0)
        self.ticks = 0
        self.lines: list[str] = []
        self.reset()
        self.refresh()

    # --- hooks a scene overrides -------------------------------------------------------
    def reset(self) -> None:
        """Put everything back where it starts (the R key, and the first frame)."""

    def grab_boxes(self) -> dict[str, Box]:
        """The shapes that can be dragged, by the key of their anchor in :attr:`pos`.

        Later entries are on top: a press picks the last one under the mouse.
        """
        return {}

    def on_key(self, key: int) -> None:
        """A key this scene uses was pressed (the testbed keeps its own keys)."""

    def controls(self) -> list[Control]:
        """The scene's parameters and switches, as they are now."""
        return []

    def on_click(self, point: Point) -> None:
        """A press that grabbed nothing (a scene may add a body there)."""

    def step(self, dt_s: float) -> None:
        """Advance the scene's own time by one frame; never called while paused."""

    def single_step(self) -> None:
        """The N key while paused: one step of the scene's own time (one frame unless the
        scene counts time in coarser ticks)."""
        self.step(TICK_S)

    def refresh(self) -> None:
        """Ask the reference about the current positions; keep the answers in :attr:`lines`."""

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        """Draw the shapes and the answers into :data:`AREA`."""

    # --- what the testbed calls -----------------------------------------------------------
    def status(self) -> list[str]:
        """The lines the panel shows: the reference's answers for this frame."""
        return self.lines

    def drag_to(self, key: str, point: Point) -> None:
        """Move anchor ``key`` to ``point`` (a scene may clamp it, or turn it into a velocity)."""
        self.pos[key] = point

    def press(self, point: Point) -> None:
        self.mouse = point
        for key, box in reversed(list(self.grab_boxes().items())):
            if inside(box, point):
                anchor = self.pos[key]
                self.dragging = key
                self._grab_offset = (point[0] - anchor[0], point[1] - anchor[1])
                return
        self.on_click(point)

    def motion(self, point: Point) -> None:
        self.mouse = point
        if self.dragging is not None:
            self.drag_to(self.dragging, (point[0] - self._grab_offset[0],
                                         point[1] - self._grab_offset[1]))

    def release(self) -> None:
        self.dragging = None
