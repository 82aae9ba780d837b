"""The F1 debug overlay: hitboxes, the cells and shapes the last tick tested, and its sweeps.

Where it sits: drawn last in a frame, over the world and the HUD, when the player presses F1.
It draws from what the last tick *recorded* (each body's ``last_x``/``last_y`` moves, the
world's query log and ``world.stats``) and changes nothing: it never calls
:meth:`TileGrid.entries_in`, whose work counters the stats are read from, and never moves a
sprite. While the overlay is on, the tick keeps the query log (:class:`game.sim.world.Measure`):
every lookup writes down what asked for it and the block of cells it visited.

What it teaches (read the colours):
  * **Hitboxes are not sprites.** The 1 px outlines are the float boxes the physics uses
    (player green, enemies red, coins yellow, exits and checkpoints cyan, moving
    platforms pink); the art around them is decoration.
  * **Broad phase.** Every cell a lookup visited in the last tick is washed, with one square
    inside it for each kind of lookup that visited it, in the colour of what asked
    (:data:`CELL_COLORS`: an enemy's ledge look-ahead gold, a platform's push or carry pink,
    the x sweep blue, the y sweep purple, the ground probe white, the hazard check red), and
    every shape those lookups tested is outlined (Solid grey, OneWay orange, Hazard
    magenta, a moving platform pink). Nothing else was tested: the rest of the map cost
    nothing. A fast fall washes its whole swept column; a body at rest only the cells its
    sweeps and probes touched (a y move that lands on the floor has found the ground, so
    no probe runs after it).
  * **Swept moves.** Each body moved along x (the blue sweep) and then along y (the purple
    sweep); a red bar marks the face a sweep stopped at. Standing still, you still see a
    thin purple sweep hitting the floor every tick: gravity pulls, the floor stops it.
  * **The cost.** "N shapes in M cells" is what the whole tick's lookups did.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache

import pygame

from game.app.assets import Assets
from game.app.hud import HUD_BAR_H_PX, SMALL_TEXT_ANTIALIAS, Color
from game.app.render import screen_offset
from game.collision.aabb import Box
from game.collision.contacts import Change, ContactEvent
from game.sim.camera import Camera
from game.sim.movement import Move, Side
from game.sim.tilegrid import QueryLog, TileGrid, TileKind, TileShape
from game.sim.world import PLAYER_KEY, ContactKey, World

PLAYER_COLOR: Color = (80, 255, 96)
ENEMY_COLOR: Color = (255, 64, 64)
COIN_COLOR: Color = (255, 232, 64)
EXIT_COLOR: Color = (64, 240, 255)  # exits and checkpoints
PLATFORM_COLOR: Color = (255, 120, 200)
SHAPE_COLORS: dict[TileKind, Color] = {
    TileKind.SOLID: (225, 225, 235),
    TileKind.ONE_WAY: (255, 150, 40),
    TileKind.HAZARD: (255, 64, 255),
}
SHAPE_RIM_COLOR: Color = (24, 20, 40)  # just inside each outline, so it shows on light tiles
SHAPE_RIM_INSET_PX = 1
SHAPE_FILL_ALPHA = 40  # 0..255: a faint wash inside each checked tile shape
SWEEP_X_COLOR: Color = (60, 120, 255, 90)
SWEEP_Y_COLOR: Color = (180, 70, 255, 90)
HIT_COLOR: Color = (255, 40, 40)
HIT_EDGE_COLOR: Color = (0, 0, 0)  # a dark rim so the bar shows on light tiles too
HIT_MARK_PX = 2  # the hit-face bar is this thick, straddling the face
HIT_EDGE_PX = 1

# Each visited cell gets a faint wash, and one square per kind of lookup that visited it, in
# the colour of what asked, nested so that no kind hides another (the purposes World.step
# writes, in the order of the tick; the first square is the outermost).
CELL_WASH: Color = (255, 255, 255, 50)
CELL_COLORS: dict[str, Color] = {
    "ledge look-ahead": (255, 200, 0),
    "platforms": (255, 120, 200),
    "x sweep": (60, 120, 255),
    "y sweep": (180, 70, 255),
    "ground probe": (255, 255, 255),
    "hazards": (255, 60, 60),
}
OTHER_CELL_COLOR: Color = (160, 160, 160)  # any other lookup (a checkpoint's spawn)
CELL_SQUARE_STEP_PX = 2  # how much each square sits inside the one before

PANEL_COLOR: Color = (0, 0, 0)
PANEL_ALPHA = 160  # 0..255: how dark the panel's glass is
PANEL_TEXT: Color = (230, 236, 255)
PANEL_PAD_PX = 3
PANEL_GAP_PX = 2  # between the HUD bar and the panel
MS_PER_S = 1000.0
CONTACT_LINES = 3  # the last few contact starts and ends, from the world's tracker
TEXT_CACHE_LINES = 128  # rendered panel lines (and backings) kept for the next frames


def _screen_rect(box: Box, camera: Camera) -> pygame.Rect:
    """The box's whole pixels through the camera, as the tiles and sprites are drawn (the
    arithmetic of :meth:`Box.to_rect`, moved by the camera's whole-pixel offset)."""
    return pygame.Rect(math.floor(box.x) - math.floor(camera.x),
                       math.floor(box.y) - math.floor(camera.y),
                       math.ceil(box.w), math.ceil(box.h))


