"""Full-screen states: the title screen, the pause menu, game over and the win screen.

Where it sits: the app draws one of these instead of (title) or on top of (pause, game over,
win) the world and the HUD, on the same 320x180 logical screen. They read the assets and the
campaign and change nothing: choosing a menu item is the app's job, these only show it.

What it teaches:
  * **Dimming what is underneath** with one multiplying fill (``BLEND_RGB_MULT``): the game
    stays visible, paused, behind the menu, and no extra surface is needed.
  * **Layout from the screen's size.** Everything is placed relative to the target's centre
    and edges, so nothing here assumes 320x180 except the font sizes.
  * **A menu is data.** :data:`PAUSE_ITEMS` is the one list the app's input handling and
    this drawing code both index with ``selected``.
"""

from __future__ import annotations

import math

import pygame

from game.assets import Assets
from game.campaign import Campaign
from game.hud import (
    DIM_TEXT,
    GOLD,
    SMALL_TEXT_ANTIALIAS,
    TEXT_COLOR,
    Color,
    draw_text,
    fit_text,
    translucent_rect,
)
from game.render import ANIMATION_HZ, animation_index

GAME_TITLE = "Tile Hopper"
PAUSE_ITEMS = ("Resume", "Restart level", "Quit to title")

DIM_MULTIPLIER = (96, 96, 120)  # the frame behind a menu is multiplied by this / 255
PANEL_COLOR: Color = (12, 10, 28, 215)
PANEL_BORDER: Color = (255, 214, 90)
HIGHLIGHT_COLOR: Color = (255, 214, 90, 70)
HIGHLIGHT_TEXT: Color = (255, 240, 170)
GAME_OVER_COLOR: Color = (255, 96, 96)
WIN_COLOR: Color = (140, 255, 140)

LINE_GAP_PX = 2  # extra space between lines of text
PANEL_PAD_PX = 6  # space between a panel's border and its contents
MENU_ROW_PAD_PX = 1  # highlight bar reaches this far above and below its text
MENU_MARKER = ">"
MENU_MARKER_GAP_PX = 6
COLUMN_GAP_PX = 12  # between a label and its value

TITLE_Y_PX = 28  # centre of the game title on the title screen
TITLE_BOB_PX = 2  # the title floats up and down by this much
TITLE_BOB_HZ = 0.5
TITLE_SKY_SCROLL_PX_S = 12  # how fast the sky drifts behind the title
PROMPT_BLINK_HZ = 1.5  # "Press Enter" is shown for half of each blink
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

CONTROLS = (
    ("Move", "Arrows / WASD"),
    ("Jump", "Space / Z / Up"),
    ("Pause", "P / Esc"),
    ("Debug overlay", "F1"),
    ("Fullscreen", "F11"),
)


def dim(target: pygame.Surface) -> None:
    """Darken everything already drawn, with a slight blue tint."""
    target.fill(DIM_MULTIPLIER, special_flags=pygame.BLEND_RGB_MULT)


def _panel(target: pygame.Surface, rect: pygame.Rect) -> None:
    translucent_rect(target, rect, PANEL_COLOR)
    pygame.draw.rect(target, PANEL_BORDER, rect, width=1)


def _blinking_on(frame: int) -> bool:
    return math.floor(frame * PROMPT_BLINK_HZ * 2 / ANIMATION_HZ) % 2 == 0


def draw_title(target: pygame.Surface, assets: Assets, frame: int) -> None:
    """The title screen: drifting sky, the game's name, a running hero, how to play.

    ``frame`` counts at :data:`game.render.ANIMATION_HZ` per second and drives the motion.
    """
    width = target.get_width()
    seconds = frame / ANIMATION_HZ
    sky = assets.background
    x = -(math.floor(seconds * TITLE_SKY_SCROLL_PX_S) % sky.get_width())
    while x < width:
        target.blit(sky, (x, 0))
        x += sky.get_width()

    bob = round(TITLE_BOB_PX * math.sin(2 * math.pi * TITLE_BOB_HZ * seconds))
    centre_x = width // 2
    draw_text(target, assets.big_font, GAME_TITLE, (centre_x, TITLE_Y_PX + bob), GOLD,
              anchor="center")
    subtitle_top = TITLE_Y_PX + assets.big_font.get_height() // 2 + LINE_GAP_PX
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

    prompt_top = coin_y + COIN_ROW_MARGIN_PX
    if _blinking_on(frame):
        draw_text(target, assets.font, "Press Enter to start", (centre_x, prompt_top),
                  anchor="midtop")
    _draw_controls(target, assets, prompt_top + assets.font.get_linesize() + LINE_GAP_PX)
    _draw_runners(target, assets, frame)


