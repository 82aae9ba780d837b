"""``python -m game.bench.window``: a frame of play in a real window, beside a bare window's.

Where it sits: beside the bench's charts, on its own, like :mod:`game.bench.drawing`, but in
a window a display shows: the game's own (:class:`game.app.window.GameWindow`, playing the
first level, standing at the spawn) and, in the same window and the same run, the cheapest
frame any pygame game with a ``SCALED`` window pays for: a 320x180 picture blitted, the
events read, the window flipped, at 60 frames a second. It measures both at the two sizes
the game's window takes on common desktops (:data:`SIZES`: 960x540 on 1280x720, 1600x900 on
1920x1080). Where there is no display it starts its own under ``Xvfb`` (an X server that
draws into memory), and where there is no ``Xvfb`` either it says so and skips.

What it teaches:
  * **The floor is the window itself.** Scaling 320x180 up to the window and showing it costs
    the same whatever was drawn; what the game adds on top (its events, its tick, its world
    and HUD) is what it can make cheaper. So the figure is a ratio to that floor, not a time.
  * **CPU time, not wall time, and side by side.** Each round runs :data:`FRAMES_PER_ROUND`
    frames of each, one after the other (which first alternates), each costed as this
    process's CPU time (``time.process_time``: every thread of it, SDL's included), so a
    busy machine slows both alike; the ratio's 95 % interval comes from the rounds
    (:func:`game.bench.intervals.paired_ratio`), and the target passes only when the whole
    interval is at most :data:`MAX_RATIO`.
  * **Sound is left out.** The mixer is closed for the measurement: the bare window plays
    nothing, and a sound card's cost is not the frame's.
"""

from __future__ import annotations

import argparse
import contextlib
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from statistics import median

from game.app.arguments import Parser, run_command, whole_number
from game.bench.intervals import Interval, paired_ratio
from game.bench.timing import collector_off
from game.levels.closed_output import say

PROGRAM = "python -m game.bench.window"
SIZES = ((960, 540), (1600, 900))  # the game's window on a 1280x720 and a 1920x1080 desktop
XVFB_SCREEN = "1920x1080x24"  # the X server made where there is no display: room for both
XVFB_START_S = 10.0  # an Xvfb that has not said its display number by then is not coming
FRAMES_PER_ROUND = 60  # one second of frames at 60 a second, of each kind, per round
ROUNDS = 10
WARM_UP_FRAMES = 30  # drawn before the first round: caches filled, the window shown
MAX_RATIO = 1.3  # a frame of play costs at most this many times the bare frame's CPU time
MS_PER_S = 1000.0
BIG_TICKS = 10**9  # the run's --ticks: never reached, and no player's files are touched
EXIT_PASSED, EXIT_OVER = 0, 3  # a size measured by a child: within the target, or over it


@dataclass(frozen=True)
class WindowCost:
    """One window size: median CPU milliseconds per frame of each kind, and their ratio."""

    size: tuple[int, int]
    play_ms: float
    bare_ms: float
    ratio: Interval
    rounds: int

    @property
    def passed(self) -> bool:
        return self.ratio.clears("<=", MAX_RATIO)

    def line(self) -> str:
        w, h = self.size
        verdict = "pass" if self.passed else "FAIL"
        return (f"{w}x{h}: a frame of play {self.play_ms:.2f} ms of CPU, the bare SCALED "
                f"blit and flip {self.bare_ms:.2f} ms: {self.ratio.text()}x over "
                f"{self.rounds} rounds (at most {MAX_RATIO:g}x: {verdict})")


def measure(size: tuple[int, int], rounds: int = ROUNDS, frames: int = FRAMES_PER_ROUND,
            warm_up: int = WARM_UP_FRAMES) -> WindowCost:
    """Open the game's window at ``size`` on the display there is, draw ``warm_up`` frames,
    then cost ``rounds`` rounds of ``frames`` frames of play and of the bare window, side
    by side."""
    import pygame

    from game.app.audio import Audio
    from game.app.display import GAME_INSTEAD, GAME_WINDOW, open_window
    from game.app.run import TARGET_FPS, Run
    from game.app.window import GameWindow
    from game.levels import FIRST_LEVEL, load_level
    from game.sim.camera import VIEW_H_PX, VIEW_W_PX
    from game.sim.campaign import Campaign

    pygame.font.init()
    problem = open_window(PROGRAM, GAME_WINDOW, (VIEW_W_PX, VIEW_H_PX), GAME_INSTEAD)
    if problem is not None:
        raise RuntimeError(problem)
    try:
        args = argparse.Namespace(level=FIRST_LEVEL, ticks=BIG_TICKS, inputs=None, go_on=False,
                                  record=None, report=None, screenshot=None, debug=False,
                                  watch=False)
        campaign = Campaign(FIRST_LEVEL, loader=lambda path: load_level(path, images=True))
        game = GameWindow(Run(campaign, None, args))
        game.audio = Audio(enabled=False)
        pygame.mixer.quit()
        game.window.size = size
        for _ in range(warm_up):
            game.one_frame()
        display = pygame.display.get_surface()
        picture = display.copy()  # the bare window shows the game's own picture
        clock = pygame.time.Clock()

        def bare_frame() -> None:
            clock.tick(TARGET_FPS)
            pygame.event.get()
            display.blit(picture, (0, 0))
            pygame.display.flip()

        def play_frame() -> None:
            game.one_frame()

        play: list[float] = []
        bare: list[float] = []
        with collector_off():
            for number in range(rounds):
                order = [(play, play_frame), (bare, bare_frame)]
                for costs, frame in order if number % 2 == 0 else order[::-1]:
                    costs.append(_cpu_per_frame(frame, frames))
        return WindowCost(size, median(play) * MS_PER_S, median(bare) * MS_PER_S,
                          paired_ratio(play, bare), rounds)
    finally:
        pygame.display.quit()


