"""Scene ``platformer``: the game's move, x then y, against tiles, with the cells each sweep tested.

What it shows: a small tile map (a :class:`~game.collision.tile_grid.TileGrid`) and a red body
moved exactly as the game moves its bodies: :func:`~game.collision.axis_sweep.move_x`, then
:func:`~game.collision.axis_sweep.move_y`, then the ground probe
:func:`~game.collision.axis_sweep.ground_under`. Blue is the region the x step swept, purple the y
step's, and the washed cells are the ones :meth:`~game.collision.tile_grid.TileGrid.cells_covering`
gives for each swept region, which is where ``entries_in`` looked (the panel prints the cells
and shapes its counters recorded). Left/Right run, Up or Space jumps, F makes the run twenty
times faster (over a tile and a half a tick): the body still stops flush against a wall.
Drag the body to put it anywhere.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.axis_sweep import Move, ground_under, move_x, move_y
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import CountedGrid, TileGrid
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Control, Layer, Point, Scene

TILE_PX = 32
ORIGIN = (AREA.x + 6, AREA.y + 12)  # the map's (0, 0) on screen
MAP = [
    "...............",
    "...........#...",
    "...........#...",
    "......---..#...",
    "...........#.##",
    "..##.......#...",
    "...........#...",
    "#..........#..#",
    "#.....##...#..#",
    "##############.",
    "###############",
]
BODY_W_PX, BODY_H_PX = 20.0, 28.0
RUN_PX_S = 150.0
FAST_FACTOR = 20.0  # 3,000 px/s: 50 px, over a tile and a half, each tick
GRAVITY_PX_S2 = 900.0
JUMP_PX_S = 420.0
MAX_FALL_PX_S = 600.0
KINDS = {"#": TileKind.SOLID, "-": TileKind.ONE_WAY}


def build_grid() -> TileGrid:
    grid = TileGrid(cols=len(MAP[0]), rows=len(MAP), tile_w=TILE_PX, tile_h=TILE_PX)
    for row, line in enumerate(MAP):
        for col, char in enumerate(line):
            if char in KINDS:
                box = Box(col * TILE_PX, row * TILE_PX, TILE_PX, TILE_PX)
                grid.put(col, row, TileShape(box, KINDS[char], col, row))
    return grid


def on_screen(box: Box) -> Box:
    return box.moved(ORIGIN[0], ORIGIN[1])


class Platformer(Scene):
    name = "platformer"
    title = "the platformer's move: x then y against tiles"
    keys_help = "Left/Right run, Up/Space jump, F fast; drag the body"
    group = "motion"
    draws = (Layer.SHAPES, Layer.PAIRS, Layer.CONTACTS, Layer.CELLS)

    def reset(self) -> None:
        self.grid = build_grid()
        self.pos = {"body": (ORIGIN[0] + 250.0, ORIGIN[1] + 256.0 - BODY_H_PX)}
        self.vy = 0.0
        self.fast = False
        self.on_ground = False
        self.last: list[tuple[str, Move, list[tuple[int, int]], int, int]] = []
        self.meter = CostMeter()

    def controls(self) -> list[Control]:
        return [Control(f"run speed: {'x20' if self.fast else 'normal'}", (pygame.K_f,)),
                Control("jump" if self.on_ground else "jump (only from the ground)",
                        (pygame.K_UP,))]

    def body(self) -> Box:
        x, y = self.pos["body"]
        return Box(x - ORIGIN[0], y - ORIGIN[1], BODY_W_PX, BODY_H_PX)

    def grab_boxes(self) -> dict[str, Box]:
        return {"body": on_screen(self.body())}

    def drag_to(self, key: str, point: Point) -> None:
        super().drag_to(key, point)
        self.vy = 0.0

    def on_key(self, key: int) -> None:
        if key in (pygame.K_UP, pygame.K_SPACE) and self.on_ground:
            self.vy = -JUMP_PX_S
        elif key == pygame.K_f:
            self.fast = not self.fast

    def step(self, dt_s: float) -> None:
        if self.dragging is not None:
            return
        direction = (pygame.K_RIGHT in self.held) - (pygame.K_LEFT in self.held)
        vx = direction * RUN_PX_S * (FAST_FACTOR if self.fast else 1.0)
        self.vy = min(MAX_FALL_PX_S, self.vy + GRAVITY_PX_S2 * dt_s)
        box = self.body()
        self.last = []
        for axis, mover, delta in (("x", move_x, vx * dt_s), ("y", move_y, self.vy * dt_s)):
            counted = CountedGrid(self.grid)  # the grid, with each query's work counted
            move = mover(counted, box, delta)
            cells = list(self.grid.cells_covering(move.swept)) if delta else []
            self.last.append((axis, move, cells, counted.stats.cells_visited,
                              counted.stats.shapes_tested))
            box = move.box
        y_move = self.last[1][1]
        if y_move.hit is not None:
            self.vy = 0.0
        self.pos["body"] = (box.x + ORIGIN[0], box.y + ORIGIN[1])

    def refresh(self) -> None:
        body = self.body()
        self.on_ground = ground_under(self.grid, body) is not None
        self.lines = [f"body at ({body.x:.2f}, {body.y:.2f}); vy {self.vy:.0f} px/s",
                      f"on ground (ground_under): {'yes' if self.on_ground else 'no'}",
                      f"run {'x20 (F)' if self.fast else 'normal'}", ""]
        for axis, move, _, visited, tested in self.last:
            hit = ("nothing" if move.hit is None
                   else f"{move.hit.side.value} side at {move.hit.face:g}")
            moved = move.box.x - move.start.x if axis == "x" else move.box.y - move.start.y
            self.lines += [f"{axis} step: moved {moved:+.2f} px; hit {hit}",
                           f"  swept {move.swept.w:.1f} x {move.swept.h:.1f}; "
                           f"{visited} cells, {tested} shapes tested"]
        if self.last:
            (_, x_move, *_), (_, y_move, *_) = self.last
            dx, dy = x_move.box.x - x_move.start.x, y_move.box.y - y_move.start.y
            start = x_move.start
            self.meter.time("the tick's x then y move", lambda: move_y(
                self.grid, move_x(self.grid, start, dx).box, dy))

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        if Layer.CELLS in layers:
            for axis, _, cells, _, _ in self.last:
                for col, row in cells:
                    cell = Box(col * TILE_PX, row * TILE_PX, TILE_PX, TILE_PX)
                    canvas.wash(surface, on_screen(cell), canvas.STILL if axis == "x"
                                else canvas.TESTED, 110)
        if Layer.SHAPES in layers:
            for shape in self.grid.shapes():
                color = (90, 96, 120) if shape.kind is TileKind.SOLID else (150, 110, 60)
                rect = on_screen(shape.box).to_rect()
                if shape.kind is TileKind.ONE_WAY:
                    rect.h = 6
                pygame.draw.rect(surface, color, rect)
                pygame.draw.rect(surface, canvas.AREA_BG, rect, 1)
        if Layer.PAIRS in layers:
            for axis, move, _, _, _ in self.last:
                canvas.box(surface, on_screen(move.swept), canvas.STILL if axis == "x"
                           else canvas.TESTED, 2)
        if Layer.SHAPES in layers:
            canvas.box(surface, on_screen(self.body()), canvas.MOVER)
        if Layer.CONTACTS in layers:
            for _, move, _, _, _ in self.last:
                if move.hit is not None and move.hit.shape is not None:
                    canvas.box(surface, on_screen(move.hit.shape.box), canvas.EXACT, 3)
