"""The debug overlay drawn the plain way, to check the game's quicker one against.

:func:`draw_debug_plainly` paints what :func:`game.app.debug_overlay.draw_debug` paints, the
long way round: every lookup's cells, every sweep and every square, in sight or not, one
rectangle at a time. Nothing is skipped or reused between frames, so it is plainly what the
README describes; the tests compare the two pixel for pixel. The colours, the panel (its
text, its cached lines and its drawing), the player's picture drawn again and the layer the
translucent fills are blended on (``Wash``) come from the game's module.

It is the overlay as it was drawn before the game learnt to skip what is out of sight,
with the two slips it then made at the edge of the screen put right (the game's overlay no
longer makes them): a fill that started left of or above the surface was moved onto it
rather than cut, and each cell's squares were drawn with ``pygame.draw.rect``, which may
add a stray line along the edge of the surface when little of the square is on it.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import pygame

from game.app.assets import Assets
from game.app.debug_overlay import (
    CELL_COLORS,
    CELL_SQUARE_STEP_PX,
    CELL_WASH,
    COIN_COLOR,
    ENEMY_COLOR,
    EXIT_COLOR,
    HIT_COLOR,
    HIT_EDGE_COLOR,
    HIT_EDGE_PX,
    HIT_MARK_PX,
    OTHER_CELL_COLOR,
    PLATFORM_COLOR,
    PLAYER_COLOR,
    SHAPE_COLORS,
    SHAPE_FILL_ALPHA,
    SHAPE_RIM_COLOR,
    SHAPE_RIM_INSET_PX,
    SWEEP_X_COLOR,
    SWEEP_Y_COLOR,
    Checked,
    PanelMode,
    Wash,
    _draw_panel,
    draw_player_again,
    panel_rows,
    player_on_screen,
)
from game.app.hud import Color
from game.app.render import screen_offset
from game.collision.aabb import Box
from game.collision.axis_sweep import Move, Side
from game.sim.camera import Camera
from game.sim.world import World

Outline = tuple[Color, pygame.Rect]


def _screen_rect(box: Box, camera: Camera) -> pygame.Rect:
    return pygame.Rect(math.floor(box.x) - math.floor(camera.x),
                       math.floor(box.y) - math.floor(camera.y),
                       math.ceil(box.w), math.ceil(box.h))


def _tested(wash: Wash, world: World) -> tuple[list[Outline], list[Outline]]:
    grid, camera = world.grid, world.camera
    tested = Checked(grid, world.query_log)  # every cell, in sight or not
    dx, dy = screen_offset(camera)
    squares: list[Outline] = []
    order = [*CELL_COLORS, *(p for p in tested.cells if p not in CELL_COLORS)]
    inset: dict[tuple[int, int], int] = {}
    for purpose in order:
        color = CELL_COLORS.get(purpose, OTHER_CELL_COLOR)
        for col, row in tested.cells.get(purpose, ()):
            cell = pygame.Rect(col * grid.tile_w - dx, row * grid.tile_h - dy,
                               grid.tile_w, grid.tile_h)
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


def _sweep(wash: Wash, move: Move | None, color: Color, camera: Camera) -> pygame.Rect | None:
    if move is None or not move.swept.is_finite():
        return None
    wash.fill(color, _screen_rect(move.swept, camera))
    if move.hit is None:
        return None
    box, face = move.box, math.floor(move.hit.face)
    dx, dy = screen_offset(camera)
    if move.hit.side in (Side.LEFT, Side.RIGHT):
        return pygame.Rect(face - dx - HIT_MARK_PX // 2, math.floor(box.top) - dy,
                           HIT_MARK_PX, math.ceil(box.h))
    return pygame.Rect(math.floor(box.left) - dx, face - dy - HIT_MARK_PX // 2,
                       math.ceil(box.w), HIT_MARK_PX)


def _fill(target: pygame.Surface, color: Color, rect: pygame.Rect) -> None:
    """Fill the part of ``rect`` on the surface (pygame 2.6's own ``fill`` moves a rect
    that starts left of or above the surface instead of cutting it)."""
    target.fill(color, rect.clip(target.get_rect()))


def _outline(target: pygame.Surface, color: Color, rect: pygame.Rect) -> None:
    """The 1 px border of ``rect``, as four thin fills (``pygame.draw.rect(..., width=1)``
    paints the same border, but may add a stray line along the edge of the surface when
    little of the rectangle is on it)."""
    for edge in ((rect.left, rect.top, rect.w, 1), (rect.left, rect.bottom - 1, rect.w, 1),
                 (rect.left, rect.top, 1, rect.h), (rect.right - 1, rect.top, 1, rect.h)):
        _fill(target, color, pygame.Rect(edge))


def _hitboxes(target: pygame.Surface, world: World) -> None:
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


def draw_debug_plainly(target: pygame.Surface, world: World, assets: Assets,
                       fps: float | None, update_ms: float,
                       extra_lines: Sequence[str] = (),
                       panel: PanelMode = PanelMode.COMPACT) -> None:
    """The overlay for the last tick, drawn the plain way (arguments as ``draw_debug``)."""
    wash = Wash()
    squares, outlines = _tested(wash, world)
    bars = []
    for body in world.bodies():
        moves = world.moves.get(body)
        if moves is None:
            continue
        for move, color in ((moves.x, SWEEP_X_COLOR), (moves.y, SWEEP_Y_COLOR)):
            bar = _sweep(wash, move, color, world.camera)
            if bar is not None:
                bars.append(bar)
    wash.blend_onto(target)
    for color, rect in squares:
        _outline(target, color, rect)
    for color, rect in outlines:
        rim = rect.inflate(-2 * SHAPE_RIM_INSET_PX, -2 * SHAPE_RIM_INSET_PX)
        pygame.draw.rect(target, SHAPE_RIM_COLOR, rim, width=1)
        pygame.draw.rect(target, color, rect, width=1)
    for bar in bars:
        _fill(target, HIT_EDGE_COLOR, bar.inflate(2 * HIT_EDGE_PX, 2 * HIT_EDGE_PX))
    for bar in bars:
        _fill(target, HIT_COLOR, bar)
    draw_player_again(target, world, screen_offset(world.camera))
    _hitboxes(target, world)
    _draw_panel(target, panel_rows(world, fps, update_ms, extra_lines, panel), assets.small_font,
                player_on_screen(world))
