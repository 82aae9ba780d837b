"""Running the game: headless for scripts and tests, or in a window for people.

Where it sits: in the app, under :mod:`game.app.cli`, which hands it the options and the
window loop to use. It owns the files a run writes and, with :mod:`game.app.window`, the clock,
the keyboard (and, through :mod:`game.app.gamepad`, the pads); the simulation below never sees
any of them.

A frame in the window (:mod:`game.app.window`), in order:

1. **Events**: quit, pads plugged in or out, F1 (debug overlay), F2-F4 (with the overlay
   on: freeze, one tick, quarter speed; :mod:`game.app.stepping`), F5 (with the overlay on:
   its panel compact, full or hidden), F11 (fullscreen), and
   menu presses from keys and pads (:mod:`game.app.menus`).
2. **Ticks**: the fixed-step loop (:mod:`game.sim.fixed_step`) says how many 1/60 s ticks are
   due (none while frozen, one per F3, fewer at a game speed under 100 %, an assist);
   each one reads the held actions (keyboard and pads together, or the script) and calls
   ``Campaign.tick``.
3. **Banner**: a finished level's tally counts up while the simulation waits for it.
4. **Draw**: world, HUD, the debug overlay if on, then any screen (title, pause, ...).

Headless runs skip 1, 3 and 4 and step as fast as the machine allows. A headless run
without ``--ticks`` first says on standard output what it will run (:func:`announcement`).
A run given an input script and no ``--ticks`` plays that script's level alone: it ends when
the level is won or lost, unless ``--go-on`` asks it to play on into the levels after it.
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

import pygame

from game.app.clashes import clashes, level_inputs
from game.app.display import EXIT_NO_WINDOW, GAME_INSTEAD, GAME_WINDOW, open_window
from game.app.files import (
    FileProblem,
    output_problem,
    read_small_text,
    save_image,
    shown,
    write_text_atomically,
)
from game.app.frame import render_frame
from game.app.report import Timing, build_report
from game.levels import FIRST_LEVEL, LevelError, load_level
from game.levels.budget import MAX_LEVELS_PER_RUN
from game.levels.closed_output import say
from game.levels.errors import escaped
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import NOTHING, Action, Actions, InputScript, InputScriptError, Recorder
from game.sim.level import Level
from game.sim.world import Event, Measure

HEADLESS_TICK_LIMIT = 60 * 60 * 60  # ticks: an hour of game time, so a run with no --ticks ends
TARGET_FPS = 60
EXIT_OK, EXIT_BAD_FILE, EXIT_USAGE = 0, 1, 2
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what shells report for a program stopped by Ctrl-C
MAX_SCRIPT_BYTES = 4 * 1024 * 1024  # an input script: 300,000 events or more
OUTPUT_OPTIONS = ("record", "report", "screenshot")

KEYS: dict[Action, tuple[int, ...]] = {
    Action.LEFT: (pygame.K_LEFT, pygame.K_a),
    Action.RIGHT: (pygame.K_RIGHT, pygame.K_d),
    Action.UP: (pygame.K_UP, pygame.K_w),
    Action.DOWN: (pygame.K_DOWN, pygame.K_s),
    Action.JUMP: (pygame.K_SPACE, pygame.K_z, pygame.K_UP, pygame.K_w),
}


def held_keys(bindings: Mapping[Action, tuple[int, ...]] = KEYS) -> Actions:
    """The actions whose keys are down right now (the pads' are :meth:`Gamepads.held`)."""
    pressed = pygame.key.get_pressed()
    return frozenset(a for a, keys in bindings.items() if any(pressed[k] for k in keys))


def input_script(path: Path) -> InputScript:
    """The input script at ``path``, read through the one bounded open; FileProblem if it
    cannot be read, InputScriptError naming the line if a line is bad."""
    return InputScript.parse(read_small_text(path, MAX_SCRIPT_BYTES, "the input script"),
                             shown(path))


def level_label(path: Path) -> str:
    """A level's path as the report shows it: relative to the working folder when inside it."""
    if not path.is_absolute():
        return path.as_posix()
    try:
        return path.relative_to(Path.cwd()).as_posix()
    except (ValueError, OSError):  # elsewhere, or the working folder has been deleted
        return path.as_posix()


def fail(message: str, status: int) -> int:
    print(message, file=sys.stderr)
    return status


@dataclass
class Run:
    """What every kind of run shares: the campaign, the input source and what to write."""

    campaign: Campaign
    script: InputScript | None
    args: argparse.Namespace
    recorder: Recorder = field(default_factory=Recorder)
    timing: Timing = field(default_factory=Timing)
    output_failed: bool = False  # a --record, --report or --screenshot could not be written

    def __post_init__(self) -> None:
        self.recorder.keep = getattr(self.args, "record", None) is not None  # else no history

    def tick(self, player: Actions = NOTHING) -> list[Event]:
        """One simulation tick with input from the script, else what the player holds."""
        held = self.script.held_at(self.campaign.ticks) if self.script else player
        self.recorder.observe(self.campaign.ticks, held)
        started = time.perf_counter()
        events = self.campaign.tick(held)
        self.timing.add(time.perf_counter() - started, self.campaign.world.stats.collision_s)
        return events

    @property
    def last_update_ms(self) -> float:
        """How long the last tick took, for the debug overlay (0 before the first)."""
        return self.timing.last_update_s * 1000.0

    def finished(self) -> bool:
        ticks = self.args.ticks
        return (self.campaign.outcome is not Outcome.RUNNING
                or (ticks is not None and self.campaign.ticks >= ticks))

    def write_outputs(self, frame: pygame.Surface | None) -> None:
        """Write what the options ask for; a file that cannot be written is one sentence on
        stderr (and exit status 1), and the others are still written."""
        writes: list[Callable[[], None]] = []
        if self.args.record:
            text = self.recorder.text()
            writes.append(lambda: write_text_atomically(self.args.record, text))
        if self.args.report:
            report = build_report(self.campaign, level_label(self.campaign.world.level.path),
                                  self.timing)
            text_report = json.dumps(report, indent=2) + "\n"
            writes.append(lambda: write_text_atomically(self.args.report, text_report))
        if self.args.screenshot and frame is not None:
            writes.append(lambda: save_image(frame, self.args.screenshot))
        for write in writes:
            try:
                write()
            except (FileProblem, pygame.error) as error:
                print(error, file=sys.stderr)
                self.output_failed = True


def _output_problems(args: argparse.Namespace) -> list[str]:
    """Every output option whose path cannot take a file, before the run starts."""
    return [f"--{option}: {problem}" for option in OUTPUT_OPTIONS
            if (path := getattr(args, option)) is not None
            and (problem := output_problem(path)) is not None]


def _too_late(script: InputScript, text: str, args: argparse.Namespace) -> str | None:
    """The sentence refusing a script whose last event comes after the end of a headless
    run without ``--ticks`` (:data:`HEADLESS_TICK_LIMIT`), else None: the run would end
    before the script does, so the script cannot be what was meant."""
    if not script.events or script.events[-1].tick < HEADLESS_TICK_LIMIT:
        return None
    last = script.events[-1].tick
    lines = text.removeprefix("\ufeff").splitlines()
    number = next((n for n in range(len(lines), 0, -1)
                   if lines[n - 1].split("#", 1)[0].strip()), len(lines))
    return (f"{escaped(shown(args.inputs))}: line {number}: tick {last:,} comes after the end "
            f"of a headless run without --ticks ({HEADLESS_TICK_LIMIT:,} ticks, "
            f"{_game_time(HEADLESS_TICK_LIMIT)} of game time) — give --ticks N to run that "
            "long, or check the tick")


def _game_time(ticks: int) -> str:
    """``ticks`` as game time, in hours from an hour up, else in seconds.

    >>> _game_time(HEADLESS_TICK_LIMIT), _game_time(90)
    ('1 h', '1.5 s')
    """
    seconds = ticks / TARGET_FPS
    return f"{seconds / 3600:g} h" if seconds >= 3600 else f"{seconds:g} s"


def levels_to_play(args: argparse.Namespace) -> int | None:
    """How many levels the run plays: one, the script's own, for a run given an input script
    and neither ``--ticks`` nor ``--go-on``; else None, every level ``next_level`` leads to."""
    scripted_alone = args.inputs is not None and args.ticks is None
    return 1 if scripted_alone and not getattr(args, "go_on", False) else None


def announcement(args: argparse.Namespace, first_level: Path, program: str) -> str:
    """The line a headless run without ``--ticks`` starts with: what it will play, with what
    input, and until when.

    >>> args = argparse.Namespace(inputs=Path("win.txt"), ticks=None, go_on=False)
    >>> line = announcement(args, Path("levels/a.tmx"), "python -m game")
    >>> line.split(" — ")  # doctest: +NORMALIZE_WHITESPACE
    ['python -m game: playing levels/a.tmx with the input script win.txt until that level is
      won or every life is lost, for at most 216,000 ticks (1 h of game time)',
     'give --go-on to play on into the levels after it, or --ticks N to stop at tick N']
    """
    level = escaped(level_label(first_level))
    limit = (f"for at most {HEADLESS_TICK_LIMIT:,} ticks ({_game_time(HEADLESS_TICK_LIMIT)} "
             "of game time)")
    if args.inputs is None:
        return (f"{program}: playing {level} and the levels after it with no input held, until "
                f"the last is won or every life is lost, {limit} — give --ticks N to stop at "
                "tick N")
    script = escaped(shown(args.inputs))
    if levels_to_play(args) is None:
        return (f"{program}: playing {level} and the levels after it with the input script "
                f"{script}, until the last is won or every life is lost, {limit} — give "
                "--ticks N to stop at tick N")
    return (f"{program}: playing {level} with the input script {script} until that level is "
            f"won or every life is lost, {limit} — give --go-on to play on into the levels "
            "after it, or --ticks N to stop at tick N")


def _clashes(args: argparse.Namespace, level: Level) -> list[str]:
    """Every output that names a file the run reads (the level, a file it uses, the input
    script) or the same file as another output; asked before the first tick."""
    outputs = [(option, path) for option in OUTPUT_OPTIONS
               if (path := getattr(args, option)) is not None]
    if not outputs:
        return []
    inputs = level_inputs(level, given=args.level is not None)
    if args.inputs is not None:
        inputs.append(("the input script (--inputs)", args.inputs))
    return clashes(outputs, inputs)


def _open_display(headless: bool, program: str) -> str | None:
    """Start the display: the game's window, or a hidden one for a headless screenshot.
    None when it is open, else the sentence to end with (see :mod:`game.app.display`)."""
    from game.sim.camera import VIEW_H_PX, VIEW_W_PX
    pygame.font.init()
    if not headless:
        return open_window(program, GAME_WINDOW, (VIEW_W_PX, VIEW_H_PX), GAME_INSTEAD)
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX))
    return None


