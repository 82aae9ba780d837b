"""The query log: every lookup a tick made, written down by a wrapper round the solids.

Where it sits: outside the collision path. While the debug overlay is on
(:class:`game.sim.world.Measure` ``queries``), the world asks its solids through
:func:`logged_lookups`: each step's source is wrapped in a :class:`LoggedSource` that
writes down what asked, the block of cells the lookup visited and the moving shapes it
tested beside the tiles, and adds up the work, then answers exactly as the plain source
does. A body's move (:func:`game.collision.axis_sweep.move_body`) asks one source for its
x pass, its y pass and its ground probe; :class:`LoggedMoves` tells them apart by the
function that asked. The overlay draws the cells and shapes from this log (nothing else
was tested).

What it teaches: **instrument from outside.** The grid's query and the tick stay plain; the
counting and the logging are a layer a reader can take away without touching either.
"""

from __future__ import annotations

import sys
from collections.abc import Iterator
from dataclasses import dataclass, field
from math import isfinite
from typing import NamedTuple

from game.collision.shapes import Entry, TileShape
from game.collision.tile_grid import QueryStats
from game.sim.solids import LevelSolids, Lookups


class Query(NamedTuple):
    """One lookup as the log keeps it: what asked, the block of cells visited (inclusive,
    empty when ``first_col > last_col``), and the moving shapes tested beside the tiles."""

    purpose: str
    first_col: int
    last_col: int
    first_row: int
    last_row: int
    extra: tuple[TileShape, ...] = ()

    def cells(self) -> Iterator[tuple[int, int]]:
        for row in range(self.first_row, self.last_row + 1):
            for col in range(self.first_col, self.last_col + 1):
                yield col, row


@dataclass
class QueryLog:
    """Every lookup made through a :class:`LoggedSource` since it was last cleared, and the
    work they did; the world clears it at the start of each tick it logs."""

    queries: list[Query] = field(default_factory=list)
    stats: QueryStats = field(default_factory=QueryStats)

    def clear(self) -> None:
        self.queries.clear()
        self.stats.reset()


NO_CELLS = (0, -1, 0, -1)  # a block with no cell: a lookup wholly off the map


@dataclass(frozen=True)
class LoggedSource:
    """The level's solids, answering as ever, with each lookup written down under
    ``purpose`` in ``log``."""

    solids: LevelSolids
    log: QueryLog
    purpose: str

    @property
    def width_px(self) -> int:
        return self.solids.width_px

    @property
    def height_px(self) -> int:
        return self.solids.height_px

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        return self._written_down(self.purpose, left, top, right, bottom)

    def _written_down(self, purpose: str, left: float, top: float, right: float,
                      bottom: float) -> list[Entry]:
        """Answer the query; log the cells it visited and the platforms it tested under
        ``purpose``, and count the work."""
        found = self.solids.entries_in(left, top, right, bottom)
        if not (right > left and bottom > top and isfinite(left + top + right + bottom)):
            return found
        solids, stats = self.solids, self.log.stats
        block = stats.count(solids.tiles, left, top, right, bottom) or NO_CELLS
        platforms = solids.platforms.tested_in(left, top, right, bottom, solids.without)
        stats.shapes_tested += len(platforms)
        self.log.queries.append(Query(purpose, *block,
                                      extra=tuple(p.shape for p in platforms)))
        return found


# The part of a body's move that asks, by the name of its function, and the purpose its
# lookups are written down under (the corner slide's moves count as the y pass).
MOVE_PARTS = {"slide_past_ceiling_corner": "y sweep", "move_x": "x sweep",
              "move_y": "y sweep", "ground_under": "ground probe"}


@dataclass(frozen=True)
class LoggedMoves(LoggedSource):
    """The source of the bodies' moves, each lookup written down under the part of the move
    that asked: the function calling this query, or the corner slide calling it."""

    purpose: str = "moves"

    def entries_in(self, left: float, top: float, right: float, bottom: float,
                   ) -> list[Entry]:
        asking = sys._getframe(1)  # move_x, move_y or ground_under
        part = MOVE_PARTS.get(asking.f_code.co_name, self.purpose)
        caller = asking.f_back  # move_body, or the corner slide
        if caller is not None:
            part = MOVE_PARTS.get(caller.f_code.co_name, part)
        return self._written_down(part, left, top, right, bottom)


def logged_lookups(solids: LevelSolids, log: QueryLog) -> Lookups:
    """Each step's source wrapped to write its lookups in ``log`` under the step's name."""
    def logged(source: LevelSolids, purpose: str) -> LoggedSource:
        return LoggedSource(source, log, purpose)

    return Lookups(
        ledges=logged(solids, "ledge look-ahead"),
        platforms=[logged(solids.leaving_out(platform), "platforms")
                   for platform in solids.platforms.platforms],
        moving_bodies=LoggedMoves(solids, log),
        hazards=logged(solids, "hazards"),
        checkpoint_spawn=logged(solids, "checkpoint spawn"),
        penetration=logged(solids, "penetration (measurement)"),
    )
