"""The windowed game: title, level select, play, pause, game over and win screens.

Where it sits: above the simulation, beside the headless runner in :mod:`game.app.run`. Each
frame reads the keyboard and any gamepads, runs the fixed-step loop, and draws. What a
press does in a menu is decided in :mod:`game.app.menus` (a small state machine this loop only
feeds and obeys); how pads become actions and menu moves is in :mod:`game.app.gamepad`.

Screens: the title (Play, Level select, Quit), the level select, playing, paused (Esc, P or
Start; Resume, Restart level, Quit to title), game over and won (Enter or A returns to the
title). Arrows, W/S, the d-pad or the stick move in menus; Enter, Space or A choose; Esc or B
go back. A scripted run (``--inputs``) or one given ``--level`` skips the title; a scripted
run ends at the end of the run, like a headless one.

The window opens at the largest whole-number scale of the 320x180 screen that takes at most
:data:`DESKTOP_SHARE_PERCENT` of the desktop each way (room for a title bar and a taskbar),
centred on it (:func:`window_scale`, :func:`fit_window`); whole numbers keep every pixel
square. F11 (or ``fullscreen`` in the settings) fills the screen instead.
"""

from __future__ import annotations

import time
from dataclasses import replace

import pygame
from pygame._sdl2.video import WINDOWPOS_CENTERED, Window

from game.app.assets import Assets, load_assets
from game.app.audio import Audio
from game.app.banner import Banner
from game.app.effects import Effects
from game.app.frame import render_frame
from game.app.gamepad import Gamepads, StickEdges, pad_in_use, pad_nav
from game.app.menus import (
    Command,
    HeldOver,
    LevelEntry,
    Menus,
    Nav,
    QuitGame,
    RestartLevel,
    Screen,
    StartLevel,
    ToggleTimer,
    campaign_levels,
    cleared,
    ended,
    key_nav,
    level_entries,
    press,
)
from game.app.render import WorldRenderer
from game.app.run import EXIT_OK, TARGET_FPS, Run, held_keys
from game.app.saves import Attempt, Progress, progress_file
from game.app.screens import (
    RELOAD_FAILED,
    draw_error_banner,
    draw_game_over,
    draw_level_select,
    draw_pause,
    draw_title,
    draw_win,
)
from game.app.settings import Settings, settings_file
from game.app.stepping import TickControl
from game.app.watch import FileWatcher
from game.levels import FIRST_LEVEL, LevelError
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Campaign, Outcome
from game.sim.fixed_step import FixedStep
from game.sim.sprite import ANIMATION_HZ

MENU_SCREENS = (Screen.TITLE, Screen.LEVEL_SELECT)  # drawn instead of the world
STILL_SCREENS = (Screen.PAUSED, Screen.ENDED)  # nothing on them moves by itself
MENU_FPS = 30  # the title and the level select animate at this rate: smooth, half the work
STILL_FPS = 10  # a still screen only waits for input, so it looks for it this often
DESKTOP_SHARE_PERCENT = 90  # the window takes at most this much of the desktop each way


def frame_rate(screen: Screen) -> int:
    """How many frames a second ``screen`` is drawn at: play and the level-end banner at the
    full rate, the animated menus at :data:`MENU_FPS`, still screens at :data:`STILL_FPS`.

    >>> frame_rate(Screen.PLAYING), frame_rate(Screen.TITLE), frame_rate(Screen.PAUSED)
    (60, 30, 10)
    """
    if screen in STILL_SCREENS:
        return STILL_FPS
    return MENU_FPS if screen in MENU_SCREENS else TARGET_FPS


