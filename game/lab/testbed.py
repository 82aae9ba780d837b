"""The testbed around the scenes: the list to pick from, pause, single step, restart, layers.

Where it sits: between :mod:`game.lab.cli` (the window, or the headless screenshot) and the
scenes. One :meth:`Lab.frame` reads the event queue, advances the scene unless it is
paused, asks it to refresh its answers, and :meth:`Lab.draw` draws everything. A test
drives it the same way: ``pygame.event.post`` some events, call :meth:`frame`, read
:meth:`Scene.status`.

The keys, the same in every scene (the help line at the bottom repeats them):

=========  ===========================================================
P          pause or run
N          one step while paused
R          restart the scene
1 to 5     switch a debug layer: shapes, bounding boxes, pairs tested,
           contacts and normals, cells or nodes
Esc        back to the list (in the list: quit)
mouse      drag any shape; in the list, click a scene
=========  ===========================================================
"""

from __future__ import annotations

from collections.abc import Sequence

import pygame

from game.lab import canvas
from game.lab.scene import AREA, LAB_H_PX, LAB_W_PX, LAYER_KEYS, PANEL, TICK_S, Layer, Scene

COMMON_HELP = "P pause  N step  R restart  1-5 layers  Esc list"
MENU_TOP_PX = 70
MENU_ROW_PX = 26


class Lab:
    """One scene at a time (or the list of them), with the testbed's keys."""

    def __init__(self, scenes: Sequence[type[Scene]], start: str | None = None) -> None:
        self.scenes = list(scenes)
        self.scene: Scene | None = None
        self.choice = 0
        self.paused = False
        self.step_once = False
        self.layers: set[Layer] = set(Layer)
        self.running = True
        if start is not None:
            self.open(start)

    def names(self) -> list[str]:
        return [scene.name for scene in self.scenes]

    def open(self, name: str) -> Scene:
        """Start the scene called ``name`` afresh (a ``KeyError`` for an unknown name)."""
        cls = {scene.name: scene for scene in self.scenes}[name]
        self.choice = self.names().index(name)
        self.scene = cls()
        self.paused = False
        return self.scene

    # --- events ------------------------------------------------------------------------
    def handle(self, event: pygame.event.Event) -> None:
        if event.type == pygame.QUIT:
            self.running = False
        elif self.scene is None:
            self._handle_menu(event)
        else:
            self._handle_scene(self.scene, event)

    def _handle_menu(self, event: pygame.event.Event) -> None:
        if event.type == pygame.KEYDOWN:
            if event.key == pygame.K_ESCAPE:
                self.running = False
            elif event.key in (pygame.K_DOWN, pygame.K_s):
                self.choice = (self.choice + 1) % len(self.scenes)
            elif event.key in (pygame.K_UP, pygame.K_w):
                self.choice = (self.choice - 1) % len(self.scenes)
            elif event.key in (pygame.K_RETURN, pygame.K_SPACE, pygame.K_KP_ENTER):
                self.open(self.scenes[self.choice].name)
        elif event.type == pygame.MOUSEMOTION:
            row = self._menu_row(event.pos[1])
            if row is not None:
                self.choice = row
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            row = self._menu_row(event.pos[1])
            if row is not None:
                self.open(self.scenes[row].name)

    def _menu_row(self, y: int) -> int | None:
        row = (y - MENU_TOP_PX) // MENU_ROW_PX
        return row if 0 <= row < len(self.scenes) and y >= MENU_TOP_PX else None

    def _handle_scene(self, scene: Scene, event: pygame.event.Event) -> None:
        if event.type == pygame.KEYDOWN:
            if event.key == pygame.K_ESCAPE:
                self.scene = None
            elif event.key == pygame.K_p:
                self.paused = not self.paused
            elif event.key == pygame.K_n:
                self.paused = True
                self.step_once = True
            elif event.key == pygame.K_r:
                self.open(type(scene).name)
            elif event.key in LAYER_KEYS:
                self.layers ^= {LAYER_KEYS[event.key]}
            else:
                scene.held.add(event.key)
                scene.on_key(event.key)
        elif event.type == pygame.KEYUP:
            scene.held.discard(event.key)
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            scene.press(event.pos)
        elif event.type == pygame.MOUSEMOTION:
            scene.motion(event.pos)
        elif event.type == pygame.MOUSEBUTTONUP and event.button == 1:
            scene.release()

    # --- one frame ---------------------------------------------------------------------
    def frame(self) -> None:
        """Handle the queued events, advance the scene unless paused, refresh its answers."""
        for event in pygame.event.get():
            self.handle(event)
        scene = self.scene
        if scene is None:
            return
        if self.step_once:
            scene.ticks += 1
            scene.single_step()
            self.step_once = False
        elif not self.paused:
            scene.ticks += 1
            scene.step(TICK_S)
        scene.refresh()

    # --- drawing -----------------------------------------------------------------------
    def draw(self, surface: pygame.Surface) -> None:
        surface.fill(canvas.BACKGROUND)
        if self.scene is None:
            self._draw_menu(surface)
            return
        scene = self.scene
        canvas.text(surface, f"{scene.name}: {scene.title}", (8, 6), canvas.TEXT, canvas.TITLE_PT)
        if self.paused:
            canvas.text(surface, "PAUSED", (LAB_W_PX - 80, 8), canvas.WRONG, canvas.TITLE_PT)
        surface.fill(canvas.AREA_BG, AREA)
        clip = surface.get_clip()
        surface.set_clip(AREA)
        scene.draw(surface, self.layers)
        surface.set_clip(clip)
        bottom = canvas.lines(surface, scene.status(), (PANEL.x, PANEL.y + 4))
        layer_rows = [f"{n} {'on ' if layer in self.layers else 'off'} {layer.value}"
                      for n, layer in enumerate(Layer, start=1)]
        canvas.lines(surface, ["layers:", *layer_rows],
                     (PANEL.x, max(bottom + 8, PANEL.bottom - 6 * canvas.line_height())),
                     canvas.DIM)
        canvas.text(surface, f"{scene.keys_help}  |  {COMMON_HELP}", (8, LAB_H_PX - 24),
                    canvas.DIM)

    def _draw_menu(self, surface: pygame.Surface) -> None:
        canvas.text(surface, "Collision lab: one scene per technique", (24, 20), canvas.TEXT,
                    canvas.TITLE_PT)
        for row, scene in enumerate(self.scenes):
            y = MENU_TOP_PX + row * MENU_ROW_PX
            color = canvas.BOUNDS if row == self.choice else canvas.TEXT
            canvas.text(surface, scene.name, (40, y), color, canvas.TITLE_PT)
            canvas.text(surface, scene.title, (250, y + 4), color if row == self.choice
                        else canvas.DIM)
        canvas.text(surface, "Up/Down and Enter, or click: open a scene  |  Esc: quit",
                    (24, LAB_H_PX - 24), canvas.DIM)


def screen() -> pygame.Surface:
    """A surface the size of the lab's screen."""
    return pygame.Surface((LAB_W_PX, LAB_H_PX))
