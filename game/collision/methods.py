"""Which collision method each scene uses, and the measured thresholds behind each choice.

Where it sits: beside the broad phases, above :mod:`game.collision.broad.brute_force`. A scene
that has to find overlapping pairs asks :func:`choose_broad_phase` how, or calls
:func:`build_broad_phase`; one with walls can ask :func:`choose_walls`. The thresholds are
named constants, and each one's docstring cites the benchmark result that set it
(``python -m game.bench``, committed in ``assets/charts/``); ``tests/test_bench.py`` checks
each against the committed CSVs, so the code and the run the README quotes agree.

What it teaches: **model no more than a scene needs.** A spatial structure costs code and
bookkeeping on every move; it only pays once there are enough things to pair up. The level's
walls are already a grid (the tile map), so bodies ask :class:`~game.collision.tile_grid.TileGrid`;
the few dozen things a player can touch are tested one by one against the path it swept
(the coins among them; see :meth:`game.sim.world.World.step`). The
game makes those choices in that code, once, and reads nothing here. Only a crowd of movers
(the crate demo, the stress scene, the lab's crowds) needs a broad phase, and asks this
module which; below the crossover plain brute force is both simpler and faster. The same
holds for walls: on a map of a few hundred tiles, scanning every wall rect with
``collidelistall`` (a loop in C) is as fast as the lookup. The levels keep the lookup at
every size (one code path, a few µs a query at worst); :func:`choose_walls` says from which
map size the lookup wins, for a scene that weighs a scan against it.

>>> choose_broad_phase(5), choose_broad_phase(5_000)
('brute_force', 'grid')
>>> type(build_broad_phase(5_000, body_size_px=16)).__name__
'SpatialGrid'
>>> grid_cell_size_px(16)
48.0
"""

from __future__ import annotations

from typing import Final

from game.collision.broad.brute_force import BroadPhase, BruteForce
from game.collision.broad.spatial_grid import SpatialGrid

WALLS: Final = "tile_grid"
"""Bodies meet walls through :meth:`TileGrid.entries_in` and the swept axis moves: the lookup
costs the same on a map of 500 tiles or of 128,000, while a scan of every wall grows with
the walls (``assets/charts/walls.csv``; the flatness and the lead over ``spritecollide``
and ``collidelistall`` are targets in ``assets/charts/targets.csv``)."""

WALL_SCAN: Final = "collidelistall"
"""Below :data:`TILE_LOOKUP_FROM_TILES` the lookup was not measurably faster than a scan of
every wall rect with ``Rect.collidelistall`` (its loop in C), which needs no grid at all."""

TILE_LOOKUP_FROM_TILES: Final = 500
"""The tile lookup beats ``collidelistall`` over every wall from a map of this many tiles on:
the smallest map of the committed run from which, on every bigger map too, the scan's time
over the lookup's has its whole 95 % interval above 1 (``assets/charts/walls.csv``, marked
on ``walls.png``; ``tests/test_bench.py`` checks it against that file)."""

BROAD_PHASE_CROSSOVER_N: Final = 10
"""The grid beats brute force (every pair tested in Python) from this many movers up in the
committed run (``assets/charts/broad_phase.csv``, marked on ``broad_phase.png``;
``tests/test_bench.py`` checks it against that file). The two lines run close between 10
and 30, so runs place it anywhere there; below it, brute force is as fast and has no
structure to keep up to date."""

GRID_CELL_SIZE_FACTOR: Final = 3.0
"""A grid cell is this many typical body sizes across: of the factors tried in the committed
run, the smallest within 5 % of the fastest (``assets/charts/grid_cells.csv``, drawn on
``grid_cells.png``; ``tests/test_bench.py`` checks it against that file)."""


def choose_broad_phase(n: int) -> str:
    """``"brute_force"`` below :data:`BROAD_PHASE_CROSSOVER_N` movers, ``"grid"`` from there."""
    if n < 0:
        raise ValueError(f"a scene cannot hold {n} movers")
    return "brute_force" if n < BROAD_PHASE_CROSSOVER_N else "grid"


def choose_walls(cols: int, rows: int) -> str:
    """How a map of ``cols`` x ``rows`` tiles should find the walls near a body:
    :data:`WALL_SCAN` below :data:`TILE_LOOKUP_FROM_TILES` tiles, :data:`WALLS` from there.

    >>> choose_walls(20, 10), choose_walls(200, 40)
    ('collidelistall', 'tile_grid')
    """
    if cols < 0 or rows < 0:
        raise ValueError(f"a map cannot be {cols} x {rows} tiles")
    return WALL_SCAN if cols * rows < TILE_LOOKUP_FROM_TILES else WALLS


def grid_cell_size_px(body_size_px: float) -> float:
    """The grid cell size for bodies of about this size (px)."""
    if not body_size_px > 0:
        raise ValueError(f"the body size must be > 0 px, not {body_size_px}")
    return GRID_CELL_SIZE_FACTOR * body_size_px


def build_broad_phase(n: int, body_size_px: float) -> BroadPhase[int]:
    """An empty broad phase for about ``n`` movers of about ``body_size_px`` across."""
    if choose_broad_phase(n) == "grid":
        return SpatialGrid(cell_size_px=grid_cell_size_px(body_size_px))
    return BruteForce()
