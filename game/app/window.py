"""The windowed game: title, level select, play, pause, game over and win screens.

Where it sits: above the simulation, beside the headless runner in :mod:`game.app.run`. Each
frame reads the keyboard and any gamepads, runs the fixed-step loop, and draws. What a
press does in a menu is decided in :mod:`game.app.menus` (a small state machine this loop only
feeds and obeys); how pads become actions and menu moves is in :mod:`game.app.gamepad`.

The loop is :class:`GameWindow`: what lasts between frames, and one short method per phase of
a frame, called in order by :meth:`GameWindow.play`: events, reload on save (``--watch``),
music (the title's track in the menus, the place's in play, a jingle when the run ends),
ticks, the level-end banner, draw.

Screens: the title (Play, Level select, Options, Quit), the level select, the options
(:mod:`game.app.options`: applied at once and saved), playing, paused (Esc, P or Start;
Resume, Restart level, Timer, Options, Quit to title), game over (Retry this level, Quit to
title) and won (Enter or A rolls the credits, and Enter or A again returns to the title).
While a level is played, its ghost (:mod:`game.app.ghosts`) is stepped beside it, one tick
for each of the player's, and a best run without an assist becomes the ghost.
Arrows, W/S, the d-pad or the stick move in menus; Enter, Space or A choose; Esc or B
go back. A scripted run (``--inputs``) or one given ``--level`` skips the title; a scripted
run ends at the end of the run, like a headless one (without ``--ticks``, when the script's
level ends, unless ``--go-on``).

The window opens at the largest whole-number scale of the 320x180 screen that takes at most
:data:`DESKTOP_SHARE_PERCENT` of the desktop each way (room for a title bar and a taskbar),
centred on it (:func:`window_scale`, :func:`window_size`, :func:`fit_window`; the lab's window
opens by the same rule); whole numbers keep every pixel square. F11 (or ``fullscreen`` in the
settings) fills the screen instead.
"""

from __future__ import annotations

import time
from dataclasses import replace

import pygame
from pygame._sdl2.video import WINDOWPOS_CENTERED, Window

