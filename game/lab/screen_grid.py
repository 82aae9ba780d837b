"""Scene ``screen-grid``: where a position is on screen, and which whole pixel draws it.

What it shows: the world's origin (0, 0) in the middle of the area, x growing to the right and
**y growing downwards**, as on every screen. Drag the red box, or nudge it a quarter pixel
with the arrow keys. The panel prints its exact float position, the Rect that
:meth:`~game.collision.aabb.Box.to_rect` derives from it (``math.floor`` of each corner), what
``int()`` would have made of it (wrong by a pixel left of or above the origin), and the
40 px grid cell that :meth:`~game.collision.broad.spatial_grid.SpatialGrid.cell_range` files it in.
"""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.collision.broad.spatial_grid import SpatialGrid
from game.lab import canvas
from game.lab.scene import AREA, Control, Layer, Scene

CELL_PX = 40
ORIGIN = (AREA.x + 280, AREA.y + 200)  # where world (0, 0) is drawn
SIZE_PX = 16.0
NUDGE_PX = 0.25
NUDGES = {pygame.K_LEFT: (-NUDGE_PX, 0.0), pygame.K_RIGHT: (NUDGE_PX, 0.0),
          pygame.K_UP: (0.0, -NUDGE_PX), pygame.K_DOWN: (0.0, NUDGE_PX)}


class ScreenGrid(Scene):
    name = "screen-grid"
    title = "the screen grid: y grows down, floor makes the pixel"
    keys_help = "drag the box; arrows nudge 0.25 px"
    group = "game"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.CELLS)
    timing_note = ("turning one position into a pixel and a cell is a floor and a "
                   "division, done once a frame; the lesson is which pixel, not how fast")

    def reset(self) -> None:
        self.pos = {"box": (ORIGIN[0] - 52.75, ORIGIN[1] + 30.25)}  # world (-52.75, 30.25)
        self.grid: SpatialGrid[int] = SpatialGrid(cell_size_px=CELL_PX)

    def world(self) -> Box:
        x, y = self.pos["box"]
        return Box(x - ORIGIN[0], y - ORIGIN[1], SIZE_PX, SIZE_PX)

    def grab_boxes(self) -> dict[str, Box]:
        x, y = self.pos["box"]
        return {"box": Box(x, y, SIZE_PX, SIZE_PX)}

    def controls(self) -> list[Control]:
        return [Control(f"nudge the box {NUDGE_PX:g} px", tuple(NUDGES))]

    def on_key(self, key: int) -> None:
        if key in NUDGES:
            dx, dy = NUDGES[key]
            x, y = self.pos["box"]
            self.pos["box"] = (x + dx, y + dy)

    def refresh(self) -> None:
        world = self.world()
        self.rect = world.to_rect()
        cells = self.grid.cell_range(world)
        self.cell = (cells.first_col, cells.first_row)
        truncated = (int(world.x), int(world.y))
        wrong = truncated != (self.rect.x, self.rect.y)
        self.lines = [
            f"box at x = {world.x:.2f}, y = {world.y:.2f}",
            "(y grows downwards: below the origin is +y)",
            f"Box.to_rect(): Rect({self.rect.x}, {self.rect.y}, {self.rect.w}, {self.rect.h})",
            f"int() would give x = {truncated[0]}, y = {truncated[1]}",
            "  -> int() is a pixel off here" if wrong else
            "  -> the same here (no negative fraction to truncate)",
            f"grid cell ({CELL_PX} px, floor): {self.cell}",
            f"screen pixel of its corner: ({math.floor(self.pos['box'][0])}, "
            f"{math.floor(self.pos['box'][1])})",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        ox, oy = ORIGIN
        if Layer.CELLS in layers:
            for col in range(-8, 9):
                x = ox + col * CELL_PX
                pygame.draw.line(surface, canvas.GRID, (x, AREA.top), (x, AREA.bottom))
                canvas.text(surface, str(col * CELL_PX), (x + 2, AREA.top + 2), canvas.DIM, 16)
            for row in range(-6, 7):
                y = oy + row * CELL_PX
                pygame.draw.line(surface, canvas.GRID, (AREA.left, y), (AREA.right, y))
                if y > AREA.top + 16:  # below the row of x labels
                    canvas.text(surface, str(row * CELL_PX), (AREA.left + 2, y + 2), canvas.DIM, 16)
            cell = Box(ox + self.cell[0] * CELL_PX, oy + self.cell[1] * CELL_PX, CELL_PX, CELL_PX)
            canvas.wash(surface, cell, canvas.TESTED)
        canvas.arrow(surface, (ox, oy), (ox + 120, oy), canvas.TEXT)
        canvas.arrow(surface, (ox, oy), (ox, oy + 120), canvas.TEXT)
        canvas.text(surface, "+x", (ox + 124, oy - 8))
        canvas.text(surface, "+y (down)", (ox + 6, oy + 122))
        canvas.text(surface, "(0, 0)", (ox + 4, oy - 18))
        corner = self.pos["box"]
        if Layer.SHAPES in layers:
            pixels = self.rect.move(ox, oy)
            pygame.draw.rect(surface, canvas.MOVER, pixels)
        if Layer.BOUNDS in layers:
            pygame.draw.rect(surface, canvas.BOUNDS, self.rect.move(ox, oy), 1)
        canvas.cross(surface, corner, canvas.WHITE, 3)
