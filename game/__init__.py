"""Tile Hopper: a pygame platformer whose code teaches 2D collision detection.

Start reading at :mod:`game.collision.axis_sweep` (the swept x and y passes) and
:mod:`game.sim.world` (one tick, top to bottom). The README maps every technique to its module.
"""

import os

# Keep the console for the game's own words.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
