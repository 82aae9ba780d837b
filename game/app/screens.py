"""Full-screen states: the title menu, the level select, pause, game over, the win and credits.

Where it sits: the app draws one of these instead of (title, level select) or on top of
(pause, game over, win) the world and the HUD, on the same 320x180 logical screen. They read
the assets, the campaign and the menu entries and change nothing: what a press does is
decided in :mod:`game.app.menus`; these only show it.

What it teaches:
  * **Dimming what is underneath** with one multiplying fill (``BLEND_RGB_MULT``): the game
    stays visible, paused, behind the menu, and no extra surface is needed.
  * **Layout from the screen's size.** Everything is placed relative to the target's centre
    and edges and the fonts' own sizes, so nothing here assumes 320x180.
  * **A menu is data.** :data:`game.app.menus.TITLE_ITEMS` and :data:`game.app.menus.PAUSE_ITEMS`
    are the lists the menu logic and this drawing code both index with ``selected``, and
    one function (:func:`draw_menu`) draws every list of choices the same way.
  * **One heading style** (:func:`draw_heading`): the title, pause, level-clear, game-over
    and win screens all name themselves in the big font, gold, outlined, over a short gold
    rule, with :data:`HEADING_ROOM_PX` of room before what follows.
  * **Draw an icon rather than hope for a glyph.** The game's pixel font has no padlock,
    so :func:`draw_lock` draws one from a rectangle and an arc.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import pygame

from game.app.assets import Assets
from game.app.goals import of_total
from game.app.hud import (
    DIM_TEXT,
    GOLD,
    OUTLINE_COLOR,
    SMALL_TEXT_ANTIALIAS,
    TEXT_COLOR,
    Color,
    draw_text,
    fit_text,
    translucent_rect,
)
from game.app.menus import (
    GAME_OVER_ITEMS,
    OPTIONS,
    PAUSE_ITEMS,
    TIMER,
    TITLE_ITEMS,
    LevelEntry,
    next_to_play,
)
from game.app.settings import DEFAULT_KEYS
from game.sim.campaign import Campaign, totals
from game.sim.sprite import ANIMATION_HZ, animation_index
from game.sim.tuning import TICK_S

GAME_TITLE = "Tile Hopper"
LEVEL_SELECT_TITLE = "Level select"
OPTIONS_HINT = "Volumes, keys, the ghost and the assists"

DIM_MULTIPLIER = (96, 96, 120)  # the frame behind a menu is multiplied by this / 255
PANEL_COLOR: Color = (12, 10, 28, 215)
PANEL_BORDER: Color = (255, 214, 90)
HIGHLIGHT_COLOR: Color = (255, 214, 90, 70)
HIGHLIGHT_TEXT: Color = (255, 240, 170)
LOCKED_TEXT: Color = (118, 120, 146)  # a level not yet unlocked, and its padlock
ERROR_COLOR: Color = (255, 150, 150)
ERROR_PANEL: Color = (40, 0, 0, 220)
ERROR_MAX_LINES = 5
RELOAD_FAILED = "Not reloaded: "  # before the loader's sentence when a --watch reload fails

LINE_GAP_PX = 2  # extra space between lines of text
HEADING_COLOR: Color = (255, 214, 90)  # every screen's heading: the HUD's gold
HEADING_RULE_GAP_PX = 2  # between a heading's letters and the rule under it
HEADING_RULE_INSET_PX = 4  # the rule is this much narrower than the heading at each end
HEADING_ROOM_PX = 6  # between the rule and whatever comes next
PANEL_PAD_PX = 6  # space between a panel's border and its contents
PANEL_GAP_PX = 8  # between two panels side by side
MENU_ROW_PAD_PX = 1  # highlight bar reaches this far above and below its text
MENU_MARKER = ">"
MENU_MARKER_GAP_PX = 6
COLUMN_GAP_PX = 12  # between a label and its value
NOT_YET = "\N{EM DASH}"  # a best time or coin count not set yet

TITLE_Y_PX = 28  # centre of the game title on the title screen
TITLE_BOB_PX = 2  # the title floats up and down by this much
TITLE_BOB_HZ = 0.5
TITLE_SKY_SCROLL_PX_S = 12  # how fast the sky drifts behind the title
RUNNER_SPEED_PX_S = 40  # the hero running across the title screen
RUNNER_FPS = 12
RUNNER_FRAMES = (2, 3, 4, 5)
CHASER_FPS = 4
CHASER_FRAMES = (0, 1)
CHASER_GAP_PX = 40  # the slime follows the hero at this distance
GROUND_FROM_BOTTOM_PX = 14  # the runners' feet sit this far above the bottom edge
COIN_ROW_GAP_PX = 12  # between coin centres in the row under the title
COIN_ROW_COUNT = 5
COIN_ROW_MARGIN_PX = 8  # above and below the row of coins
COIN_FPS = 8

LEVEL_SELECT_HEADING_Y_PX = 14  # centre of the letters of "Level select"
LEVEL_NUMBER_W_PX = 16  # the "1." column of the level select
BEST_TIME_W_PX = 44  # the best-time column, right-aligned
BEST_COINS_W_PX = 40  # the coins column ("12 of 15"), right-aligned
MEDAL_W_PX = 9  # the medal column, after the best time
MEDAL_RADIUS_PX = 3  # the medal drawn beside a best time within the level's target
MEDAL_COLOR: Color = (255, 214, 90)
LOCK_BODY_PX = (7, 5)  # the padlock's body, width and height
LOCK_SHACKLE_H_PX = 3  # how far its shackle rises above the body

CREDITS_SCROLL_PX_S = 16  # how fast the credits roll up the screen
CREDITS_BOTTOM_GAP_PX = 34  # they rise from this far above the bottom, over the runners
CREDITS_STOP_ROW_PX = 96  # the last line stops rising when it reaches this row
CREDITS_ROLE_GAP_PX = 6  # between one credit and the next
CREDITS = (  # (what, who or how): the roll after the win, top to bottom
    ("Tile Hopper", "a platformer about collisions"),
    ("Code", "Python, with pygame and pytmx"),
    ("Levels", "drawn in Tiled, checked by the game's own solver"),
    ("Art", "drawn pixel by pixel by game/tools/art.py"),
    ("Font", "drawn by game/tools/pixel_font.py"),
    ("Music and sounds", "synthesised by game/tools/synth.py"),
    ("Licence", "every picture and sound is CC0"),
)
CREDITS_LAST = "Thank you for playing!"

CONTROLS = (  # action, keyboard, pad (an Xbox-style pad with the default buttons)
    ("Move", "Arrows / WASD", "Stick / D-pad"),
    ("Jump", "Space / Z / Up", "A"),
    ("Pause", "P / Esc", "Start"),
    ("Back", "Esc", "B"),
    ("Debug overlay", "F1", "F1"),
    ("Fullscreen", "F11", "F11"),
)
CONTROLS_HEADINGS = ("", "Keyboard", "Gamepad")
KEY_NAMES_SHOWN = 2  # a bound action's keys the title lists; the options screen shows all


def controls_rows(keys: Mapping[str, Sequence[str]] | None = None
                  ) -> tuple[tuple[str, str, str], ...]:
    """The title's controls table, with the keyboard column the player's own bindings
    (``keys``: action name -> pygame key names, as the options screen saves them); None or
    the default bindings give the table as written in :data:`CONTROLS`.

    >>> controls_rows({"left": ["j"], "right": ["l"], "jump": ["k", "x", "c"]})[:2]
    (('Move', 'J / L', 'Stick / D-pad'), ('Jump', 'K / X', 'A'))
    """
    if keys is None or all(list(keys.get(action, ())) == list(names)
                           for action, names in DEFAULT_KEYS.items()):
        return CONTROLS

    def shown(action: str) -> str:
        names = list(keys.get(action, ()))[:KEY_NAMES_SHOWN]
        return " / ".join(name.title() for name in names) or "-"

    move = (CONTROLS[0][0], f"{shown('left')} / {shown('right')}", CONTROLS[0][2])
    jump = (CONTROLS[1][0], shown("jump"), CONTROLS[1][2])
    return (move, jump, *CONTROLS[2:])


def heading_h(assets: Assets) -> int:
    """The height :func:`draw_heading` takes, room below included."""
    return assets.big_font.get_height() + HEADING_RULE_GAP_PX + 1 + HEADING_ROOM_PX


def draw_heading(target: pygame.Surface, assets: Assets, text: str,
                 midtop: tuple[int, int]) -> pygame.Rect:
    """A screen's heading, the same on every screen: ``text`` in the big font, gold and
    outlined, with a short gold rule under it. Returns the area it takes, room below
    included (:func:`heading_h` tall)."""
    letters = draw_text(target, assets.big_font, text, midtop, HEADING_COLOR, anchor="midtop")
    rule_y = letters.top + assets.big_font.get_height() + HEADING_RULE_GAP_PX
    pygame.draw.line(target, HEADING_COLOR, (letters.left + HEADING_RULE_INSET_PX, rule_y),
                     (letters.right - 1 - HEADING_RULE_INSET_PX, rule_y))
    return pygame.Rect(letters.left, letters.top, letters.w, heading_h(assets))


def dim(target: pygame.Surface) -> None:
    """Darken everything already drawn, with a slight blue tint."""
    target.fill(DIM_MULTIPLIER, special_flags=pygame.BLEND_RGB_MULT)


def draw_panel(target: pygame.Surface, rect: pygame.Rect) -> None:
    translucent_rect(target, rect, PANEL_COLOR)
    pygame.draw.rect(target, PANEL_BORDER, rect, width=1)


def _menu_row_h(font: pygame.font.Font) -> int:
    return font.get_linesize() + LINE_GAP_PX


def _marker_w(font: pygame.font.Font) -> int:
    return font.size(MENU_MARKER)[0] + MENU_MARKER_GAP_PX


def menu_size(font: pygame.font.Font, items: Sequence[str]) -> tuple[int, int]:
    """The width and height :func:`draw_menu` needs for ``items``, inside a panel's padding."""
    items_w = max(font.size(item)[0] for item in items)
    return items_w + 2 * _marker_w(font), len(items) * _menu_row_h(font) - LINE_GAP_PX


