"""The F1 debug overlay: hitboxes, the cells and shapes the last tick tested, and its sweeps.

Where it sits: drawn last in a frame, over the world and the HUD, when the player presses F1.
It draws from what the last tick *recorded* (each body's moves in ``world.moves``, the
world's query log and ``world.stats``) and changes nothing: it never queries the solids
and never moves a sprite. While the overlay is on, the tick asks its solids through the
query log's wrapper (:class:`game.sim.world.Measure`, :mod:`game.sim.query_log`): every
lookup writes down what asked for it, the block of cells it visited and the work it did.

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

The panel informs without covering (:class:`PanelMode`, cycled with F5): compact by default
(the frame and tick times, the tick's cost, the stepping state, and the colour key, each
word in the colour it names), full detail one key away, or hidden. It sits in the corner of
the view diagonally opposite the player (:func:`panel_rect`), on translucent glass, and the
player's picture is drawn again above the washes and outlines, under his own green hitbox,
so he stays readable however many cells his lookups visited.

How it stays cheaper than the frame under it (``python -m game.bench.drawing`` times both):
  * **Draw only what can show.** The tick looks all over the map (every enemy moves and
    looks ahead), but the screen shows a few cells of it: of each lookup in the log only
    the cells in sight (:func:`cells_in_sight`) are walked, and sweeps, shapes and hitboxes
    out of sight are passed over. The picture is the same as drawing everything
    (``tests/overlay_reference.py`` does; the tests compare the two, pixel for pixel).
  * **Draw repeated things once.** A cell's nested squares are one small picture for each
    mix of lookups, drawn the first time it is met and then stamped in one blit per cell;
    the panel's lines are rendered once and kept while they are shown; all the
    translucent washes share one layer, blended in one blit.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from enum import Enum
from functools import lru_cache

import pygame

from game.app.assets import Assets
from game.app.hud import HUD_BAR_H_PX, SMALL_TEXT_ANTIALIAS, Color
from game.app.render import screen_offset
from game.app.stepping import key_label
from game.collision.aabb import Box
from game.collision.axis_sweep import Side
from game.collision.contacts import Change, ContactEvent
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.query_log import QueryLog
from game.sim.sprite import BoxSprite
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
SQUARES_KEY: Color = (1, 2, 3)  # the see-through colour around a cell's squares (none uses it)
SQUARES_CACHE = 128  # mixes of lookups met in one cell, kept drawn

PANEL_COLOR: Color = (0, 0, 0)
PANEL_ALPHA = 160  # 0..255: how dark the panel's glass is
PANEL_TEXT: Color = (230, 236, 255)
PANEL_PAD_PX = 3
PANEL_GAP_PX = 2  # between the panel and the HUD bar, or the view's edge
KEY_WORD_GAP_PX = 4  # between the coloured words of a key row
PANEL_KEY = pygame.K_F5  # cycle the panel: compact, full, hidden
MS_PER_S = 1000.0
CONTACT_LINES = 3  # the last few contact starts and ends, from the world's tracker
TEXT_CACHE_LINES = 128  # rendered panel lines (and backings) kept for the next frames


class PanelMode(Enum):
    """How much the panel shows: a few lines (the start), everything, or nothing."""

    COMPACT = "compact"
    FULL = "full"
    HIDDEN = "hidden"

    def next(self) -> PanelMode:
        """The mode :data:`PANEL_KEY` switches to.

        >>> [mode.next().value for mode in PanelMode]
        ['full', 'hidden', 'compact']
        """
        modes = list(PanelMode)
        return modes[(modes.index(self) + 1) % len(modes)]


KeyRow = tuple[tuple[str, Color], ...]  # a row of the colour key: words, each in its colour
Row = str | KeyRow  # a panel row: plain text, or a row of the key

# The colour key, as the panel shows it: what each outline and wash means.
HITBOX_KEY: KeyRow = (("player", PLAYER_COLOR), ("enemy", ENEMY_COLOR), ("coin", COIN_COLOR),
                      ("exit", EXIT_COLOR))
TILE_KEY: KeyRow = (("solid", SHAPE_COLORS[TileKind.SOLID]),
                    ("one-way", SHAPE_COLORS[TileKind.ONE_WAY]),
                    ("hazard", SHAPE_COLORS[TileKind.HAZARD]))
SWEEP_KEY: KeyRow = (("platform", PLATFORM_COLOR), ("sweep x", SWEEP_X_COLOR[:3]),
                     ("y", SWEEP_Y_COLOR[:3]), ("hit", HIT_COLOR))


CELL_KEY_HEADING = "squares in cells, by who looked:"


def cell_key_rows() -> tuple[KeyRow, ...]:
    """The full key's rows for the squares inside visited cells: who asked, in its colour."""
    words = [(purpose, color) for purpose, color in CELL_COLORS.items()]
    return tuple(tuple(words[i:i + 2]) for i in range(0, len(words), 2))


