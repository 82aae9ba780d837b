"""``python -m game.levels``: check maps, solve them, and keep the Tiled project's classes
up to date.

``check PATH...`` prints one line per problem, ``PATH: place: message — how to fix``
(warnings say ``warning:`` before the message), and exits 0 when every map is playable,
1 otherwise, 2 for bad usage. A folder stands for the ``.tmx`` maps inside it. Never a
traceback, whatever the input. A map that loads is also *solved*
(:mod:`game.levels.solver`): if the search gives up without reaching an Exit, that is an
error naming the furthest place reached; if it runs out of time (``--solve-seconds``), a
warning; ``--no-solve`` skips the search. The summary line, on stdout, says how high and
far the player jumps.

``solve MAP [--out SCRIPT] [--picture PNG] [--seconds S]`` searches for that route, writes
it as an input script and draws it over the map; exit 0 when found, 1 when the map is bad or
no route was found (the line says how far the search got), 2 for bad usage.

``types`` says whether the generated Tiled files in ``levels/`` match
:mod:`game.levels.classes` (exit 1 if not); ``types --write`` regenerates them.

>>> from game.levels import LEVELS_DIR
>>> check([LEVELS_DIR], solve_seconds=None)  # doctest: +ELLIPSIS
checked 6 map(s): all playable; the player jumps 2.8 tiles high and 3.6 tiles across ...
0
"""

from __future__ import annotations

import argparse
import math
import os
import signal
import sys
from collections.abc import Iterator
from pathlib import Path

import pygame

from game.levels.errors import LevelError, escaped
from game.levels.loader import check_level, load_level
from game.levels.outputs import image_suffix, write_output, write_surface
from game.levels.reach import measure_reach
from game.levels.route_picture import draw_route
from game.levels.solver import Effort, solve
from game.sim.level import Level
from game.sim.tuning import TICK_HZ, Tuning

DEFAULT_SOLVE_SECONDS = 120.0  # how long check looks for a route on one map
TILE_PX = 16  # the tile size the reach is given in (the shipped maps')

EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for Ctrl-C


def _maps(path: Path) -> Iterator[tuple[Path, str | None]]:
    """The maps a command-line path stands for, or the path and why it stands for none."""
    try:
        is_folder = path.is_dir()
        found = sorted(path.rglob("*.tmx")) if is_folder else []
    except (OSError, ValueError) as error:
        yield path, f"{path}: the path cannot be read ({error}) — check it"
        return
    if not is_folder:
        yield path, None
    elif not found:
        yield path, f"{path}: this folder holds no .tmx maps — give a map or a folder of maps"
    else:
        yield from ((map_path, None) for map_path in found)


def _unsolved(path: Path, level: Level, seconds: float | None) -> tuple[str, bool] | None:
    """The line for a map whose Exit the solver did not reach, and whether it is an error
    (the search gave up) or a warning (it ran out of time, which proves nothing)."""
    solution = solve(level, Effort(seconds=seconds))
    if solution.found:
        return None
    col, row = solution.furthest_tile()
    if solution.timed_out and seconds is not None:
        return (f"{path}: tile ({col},{row}): warning: no route to an Exit was found within "
                f"{seconds:g} s; this is the furthest place reached — give the search more "
                "time with --solve-seconds, or run python -m game.levels solve on this map",
                False)
    return (f"{path}: tile ({col},{row}): the exit was not reached from the spawn; this is "
            "the furthest place reached — check the jumps on the way against the player's "
            f"reach, or run python -m game.levels solve {path} --picture route.png to see "
            "how far the search got", True)


def _reach_summary(own: list[tuple[Path, Tuning]]) -> str:
    """The player's reach with the default physics, then on each map that sets its own."""
    text = ("with the default physics the player " if own else "the player ") + \
        measure_reach(Tuning()).describe(TILE_PX)
    for path, tuning in own:
        text += f"; on {path.name}, with its own physics, it " + \
            measure_reach(tuning).describe(TILE_PX)
    return text


def check(paths: list[Path], solve_seconds: float | None = DEFAULT_SOLVE_SECONDS) -> int:
    """Print what is wrong with each map; return the exit status. ``solve_seconds`` None:
    do not look for a route to the Exit."""
    checked = failures = 0
    own: list[tuple[Path, Tuning]] = []  # the maps whose properties change the physics
    for argument in paths:
        for path, refusal in _maps(argument):
            checked += 1
            if refusal is not None:
                print(escaped(refusal))
                failures += 1
                continue
            try:
                findings = check_level(path)
                lines, failed = list(findings.lines()), bool(findings.errors)
                if not failed:
                    level = load_level(path)
                    tuning = Tuning().with_map_properties(level.properties)
                    if tuning != Tuning():  # its properties change the physics
                        own.append((path, tuning))
                    unsolved = (None if solve_seconds is None
                                else _unsolved(path, level, solve_seconds))
                    if unsolved is not None:
                        lines.append(unsolved[0])
                        failed = unsolved[1]
            except Exception as error:  # a loader bug still gets a sentence
                lines = [f"{path}: the map could not be read ({type(error).__name__}: "
                         f"{error}) — open it in Tiled and save it again"]
                failed = True
            for line in lines:
                print(escaped(line))
            failures += failed
    verdict = "all playable" if not failures else f"{failures} not playable"
    solved = ", each solved from spawn to Exit" if solve_seconds is not None and not failures \
        else ""
    print(escaped(f"checked {checked} map(s): {verdict}{solved}; {_reach_summary(own)}"))
    return 1 if failures else 0


