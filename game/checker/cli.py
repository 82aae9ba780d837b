"""The level tools' command line, run as ``python -m game.levels`` (installed:
``tile-hopper-levels``): check maps, solve them, measure the player's reach, and keep the
Tiled project's classes up to date.

``check [PATH...]`` prints one line per problem, ``PATH: place: message — how to fix``
(warnings say ``warning:`` before the message). A folder stands for the ``.tmx`` maps inside
it; no PATH checks the shipped campaign. Never a traceback, whatever the input. A map that
loads is then *judged* (:mod:`game.checker.verdict`): **solved** (a route reaches an Exit
when replayed), **impossible** (no open path joins spawn and Exit, or the Exit lies outside
the player's reach: an error), or **not decided** (the search spent its budget of work,
the map's own or ``--budget N`` moves, or ``--seconds S`` if given, and nothing proved it
impossible: a ``warning: not decided`` line that says how far it got and how to search further).
``--proof SCRIPT`` replays a recorded win instead of searching; ``--no-solve`` judges
nothing; ``--format json`` prints one JSON document instead of lines; ``--jobs N`` checks
up to N maps at once (default: one per core), with the same lines in the same order. The
summary line counts each verdict and states the player's reach. Exit status: 0 every map
playable (and, when judged, solved); 1 a map is bad or impossible; 2 bad usage; 3 no map
bad or impossible, but at least one not decided; 130 Ctrl-C; 143 SIGTERM (which ends the
workers of ``--jobs`` too). An output closed or full changes no status: the lines nobody
reads are dropped (:mod:`game.levels.closed_output`).

``solve MAP [--out SCRIPT] [--picture PNG] [--budget N] [--seconds S]`` searches for that
route, writes it as an input script and draws it over the map; exit 0 when found, 1 when
there is no route to write: the map is bad, impossible or not decided (the line says which,
and how far the search got), 2 for bad usage.

``reach`` prints the player's reach with the default physics (or a map's own, given one),
measured in the game's own tick: the highest ledge and the widest gaps (within a budget of
ticks of play: :data:`game.checker.reach.MAX_MEASURE_TICKS`).

``types`` says whether the generated Tiled files in ``levels/`` match
:mod:`game.levels.classes` (exit 1 if not); ``types --write`` regenerates them.

>>> from game.levels import LEVELS_DIR
>>> check([LEVELS_DIR / "01-first-steps.tmx"], Options(solve=False))  # doctest: +ELLIPSIS
checked 1 map(s): all playable; the player jumps 2.8 tiles high and 3.6 tiles across ...
0
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import os
import signal
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pygame

from game.checker.checking import Finding, MapReport, Options
from game.checker.reach import limits_of, measure_reach, own_reaches
from game.checker.route_picture import draw_route
from game.checker.search_budget import MOVES_PER_CELL
from game.checker.side_by_side import Terminated, check_maps, usable_cores
from game.checker.solver import Effort
from game.checker.verdict import Kind, judge
from game.levels.closed_output import flush_both, say, tell
from game.levels.errors import LevelError, escaped
from game.levels.loader import files_read, load_level
from game.levels.outputs import image_suffix, unwritable, write_output, write_surface
from game.levels.reading import reason
from game.levels.shipped import LEVELS_DIR
from game.sim.tuning import TICK_HZ, Tuning
from game.sim.whole_numbers import NumberTextError, quoted, read_whole

TILE_PX = 16  # the tile size the reach is given in (the shipped maps')

EXIT_OK = 0
EXIT_BAD = 1  # a map is bad, or proven impossible
EXIT_USAGE = 2
EXIT_UNDECIDED = 3  # nothing bad or impossible, but some map's search was not decided
MAX_COUNT_DIGITS = 12  # --budget and --jobs: more is a typo, not a plan
EXIT_INTERRUPTED = 130  # 128 + SIGINT, what a shell reports for Ctrl-C
EXIT_TERMINATED = 143  # 128 + SIGTERM


def command_name(argv0: str | None = None) -> str:
    """The command as it was typed, for usage lines and advice: ``tile-hopper-levels`` when
    installed, else ``python -m game.levels``.

    >>> command_name("/usr/bin/tile-hopper-levels"), command_name("/x/game/levels/__main__.py")
    ('tile-hopper-levels', 'python -m game.levels')
    """
    name = Path(argv0 if argv0 is not None else sys.argv[0]).name
    if not name or name in ("__main__.py", "-c", "-m") or name.startswith("python"):
        return "python -m game.levels"
    return name.removesuffix(".exe")


def _maps_in(folder: Path) -> list[Path]:
    """The ``.tmx`` maps anywhere under ``folder``, sorted. The folders are walked with a
    list of folders still to look into, not by recursion, so a folder 1,200 levels deep is
    no RecursionError; a link to a folder is not followed (it could lead back up)."""
    found: list[Path] = []
    waiting = [folder]
    while waiting:
        with os.scandir(waiting.pop()) as entries:
            for entry in entries:
                if entry.is_dir(follow_symlinks=False):
                    waiting.append(Path(entry.path))
                elif entry.name.endswith(".tmx"):
                    found.append(Path(entry.path))
    return sorted(found)


def _maps(path: Path) -> Iterator[tuple[Path, tuple[str, str] | None]]:
    """The maps a command-line path stands for, or the path and why it stands for none."""
    try:
        is_folder = path.is_dir()
        found = _maps_in(path) if is_folder else []
    except (OSError, ValueError) as error:
        yield path, (f"the path cannot be read ({reason(error)})", "check it")
        return
    if not is_folder:
        yield path, None
    elif not found:
        yield path, ("this folder holds no .tmx maps", "give a map or a folder of maps")
    else:
        yield from ((map_path, None) for map_path in found)


def reach_summary(own: list[tuple[Path, Tuning]]) -> str:
    """The player's reach with the default physics, then on each map that sets its own."""
    default = Tuning()
    text = ("with the default physics the player " if own else "the player ") + \
        measure_reach(default).describe(TILE_PX) + "; " + limits_of(default).describe()
    shown, more = own_reaches(own)
    for item in shown:
        text += (f"; on {item.path.name}, with its own physics, it "
                 f"{item.reach.describe(TILE_PX)}; {item.limits.describe()}")
    if more:
        text += f"; {more:,} more map(s) set their own physics (reach MAP measures one)"
    return text


