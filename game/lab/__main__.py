"""``python -m game.lab``: the collision lab (see :mod:`game.lab.cli`)."""

import sys

from game.lab.cli import main

sys.exit(main())