def solve_command(path: Path, out: Path | None, picture: Path | None,
                  seconds: float | None) -> int:
    """``solve``: find a route, write the script and the picture; return the exit status."""
    try:
        level = load_level(path, images=picture is not None)
    except LevelError as error:
        print(error, file=sys.stderr)
        return 1
    solution = solve(level, Effort(seconds=seconds))
    if picture is not None:
        suffix = image_suffix(picture)
        drawn = draw_route(level, solution.route, None if solution.found else solution.furthest)
        failed = write_output(picture, lambda tmp: write_surface(drawn, tmp, suffix),
                              "the picture", suffix)
        if failed is not None:
            print(failed, file=sys.stderr)
            return 1
    if not solution.found:
        col, row = solution.furthest_tile()
        why = f"in {seconds:g} s" if solution.timed_out and seconds is not None else \
            "with every move it tried"
        print(f"{path}: tile ({col},{row}): no route to an Exit was found {why}; this is the "
              "furthest place reached — see the picture (--picture) for the way there",
              file=sys.stderr)
        return 1
    script = solution.script()
    if out is not None:
        failed = write_output(out, lambda tmp: tmp.write_text(script, encoding="utf-8"),
                              "the script")
        if failed is not None:
            print(failed, file=sys.stderr)
            return 1
    else:
        sys.stdout.write(script)
    print(f"{path}: a route reaches the exit at tick {solution.exit_tick} "
          f"({solution.exit_tick / TICK_HZ:.1f} s of play)", file=sys.stderr)
    return 0


def _shown(path: Path) -> str:
    """``path`` relative to the working folder when it is inside it."""
    try:
        return str(path.relative_to(Path.cwd()))
    except ValueError:
        return str(path)


def types(write: bool) -> int:
    """Compare (or with ``write``, regenerate) the Tiled files made from the classes."""
    from game.levels.project import stale_files, write_files

    if write:
        for path in write_files():
            print(f"{_shown(path)}: written")
        return 0
    stale = stale_files()
    for path in stale:
        print(f"{_shown(path)}: out of date — run python -m game.levels types --write")
    return 1 if stale else 0


def _seconds(text: str) -> float:
    """A positive number of seconds, for argparse."""
    try:
        seconds = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds") from None
    if not (seconds > 0 and math.isfinite(seconds)):
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive number of seconds")
    return seconds


def main(argv: list[str] | None = None) -> int:
    """Run a command; Ctrl-C stops it with exit status 130 and one line, not a traceback."""
    try:
        if __name__ == "__main__":  # from here Ctrl-C is a KeyboardInterrupt, caught below
            signal.signal(signal.SIGINT, signal.default_int_handler)
        return _main(argv)
    except KeyboardInterrupt:
        print("stopped by Ctrl-C", file=sys.stderr)
        return EXIT_INTERRUPTED


def _main(argv: list[str] | None) -> int:
    for stream in (sys.stdout, sys.stderr):  # odd bytes in a file name must not crash print
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")
    parser = argparse.ArgumentParser(prog="python -m game.levels",
                                     description="Check Tiled maps for the game.")
    commands = parser.add_subparsers(dest="command", required=True)
    check_parser = commands.add_parser("check", help="check that maps are playable")
    check_parser.add_argument("paths", nargs="+", type=Path, metavar="PATH",
                              help="a .tmx map, or a folder of them")
    check_parser.add_argument("--no-solve", action="store_true",
                              help="do not search for a route from the spawn to an Exit")
    check_parser.add_argument("--solve-seconds", type=_seconds, default=DEFAULT_SOLVE_SECONDS,
                              metavar="S", help="how long to look for a route on each map "
                              f"(default {DEFAULT_SOLVE_SECONDS:g})")
    solve_parser = commands.add_parser("solve", help="find inputs that win a map")
    solve_parser.add_argument("map", type=Path, metavar="MAP", help="a .tmx map")
    solve_parser.add_argument("--out", type=Path, metavar="SCRIPT",
                              help="write the input script here (default: stdout)")
    solve_parser.add_argument("--picture", type=Path, metavar="PNG",
                              help="draw the route (or how far the search got) over the map")
    solve_parser.add_argument("--seconds", type=_seconds, default=None, metavar="S",
                              help="give up after this many seconds (default: no limit "
                              "beyond the search's own)")
    types_parser = commands.add_parser("types", help="the game's classes for Tiled")
    types_parser.add_argument("--write", action="store_true",
                              help="regenerate levels/*.tiled-project and friends")
    args = parser.parse_args(argv)
    if args.command == "types":
        return types(args.write)
    if args.command == "solve":
        if args.picture is not None:
            os.environ.setdefault("SDL_VIDEODRIVER", "dummy")  # pictures, never a window
            pygame.display.init()
            pygame.display.set_mode((1, 1))
        return solve_command(args.map, args.out, args.picture, args.seconds)
    return check(args.paths, None if args.no_solve else args.solve_seconds)


if __name__ == "__main__":
    sys.exit(main())
