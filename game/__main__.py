"""``python -m game``: play, or run a scripted headless game (see :mod:`game.app.cli`)."""

import sys

from game.app.cli import main

sys.exit(main())