def _summary(reports: list[MapReport], options: Options) -> tuple[str, int]:
    """The summary line and the exit status."""
    unread = sum(r.proof_unread for r in reports)  # the script's fault, not the map's
    bad = sum(r.bad and r.verdict is not Kind.IMPOSSIBLE and not r.proof_unread
              for r in reports)
    counts = {kind: sum(r.verdict is kind for r in reports) for kind in Kind}
    impossible, undecided = counts[Kind.IMPOSSIBLE], counts[Kind.UNDECIDED]
    # "all playable" only when nothing is bad, impossible or left undecided by the search.
    parts = [] if bad or impossible or unread else (
        ["all playable"] if not undecided else ["none bad"])
    if bad:
        parts.append(f"{bad} not playable")
    if unread:
        parts.append(f"{unread} not judged (the --proof script cannot be read)")
    if options.solve:
        parts += [f"{counts[kind]} {kind.value}" for kind in Kind
                  if counts[kind] or kind is Kind.SOLVED]
    own = [(r.path, r.tuning) for r in reports if r.tuning is not None]
    line = f"checked {len(reports)} map(s): {', '.join(parts)}; {reach_summary(own)}"
    status = (EXIT_BAD if bad or impossible or unread else
              EXIT_UNDECIDED if undecided else EXIT_OK)
    return line, status


def check(paths: list[Path], options: Options, output: str = "text", jobs: int = 1) -> int:
    """Print what is wrong with each map and how each was judged; return the exit status.
    ``jobs``: how many maps to check at once (:mod:`game.checker.side_by_side`)."""
    found = [found for argument in paths or sorted(LEVELS_DIR.glob("*.tmx"))  # none: the
             for found in _maps(argument)]                                      # campaign
    reports: list[MapReport] = []
    with contextlib.closing(check_maps([path for path, refusal in found if refusal is None],
                                       options, jobs)) as checked:  # closed: no worker left
        for path, refusal in found:
            if refusal is not None:
                report = MapReport(path)
                report.findings.append(_refused(path, refusal))
            else:
                report = next(checked)
            reports.append(report)
            if output == "text":
                for finding in report.findings:
                    say(escaped(finding.text))
    line, status = _summary(reports, options)
    if output == "json":
        say(json.dumps({"maps": [r.as_json() for r in reports], "summary": escaped(line),
                          "status": status}, indent=1))
    else:
        say(escaped(line))
    return status


