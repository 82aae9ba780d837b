"""``--level NAME``: a shipped level found by its name, whatever maps the campaign holds.

The lookup reads the campaign's folder, so the tests give it folders of their own making
(names no shipped map has) as well as the shipped one.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from game.app import cli
from game.app.level_names import UnknownLevel, level_names, level_path
from game.levels.shipped import LEVELS_DIR
from tests.in_process import call_main

ROOT = Path(__file__).resolve().parent.parent


def campaign(tmp_path: Path, *names: str) -> Path:
    folder = tmp_path / "levels"
    folder.mkdir()
    for name in names:
        (folder / name).write_text("<map/>", encoding="utf-8")
    return folder


@pytest.mark.parametrize("name", ["harbour-run", "07-harbour-run", "07-harbour-run.tmx", "7",
                                  "Harbour Run", "HARBOUR_RUN"])
def test_a_name_finds_the_map_whatever_maps_the_folder_holds(tmp_path: Path, name: str) -> None:
    folder = campaign(tmp_path, "07-harbour-run.tmx", "12-night-lift.tmx", "notes.txt")
    assert level_path(Path(name), folder) == folder / "07-harbour-run.tmx"
    assert level_names(folder) == ["07-harbour-run", "12-night-lift"]


def test_an_unknown_name_is_one_sentence_naming_the_levels_and_the_list_option(
        tmp_path: Path) -> None:
    folder = campaign(tmp_path, "07-harbour-run.tmx", "12-night-lift.tmx")
    with pytest.raises(UnknownLevel) as refused:
        level_path(Path("harbor-run"), folder)
    sentence = str(refused.value)
    assert "\n" not in sentence and "'harbor-run'" in sentence and " — " in sentence
    assert "07-harbour-run, 12-night-lift" in sentence and "--list-levels" in sentence


def test_a_name_two_maps_answer_to_is_refused_with_both(tmp_path: Path) -> None:
    folder = campaign(tmp_path, "03-cave.tmx", "09-cave.tmx")
    with pytest.raises(UnknownLevel, match="03-cave, 09-cave"):
        level_path(Path("cave"), folder)
    assert level_path(Path("09-cave"), folder) == folder / "09-cave.tmx"


def test_a_path_stays_a_path(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    folder = campaign(tmp_path, "01-first-steps.tmx")
    monkeypatch.chdir(tmp_path)
    (tmp_path / "first-steps").write_text("<map/>", encoding="utf-8")  # a file of that name
    assert level_path(Path("first-steps"), folder) == Path("first-steps")
    assert level_path(Path("elsewhere/first-steps"), folder) == Path("elsewhere/first-steps")
    assert level_path(Path("missing.tmx"), folder) == Path("missing.tmx")  # the loader says


def test_the_game_starts_a_shipped_level_by_name_from_any_folder(tmp_path: Path) -> None:
    report = tmp_path / "r.json"
    ran = call_main(cli.main, ["--headless", "--level", "over-the-gaps", "--ticks", "1",
                               "--report", report], cwd=tmp_path)
    assert ran.returncode == 0, ran.stderr
    level = json.loads(report.read_text(encoding="utf-8"))["level"]
    assert Path(level) == LEVELS_DIR / "02-over-the-gaps.tmx"


def test_an_unknown_level_name_is_bad_usage_in_one_line(tmp_path: Path) -> None:
    ran = call_main(cli.main, ["--headless", "--level", "no-such-level"], cwd=tmp_path)
    assert ran.returncode == 2 and ran.stderr.count("\n") == 1 and "Traceback" not in ran.stderr
    assert ran.stderr.startswith("python -m game: --level 'no-such-level': ")


def test_list_levels_prints_the_shipped_names_one_a_line() -> None:
    ran = call_main(cli.main, ["--list-levels"], cwd=ROOT)
    assert ran.returncode == 0
    assert ran.stdout.splitlines() == sorted(p.stem for p in LEVELS_DIR.glob("*.tmx"))
