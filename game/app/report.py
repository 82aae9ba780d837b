"""The JSON report of a run (``--report FILE``), with every key the contract lists.

Where it sits: read off the campaign at the end of a run. The same inputs on the same level
give the same report, except the ``timing`` figures, which measure this machine.

What it teaches: **what a run keeps per tick must be bounded.** The timing figures come
from a fixed-size :class:`Reservoir` sample, so a run of a million ticks holds no more than
one of ten thousand.
"""

from __future__ import annotations

import random
import statistics
from dataclasses import dataclass, field
from typing import Any

from game.sim.campaign import Campaign

TIMING_SAMPLE_SIZE = 10_000  # ticks of timing kept: every tick of a run up to 2.8 minutes


class Reservoir:
    """A fixed-size, evenly drawn sample of a stream of numbers (Vitter's Algorithm R).

    The first ``size`` values are all kept; after that, the n-th value replaces a random
    kept one with probability ``size / n``, so every value seen so far is equally likely to
    be in the sample. A run of any length keeps the same memory, and its median and 95th
    percentile are those of the sample: exact up to ``size`` ticks, estimates after. The
    random draws are seeded, so the same run keeps the same sample.

    >>> sample = Reservoir(size=100)
    >>> for value in range(10_000):
    ...     sample.add(float(value))
    >>> len(sample.values), sample.seen, sample.last
    (100, 10000, 9999.0)
    """

    def __init__(self, size: int = TIMING_SAMPLE_SIZE, seed: int = 0) -> None:
        self.size = size
        self.values: list[float] = []
        self.seen = 0
        self.last = 0.0
        self._random = random.Random(seed)

    def add(self, value: float) -> None:
        self.seen += 1
        self.last = value
        if len(self.values) < self.size:
            self.values.append(value)
            return
        slot = self._random.randrange(self.seen)
        if slot < self.size:
            self.values[slot] = value


@dataclass
class Timing:
    """Per-tick wall-clock costs in seconds, collected by the runner, in fixed memory."""

    update_s: Reservoir = field(default_factory=Reservoir)
    collision_s: Reservoir = field(default_factory=lambda: Reservoir(seed=1))

    def add(self, update_s: float, collision_s: float) -> None:
        self.update_s.add(update_s)
        self.collision_s.add(collision_s)

    @property
    def last_update_s(self) -> float:
        """How long the last tick took (0 before the first)."""
        return self.update_s.last

    def summary(self) -> dict[str, float]:
        update, collision = self.update_s.values, self.collision_s.values
        return {
            "update_ms_median": _ms(statistics.median(update)) if update else 0.0,
            "update_ms_p95": _ms(_percentile(update, 0.95)),
            "collision_ms_median": _ms(statistics.median(collision)) if collision else 0.0,
        }


def _ms(seconds: float) -> float:
    return round(seconds * 1000.0, 4)


def _percentile(values: list[float], q: float) -> float:
    """The q-quantile by the nearest-rank rule: an actual measured value.

    >>> _percentile([5.0, 1.0, 3.0, 2.0, 4.0], 0.95)
    5.0
    """
    if not values:
        return 0.0
    ordered = sorted(values)
    rank = max(0, min(len(ordered) - 1, -(-len(ordered) * q // 1) - 1))
    return ordered[int(rank)]


def build_report(campaign: Campaign, level_label: str, timing: Timing) -> dict[str, Any]:
    world = campaign.world
    player = world.player
    return {
        "ticks": campaign.ticks,
        "outcome": campaign.outcome.value,
        "level": level_label,
        "levels_completed": campaign.levels_completed,
        "score": campaign.score,
        "coins_collected": campaign.coins_collected,
        "coins_left": len(world.coins),
        "enemies_stomped": campaign.enemies_stomped,
        "enemies_left": len(world.enemies),
        "lives": campaign.lives,
        "deaths": campaign.deaths,
        "player": {
            "x": float(player.box.x),
            "y": float(player.box.y),
            "width": int(player.box.w),
            "height": int(player.box.h),
            "vx": float(player.vx),
            "vy": float(player.vy),
            "on_ground": bool(player.on_ground),
        },
        "max_penetration_px": float(campaign.max_penetration_px),
        "timing": timing.summary(),
    }
