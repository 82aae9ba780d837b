"""The options screen: each row changes its setting, which is applied at once, saved in
settings.json and read back the next time; a bad value keeps the one-sentence behaviour of a
bad settings file; keys are shown and rebound on screen; the game speed assist slows the
ticks, not the tick."""

from __future__ import annotations

import json
from pathlib import Path

import pygame
import pytest

from game.app import window as window_module
from game.app.assets import Assets
from game.app.audio import Audio
from game.app.cli import parser
from game.app.menus import (
    OPTIONS,
    PAUSE_ITEMS,
    ChangeOption,
    Menus,
    Nav,
    RebindKey,
    Screen,
    press,
)
from game.app.options import (
    BACK,
    EFFECTS,
    GAME_SPEED,
    GHOST,
    MUSIC,
    NO_DAMAGE,
    OPTION_ITEMS,
    PRESS_A_KEY,
    change,
    option_rows,
)
from game.app.options_screen import draw_options
from game.app.run import Run
from game.app.screens import CONTROLS, controls_rows, draw_title
from game.app.settings import Settings, settings_file
from game.app.window import GameWindow
from game.sim.campaign import Campaign
from game.sim.inputs import Action
from tests.maps import level_from_ascii

FLOOR = ["            ", " P          ", "############"]
FRAME_MS = 17  # every frame of the steady clock


class SteadyClock:
    def tick(self, framerate: int = 0) -> int:
        return FRAME_MS

    def get_fps(self) -> float:
        return 60.0


def key(code: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.KEYDOWN, key=code, mod=0, unicode="", scancode=0)


def _window(monkeypatch: pytest.MonkeyPatch, options: list[str],
            batches: list[list[pygame.event.Event]]) -> GameWindow:
    """A person's window on a flat level, fed one batch of events a frame, then closed."""
    level = level_from_ascii(FLOOR)
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), None,
              parser().parse_args(options))
    monkeypatch.setattr(pygame.time, "Clock", SteadyClock)
    monkeypatch.setattr(pygame.display, "toggle_fullscreen", lambda: 1)
    monkeypatch.setattr(window_module, "fit_window", lambda _: None)
    game = GameWindow(run)
    feed = [*batches, [pygame.event.Event(pygame.QUIT)]]
    monkeypatch.setattr(pygame.event, "get", lambda *_, **__: feed.pop(0))
    assert game.play() == 0
    return game


def _to_row(row: str) -> list[pygame.event.Event]:
    """From the options screen's first row down to ``row``."""
    return [key(pygame.K_DOWN)] * OPTION_ITEMS.index(row)


def test_every_row_changes_its_setting_one_notch_and_stops_at_the_ends() -> None:
    settings = Settings()
    assert change(settings, MUSIC, +1).music_volume == 0.6
    assert change(change(settings, EFFECTS, +1), EFFECTS, +1).effects_volume == 1.0
    quiet = Settings(music_volume=0.0)
    assert change(quiet, MUSIC, -1).music_volume == 0.0
    assert change(settings, GAME_SPEED, +1).game_speed == 100
    slowest = settings
    for _ in range(9):
        slowest = change(slowest, GAME_SPEED, -1)
    assert slowest.game_speed == 50
    for row, name in (("Timer", "hud_timer"), ("Fullscreen", "fullscreen"), (GHOST, "ghost"),
                      (NO_DAMAGE, "no_damage")):
        assert getattr(change(settings, row, -1), name) is not getattr(settings, name)
    assert settings == Settings()  # a change makes new settings; the old are untouched
    rows = dict(option_rows(Settings(), waiting_for="jump"))
    assert rows["Key: left"] == "left, a" and rows["Key: jump"] == PRESS_A_KEY


def test_the_options_are_reached_from_the_title_and_the_pause_menu_and_back() -> None:
    title = Menus(title_item=2)
    menus, _ = press(title, Nav.CONFIRM, ())
    assert menus.screen is Screen.OPTIONS
    assert press(menus, Nav.RIGHT, ())[1] == ChangeOption(MUSIC, +1)
    assert press(menus, Nav.LEFT, ())[1] == ChangeOption(MUSIC, -1)
    keys = Menus(Screen.OPTIONS, options_item=OPTION_ITEMS.index("Key: jump"))
    assert press(keys, Nav.CONFIRM, ()) == (keys, RebindKey("jump"))
    assert press(menus, Nav.BACK, ())[0].screen is Screen.TITLE
    paused = Menus(Screen.PAUSED, pause_item=PAUSE_ITEMS.index(OPTIONS))
    menus, _ = press(paused, Nav.CONFIRM, ())
    back = Menus(Screen.OPTIONS, options_item=OPTION_ITEMS.index(BACK),
                 options_from=Screen.PAUSED)
    assert menus.screen is Screen.OPTIONS and press(back, Nav.CONFIRM, ())[0].screen is (
        Screen.PAUSED)


