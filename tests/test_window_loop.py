"""The window's frame loop: one short method per phase, the frame rate each screen asks for, a
still screen drawn once, the outputs a window run writes, and F11 remembered. Driven through
the real loop on the dummy video driver, with the events fed in frame by frame and a clock
that reports a steady 1/60 s."""

from __future__ import annotations

import ast
import json
from pathlib import Path

import pygame
import pytest

from game.app import window as window_module
from game.app.audio import SOUND_FOR_EVENT
from game.app.banner import SKIP_AFTER_S
from game.app.cli import parser
from game.app.menus import Screen
from game.app.run import Run
from game.app.saves import CampaignMaps
from game.app.window import MENU_FPS, STILL_FPS, GameWindow, play_in_window
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import Action, InputScript
from game.sim.world import EventKind
from tests.maps import level_from_ascii

ROOT = Path(__file__).resolve().parent.parent
WINDOW_SOURCE = ROOT / "game" / "app" / "window.py"
LONGEST_FUNCTION_LINES = 49
PHASES = ("events", "ticks", "advance_banner", "draw")
FRAME_S = 17 / 1000  # every frame of the steady clock
ASKED_RATES: list[int] = []  # the frame rate each frame asked the clock for
FLOOR = ["            ", " P          ", "############"]


def key(code: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.KEYDOWN, key=code, mod=0, unicode="", scancode=0)


class SteadyClock:
    """A clock whose every frame lasts 1/60 s, and that notes the rate each frame asked for."""

    def tick(self, framerate: int = 0) -> int:
        ASKED_RATES.append(framerate)
        return 17

    def get_fps(self) -> float:
        return 60.0


class Frames:
    """What the loop did frame by frame: the campaign's tick count as each frame began and
    how many times the picture was shown."""

    def __init__(self) -> None:
        self.ticks: list[int] = []
        self.flips = 0
        self.flips_by_frame: list[int] = []




def play(batches: list[list[pygame.event.Event]], monkeypatch: pytest.MonkeyPatch,
         options: list[str], script: InputScript | None = None,
         end_with_quit: bool = True) -> tuple[int, Frames, Run]:
    """Play a flat level in the window with ``options``, one batch of events a frame."""
    level = level_from_ascii(FLOOR)
    args = parser().parse_args(["--level", "x.tmx", *options])
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), script, args)
    feed = [*batches, *([[pygame.event.Event(pygame.QUIT)]] if end_with_quit else [])]
    frames = Frames()
    flip = pygame.display.flip

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        frames.ticks.append(run.campaign.ticks)
        frames.flips_by_frame.append(frames.flips)
        return feed.pop(0) if feed else []

    def counted_flip() -> None:
        frames.flips += 1
        flip()

    ASKED_RATES.clear()
    monkeypatch.setattr(pygame.event, "get", next_batch)
    monkeypatch.setattr(pygame.display, "flip", counted_flip)
    monkeypatch.setattr(pygame.time, "Clock", SteadyClock)
    return play_in_window(run), frames, run


def test_each_phase_of_a_frame_is_a_method_and_no_function_reaches_fifty_lines() -> None:
    tree = ast.parse(WINDOW_SOURCE.read_text(encoding="utf-8"))
    loop = next(node for node in tree.body
                if isinstance(node, ast.ClassDef) and node.name == GameWindow.__name__)
    methods = {node.name for node in loop.body if isinstance(node, ast.FunctionDef)}
    assert set(PHASES) <= methods
    lengths = {node.name: node.end_lineno - node.lineno + 1 for node in ast.walk(tree)
               if isinstance(node, ast.FunctionDef) and node.end_lineno is not None}
    too_long = {name: n for name, n in lengths.items() if n > LONGEST_FUNCTION_LINES}
    assert too_long == {}, f"functions of the window loop of 50 lines or more: {too_long}"


def test_play_paces_at_60_a_pause_at_10_and_draws_the_still_pause_screen_once(
        display: None, monkeypatch: pytest.MonkeyPatch) -> None:
    esc = key(pygame.K_ESCAPE)
    status, frames, _ = play([[], [esc], [], [], [], [esc], [], []], monkeypatch,
                             ["--ticks", "1000000"])
    assert status == 0
    # The rate a frame asks for is that of the screen it begins on.
    assert ASKED_RATES[:8] == [60, 60, STILL_FPS, STILL_FPS, STILL_FPS, STILL_FPS, 60, 60]
    runs = [b - a for a, b in zip(frames.ticks, frames.ticks[1:], strict=False)]
    assert runs[0] > 0 and runs[1] == 0  # the frame with Esc pauses before its ticks
    assert runs[2:5] == [0, 0, 0]        # nothing moves while paused
    assert runs[6] > 0                   # Esc again plays on
    shown = [b - a for a, b in zip(frames.flips_by_frame, frames.flips_by_frame[1:],
                                   strict=False)]
    assert shown[:7] == [1, 1, 0, 0, 0, 1, 1]  # the pause screen is shown once, then left be