def _refused(path: Path, refusal: tuple[str, str]) -> Finding:
    return Finding.of("error", path, "", *refusal)


def solve_command(path: Path, out: Path | None, picture: Path | None, effort: Effort,
                  command: str) -> int:
    """``solve``: judge the map, write the script and the picture; return the exit status.
    An output that plainly cannot be written is said before the search, not after it, and
    so is one that would replace a file the map uses (the map, a tileset, an image)."""
    files_read(path)  # each file the map uses, images included, is now known as an input
    for output, what in ((out, "the script"), (picture, "the picture")):
        problem = unwritable(output, what) if output is not None else None
        if problem is not None:
            tell(problem)
            return EXIT_BAD
    try:
        level = load_level(path, images=picture is not None)
    except LevelError as error:
        tell(str(error))
        return EXIT_BAD
    verdict = judge(level, effort, command)
    solution = verdict.solution
    status = EXIT_OK
    if verdict.kind is Kind.SOLVED and solution is not None and out is not None:
        # The route is written first: nothing after (the picture, a closed output) loses it.
        script = solution.script()
        failed = write_output(out, lambda tmp: tmp.write_text(script, encoding="utf-8"),
                              "the script")
        if failed is not None:
            tell(failed)
            status = EXIT_BAD
    if picture is not None:
        route = solution.route if solution is not None else []
        furthest = (solution.furthest if solution is not None and not solution.found
                    else None)
        reach = verdict.reach.cells if verdict.reach is not None else None
        suffix = image_suffix(picture)
        drawn = draw_route(level, route, furthest, reach)
        failed = write_output(picture, lambda tmp: write_surface(drawn, tmp, suffix),
                              "the picture", suffix)
        if failed is not None:
            tell(failed)
            status = EXIT_BAD
    if verdict.kind is not Kind.SOLVED or solution is None:
        where = f"tile ({verdict.tile[0]},{verdict.tile[1]}): " if verdict.tile else ""
        tell(escaped(f"{path}: {where}{verdict.finding} — {verdict.advice}"))
        return EXIT_BAD  # impossible or not decided: no route to write (the public form)
    if status != EXIT_OK:
        return status
    if out is None and not say(solution.script(), end=""):
        tell(f"{path}: the route could not be printed (the output is closed or full) — "
             "give --out SCRIPT to write it to a file")
        return EXIT_BAD
    tell(f"{path}: a route reaches the exit at tick {solution.exit_tick} "
         f"({solution.exit_tick / TICK_HZ:.1f} s of play; {solution.moves_tried:,} moves "
         "tried)")
    return EXIT_OK


def reach_command(path: Path | None) -> int:
    """``reach``: the player's reach, measured, with the default physics or a map's own."""
    tuning = Tuning()
    if path is not None:
        try:
            tuning = tuning.with_map_properties(load_level(path).properties)
        except LevelError as error:
            tell(str(error))
            return EXIT_BAD
    limits = limits_of(tuning)
    say(f"the player {measure_reach(tuning).describe(TILE_PX)}; {limits.describe()}")
    return EXIT_OK


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
            say(f"{_shown(path)}: written")
        return 0
    stale = stale_files()
    for path in stale:
        say(f"{_shown(path)}: out of date — run python -m game.levels types --write")
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


def main(argv: list[str] | None = None, *, catch_ctrl_c: bool = False) -> int:
    """Run a command; Ctrl-C stops it with exit status 130 and one line, not a traceback.
    An output closed or full (``| head -1``, ``> /dev/full``) loses only the lines printed
    (:mod:`game.levels.closed_output`): the command ends with the status it would have had.
    ``catch_ctrl_c``: the command line's own process (``python -m game.levels``), where
    Ctrl-C becomes a KeyboardInterrupt from here on, caught below."""
    try:
        if catch_ctrl_c:
            signal.signal(signal.SIGINT, signal.default_int_handler)
        return _main(argv)
    except KeyboardInterrupt:
        tell("stopped by Ctrl-C")
        return EXIT_INTERRUPTED
    except Terminated:  # SIGTERM during a check of maps side by side: the workers end too
        tell("stopped by SIGTERM")
        return EXIT_TERMINATED
    finally:
        flush_both()  # an output closed or full ends the command quietly, with its status


