"""``python -m game.bench [--quick] [--out DIR] [--check]``: measure, chart, check the targets."""

import sys

from game.bench import main

sys.exit(main())
