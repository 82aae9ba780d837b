"""The HUD's timer: it shows the level's time as the banner counts it, and it can be hidden."""

from __future__ import annotations

import json

import pygame
import pytest

from game.app.assets import load_assets
from game.app.banner import format_ticks
from game.app.hud import draw_hud
from game.app.menus import PAUSE_ITEMS, TIMER, Menus, Nav, Screen, ToggleTimer, press
from game.app.run import input_script
from game.app.screens import pause_labels
from game.app.settings import Settings
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign
from tests.test_places import SCRIPTS


@pytest.fixture
def screen() -> pygame.Surface:
    pygame.display.init()
    return pygame.display.set_mode((320, 180))


def test_the_hud_timer_shows_the_runs_time_in_the_level(screen: pygame.Surface) -> None:
    assets = load_assets()
    script = input_script(SCRIPTS / f"{FIRST_LEVEL.stem}.txt")
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    for ticks in (1, 60, 250, 600):
        while campaign.ticks < ticks:
            campaign.tick(script.held_at(campaign.ticks))
        shown = draw_hud(screen, campaign, assets)
        assert shown["time"] == format_ticks(ticks)  # the banner's clock and form
    assert shown["time"] == "10.00 s"
    assert "time" not in draw_hud(screen, campaign, assets, timer=False)


def test_under_the_banner_the_timer_shows_the_finished_levels_time_then_restarts(
        screen: pygame.Surface) -> None:
    assets = load_assets()
    script = input_script(SCRIPTS / f"{FIRST_LEVEL.stem}.txt")
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    finishing = campaign.world
    while not campaign.results:
        finishing = campaign.world
        campaign.tick(script.held_at(campaign.ticks))
    first_level_ticks = campaign.results[-1].ticks
    assert draw_hud(screen, campaign, assets, finishing)["time"] == format_ticks(
        first_level_ticks)
    campaign.tick(frozenset())
    assert campaign.ticks > first_level_ticks
    assert draw_hud(screen, campaign, assets)["time"] == format_ticks(
        campaign.ticks - campaign.level_started_tick)


def test_the_pause_menu_turns_the_timer_off_and_the_setting_is_kept() -> None:
    menus = Menus(screen=Screen.PAUSED, pause_item=PAUSE_ITEMS.index(TIMER))
    after, command = press(menus, Nav.CONFIRM, ())
    assert command == ToggleTimer() and after.screen is Screen.PAUSED
    assert pause_labels(True)[PAUSE_ITEMS.index(TIMER)] == "Timer: on"
    settings = Settings(hud_timer=False)
    again, problems = Settings.from_json(json.loads(json.dumps(settings.to_json())))
    assert again.hud_timer is False and problems == []
    assert Settings.from_json({"hud_timer": "no"})[0].hud_timer is True
