"""``python -m game.levels``: check maps, and keep the Tiled project's classes up to date.

``check PATH...`` prints one line per problem, ``PATH: place: message — how to fix``
(warnings say ``warning:`` before the message), and exits 0 when every map is playable,
1 otherwise, 2 for bad usage. A folder stands for the ``.tmx`` maps inside it. Never a
traceback, whatever the input.

``types`` says whether the generated Tiled files in ``levels/`` match
:mod:`game.levels.classes` (exit 1 if not); ``types --write`` regenerates them.

>>> from game.levels import LEVELS_DIR
>>> check([LEVELS_DIR])
0
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator
from pathlib import Path

from game.levels.loader import check_level

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


def check(paths: list[Path]) -> int:
    """Print what is wrong with each map; return the exit status."""
    checked = failures = 0
    for argument in paths:
        for path, refusal in _maps(argument):
            checked += 1
            if refusal is not None:
                print(refusal)
                failures += 1
                continue
            try:
                findings = check_level(path)
                lines, failed = list(findings.lines()), bool(findings.errors)
            except Exception as error:  # a loader bug still gets a sentence
                lines = [f"{path}: the map could not be read ({type(error).__name__}: "
                         f"{error}) — open it in Tiled and save it again"]
                failed = True
            for line in lines:
                print(line)
            failures += failed
    verdict = "all playable" if not failures else f"{failures} not playable"
    print(f"checked {checked} map(s): {verdict}", file=sys.stderr)
    return 1 if failures else 0


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


def main(argv: list[str] | None = None) -> int:
    """Run a command; Ctrl-C stops it with exit status 130 and one line, not a traceback."""
    try:
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
    types_parser = commands.add_parser("types", help="the game's classes for Tiled")
    types_parser.add_argument("--write", action="store_true",
                              help="regenerate levels/*.tiled-project and friends")
    args = parser.parse_args(argv)
    if args.command == "types":
        return types(args.write)
    return check(args.paths)


if __name__ == "__main__":
    sys.exit(main())
