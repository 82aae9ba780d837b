"""``python -m game.bench.window``: a frame of play against the bare SCALED window, at both
window sizes, side by side; a skip, said in one line, where no window can be shown."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from game.bench import window as bench_window
from tests.in_process import call_main

ROOT = Path(__file__).resolve().parent.parent


def test_the_window_bench_costs_play_and_the_bare_window_in_the_same_rounds() -> None:
    cost = bench_window.measure((960, 540), rounds=2, frames=2, warm_up=1)
    assert cost.size == (960, 540) and cost.rounds == 2
    assert cost.play_ms > 0 and cost.bare_ms > 0
    assert cost.ratio.low <= cost.ratio.estimate <= cost.ratio.high
    line = cost.line()
    assert line.startswith("960x540: a frame of play ") and "x over 2 rounds" in line
    assert f"at most {bench_window.MAX_RATIO:g}x" in line


def test_the_window_bench_measures_a_size_from_its_command_line() -> None:
    ran = call_main(bench_window.main, ["--size", "1600x900", "--rounds", "2", "--frames", "2"],
                    cwd=ROOT)
    assert ran.returncode in (bench_window.EXIT_PASSED, bench_window.EXIT_OVER), ran.stderr
    [line] = ran.stdout.splitlines()
    assert line.startswith("1600x900: ")


def test_the_window_bench_skips_in_one_line_with_no_display_and_no_xvfb(
        monkeypatch: pytest.MonkeyPatch) -> None:
    for variable in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(variable, raising=False)
    monkeypatch.setattr("sys.platform", "linux")
    monkeypatch.setattr(shutil, "which", lambda name: None)
    ran = call_main(bench_window.main, ["--rounds", "2"], cwd=ROOT)
    assert ran.returncode == 0 and ran.stderr == ""
    [line] = ran.stdout.splitlines()
    assert "skipped" in line and "no Xvfb" in line