def test_the_title_animates_at_the_menu_rate(display: None,
                                            monkeypatch: pytest.MonkeyPatch,
                                            tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))  # a person's run reads their files
    level = level_from_ascii(FLOOR)
    args = parser().parse_args([])
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), None, args)
    feed: list[list[pygame.event.Event]] = [[], [], [pygame.event.Event(pygame.QUIT)]]
    monkeypatch.setattr(pygame.event, "get", lambda *_, **__: feed.pop(0))
    monkeypatch.setattr(pygame.time, "Clock", SteadyClock)
    ASKED_RATES.clear()
    assert play_in_window(run) == 0
    assert ASKED_RATES == [MENU_FPS] * 3
    assert run.campaign.ticks == 0  # the title runs no ticks


def test_a_scripted_window_run_ends_at_its_last_tick_and_writes_every_output(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    text = "0 +right\n20 -right\n25 +jump\n"
    script = InputScript.parse(text, "walk.txt")
    record, report, shot = tmp_path / "rec.txt", tmp_path / "report.json", tmp_path / "shot.png"
    status, _, run = play([], monkeypatch, [
        "--ticks", "40", "--record", str(record), "--report", str(report),
        "--screenshot", str(shot)], script=script, end_with_quit=False)
    assert status == 0 and run.campaign.ticks == 40
    recorded = InputScript.parse(record.read_text(encoding="utf-8"), "rec.txt")
    fresh = InputScript.parse(text, "walk.txt")  # a script is read once, forwards
    held = [recorded.held_at(t) for t in range(40)]
    assert held == [fresh.held_at(t) for t in range(40)]
    assert Action.RIGHT in held[19] and Action.RIGHT not in held[20] and Action.JUMP in held[30]
    assert json.loads(report.read_text(encoding="utf-8"))["ticks"] == 40
    assert pygame.image.load(str(shot)).get_size() == pygame.display.get_surface().get_size()


def test_closing_the_window_mid_run_writes_the_run_so_far(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    report = tmp_path / "report.json"
    status, frames, run = play([[], [], []], monkeypatch,
                               ["--ticks", "1000000", "--report", str(report)])
    assert status == 0 and 0 < run.campaign.ticks < 1000000
    assert json.loads(report.read_text(encoding="utf-8"))["ticks"] == run.campaign.ticks
    assert frames.ticks[-1] == run.campaign.ticks  # the closing frame ran no tick


def test_f11_toggles_fullscreen_and_a_person_s_settings_remember_it(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    toggles: list[int] = []

    def toggle() -> int:
        toggles.append(1)
        return 1

    monkeypatch.setattr(pygame.display, "toggle_fullscreen", toggle)
    fitted: list[object] = []
    monkeypatch.setattr(window_module, "fit_window", fitted.append)
    f11 = key(pygame.K_F11)
    status, _, _ = play([[f11]], monkeypatch, [])  # no --ticks: a person playing
    assert status == 0 and len(toggles) == 1
    saved = json.loads((tmp_path / "tile-hopper" / "settings.json").read_text("utf-8"))
    assert saved["fullscreen"] is True
    assert len(fitted) == 1  # at the start only: going fullscreen does not refit
    status, _, _ = play([[f11]], monkeypatch, [])  # starts fullscreen, F11 goes back
    assert len(toggles) == 3 and len(fitted) == 3  # fitted at the start and on the way back
    saved = json.loads((tmp_path / "tile-hopper" / "settings.json").read_text("utf-8"))
    assert saved["fullscreen"] is False


def test_a_timed_run_leaves_a_person_s_settings_alone(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    monkeypatch.setattr(pygame.display, "toggle_fullscreen", lambda: 1)
    status, _, _ = play([[key(pygame.K_F11)]], monkeypatch, ["--ticks", "1000000"])
    assert status == 0 and not (tmp_path / "tile-hopper").exists()


def test_the_level_end_banner_holds_the_simulation_and_enter_skips_it_only_after_a_moment(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    monkeypatch.setattr(window_module, "held_keys", lambda *_: frozenset({Action.RIGHT}))
    monkeypatch.setattr(pygame.time, "Clock", SteadyClock)
    level = level_from_ascii([" P D ", "#####"])
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), None,
              parser().parse_args(["--level", "x.tmx"]))  # a person playing: progress is kept
    game = GameWindow(run)
    game.campaign_maps = CampaignMaps.of([level.path])  # as if it were the campaign's own map
    seen: list[tuple[Screen, int]] = []
    enter = key(pygame.K_RETURN)
    skip_at = round(SKIP_AFTER_S / FRAME_S) + 10  # a frame well after the banner may be skipped

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        seen.append((game.menus.screen, run.campaign.ticks))
        cleared = [ticks for screen, ticks in seen if screen is Screen.CLEARED]
        assert len(seen) < 600, "the level never ended"
        if game.menus.screen is Screen.ENDED:
            return [pygame.event.Event(pygame.QUIT)]
        return [enter] if len(cleared) in (1, skip_at) else []

    monkeypatch.setattr(pygame.event, "get", next_batch)
    assert game.play() == 0
    cleared_ticks = [ticks for screen, ticks in seen if screen is Screen.CLEARED]
    assert len(cleared_ticks) == skip_at      # the first Enter came too soon; the second skipped
    assert len(set(cleared_ticks)) == 1       # no tick ran under the banner
    assert seen[-1][0] is Screen.ENDED and run.campaign.outcome is Outcome.WON
    progress = json.loads((tmp_path / "tile-hopper" / "progress.json").read_text("utf-8"))
    assert progress != {} and str(cleared_ticks[0]) in json.dumps(progress)


class Speakers:
    """Stands in for the window's Audio: notes what it was asked to play, in order."""

    def __init__(self) -> None:
        self.heard: list[str] = []

    def play(self, sound: EventKind | str) -> None:
        name = SOUND_FOR_EVENT.get(sound) if isinstance(sound, EventKind) else sound
        if name not in (None, "menu", "tally"):
            self.heard.append(str(name))

    def start_music(self, track: str = "title") -> None:
        music = [heard for heard in self.heard if heard.startswith("music:")]
        if not music or music[-1] != f"music:{track}":
            self.heard.append(f"music:{track}")

    def pause_music(self) -> None:
        pass

    def stop_music(self) -> None:
        self.start_music("off")

    def close(self) -> None:
        pass


def ending(rows: list[str], monkeypatch: pytest.MonkeyPatch, tmp_path: Path, held: Action | None,
           answer: list[tuple[Screen, int]]) -> tuple[GameWindow, list[Screen], Speakers]:
    """Play ``rows`` holding ``held`` until the run ends; press each key of ``answer`` in
    turn, in a frame when its screen is up; close the window on the title after the last.
    The window, the screens seen frame by frame and what its speakers were asked."""
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path))
    monkeypatch.setattr(window_module, "held_keys",
                        lambda *_: frozenset({held} if held else set()))
    monkeypatch.setattr(pygame.time, "Clock", SteadyClock)
    level = level_from_ascii(rows)
    run = Run(Campaign(Path("x.tmx"), loader=lambda _: level), None,
              parser().parse_args(["--level", "x.tmx"]))
    game = GameWindow(run)
    speakers = Speakers()
    game.audio = speakers  # type: ignore[assignment]
    seen: list[Screen] = []

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        screen = game.menus.screen
        seen.append(screen)
        assert len(seen) < 1200, "the run never ended"
        if answer and answer[0][0] is screen:
            return [key(answer.pop(0)[1])]
        return [pygame.event.Event(pygame.QUIT)] if screen is Screen.TITLE else []

    monkeypatch.setattr(pygame.event, "get", next_batch)
    assert game.play() == 0
    return game, seen, speakers


def test_the_win_plays_its_jingle_and_enter_rolls_the_credits_to_the_title_music(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    _, seen, speakers = ending([" P D ", "#####"], monkeypatch, tmp_path, Action.RIGHT,
                                  [(Screen.ENDED, pygame.K_RETURN),
                                   (Screen.CREDITS, pygame.K_DOWN),
                                   (Screen.CREDITS, pygame.K_RETURN)])
    assert [s for n, s in enumerate(seen) if n == 0 or seen[n - 1] is not s] == [
        Screen.PLAYING, Screen.CLEARED, Screen.ENDED, Screen.CREDITS, Screen.TITLE]
    assert speakers.heard == ["music:meadow", "clear", "music:off", "win", "music:title"]


def test_game_over_plays_its_jingle_and_retry_plays_the_level_again_with_its_music(
        display: None, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    game, seen, speakers = ending([" P ", "   ", "   "], monkeypatch, tmp_path, None,
                                  [(Screen.ENDED, pygame.K_RETURN),
                                   (Screen.PLAYING, pygame.K_p),
                                   (Screen.PAUSED, pygame.K_UP),
                                   (Screen.PAUSED, pygame.K_RETURN)])
    assert seen.index(Screen.ENDED) < seen.index(Screen.PAUSED)  # played on after the retry
    assert game.run.campaign.lives == game.run.campaign.tuning.start_lives
    assert speakers.heard == ["music:meadow", "hurt", "hurt", "hurt", "music:off", "game-over",
                              "music:meadow", "music:title"]
