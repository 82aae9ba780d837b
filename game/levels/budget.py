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
* **Enemies and platforms, by what a tick can afford.** A tick has 16.7 ms at 60 ticks a
  second. Enemies cost more than their number when they crowd: 100 Enemies packed 10 px
  apart on a floor, each touching its neighbours, took a median 2.1 ms a tick on a shared
  2-core machine, and 150 took 10.8 ms, so 100 is the limit (the shipped levels have at
  most 7). 300 Platforms moving over open ground took 0.1 ms a tick. (Measured with
  ``python -m game --headless --ticks 600 --report R`` on such maps: the report's
  ``update_ms_median``.)
* **Cutting tilesets.** pytmx visits every place of a tileset's image once per mention of
  the tileset, whatever tiles the map uses, and with or without loading the image.
* **Animated cells.** Every animated cell of a drawn layer is looked at every frame: a layer
  of 5,000 animated cells took 2.8 ms a frame to draw, and one of 20,000 took 9.1 ms
  (``game.app.render.LayerCache.draw`` on a 320x180 view, timed over 20 frames).
* **Levels per run.** Levels that name each other as ``next_level`` and are won at the spawn
  would load forever in a headless run without ``--ticks``.
"""

from __future__ import annotations

MAX_SHAPES_PER_TILE = 16  # collision rectangles drawn on one tile
MAX_SHAPES = 250_000  # collision shapes in the whole map, every cell's counted
MAX_COINS = 5_000
MAX_ENEMIES = 100  # moved, swept and checked every tick; crowded, they cost more each
MAX_PLATFORMS = 300  # moved, and carrying what stands on them, every tick
MAX_SPRITE_PIXELS = 4096 * 4096  # all the bodies' boxes together: 64 MB of surfaces
MAX_TILES_CUT = 1 << 19  # places cut out of tileset images, over every mention of each
MAX_ANIMATED_CELLS = 5_000  # animated cells over all drawn layers, looked at every frame
MAX_LEVELS_PER_RUN = 1_000  # levels started in one headless run without --ticks

FIX_SHAPES = ("draw fewer collision rectangles on the tile (one rectangle round the solid "
              "part is usually enough), in Tiled's tile collision editor")