class Wash:
    """Translucent fills, gathered during a frame and then blended in one blit of the
    smallest surface that holds them all (not a whole-screen layer every frame)."""

    def __init__(self) -> None:
        self.fills: list[tuple[Color, pygame.Rect]] = []

    def fill(self, color: Color, rect: pygame.Rect) -> None:
        """Cover ``rect`` with ``color`` (RGBA); a later fill replaces an earlier one."""
        self.fills.append((color, pygame.Rect(rect)))

    def blend_onto(self, target: pygame.Surface) -> None:
        if not self.fills:
            return
        rects = [rect for _, rect in self.fills]
        area = rects[0].unionall(rects[1:]).clip(target.get_rect())
        if not area.w or not area.h:
            return
        layer = pygame.Surface(area.size, pygame.SRCALPHA)
        for color, rect in self.fills:
            layer.fill(color, rect.move(-area.x, -area.y))
        target.blit(layer, area.topleft)


class Checked:
    """What the last tick's lookups tested, read from its query log: the cells each kind of
    lookup visited, and every shape tested (the tiles in those cells, the platforms beside)."""

    def __init__(self, grid: TileGrid, log: QueryLog) -> None:
        self.cells: dict[str, set[tuple[int, int]]] = {}
        self.shapes: dict[TileShape, None] = {}  # in the order first tested, each once
        seen: set[tuple[int, int]] = set()  # a cell's shapes are gathered on its first visit
        for query in log.queries:
            visited = self.cells.setdefault(query.purpose, set())
            cols = range(query.first_col, query.last_col + 1)
            for row in range(query.first_row, query.last_row + 1):
                for col in cols:
                    visited.add((col, row))
                    if (col, row) in seen:
                        continue
                    seen.add((col, row))
                    for shape in grid.shapes_at(col, row):
                        if shape.box.w > 0 and shape.box.h > 0:  # lookups skip empty shapes
                            self.shapes.setdefault(shape)
            for shape in query.extra:
                self.shapes.setdefault(shape)

    def all_cells(self) -> set[tuple[int, int]]:
        return set().union(*self.cells.values())


Outline = tuple[Color, pygame.Rect]


