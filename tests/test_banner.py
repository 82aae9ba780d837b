"""The level-end banner: its timeline, its tally, and the win screen's sums."""

from __future__ import annotations

from pathlib import Path

import pygame
import pytest

from game.app.assets import load_assets
from game.app.banner import BANNER_S, LINE_EVERY_S, SKIP_AFTER_S, TALLY_SOUND, Banner
from game.app.screens import draw_win, win_rows
from game.levels import load_level
from game.sim.campaign import Campaign, LevelResult
from game.sim.tuning import TICK_S

RESULT = LevelResult(Path("01.tmx"), "One", 861, 4, 12, 2, 2, 14)


@pytest.fixture
def screen() -> pygame.Surface:
    pygame.display.init()
    return pygame.display.set_mode((320, 180))


def test_the_tally_appears_line_by_line_then_sounds_once_then_ends() -> None:
    banner = Banner(RESULT, best_before_ticks=900)
    sounds, shown = [], []
    for _ in range(round(BANNER_S / TICK_S) + 1):
        sounds.append(banner.advance(TICK_S))
        shown.append(banner.lines_shown())
    assert shown == sorted(shown) and shown[-1] == len(banner.lines) == 5
    assert sounds.count(TALLY_SOUND) == 1 and sounds.count(None) == len(sounds) - 1
    sounded_at = sounds.index(TALLY_SOUND)
    assert shown[sounded_at] == 5 and shown[sounded_at - 1] == 4
    assert sounded_at * TICK_S == pytest.approx(5 * LINE_EVERY_S, abs=TICK_S)
    assert banner.done()


def test_the_banner_can_be_skipped_only_after_a_moment() -> None:
    banner = Banner(RESULT, best_before_ticks=None)
    banner.advance(SKIP_AFTER_S / 2)
    assert not banner.skippable() and not banner.done()
    banner.advance(SKIP_AFTER_S)
    assert banner.skippable() and not banner.done()


def test_the_banner_says_whether_the_time_beat_the_best() -> None:
    assert Banner(RESULT, 900).lines[-1] == ("Best", "new best!")
    assert Banner(RESULT, 800).lines[-1] == ("Best", "13.33 s")
    assert Banner(RESULT, None).lines[-1] == ("Best", "first clear")
    assert Banner(RESULT, None).lines[:4] == [("Time", "14.35 s"), ("Coins", "4 of 12"),
                                              ("Stomps", "2 of 2"), ("Score", "+14")]


def test_the_banner_and_the_win_screen_draw_over_a_frame(screen: pygame.Surface) -> None:
    assets = load_assets()
    screen.fill((0, 0, 0))
    banner = Banner(RESULT, 900)
    banner.advance(BANNER_S / 2)
    banner.draw(screen, assets)
    assert screen.get_at(screen.get_rect().center) != pygame.Color(0, 0, 0)
    level = load_level(Path("levels/01-first-steps.tmx"))
    campaign = Campaign(Path("a.tmx"), loader=lambda _: level)
    campaign.results += [RESULT, RESULT]
    assert win_rows(campaign)[-1] == ("Total", "28.70 s", "8/24", "4/4")
    draw_win(screen, assets, campaign)