def _highlight(target: pygame.Surface, font: pygame.font.Font, left: int, top: int,
               width: int) -> None:
    """The lit row: a translucent bar and the marker at its left end."""
    row = pygame.Rect(left, top - MENU_ROW_PAD_PX, width, font.get_height() + 2 * MENU_ROW_PAD_PX)
    translucent_rect(target, row, HIGHLIGHT_COLOR)
    draw_text(target, font, MENU_MARKER, (left + MENU_MARKER_GAP_PX // 2, top), GOLD)


def draw_menu(target: pygame.Surface, font: pygame.font.Font, items: Sequence[str],
              selected: int, topleft: tuple[int, int], width: int) -> None:
    """One choice per row, ``items[selected]`` lit; every menu in the game looks like this."""
    left, y = topleft
    for number, item in enumerate(items):
        lit = number == selected
        if lit:
            _highlight(target, font, left, y, width)
        draw_text(target, font, item, (left + _marker_w(font), y),
                  HIGHLIGHT_TEXT if lit else DIM_TEXT)
        y += _menu_row_h(font)


def _draw_sky(target: pygame.Surface, assets: Assets, frame: int) -> None:
    """The still sky and its sun, and the clouds and hills drifting slowly left, repeating."""
    target.blit(assets.sky, (0, 0))
    scenery = assets.background
    seconds = frame / ANIMATION_HZ
    x = -(math.floor(seconds * TITLE_SKY_SCROLL_PX_S) % scenery.get_width())
    while x < target.get_width():
        target.blit(scenery, (x, 0))
        x += scenery.get_width()


def draw_title(target: pygame.Surface, assets: Assets, frame: int, selected: int,
               levels: Sequence[LevelEntry], *, pad: bool = False,
               keys: Mapping[str, Sequence[str]] | None = None) -> None:
    """The title screen: drifting sky, the game's name, the menu, how to play, a running hero.

    ``frame`` counts at :data:`game.sim.sprite.ANIMATION_HZ` per second and drives the motion;
    ``TITLE_ITEMS[selected]`` is lit, and a line under the panels says what it leads to. The
    controls shown are the gamepad's if ``pad`` (the last thing pressed was on a pad), else
    the keyboard's, as the player has bound them (``keys``, see :func:`controls_rows`).
    """
    _draw_sky(target, assets, frame)
    seconds = frame / ANIMATION_HZ
    bob = round(TITLE_BOB_PX * math.sin(2 * math.pi * TITLE_BOB_HZ * seconds))
    centre_x = target.get_width() // 2
    heading = draw_heading(target, assets, GAME_TITLE,
                           (centre_x, TITLE_Y_PX - assets.big_font.get_height() // 2 + bob))
    subtitle_top = heading.bottom - bob - HEADING_ROOM_PX + 2 * LINE_GAP_PX
    subtitle = draw_text(target, assets.small_font, "a platformer about collisions",
                         (centre_x, subtitle_top), DIM_TEXT, anchor="midtop",
                         antialias=SMALL_TEXT_ANTIALIAS)

    coin_frames = assets.coin_frames
    coin_y = subtitle.bottom + COIN_ROW_MARGIN_PX
    row_w = (COIN_ROW_COUNT - 1) * COIN_ROW_GAP_PX
    for number in range(COIN_ROW_COUNT):
        coin = coin_frames[animation_index(frame, COIN_FPS, range(len(coin_frames)), number)]
        coin_x = centre_x - row_w // 2 + number * COIN_ROW_GAP_PX
        target.blit(coin, coin.get_rect(center=(coin_x, coin_y)))

    # The menu and the controls side by side, centred as a pair.
    top = coin_y + COIN_ROW_MARGIN_PX
    menu_w, menu_h = menu_size(assets.font, TITLE_ITEMS)
    menu = pygame.Rect(0, top, menu_w + 2 * PANEL_PAD_PX, menu_h + 2 * PANEL_PAD_PX)
    column = 2 if pad else 1
    rows = controls_rows(keys)
    controls = _controls_panel(assets, top, rows)
    menu.left = (target.get_width() - menu.w - PANEL_GAP_PX - controls.w) // 2
    controls.left = menu.right + PANEL_GAP_PX
    draw_panel(target, menu)
    draw_menu(target, assets.font, TITLE_ITEMS, selected,
              (menu.left + PANEL_PAD_PX, menu.top + PANEL_PAD_PX), menu.w - 2 * PANEL_PAD_PX)
    hint = _title_hint(TITLE_ITEMS[selected], levels)
    if hint:  # under both panels, where a level's whole title fits
        font, pair = assets.small_font, menu.union(controls)
        draw_text(target, font, fit_text(font, hint, pair.w),
                  (pair.centerx, pair.bottom + LINE_GAP_PX), DIM_TEXT, anchor="midtop",
                  antialias=SMALL_TEXT_ANTIALIAS)
    _draw_controls(target, assets, controls, column, rows)
    _draw_runners(target, assets, frame)


def _title_hint(item: str, levels: Sequence[LevelEntry]) -> str:
    """What a title menu item leads to: the level Play starts, how many are unlocked."""
    if item == OPTIONS:
        return OPTIONS_HINT
    if not levels or item == TITLE_ITEMS[-1]:
        return ""
    if item == TITLE_ITEMS[0]:
        number = next_to_play(levels)
        return f"Level {number + 1}: {levels[number].title}"
    unlocked = sum(entry.unlocked for entry in levels)
    return f"{unlocked} of {len(levels)} levels unlocked"


def _controls_panel(assets: Assets, top: int,
                    controls: Sequence[tuple[str, str, str]]) -> pygame.Rect:
    """Where the controls table goes: wide enough for either device's column, so the title
    does not shift when the player picks up a pad."""
    font = assets.small_font
    rows = (CONTROLS_HEADINGS, *controls)
    labels_w = max(font.size(row[0])[0] for row in rows)
    columns_w = labels_w + max(font.size(text)[0] for row in rows for text in row[1:])
    return pygame.Rect(0, top, columns_w + COLUMN_GAP_PX + 2 * PANEL_PAD_PX,
                       len(rows) * font.get_linesize() + 2 * PANEL_PAD_PX - LINE_GAP_PX)


def _draw_controls(target: pygame.Surface, assets: Assets, panel: pygame.Rect,
                   column: int, controls: Sequence[tuple[str, str, str]]) -> None:
    """The controls as a table: what, and which keys (column 1) or pad buttons (column 2)."""
    font = assets.small_font
    translucent_rect(target, panel, PANEL_COLOR)
    y = panel.top + PANEL_PAD_PX
    for number, row in enumerate((CONTROLS_HEADINGS, *controls)):
        draw_text(target, font, row[0], (panel.left + PANEL_PAD_PX, y), DIM_TEXT,
                  outline=None, antialias=SMALL_TEXT_ANTIALIAS)
        draw_text(target, font, row[column], (panel.right - PANEL_PAD_PX, y),
                  GOLD if number == 0 else TEXT_COLOR, anchor="topright", outline=None,
                  antialias=SMALL_TEXT_ANTIALIAS)
        y += font.get_linesize()


def _draw_runners(target: pygame.Surface, assets: Assets, frame: int) -> None:
    """The hero runs along the bottom of the title screen, a slime in pursuit."""
    width, height = target.get_size()
    hero = assets.player_frames[animation_index(frame, RUNNER_FPS, RUNNER_FRAMES)]
    slime = assets.enemy_frames[animation_index(frame, CHASER_FPS, CHASER_FRAMES)]
    lap_px = width + hero.get_width() + CHASER_GAP_PX + slime.get_width()
    travelled = math.floor(frame * RUNNER_SPEED_PX_S / ANIMATION_HZ) % lap_px
    feet = height - GROUND_FROM_BOTTOM_PX
    hero_x = travelled - hero.get_width()
    target.blit(hero, (hero_x, feet - hero.get_height()))
    target.blit(slime, (hero_x - CHASER_GAP_PX - slime.get_width(), feet - slime.get_height()))


def draw_lock(target: pygame.Surface, center: tuple[int, int], color: Color) -> pygame.Rect:
    """A small padlock centred on ``center``, pixel by pixel: a shackle over a solid body
    with a keyhole. (``pygame.draw.arc`` is too ragged at this size.)"""
    body_w, body_h = LOCK_BODY_PX
    lock = pygame.Rect(0, 0, body_w, LOCK_SHACKLE_H_PX + body_h)
    lock.center = center
    left, top = lock.topleft
    pygame.draw.line(target, color, (left + 2, top), (left + body_w - 3, top))  # its crown
    for x in (left + 1, left + body_w - 2):  # its sides
        pygame.draw.line(target, color, (x, top + 1), (x, top + LOCK_SHACKLE_H_PX - 1))
    body = pygame.Rect(left, top + LOCK_SHACKLE_H_PX, body_w, body_h)
    pygame.draw.rect(target, color, body)
    target.set_at((body.centerx, body.centery), OUTLINE_COLOR)  # the keyhole
    return lock


def format_seconds(seconds: float | None) -> str:
    """A best time as the level select shows it.

    >>> format_seconds(12.3456), format_seconds(None) == NOT_YET
    ('12.35 s', True)
    """
    return NOT_YET if seconds is None else f"{seconds:.2f} s"


def level_row_values(entry: LevelEntry) -> tuple[str, str]:
    """A level select row's best time and coins, as shown: the coins of the level's total.

    >>> from pathlib import Path
    >>> level_row_values(LevelEntry(Path("a.tmx"), "A", True, 12.5, 3, coins_total=5))
    ('12.50 s', '3 of 5')
    >>> level_row_values(LevelEntry(Path("b.tmx"), "B", True, coins_total=4))[1] == (
    ...     f"{NOT_YET} of 4")
    True
    """
    return format_seconds(entry.best_s), of_total(entry.best_coins, entry.coins_total)


def draw_medal(target: pygame.Surface, center: tuple[int, int]) -> None:
    """The medal a best time within the level's target earns: a gold disc, outlined."""
    pygame.draw.circle(target, OUTLINE_COLOR, center, MEDAL_RADIUS_PX + 1)
    pygame.draw.circle(target, MEDAL_COLOR, center, MEDAL_RADIUS_PX)


def draw_level_select(target: pygame.Surface, assets: Assets, frame: int,
                      levels: Sequence[LevelEntry], selected: int) -> None:
    """The campaign's levels in order: unlocked ones bright, locked ones grey with a padlock,
    each with its best time and most coins; ``levels[selected]`` lit, and a line saying what
    Enter will do with it."""
    _draw_sky(target, assets, frame)
    width, height = target.get_size()
    title_area = draw_heading(target, assets, LEVEL_SELECT_TITLE,
                              (width // 2, LEVEL_SELECT_HEADING_Y_PX
                               - assets.big_font.get_height() // 2))
    font, small = assets.font, assets.small_font
    row_h = _menu_row_h(font)
    footer_h = small.get_linesize() + 2 * LINE_GAP_PX
    top = title_area.bottom
    room = height - top - footer_h - 2 * PANEL_PAD_PX - small.get_linesize()
    shown = max(1, min(len(levels), (room + LINE_GAP_PX) // row_h))
    first = min(max(0, selected - shown + 1), max(0, len(levels) - shown))  # keep it in view

    titles_w = max((font.size(entry.title)[0] for entry in levels), default=0)
    panel = pygame.Rect(0, top, _marker_w(font) + LEVEL_NUMBER_W_PX + titles_w + COLUMN_GAP_PX
                        + BEST_TIME_W_PX + MEDAL_W_PX + COLUMN_GAP_PX + BEST_COINS_W_PX
                        + 3 * PANEL_PAD_PX,
                        small.get_linesize() + shown * row_h + 2 * PANEL_PAD_PX - LINE_GAP_PX)
    panel.w = min(panel.w, width - 2 * PANEL_PAD_PX)
    panel.centerx = width // 2
    draw_panel(target, panel)
    inner_left, inner_right = panel.left + PANEL_PAD_PX, panel.right - PANEL_PAD_PX
    coins_right = inner_right - PANEL_PAD_PX
    time_right = coins_right - BEST_COINS_W_PX - COLUMN_GAP_PX - MEDAL_W_PX
    title_left = inner_left + _marker_w(font) + LEVEL_NUMBER_W_PX
    y = panel.top + PANEL_PAD_PX
    draw_text(target, small, "Level", (title_left, y), GOLD, outline=None,
              antialias=SMALL_TEXT_ANTIALIAS)
    for heading, right in (("Best time", time_right), ("Coins", coins_right)):
        draw_text(target, small, heading, (right, y), GOLD, anchor="topright", outline=None,
                  antialias=SMALL_TEXT_ANTIALIAS)
    y += small.get_linesize()
    for number in range(first, first + shown):
        entry = levels[number]
        lit = number == selected
        if lit:
            _highlight(target, font, inner_left, y, inner_right - inner_left)
        color = (HIGHLIGHT_TEXT if lit else TEXT_COLOR) if entry.unlocked else LOCKED_TEXT
        number_left = inner_left + _marker_w(font)
        if entry.unlocked:
            draw_text(target, font, f"{number + 1}.", (number_left, y), color)
        else:
            draw_lock(target, (number_left + LOCK_BODY_PX[0] // 2,
                               y + font.get_height() // 2), LOCKED_TEXT)
        title = fit_text(font, entry.title, time_right - BEST_TIME_W_PX - title_left)
        draw_text(target, font, title, (title_left, y), color)
        best_time, coins = level_row_values(entry)
        draw_text(target, font, best_time, (time_right, y), color, anchor="topright")
        if entry.medal:
            draw_medal(target, (time_right + MEDAL_W_PX // 2 + 1, y + font.get_height() // 2))
        draw_text(target, font, coins, (coins_right, y), color, anchor="topright")
        y += row_h
    _draw_level_select_footer(target, assets, levels, selected, panel.bottom + LINE_GAP_PX)


def _draw_level_select_footer(target: pygame.Surface, assets: Assets,
                              levels: Sequence[LevelEntry], selected: int, top: int) -> None:
    """What Enter does with the lit level, or why it cannot be played."""
    font = assets.small_font
    color = TEXT_COLOR
    if not levels:
        text = "No levels found"
    elif levels[selected].problem is not None:
        text, color = f"{levels[selected].path.name} cannot be loaded", ERROR_COLOR
    elif not levels[selected].unlocked:
        text = f"Locked: finish {levels[selected - 1].title} to unlock it"
    else:
        text = "Enter / A: play       Esc / B: back"
    width = target.get_width()
    draw_text(target, font, fit_text(font, text, width - 2 * PANEL_PAD_PX), (width // 2, top),
              color, anchor="midtop", antialias=SMALL_TEXT_ANTIALIAS)


def pause_labels(timer_on: bool) -> list[str]:
    """The pause menu's rows as shown: the timer's row says whether the timer is on.

    >>> pause_labels(False)
    ['Resume', 'Restart level', 'Timer: off', 'Options', 'Quit to title']
    """
    return [f"{item}: {'on' if timer_on else 'off'}" if item == TIMER else item
            for item in PAUSE_ITEMS]


def draw_pause(target: pygame.Surface, assets: Assets, selected: int, *,
               timer_on: bool = True) -> None:
    """Dim the frame and show the pause menu with ``PAUSE_ITEMS[selected]`` highlighted."""
    dim(target)
    font = assets.font
    labels = pause_labels(timer_on)
    menu_w, menu_h = menu_size(font, labels)
    head_h = heading_h(assets)
    panel = pygame.Rect(0, 0, max(menu_w, assets.big_font.size("Paused")[0]) + 4 * PANEL_PAD_PX,
                        head_h + menu_h + 2 * PANEL_PAD_PX)
    panel.center = target.get_rect().center
    draw_panel(target, panel)
    draw_heading(target, assets, "Paused", (panel.centerx, panel.top + PANEL_PAD_PX))
    draw_menu(target, font, labels, selected,
              (panel.left + PANEL_PAD_PX, panel.top + PANEL_PAD_PX + head_h),
              panel.w - 2 * PANEL_PAD_PX)


def _draw_result(target: pygame.Surface, assets: Assets, campaign: Campaign,
                 heading: str, choices: Sequence[str] = (), selected: int = 0) -> None:
    """The run's figures in a panel under ``heading``, then ``choices`` as a menu with
    ``choices[selected]`` lit, or, without choices, what to press."""
    dim(target)
    width, height = target.get_size()
    lines = (
        ("Score", str(campaign.score)),
        ("Coins", str(campaign.coins_collected)),
        ("Enemies stomped", str(campaign.enemies_stomped)),
        ("Levels completed", str(campaign.levels_completed)),
        ("Deaths", str(campaign.deaths)),
    )
    font = assets.font
    line_h = font.get_linesize() + LINE_GAP_PX
    head_h = heading_h(assets)
    text_w = max(font.size(label)[0] + font.size(value)[0] for label, value in lines)
    menu_w, menu_h = menu_size(font, choices) if choices else (0, line_h)
    panel_w = max(text_w + COLUMN_GAP_PX, menu_w,
                  assets.big_font.size(heading)[0]) + 4 * PANEL_PAD_PX
    panel = pygame.Rect(0, 0, panel_w,
                        head_h + len(lines) * line_h + menu_h + 3 * PANEL_PAD_PX)
    panel.center = (width // 2, height // 2)
    draw_panel(target, panel)
    draw_heading(target, assets, heading, (panel.centerx, panel.top + PANEL_PAD_PX))
    y = panel.top + PANEL_PAD_PX + head_h
    for label, value in lines:
        draw_text(target, font, label, (panel.left + 2 * PANEL_PAD_PX, y), DIM_TEXT)
        draw_text(target, font, value, (panel.right - 2 * PANEL_PAD_PX, y), TEXT_COLOR,
                  anchor="topright")
        y += line_h
    if choices:
        draw_menu(target, font, choices, selected, (panel.left + PANEL_PAD_PX, y + PANEL_PAD_PX),
                  panel.w - 2 * PANEL_PAD_PX)
        return
    draw_text(target, font, "Press Enter or A", (panel.centerx, panel.bottom - PANEL_PAD_PX),
              GOLD, anchor="midbottom")


def draw_game_over(target: pygame.Surface, assets: Assets, campaign: Campaign,
                   selected: int = 0) -> None:
    """Dim the last frame and show the final score, coins and deaths, and the choice to
    retry the level lost or go back to the title (``GAME_OVER_ITEMS[selected]`` lit)."""
    _draw_result(target, assets, campaign, "Game Over", GAME_OVER_ITEMS, selected)


WIN_HEADINGS = ("Level", "Time", "Coins", "Stomps")
ASSIST_MARK = " (assist)"  # after the title of a level played with an assist on


def win_rows(campaign: Campaign) -> list[tuple[str, str, str, str]]:
    """The win screen's table: one row per level finished, then the campaign's total."""
    rows = [(f"{r.title}{ASSIST_MARK if r.assisted else ''}", format_seconds(r.ticks * TICK_S),
             f"{r.coins}/{r.coins_total}", f"{r.stomps}/{r.enemies_total}")
            for r in campaign.results]
    ticks, coins, coins_total, stomps, _score = totals(campaign.results)
    enemies = sum(r.enemies_total for r in campaign.results)
    rows.append(("Total", format_seconds(ticks * TICK_S), f"{coins}/{coins_total}",
                 f"{stomps}/{enemies}"))
    return rows


def draw_win(target: pygame.Surface, assets: Assets, campaign: Campaign) -> None:
    """Dim the last frame and sum up the campaign: each level's time, coins and stomps, the
    totals, the score and the deaths."""
    dim(target)
    font, big = assets.font, assets.big_font
    rows = [WIN_HEADINGS, *win_rows(campaign)]
    widths = [max(font.size(row[column])[0] for row in rows) for column in range(4)]
    line_h = font.get_linesize() + LINE_GAP_PX
    footer = f"Score {campaign.score}    Deaths {campaign.deaths}"
    table_w = sum(widths) + 3 * COLUMN_GAP_PX
    box = pygame.Rect(0, 0, max(table_w, big.size("You Win!")[0]) + 4 * PANEL_PAD_PX,
                      heading_h(assets) + (len(rows) + 2) * line_h + 3 * PANEL_PAD_PX)
    box.center = target.get_rect().center
    draw_panel(target, box)
    y = draw_heading(target, assets, "You Win!", (box.centerx, box.top + PANEL_PAD_PX)).bottom
    left = box.centerx - table_w // 2
    for number, row in enumerate(rows):
        color = GOLD if number in (0, len(rows) - 1) else TEXT_COLOR
        x = left
        for column, text in enumerate(row):
            if column == 0:
                draw_text(target, font, text, (x, y), DIM_TEXT if number else GOLD)
            else:
                draw_text(target, font, text, (x + widths[column], y), color,
                          anchor="topright")
            x += widths[column] + COLUMN_GAP_PX
        y += line_h
    draw_text(target, font, footer, (box.centerx, y), TEXT_COLOR, anchor="midtop")
    draw_text(target, font, "Press Enter or A", (box.centerx, box.bottom - PANEL_PAD_PX),
              GOLD, anchor="midbottom")


def credits_lines(font: pygame.font.Font, width: int) -> list[tuple[str, Color, int]]:
    """The credits roll as lines of (text, colour, gap before it), each at most ``width``."""
    lines: list[tuple[str, Color, int]] = []
    for role, who in CREDITS:
        lines.append((role, GOLD, CREDITS_ROLE_GAP_PX if lines else 0))
        lines.extend((line, TEXT_COLOR, 0) for line in wrap_text(font, who, width))
    lines.append((CREDITS_LAST, HIGHLIGHT_TEXT, 2 * CREDITS_ROLE_GAP_PX))
    return lines


def draw_credits(target: pygame.Surface, assets: Assets, frame: int) -> None:
    """The credits after the win: over the title's drifting sky and running hero, the lines
    roll up from the bottom at :data:`CREDITS_SCROLL_PX_S` and stop when the thanks reach
    :data:`CREDITS_STOP_ROW_PX`. They are clipped to the screen below the heading (its
    letters, rule and room, :func:`heading_h` tall), so they pass under it and vanish there,
    never drawn over or above it. ``frame`` counts from when the credits came up, at
    :data:`game.sim.sprite.ANIMATION_HZ` per second."""
    _draw_sky(target, assets, frame)
    dim(target)
    width, height = target.get_size()
    font = assets.font
    line_h = font.get_linesize() + LINE_GAP_PX
    lines = credits_lines(font, width - 4 * PANEL_PAD_PX)
    roll_h = sum(line_h + gap for _, _, gap in lines) - line_h  # to the last line's top
    risen = math.floor(frame * CREDITS_SCROLL_PX_S / ANIMATION_HZ)
    bottom = height - CREDITS_BOTTOM_GAP_PX
    y = max(bottom - risen, CREDITS_STOP_ROW_PX - roll_h)
    top = HEADING_RULE_GAP_PX + heading_h(assets)  # the first row below the heading's room
    clip = target.get_clip()
    target.set_clip(pygame.Rect(0, top, width, bottom - top).clip(clip))
    for text, color, gap in lines:
        y += gap
        if top - line_h < y < bottom:
            draw_text(target, font, text, (width // 2, y), color, anchor="midtop")
        y += line_h
    if y - line_h <= CREDITS_STOP_ROW_PX:  # the roll has stopped: say how to leave
        draw_text(target, font, "Press Enter or A", (width // 2, y + line_h), GOLD,
                  anchor="midtop")
    target.set_clip(clip)
    draw_heading(target, assets, "Credits", (width // 2, HEADING_RULE_GAP_PX))
    _draw_runners(target, assets, frame)


def wrap_text(font: pygame.font.Font, text: str, max_w: int) -> list[str]:
    """Break ``text`` into lines no wider than ``max_w`` pixels, at spaces where possible."""
    lines: list[str] = []
    line = ""
    for word in text.split():
        candidate = f"{line} {word}" if line else word
        if font.size(candidate)[0] <= max_w or not line:
            line = candidate
        else:
            lines.append(line)
            line = word
    if line:
        lines.append(line)
    return lines


def draw_error_banner(target: pygame.Surface, assets: Assets, message: str) -> None:
    """A problem for the player, along the bottom of the screen, over whatever is there:
    a ``--watch`` reload that failed (:data:`RELOAD_FAILED` and the loader's sentence), a
    level that would not start, a settings or progress file that could not be used."""
    width = target.get_width() - 2 * PANEL_PAD_PX
    font = assets.small_font
    lines = wrap_text(font, message, width - 2 * PANEL_PAD_PX)
    lines = lines[:ERROR_MAX_LINES]
    line_h = font.get_linesize()
    height = len(lines) * line_h + 2 * PANEL_PAD_PX
    panel = pygame.Rect(PANEL_PAD_PX, target.get_height() - height - PANEL_PAD_PX,
                        width, height)
    translucent_rect(target, panel, ERROR_PANEL)
    for number, text in enumerate(lines):
        draw_text(target, font, fit_text(font, text, panel.w - 2 * PANEL_PAD_PX),
                  (panel.x + PANEL_PAD_PX, panel.y + PANEL_PAD_PX + number * line_h),
                  ERROR_COLOR, outline=None, antialias=SMALL_TEXT_ANTIALIAS)