def window_scale(desktop: tuple[int, int], view: tuple[int, int] = (VIEW_W_PX, VIEW_H_PX),
                 share_percent: int = DESKTOP_SHARE_PERCENT) -> int:
    """The largest whole-number scale of ``view`` within ``share_percent`` of ``desktop``
    each way; 1 if even that does not fit.

    >>> [window_scale(d) for d in ((1920, 1080), (1280, 720), (2560, 1440), (800, 600))]
    [5, 3, 7, 2]
    """
    room_w, room_h = (side * share_percent // 100 for side in desktop)
    return max(1, min(room_w // view[0], room_h // view[1]))


def fit_window(window: Window) -> None:
    """Size the window by :func:`window_scale` for the desktop it is on and centre it there.
    (``pygame.SCALED`` alone would fill the whole desktop.)

    ``window`` is ``Window.from_display_module()``, kept for as long as the window is open:
    SDL holds a pointer to that object and hands it to every window event, so letting it be
    collected crashes the next event."""
    desktops = pygame.display.get_desktop_sizes()
    desktop = desktops[window.display_index] if window.display_index < len(desktops) else (
        VIEW_W_PX, VIEW_H_PX)
    scale = window_scale(desktop)
    window.size = (VIEW_W_PX * scale, VIEW_H_PX * scale)
    window.position = WINDOWPOS_CENTERED


def play_in_window(run: Run) -> int:
    """The interactive loop; returns when the window closes or a scripted run ends."""
    assets = load_assets()
    renderer = WorldRenderer(assets)  # keeps the tile caches and sprite group between frames
    clock = pygame.time.Clock()
    stepper = FixedStep()
    stepping = TickControl()  # with the overlay on: freeze, one tick, quarter speed
    scripted = run.script is not None
    menus = Menus(Screen.PLAYING if scripted or run.args.level else Screen.TITLE)
    debug = bool(run.args.debug)
    frame = 0
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
    keys, buttons = settings.key_codes(), settings.button_numbers()
    effects = renderer.effects = Effects(shake_on=settings.screen_shake)
    window = Window.from_display_module()  # held while the window is open (see fit_window)
    fit_window(window)
    if settings.fullscreen:
        pygame.display.toggle_fullscreen()
    audio = Audio()  # silent, without a word, when there is no sound card
    audio.set_volume(settings.effects_volume, settings.music_volume)
    pads, stick_edges, held_over = Gamepads(), StickEdges(), HeldOver()
    using_pad = False  # the title shows the controls of the device last pressed
    levels = campaign_levels(FIRST_LEVEL)  # titles read once; locks and bests read each frame
    attempt = Attempt()
    banner: Banner | None = None
    dirty, last_shown = True, None  # what a still screen last drew (see step 3)
    while True:
        frame_s = clock.tick(frame_rate(menus.screen)) / 1000.0
        frame += max(1, round(frame_s * ANIMATION_HZ))  # animations keep time at any rate
        entries = level_entries(levels, progress)
        # 1. Events: the window, pads plugged in or out, overlay and fullscreen, menus.
        for event in pygame.event.get():
            dirty = True  # a still screen is drawn again after any event (a key, an expose)
            if event.type == pygame.QUIT:
                run.write_outputs(pygame.display.get_surface())
                return EXIT_OK
            pads.handle(event)
            using_pad = pad_in_use(event, using_pad)
            if event.type == pygame.KEYDOWN and event.key == pygame.K_F1:
                debug = not debug
                run.campaign.measure.queries = debug  # the overlay draws the tick's query log
            elif event.type == pygame.KEYDOWN and stepping.press(event.key, overlay_on=debug):
                pass
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_F11:
                pygame.display.toggle_fullscreen()
                settings.fullscreen = not settings.fullscreen
                if not settings.fullscreen:
                    fit_window(window)  # back to the scaled, centred window
                if personal:
                    notice = settings_store.save(settings.to_json()) or notice
            elif (nav := _nav(event, stick_edges, menus.screen)) is not None:
                if banner is not None and not banner.skippable():
                    continue  # a jump held over the exit must not skip the tally unseen
                before = menus
                menus, command = press(menus, nav, entries)
                if menus != before or command is not None:
                    audio.play("menu")
                if isinstance(command, QuitGame):
                    run.write_outputs(pygame.display.get_surface())
                    return EXIT_OK
                if isinstance(command, ToggleTimer):
                    settings.hud_timer = not settings.hud_timer
                    notice = settings_store.save(settings.to_json()) or notice
                elif command is not None and (problem := _obey(command, run)) is not None:
                    menus, notice = before, problem  # stay on the menu and say why
                if menus.screen is Screen.PLAYING and before.screen is not Screen.PLAYING:
                    held_over.begin(held_keys(keys) | pads.held(buttons))

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
        if menus.screen is Screen.PLAYING:
            audio.start_music()
        elif menus.screen is Screen.PAUSED:
            audio.pause_music()
        else:
            audio.stop_music()

        # 2. Ticks: as many fixed 1/60 s steps as real time has paid for, each with what the
        # keyboard and the pads hold; each tick's events sound, and a finished level is saved.
        if menus.screen is Screen.PLAYING:
            due = stepping.ticks_due(stepper, frame_s, overlay_on=debug)
            # Effects age in game time, by the ticks this frame runs: they stand still in
            # menus and while frozen (F2), and slow down at quarter speed (F4), as sprites do.
            effects.advance(due * stepper.tick_s)
            for _ in range(due):
                attempt.before_tick(run.campaign)
                finishing = run.campaign.world
                try:
                    events = run.tick(held_over.filter(held_keys(keys) | pads.held(buttons)))
                    effects.observe(finishing, events)
                except LevelError as error:  # the next level will not load: say so, go back
                    menus, notice = Menus(), str(error)
                    break
                for tick_event in events:
                    audio.play(tick_event.kind)
                finish = attempt.after_tick(run.campaign, events)
                if finish is not None:
                    banner = Banner(run.campaign.results[-1],
                                    progress.best_ticks.get(finish.level), world=finishing)
                    progress.record(finish)
                    if personal:
                        notice = progress_store.save(progress.to_json()) or notice
                if run.finished() or finish is not None:
                    break
            if run.finished() and (scripted or run.args.ticks is not None):
                run.write_outputs(render_frame(
                    run.campaign, debug=debug, renderer=renderer, fps=clock.get_fps(),
                    update_ms=run.last_update_ms, debug_lines=stepping.lines(run.campaign.ticks),
                    timer=settings.hud_timer))
                return EXIT_OK
            if banner is not None:
                menus = cleared(menus)
            elif run.finished():
                menus = ended(menus)
        else:
            stepper.advance(0.0)
        # The level-end banner: a pause of the window only; the simulation waits for it.
        if banner is not None:
            if (sound := banner.advance(frame_s)) is not None:
                audio.play(sound)
            if banner.done() or menus.screen is not Screen.CLEARED:
                banner = None
                if menus.screen is Screen.CLEARED:
                    menus = replace(menus, screen=Screen.PLAYING)
                if run.finished():
                    menus = ended(menus)
                elif menus.screen is Screen.PLAYING:
                    held_over.begin(held_keys(keys) | pads.held(buttons))

        # 3. Draw: the world, HUD and overlay (or a menu in their place), then any screen on
        # top, then a problem to report, if there is one. A still screen (pause, game over,
        # the win) is drawn once, and again only after an event or a change of what it shows.
        shown = (menus, notice, reload_error, debug)
        if menus.screen in STILL_SCREENS and not dirty and shown == last_shown:
            continue
        dirty, last_shown = False, shown
        target = pygame.display.get_surface()
        if menus.screen not in MENU_SCREENS:
            # Sprites animate by game time: still while paused or frozen, slow when slowed.
            render_frame(run.campaign, debug=debug, renderer=renderer,
                         frame=run.campaign.ticks, fps=clock.get_fps(),
                         update_ms=run.last_update_ms,
                         world=banner.world if banner is not None else None,
                         debug_lines=stepping.lines(run.campaign.ticks),
                         timer=settings.hud_timer)
        if banner is not None:
            banner.draw(target, assets)
        _draw_screen(target, assets, menus, entries, run.campaign, frame, using_pad,
                     settings.hud_timer)
        if reload_error is not None:
            draw_error_banner(target, assets, RELOAD_FAILED + reload_error)
        elif notice is not None and menus.screen is not Screen.PLAYING:
            draw_error_banner(target, assets, notice)
        pygame.display.flip()


def _nav(event: pygame.event.Event, stick_edges: StickEdges, screen: Screen) -> Nav | None:
    """The menu move a key or pad event makes on ``screen``, if any."""
    return key_nav(event) or pad_nav(event, stick_edges, playing=screen is Screen.PLAYING)


def _obey(command: Command, run: Run) -> str | None:
    """Carry out a menu's command; a level that will not load is a sentence, not a crash."""
    try:
        if isinstance(command, StartLevel):
            run.campaign = Campaign(command.level, run.campaign.tuning, loader=run.campaign.loader)
        elif isinstance(command, RestartLevel):
            run.campaign.restart_level()
    except LevelError as error:
        return str(error)
    return None


def _draw_screen(target: pygame.Surface, assets: Assets, menus: Menus,
                 entries: tuple[LevelEntry, ...], campaign: Campaign, frame: int,
                 using_pad: bool, timer_on: bool) -> None:
    """The screen that is up: a menu in place of the world, or over it."""
    if menus.screen is Screen.TITLE:
        draw_title(target, assets, frame, menus.title_item, entries, pad=using_pad)
    elif menus.screen is Screen.LEVEL_SELECT:
        draw_level_select(target, assets, frame, entries, menus.level_item)
    elif menus.screen is Screen.PAUSED:
        draw_pause(target, assets, menus.pause_item, timer_on=timer_on)
    elif menus.screen is Screen.ENDED:
        if campaign.outcome is Outcome.WON:
            draw_win(target, assets, campaign)
        else:
            draw_game_over(target, assets, campaign)

