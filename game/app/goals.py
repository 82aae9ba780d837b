"""Goals to chase in a level: its coins of their total, and a medal for beating its target time.

Where it sits: beside the menus and the level-end banner, which show what it works out. The
target comes from the map property ``target_seconds`` (:mod:`game.levels.classes`; a map
without it, or with 0, has no target and shows no medal). The level select shows the medal
for the best time kept (:class:`game.app.menus.LevelEntry`), the banner for the finish just
made (:mod:`game.app.banner`). A finish with an assist on (:mod:`game.app.settings`) earns
none.

What it teaches: **compare times in the unit the game counts in.** The game counts whole
1/60 s ticks; a target written in seconds is turned into the last tick within it once
(:func:`target_ticks`), so 10.1 s means 606 ticks, not "606 ticks are 10.100000000000001 s,
which is over".

>>> target_ticks({"target_seconds": 10.1}), target_ticks({}), target_ticks({"target_seconds": 0.0})
(606, None, None)
>>> earns_medal(606, 606), earns_medal(607, 606), earns_medal(500, None)
(True, False, False)
>>> of_total(3, 5)
'3 of 5'
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from game.sim.tuning import TICK_HZ

TARGET_PROPERTY = "target_seconds"  # the map property that sets a level's target time
ROUNDING_TICKS = 1e-6  # a target this close under a whole tick counts as that tick
NONE_YET = "\N{EM DASH}"  # a count not made yet


def target_ticks(properties: Mapping[str, object]) -> int | None:
    """The last tick a finish may take to earn the medal, or None if the level has no target."""
    seconds = properties.get(TARGET_PROPERTY)
    if isinstance(seconds, bool) or not isinstance(seconds, int | float) or seconds <= 0:
        return None
    return math.floor(seconds * TICK_HZ + ROUNDING_TICKS)


def earns_medal(ticks: int, target: int | None, assisted: bool = False) -> bool:
    """A finish in ``ticks`` earns the medal when it is at or under the ``target`` (in ticks)
    and no assist was on."""
    return target is not None and not assisted and ticks <= target


def of_total(taken: int | None, total: int) -> str:
    """A count of what a level holds as the level select and the tally show it: ``n of N``
    (a dash of N when there is no count yet)."""
    return f"{NONE_YET if taken is None else taken} of {total}"