from game.app.assets import Assets, load_assets
from game.app.audio import TITLE_TRACK, Audio
from game.app.banner import Banner
from game.app.debug_overlay import PANEL_KEY, PanelMode
from game.app.effects import Effects
from game.app.frame import render_frame
from game.app.gamepad import Gamepads, StickEdges, pad_in_use, pad_nav
from game.app.ghosts import Replay, load_replay, recorded, save_ghost
from game.app.menus import (
    ChangeOption,
    Command,
    HeldOver,
    LevelEntry,
    Menus,
    Nav,
    QuitGame,
    RebindKey,
    RestartLevel,
    RetryLevel,
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
from game.app.options import change
from game.app.options_screen import draw_options
from game.app.places import place_of
from game.app.render import WorldRenderer
from game.app.run import EXIT_OK, TARGET_FPS, Run, held_keys
from game.app.saves import Attempt, CampaignMaps, Finish, Progress, progress_file
from game.app.screens import (
    RELOAD_FAILED,
    draw_credits,
    draw_error_banner,
    draw_game_over,
    draw_level_select,
    draw_pause,
    draw_title,
    draw_win,
)
from game.app.settings import DEFAULT_GAME_SPEED, Settings, key_name, settings_file
from game.app.stepping import TickControl
from game.app.watch import FileWatcher
from game.levels import FIRST_LEVEL, LevelError
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Campaign, Outcome
from game.sim.fixed_step import FixedStep
from game.sim.inputs import Actions
from game.sim.sprite import ANIMATION_HZ
from game.sim.world import World

MENU_SCREENS = (Screen.TITLE, Screen.LEVEL_SELECT, Screen.OPTIONS, Screen.CREDITS)  # not the world
STILL_SCREENS = (Screen.PAUSED, Screen.ENDED)  # nothing on them moves by itself
MENU_FPS = 30  # the title and the level select animate at this rate: smooth, half the work
STILL_FPS = 10  # a still screen only waits for input, so it looks for it this often
DESKTOP_SHARE_PERCENT = 90  # the window takes at most this much of the desktop each way
NOT_REBOUND = "Not rebound: "  # before the reason a key chosen on the options is refused


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


def window_size(desktop: tuple[int, int], view: tuple[int, int] = (VIEW_W_PX, VIEW_H_PX)
                ) -> tuple[int, int]:
    """The window for a screen of ``view`` pixels on ``desktop``: the screen at
    :func:`window_scale`. The game (320x180) and the lab (800x450) both open by it.

    >>> window_size((1920, 1080)), window_size((1920, 1080), (800, 450))
    ((1600, 900), (1600, 900))
    """
    scale = window_scale(desktop, view)
    return view[0] * scale, view[1] * scale


def fit_window(window: Window, view: tuple[int, int] = (VIEW_W_PX, VIEW_H_PX)) -> None:
    """Size the window of a screen of ``view`` pixels by :func:`window_size` for the desktop
    it is on and centre it there. (``pygame.SCALED`` alone would fill the whole desktop.)

    ``window`` is ``Window.from_display_module()``, kept for as long as the window is open:
    SDL holds a pointer to that object and hands it to every window event, so letting it be
    collected crashes the next event."""
    desktops = pygame.display.get_desktop_sizes()
    desktop = desktops[window.display_index] if window.display_index < len(desktops) else view
    window.size = window_size(desktop, view)
    window.position = WINDOWPOS_CENTERED


class GameWindow:
    """The window's state between frames, and one method per phase of a frame.

    :meth:`play` runs frames until the window closes; each frame is :meth:`events`,
    :meth:`reload_on_save`, :meth:`music`, :meth:`ticks`, :meth:`advance_banner` and
    :meth:`draw`, in that order (the order :mod:`game.app.run` describes)."""

    def __init__(self, run: Run) -> None:
        self.run = run
        self.assets = load_assets()
        self.renderer = WorldRenderer(self.assets)  # keeps its caches between frames
        self.clock = pygame.time.Clock()
        self.stepper = FixedStep()
        self.stepping = TickControl()  # with the overlay on: freeze, one tick, quarter speed
        self.scripted = run.script is not None
        self.menus = Menus(Screen.PLAYING if self.scripted or run.args.level else Screen.TITLE)
        self.debug = bool(run.args.debug)
        self.panel = PanelMode.COMPACT  # the overlay's panel: F5 cycles compact, full, hidden
        self.frame = 0  # animation frames of the menus, counted at ANIMATION_HZ
        self.watcher: FileWatcher | None = None
        self.reload_error: str | None = None
        # The player's own files, read only when a person plays (never a scripted or timed run).
        self.personal = not self.scripted and run.args.ticks is None
        self.settings_store, self.progress_store = settings_file(), progress_file()
        self.settings, self.progress = Settings(), Progress()
        self.notice: str | None = None  # a problem with the player's files, shown in menus
        if self.personal:
            self.settings, settings_problem = self.settings_store.load(Settings.from_json, Settings)
            self.progress, progress_problem = self.progress_store.load(Progress.from_json, Progress)
            self.notice = settings_problem or progress_problem
        self.keys, self.buttons = self.settings.key_codes(), self.settings.button_numbers()
        self.effects = self.renderer.effects = Effects(shake_on=self.settings.screen_shake)
        self.window = Window.from_display_module()  # held while the window is open (fit_window)
        fit_window(self.window)
        if self.settings.fullscreen:
            pygame.display.toggle_fullscreen()
        self.audio = Audio()  # silent, without a word, when there is no sound card
        self.audio.set_volume(self.settings.effects_volume, self.settings.music_volume)
        self.pads, self.stick_edges, self.held_over = Gamepads(), StickEdges(), HeldOver()
        self.using_pad = False  # the title shows the controls of the device last pressed
        self.levels = campaign_levels(FIRST_LEVEL)  # titles read once; locks, bests each menu frame
        self.campaign_maps = CampaignMaps.of(info.path for info in self.levels)  # saved maps
        self.entries = level_entries(self.levels, self.progress)
        self.attempt = Attempt()
        self.banner: Banner | None = None
        self.rebinding: str | None = None  # the action whose new key the next press sets
        self.replay: Replay | None = None  # the ghost of the level in play, if it has one
        self.replay_world: World | None = None  # the world the ghost was set up for
        self.dirty = True  # a still screen is drawn again after any event (see draw)
        self.last_shown: tuple[Menus, str | None, str | None, bool, PanelMode] | None = None
        self.credits_from = 0  # self.frame when the credits came up: they roll from there

    def play(self) -> int:
        """Run frames until the window closes or a scripted run ends; the exit status."""
        while (status := self.one_frame()) is None:
            pass
        return status

    def one_frame(self) -> int | None:
        """Wait for the frame's time, then run its phases in order; the exit status if the
        frame ends the game (``python -m game.bench.window`` times this call)."""
        frame_s = self.clock.tick(frame_rate(self.menus.screen)) / 1000.0
        self.frame += max(1, round(frame_s * ANIMATION_HZ))  # animations keep time at any rate
        if self.menus.screen is not Screen.PLAYING:  # play reads no row of the level select
            self.entries = level_entries(self.levels, self.progress)
        if (status := self.events()) is not None:
            return status
        self.reload_on_save()
        self.music()
        if (status := self.ticks(frame_s)) is not None:
            return status
        self.advance_banner(frame_s)
        self.draw()
        return None

    def held(self) -> Actions:
        """What the keyboard and the pads hold right now."""
        return held_keys(self.keys) | self.pads.held(self.buttons)

    def save_settings(self) -> None:
        if self.personal:
            self.notice = self.settings_store.save(self.settings.to_json()) or self.notice

    def save_progress(self) -> None:
        if self.personal:
            self.notice = self.progress_store.save(self.progress.to_json()) or self.notice

    def quit(self) -> int:
        """Write what the options ask for (a screenshot of the last frame shown) and end."""
        self.run.write_outputs(pygame.display.get_surface())
        return EXIT_OK

    # 1. Events: the window, pads plugged in or out, overlay and fullscreen, menus.
    def events(self) -> int | None:
        """Handle this frame's events; the exit status if one of them ends the game."""
        for event in pygame.event.get():
            self.dirty = True  # a still screen is drawn again after any event (a key, an expose)
            if event.type == pygame.QUIT:
                return self.quit()
            self.pads.handle(event)
            self.using_pad = pad_in_use(event, self.using_pad)
            if event.type == pygame.KEYDOWN and self.rebinding is not None:
                self.rebind(event.key)
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_F1:
                self.debug = not self.debug
                self.run.campaign.measure.queries = self.debug  # the overlay draws the query log
            elif event.type == pygame.KEYDOWN and self.debug and event.key == PANEL_KEY:
                self.panel = self.panel.next()
            elif event.type == pygame.KEYDOWN and self.stepping.press(event.key,
                                                                      overlay_on=self.debug):
                pass
            elif event.type == pygame.KEYDOWN and event.key == pygame.K_F11:
                self.toggle_fullscreen()
            elif (nav := _nav(event, self.stick_edges, self.menus.screen)) is not None:
                if self.banner is not None and not self.banner.skippable():
                    continue  # a jump held over the exit must not skip the tally unseen
                if self.menu_press(nav):
                    return self.quit()
        return None

    def toggle_fullscreen(self) -> None:
        """F11: fill the screen, or go back to the scaled, centred window; remembered."""
        self.settings.fullscreen = not self.settings.fullscreen
        self.show_fullscreen()
        self.save_settings()

    def show_fullscreen(self) -> None:
        """Make the window match the fullscreen setting."""
        pygame.display.toggle_fullscreen()
        if not self.settings.fullscreen:
            fit_window(self.window)

    def change_option(self, command: ChangeOption) -> None:
        """A press on an options row: change the setting, apply it at once, and save."""
        before, self.settings = self.settings, change(self.settings, command.item,
                                                      command.step)
        self.audio.set_volume(self.settings.effects_volume, self.settings.music_volume)
        if self.settings.fullscreen != before.fullscreen:
            self.show_fullscreen()
        self.apply_assist()
        self.save_settings()

    def apply_assist(self) -> None:
        """Tell the campaign which assists are on (it marks the level it is playing)."""
        self.run.campaign.set_assist(
            no_damage=self.settings.no_damage,
            slowed=self.settings.game_speed < DEFAULT_GAME_SPEED)

    def rebind(self, key: int) -> None:
        """The key pressed after choosing a key row: bind it (Esc keeps the old keys)."""
        action, self.rebinding = self.rebinding, None
        if action is None or key == pygame.K_ESCAPE:
            return
        problem = self.settings.rebind(action, key_name(key))
        if problem is not None:
            self.notice = f"{NOT_REBOUND}{problem}."
            return
        if self.notice is not None and self.notice.startswith(NOT_REBOUND):
            self.notice = None  # the last refusal is answered
        self.keys = self.settings.key_codes()
        self.save_settings()

    def menu_press(self, nav: Nav) -> bool:
        """Move through the menus and obey what they command; True if that is to quit."""
        before = self.menus
        self.menus, command = press(self.menus, nav, self.entries)
        if self.menus != before or command is not None:
            self.audio.play("menu")
        if isinstance(command, QuitGame):
            return True
        if isinstance(command, ToggleTimer):
            self.settings.hud_timer = not self.settings.hud_timer
            self.save_settings()
        elif isinstance(command, ChangeOption):
            self.change_option(command)
        elif isinstance(command, RebindKey):
            self.rebinding = command.action
        elif command is not None and (problem := _obey(command, self.run)) is not None:
            self.menus, self.notice = before, problem  # stay on the menu and say why
        if self.menus.screen is Screen.PLAYING and before.screen is not Screen.PLAYING:
            self.held_over.begin(self.held())
        if self.menus.screen is Screen.CREDITS and before.screen is not Screen.CREDITS:
            self.credits_from = self.frame
        return False

    def reload_on_save(self) -> None:
        """With --watch: reload the level when its file changes; a bad save keeps the old
        level and shows why."""
        if not self.run.args.watch:
            return
        path = self.run.campaign.world.level.path
        if self.watcher is None or self.watcher.level_path != path:
            self.watcher, self.reload_error = FileWatcher(path), None
        elif self.watcher.poll(time.monotonic()):
            try:
                self.run.campaign.reload(self.run.campaign.loader(path))
                self.reload_error = None
            except LevelError as error:
                self.reload_error = str(error)

    def music(self) -> None:
        """The place's music plays while playing and holds its place while paused (and on the
        options screen opened from the pause menu); the title's plays in the menus and the
        credits; none under the level-end banner or an ending (whose jingle plays as it comes
        up, :meth:`end_run`)."""
        screen = self.menus.screen
        if screen is Screen.PLAYING:
            self.audio.start_music(place_of(self.run.campaign.world.level.properties).name)
        elif screen is Screen.PAUSED or (screen is Screen.OPTIONS and
                                         self.menus.options_from is Screen.PAUSED):
            self.audio.pause_music()
        elif screen in MENU_SCREENS:
            self.audio.start_music(TITLE_TRACK)
        else:
            self.audio.stop_music()

    # 2. Ticks: as many fixed 1/60 s steps as real time has paid for, each with what the
    # keyboard and the pads hold; each tick's events sound, and a finished level is saved.
    def ticks(self, frame_s: float) -> int | None:
        """Run the ticks this frame is due; the exit status if a scripted or timed run ends.
        None run in menus, nor under the level-end banner, even in the frame that Enter
        skips it (the banner gives way first, in :meth:`advance_banner`)."""
        if self.menus.screen is not Screen.PLAYING or self.banner is not None:
            self.stepper.advance(0.0)
            return None
        self.apply_assist()  # the game speed assist: real time pays for fewer ticks
        due = self.stepping.ticks_due(
            self.stepper, frame_s * self.settings.game_speed / DEFAULT_GAME_SPEED,
            overlay_on=self.debug)
        # Effects age in game time, by the ticks this frame runs: they stand still in
        # menus and while frozen (F2), and slow down at quarter speed (F4), as sprites do.
        self.effects.advance(due * self.stepper.tick_s)
        for _ in range(due):
            if not self.tick():
                break
        run = self.run
        if run.finished() and (self.scripted or run.args.ticks is not None):
            run.write_outputs(render_frame(
                run.campaign, debug=self.debug, renderer=self.renderer, fps=self.clock.get_fps(),
                update_ms=run.last_update_ms, debug_lines=self.stepping.lines(run.campaign.ticks),
                panel=self.panel, timer=self.settings.hud_timer))
            return EXIT_OK
        if self.banner is not None:
            self.menus = cleared(self.menus)
        elif run.finished():
            self.end_run()
        return None

    def end_run(self) -> None:
        """The run is over: its ending comes up (the win, or game over), with its jingle."""
        won = self.run.campaign.outcome is Outcome.WON
        self.menus = ended(self.menus, won=won)
        self.audio.stop_music()
        self.audio.play("win" if won else "game-over")

    def tick(self) -> bool:
        """One tick with what is held; False when no more ticks should run this frame (the
        level or the run ended, or the next level will not load)."""
        run = self.run
        self.attempt.before_tick(run.campaign)
        finishing = run.campaign.world
        self.follow_ghost(finishing)
        try:
            held = self.held_over.filter(self.held())
            events = run.tick(held)
            self.effects.observe(finishing, events)
        except LevelError as error:  # the next level will not load: say so, go back
            self.menus, self.notice = Menus(), str(error)
            return False
        for tick_event in events:
            self.audio.play(tick_event.kind)
        if self.replay is not None:
            self.replay.step()
        finish = self.attempt.after_tick(run.campaign, events, held)
        if finish is not None:
            self.keep_finish(finish, finishing)
        return not (run.finished() or finish is not None)

    def keep_finish(self, finish: Finish, finishing: World) -> None:
        """Show a finished level's banner; keep a finish of the campaign's own maps in the
        progress, and a best time without an assist as the level's ghost."""
        kept = self.campaign_maps.kept(finish, finishing.level)  # None: not the campaign's
        best = None if kept is None else self.progress.best_ticks.get(finish.level)
        self.banner = Banner(self.run.campaign.results[-1], best, world=finishing)
        if kept is None:
            return
        self.progress.record(kept)
        self.save_progress()
        faster = best is None or finish.ticks < best
        if self.personal and faster and not finish.assisted:
            ghost = recorded(self.attempt.inputs, finish.ticks, finishing.level.path)
            if ghost is not None:
                self.notice = save_ghost(ghost, finish.level) or self.notice

    def follow_ghost(self, world: World) -> None:
        """A level started (or started again): set up its ghost, if the player wants it and
        the level has one made on this map."""
        if world is self.replay_world:
            return
        self.replay_world, self.replay = world, None
        if self.settings.ghost and self.personal and self.campaign_maps.holds(world.level.path):
            self.replay, problem = load_replay(world.level, self.run.campaign.tuning)
            self.notice = problem or self.notice

    # The level-end banner: a pause of the window only; the simulation waits for it.
    def advance_banner(self, frame_s: float) -> None:
        """Advance the banner's tally; when it is done (or skipped), play on or end."""
        if self.banner is None:
            return
        if (sound := self.banner.advance(frame_s)) is not None:
            self.audio.play(sound)
        if self.banner.done() or self.menus.screen is not Screen.CLEARED:
            self.banner = None
            if self.menus.screen is Screen.CLEARED:
                self.menus = replace(self.menus, screen=Screen.PLAYING)
            if self.run.finished():
                self.end_run()
            elif self.menus.screen is Screen.PLAYING:
                self.held_over.begin(self.held())

    # 3. Draw: the world, HUD and overlay (or a menu in their place), then any screen on
    # top, then a problem to report, if there is one.
    def draw(self) -> None:
        """Draw the frame and show it. A still screen (pause, game over, the win) is drawn
        once, and again only after an event or a change of what it shows."""
        shown = (self.menus, self.notice, self.reload_error, self.debug, self.panel)
        if self.menus.screen in STILL_SCREENS and not self.dirty and shown == self.last_shown:
            return
        self.dirty, self.last_shown = False, shown
        target = pygame.display.get_surface()
        campaign = self.run.campaign
        if self.menus.screen not in MENU_SCREENS:
            # Sprites animate by game time: still while paused or frozen, slow when slowed.
            render_frame(campaign, debug=self.debug, renderer=self.renderer,
                         frame=campaign.ticks, fps=self.clock.get_fps(),
                         update_ms=self.run.last_update_ms,
                         world=self.banner.world if self.banner is not None else None,
                         debug_lines=self.stepping.lines(campaign.ticks), panel=self.panel,
                         timer=self.settings.hud_timer, ghost=self.ghost_shown())
        if self.banner is not None:
            self.banner.draw(target, self.assets)
        if self.menus.screen is Screen.OPTIONS:
            draw_options(target, self.assets, self.frame, self.settings,
                         self.menus.options_item, self.rebinding)
        frame = self.frame - (self.credits_from if self.menus.screen is Screen.CREDITS else 0)
        _draw_screen(target, self.assets, self.menus, self.entries, campaign, frame,
                     self.using_pad, self.settings.hud_timer, self.settings.keys)
        if self.reload_error is not None:
            draw_error_banner(target, self.assets, RELOAD_FAILED + self.reload_error)
        elif self.notice is not None and self.menus.screen is not Screen.PLAYING:
            draw_error_banner(target, self.assets, self.notice)
        pygame.display.flip()


    def ghost_shown(self) -> Replay | None:
        """The ghost to draw: the level in play's, when the ghost is on (not under a banner)."""
        on = self.settings.ghost and self.banner is None
        return self.replay if on and self.replay_world is self.run.campaign.world else None


def play_in_window(run: Run) -> int:
    """The interactive loop; returns when the window closes or a scripted run ends."""
    return GameWindow(run).play()


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
        elif isinstance(command, RetryLevel):
            run.campaign.retry_level()
    except LevelError as error:
        return str(error)
    return None


def _draw_screen(target: pygame.Surface, assets: Assets, menus: Menus,
                 entries: tuple[LevelEntry, ...], campaign: Campaign, frame: int,
                 using_pad: bool, timer_on: bool, keys: dict[str, list[str]]) -> None:
    """The screen that is up: a menu in place of the world, or over it."""
    if menus.screen is Screen.TITLE:
        draw_title(target, assets, frame, menus.title_item, entries, pad=using_pad, keys=keys)
    elif menus.screen is Screen.LEVEL_SELECT:
        draw_level_select(target, assets, frame, entries, menus.level_item)
    elif menus.screen is Screen.PAUSED:
        draw_pause(target, assets, menus.pause_item, timer_on=timer_on)
    elif menus.screen is Screen.ENDED:
        if campaign.outcome is Outcome.WON:
            draw_win(target, assets, campaign)
        else:
            draw_game_over(target, assets, campaign, menus.game_over_item)
    elif menus.screen is Screen.CREDITS:
        draw_credits(target, assets, frame)

