"""The solver's route through each shipped level, searched once for every test that asks.

The search is bounded by work, not by time, and plays a level loaded afresh from its file:
the same level gives the same moves and the same route every time. So the test that every
shipped level is solved (``tests/test_solver.py``) and the tests that pin how few moves the
search needs on one of them (``tests/test_solver_search.py``) may share one solving of each
level, the dearest work of the suite's searches.
"""

from __future__ import annotations

import functools
from pathlib import Path

from game.checker.solver import Solution, solve
from game.levels import LEVELS_DIR, load_level


@functools.cache
def solved(level: Path) -> Solution:
    """What :func:`solve` finds on the shipped level at ``level`` with the default effort."""
    return solve(load_level(level))


def solved_shipped(name: str) -> Solution:
    """The same for a shipped level named by its file's stem (``"11-dusk-rhythm"``)."""
    return solved(LEVELS_DIR / f"{name}.tmx")
