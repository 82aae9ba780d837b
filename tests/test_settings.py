"""Settings round-trip through the data folder; bad values fall back to defaults, with a reason."""

from __future__ import annotations

import json
import os
import warnings
from pathlib import Path
from typing import Any

import pygame
import pytest

from game.app.settings import DEFAULT_KEYS, Settings, key_code, settings_file
from game.sim.inputs import Action


@pytest.fixture
def data_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A fresh XDG_DATA_HOME; returns the game's folder inside it."""
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    return tmp_path / "tile-hopper"


def write_settings(folder: Path, data: Any) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "settings.json").write_text(json.dumps(data), encoding="utf-8")


def load() -> tuple[Settings, str | None]:
    return settings_file().load(Settings.from_json, Settings)


def test_settings_survive_a_round_trip(data_home: Path) -> None:
    chosen = Settings(effects_volume=0.3, music_volume=0.0, fullscreen=True,
                      keys={**Settings().keys, "jump": ["x", "return"]},
                      buttons={**Settings().buttons, "jump": [1], "down": [13]})
    assert settings_file().save(chosen.to_json()) is None
    assert (data_home / "settings.json").is_file()
    assert load() == (chosen, None)


def test_no_settings_file_gives_the_defaults_quietly(data_home: Path) -> None:
    assert load() == (Settings(), None)


def test_unknown_keys_and_actions_are_ignored_without_a_word(data_home: Path) -> None:
    write_settings(data_home, {"theme": "dark", "music_volume": 0.1,
                               "keys": {"dash": ["lshift"]}})
    settings, problem = load()
    assert problem is None
    assert settings == Settings(music_volume=0.1)
    assert list(data_home.iterdir()) == [data_home / "settings.json"]  # nothing kept aside


@pytest.mark.parametrize(("stored", "named"), [
    ({"effects_volume": 1.5}, "effects_volume is 1.5"),
    ({"effects_volume": "loud"}, 'effects_volume is "loud"'),
    ({"music_volume": None}, "music_volume is null"),
    ({"music_volume": True}, "music_volume is true"),
    ({"fullscreen": "yes"}, 'fullscreen is "yes"'),
    ({"keys": {"left": "left"}}, 'keys.left is "left", not a list'),
    ({"keys": {"left": []}}, "keys.left has no usable entry"),
    ({"keys": {"left": ["nosuchkey"]}}, '"nosuchkey" is not a key name'),
    ({"keys": ["left"]}, "keys is not an object"),
    ({"buttons": {"jump": [-1]}}, "buttons.jump: -1 is not a button number"),
])
def test_a_bad_value_falls_back_to_its_default_with_a_message(
        data_home: Path, stored: dict[str, Any], named: str) -> None:
    write_settings(data_home, stored)
    settings, problem = load()
    assert settings == Settings()
    assert problem is not None and named in problem
    assert problem.startswith(str(data_home / "settings.json")) and problem.endswith(".")
    [backup] = data_home.glob("settings.json.corrupt-*")
    assert json.loads(backup.read_text(encoding="utf-8")) == stored


def test_good_values_beside_a_bad_one_are_kept(data_home: Path) -> None:
    write_settings(data_home, {"effects_volume": 9, "music_volume": 0.2,
                               "keys": {"jump": ["spcae", "x"]}})
    settings, problem = load()
    assert (settings.effects_volume, settings.music_volume) == (0.8, 0.2)
    assert settings.keys["jump"] == ["x"]
    assert problem is not None and "effects_volume" in problem and '"spcae"' in problem


def test_settings_that_are_not_json_are_kept_aside(data_home: Path) -> None:
    data_home.mkdir()
    (data_home / "settings.json").write_text("effects_volume = 0.5\n", encoding="utf-8")
    settings, problem = load()
    assert settings == Settings()
    assert problem is not None and "not valid JSON" in problem
    assert len(list(data_home.glob("settings.json.corrupt-*"))) == 1


def test_an_empty_button_list_unbinds_on_purpose(data_home: Path) -> None:
    write_settings(data_home, {"buttons": {"jump": []}})
    settings, problem = load()
    assert problem is None and settings.button_numbers()[Action.JUMP] == ()


def test_key_names_are_stored_the_way_pygame_spells_them() -> None:
    settings, problems = Settings.from_json({"keys": {"left": ["Left", "A"]}})
    assert problems == []
    assert settings.keys["left"] == ["left", "a"]
    assert settings.key_codes()[Action.LEFT] == (pygame.K_LEFT, pygame.K_a)


def test_the_default_keys_are_the_game_s_keys() -> None:
    codes = Settings().key_codes()
    assert codes[Action.JUMP] == (pygame.K_SPACE, pygame.K_z, pygame.K_UP, pygame.K_w)
    assert set(DEFAULT_KEYS) == {action.value for action in Action}


def test_key_names_are_read_before_pygame_init_without_a_warning() -> None:
    pygame.display.quit()  # the state a settings file is read in: no window yet
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert key_code("space") == pygame.K_SPACE
        assert key_code("nosuchkey") is None
        settings, problems = Settings.from_json({"keys": {"jump": ["Return"]}})
    assert problems == [] and settings.keys["jump"] == ["return"]


@pytest.mark.parametrize(("data", "reason"), [
    ({"buttons": {"jump": [10**29]}}, "not a button number from 0 to 63"),
    ({"keys": {action: ["x"] for action in ("left", "right", "up", "down", "jump")}},
     "'x' is bound to both left and right"),
    ({"keys": {"down": ["s"], "jump": ["s"]}}, "'s' is bound to both down and jump"),
    ({"buttons": {"left": [3], "right": [3]}}, "3 is bound to both left and right"),
])
def test_impossible_bindings_are_refused_with_the_reason_and_the_defaults_kept(
        data: dict[str, object], reason: str) -> None:
    settings, problems = Settings.from_json(data)
    assert settings.keys == Settings().keys and settings.buttons == Settings().buttons
    assert any(reason in problem for problem in problems), problems


def test_temporary_files_of_an_interrupted_save_are_removed_at_the_next_start(
        tmp_path: Path) -> None:
    dead = 2**22 + 12345  # above Linux's largest process id, so no process has it
    orphans = [tmp_path / f".settings.{dead}.0123abcd.json",
               tmp_path / f".settings.{dead}.89abcdef.json"]
    for orphan in orphans:
        orphan.write_text("{", encoding="utf-8")
    mine = tmp_path / f".settings.{os.getpid()}.00000000.json"  # a save under way: kept
    mine.write_text("{", encoding="utf-8")
    other = tmp_path / f".progress.{dead}.0123abcd.json"  # another file's: not touched here
    other.write_text("{", encoding="utf-8")
    settings, problem = settings_file(tmp_path).load(Settings.from_json, Settings)
    assert problem is None and settings == Settings()
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([mine.name, other.name])
