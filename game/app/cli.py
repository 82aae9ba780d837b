"""The command line of ``python -m game`` (see the README and the contract).

Where it sits: the outermost layer. It parses options, turns every bad input into one
sentence and an exit status (0 done, 1 a file that cannot be read or written, or no display
for the window, 2 bad usage, 130 stopped by Ctrl-C), and hands the run to
:mod:`game.app.run`. Installed with pip, the same command is ``tile-hopper``; ``--level``
takes a shipped level's name as well as a path (:mod:`game.app.level_names`).
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

from game.app.arguments import EXIT_USAGE, Parser, run_command, whole_number
from game.app.display import EXIT_NO_WINDOW, GAME_INSTEAD, missing_display, no_window
from game.app.level_names import UnknownLevel, level_names, level_path
from game.levels.closed_output import say

MAX_TICKS = 1_000_000_000  # six months of game time


def parser() -> argparse.ArgumentParser:
    p = Parser(
        prog=Path(sys.argv[0]).name if Path(sys.argv[0]).stem == "tile-hopper"
        else "python -m game",
        description="A platformer that teaches 2D collision detection. Levels are Tiled maps.")
    p.add_argument("--level", type=Path, metavar="PATH",
                   help="start at this .tmx map, or at the shipped level of this name "
                   "(first-steps, or 01-first-steps; see --list-levels)")
    p.add_argument("--list-levels", action="store_true",
                   help="print the shipped levels' names, one a line, and exit")
    p.add_argument("--headless", action="store_true",
                   help="no window and no audio; simulate as fast as possible (without "
                   "--ticks, for at most an hour of game time)")
    p.add_argument("--ticks", type=whole_number(0, MAX_TICKS, "ticks"), metavar="N",
                   help="stop after N ticks (1 tick = 1/60 s of game time)")
    p.add_argument("--inputs", type=Path, metavar="FILE",
                   help="replay an input script (without --ticks, until its level ends)")
    p.add_argument("--go-on", action="store_true",
                   help="with --inputs and no --ticks: play on into the levels after the "
                   "script's level")
    p.add_argument("--record", type=Path, metavar="FILE", help="record this run's input")
    p.add_argument("--report", type=Path, metavar="FILE", help="write the JSON report at exit")
    p.add_argument("--screenshot", type=Path, metavar="FILE",
                   help="save the last rendered frame as PNG at exit")
    p.add_argument("--debug", action="store_true", help="start with the debug overlay (F1)")
    p.add_argument("--watch", action="store_true",
                   help="reload the level when its .tmx or .tsx changes on disk")
    return p


def main(argv: list[str] | None = None) -> int:
    return run_command(lambda: _main(argv))


def _main(argv: list[str] | None) -> int:
    options = parser()
    args = options.parse_args(argv)
    if args.list_levels:  # an output closed or full (| head -1) ends the list quietly
        say("\n".join(level_names()))
        return 0
    if args.level is not None:
        try:
            args.level = level_path(args.level, program=options.prog)
        except UnknownLevel as error:
            print(error, file=sys.stderr)
            return EXIT_USAGE
    if args.headless:  # before pygame is imported anywhere: no window, no sound card
        os.environ["SDL_VIDEODRIVER"] = "dummy"
        os.environ["SDL_AUDIODRIVER"] = "dummy"
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    if not args.headless and (why := missing_display()) is not None:  # said before pygame loads
        print(no_window(options.prog, why, GAME_INSTEAD), file=sys.stderr)
        return EXIT_NO_WINDOW
    from game.app.run import run
    from game.app.window import play_in_window

    return run(args, play_in_window, options.prog)


if __name__ == "__main__":
    sys.exit(main())
