"""The options screen: every row of :mod:`game.app.options` with its value, the lit one marked.

Where it sits: drawn by the window (:mod:`game.app.window`) in place of the world, like the
title and the level select, over the same drifting sky; it reads the settings and changes
nothing. The rows come from :func:`game.app.options.option_rows`, so what is drawn and what
a press changes are one list.

What it teaches: **a section heading is just a row that cannot be lit.** The Assist rows sit
under a gold "Assist" label, drawn between two rows; the lit row's index still counts only
the rows that can be chosen.
"""

from __future__ import annotations

import pygame

from game.app.assets import Assets
from game.app.hud import DIM_TEXT, GOLD, TEXT_COLOR, draw_text, fit_text
from game.app.options import ASSIST_FIRST, option_rows
from game.app.screens import (
    COLUMN_GAP_PX,
    HIGHLIGHT_TEXT,
    PANEL_PAD_PX,
    _draw_sky,
    _highlight,
    _marker_w,
    draw_heading,
    draw_panel,
    heading_h,
)
from game.app.settings import Settings

OPTIONS_TITLE = "Options"
ASSIST_TITLE = "Assist"
OPTIONS_HEADING_TOP_PX = 4  # the heading's letters start this far below the top edge
OPTIONS_ROW_GAP_PX = 1  # between two rows: tighter than a menu's, so every row fits
OPTIONS_MIN_VALUE_W_PX = 64  # the value column is at least this wide


def draw_options(target: pygame.Surface, assets: Assets, frame: int, settings: Settings,
                 selected: int, waiting_for: str | None = None) -> list[tuple[str, str]]:
    """The options over the sky: name and value per row, ``selected`` lit, the Assist rows
    under their own label. Returns the rows drawn (name, value) for a test to read."""
    _draw_sky(target, assets, frame)
    width = target.get_width()
    head = draw_heading(target, assets, OPTIONS_TITLE, (width // 2, OPTIONS_HEADING_TOP_PX))
    font = assets.font
    rows = option_rows(settings, waiting_for)
    row_h = font.get_linesize() + OPTIONS_ROW_GAP_PX
    names_w = max(font.size(name)[0] for name, _ in rows)
    values_w = max(OPTIONS_MIN_VALUE_W_PX, *(font.size(value)[0] for _, value in rows))
    panel = pygame.Rect(0, head.top + heading_h(assets) - PANEL_PAD_PX,
                        _marker_w(font) + names_w + COLUMN_GAP_PX + values_w + 3 * PANEL_PAD_PX,
                        (len(rows) + 1) * row_h + 2 * PANEL_PAD_PX)
    panel.w = min(panel.w, width - 2 * PANEL_PAD_PX)
    panel.centerx = width // 2
    draw_panel(target, panel)
    left, right = panel.left + PANEL_PAD_PX, panel.right - PANEL_PAD_PX
    y = panel.top + PANEL_PAD_PX
    for number, (name, value) in enumerate(rows):
        if number == ASSIST_FIRST:
            draw_text(target, font, ASSIST_TITLE, (left + _marker_w(font), y), GOLD)
            y += row_h
        lit = number == selected
        if lit:
            _highlight(target, font, left, y, right - left)
        draw_text(target, font, name, (left + _marker_w(font), y),
                  HIGHLIGHT_TEXT if lit else DIM_TEXT)
        shown = fit_text(font, value, right - PANEL_PAD_PX - left - _marker_w(font) - names_w
                         - COLUMN_GAP_PX)
        draw_text(target, font, shown, (right - PANEL_PAD_PX, y),
                  HIGHLIGHT_TEXT if lit else TEXT_COLOR, anchor="topright")
        y += row_h
    return rows
