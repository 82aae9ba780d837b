"""With no display to show a window on, the game and the lab end at once with one sentence
that names what to run instead, and exit 1; their headless options still work there; and
the windows they open are called ``tile-hopper`` and ``tile-hopper lab``, title and class.

The programs run as subprocesses with ``DISPLAY``, ``WAYLAND_DISPLAY`` and
``SDL_VIDEODRIVER`` taken out of their environment, as on a server or over plain SSH."""

from __future__ import annotations

import gc
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pygame
import pytest

from game.app import display
from game.app.display import (
    CLASS_VARIABLES,
    EXIT_NO_WINDOW,
    GAME_WINDOW,
    LAB_WINDOW,
    open_window,
)
from game.lab import cli as lab_cli

ROOT = Path(__file__).resolve().parent.parent
HANG_GUARD_S = 120  # a hang guard only: the verdict never depends on time
GAME = ("-m", "game")
LAB = ("-m", "game.lab")
SDL_NOISE = ("XDG_RUNTIME_DIR", "Traceback", "pygame ")


def without_display(**extra: str) -> dict[str, str]:
    env = {name: value for name, value in os.environ.items()
           if name not in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER")}
    return {**env, "SDL_AUDIODRIVER": "dummy", **extra}


def run(program: tuple[str, ...], *args: str, env: dict[str, str] | None = None,
        cwd: Path = ROOT) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, *program, *args], cwd=cwd,
                          env=without_display() if env is None else env,
                          capture_output=True, text=True, timeout=HANG_GUARD_S, check=False)


def assert_one_sentence(result: subprocess.CompletedProcess[str], program: str,
                        *options: str) -> None:
    assert result.returncode == EXIT_NO_WINDOW == 1
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    sentence = lines[0]
    assert sentence.startswith(f"{program}: cannot open a window (")
    assert sentence.endswith(".") and sentence.count(". ") == 0
    assert all(option in sentence for option in options), sentence
    assert not any(noise in result.stderr for noise in SDL_NOISE)
    assert result.stdout == ""


def test_the_game_with_no_display_says_so_and_names_headless_and_screenshot() -> None:
    result = run(GAME)
    assert_one_sentence(result, "python -m game", "--headless", "--screenshot")
    assert "neither DISPLAY nor WAYLAND_DISPLAY is set" in result.stderr


def test_a_level_or_a_script_needs_the_window_too() -> None:
    result = run(GAME, "--level", "levels/01-first-steps.tmx", "--ticks", "10")
    assert_one_sentence(result, "python -m game", "--headless")


def test_the_lab_with_no_display_says_so_and_names_screenshot_and_list() -> None:
    result = run(LAB)
    assert_one_sentence(result, "python -m game.lab", "--screenshot", "--list")
    result = run(LAB, "--scene", "overlap")
    assert_one_sentence(result, "python -m game.lab", "--screenshot")


@pytest.mark.parametrize("program", [GAME, LAB], ids=["game", "lab"])
def test_a_display_that_does_not_answer_is_the_same_sentence_without_sdl_noise(
        program: tuple[str, ...]) -> None:
    result = run(program, env=without_display(DISPLAY=":1987"))  # no X server there
    assert_one_sentence(result, f"python {' '.join(program)}", "--screenshot")
    assert "':1987'" in result.stderr


def test_sdl_falling_back_to_its_offscreen_driver_is_no_display(tmp_path: Path) -> None:
    env = without_display(WAYLAND_DISPLAY="no-compositor-here", XDG_RUNTIME_DIR=str(tmp_path))
    result = run(GAME, env=env)
    assert_one_sentence(result, "python -m game", "--headless")
    assert "only its offscreen driver" in result.stderr


def test_the_headless_paths_still_work_with_no_display(tmp_path: Path) -> None:
    shot, lab_shot = tmp_path / "game.png", tmp_path / "lab.png"
    game = run(GAME, "--headless", "--ticks", "5", "--screenshot", str(shot))
    assert game.returncode == 0, game.stderr
    lab = run(LAB, "--scene", "overlap", "--screenshot", str(lab_shot))
    assert lab.returncode == 0, lab.stderr
    assert shot.stat().st_size > 0 and lab_shot.stat().st_size > 0
    listed = run(LAB, "--list")
    assert listed.returncode == 0 and "overlap" in listed.stdout.split()


@pytest.fixture
def chosen_dummy_driver(monkeypatch: pytest.MonkeyPatch) -> Iterator[None]:
    """``SDL_VIDEODRIVER=dummy`` set by hand, with the class variables restored after."""
    monkeypatch.setenv("SDL_VIDEODRIVER", "dummy")
    for variable in CLASS_VARIABLES:
        monkeypatch.delenv(variable, raising=False)
    pygame.display.quit()  # a window made afresh, whatever an earlier test left open
    gc.collect()  # and no window object of an earlier test still holding SDL's renderer
    yield
    pygame.display.quit()


def test_a_driver_chosen_by_hand_opens_the_window_named_for_its_class_and_title(
        chosen_dummy_driver: None) -> None:
    assert open_window("python -m game", GAME_WINDOW, (320, 180), "run with --headless") is None
    assert pygame.display.get_caption()[0] == "tile-hopper"
    assert {os.environ[variable] for variable in CLASS_VARIABLES} == {"tile-hopper"}
    assert pygame.display.get_surface().get_size() == (320, 180)


def test_the_game_opens_its_window_as_tile_hopper(chosen_dummy_driver: None) -> None:
    from game.app.run import _open_display

    assert _open_display(False, "python -m game") is None
    assert pygame.display.get_caption()[0] == GAME_WINDOW
    assert os.environ["SDL_VIDEO_X11_WMCLASS"] == GAME_WINDOW


def test_the_lab_asks_for_its_window_as_tile_hopper_lab(
        monkeypatch: pytest.MonkeyPatch) -> None:
    asked: list[tuple[str, str]] = []

    def refuse(program: str, name: str, size: tuple[int, int], instead: str) -> str:
        asked.append((program, name))
        return display.no_window(program, "test", instead)

    monkeypatch.setattr(lab_cli, "open_window", refuse)
    assert lab_cli.window(None) == EXIT_NO_WINDOW
    assert asked == [("python -m game.lab", LAB_WINDOW)]
