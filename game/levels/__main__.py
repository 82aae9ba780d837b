"""``python -m game.levels`` (installed: ``tile-hopper-levels``): the level tools' command
line, ``check``, ``solve``, ``reach`` and ``types``, which lives with the checker in
:mod:`game.checker.cli`; this file only starts it.
"""

from __future__ import annotations

import sys

from game.checker.cli import main

__all__ = ["main"]

if __name__ == "__main__":
    sys.exit(main(catch_ctrl_c=True))