def test_each_option_set_on_screen_is_applied_saved_and_read_back(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    volumes: list[tuple[float, float]] = []
    set_volume = Audio.set_volume

    def noted(audio: Audio, effects: float, music: float) -> None:
        volumes.append((effects, music))
        set_volume(audio, effects, music)

    monkeypatch.setattr(Audio, "set_volume", noted)
    down, enter = key(pygame.K_DOWN), key(pygame.K_RETURN)
    open_options = [key(pygame.K_DOWN), key(pygame.K_DOWN), enter]  # Play, Level select
    on_screen = [
        open_options, [key(pygame.K_RIGHT)], [down, key(pygame.K_LEFT)],  # music, effects
        [down, enter], [down, enter], [down, enter],  # timer, fullscreen, ghost
        [down, enter], [key(pygame.K_j)],  # left is now J
        [down, down, down, enter], [key(pygame.K_ESCAPE)],  # jump: Esc keeps its keys
        [down, key(pygame.K_LEFT), key(pygame.K_LEFT)], [down, enter],  # 80 %, no damage
    ]
    game = _window(monkeypatch, [], on_screen)
    assert game.menus.screen is Screen.OPTIONS and game.rebinding is None
    assert volumes[-1] == (0.7, 0.6)  # the audio has the new volumes at once
    assert game.keys[Action.LEFT] == (pygame.K_j,)  # the new key moves left at once
    saved = json.loads((tmp_path / "tile-hopper" / "settings.json").read_text("utf-8"))
    expected = {"music_volume": 0.6, "effects_volume": 0.7, "hud_timer": False,
                "fullscreen": True, "ghost": False, "game_speed": 80, "no_damage": True}
    assert {name: saved[name] for name in expected} == expected
    assert saved["keys"]["left"] == ["j"] and saved["keys"]["jump"] == Settings().keys["jump"]
    again, problem = settings_file().load(Settings.from_json, Settings)
    assert problem is None and again == game.settings
    playing = _window(monkeypatch, ["--level", "x.tmx"], [[]] * 3)  # read back and applied
    assert playing.settings == again and playing.run.campaign.world.no_damage
    assert volumes[-1] == (0.7, 0.6) and playing.run.campaign.results == []


def test_a_key_that_would_clash_is_not_bound_and_the_screen_says_why(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    open_options = [key(pygame.K_DOWN), key(pygame.K_DOWN), key(pygame.K_RETURN)]
    to_left = [*_to_row("Key: left"), key(pygame.K_RETURN)]
    game = _window(monkeypatch, [], [open_options, to_left, [key(pygame.K_d)]])
    assert game.settings.keys["left"] == ["left", "a"]
    assert game.notice is not None and "'d' is bound to both left and right" in game.notice


def test_the_game_speed_assist_runs_fewer_ticks_for_the_same_real_time(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    ticks = {}
    for speed in (100, 50):
        settings_file().save({**Settings().to_json(), "game_speed": speed})
        game = _window(monkeypatch, ["--level", "x.tmx"], [[]] * 120)
        ticks[speed] = game.run.campaign.ticks
        assert game.run.campaign.level_assisted is (speed < 100)
    assert ticks[100] >= 120 and abs(2 * ticks[50] - ticks[100]) <= 2


def test_a_bad_assist_value_gets_its_default_and_one_sentence(tmp_path: Path) -> None:
    file = settings_file(tmp_path)
    file.path.write_text('{"game_speed": 45, "no_damage": "yes", "ghost": false}', "utf-8")
    settings, problem = file.load(Settings.from_json, Settings)
    assert (settings.game_speed, settings.no_damage, settings.ghost) == (100, False, False)
    assert problem is not None and "\n" not in problem
    assert "game_speed is 45, not one of 50, 60, 70, 80, 90, 100 (using 100)" in problem
    assert 'no_damage is "yes", not true or false (using false)' in problem


def test_the_options_screen_draws_every_row_with_its_value(assets: Assets) -> None:
    target = pygame.display.get_surface()
    rows = draw_options(target, assets, 0, Settings(game_speed=70), 0)
    assert [name for name, _ in rows] == list(OPTION_ITEMS)
    assert dict(rows)[GAME_SPEED] == "70 %" and dict(rows)["Key: jump"] == "space, z, up, w"


def test_the_title_shows_the_keys_the_player_has_bound(assets: Assets) -> None:
    surface = pygame.Surface((320, 180))
    settings = Settings()
    draw_title(surface, assets, 0, 0, (), keys=settings.keys)
    before = pygame.image.tobytes(surface, "RGB")
    assert controls_rows(settings.keys) == CONTROLS
    settings.rebind("jump", "x")
    assert controls_rows(settings.keys)[1][1] == "X"
    draw_title(surface, assets, 0, 0, (), keys=settings.keys)
    assert pygame.image.tobytes(surface, "RGB") != before
