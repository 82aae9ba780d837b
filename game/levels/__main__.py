"""``python -m game.levels check PATH...``: is every map playable?

Prints one line per problem, ``PATH: place: message — how to fix``, and exits 0 when every
map loads, 1 otherwise, 2 for bad usage. Never a traceback.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from game.levels.errors import LevelError
from game.levels.loader import load_level


def check(paths: list[Path]) -> int:
    failures = 0
    for path in paths:
        try:
            level = load_level(path)
        except LevelError as error:
            print(error)
            failures += 1
            continue
        except Exception as error:  # a bug in the loader still gets a sentence, not a trace
            print(f"{path}: the map could not be read ({type(error).__name__}: {error}) — "
                  "open it in Tiled and save it again")
            failures += 1
            continue
        if level.next_level is not None and not level.next_level.is_file():
            print(f"{path}: map properties: warning: next_level {level.next_level.name!r} "
                  "does not exist — fix the 'next_level' property")
    verdict = "all playable" if not failures else f"{failures} not playable"
    print(f"checked {len(paths)} map(s): {verdict}", file=sys.stderr)
    return 1 if failures else 0


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m game.levels",
                                     description="Check Tiled maps for the game.")
    commands = parser.add_subparsers(dest="command", required=True)
    check_parser = commands.add_parser("check", help="check that maps are playable")
    check_parser.add_argument("paths", nargs="+", type=Path, metavar="PATH")
    args = parser.parse_args(argv)
    return check(args.paths)


if __name__ == "__main__":
    sys.exit(main())