def run(args: argparse.Namespace, play_in_window: Callable[[Run], int],
        program: str = "python -m game") -> int:
    """Run the game as the options ask, in a window through ``play_in_window`` unless
    headless; return the exit status. ``program`` is how a sentence on stderr names it."""
    problems = _output_problems(args)
    if problems:
        return fail("\n".join(problems), EXIT_BAD_FILE)
    script: InputScript | None = None
    if args.inputs:
        try:
            text = read_small_text(args.inputs, MAX_SCRIPT_BYTES, "the input script",
                                   pipes=True)
            script = InputScript.parse(text, shown(args.inputs))
        except FileProblem as error:
            return fail(str(error), EXIT_BAD_FILE)
        except InputScriptError as error:
            return fail(str(error), EXIT_USAGE)
        if args.headless and args.ticks is None and (late := _too_late(script, text, args)):
            return fail(late, EXIT_USAGE)
    first_level = args.level or FIRST_LEVEL
    needs_pictures = not args.headless or args.screenshot is not None
    if needs_pictures and (problem := _open_display(args.headless, program)) is not None:
        pygame.quit()
        return fail(problem, EXIT_NO_WINDOW)

    def loader(path: Path) -> Level:
        return load_level(path, images=needs_pictures)

    game_run: Run | None = None
    try:
        # The report's max_penetration_px is measured only when a report is written; the
        # overlay's query log is kept only while the overlay is on.
        measure = Measure(penetration=args.report is not None, queries=bool(args.debug))
        campaign = Campaign(first_level, loader=loader, measure=measure,
                            levels_to_play=levels_to_play(args))
        if clashing := _clashes(args, campaign.world.level):
            return fail("\n".join(clashing), EXIT_BAD_FILE)
        game_run = Run(campaign, script, args)
        if args.headless and args.ticks is None:
            say(announcement(args, first_level, program))
        status = run_headless(game_run) if args.headless else play_in_window(game_run)
        return EXIT_BAD_FILE if game_run.output_failed else status
    except LevelError as error:
        return fail(str(error), EXIT_BAD_FILE)
    except KeyboardInterrupt:  # Ctrl-C: keep what the run has done so far
        if game_run is not None and not args.headless:
            game_run.write_outputs(None)
        print("stopped by Ctrl-C", file=sys.stderr)
        return EXIT_INTERRUPTED
    finally:
        pygame.quit()


