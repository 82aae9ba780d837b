"""Progress is saved atomically in the data folder; a bad save is kept aside, never wiped."""

from __future__ import annotations

import errno
import json
import os
from pathlib import Path

import pygame
import pytest

from game.app import cli, saves
from game.app import window as window_module
from game.app.cli import parser
from game.app.files import FileProblem
from game.app.menus import Screen
from game.app.run import Run, input_script
from game.app.saves import (
    Attempt,
    CampaignMaps,
    Finish,
    JsonFile,
    Progress,
    data_dir,
    progress_file,
)
from game.app.window import GameWindow
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import NOTHING, Action
from game.sim.world import EventKind
from tests.in_process import call_main
from tests.maps import write_tmx

SCRIPTS = Path(__file__).resolve().parent / "scripts"


@pytest.fixture
def data_home(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A fresh XDG_DATA_HOME; returns the game's folder inside it."""
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    return tmp_path / "tile-hopper"


def load(file: JsonFile) -> tuple[Progress, str | None]:
    return file.load(Progress.from_json, Progress)


def played() -> Progress:
    progress = Progress()
    progress.complete_level("01-first-steps.tmx", ticks=900, coins=4,
                            next_level="02-over-the-gaps.tmx")
    return progress


def backups(folder: Path) -> list[Path]:
    return sorted(folder.glob("progress.json.corrupt-*"))


def test_the_data_folder_follows_xdg_data_home(data_home: Path) -> None:
    assert data_dir() == data_home
    assert progress_file().path == data_home / "progress.json"


def test_a_relative_xdg_data_home_is_ignored(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", "relative/data")
    home = Path("/home/ann")
    assert data_dir(platform="linux", home=home) == home / ".local/share/tile-hopper"


def test_windows_without_appdata_uses_the_roaming_folder() -> None:
    home = Path("/Users/ann")
    assert data_dir({}, "win32", home) == home / "AppData" / "Roaming" / "tile-hopper"


def test_progress_survives_a_round_trip(data_home: Path) -> None:
    assert progress_file().save(played().to_json()) is None
    loaded, problem = load(progress_file())
    assert problem is None
    assert loaded == played()
    assert json.loads((data_home / "progress.json").read_text())["version"] == 1


def test_no_save_yet_is_fresh_progress_and_no_message(data_home: Path) -> None:
    assert load(progress_file()) == (Progress(), None)
    assert not data_home.exists()  # reading never creates anything


def test_a_faster_finish_and_more_coins_are_kept_separately() -> None:
    progress = played()
    assert not progress.complete_level("01-first-steps.tmx", 1000, 2, None)
    assert progress.complete_level("01-first-steps.tmx", 800, 1, None)
    assert progress.best_ticks == {"01-first-steps.tmx": 800}
    assert progress.best_coins == {"01-first-steps.tmx": 4}


def test_a_save_that_is_not_json_is_kept_aside_and_reported(data_home: Path) -> None:
    data_home.mkdir()
    (data_home / "progress.json").write_text('{"unlocked": ["02-over-the-', encoding="utf-8")
    loaded, problem = load(progress_file())
    assert loaded == Progress()
    [backup] = backups(data_home)
    assert backup.read_text(encoding="utf-8") == '{"unlocked": ["02-over-the-'
    assert not (data_home / "progress.json").exists()
    assert problem is not None and "not valid JSON" in problem and backup.name in problem
    assert problem.endswith(".") and problem.count(". ") == 0 and "\n" not in problem


def test_wrong_types_keep_the_good_entries_and_back_up_the_file(data_home: Path) -> None:
    data_home.mkdir()
    original = json.dumps({"unlocked": ["02-over-the-gaps.tmx", 2],
                           "best_ticks": {"01-first-steps.tmx": 900, "x.tmx": -5},
                           "best_coins": {"01-first-steps.tmx": True}})
    (data_home / "progress.json").write_text(original, encoding="utf-8")
    loaded, problem = load(progress_file())
    assert loaded == Progress({"02-over-the-gaps.tmx"}, {"01-first-steps.tmx": 900}, {})
    assert problem is not None and '"x.tmx" has -5' in problem and "and 0 more" not in problem
    [backup] = backups(data_home)
    assert backup.read_text(encoding="utf-8") == original


def test_a_save_holding_a_list_is_kept_aside(data_home: Path) -> None:
    data_home.mkdir()
    (data_home / "progress.json").write_text("[1, 2]", encoding="utf-8")
    loaded, problem = load(progress_file())
    assert loaded == Progress()
    assert problem is not None and "a list, not an object" in problem
    assert len(backups(data_home)) == 1


def test_an_unreadable_save_is_kept_aside_and_reported(data_home: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    progress_file().save(played().to_json())

    def refuse(path: Path, *args: object, **kwargs: object) -> str:
        raise FileProblem(f"{path}: the file cannot be read (Permission denied) — check it",
                          "Permission denied")

    monkeypatch.setattr(saves, "read_small_text", refuse)
    loaded, problem = load(progress_file())
    monkeypatch.undo()
    assert loaded == Progress()
    assert problem is not None and "could not be read (Permission denied)" in problem
    [backup] = backups(data_home)
    assert json.loads(backup.read_text(encoding="utf-8")) == played().to_json()


def test_a_bad_save_that_cannot_be_moved_is_never_written_over(
        data_home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    data_home.mkdir()
    (data_home / "progress.json").write_text("not json", encoding="utf-8")
    file = progress_file()
    with monkeypatch.context() as patch:
        def stuck(src: object, dst: object) -> None:
            raise PermissionError(errno.EPERM, "Operation not permitted")

        patch.setattr(os, "replace", stuck)
        _, problem = load(file)
    assert problem is not None and "could not be moved aside" in problem
    assert file.save(played().to_json()) == problem
    assert (data_home / "progress.json").read_text(encoding="utf-8") == "not json"


def test_two_bad_saves_in_the_same_second_keep_both_backups(data_home: Path) -> None:
    data_home.mkdir()
    for text in ("first", "second"):
        (data_home / "progress.json").write_text(text, encoding="utf-8")
        load(progress_file())
    assert sorted(path.read_text(encoding="utf-8") for path in backups(data_home)) == [
        "first", "second"]


def test_a_write_that_fails_midway_leaves_the_old_save_intact(
        data_home: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    file = progress_file()
    file.save(Progress().to_json())
    before = (data_home / "progress.json").read_bytes()

    def disk_fills_up(self: Path, text: str, *args: object, **kwargs: object) -> int:
        with open(self, "w", encoding="utf-8") as half:
            half.write(text[: len(text) // 2])
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(Path, "write_text", disk_fills_up)
    problem = file.save(played().to_json())
    monkeypatch.undo()
    assert problem is not None and "No space left on device" in problem
    assert (data_home / "progress.json").read_bytes() == before
    assert [path.name for path in data_home.iterdir()] == ["progress.json"]  # no temp left


def test_a_long_list_of_problems_is_cut_short() -> None:
    _, problems = Progress.from_json({"best_ticks": {f"{n}.tmx": "x" for n in range(10)}})
    assert len(problems) == 10
    assert saves.summarise(problems).endswith("; and 7 more")


def test_an_attempt_times_a_finished_level_and_counts_its_coins() -> None:
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    script = input_script(SCRIPTS / "01-first-steps.txt")
    attempt = Attempt()
    finishes: list[Finish] = []
    exit_tick = None
    while not finishes and campaign.ticks < 60 * 60:
        attempt.before_tick(campaign)
        events = campaign.tick(script.held_at(campaign.ticks))
        if any(event.kind is EventKind.EXIT for event in events):
            exit_tick = campaign.ticks
        if (finish := attempt.after_tick(campaign, events)) is not None:
            finishes.append(finish)
    assert exit_tick is not None
    assert finishes == [Finish("01-first-steps.tmx", exit_tick, campaign.coins_collected,
                               "02-over-the-gaps.tmx")]
    assert campaign.coins_collected > 0
    progress = Progress()
    assert progress.record(finishes[0])
    assert progress.unlocked == {"02-over-the-gaps.tmx"}


def test_an_attempt_starts_again_when_the_level_restarts() -> None:
    campaign = Campaign(FIRST_LEVEL, loader=load_level)
    attempt = Attempt()
    for _ in range(10):
        attempt.before_tick(campaign)
        attempt.after_tick(campaign, campaign.tick(NOTHING))
    attempt.coins = 3  # as if some had been taken
    campaign.restart_level()
    attempt.before_tick(campaign)
    assert (attempt.started_tick, attempt.coins) == (10, 0)


def _play_to_the_end(run: Run, monkeypatch: pytest.MonkeyPatch) -> GameWindow:
    """A person holding right in the window until the run ends, Enter pressed at every
    banner; the window closed at the end screen."""
    monkeypatch.setattr(window_module, "held_keys", lambda *_: frozenset({Action.RIGHT}))
    game = GameWindow(run)
    frames: list[Screen] = []
    enter = pygame.event.Event(pygame.KEYDOWN, key=pygame.K_RETURN, mod=0, unicode="",
                               scancode=0)

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        frames.append(game.menus.screen)
        assert len(frames) < 2000, "the run never ended"
        if game.menus.screen is Screen.ENDED:
            return [pygame.event.Event(pygame.QUIT)]
        return [enter]

    monkeypatch.setattr(pygame.event, "get", next_batch)
    assert game.play() == 0
    assert run.campaign.outcome is Outcome.WON
    return game


def test_a_downloaded_map_named_like_a_campaign_map_never_changes_progress(
        display: None, data_home: Path, tmp_path: Path,
        monkeypatch: pytest.MonkeyPatch) -> None:
    progress_file().save(played().to_json())
    before = (data_home / "progress.json").read_bytes()
    downloads = tmp_path / "Downloads"
    downloads.mkdir()
    first = write_tmx(downloads, [" PD ", "####"], name=FIRST_LEVEL.name,
                      properties={"next_level": ("file", "06-the-summit.tmx")})
    write_tmx(downloads, [" PD ", "####"], name="06-the-summit.tmx")
    run = Run(Campaign(first, loader=load_level), None,
              parser().parse_args(["--level", str(first)]))
    game = _play_to_the_end(run, monkeypatch)
    assert len(run.campaign.results) == 2  # both downloaded maps were finished
    assert (data_home / "progress.json").read_bytes() == before
    assert game.progress.best_ticks == {"01-first-steps.tmx": 900}
    assert "06-the-summit.tmx" not in game.progress.unlocked


def test_a_campaign_map_keeps_its_finish_whatever_name_leads_to_it(tmp_path: Path) -> None:
    level = load_level(FIRST_LEVEL.parent / ".." / FIRST_LEVEL.parent.name / FIRST_LEVEL.name)
    maps = CampaignMaps.of([FIRST_LEVEL, FIRST_LEVEL.with_name("02-over-the-gaps.tmx")])
    finish = Finish(FIRST_LEVEL.name, 900, 3, "02-over-the-gaps.tmx")
    assert maps.kept(finish, level) == finish
    alone = CampaignMaps.of([FIRST_LEVEL])  # its next map is not the campaign's: no unlock
    assert alone.kept(finish, level) == finish._replace(next_level=None)
    copy = tmp_path / FIRST_LEVEL.name
    copy.write_bytes(FIRST_LEVEL.read_bytes())
    assert not maps.holds(copy)


def test_a_headless_run_never_touches_the_saves(data_home: Path) -> None:
    ran = call_main(cli.main, ["--headless", "--level", FIRST_LEVEL, "--inputs",
                               SCRIPTS / "01-first-steps.txt", "--ticks", "900"])
    assert ran.returncode == 0, ran.stderr
    assert not data_home.exists()
