"""Tile Hopper: a pygame platformer whose code teaches 2D collision detection.

Start reading at :mod:`game.sim.world` (one tick, top to bottom) and :mod:`game.sim.movement`
(the swept x and y passes). The README maps every technique to its module.
"""

import os

# Keep the console for the game's own words.
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")
