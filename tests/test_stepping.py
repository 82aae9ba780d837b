"""Step through a tick: with the overlay on, F2 freezes the simulation, F3 runs exactly one
tick, F4 plays at quarter speed; with the overlay off the keys do nothing. Driven through the
real window loop, headless, with the key presses fed in frame by frame."""

from __future__ import annotations

import itertools
import re
from pathlib import Path

import pygame
import pytest

from game.app import frame as frame_module
from game.app.cli import parser
from game.app.effects import Effects
from game.app.run import Run
from game.app.stepping import (
    FREEZE_KEY,
    SLOW_KEY,
    SLOW_SPEED,
    STEP_KEY,
    TickControl,
    key_label,
)
from game.app.window import play_in_window
from game.sim.campaign import Campaign
from game.sim.fixed_step import FixedStep
from game.sim.tuning import TICK_S
from tests.maps import level_from_ascii

ROOT = Path(__file__).resolve().parent.parent
FRAME_S = 1 / 60


def key(code: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.KEYDOWN, key=code, mod=0, unicode="", scancode=0)




def ticks_at_each_frame(batches: list[list[pygame.event.Event]],
                        monkeypatch: pytest.MonkeyPatch,
                        pictures: list[pygame.Surface] | None = None) -> list[int]:
    """Play a level in the window, feeding it one batch of events per frame, and return the
    tick count the campaign had reached as each frame began (and, into ``pictures``, the
    player's picture then)."""
    level = level_from_ascii(["          ", " P        ", "##########"])
    args = parser().parse_args(["--level", "x.tmx", "--debug", "--ticks", "1000000"])
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), None, args)
    feed = [*batches, [pygame.event.Event(pygame.QUIT)]]
    seen: list[int] = []

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        seen.append(run.campaign.ticks)
        if pictures is not None:
            pictures.append(run.campaign.world.player.image)
        return feed.pop(0)

    monkeypatch.setattr(pygame.event, "get", next_batch)
    assert play_in_window(run) == 0
    return seen


def test_freeze_step_and_the_overlay_switch_drive_the_window_tick_by_tick(
        display: None, monkeypatch: pytest.MonkeyPatch) -> None:
    f1 = key(pygame.K_F1)
    seen = ticks_at_each_frame(
        [[key(FREEZE_KEY)], [], [], [],             # frozen: frames pass, no tick runs
         [key(STEP_KEY)], [],                       # one tick
         [key(STEP_KEY), key(STEP_KEY)], [],        # two presses, two ticks
         [f1], [key(STEP_KEY)], [], [], [], [], [],  # overlay off: play runs, F3 does nothing
         [f1, key(FREEZE_KEY)], [], []],            # on again and frozen
        monkeypatch)
    runs = [b - a for a, b in itertools.pairwise(seen)]
    assert runs[:8] == [0, 0, 0, 0, 1, 0, 2, 0]
    assert sum(runs[8:15]) > 0
    assert runs[15:] == [0, 0, 0]


def test_a_frozen_game_stands_still_on_screen_too(display: None,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    pictures: list[pygame.Surface] = []
    idle_loop_frames = 60  # the player's idle animation changes picture twice a second
    landing: list[list[pygame.event.Event]] = [[] for _ in range(20)]  # drop onto the floor
    seen = ticks_at_each_frame([*landing, [key(FREEZE_KEY)],
                                *([] for _ in range(idle_loop_frames))], monkeypatch, pictures)
    frozen = len(landing) + 1
    assert seen[frozen] > 0 and len(set(seen[frozen:])) == 1
    assert len({id(picture) for picture in pictures[frozen + 1:]}) == 1


def test_effects_age_by_the_ticks_a_frame_runs_so_a_frozen_game_holds_them_too(
        display: None, monkeypatch: pytest.MonkeyPatch) -> None:
    aged: list[float] = []
    advance = Effects.advance

    def recording(effects: Effects, game_s: float) -> None:
        aged.append(game_s)
        advance(effects, game_s)

    monkeypatch.setattr(Effects, "advance", recording)
    seen = ticks_at_each_frame([[], [], [key(FREEZE_KEY)], [], [], [key(STEP_KEY)], []],
                               monkeypatch)
    runs = [b - a for a, b in itertools.pairwise(seen)]
    assert aged == pytest.approx([ticks * TICK_S for ticks in runs])
    assert aged[2:5] == [0.0, 0.0, 0.0] and aged[5] == pytest.approx(TICK_S)


def test_quarter_speed_runs_a_quarter_of_the_ticks_and_f4_unfreezes() -> None:
    control, stepper = TickControl(), FixedStep()
    control.press(FREEZE_KEY, overlay_on=True)
    assert control.press(SLOW_KEY, overlay_on=True) and not control.frozen
    ticks = sum(control.ticks_due(stepper, FRAME_S, overlay_on=True) for _ in range(120))
    assert ticks == 120 * SLOW_SPEED
    control.press(SLOW_KEY, overlay_on=True)
    assert sum(control.ticks_due(stepper, FRAME_S, overlay_on=True) for _ in range(60)) == 60


def test_the_stepping_keys_do_nothing_with_the_overlay_off() -> None:
    control, stepper = TickControl(), FixedStep()
    assert not any(control.press(k, overlay_on=False) for k in (FREEZE_KEY, STEP_KEY, SLOW_KEY))
    assert sum(control.ticks_due(stepper, FRAME_S, overlay_on=False) for _ in range(60)) == 60


def test_the_overlay_and_the_readme_name_the_same_stepping_keys() -> None:
    control = TickControl()
    labels = [key_label(k) for k in (FREEZE_KEY, STEP_KEY, SLOW_KEY)]
    assert labels == ["F2", "F3", "F4"]
    shown = " ".join(control.lines(0))
    assert all(label in shown for label in labels)
    control.press(FREEZE_KEY, overlay_on=True)
    assert "frozen at tick 7" in control.lines(7)
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    controls = readme.split("## Controls", 1)[1].split("\n## ", 1)[0]
    rows = {label: row for row in controls.splitlines() for label in labels
            if re.match(rf"\| {label} \|", row)}
    assert set(rows) == set(labels), "the README's controls table lists each stepping key"


def test_a_screenshot_at_the_end_of_a_window_run_shows_the_panel_the_window_showed(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    panels: list[tuple[float | None, float]] = []

    def recording(target: pygame.Surface, world: object, assets: object, fps: float | None,
                  update_ms: float, lines: object = (), panel: object = None) -> None:
        panels.append((fps, update_ms))

    monkeypatch.setattr(frame_module, "draw_debug", recording)
    monkeypatch.setattr(pygame.event, "get", lambda *_, **__: [])
    level = level_from_ascii(["          ", " P        ", "##########"])
    shot = tmp_path / "shot.png"
    args = parser().parse_args(["--level", "x.tmx", "--debug", "--ticks", "5",
                                "--screenshot", str(shot)])
    assert play_in_window(Run(Campaign(Path("x.tmx"), loader=lambda _: level), None, args)) == 0
    assert shot.is_file()
    fps, update_ms = panels[-1]      # the screenshot's panel: the window's, not "no window"
    assert fps is not None and update_ms > 0
