"""``python -m game.bench [--quick] [--out DIR] [--check]``: measure, chart, check the targets."""

import sys

from game.app.arguments import run_command
from game.bench import main

sys.exit(run_command(main))