def _draw_tested(wash: Wash, world: World) -> tuple[list[Outline], list[Outline]]:
    """Wash every cell the last tick's lookups visited; return a square for each such cell
    and the outline of every shape they tested (read-only: cells are read through
    ``shapes_at``, never ``entries_in``)."""
    grid, camera = world.grid, world.camera
    tested = Checked(grid, world.query_log)
    dx, dy = screen_offset(camera)
    tile_w, tile_h = grid.tile_w, grid.tile_h
    squares: list[Outline] = []
    order = [*CELL_COLORS, *(p for p in tested.cells if p not in CELL_COLORS)]
    inset: dict[tuple[int, int], int] = {}
    for purpose in order:
        color = CELL_COLORS.get(purpose, OTHER_CELL_COLOR)
        for col, row in tested.cells.get(purpose, ()):  # squares of two cells never overlap
            cell = pygame.Rect(col * tile_w - dx, row * tile_h - dy, tile_w, tile_h)
            if (col, row) not in inset:
                wash.fill(CELL_WASH, cell)
            step = inset[col, row] = inset.get((col, row), 0) + CELL_SQUARE_STEP_PX
            square = cell.inflate(-step, -step)
            if square.w > 0 and square.h > 0:
                squares.append((color, square))
    outlines: list[Outline] = []
    for shape in tested.shapes:
        color = PLATFORM_COLOR if shape.col == -1 else SHAPE_COLORS[shape.kind]
        rect = _screen_rect(shape.box, camera)
        wash.fill((*color[:3], SHAPE_FILL_ALPHA), rect)
        outlines.append((color, rect))
    return squares, outlines


def _draw_sweep(wash: Wash, move: Move | None, color: Color,
                camera: Camera) -> pygame.Rect | None:
    """Wash the region one axis move swept; return the bar marking the face it hit, if any."""
    if move is None:
        return None
    swept = move.swept
    if not swept.is_finite():
        return None
    wash.fill(color, _screen_rect(swept, camera))
    hit = move.hit
    if hit is None:
        return None
    box = move.box
    if hit.side in (Side.LEFT, Side.RIGHT):
        dx, dy = screen_offset(camera)
        left = math.floor(hit.face) - dx - HIT_MARK_PX // 2
        top = math.floor(box.top) - dy
        bar = pygame.Rect(left, top, HIT_MARK_PX, math.ceil(box.h))
    else:
        dx, dy = screen_offset(camera)
        left = math.floor(box.left) - dx
        top = math.floor(hit.face) - dy - HIT_MARK_PX // 2
        bar = pygame.Rect(left, top, math.ceil(box.w), HIT_MARK_PX)
    return bar


def _draw_outlines(target: pygame.Surface, world: World) -> None:
    camera = world.camera
    for goal in world.exits:
        pygame.draw.rect(target, EXIT_COLOR, _screen_rect(goal.box, camera), width=1)
    for coin in world.coins:
        pygame.draw.rect(target, COIN_COLOR, _screen_rect(coin.box, camera), width=1)
    for enemy in world.enemies:
        pygame.draw.rect(target, ENEMY_COLOR, _screen_rect(enemy.box, camera), width=1)
    for platform in world.platforms:
        pygame.draw.rect(target, PLATFORM_COLOR, _screen_rect(platform.box, camera), width=1)
    for flag in world.checkpoints:
        pygame.draw.rect(target, EXIT_COLOR, _screen_rect(flag.box, camera), width=1)
    pygame.draw.rect(target, PLAYER_COLOR, _screen_rect(world.player.box, camera), width=1)


def _contact_line(event: ContactEvent[ContactKey]) -> str:
    """``tick 307 +enemy 0``: a contact starting (+) or ending (-) with the player."""
    sign = "+" if event.change is Change.STARTED else "-"
    other = next((key for key in event.pair if key != PLAYER_KEY), event.pair[0])
    return f"tick {event.tick} {sign}{other[0]} {other[1]}"