CellBlock = tuple[int, int, int, int]  # first_col, last_col, first_row, last_row (inclusive)


def _screen_rect(box: Box, dx: int, dy: int) -> pygame.Rect:
    """The box's whole pixels moved by the frame's offset (:func:`screen_offset`), as the
    tiles and sprites are drawn (the arithmetic of :meth:`Box.to_rect`)."""
    x, y, w, h = box
    return pygame.Rect(math.floor(x) - dx, math.floor(y) - dy, math.ceil(w), math.ceil(h))


def cells_in_sight(grid: TileGrid, clip: pygame.Rect, offset: tuple[int, int]) -> CellBlock:
    """The block of cells with a pixel inside ``clip`` (screen pixels) this frame: whatever
    the overlay would draw for a cell outside it falls outside the picture.

    >>> cells_in_sight(TileGrid(cols=99, rows=99, tile_w=16, tile_h=16),
    ...                pygame.Rect(0, 0, 320, 180), (8, 0))
    (0, 20, 0, 11)
    """
    left, top = clip.left + offset[0], clip.top + offset[1]  # map pixels
    return (left // grid.tile_w, (left + clip.w - 1) // grid.tile_w,
            top // grid.tile_h, (top + clip.h - 1) // grid.tile_h)


def _fill(target: pygame.Surface, color: Color, rect: pygame.Rect) -> None:
    """``target.fill`` of the part of ``rect`` inside the target's clip. pygame 2.6 moves a
    rect that starts left of or above the surface to its edge instead of cutting it, so a
    fill is cut here first."""
    target.fill(color, rect.clip(target.get_clip()))


class Wash:
    """Translucent fills, gathered during a frame and then blended in one blit of the
    smallest surface that holds them all (not a whole-screen layer every frame)."""

    def __init__(self) -> None:
        self.fills: list[tuple[Color, pygame.Rect]] = []

    def fill(self, color: Color, rect: pygame.Rect) -> None:
        """Cover ``rect`` with ``color`` (RGBA); a later fill replaces an earlier one."""
        self.fills.append((color, rect))

    def blend_onto(self, target: pygame.Surface) -> None:
        if not self.fills:
            return
        rects = [rect for _, rect in self.fills]
        area = rects[0].unionall(rects[1:]).clip(target.get_clip())
        if not area.w or not area.h:
            return
        layer = pygame.Surface(area.size, pygame.SRCALPHA)
        for color, rect in self.fills:  # cut to the layer first: see :func:`_fill`
            layer.fill(color, rect.clip(area).move(-area.x, -area.y))
        target.blit(layer, area.topleft)


class Checked:
    """What the last tick's lookups tested, read from its query log: the cells each kind of
    lookup visited, and every shape tested (the tiles in those cells, the platforms beside).

    ``within`` keeps only the cells of one block (and the tiles in them), by default the
    whole map: for drawing, the ones in sight. Moving shapes tested beside the tiles are
    kept wherever they are.
    """

    def __init__(self, grid: TileGrid, log: QueryLog, within: CellBlock | None = None) -> None:
        self.cells: dict[str, set[tuple[int, int]]] = {}
        self.shapes: dict[TileShape, None] = {}  # in the order first tested, each once
        seen: set[tuple[int, int]] = set()  # a cell's shapes are gathered on its first visit
        left, right, top, bottom = within or (0, grid.cols - 1, 0, grid.rows - 1)
        for purpose, first_col, last_col, first_row, last_row, extra in log.queries:
            visited = self.cells.setdefault(purpose, set())
            if first_col <= right and last_col >= left and first_row <= bottom and last_row >= top:
                cols = range(max(first_col, left), min(last_col, right) + 1)
                rows = range(max(first_row, top), min(last_row, bottom) + 1)
            else:  # nothing of it inside the block
                cols = rows = range(0)
            for row in rows:
                for col in cols:
                    visited.add((col, row))
                    if (col, row) in seen:
                        continue
                    seen.add((col, row))
                    for shape in grid.shapes_at(col, row):
                        if shape.box.w > 0 and shape.box.h > 0:  # lookups skip empty shapes
                            self.shapes.setdefault(shape)
            for shape in extra:
                self.shapes.setdefault(shape)

    def all_cells(self) -> set[tuple[int, int]]:
        return set().union(*self.cells.values())


Outline = tuple[Color, pygame.Rect]
Stamp = tuple[pygame.Surface, tuple[int, int]]  # a picture and where its top left goes


def _draw_tested(wash: Wash, world: World, clip: pygame.Rect,
                 offset: tuple[int, int]) -> tuple[list[Stamp], list[Outline]]:
    """Wash every cell in sight that the last tick's lookups visited; return the squares
    to stamp in each such cell and the outline of every shape they tested (read-only: cells
    are read through ``shapes_at``, never queried)."""
    grid = world.grid
    tested = Checked(grid, world.query_log, within=cells_in_sight(grid, clip, offset))
    dx, dy = offset
    tile_w, tile_h = grid.tile_w, grid.tile_h
    colors_at: dict[tuple[int, int], list[Color]] = {}  # each cell's squares, outermost first
    for purpose in [*CELL_COLORS, *(p for p in tested.cells if p not in CELL_COLORS)]:
        color = CELL_COLORS.get(purpose, OTHER_CELL_COLOR)
        for cell in tested.cells.get(purpose, ()):
            colors_at.setdefault(cell, []).append(color)
    stamps: list[Stamp] = []
    for (col, row), colors in colors_at.items():
        corner = col * tile_w - dx, row * tile_h - dy
        wash.fill(CELL_WASH, pygame.Rect(corner, (tile_w, tile_h)))
        stamps.append((_squares(tile_w, tile_h, tuple(colors)), corner))
    outlines: list[Outline] = []
    for shape in tested.shapes:
        rect = _screen_rect(shape.box, dx, dy)
        if not clip.colliderect(rect):
            continue  # a platform tested out of sight
        color = PLATFORM_COLOR if shape.col == -1 else SHAPE_COLORS[shape.kind]
        wash.fill((*color[:3], SHAPE_FILL_ALPHA), rect)
        outlines.append((color, rect))
    return stamps, outlines


@lru_cache(maxsize=SQUARES_CACHE)
def _squares(tile_w: int, tile_h: int, colors: tuple[Color, ...]) -> pygame.Surface:
    """A cell's nested squares, one per colour, each :data:`CELL_SQUARE_STEP_PX` inside the
    one before, on a see-through colour key: drawn once for each mix of lookups, then one
    blit per cell."""
    stamp = pygame.Surface((tile_w, tile_h))
    stamp.fill(SQUARES_KEY)
    stamp.set_colorkey(SQUARES_KEY)
    cell = stamp.get_rect()
    for ring, color in enumerate(colors, start=1):
        square = cell.inflate(-ring * CELL_SQUARE_STEP_PX, -ring * CELL_SQUARE_STEP_PX)
        if square.w > 0 and square.h > 0:
            pygame.draw.rect(stamp, color, square, 1)
    return stamp


def _draw_sweeps(wash: Wash, world: World, clip: pygame.Rect,
                 offset: tuple[int, int]) -> list[pygame.Rect]:
    """Wash the region each body's x and y moves swept; return the bars marking the faces
    they hit. Only what falls in ``clip`` is kept: most bodies are out of sight."""
    dx, dy = offset
    bars: list[pygame.Rect] = []
    for body in world.bodies():
        moves = world.moves.get(body)
        if moves is None:
            continue  # no move recorded (a respawn)
        for move, color in ((moves.x, SWEEP_X_COLOR), (moves.y, SWEEP_Y_COLOR)):
            swept = move.swept
            if not math.isfinite(sum(swept)):  # a NaN or an infinity makes the sum one
                continue
            region = _screen_rect(swept, dx, dy)
            if clip.colliderect(region):
                wash.fill(color, region)
            hit = move.hit
            if hit is not None:
                bar = _hit_bar(move.box, hit.side, hit.face, dx, dy)
                if clip.colliderect(bar.inflate(2 * HIT_EDGE_PX, 2 * HIT_EDGE_PX)):
                    bars.append(bar)
    return bars


def _hit_bar(box: Box, side: Side, face: float, dx: int, dy: int) -> pygame.Rect:
    """The bar straddling the face a move stopped at, as long as the body's side."""
    if side in (Side.LEFT, Side.RIGHT):
        return pygame.Rect(math.floor(face) - dx - HIT_MARK_PX // 2, math.floor(box.top) - dy,
                           HIT_MARK_PX, math.ceil(box.h))
    return pygame.Rect(math.floor(box.left) - dx, math.floor(face) - dy - HIT_MARK_PX // 2,
                       math.ceil(box.w), HIT_MARK_PX)


def _draw_hitboxes(target: pygame.Surface, world: World, clip: pygame.Rect,
                   offset: tuple[int, int]) -> None:
    """The 1 px outline of every hitbox in sight, the player's last (on top)."""
    dx, dy = offset
    left, top = clip.left + dx, clip.top + dy  # the clip, in map pixels
    right, bottom = left + clip.w, top + clip.h
    kinds: tuple[tuple[Color, Iterable[BoxSprite]], ...] = (
        (EXIT_COLOR, world.exits), (COIN_COLOR, world.coins), (ENEMY_COLOR, world.enemies),
        (PLATFORM_COLOR, world.platforms), (EXIT_COLOR, world.checkpoints),
        (PLAYER_COLOR, (world.player,)))
    for color, things in kinds:
        for thing in things:
            x, y, w, h = box = thing.box
            # Drawn, it spans floor(x) to floor(x) + ceil(w), short of x + w + 1: so a box
            # that ends that far left of the clip (or above it) leaves no pixel in it.
            if x < right and y < bottom and x + w + 1 > left and y + h + 1 > top:
                pygame.draw.rect(target, color, _screen_rect(box, dx, dy), 1)


def _contact_line(event: ContactEvent[ContactKey]) -> str:
    """``tick 307 +enemy 0``: a contact starting (+) or ending (-) with the player."""
    sign = "+" if event.change is Change.STARTED else "-"
    other = next((key for key in event.pair if key != PLAYER_KEY), event.pair[0])
    return f"tick {event.tick} {sign}{other[0]} {other[1]}"


def panel_lines(world: World, fps: float | None, update_ms: float,
                extra_lines: Sequence[str] = ()) -> tuple[str, ...]:
    """What the panel says, line by line (the arguments are :func:`draw_debug`'s)."""
    player, stats = world.player, world.stats
    ground = "ground" if player.on_ground else "air"
    return (
        _times_line(fps, update_ms),
        f"collide {stats.collision_s * MS_PER_S:4.2f} ms",
        _cost_line(world),
        (f"{len(world.query_log.queries)} lookups, all drawn" if world.measure.queries
         else "lookups not recorded"),
        f"x {player.box.x:.1f} y {player.box.y:.1f} {ground}",
        f"vx {player.vx:.0f} vy {player.vy:.0f}",
        "walls: tile grid + sweeps",
        f"enemies: brute force x{len(world.enemies)}",
        *(_contact_line(event) for event in list(world.contacts.log)[-CONTACT_LINES:]),
        *extra_lines,
    )


def _times_line(fps: float | None, update_ms: float) -> str:
    """``FPS 59.5  tick 0.42 ms``: the panel's first line in every mode."""
    frames = "no window" if fps is None else f"FPS {fps:4.1f}"  # a picture has no frame rate
    return f"{frames}  tick {update_ms:4.2f} ms"


def _cost_line(world: World) -> str:
    """``12 shapes in 9 cells``: what the whole tick's lookups did."""
    return f"{world.stats.shapes_tested} shapes in {world.stats.cells_visited} cells"


def compact_lines(world: World, fps: float | None, update_ms: float,
                  extra_lines: Sequence[str] = ()) -> tuple[str, ...]:
    """The compact panel's text: the times, the tick's cost, and the first of
    ``extra_lines`` (the window's stepping state), with the key to more detail."""
    return (_times_line(fps, update_ms), _cost_line(world), *extra_lines[:1],
            f"{key_label(PANEL_KEY)} more")


def panel_rows(world: World, fps: float | None, update_ms: float,
               extra_lines: Sequence[str] = (),
               mode: PanelMode = PanelMode.COMPACT) -> tuple[Row, ...]:
    """Every row the panel shows in ``mode``: its text, then the colour key."""
    if mode is PanelMode.HIDDEN:
        return ()
    if mode is PanelMode.COMPACT:
        return (*compact_lines(world, fps, update_ms, extra_lines),
                HITBOX_KEY, TILE_KEY, SWEEP_KEY)
    return (*panel_lines(world, fps, update_ms, extra_lines), f"{key_label(PANEL_KEY)} hide",
            HITBOX_KEY, TILE_KEY, SWEEP_KEY, CELL_KEY_HEADING, *cell_key_rows())


def _row_faces(font: pygame.font.Font, row: Row) -> list[tuple[pygame.Surface, int]]:
    """A row's rendered pieces and each one's x from the row's left."""
    if isinstance(row, str):
        return [(_line_face(font, row), 0)]
    faces, x = [], 0
    for word, color in row:
        face = _line_face(font, word, color)
        faces.append((face, x))
        x += face.get_width() + KEY_WORD_GAP_PX
    return faces


def panel_rect(rows: Sequence[Row], font: pygame.font.Font, view: pygame.Rect,
               player_at: tuple[int, int]) -> pygame.Rect:
    """Where the panel goes: in the corner of ``view`` diagonally opposite ``player_at``
    (the player's middle, on screen), under the HUD bar when at the top. Empty when there
    are no rows."""
    if not rows:
        return pygame.Rect(view.left, view.top, 0, 0)
    width = max(face.get_width() + x for row in rows for face, x in _row_faces(font, row))
    size = (width + 2 * PANEL_PAD_PX, len(rows) * font.get_linesize() + 2 * PANEL_PAD_PX)
    panel = pygame.Rect((0, 0), size)
    play_top = view.top + HUD_BAR_H_PX
    if player_at[0] >= view.centerx:
        panel.left = view.left
    else:
        panel.right = view.right
    if player_at[1] >= (play_top + view.bottom) // 2:
        panel.top = play_top + PANEL_GAP_PX
    else:
        panel.bottom = view.bottom - PANEL_GAP_PX
    return panel


def _draw_panel(target: pygame.Surface, rows: Sequence[Row], font: pygame.font.Font,
                player_at: tuple[int, int]) -> pygame.Rect:
    """The rows on dark glass in the corner away from the player (:func:`panel_rect`): the
    backing and every piece in one call. Returns where the panel went."""
    panel = panel_rect(rows, font, target.get_rect(), player_at)
    if not rows:
        return panel
    line_h = font.get_linesize()
    left, top = panel.left + PANEL_PAD_PX, panel.top + PANEL_PAD_PX
    target.blits([(_panel_backing(panel.size), panel.topleft),
                  *((face, (left + x, top + i * line_h))
                    for i, row in enumerate(rows) for face, x in _row_faces(font, row))],
                 doreturn=False)
    return panel


@lru_cache(maxsize=TEXT_CACHE_LINES)
def _line_face(font: pygame.font.Font, line: str, color: Color = PANEL_TEXT) -> pygame.Surface:
    """One line (or word) of panel text, rendered once and kept while it keeps being shown."""
    return font.render(line, SMALL_TEXT_ANTIALIAS, color)


@lru_cache(maxsize=TEXT_CACHE_LINES)
def _panel_backing(size: tuple[int, int]) -> pygame.Surface:
    """The panel's dark glass: one colour at one alpha for the whole surface, which blends
    faster than the same alpha stored in every pixel."""
    backing = pygame.Surface(size)
    backing.fill(PANEL_COLOR)
    backing.set_alpha(PANEL_ALPHA)
    return backing


def draw_debug(target: pygame.Surface, world: World, assets: Assets, fps: float | None,
               update_ms: float, extra_lines: Sequence[str] = (),
               panel: PanelMode = PanelMode.COMPACT) -> pygame.Rect:
    """Draw the overlay for the last tick: checked tiles, sweeps, the player's picture again,
    the hitboxes, and the panel (in ``panel`` mode). Returns where the panel went.

    ``fps`` is the window's measured frame rate, None for a picture made without a window
    (the panel then says so); ``update_ms`` is how long the last frame's ticks took, in
    milliseconds; ``extra_lines`` end the panel (the window's stepping keys and
    state, :mod:`game.app.stepping`). Reads ``world`` and changes none of it.
    """
    clip = target.get_clip()
    offset = screen_offset(world.camera)
    wash = Wash()  # translucent fills go here
    squares, outlines = _draw_tested(wash, world, clip, offset)
    bars = _draw_sweeps(wash, world, clip, offset)
    wash.blend_onto(target)
    target.blits(squares, doreturn=False)  # one square inside each cell a lookup visited
    for color, rect in outlines:
        rim = rect.inflate(-2 * SHAPE_RIM_INSET_PX, -2 * SHAPE_RIM_INSET_PX)
        pygame.draw.rect(target, SHAPE_RIM_COLOR, rim, 1)
        pygame.draw.rect(target, color, rect, 1)
    for bar in bars:
        _fill(target, HIT_EDGE_COLOR, bar.inflate(2 * HIT_EDGE_PX, 2 * HIT_EDGE_PX))
    for bar in bars:
        _fill(target, HIT_COLOR, bar)
    draw_player_again(target, world, offset)
    _draw_hitboxes(target, world, clip, offset)
    return _draw_panel(target, panel_rows(world, fps, update_ms, extra_lines, panel),
                       assets.small_font, player_on_screen(world))


def player_on_screen(world: World) -> tuple[int, int]:
    """The middle of the player's hitbox, in screen pixels: the panel keeps away from it."""
    return _screen_rect(world.player.box, *screen_offset(world.camera)).center


def draw_player_again(target: pygame.Surface, world: World, offset: tuple[int, int]) -> None:
    """The player's picture, as the frame drew it, again over the washes and outlines (a
    player with no picture yet, in a test, has none to draw)."""
    player = world.player
    if player.strip is not None:
        target.blit(player.image, player.rect.move(-offset[0], -offset[1]))
