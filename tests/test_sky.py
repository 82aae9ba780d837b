"""The title screen: one sun that stands still, clouds and hills that scroll without a seam,
and the name of the level Play starts."""

from __future__ import annotations

import itertools

import pygame
import pytest

from game.app import screens
from game.app.assets import load_assets
from game.app.hud import fit_text
from game.app.menus import campaign_levels, level_entries
from game.app.saves import Progress
from game.app.screens import draw_title
from game.levels import FIRST_LEVEL
from game.tools import art


@pytest.fixture
def screen() -> pygame.Surface:
    pygame.display.init()
    return pygame.display.set_mode((320, 180))


def sun_pixels(surface: pygame.Surface) -> pygame.mask.Mask:
    """The pixels of ``surface`` in the sun's colour."""
    return pygame.mask.from_threshold(surface, art.SUN, (1, 1, 1, 255))


def beyond(size: tuple[int, int], centre: tuple[int, int], radius: int) -> pygame.mask.Mask:
    """The pixels of a picture of ``size`` farther than ``radius`` from ``centre``."""
    far = pygame.mask.Mask(size, fill=True)
    (cx, cy) = centre
    for x in range(max(cx - radius, 0), min(cx + radius + 1, size[0])):
        for y in range(max(cy - radius, 0), min(cy + radius + 1, size[1])):
            if (x - cx) ** 2 + (y - cy) ** 2 <= radius ** 2:
                far.set_at((x, y), 0)
    return far


def test_the_title_shows_one_sun_that_stays_put_however_far_the_hills_drift(
        screen: pygame.Surface) -> None:
    assets = load_assets()
    assert sun_pixels(assets.background).count() == 0
    away = beyond(screen.get_size(), art.SUN_CENTRE, art.SUN_RADIUS + 1)
    for frame in range(0, 60 * 40, 37):  # 40 s of drift: more than one whole lap
        draw_title(screen, assets, frame, 0, ())
        sun = sun_pixels(screen)
        assert sun.count(), "clouds and titles may pass in front of the sun, never hide it all"
        assert sun.overlap_area(away, (0, 0)) == 0, frame  # every sun pixel within the disc


def test_the_scenery_joins_its_own_copy_without_a_step() -> None:
    scenery = art.draw_background()
    width, height = scenery.get_size()

    def skyline(x: int) -> list[int]:
        """For each alpha-opaque run, where the scenery starts in column ``x``."""
        return [y for y in range(height) if scenery.get_at((x, y)).a == 255
                and (y == 0 or scenery.get_at((x, y - 1)).a < 255)]

    for x in range(width):
        here, there = skyline(x), skyline((x + 1) % width)
        assert here and there
        assert abs(here[-1] - there[-1]) <= 3, f"the hills jump between columns {x} and {x + 1}"


def test_the_title_names_every_campaign_level_play_would_start_in_full(
        screen: pygame.Surface, monkeypatch: pytest.MonkeyPatch) -> None:
    assets = load_assets()
    infos = campaign_levels(FIRST_LEVEL)
    fitted: list[tuple[str, str]] = []

    def recording_fit(font: pygame.font.Font, text: str, max_w: int) -> str:
        fitted.append((text, fit_text(font, text, max_w)))
        return fitted[-1][1]

    monkeypatch.setattr(screens, "fit_text", recording_fit)
    for number in range(len(infos)):
        progress = Progress()
        for done, following in itertools.pairwise(infos[:number + 1]):
            # the earlier levels finished: Play starts at this one
            progress.complete_level(done.path.name, ticks=600, coins=0,
                                    next_level=following.path.name)
        levels = level_entries(infos, progress)
        draw_title(screen, assets, 0, 0, levels)
        hint = f"Level {number + 1}: {infos[number].title}"
        assert (hint, hint) in fitted, fitted[-1]
