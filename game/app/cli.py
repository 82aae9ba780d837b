"""The command line of ``python -m game`` (see the README and the contract).

Where it sits: the outermost layer. It parses options, turns every bad input into one
sentence and an exit status (0 done, 1 a bad level or input file, 2 bad usage), and hands
the run to :mod:`game.app.run`.
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path


def _non_negative(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"{text} is negative; give 0 or more ticks")
    return value


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m game",
        description="A platformer that teaches 2D collision detection. Levels are Tiled maps.")
    p.add_argument("--level", type=Path, metavar="PATH", help="start at this .tmx map")
    p.add_argument("--headless", action="store_true",
                   help="no window and no audio; simulate as fast as possible")
    p.add_argument("--ticks", type=_non_negative, metavar="N",
                   help="stop after N ticks (1 tick = 1/60 s of game time)")
    p.add_argument("--inputs", type=Path, metavar="FILE", help="replay an input script")
    p.add_argument("--record", type=Path, metavar="FILE", help="record this run's input")
    p.add_argument("--report", type=Path, metavar="FILE", help="write the JSON report at exit")
    p.add_argument("--screenshot", type=Path, metavar="FILE",
                   help="save the last rendered frame as PNG at exit")
    p.add_argument("--debug", action="store_true", help="start with the debug overlay (F1)")
    p.add_argument("--watch", action="store_true",
                   help="reload the level when its .tmx or .tsx changes on disk")
    return p


def main(argv: list[str] | None = None) -> int:
    args = parser().parse_args(argv)
    if args.headless:  # before pygame is imported anywhere: no window, no sound card
        os.environ["SDL_VIDEODRIVER"] = "dummy"
        os.environ["SDL_AUDIODRIVER"] = "dummy"
    os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
    from game.app.run import run
    from game.app.window import play_in_window

    return run(args, play_in_window)


if __name__ == "__main__":
    sys.exit(main())
