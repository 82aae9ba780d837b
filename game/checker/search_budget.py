"""How much work the solver may do on one map: a budget of moves that grows with the map.

Where it sits: :func:`game.checker.solver.solve` asks :func:`map_budget` for the budget of a
map unless ``--budget N`` gives one; :mod:`game.checker.verdict` says it when the search
stops without a route ("searched N moves of this map's budget of M").

What it teaches: **bound work by the size of the problem.** A fixed number of moves is too
few for a long maze and far too many for a small map the search cannot decide: every map
gets :data:`MOVES_PER_CELL` moves for each cell its route may pass through (the cells the
reach proof's fill reached, or else the open cells), at least :data:`MIN_BUDGET` and at
most :data:`MAX_BUDGET`. The budget counts moves, never seconds, so every machine gives
the same verdict. Each shipped level is solved within the plain moves' first turn of its
budget (:data:`~game.checker.solver.FIRST_PLAIN_SHARE`: 8 moves a reached cell; a test
keeps it so); a maze of corridors needs more than its route's tiles, as the search also
walks the corridors that lead nowhere (a serpentine of low corridors, with none, takes
about 6 moves a tile; ``tests/test_solver_search.py`` keeps it under 14).
"""

from __future__ import annotations

MOVES_PER_CELL = 40  # moves (6 ticks each) the search may try for each cell it may reach
MIN_BUDGET = 9_000  # moves, however small the map
MAX_BUDGET = 300_000  # moves, however large the map (about two minutes of a small map's work)


def map_budget(cells: int) -> int:
    """The moves the search may try on a map whose route may pass through ``cells`` cells.

    >>> map_budget(10), map_budget(1_000), map_budget(10**9)
    (9000, 40000, 300000)
    """
    return max(MIN_BUDGET, min(MAX_BUDGET, MOVES_PER_CELL * cells))
