"""``python -m game``: play, or run a scripted headless game (see :mod:`game.app.cli`).

Ctrl-C while the modules load ends it with status 130 and one line (:func:`game.guard_startup`)."""

import sys

from game import guard_startup

if __name__ == "__main__":
    guard_startup()
    from game.app.cli import main

    sys.exit(main())
