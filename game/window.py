"""The windowed game: title, play, pause, game over and win screens around the campaign.

Where it sits: above the simulation, beside the headless runner in :mod:`game.app`. It
turns keys into menu choices and held actions, runs the fixed-step loop, and draws.

Screens: the title (Enter starts), playing, paused (Esc or P; Resume, Restart level, Quit to
title), game over and won (Enter returns to the title). A scripted run (``--inputs``) skips
the title and ends at the end of the run, like a headless one.
"""

from __future__ import annotations

import time
from enum import Enum

import pygame

from game.app import EXIT_OK, TARGET_FPS, Run, held_keys
from game.assets import Assets, load_assets
from game.audio import Audio
from game.campaign import Campaign, Outcome
from game.debug_overlay import draw_debug
from game.hud import draw_hud
from game.levels import LevelError
from game.loop import FixedStep
from game.render import draw_world
from game.saves import Attempt, Progress, progress_file
from game.screens import (
    PAUSE_ITEMS,
    draw_error_banner,
    draw_game_over,
    draw_pause,
    draw_title,
    draw_win,
)
from game.settings import Settings, settings_file
from game.watch import FileWatcher

CONFIRM_KEYS = (pygame.K_RETURN, pygame.K_KP_ENTER, pygame.K_SPACE)
PAUSE_KEYS = (pygame.K_ESCAPE, pygame.K_p)


class Screen(Enum):
    TITLE = "title"
    PLAYING = "playing"
    PAUSED = "paused"
    ENDED = "ended"


def render_frame(campaign: Campaign, *, debug: bool, assets: Assets | None = None,
                 frame: int = 0, fps: float = 0.0, update_ms: float = 0.0) -> pygame.Surface:
    """Draw the current state of play on the display surface and return it."""
    target = pygame.display.get_surface()
    assets = assets or load_assets()
    draw_world(target, campaign.world, assets, frame or campaign.ticks)
    draw_hud(target, campaign, assets)
    if debug:
        draw_debug(target, campaign.world, assets, fps, update_ms)
    return target


def play_in_window(run: Run) -> int:
    """The interactive loop; returns when the window closes or a scripted run ends."""
    assets = load_assets()
    clock = pygame.time.Clock()
    stepper = FixedStep()
    scripted = run.script is not None
    screen = Screen.PLAYING if scripted or run.args.level else Screen.TITLE
    debug = bool(run.args.debug)
    selected = 0
    frame = 0
    first_level = run.campaign.world.level.path
    watcher: FileWatcher | None = None
    reload_error: str | None = None
    # The player's own files, read only when a person plays (never a scripted or timed run).
    personal = not scripted and run.args.ticks is None
    settings_store, progress_store = settings_file(), progress_file()
    settings, progress, notice = Settings(), Progress(), None
    if personal:
        settings, settings_problem = settings_store.load(Settings.from_json, Settings)
        progress, progress_problem = progress_store.load(Progress.from_json, Progress)
        notice = settings_problem or progress_problem
    keys = settings.key_codes()
    if settings.fullscreen:
        pygame.display.toggle_fullscreen()
    audio = Audio()  # silent, without a word, when there is no sound card
    audio.set_volume(settings.effects_volume, settings.music_volume)
    attempt = Attempt()
    while True:
        frame_s = clock.tick(TARGET_FPS) / 1000.0
        frame += 1
        # 1. Events: window, overlay, fullscreen, menus.
        for event in pygame.event.get():
            if event.type == pygame.QUIT:
                run.write_outputs(pygame.display.get_surface())
                return EXIT_OK
            if event.type != pygame.KEYDOWN:
                continue
            if event.key == pygame.K_F1:
                debug = not debug
            elif event.key == pygame.K_F11:
                pygame.display.toggle_fullscreen()
                settings.fullscreen = not settings.fullscreen
                if personal:
                    notice = settings_store.save(settings.to_json()) or notice
            elif screen is Screen.TITLE and event.key in CONFIRM_KEYS:
                audio.play("menu")
                run.campaign = Campaign(first_level, run.campaign.tuning, run.campaign.loader)
                screen = Screen.PLAYING
            elif screen is Screen.PLAYING and event.key in PAUSE_KEYS:
                screen, selected = Screen.PAUSED, 0
            elif screen is Screen.PAUSED:
                audio.play("menu")
                if event.key in PAUSE_KEYS:
                    screen = Screen.PLAYING
                elif event.key in (pygame.K_UP, pygame.K_w):
                    selected = (selected - 1) % len(PAUSE_ITEMS)
                elif event.key in (pygame.K_DOWN, pygame.K_s):
                    selected = (selected + 1) % len(PAUSE_ITEMS)
                elif event.key in CONFIRM_KEYS:
                    screen = _choose(run, selected)
            elif screen is Screen.ENDED and event.key in CONFIRM_KEYS:
                screen = Screen.TITLE

        # Reload on save (--watch): a bad save keeps the old level and shows why.
        if run.args.watch:
            path = run.campaign.world.level.path
            if watcher is None or watcher.level_path != path:
                watcher, reload_error = FileWatcher(path), None
            elif watcher.poll(time.monotonic()):
                try:
                    run.campaign.reload(run.campaign.loader(path))
                    reload_error = None
                except LevelError as error:
                    reload_error = str(error)

        # Music plays while playing, holds its place while paused, stops elsewhere.
        if screen is Screen.PLAYING:
            audio.start_music()
        elif screen is Screen.PAUSED:
            audio.pause_music()
        else:
            audio.stop_music()

        # 2. Ticks: as many fixed 1/60 s steps as real time has paid for; each tick's events
        # sound, and a finished level is saved at once.
        if screen is Screen.PLAYING:
            for _ in range(stepper.advance(frame_s)):
                attempt.before_tick(run.campaign)
                events = run.tick(held_keys(keys))
                for tick_event in events:
                    audio.play(tick_event.kind)
                finish = attempt.after_tick(run.campaign, events)
                if finish is not None and personal:
                    progress.record(finish)
                    notice = progress_store.save(progress.to_json()) or notice
                if run.finished():
                    break
            if run.finished():
                if scripted or run.args.ticks is not None:
                    run.write_outputs(render_frame(run.campaign, debug=debug, assets=assets))
                    return EXIT_OK
                screen = Screen.ENDED
        else:
            stepper.advance(0.0)

        # 3. Draw: the world, the HUD, the overlay, then whatever screen is up.
        target = render_frame(run.campaign, debug=debug, assets=assets, frame=frame,
                              fps=clock.get_fps(), update_ms=_last_update_ms(run))
        if reload_error is not None:
            draw_error_banner(target, assets, reload_error)
        elif notice is not None and screen is not Screen.PLAYING:
            draw_error_banner(target, assets, notice)
        if screen is Screen.TITLE:
            draw_title(target, assets, frame)
        elif screen is Screen.PAUSED:
            draw_pause(target, assets, selected)
        elif screen is Screen.ENDED:
            if run.campaign.outcome is Outcome.WON:
                draw_win(target, assets, run.campaign)
            else:
                draw_game_over(target, assets, run.campaign)
        pygame.display.flip()


def _choose(run: Run, selected: int) -> Screen:
    item = PAUSE_ITEMS[selected]
    if item == "Restart level":
        run.campaign.restart_level()
        return Screen.PLAYING
    if item == "Quit to title":
        return Screen.TITLE
    return Screen.PLAYING


def _last_update_ms(run: Run) -> float:
    return run.timing.update_s[-1] * 1000.0 if run.timing.update_s else 0.0