def _positive(unit: str) -> Callable[[str], int]:
    """An argparse ``type`` for a positive whole number of ``unit``."""
    def parse(text: str) -> int:
        try:
            value = read_whole(text, MAX_COUNT_DIGITS)
        except NumberTextError:
            value = 0
        if value <= 0:
            raise argparse.ArgumentTypeError(f"{quoted(text)} is not a positive whole number "
                                             f"of {unit}")
        return value
    return parse


_budget = _positive("moves")
_jobs = _positive("maps")


def _add_search_options(parser: argparse.ArgumentParser, seconds_flags: list[str]) -> None:
    parser.add_argument("--budget", type=_budget, default=None, metavar="N",
                        help="the most moves the search may try on a map, the same on any "
                        f"machine (default: the map's own, {MOVES_PER_CELL} for each cell "
                        "its route may pass through); more decides more maps")
    parser.add_argument(*seconds_flags, dest="seconds", type=_seconds, default=None,
                        metavar="S", help="also stop a map's search after S seconds of wall "
                        "time (default: no limit; a limit in seconds may decide differently "
                        "on a slower or busier machine)")


def _parser(prog: str) -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog=prog, description="Check Tiled maps for the game.")
    commands = parser.add_subparsers(dest="command", required=True)
    check_parser = commands.add_parser(
        "check", help="check that maps are playable and can be won",
        description="Exit status: 0 every map playable (and solved, when searched); 1 a map "
        "is bad or impossible; 2 bad usage; 3 none bad or impossible, but some not decided.")
    check_parser.add_argument("paths", nargs="*", type=Path, metavar="PATH",
                              help="a .tmx map, or a folder of them (default: the shipped "
                              "campaign)")
    check_parser.add_argument("--no-solve", action="store_true",
                              help="do not search for a route from the spawn to an Exit")
    _add_search_options(check_parser, ["--seconds", "--solve-seconds"])
    check_parser.add_argument("--proof", type=Path, metavar="SCRIPT",
                              help="a win recorded with python -m game --record: replay it "
                              "instead of searching (one map only)")
    check_parser.add_argument("--format", choices=("text", "json"), default="text",
                              help="text lines (default) or one JSON document")
    check_parser.add_argument("--jobs", type=_jobs, default=usable_cores(), metavar="N",
                              help="check up to N maps at once, never more than one per core "
                              f"(default: one per core, here {usable_cores()}); the lines and "
                              "verdicts are the same")
    solve_parser = commands.add_parser(
        "solve", help="find inputs that win a map",
        description="Exit status: 0 a route was found; 1 the map is bad or impossible; "
        "2 bad usage; 3 not decided.")
    solve_parser.add_argument("map", type=Path, metavar="MAP", help="a .tmx map")
    solve_parser.add_argument("--out", type=Path, metavar="SCRIPT",
                              help="write the input script here (default: stdout)")
    solve_parser.add_argument("--picture", type=Path, metavar="PNG",
                              help="draw the route (or how far the search got) over the map")
    _add_search_options(solve_parser, ["--seconds"])
    reach_parser = commands.add_parser("reach", help="the player's reach, measured")
    reach_parser.add_argument("map", type=Path, nargs="?", metavar="MAP",
                              help="use this map's own physics (default: the game's)")
    types_parser = commands.add_parser("types", help="the game's classes for Tiled")
    types_parser.add_argument("--write", action="store_true",
                              help="regenerate levels/*.tiled-project and friends")
    return parser


def _main(argv: list[str] | None) -> int:
    for stream in (sys.stdout, sys.stderr):  # odd bytes in a file name must not crash print
        if hasattr(stream, "reconfigure"):
            stream.reconfigure(errors="backslashreplace")
    prog = command_name()
    parser = _parser(prog)
    args = parser.parse_args(argv)
    if args.command == "types":
        return types(args.write)
    if args.command == "reach":
        return reach_command(args.map)
    effort = Effort(budget=args.budget, seconds=args.seconds)
    if args.command == "solve":
        if args.picture is not None:
            os.environ.setdefault("SDL_VIDEODRIVER", "dummy")  # pictures, never a window
            pygame.display.init()
            pygame.display.set_mode((1, 1))
        return solve_command(args.map, args.out, args.picture, effort, prog)
    if args.proof is not None and (len(args.paths) != 1 or args.no_solve):
        parser.error("--proof SCRIPT goes with exactly one map, and not with --no-solve")
    return check(args.paths, Options(solve=not args.no_solve, effort=effort,
                                     proof=args.proof, command=prog), args.format,
                 args.jobs)

