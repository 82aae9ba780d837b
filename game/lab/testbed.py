"""The testbed around the scenes: the list, pause and step, the view, layers, parameters, timing.

Where it sits: between :mod:`game.lab.cli` (the window, or the headless screenshot) and the
scenes. One :meth:`Lab.frame` reads the event queue, advances the scene unless it is
paused, asks it to refresh its answers, and :meth:`Lab.draw` draws everything. A test
drives it the same way: ``pygame.event.post`` some events, call :meth:`frame`, read
:meth:`Scene.status` (or :meth:`Lab.panel_text`, everything the side panel says).

The keys and the mouse, the same in every scene (the help line at the bottom repeats them):

==================  ===========================================================
P                   pause or run
N                   one step while paused
R                   restart the scene
PageDown / PageUp   the next or the previous scene (the list's order, by group)
1 to 5              switch a debug layer the scene draws (or click its legend line)
0                   the whole scene again: zoom 1x, no pan
Esc                 back to the list (in the list: quit)
left mouse          drag any shape; click a parameter's button or a layer's line
wheel               zoom in or out about the mouse
right/middle drag   pan a zoomed view
==================  ===========================================================

What it teaches (about testbeds): **hide nothing.** A scene opens with every layer it draws
switched on, and the legend lists those layers only, so nothing carries over unseen from the
scene before; every parameter is on screen with its value; every time is a median with its
spread over the last two seconds, and a small graph of those two seconds; the colours that
judge an answer mean one thing in every scene (:data:`game.lab.canvas.VERDICTS`, keyed at the
bottom of the screen).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import pygame
from pygame._sdl2.video import Window

from game.app.window import fit_window as fit_to_desktop
from game.lab import canvas
from game.lab.scene import (
    AREA,
    LAB_H_PX,
    LAB_W_PX,
    LAYER_KEYS,
    PANEL,
    TICK_S,
    Layer,
    Point,
    Scene,
    key_label,
)

COMMON_HELP = ("P pause  N step  R restart  PgUp/PgDn scene  1-5 layers  wheel zoom  "
               "right-drag pan  0 whole view  Esc list")
MENU_TOP_PX = 50
MENU_ROW_PX = 22
MENU_GROUP_X, MENU_NAME_X, MENU_TITLE_X = 16, 110, 272
ZOOMS = (1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0)  # the wheel's steps
PAN_BUTTONS = (2, 3)  # middle and right
GRAPH_W_PX, GRAPH_H_PX = 220, 12  # one timing's history
BUTTON_GAP_PX = 5
BUTTON_PAD_PX = 3
PAUSED = "PAUSED"  # at the right of the title line while paused
HELP_Y = LAB_H_PX - 25  # the help line, under the area and the panel
KEY_Y = LAB_H_PX - 13  # the key to the verdict colours

Action = Callable[[], None]


@dataclass(frozen=True)
class PanelRow:
    """One row of the side panel: its words, where they go, their colour, and what a click
    on them does (nothing for most)."""

    text: str
    rect: pygame.Rect
    color: canvas.Color
    action: Action | None = None
    graph: list[float] | None = None  # a timing's history, drawn in ``rect``
    button: bool = False  # drawn boxed: a key's name that works as a button


class View:
    """The part of :data:`AREA` shown, magnified: ``zoom`` and the scene point at the top
    left of the area. Zoom 1 shows the whole scene, as drawn."""

    def __init__(self) -> None:
        self.zoom = 1.0
        self.left, self.top = float(AREA.x), float(AREA.y)

    def to_scene(self, point: tuple[float, float]) -> Point:
        """The scene point under a screen point."""
        return (self.left + (point[0] - AREA.x) / self.zoom,
                self.top + (point[1] - AREA.y) / self.zoom)

    def source(self) -> pygame.Rect:
        """The scene rectangle on show."""
        return pygame.Rect(round(self.left), round(self.top), round(AREA.w / self.zoom),
                           round(AREA.h / self.zoom))

    def zoom_about(self, screen_point: tuple[float, float], steps: int) -> None:
        """Zoom by ``steps`` of :data:`ZOOMS` (the wheel's clicks: up zooms in), keeping the
        scene point under the mouse put."""
        index = min(range(len(ZOOMS)), key=lambda i: abs(ZOOMS[i] - self.zoom))
        new = ZOOMS[max(0, min(len(ZOOMS) - 1, index + steps))]
        fixed = self.to_scene(screen_point)
        self.zoom = new
        self.left = fixed[0] - (screen_point[0] - AREA.x) / new
        self.top = fixed[1] - (screen_point[1] - AREA.y) / new
        self._clamp()

    def pan(self, rel: tuple[float, float]) -> None:
        """Move the view with the mouse (screen pixels)."""
        self.left -= rel[0] / self.zoom
        self.top -= rel[1] / self.zoom
        self._clamp()

    def _clamp(self) -> None:
        self.left = min(max(self.left, AREA.x), AREA.right - AREA.w / self.zoom)
        self.top = min(max(self.top, AREA.y), AREA.bottom - AREA.h / self.zoom)

    def words(self) -> str:
        return ("view: whole scene (wheel zooms)" if self.zoom == 1 else
                f"view: zoom {self.zoom:g}x at ({self.left:.0f}, {self.top:.0f}); 0 resets")


class Lab:
    """One scene at a time (or the list of them), with the testbed's keys."""

    def __init__(self, scenes: Sequence[type[Scene]], start: str | None = None) -> None:
        self.scenes = list(scenes)
        self.scene: Scene | None = None
        self.choice = 0
        self.paused = False
        self.step_once = False
        self.running = True
        self.view = View()
        self.panning = False
        self.pointer: tuple[int, int] = (AREA.centerx, AREA.centery)
        if start is not None:
            self.open(start)

    def names(self) -> list[str]:
        return [scene.name for scene in self.scenes]

    def open(self, name: str) -> Scene:
        """Start the scene called ``name`` afresh (a ``KeyError`` for an unknown name): its
        own layers all on, the whole scene in view, running."""
        cls = {scene.name: scene for scene in self.scenes}[name]
        self.choice = self.names().index(name)
        self.scene = cls()
        self.paused = False
        self.view = View()
        return self.scene

    def open_next(self, steps: int) -> Scene:
        """The scene ``steps`` after (or before) the one open, round the list."""
        return self.open(self.scenes[(self.choice + steps) % len(self.scenes)].name)

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
            self._key(scene, event.key)
        elif event.type == pygame.KEYUP:
            scene.held.discard(event.key)
        elif event.type == pygame.MOUSEWHEEL:
            self.view.zoom_about(self.pointer, event.y)
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button in PAN_BUTTONS:
            self.panning = True
        elif event.type == pygame.MOUSEBUTTONUP and event.button in PAN_BUTTONS:
            self.panning = False
        elif event.type == pygame.MOUSEBUTTONDOWN and event.button == 1:
            if AREA.collidepoint(event.pos):
                scene.press(self.view.to_scene(event.pos))
            else:
                self.click_panel(event.pos)
        elif event.type == pygame.MOUSEMOTION:
            self.pointer = event.pos
            if self.panning:
                self.view.pan(event.rel)
            scene.motion(self.view.to_scene(event.pos))
        elif event.type == pygame.MOUSEBUTTONUP and event.button == 1:
            scene.release()

    def _key(self, scene: Scene, key: int) -> None:
        if key == pygame.K_ESCAPE:
            self.scene = None
        elif key == pygame.K_p:
            self.paused = not self.paused
        elif key == pygame.K_n:
            self.paused = True
            self.step_once = True
        elif key == pygame.K_r:
            self.open(type(scene).name)
        elif key in (pygame.K_PAGEDOWN, pygame.K_PAGEUP):
            self.open_next(1 if key == pygame.K_PAGEDOWN else -1)
        elif key == pygame.K_0:
            self.view = View()
        elif key in LAYER_KEYS:
            self.toggle(scene, LAYER_KEYS[key])
        else:
            scene.held.add(key)
            scene.on_key(key)

    @staticmethod
    def toggle(scene: Scene, layer: Layer) -> None:
        """Switch one of the layers the scene draws (the others are not the scene's)."""
        if layer in scene.draws:
            scene.layers ^= {layer}

    def click_panel(self, at: tuple[int, int]) -> None:
        """A click on the side panel: a parameter's button or a layer's line does its job."""
        for row in self.panel_rows():
            if row.action is not None and row.rect.collidepoint(at):
                row.action()
                if self.scene is not None:
                    self.scene.refresh()
                return

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

    # --- the side panel ------------------------------------------------------------------
    def panel_rows(self) -> list[PanelRow]:
        """Everything the side panel shows, top to bottom, with where it goes: the scene's
        answers, its timings, its parameters, its layers, the view."""
        scene = self.scene
        if scene is None:
            return []
        step = canvas.line_height()
        rows: list[PanelRow] = []
        y = PANEL.y + 4

        def add(text: str, color: canvas.Color = canvas.TEXT, action: Action | None = None,
                x: int = PANEL.x, graph: list[float] | None = None) -> None:
            nonlocal y
            rows.append(PanelRow(text, pygame.Rect(x, y, canvas.text_width(text), step),
                                 color, action, graph))
            y += step

        for line in scene.status():
            add(line)
        y += step // 2
        meter = scene.meter
        if meter.labels():
            add(f"timed here, last {meter.window} frames: median (p10 to p90)", canvas.DIM)
            for label in meter.labels():
                add(f"  {meter.text(label)}", canvas.TEXT)
                rows.append(PanelRow("", pygame.Rect(PANEL.x + 16, y, GRAPH_W_PX, GRAPH_H_PX),
                                     canvas.DIM, graph=meter.history(label)))
                y += GRAPH_H_PX + 2
        else:
            for line in _wrap(f"no timing: {scene.timing_note}"):
                add(line, canvas.DIM)
        y += step // 2
        controls = scene.controls()
        if controls:
            add("parameters (click a key, or press it):", canvas.DIM)
        for control in controls:
            x = PANEL.x + 8
            words = PanelRow(control.text, pygame.Rect(x, y, canvas.text_width(control.text),
                                                       step), canvas.TEXT)
            rows.append(words)
            x = words.rect.right + BUTTON_GAP_PX
            for key in control.keys:
                label = key_label(key)
                button = pygame.Rect(x, y - 1, canvas.text_width(label) + 2 * BUTTON_PAD_PX,
                                     canvas.font().get_height() + 2)  # a pixel round the key
                rows.append(PanelRow(label, button, canvas.BOUNDS, _pressing(scene, key),
                                     button=True))
                x = button.right + BUTTON_GAP_PX
            y += step
        y += step // 2
        add("layers this scene draws (click, or 1-5):", canvas.DIM)
        numbers = {layer: number for number, layer in enumerate(Layer, start=1)}
        for layer in scene.draws:
            shown = layer in scene.layers
            add(f"  {numbers[layer]} [{'x' if shown else ' '}] {layer.value}",
                canvas.TEXT if shown else canvas.DIM, _toggling(scene, layer))
        add(self.view.words(), canvas.DIM)
        return rows

    def panel_text(self) -> list[str]:
        """The side panel's words, row by row (buttons on the row of their parameter)."""
        lines: dict[int, list[str]] = {}
        for row in self.panel_rows():
            if row.graph is None:
                lines.setdefault(row.rect.y + (1 if row.button else 0), []).append(row.text)
        return [" ".join(words) for _, words in sorted(lines.items())]

    # --- drawing -----------------------------------------------------------------------
    def draw(self, surface: pygame.Surface) -> None:
        surface.fill(canvas.BACKGROUND)
        if self.scene is None:
            self._draw_menu(surface)
            return
        scene = self.scene
        canvas.text(surface, title_line(scene), (8, 6),
                    canvas.TEXT, canvas.TITLE_PT)
        if self.paused:
            canvas.text(surface, PAUSED, (paused_x(), 6), canvas.TEXT, canvas.TITLE_PT)
        self._draw_scene(surface, scene)
        for row in self.panel_rows():
            if row.graph is not None:
                _graph(surface, row.graph, row.rect)
            elif row.button:
                pygame.draw.rect(surface, row.color, row.rect, 1)
                canvas.text(surface, row.text, (row.rect.x + BUTTON_PAD_PX, row.rect.y + 1),
                            row.color)
            else:
                canvas.text(surface, row.text, row.rect.topleft, row.color)
        canvas.text(surface, f"{scene.keys_help}  |  {COMMON_HELP}", (8, HELP_Y), canvas.DIM)
        x = 8
        for color, meaning in canvas.VERDICTS:
            x = canvas.text(surface, meaning, (x, KEY_Y), color).right + 16

    def _draw_scene(self, surface: pygame.Surface, scene: Scene) -> None:
        """The scene, drawn at its own coordinates, then the part in view, magnified."""
        if self.view.zoom == 1:
            surface.fill(canvas.AREA_BG, AREA)
            clip = surface.get_clip()
            surface.set_clip(AREA)
            scene.draw(surface, scene.layers)
            surface.set_clip(clip)
            return
        whole = pygame.Surface(surface.get_size())
        whole.fill(canvas.AREA_BG, AREA)
        whole.set_clip(AREA)
        scene.draw(whole, scene.layers)
        source = self.view.source().clip(AREA)
        surface.blit(pygame.transform.scale(whole.subsurface(source), AREA.size), AREA)

    def _draw_menu(self, surface: pygame.Surface) -> None:
        canvas.text(surface, "Collision lab: one scene per technique, by group", (16, 14),
                    canvas.TEXT, canvas.TITLE_PT)
        group = None
        for row, scene in enumerate(self.scenes):
            y = MENU_TOP_PX + row * MENU_ROW_PX
            chosen = row == self.choice
            if scene.group != group:
                group = scene.group
                canvas.text(surface, group, (MENU_GROUP_X, y + 4), canvas.DIM)
            canvas.text(surface, scene.name, (MENU_NAME_X, y),
                        canvas.BOUNDS if chosen else canvas.TEXT, canvas.TITLE_PT)
            canvas.text(surface, scene.title, (MENU_TITLE_X, y + 4),
                        canvas.BOUNDS if chosen else canvas.DIM)
        canvas.text(surface, "Up/Down and Enter, or click: open a scene  |  Esc: quit",
                    (16, HELP_Y), canvas.DIM)


def menu_rows(lab: Lab) -> list[pygame.Rect]:
    """Where each row of the list is drawn: its group, name and title, from the left of the
    group to the end of the title."""
    rows = []
    for row, scene in enumerate(lab.scenes):
        y = MENU_TOP_PX + row * MENU_ROW_PX
        name = pygame.Rect((MENU_NAME_X, y), canvas.font(canvas.TITLE_PT).size(scene.name))
        title = pygame.Rect((MENU_TITLE_X, y + 4), canvas.font().size(scene.title))
        rows.append(name.union(title).union(pygame.Rect(MENU_GROUP_X, y + 4, 1, 1)))
    return rows


def title_line(scene: Scene) -> str:
    """The line across the top of a scene: its group, name and what it shows."""
    return f"{scene.group} / {scene.name}: {scene.title}"


def paused_x() -> int:
    """Where :data:`PAUSED` starts: right-aligned on the title line."""
    return LAB_W_PX - 8 - canvas.text_width(PAUSED, canvas.TITLE_PT)


def _pressing(scene: Scene, key: int) -> Action:
    return lambda: scene.on_key(key)


def _toggling(scene: Scene, layer: Layer) -> Action:
    return lambda: Lab.toggle(scene, layer)


def _wrap(words: str, width: int = PANEL.w) -> list[str]:
    """``words`` broken into lines that fit ``width`` pixels."""
    lines: list[str] = []
    for word in words.split():
        if lines and canvas.text_width(f"{lines[-1]} {word}") <= width:
            lines[-1] = f"{lines[-1]} {word}"
        else:
            lines.append(word)
    return lines


def _graph(surface: pygame.Surface, values: Sequence[float], rect: pygame.Rect) -> None:
    """The window's measurements, oldest at the left, from 0 (the bottom) to the highest;
    the median is the brighter line across."""
    pygame.draw.rect(surface, canvas.GRID, rect, 1)
    top = max(values)
    if top <= 0 or len(values) < 2:
        return
    ordered = sorted(values)
    median = ordered[len(ordered) // 2]

    def height(value: float) -> float:
        return rect.bottom - 1 - (rect.h - 2) * value / top

    step = (rect.w - 2) / (len(values) - 1)
    points = [(rect.x + 1 + i * step, height(v)) for i, v in enumerate(values)]
    pygame.draw.lines(surface, canvas.DIM, False, points)
    level = round(height(median))
    pygame.draw.line(surface, canvas.TEXT, (rect.x + 1, level), (rect.right - 2, level))


def fit_window() -> Window:
    """Size the lab's window for the desktop it is on and centre it there, by the game's own
    rule (:func:`game.app.window.fit_window`: on 1920x1080 the lab's 800x450 screen opens at
    2x, 1600x900, the size of the game's window). Returns the window, which must be kept
    while it is open."""
    window = Window.from_display_module()
    fit_to_desktop(window, (LAB_W_PX, LAB_H_PX))
    return window


def screen() -> pygame.Surface:
    """A surface the size of the lab's screen."""
    return pygame.Surface((LAB_W_PX, LAB_H_PX))