def _draw_panel(target: pygame.Surface, world: World, assets: Assets, fps: float | None,
                update_ms: float, extra_lines: Sequence[str] = ()) -> None:
    player, stats = world.player, world.stats
    ground = "ground" if player.on_ground else "air"
    frames = "no window" if fps is None else f"FPS {fps:4.1f}"  # a picture has no frame rate
    lines = (
        f"{frames}  tick {update_ms:4.2f} ms",
        f"collide {stats.collision_s * MS_PER_S:4.2f} ms",
        f"{stats.shapes_tested} shapes in {stats.cells_visited} cells",
        (f"{len(world.query_log.queries)} lookups, all drawn" if world.measure.queries
         else "lookups not recorded"),
        f"x {player.box.x:.1f} y {player.box.y:.1f} {ground}",
        f"vx {player.vx:.0f} vy {player.vy:.0f}",
        "walls: tile grid + sweeps",
        f"enemies: brute force x{len(world.enemies)}",
        *(_contact_line(event) for event in list(world.contacts.log)[-CONTACT_LINES:]),
        *extra_lines,
    )
    font = assets.small_font
    line_h = font.get_linesize()
    faces = [_line_face(font, line) for line in lines]
    width = max(face.get_width() for face in faces) + 2 * PANEL_PAD_PX
    panel = pygame.Rect(0, HUD_BAR_H_PX + PANEL_GAP_PX, width,
                        len(lines) * line_h + 2 * PANEL_PAD_PX)
    target.blit(_panel_backing(panel.size), panel.topleft)
    y = panel.top + PANEL_PAD_PX
    for face in faces:
        target.blit(face, (panel.left + PANEL_PAD_PX, y))
        y += line_h


@lru_cache(maxsize=TEXT_CACHE_LINES)
def _line_face(font: pygame.font.Font, line: str) -> pygame.Surface:
    """One line of panel text, rendered once and kept while it keeps being shown."""
    return font.render(line, SMALL_TEXT_ANTIALIAS, PANEL_TEXT)


@lru_cache(maxsize=TEXT_CACHE_LINES)
def _panel_backing(size: tuple[int, int]) -> pygame.Surface:
    """The panel's dark glass: one colour at one alpha for the whole surface, which blends
    faster than the same alpha stored in every pixel."""
    backing = pygame.Surface(size)
    backing.fill(PANEL_COLOR)
    backing.set_alpha(PANEL_ALPHA)
    return backing


def draw_debug(target: pygame.Surface, world: World, assets: Assets, fps: float | None,
               update_ms: float, extra_lines: Sequence[str] = ()) -> None:
    """Draw the overlay for the last tick: checked tiles, sweeps, hitboxes, and the numbers.

    ``fps`` is the window's measured frame rate, None for a picture made without a window
    (the panel then says so); ``update_ms`` is how long the last frame's ticks took, in
    milliseconds; ``extra_lines`` end the panel (the window's stepping keys and
    state, :mod:`game.app.stepping`). Reads ``world`` and changes none of it.
    """
    camera = world.camera
    wash = Wash()  # translucent fills go here
    squares, outlines = _draw_tested(wash, world)
    bars: list[pygame.Rect] = []
    for body in world.bodies():
        for move, color in ((body.last_x, SWEEP_X_COLOR), (body.last_y, SWEEP_Y_COLOR)):
            bar = _draw_sweep(wash, move, color, camera)
            if bar is not None:
                bars.append(bar)
    wash.blend_onto(target)
    for color, rect in squares:  # one square inside each cell a lookup visited
        pygame.draw.rect(target, color, rect, width=1)
    for color, rect in outlines:
        rim = rect.inflate(-2 * SHAPE_RIM_INSET_PX, -2 * SHAPE_RIM_INSET_PX)
        pygame.draw.rect(target, SHAPE_RIM_COLOR, rim, width=1)
        pygame.draw.rect(target, color, rect, width=1)
    for bar in bars:
        target.fill(HIT_EDGE_COLOR, bar.inflate(2 * HIT_EDGE_PX, 2 * HIT_EDGE_PX))
    for bar in bars:
        target.fill(HIT_COLOR, bar)
    _draw_outlines(target, world)
    _draw_panel(target, world, assets, fps, update_ms, extra_lines)