def _draw_controls(target: pygame.Surface, assets: Assets, top: int) -> None:
    font = assets.small_font
    line_h = font.get_linesize()
    label_w = max(font.size(label)[0] for label, _ in CONTROLS)
    keys_w = max(font.size(keys)[0] for _, keys in CONTROLS)
    panel = pygame.Rect(0, top, label_w + keys_w + COLUMN_GAP_PX + 2 * PANEL_PAD_PX,
                        len(CONTROLS) * line_h + 2 * PANEL_PAD_PX - LINE_GAP_PX)
    panel.centerx = target.get_width() // 2
    translucent_rect(target, panel, PANEL_COLOR)
    y = panel.top + PANEL_PAD_PX
    for label, keys in CONTROLS:
        draw_text(target, font, label, (panel.left + PANEL_PAD_PX, y), DIM_TEXT, outline=None,
                  antialias=SMALL_TEXT_ANTIALIAS)
        draw_text(target, font, keys, (panel.right - PANEL_PAD_PX, y), anchor="topright",
                  outline=None, antialias=SMALL_TEXT_ANTIALIAS)
        y += line_h


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


def draw_pause(target: pygame.Surface, assets: Assets, selected: int) -> None:
    """Dim the frame and show the pause menu with ``PAUSE_ITEMS[selected]`` highlighted."""
    dim(target)
    font = assets.font
    line_h = font.get_linesize() + LINE_GAP_PX
    items_w = max(font.size(item)[0] for item in PAUSE_ITEMS)
    marker_w = font.size(MENU_MARKER)[0] + MENU_MARKER_GAP_PX
    heading_h = assets.big_font.get_linesize()
    panel = pygame.Rect(0, 0, items_w + 2 * (marker_w + PANEL_PAD_PX),
                        heading_h + len(PAUSE_ITEMS) * line_h + 2 * PANEL_PAD_PX)
    panel.center = target.get_rect().center
    _panel(target, panel)
    draw_text(target, assets.big_font, "Paused", (panel.centerx, panel.top + PANEL_PAD_PX),
              anchor="midtop")
    y = panel.top + PANEL_PAD_PX + heading_h
    text_left = panel.left + PANEL_PAD_PX + marker_w
    for number, item in enumerate(PAUSE_ITEMS):
        if number == selected:
            row = pygame.Rect(panel.left + PANEL_PAD_PX, y - MENU_ROW_PAD_PX,
                              panel.w - 2 * PANEL_PAD_PX,
                              font.get_height() + 2 * MENU_ROW_PAD_PX)
            translucent_rect(target, row, HIGHLIGHT_COLOR)
            draw_text(target, font, MENU_MARKER, (row.left + MENU_MARKER_GAP_PX // 2, y), GOLD)
            draw_text(target, font, item, (text_left, y), HIGHLIGHT_TEXT)
        else:
            draw_text(target, font, item, (text_left, y), DIM_TEXT)
        y += line_h


def _draw_result(target: pygame.Surface, assets: Assets, campaign: Campaign, heading: str,
                 color: Color) -> None:
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
    line_h = font.get_linesize()
    heading_h = assets.big_font.get_linesize()
    text_w = max(font.size(label)[0] + font.size(value)[0] for label, value in lines)
    panel_w = max(text_w + COLUMN_GAP_PX, assets.big_font.size(heading)[0]) + 4 * PANEL_PAD_PX
    panel = pygame.Rect(0, 0, panel_w,
                        heading_h + len(lines) * line_h + line_h + 3 * PANEL_PAD_PX)
    panel.center = (width // 2, height // 2)
    _panel(target, panel)
    draw_text(target, assets.big_font, heading, (panel.centerx, panel.top + PANEL_PAD_PX),
              color, anchor="midtop")
    y = panel.top + PANEL_PAD_PX + heading_h
    for label, value in lines:
        draw_text(target, font, label, (panel.left + 2 * PANEL_PAD_PX, y), DIM_TEXT)
        draw_text(target, font, value, (panel.right - 2 * PANEL_PAD_PX, y), TEXT_COLOR,
                  anchor="topright")
        y += line_h
    draw_text(target, font, "Press Enter", (panel.centerx, panel.bottom - PANEL_PAD_PX),
              GOLD, anchor="midbottom")


def draw_game_over(target: pygame.Surface, assets: Assets, campaign: Campaign) -> None:
    """Dim the last frame and show the final score, coins and deaths."""
    _draw_result(target, assets, campaign, "Game Over", GAME_OVER_COLOR)


def draw_win(target: pygame.Surface, assets: Assets, campaign: Campaign) -> None:
    """Dim the last frame and celebrate: the final score, coins and deaths."""
    _draw_result(target, assets, campaign, "You Win!", WIN_COLOR)


ERROR_COLOR: Color = (255, 150, 150)
ERROR_PANEL: Color = (40, 0, 0, 220)
ERROR_MAX_LINES = 5


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
    """A reload that failed (``--watch``): the loader's sentence, over the still-running level."""
    width = target.get_width() - 2 * PANEL_PAD_PX
    font = assets.small_font
    lines = wrap_text(font, "Not reloaded: " + message, width - 2 * PANEL_PAD_PX)
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