def run_headless(game_run: Run) -> int:
    """Step without a window until the run ends; render one frame if a screenshot is asked.

    Ctrl-C ends the run early, and its report, recording and screenshot are still written
    (exit status 130)."""
    limit = game_run.args.ticks if game_run.args.ticks is not None else HEADLESS_TICK_LIMIT
    levels = MAX_LEVELS_PER_RUN if game_run.args.ticks is None else None
    status = EXIT_OK
    try:
        while not game_run.finished() and game_run.campaign.ticks < limit:
            game_run.tick()
            if levels is not None and game_run.campaign.levels_completed >= levels:
                level = game_run.campaign.world.level.path
                print(f"{escaped(shown(level))}: {levels:,} levels were completed in one run "
                      "without --ticks, so the levels' next_level properties must go round "
                      "in a circle of levels won at once — give --ticks N to play it anyway, "
                      "or check next_level and the Exits", file=sys.stderr)
                status = EXIT_BAD_FILE
                break
    except KeyboardInterrupt:
        status = EXIT_INTERRUPTED
    if status == EXIT_OK and not game_run.finished() and game_run.campaign.ticks >= limit:
        print(f"the run stopped after {limit:,} ticks ({_game_time(limit)} of game time), "
              "the end of a headless run without --ticks — give --ticks N to run longer",
              file=sys.stderr)
    frame = None
    if game_run.args.screenshot:
        frame = render_frame(game_run.campaign, debug=game_run.args.debug,
                             update_ms=game_run.last_update_ms)
    game_run.write_outputs(frame)
    if status == EXIT_INTERRUPTED:
        print("stopped by Ctrl-C; the report and recording hold the run so far",
              file=sys.stderr)
    return status
