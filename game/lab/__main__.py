"""``python -m game.lab``: the collision lab (see :mod:`game.lab.cli`)."""

import sys

from game.app.arguments import run_command
from game.lab.cli import main

sys.exit(run_command(main))
