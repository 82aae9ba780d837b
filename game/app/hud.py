"""The heads-up display: lives, coins, the level's title, its time and the score, along the top.

Where it sits: drawn after the world (:meth:`game.app.render.WorldRenderer.draw`) each frame,
in screen space (the camera does not move it). It reads the
:class:`~game.sim.campaign.Campaign` and changes nothing. It also holds the small text helpers
the menus and the debug overlay share.

What it teaches:
  * **Screen space versus world space.** The world is drawn through the camera; the HUD is
    not, so it stays put while the level scrolls underneath.
  * **Readable text on any background.** A dark translucent strip behind the bar, and a
    one-pixel outline around free-standing text, keep light letters legible over a bright
    sky and a dark cave alike.
  * **Translucency in pygame 2.6** needs a surface with per-pixel alpha (``SRCALPHA``):
    ``pygame.draw`` writes colours, it does not blend them onto an opaque target.
  * **Draw repeated things once.** An outlined text is two renders and nine blits; the HUD
    shows the same few texts frame after frame, so each is put together once, on a
    transparent surface, and kept (:func:`outlined_text`, the last
    :data:`OUTLINED_TEXTS_KEPT`): a frame blits one picture per text.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Literal

import pygame

from game.app.assets import Assets
from game.sim.campaign import Campaign
from game.sim.tuning import TICK_S
from game.sim.world import World

Color = tuple[int, int, int] | tuple[int, int, int, int]
Anchor = Literal["topleft", "midtop", "topright", "midleft", "center", "midright",
                 "bottomleft", "midbottom", "bottomright"]

TEXT_COLOR: Color = (255, 255, 255)
OUTLINE_COLOR: Color = (20, 16, 32)
OUTLINE_PX = 1  # free-standing text is ringed by this many pixels of OUTLINE_COLOR
GOLD: Color = (255, 214, 90)
DIM_TEXT: Color = (190, 196, 220)

HUD_BAR_H_PX = 13  # height of the strip along the top of the screen
HUD_BAR_COLOR: Color = (12, 10, 28, 150)  # dark and translucent: the level shows through
HUD_MARGIN_PX = 3  # gap between the screen edge and the first/last item
HUD_GAP_PX = 8  # gap between groups (hearts, coins, title, score)
ICON_GAP_PX = 1  # gap between neighbouring hearts, and between an icon and its number
MAX_HEARTS_SHOWN = 6  # more lives than this are shown as one heart and a count
LOST_HEART_ALPHA = 70  # 0..255: a life already lost is drawn faint
SCORE_DIGITS = 5
ELLIPSIS = "..."
SMALL_TEXT_ANTIALIAS = False  # ``Assets.small_font`` is crisper unsmoothed at 320x180
OUTLINED_TEXTS_KEPT = 256  # outlined texts kept ready to blit (the HUD's and the menus')


def draw_text(target: pygame.Surface, font: pygame.font.Font, text: str,
              pos: tuple[int, int], color: Color = TEXT_COLOR, *,
              anchor: Anchor = "topleft", outline: Color | None = OUTLINE_COLOR,
              antialias: bool = True) -> pygame.Rect:
    """Draw ``text`` with its ``anchor`` point at ``pos``, outlined 1 px unless ``outline`` is
    None; return the rectangle it covers (without the outline)."""
    if outline is None:
        face = font.render(text, antialias, color)
        rect = face.get_rect()
        setattr(rect, anchor, pos)
        target.blit(face, rect)
        return rect
    ringed = outlined_text(font, text, antialias, tuple(color), tuple(outline))
    rect = ringed.get_rect().inflate(-2 * OUTLINE_PX, -2 * OUTLINE_PX)
    setattr(rect, anchor, pos)
    target.blit(ringed, rect.move(-OUTLINE_PX, -OUTLINE_PX))
    return rect


@lru_cache(maxsize=OUTLINED_TEXTS_KEPT)
def outlined_text(font: pygame.font.Font, text: str, antialias: bool, color: Color,
                  outline: Color) -> pygame.Surface:
    """``text`` in ``color`` ringed by :data:`OUTLINE_PX` of ``outline``, on a transparent
    surface that much larger each way: the outline drawn at the eight offsets, the text on
    top. Made once per font, text and colours (kept for the next frames; do not draw on it)."""
    face = font.render(text, antialias, color)
    edge = font.render(text, antialias, outline)
    ringed = pygame.Surface((face.get_width() + 2 * OUTLINE_PX,
                             face.get_height() + 2 * OUTLINE_PX), pygame.SRCALPHA)
    for dx in (0, OUTLINE_PX, 2 * OUTLINE_PX):
        for dy in (0, OUTLINE_PX, 2 * OUTLINE_PX):
            if (dx, dy) != (OUTLINE_PX, OUTLINE_PX):
                ringed.blit(edge, (dx, dy))
    ringed.blit(face, (OUTLINE_PX, OUTLINE_PX))
    return ringed


def fit_text(font: pygame.font.Font, text: str, max_w: int) -> str:
    """``text``, shortened with an ellipsis if it is wider than ``max_w`` pixels.

    The longest prefix that fits is found by halving (a few measurements, however long the
    text), not by dropping one character at a time, which costs a measurement per character
    and took seconds a frame for a 20,000-character title.
    """
    if font.size(text)[0] <= max_w:
        return text
    fits, too_long = 0, len(text)  # the prefix of length `fits` fits; `too_long` does not
    while too_long - fits > 1:
        middle = (fits + too_long) // 2
        if font.size(text[:middle] + ELLIPSIS)[0] <= max_w:
            fits = middle
        else:
            too_long = middle
    text = text[:fits]
    return text.rstrip() + ELLIPSIS if text else ""


def translucent_rect(target: pygame.Surface, rect: pygame.Rect, color: Color) -> None:
    """Fill ``rect`` with an RGBA colour blended over what is already there."""
    if rect.w <= 0 or rect.h <= 0:
        return
    target.blit(_wash(rect.size, tuple(color)), rect.topleft)


@lru_cache(maxsize=OUTLINED_TEXTS_KEPT)
def _wash(size: tuple[int, int], color: Color) -> pygame.Surface:
    """A surface of ``size`` filled with the RGBA ``color``, made once (do not draw on it)."""
    layer = pygame.Surface(size, pygame.SRCALPHA)
    layer.fill(color)
    return layer


@lru_cache(maxsize=OUTLINED_TEXTS_KEPT)
def _faint(heart: pygame.Surface) -> pygame.Surface:
    """The heart of a life already lost, made once (do not draw on it)."""
    lost = heart.copy()
    lost.set_alpha(LOST_HEART_ALPHA)
    return lost


def _draw_hearts(target: pygame.Surface, assets: Assets, lives: int, start_lives: int,
                 left: int, mid_y: int) -> int:
    """Hearts for the lives left (and faint ones for those lost); return the right edge."""
    heart = assets.heart
    top = mid_y - heart.get_height() // 2
    if max(lives, start_lives) > MAX_HEARTS_SHOWN:
        target.blit(heart, (left, top))
        rect = draw_text(target, assets.font, f"x{lives}",
                         (left + heart.get_width() + ICON_GAP_PX, mid_y), anchor="midleft")
        return rect.right
    lost = _faint(heart)
    x = left
    for index in range(max(lives, start_lives)):
        target.blit(heart if index < lives else lost, (x, top))
        x += heart.get_width() + ICON_GAP_PX
    return x


def level_time(campaign: Campaign) -> str:
    """The time spent in the level in play, as the HUD shows it: the same clock and the same
    form as the level-end banner's Time (game time, so a pause does not count).

    >>> from game.levels import FIRST_LEVEL, load_level
    >>> campaign = Campaign(FIRST_LEVEL, loader=load_level)
    >>> for _ in range(90):
    ...     events = campaign.tick(frozenset())
    >>> level_time(campaign)
    '1.50 s'
    """
    return f"{(campaign.ticks - campaign.level_started_tick) * TICK_S:.2f} s"


def draw_hud(target: pygame.Surface, campaign: Campaign, assets: Assets,
             world: World | None = None, *, timer: bool = True) -> dict[str, str]:
    """Draw the top bar: hearts for lives, the coins taken in the level of all it holds, the
    level's title, the level's time (unless ``timer`` is off) and the score (coin values and
    stomps: not a second coin count). The level is the campaign's, or ``world`` (one just
    finished, under its banner). Returns the texts it drew, by name (``coins``, ``title``,
    ``time``, ``score``), so a test can read the HUD without reading pixels."""
    world = world or campaign.world
    level = world.level
    width = target.get_width()
    bar = pygame.Rect(0, 0, width, HUD_BAR_H_PX)
    translucent_rect(target, bar, HUD_BAR_COLOR)
    mid_y = bar.centery

    right = _draw_hearts(target, assets, max(0, campaign.lives), campaign.tuning.start_lives,
                         HUD_MARGIN_PX, mid_y)

    coin = assets.coin_frames[0]
    coin_x = right + HUD_GAP_PX
    target.blit(coin, (coin_x, mid_y - coin.get_height() // 2))
    coins = draw_text(target, assets.font,
                      f"{len(level.coins) - len(world.coins)}/{len(level.coins)}",
                      (coin_x + coin.get_width() + ICON_GAP_PX, mid_y), GOLD, anchor="midleft")

    shown = {"coins": f"{len(level.coins) - len(world.coins)}/{len(level.coins)}"}
    shown["score"] = f"SCORE {campaign.score:0{SCORE_DIGITS}d}"
    score = draw_text(target, assets.font, shown["score"],
                      (width - HUD_MARGIN_PX, mid_y), anchor="midright")
    right_edge = score.left
    if timer:  # under the banner, the finished level's own time, as the banner tallies it
        finished = world is not campaign.world and campaign.results
        shown["time"] = (f"{campaign.results[-1].ticks * TICK_S:.2f} s" if finished
                         else level_time(campaign))
        clock = draw_text(target, assets.font, shown["time"], (score.left - HUD_GAP_PX, mid_y),
                          anchor="midright")
        right_edge = clock.left

    room = right_edge - coins.right - 2 * HUD_GAP_PX
    title = fit_text(assets.font, level.title, room)
    if title:
        half = assets.font.size(title)[0] // 2 + HUD_GAP_PX
        centre_x = width // 2  # centred on the screen if it fits there, else in the gap
        if not coins.right + half <= centre_x <= right_edge - half:
            centre_x = (coins.right + right_edge) // 2
        draw_text(target, assets.font, title, (centre_x, mid_y), DIM_TEXT, anchor="center")
        shown["title"] = title
    return shown
