"""A level's solids as one source of shapes: its tiles, then its moving platforms.

Where it sits: what every lookup of a tick asks (:meth:`game.sim.world.World.step`). The
tile grid (:class:`~game.collision.tile_grid.TileGrid`) and the platforms' index
(:class:`~game.sim.platforms.PlatformIndex`) are two
:class:`~game.collision.shapes.ShapeSource`\\ s; :class:`LevelSolids` asks both and joins
the answers, so the swept moves of :mod:`game.collision.axis_sweep` need no special case
for things that move. :class:`Lookups` names the source each step of a tick asks, so an
observer (the debug overlay's query log, :mod:`game.sim.query_log`) can be put round any
of them without a line of the tick changing.

What it teaches: **compose, don't special-case.** The grid's query knows nothing of
platforms, and the platforms' index nothing of tiles; a third small object asks both.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from game.collision.aabb import Box
from game.collision.shapes import Entry, ShapeSource, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.platforms import Platform, PlatformIndex


class LevelSolids:
    """The tiles and the moving platforms, asked as one; ``without`` leaves out the
    platform that is itself moving (it must not stop what it pushes or carries).

    Speed, kept: the map's size and the tiles' query are looked up once, here, not on each
    of the dozen queries a tick makes: read through properties and attributes on each query
    they cost a tenth of it (timeit, over the queries of The Summit's first 1,200 ticks).
    With a handful of platforms, all on the map (:meth:`PlatformIndex.few_routes`), each
    route's block of cells and then the platform's box are tested right here, as
    :meth:`PlatformIndex.entries_in` would test them, after one test of the block holding
    every route: the queries took about a quarter less time than asking the index (timeit, as
    above, 6.0 against 8.4 µs a query, medians of three runs on a loaded machine).
    """

    __slots__ = ("_bounds", "_few_routes", "_tiles_in", "height_px", "platforms",
                 "tiles", "width_px", "without")

    def __init__(self, tiles: TileGrid, platforms: PlatformIndex,
                 without: Platform | None = None) -> None:
        self.tiles, self.platforms, self.without = tiles, platforms, without
        self.width_px, self.height_px = tiles.width_px, tiles.height_px
        self._tiles_in = tiles.entries_in
        self._few_routes = platforms.few_routes()
        # The block of cells holding every route; with a platform off the map, everywhere.
        self._bounds = (platforms.cell_bounds if not platforms.outside
                        else (-math.inf, -math.inf, math.inf, math.inf))

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        """The tiles that overlap the region, then the platforms that do (by number)."""
        found = self._tiles_in(left, top, right, bottom)
        low_x, low_y, high_x, high_y = self._bounds
        if not (left < high_x and low_x < right and top < high_y and low_y < bottom):
            return found  # far from every route (or NaN)
        routes = self._few_routes
        if routes is None:  # many platforms, or one off the map: the index answers
            found.extend(self.platforms.entries_in(left, top, right, bottom, self.without))
            return found
        if not (right > left and bottom > top):
            return found  # an empty region
        for r_left, r_top, r_right, r_bottom, platform in routes:
            if (left < r_right and r_left < right and top < r_bottom and r_top < bottom
                    and platform is not self.without):
                e_left, e_top, e_right, e_bottom, _, _ = entry = platform.entry
                if (e_left < right and left < e_right and e_top < bottom and top < e_bottom
                        and e_right > e_left and e_bottom > e_top):
                    found.append(entry)
        return found

    def shapes_in(self, region: Box) -> list[TileShape]:
        """The shapes (tiles, then platforms) whose box overlaps the region (strictly)."""
        x, y, w, h = region
        return [entry.shape for entry in self.entries_in(x, y, x + w, y + h)]

    def leaving_out(self, platform: Platform) -> LevelSolids:
        """The same solids less one platform: what that platform pushes bodies against."""
        return LevelSolids(self.tiles, self.platforms, platform)


@dataclass(frozen=True)
class Lookups:
    """The source each step of a tick asks for solid shapes.

    Plainly (:meth:`plain`) every field is the level's solids (the platforms' each less its
    own platform); an observer may wrap any of them, and the tick reads the same.
    """

    ledges: ShapeSource             # 1. the enemies' look-ahead for a ledge or a wall
    platforms: Sequence[ShapeSource]  # 2. what platform number n pushes and carries against
    x_sweep: ShapeSource            # 3. the x pass
    y_sweep: ShapeSource            # 4. the y pass, with its corner slide
    ground_probe: ShapeSource       # 4. the probe under the feet
    hazards: ShapeSource            # 7. the spikes along the player's path
    checkpoint_spawn: ShapeSource   # 7. where a counted flag puts the respawn
    penetration: ShapeSource        # measurement only: how deep a body sits in a solid

    @classmethod
    def plain(cls, solids: LevelSolids, platforms: Sequence[Platform]) -> Lookups:
        without = [solids.leaving_out(platform) for platform in platforms]
        return cls(solids, without, solids, solids, solids, solids, solids, solids)
