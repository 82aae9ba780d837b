"""Which collision method each scene uses, and the measured thresholds behind each choice.

Where it sits: beside the broad phases, above :mod:`game.collision.broad.brute_force`. A scene that
has to
find overlapping pairs asks :func:`choose_broad_phase` how, or calls
:func:`build_broad_phase`; the thresholds are named constants, and each one's docstring cites
the benchmark result that set it (``python -m game.bench``, committed in ``assets/charts/``).

What it teaches: **model no more than a scene needs.** A spatial structure costs code and
bookkeeping on every move; it only pays once there are enough things to pair up. The level's
walls are already a grid (the tile map), so bodies ask :class:`~game.sim.tilegrid.TileGrid`;
the few dozen things a player can touch are tested one by one against the path it swept
(coins through ``pygame.sprite.groupcollide``; see :meth:`game.sim.world.World.step`). The
game makes those choices in that code, once, and reads nothing here. Only a crowd of movers
(the crate demo, the stress scene, the lab's crowds) needs a broad phase, and asks this
module which; below the crossover plain brute force is both simpler and faster.

>>> choose_broad_phase(5), choose_broad_phase(5_000)
('brute_force', 'grid')
>>> type(build_broad_phase(5_000, body_size_px=16)).__name__
'SpatialGrid'
>>> grid_cell_size_px(16)
32.0
"""

from __future__ import annotations

from typing import Final

from game.collision.broad.brute_force import BroadPhase, BruteForce
from game.collision.broad.spatial_grid import SpatialGrid

WALLS: Final = "tile_grid"
"""Bodies meet walls through :meth:`TileGrid.entries_in` and the swept axis moves: in the
committed run the lookup took 1.00x as long on an 800x160 map as on a 200x40 one, and was
42.0x faster than ``spritecollide`` over all 2,413 walls of the 200x40 map
(``assets/charts/walls.csv``, ``assets/charts/targets.csv``)."""

BROAD_PHASE_CROSSOVER_N: Final = 10
"""The grid beats brute force (every pair tested in Python) from N = 10 movers up in the
committed run (``assets/charts/broad_phase.csv``, marked on ``broad_phase.png``). The two
lines run close between 10 and 30, so runs place it anywhere there; below it, brute force
is as fast and has no structure to keep up to date."""

GRID_CELL_SIZE_FACTOR: Final = 2.0
"""A grid cell is this many typical body sizes across: the fastest of the factors 1 to 6
tried in the committed run, 5.80 ms per frame for 2,000 movers against 8.20 ms with cells
one body across (``assets/charts/grid_cells.csv``)."""


def choose_broad_phase(n: int) -> str:
    """``"brute_force"`` below :data:`BROAD_PHASE_CROSSOVER_N` movers, ``"grid"`` from there."""
    if n < 0:
        raise ValueError(f"a scene cannot hold {n} movers")
    return "brute_force" if n < BROAD_PHASE_CROSSOVER_N else "grid"


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
