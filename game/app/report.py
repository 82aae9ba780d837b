"""The JSON report of a run (``--report FILE``), with every key the contract lists.

Where it sits: read off the campaign at the end of a run. The same inputs on the same level
give the same report, except the ``timing`` figures, which measure this machine.
"""

from __future__ import annotations

import statistics
from dataclasses import dataclass, field
from typing import Any

from game.sim.campaign import Campaign


@dataclass
class Timing:
    """Per-tick wall-clock costs in seconds, collected by the runner."""

    update_s: list[float] = field(default_factory=list)
    collision_s: list[float] = field(default_factory=list)

    def add(self, update_s: float, collision_s: float) -> None:
        self.update_s.append(update_s)
        self.collision_s.append(collision_s)

    def summary(self) -> dict[str, float]:
        return {
            "update_ms_median": _ms(statistics.median(self.update_s)) if self.update_s else 0.0,
            "update_ms_p95": _ms(_percentile(self.update_s, 0.95)),
            "collision_ms_median": (_ms(statistics.median(self.collision_s))
                                    if self.collision_s else 0.0),
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
