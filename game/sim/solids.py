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
platforms, and the platforms' index nothing of tiles; a third small object asks both. A
level with no moving platform has nothing to join: its lookups ask the tiles alone.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from game.collision.aabb import Box
from game.collision.shapes import Entry, ShapeSource, TileShape
from game.collision.tile_grid import TileGrid
from game.sim.platforms import Platform, PlatformIndex


class LevelSolids:
    """The tiles and the moving platforms, asked as one; ``without`` leaves out the
    platform that is itself moving (it must not stop what it pushes or carries)."""

    __slots__ = ("height_px", "platforms", "tiles", "width_px", "without")

    def __init__(self, tiles: TileGrid, platforms: PlatformIndex,
                 without: Platform | None = None) -> None:
        self.tiles, self.platforms, self.without = tiles, platforms, without
        self.width_px, self.height_px = tiles.width_px, tiles.height_px

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        """The tiles that overlap the region (:meth:`TileGrid.entries_in`), then the
        platforms that do, by number (:meth:`PlatformIndex.entries_in`). The platforms are
        asked only when the region meets the block of cells that holds every route (or a
        route leaves the map): most regions lie far from every platform."""
        found = self.tiles.entries_in(left, top, right, bottom)
        platforms = self.platforms
        low_x, low_y, high_x, high_y = platforms.cell_bounds
        if platforms.outside or (left < high_x and low_x < right and top < high_y
                                 and low_y < bottom):
            found += platforms.entries_in(left, top, right, bottom, self.without)
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
    own platform), or its tiles alone when it has no moving platform; an observer may wrap
    any of them, and the tick reads the same.
    """

    ledges: ShapeSource             # 1. the enemies' look-ahead for a ledge or a wall
    platforms: Sequence[ShapeSource]  # 2. what platform number n pushes and carries against
    moving_bodies: ShapeSource      # 3-4. each body's move: x pass, y pass, ground probe
    hazards: ShapeSource            # 7. the spikes along the player's path
    checkpoint_spawn: ShapeSource   # 7. where a counted flag puts the respawn
    penetration: ShapeSource        # measurement only: how deep a body sits in a solid

    @classmethod
    def plain(cls, solids: LevelSolids, platforms: Sequence[Platform]) -> Lookups:
        if not platforms:
            tiles = solids.tiles
            return cls(tiles, [], tiles, tiles, tiles, tiles)
        without = [solids.leaving_out(platform) for platform in platforms]
        return cls(solids, without, solids, solids, solids, solids)
