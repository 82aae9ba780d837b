"""The checker's reach fills of the shipped levels, worked out once for every test that checks
them.

The map checks (:mod:`game.checker.designer_checks`) fill the player's reach from the spawn to
find Coins no jump reaches: the dearest part of checking a map without a search. The fill is
a function of the loaded level alone (the folder it was read from aside) and starts from a
world no tick has moved, so a test checking the shipped levels, or copies of them that load
to the same :class:`Level`, may be handed the fill worked out once for each shipped level
(:func:`share_fills`); a level equal to none of them gets its own fill, and is listed.
"""

from __future__ import annotations

import functools
from dataclasses import replace
from pathlib import Path

import pytest

from game.checker import designer_checks
from game.checker.reachable import FillWork, Reach, reachable
from game.collision.aabb import Box
from game.levels import LEVELS_DIR, load_level
from game.sim.level import Level
from game.sim.tuning import Tuning
from game.sim.world import World

SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))

FillKey = tuple[Level, Tuning, Box, bool]  # the level, its physics, the spawn, narrow or not
Fills = tuple[tuple[FillKey, Reach | None], ...]


def folderless(level: Level) -> Level:
    """``level`` with its own path and its ``next_level`` made relative to the folder it was
    read from (the one thing a copy of the project may change)."""
    folder = level.path.parent
    return replace(level, path=level.path.relative_to(folder), next_level=None
                   if level.next_level is None else level.next_level.relative_to(folder))


def fill_key(world: World, narrow: bool) -> FillKey:
    return folderless(world.level), world.tuning, world.spawn, narrow


@functools.cache  # one fill of each kind for each shipped level, whichever test asks first
def shipped_fills() -> Fills:
    """The fills the map checks ask for on every shipped level (the narrow one, and the full
    one when a Coin lies outside it): the checks are run on each level, the fills kept."""
    fills: list[tuple[FillKey, Reach | None]] = []

    def fill(world: World, work: FillWork | None = None, narrow: bool = False
             ) -> Reach | None:
        reach = reachable(world, work, narrow)
        if work is None:
            fills.append((fill_key(world, narrow), reach))
        return reach

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(designer_checks, "reachable", fill)
        for level in SHIPPED:
            designer_checks.designer_findings(level, load_level(level))
    return tuple(fills)


def share_fills(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """Until ``monkeypatch`` is undone, the map checks' fill of a level equal to a shipped
    one is the shipped level's; the list returned names the levels given a fill of their own
    (a test that expects none asserts it is empty)."""
    known, own = shipped_fills(), []

    def fill(world: World, work: FillWork | None = None, narrow: bool = False
             ) -> Reach | None:
        key = fill_key(world, narrow)
        for shipped, reach in known:
            if work is None and shipped == key:
                return reach
        own.append(world.level.path)
        return reachable(world, work, narrow)

    monkeypatch.setattr(designer_checks, "reachable", fill)
    return own
