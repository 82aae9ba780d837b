"""``python -m game``: play, or run a scripted headless game (see :mod:`game.cli`)."""

import sys

from game.cli import main

sys.exit(main())
