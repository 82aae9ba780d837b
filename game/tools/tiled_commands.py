"""The door Tiled's Play and Check commands come in by: one whole map path, or a refusal.

Where it sits: the project's commands (F5 **Play this level**, F6 **Check this level**,
written into the project files by :mod:`game.levels.project`) run
``python -I -m game.tools.tiled_commands play %mapfile`` (or ``check``). This module takes
the pieces Tiled hands over, makes sure they are exactly one existing ``.tmx`` file, and
then plays it (``python -m game --level MAP --watch``) or checks it
(``python -m game.levels check MAP``). It writes nothing of its own, and nothing into the
project or the map's folder (playing keeps the player's progress in the user's data folder,
as the game always does).

What it teaches: a program that builds a command line as text must quote, and a quote can
be broken. Tiled substitutes ``%mapfile`` as ``"PATH"`` into one line of text and splits
that line again into arguments (Qt's ``QProcess::splitCommand``); a double quote inside a
file name ends the quoted path early, and the rest of the name becomes arguments of its
own, so a map named ``x" --report README.md "y.tmx`` would tell the game to write its report
over the project's README. Tiled offers no other way to pass the path, so the pieces are
taken as they come and anything but one existing ``.tmx`` file is refused with one
sentence. ``python -I`` (isolated mode) keeps the working folder, the ``PYTHON*`` variables
and the user's own site-packages off ``sys.path``: a folder that ships its own ``game/``
package or an ``argparse.py`` runs none of it; only the installed game is imported.

>>> one_map(["a.tmx", "--report", "README.md"])
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: 'a.tmx' '--report' 'README.md': map: Tiled split the map's \
path into 3 pieces, because its name holds a double quote (") or a '%' Tiled fills in — \
rename the map without '"' and '%' and run the command again
"""

from __future__ import annotations

import stat
import sys
from pathlib import Path

from game.levels.closed_output import quiet_when_output_closes
from game.levels.errors import LevelError, excerpt

VERBS = ("play", "check")
EXIT_USAGE = 2  # as the game's and the checker's own usage errors
MAP_SUFFIX = ".tmx"


def one_map(pieces: list[str]) -> Path:
    """The one existing ``.tmx`` file the pieces name, or a :class:`LevelError` saying why
    they do not."""
    if len(pieces) != 1:
        named = " ".join(excerpt(piece) for piece in pieces) or "(nothing)"
        raise LevelError(named, "map", f"Tiled split the map's path into {len(pieces)} pieces, "
                         "because its name holds a double quote (\") or a '%' Tiled fills in",
                         "rename the map without '\"' and '%' and run the command again")
    path = Path(pieces[0]).absolute()
    if path.suffix.lower() != MAP_SUFFIX:
        raise LevelError(path, "map", "not a .tmx map",
                         "open a map saved as .tmx in Tiled and run the command again")
    try:
        regular = stat.S_ISREG(path.stat().st_mode)
    except (OSError, ValueError):
        regular = False
    if not regular:
        raise LevelError(path, "map", "no such map file (a double quote or a '%' in a "
                         "folder's or the map's name changes the path Tiled passes)",
                         "save the map, rename it or its folder without '\"' and '%', and "
                         "run the command again")
    return path


def main(argv: list[str] | None = None) -> int:
    """``play PATH`` or ``check PATH``, exactly as Tiled passes them."""
    args = sys.argv[1:] if argv is None else argv
    if not args or args[0] not in VERBS:
        print("usage: python -I -m game.tools.tiled_commands {play,check} MAP.tmx "
              "(run by the Tiled project's commands)", file=sys.stderr)
        return EXIT_USAGE
    try:
        path = one_map(args[1:])
    except LevelError as error:
        print(error, file=sys.stderr)
        return EXIT_USAGE
    if args[0] == "play":
        from game.app.cli import main as play

        return play([f"--level={path}", "--watch"])
    from game.checker.cli import main as levels

    return levels(["check", "--", str(path)])


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
