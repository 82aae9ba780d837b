"""The budget of one level: how much of everything a map may make, each bound in one place.

Where it sits: the loader's readers check their counts against these numbers *before* the
work is done (a shape built, a surface allocated, a tileset cut), so a hostile map is one
sentence in a fraction of a second instead of gigabytes and minutes. ``levels/README.md``
lists them for level designers; a test reads this module to keep that table true.

What it teaches: bound work, not time. A limit in seconds depends on the machine; a limit
on what is made (shapes, pixels, sprites, tiles cut) gives every machine the same verdict.
Each number is generous for a real level (the shipped ones use a few percent of each) and
small enough that the worst map within it still loads in seconds and ticks in time:

* **Collision shapes.** A tile's own rectangles are stored once per tile, but copied into
  every cell painted with it: 40 rectangles on 249,000 cells would be 10 M shapes. Tiled
  users draw one to a few rectangles per tile.
* **Sprites.** Every coin, enemy, platform, exit and checkpoint is a sprite with a surface
  the size of its box, so their pixels are counted like the images' pixels.
* **Enemies and platforms, by what a tick can afford.** Each enemy and each platform is
  moved and swept every tick, about 10 µs each in CPython on a small machine: 300 of each
  cost some 6 ms of the 16.7 ms a frame has at 60 frames a second.
* **Cutting tilesets.** pytmx visits every place of a tileset's image once per mention of
  the tileset, whatever tiles the map uses, and with or without loading the image.
* **Animated cells.** Every animated cell of a drawn layer is looked at every frame.
* **Levels per run.** Levels that name each other as ``next_level`` and are won at the spawn
  would load forever in a headless run without ``--ticks``.
"""

from __future__ import annotations

MAX_SHAPES_PER_TILE = 16  # collision rectangles drawn on one tile
MAX_SHAPES = 250_000  # collision shapes in the whole map, every cell's counted
MAX_COINS = 5_000
MAX_ENEMIES = 300  # moved, swept and checked against the player every tick
MAX_PLATFORMS = 300  # moved, and carrying what stands on them, every tick
MAX_SPRITE_PIXELS = 4096 * 4096  # all the bodies' boxes together: 64 MB of surfaces
MAX_TILES_CUT = 1 << 19  # places cut out of tileset images, over every mention of each
MAX_ANIMATED_CELLS = 20_000  # animated cells over all drawn layers, looked at every frame
MAX_LEVELS_PER_RUN = 1_000  # levels started in one headless run without --ticks

FIX_SHAPES = ("draw fewer collision rectangles on the tile (one rectangle round the solid "
              "part is usually enough), in Tiled's tile collision editor")