def _cpu_per_frame(frame: Callable[[], None], frames: int) -> float:
    """The process's CPU seconds per call of ``frame``, over ``frames`` calls."""
    started = time.process_time()
    for _ in range(frames):
        frame()
    return (time.process_time() - started) / frames


@contextlib.contextmanager
def virtual_display(xvfb: str) -> Iterator[str]:
    """Start ``Xvfb`` on a free display number (it writes the number it took to a pipe
    once it is ready) and point ``DISPLAY`` at it; stop it and restore ``DISPLAY`` after."""
    read_end, write_end = os.pipe()
    server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", XVFB_SCREEN,
                               "-nolisten", "tcp"], pass_fds=(write_end,),
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    os.close(write_end)
    previous = os.environ.get("DISPLAY")
    try:
        number = _read_number(read_end)
        if not number:
            raise RuntimeError(f"{xvfb} did not start within {XVFB_START_S:g} s")
        os.environ["DISPLAY"] = f":{number}"
        yield os.environ["DISPLAY"]
    finally:
        os.close(read_end)
        server.terminate()
        try:
            server.wait(timeout=XVFB_START_S)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()
        if previous is None:
            os.environ.pop("DISPLAY", None)
        else:
            os.environ["DISPLAY"] = previous


def _read_number(descriptor: int) -> str:
    """The display number an Xvfb writes to ``descriptor``, or "" if none comes in time."""
    import select

    deadline = time.monotonic() + XVFB_START_S
    text = b""
    while not text.endswith(b"\n") and (left := deadline - time.monotonic()) > 0:
        ready, _, _ = select.select([descriptor], [], [], left)
        if not ready or not (chunk := os.read(descriptor, 16)):
            break
        text += chunk
    return text.decode("ascii", "replace").strip() if text.strip().isdigit() else ""


def main(argv: list[str] | None = None) -> int:
    """``python -m game.bench.window``: 0 done (or skipped), 1 with ``--check`` and a size
    over the target, or no window; 2 bad usage."""
    return run_command(lambda: _main(argv))


def _main(argv: list[str] | None) -> int:
    parser = Parser(prog=PROGRAM, description="Cost a frame of play in a real window against "
                    "a bare SCALED window's blit and flip, at 960x540 and 1600x900.")
    parser.add_argument("--rounds", type=whole_number(2, 1000, "rounds"), default=ROUNDS,
                        metavar="N", help=f"rounds of each kind (default {ROUNDS})")
    parser.add_argument("--frames", type=whole_number(1, 100_000, "frames"),
                        default=FRAMES_PER_ROUND, metavar="N",
                        help=f"frames of each kind per round (default {FRAMES_PER_ROUND})")
    parser.add_argument("--check", action="store_true",
                        help=f"exit 1 if a size costs more than {MAX_RATIO:g}x the bare window")
    parser.add_argument("--size", choices=[f"{w}x{h}" for w, h in SIZES],
                        help=argparse.SUPPRESS)  # one size, in the process the run starts
    args = parser.parse_args(argv)
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    if args.size is not None:
        return _one_size(args.size, args.rounds, args.frames)
    from game.app.display import missing_display

    with contextlib.ExitStack() as stack:
        if missing_display() is not None:
            xvfb = shutil.which("Xvfb")
            if xvfb is None:
                say(f"{PROGRAM}: skipped: there is no display to open a window on, and no Xvfb "
                    "to make one (install it, e.g. apt-get install xvfb)")
                return 0
            try:
                shown = stack.enter_context(virtual_display(xvfb))
            except (OSError, RuntimeError) as error:
                print(f"{PROGRAM}: cannot start Xvfb: {error}", file=sys.stderr)
                return 1
            say(f"no display: measuring under Xvfb on {shown} ({XVFB_SCREEN})")
        passed = True
        for size in SIZES:  # each in a process of its own: SDL's display starts once a process
            status = _measure_apart(size, args.rounds, args.frames)
            if status not in (EXIT_PASSED, EXIT_OVER):
                return 1
            passed = passed and status == EXIT_PASSED
    return 1 if args.check and not passed else 0


def _measure_apart(size: tuple[int, int], rounds: int, frames: int) -> int:
    """Measure ``size`` in a child process that prints its line; its exit status."""
    command = [sys.executable, "-m", "game.bench.window", "--size", f"{size[0]}x{size[1]}",
               "--rounds", str(rounds), "--frames", str(frames)]
    done = subprocess.run(command, stdout=subprocess.PIPE, text=True, check=False)
    if done.stdout:
        say(done.stdout.rstrip("\n"))
    return done.returncode


def _one_size(text: str, rounds: int, frames: int) -> int:
    """``--size WxH``: measure that size on the display there is and print its line; 0 when
    it passes, :data:`EXIT_OVER` when it costs more than the target."""
    width, _, height = text.partition("x")
    try:
        cost = measure((int(width), int(height)), rounds, frames)
    except RuntimeError as error:
        print(error, file=sys.stderr)
        return 1
    say(cost.line())
    return EXIT_PASSED if cost.passed else EXIT_OVER


if __name__ == "__main__":
    raise SystemExit(main())
