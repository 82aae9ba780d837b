"""Drawing helpers for the lab: its colours, its text, and boxes, polygons and arrows on screen.

Where it sits: under every scene's ``draw``; it only draws and never decides anything.

Text is drawn in the game's own pixel font, unsmoothed, so it stays crisp at any whole scale.

What it teaches: one colour per role, the same in every scene, so a reader learns the code
once: red is the thing you move, blue the thing it meets, yellow a bounding box (the cheap
answer), purple what was tested. Three colours judge an answer, and only they do
(:data:`VERDICTS`, keyed at the bottom of every scene): green the exact method's answer,
teal an approximate method that is right here, orange an approximate method that is wrong
here.
"""

from __future__ import annotations

import io
import math
from collections.abc import Sequence

import pygame

from game.app.assets import ASSETS, BIG_FONT_FILE, BIG_FONT_PX, FONT_FILE, FONT_PX, MAX_ASSET_BYTES
from game.app.files import FileProblem, read_small_bytes
from game.collision.aabb import Box

Color = tuple[int, int, int]

BACKGROUND: Color = (22, 24, 36)
AREA_BG: Color = (30, 33, 48)
GRID: Color = (48, 52, 72)
TEXT: Color = (232, 232, 240)
DIM: Color = (150, 152, 172)
MOVER: Color = (222, 72, 72)      # the shape you drag
STILL: Color = (72, 124, 222)     # the shape it meets
BOUNDS: Color = (240, 210, 60)    # bounding boxes: the cheap answer
EXACT: Color = (90, 205, 120)     # the exact method's answer
APPROX_RIGHT: Color = (80, 200, 210)  # an approximate method, right here
WRONG: Color = (245, 150, 50)     # an approximate method, wrong here
TESTED: Color = (170, 110, 230)   # what was tested: cells, pairs, positions
WHITE: Color = (255, 255, 255)

VERDICTS: tuple[tuple[Color, str], ...] = (
    (EXACT, "green: the exact method's answer"),
    (APPROX_RIGHT, "teal: an approximate method, right here"),
    (WRONG, "orange: an approximate method, wrong here"),
)

TEXT_PT = 20   # a size asked for; see :func:`font` for what draws it
TITLE_PT = 28
BIG_FROM_PT = 24  # sizes from this up get the big font
LINE_GAP_PX = 3   # between rows of text

_fonts: dict[bool, pygame.font.Font] = {}


def font(size_pt: int = TEXT_PT) -> pygame.font.Font:
    """The game's own pixel font (``assets/font.bdf``, or ``font-big.bdf`` for titles), made
    once; pygame's bundled font if those files cannot be read."""
    big = size_pt >= BIG_FROM_PT
    if big not in _fonts:
        if not pygame.font.get_init():
            pygame.font.init()
        name, size_px = (BIG_FONT_FILE, BIG_FONT_PX) if big else (FONT_FILE, FONT_PX)
        try:
            data = read_small_bytes(ASSETS / name, MAX_ASSET_BYTES, "the font")
            _fonts[big] = pygame.font.Font(io.BytesIO(data), size_px)
        except (pygame.error, FileProblem):
            _fonts[big] = pygame.font.Font(None, size_pt)
    return _fonts[big]


def line_height(size_pt: int = TEXT_PT) -> int:
    return font(size_pt).get_linesize() + LINE_GAP_PX


def text_width(words: str, size_pt: int = TEXT_PT) -> int:
    return font(size_pt).size(words)[0]


def text(surface: pygame.Surface, words: str, at: tuple[int, int], color: Color = TEXT,
         size_pt: int = TEXT_PT) -> pygame.Rect:
    """Draw one line with its top-left at ``at``; returns where it went."""
    image = font(size_pt).render(words, False, color)
    return surface.blit(image, at)


def lines(surface: pygame.Surface, rows: Sequence[str], at: tuple[int, int],
          color: Color = TEXT, size_pt: int = TEXT_PT) -> int:
    """Draw lines top to bottom; returns the y below the last one."""
    x, y = at
    step = line_height(size_pt)
    for row in rows:
        text(surface, row, (x, y), color, size_pt)
        y += step
    return y


def box(surface: pygame.Surface, shape: Box, color: Color, width: int = 0) -> None:
    """A box as pixels (``Box.to_rect``); a box with no width or height as a line."""
    if shape.w <= 0 or shape.h <= 0:
        start = (math.floor(shape.x), math.floor(shape.y))
        end = (math.floor(shape.right), math.floor(shape.bottom))
        pygame.draw.line(surface, color, start, end, 3)
        return
    pygame.draw.rect(surface, color, shape.to_rect(), width)


def wash(surface: pygame.Surface, shape: Box, color: Color, alpha: int = 70) -> None:
    """A see-through fill: a cell or a region that was looked at."""
    rect = shape.to_rect()
    if rect.w <= 0 or rect.h <= 0:
        return
    layer = pygame.Surface(rect.size, pygame.SRCALPHA)
    layer.fill((*color, alpha))
    surface.blit(layer, rect.topleft)


def polygon(surface: pygame.Surface, points: Sequence[tuple[float, float]], color: Color,
            width: int = 0) -> None:
    pygame.draw.polygon(surface, color, [(round(x), round(y)) for x, y in points], width)


def arrow(surface: pygame.Surface, start: tuple[float, float], end: tuple[float, float],
          color: Color, width: int = 2) -> None:
    """A line with a head at ``end``."""
    pygame.draw.line(surface, color, start, end, width)
    dx, dy = end[0] - start[0], end[1] - start[1]
    length = math.hypot(dx, dy)
    if length < 1:
        return
    ux, uy = dx / length, dy / length
    head = min(10.0, length / 2)
    left = (end[0] - head * (ux - 0.5 * uy), end[1] - head * (uy + 0.5 * ux))
    right = (end[0] - head * (ux + 0.5 * uy), end[1] - head * (uy - 0.5 * ux))
    pygame.draw.polygon(surface, color, [end, left, right])


def cross(surface: pygame.Surface, at: tuple[float, float], color: Color, size: int = 6) -> None:
    x, y = round(at[0]), round(at[1])
    pygame.draw.line(surface, color, (x - size, y - size), (x + size, y + size), 2)
    pygame.draw.line(surface, color, (x - size, y + size), (x + size, y - size), 2)


def yes_no(answer: bool, yes: str = "hit", no: str = "apart") -> str:
    return yes if answer else no
