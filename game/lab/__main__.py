"""``python -m game.lab``: the collision lab (see :mod:`game.lab.cli`).

Ctrl-C while the modules load ends it with status 130 and one line (:func:`game.guard_startup`)."""

import sys

from game import guard_startup

if __name__ == "__main__":
    guard_startup()
    from game.app.arguments import run_command
    from game.lab.cli import main

    sys.exit(run_command(main))
