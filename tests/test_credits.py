"""The credits roll under their heading: whatever the time, the rolling lines leave every
pixel of the heading (its letters, its rule and the room under it) as the heading alone
draws it, and never show above it."""

from __future__ import annotations

from dataclasses import replace

import pygame
import pytest

from game.app import screens
from game.app.assets import Assets
from game.app.screens import HEADING_RULE_GAP_PX, draw_credits, heading_h

FRAMES = (0, 120, 240, 360, 480, 600, 900, 3000)  # rising, the heading passed, stopped
TALL_HEADING_PT = 48  # a heading font taller than the game's own


def heading_band(assets: Assets) -> pygame.Rect:
    """Everything from the top of the screen to the bottom of the heading's room."""
    return pygame.Rect(0, 0, 320, HEADING_RULE_GAP_PX + heading_h(assets))


def credits_at(assets: Assets, frame: int) -> pygame.Surface:
    surface = pygame.Surface((320, 180))
    draw_credits(surface, assets, frame)
    return surface


def rows(surface: pygame.Surface, band: pygame.Rect) -> bytes:
    return pygame.image.tobytes(surface.subsurface(band), "RGB")


def check_heading_untouched(assets: Assets, monkeypatch: pytest.MonkeyPatch) -> None:
    band = heading_band(assets)
    rolled = {frame: credits_at(assets, frame) for frame in FRAMES}
    with monkeypatch.context() as patch:
        patch.setattr(screens, "credits_lines", lambda font, width: [])
        bare = {frame: credits_at(assets, frame) for frame in FRAMES}
    below = pygame.Rect(0, band.bottom, 320, 180 - band.bottom)
    shown = [frame for frame in FRAMES if rows(rolled[frame], below) != rows(bare[frame], below)]
    assert len(shown) >= len(FRAMES) - 1  # the roll is drawn (at frame 0 it may not be yet)
    for frame in FRAMES:
        assert rows(rolled[frame], band) == rows(bare[frame], band), f"frame {frame}"


@pytest.mark.usefixtures("display")
def test_the_rolling_credits_never_touch_their_heading(
        assets: Assets, monkeypatch: pytest.MonkeyPatch) -> None:
    check_heading_untouched(assets, monkeypatch)


@pytest.mark.usefixtures("display")
def test_the_credits_pass_under_a_taller_heading_too(
        assets: Assets, monkeypatch: pytest.MonkeyPatch) -> None:
    """The clip follows the heading's own height, not a row fixed for the game's font."""
    pygame.font.init()
    tall = replace(assets, big_font=pygame.font.Font(None, TALL_HEADING_PT))
    assert heading_band(tall).bottom > heading_band(assets).bottom
    check_heading_untouched(tall, monkeypatch)
