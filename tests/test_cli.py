"""``python -m game`` as scripts use it: options, exit codes, the report, replay.

A few tests start the real command as a program (its exit status and its stderr, end to end);
the rest call its ``main`` in this process, where an exception escaping it fails the test.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from game.app import cli
from game.app import run as run_module
from game.sim.inputs import NOTHING, Actions
from game.sim.world import Event
from tests.in_process import call_main
from tests.maps import write_tmx

ROOT = Path(__file__).resolve().parent.parent
ENV = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
REPORT_KEYS = {"ticks", "outcome", "level", "levels_completed", "score", "coins_collected",
               "coins_left", "enemies_stomped", "enemies_left", "lives", "deaths", "player",
               "max_penetration_px", "timing"}
PLAYER_KEYS = {"x", "y", "width", "height", "vx", "vy", "on_ground"}
TIMING_KEYS = {"update_ms_median", "update_ms_p95", "collision_ms_median"}


def game(*args: str | Path, cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "game", *map(str, args)], cwd=cwd, env=ENV,
                          capture_output=True, text=True, timeout=120, check=False)


def in_process(*args: str | Path) -> tuple[int, str]:
    """``python -m game ARGS`` called in this process from the repository's root: its exit
    status and what it said on stderr."""
    ran = call_main(cli.main, args, cwd=ROOT)
    return ran.returncode, ran.stderr


def report_of(tmp_path: Path, *args: str | Path) -> dict[str, object]:
    out = tmp_path / "report.json"
    status, err = in_process("--headless", "--report", out, *args)
    assert status == 0, err
    data: dict[str, object] = json.loads(out.read_text())
    return data


def test_the_report_has_every_key_of_the_contract(tmp_path: Path) -> None:
    """The program itself, end to end: exit status 0 and the report it wrote."""
    out = tmp_path / "report.json"
    result = game("--headless", "--report", out, "--ticks", "30")
    assert result.returncode == 0, result.stderr
    report = json.loads(out.read_text())
    assert set(report) == REPORT_KEYS
    player = report["player"]
    timing = report["timing"]
    assert isinstance(player, dict) and set(player) == PLAYER_KEYS
    assert isinstance(timing, dict) and set(timing) == TIMING_KEYS
    assert report["ticks"] == 30 and report["outcome"] == "running"
    assert report["level"] == "levels/01-first-steps.tmx"


def test_the_same_inputs_give_the_same_report(tmp_path: Path) -> None:
    script = ROOT / "tests/scripts/01-first-steps.txt"
    first = report_of(tmp_path, "--ticks", "500", "--inputs", script)
    second = report_of(tmp_path, "--ticks", "500", "--inputs", script)
    first.pop("timing")
    second.pop("timing")
    assert first == second


def test_a_recorded_run_replays_to_the_same_report(tmp_path: Path) -> None:
    script = ROOT / "tests/scripts/01-first-steps.txt"
    recorded = tmp_path / "recorded.txt"
    original = report_of(tmp_path, "--ticks", "400", "--inputs", script, "--record", recorded)
    replayed = report_of(tmp_path, "--ticks", "400", "--inputs", recorded)
    original.pop("timing")
    replayed.pop("timing")
    assert original == replayed


def test_a_player_on_an_unseen_level_stops_flush_at_9_tiles_per_tick(tmp_path: Path) -> None:
    speed = 9 * 16 * 60  # px/s
    level = write_tmx(tmp_path, [
        "P                             ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                              ",
        "                             #",
        "##############################",
    ], properties={"gravity": ("float", speed * 60), "max_fall_speed": ("float", speed),
                   "run_speed": ("float", speed)})
    inputs = tmp_path / "in.txt"
    inputs.write_text("5 +right\n")
    report = report_of(tmp_path, "--level", level, "--ticks", "20", "--inputs", inputs)
    player = report["player"]
    assert isinstance(player, dict)
    assert player["x"] + player["width"] == 29 * 16
    assert player["y"] + player["height"] == 11 * 16 and player["on_ground"] is True
    assert report["max_penetration_px"] == 0.0


def test_tiled_1_9_class_attributes_are_read_like_type(tmp_path: Path) -> None:
    rows = ["        ", " P  C  D", "########"]
    inputs = tmp_path / "in.txt"
    inputs.write_text("0 +right\n")
    for attr in ("type", "class"):
        folder = tmp_path / attr
        folder.mkdir()
        report = report_of(tmp_path, "--level", write_tmx(folder, rows, class_attr=attr),
                           "--inputs", inputs, "--ticks", "200")
        assert report["outcome"] == "won" and report["coins_collected"] == 1, attr


def test_debug_screenshot_writes_a_png(tmp_path: Path) -> None:
    shot = tmp_path / "shot.png"
    status, err = in_process("--headless", "--ticks", "10", "--debug", "--screenshot", shot)
    assert status == 0, err
    assert shot.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_missing_level_exits_1_with_one_sentence(tmp_path: Path) -> None:
    status, err = in_process("--headless", "--ticks", "5", "--level", tmp_path / "nope.tmx")
    assert status == 1
    assert "Traceback" not in err
    assert err.strip().count("\n") == 0 and "nope.tmx" in err


def test_a_broken_level_exits_1_without_a_traceback(tmp_path: Path) -> None:
    """The program itself, end to end: exit status 1 and nothing but its sentence."""
    bad = tmp_path / "bad.tmx"
    bad.write_text("<map><layer>")
    result = game("--headless", "--ticks", "5", "--level", bad)
    assert result.returncode == 1
    assert "Traceback" not in result.stderr and "bad.tmx" in result.stderr


def test_a_bad_input_line_exits_2_naming_the_line(tmp_path: Path) -> None:
    """The program itself, end to end: exit status 2."""
    inputs = tmp_path / "in.txt"
    inputs.write_text("# fine\n0 +right\n10 +fly\n")
    result = game("--headless", "--ticks", "5", "--inputs", inputs)
    assert result.returncode == 2
    assert "line 3" in result.stderr and "Traceback" not in result.stderr


def test_decreasing_ticks_in_an_input_script_are_refused(tmp_path: Path) -> None:
    inputs = tmp_path / "in.txt"
    inputs.write_text("10 +right\n5 -right\n")
    status, err = in_process("--headless", "--ticks", "5", "--inputs", inputs)
    assert status == 2 and "line 2" in err


@pytest.mark.parametrize("args", [["--ticks", "-3"], ["--ticks", "many"], ["--frobnicate"]])
def test_bad_usage_exits_2(args: list[str]) -> None:
    status, err = in_process("--headless", *args)
    assert status == 2
    assert "Traceback" not in err and "usage:" in err


def test_the_game_starts_without_setuptools_and_pygame_still_finds_its_own_font() -> None:
    """pygame imported through the game skips ``pkg_resources`` and numpy (a fifth and a
    sixth of a second at every start) and finds its default font in its own folder instead."""
    code = ("import sys, game, pygame; pygame.font.init(); "
            "print('pkg_resources' in sys.modules, 'numpy' in sys.modules, "
            "pygame.font.Font(None, 24).size('Tile'))")
    ran = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=ENV, text=True,
                         capture_output=True, timeout=120, check=False)
    assert ran.returncode == 0, ran.stderr
    setuptools_kept_out, numpy_kept_out, size = ran.stdout.split(" ", 2)
    assert setuptools_kept_out == numpy_kept_out == "False"
    assert size.strip() != "(0, 0)"


def test_the_game_starts_without_numpy_and_pygame_loads_its_arrays_when_used() -> None:
    """numpy (installed here for the benchmark) is not imported at start; pygame's surfarray
    and sndarray load it the first time they are used, by attribute or by import."""
    pytest.importorskip("numpy")
    code = ("import sys, game, pygame; started = 'numpy' in sys.modules; "
            "shape = pygame.surfarray.array3d(pygame.Surface((4, 3))).shape; "
            "import pygame.sndarray; "
            "print(started, 'numpy' in sys.modules, shape, callable(pygame.sndarray.array))")
    ran = subprocess.run([sys.executable, "-c", code], cwd=ROOT, env=ENV, text=True,
                         capture_output=True, timeout=120, check=False)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout.split() == ["False", "True", "(4,", "3,", "3)", "True"]


def test_a_script_that_ends_after_a_headless_run_would_is_refused_before_any_tick(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    script = tmp_path / "far.txt"
    script.write_text("0 +right\n999999999999 -right  # a typo\n# the end\n\n", encoding="utf-8")
    ticks: list[int] = []
    tick = run_module.Run.tick

    def counted(self: run_module.Run, player: Actions = NOTHING) -> list[Event]:
        ticks.append(self.campaign.ticks)
        assert len(ticks) < 1000, "the run started"
        return tick(self, player)

    monkeypatch.setattr(run_module.Run, "tick", counted)
    status, err = in_process("--headless", "--inputs", script)
    assert status == 2 and ticks == [], err
    assert err.count("\n") == 1 and "far.txt: line 2: tick 999,999,999,999 comes after" in err
    status, err = in_process("--headless", "--inputs", script, "--ticks", "5")
    assert status == 0 and len(ticks) == 5, err  # with --ticks, the script is cut there


def test_a_headless_run_without_ticks_stops_at_its_limit_and_says_so(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(run_module, "HEADLESS_TICK_LIMIT", 30)
    out = tmp_path / "report.json"
    status, err = in_process("--headless", "--report", out)
    assert status == 0 and json.loads(out.read_text("utf-8"))["ticks"] == 30
    assert err.startswith("the run stopped after 30 ticks") and "--ticks N" in err


@pytest.mark.parametrize(("last_tick", "status"), [(29, 0), (30, 2)])
def test_a_script_may_end_on_the_last_tick_of_a_headless_run_and_no_later(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, last_tick: int, status: int) -> None:
    monkeypatch.setattr(run_module, "HEADLESS_TICK_LIMIT", 30)
    script = tmp_path / "edge.txt"
    script.write_text(f"0 +right\n{last_tick} -right\n", encoding="utf-8")
    assert in_process("--headless", "--inputs", script)[0] == status


# -- runs without --ticks: what they say, and where a script's run ends -------------------------

WINNING = ROOT / "tests" / "scripts" / "01-first-steps.txt"
FIRST = ROOT / "levels" / "01-first-steps.tmx"


def test_a_script_run_without_ticks_ends_when_its_level_ends(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(run_module, "HEADLESS_TICK_LIMIT", 3_000)  # the level ends near 2,110
    report = report_of(tmp_path, "--level", FIRST, "--inputs", WINNING)
    assert report["outcome"] == "won" and report["levels_completed"] == 1
    assert str(report["level"]).endswith("01-first-steps.tmx")
    assert isinstance(report["ticks"], int) and report["ticks"] < 2_200


def test_go_on_carries_a_script_run_on_into_the_next_level(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(run_module, "HEADLESS_TICK_LIMIT", 2_500)
    report = report_of(tmp_path, "--level", FIRST, "--inputs", WINNING, "--go-on")
    assert report["outcome"] == "running" and report["levels_completed"] == 1
    assert str(report["level"]).endswith("02-over-the-gaps.tmx") and report["ticks"] == 2_500
    with_ticks = report_of(tmp_path, "--level", FIRST, "--inputs", WINNING, "--ticks", "2500")
    assert with_ticks["level"] == report["level"]  # --ticks goes on, as it always has


@pytest.mark.parametrize(("options", "says"), [
    ((), "and the levels after it with no input held"),
    (("--inputs", WINNING), "until that level is won or every life is lost"),
    (("--inputs", WINNING, "--go-on"), "and the levels after it with the input script")])
def test_a_headless_run_without_ticks_says_on_stdout_what_it_will_run(
        monkeypatch: pytest.MonkeyPatch, options: tuple[str | Path, ...], says: str) -> None:
    monkeypatch.setattr(run_module, "HEADLESS_TICK_LIMIT", 2_500)  # after the script's end
    ran = call_main(cli.main, ["--headless", "--level", FIRST, *options], cwd=ROOT)
    assert ran.returncode == 0, ran.stderr
    [line] = ran.stdout.splitlines()
    assert line.startswith("python -m game: playing levels/01-first-steps.tmx") and says in line
    assert "for at most 2,500 ticks" in line and "--ticks N" in line
    timed = call_main(cli.main, ["--headless", "--level", FIRST, *options, "--ticks", "30"],
                      cwd=ROOT)
    assert (timed.returncode, timed.stdout, timed.stderr) == (0, "", "")  # as it always was

