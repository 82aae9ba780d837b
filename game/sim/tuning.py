"""Every number that shapes how the game moves, with its unit in its name.

Where it sits: read by the entities when they choose velocities. A level can override the
four map properties of the contract (``gravity``, ``max_fall_speed``, ``run_speed``,
``jump_speed``); :meth:`Tuning.with_map_properties` applies them exactly as given (the
level loader has kept them within the ranges of ``game/levels/classes.py``).

What it teaches: speeds are in pixels per *second* and the tick length is explicit, so the
game runs the same whatever the frame rate; derived values (pixels per tick) are computed,
never typed in twice.

>>> t = Tuning().with_map_properties({"gravity": 100.0, "title": "ignored"})
>>> t.gravity_px_s2
100.0
>>> Tuning().coyote_ticks                # 0.1 s at 60 ticks a second
6
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

TICK_HZ = 60
TICK_S = 1.0 / TICK_HZ  # one simulation tick of game time


@dataclass(frozen=True)
class Tuning:
    """Movement tunables: the player's, the enemies' and the rules of the game."""

    run_speed_px_s: float = 90.0
    gravity_px_s2: float = 900.0
    jump_speed_px_s: float = 290.0
    max_fall_speed_px_s: float = 360.0
    # Game feel: how a run starts and stops, and the forgiving edges of a jump.
    run_accel_time_s: float = 0.05         # standing to full run speed, on the ground
    run_stop_time_s: float = 0.05          # full run speed to standing, on the ground
    air_accel_time_s: float = 0.10         # the same in the air: less grip, still steerable
    air_stop_time_s: float = 0.20
    jump_cut_ratio: float = 0.5            # upward speed kept when jump is released early
    coyote_time_s: float = 0.1             # a jump still works this long after a ledge
    jump_buffer_s: float = 0.1             # a jump pressed this long before landing happens
    corner_correction_px: float = 4.0      # a head bump this close to a ceiling's corner slides
    stomp_bounce_px_s: float = 200.0       # upward speed after stomping an enemy
    invulnerable_time_s: float = 1.5       # after losing a life, enemies and spikes can't hurt
    enemy_speed_px_s: float = 30.0         # default patrol speed (an Enemy's ``speed``)
    hopper_jump_speed_px_s: float = 220.0  # a hopper's take-off speed
    hopper_rest_s: float = 0.8             # how long a hopper sits between hops
    player_width_px: int = 12              # hitbox of a point-shaped Player spawn
    player_height_px: int = 14
    enemy_width_px: int = 14
    enemy_height_px: int = 12
    start_lives: int = 3
    stomp_points: int = 5                  # score for each enemy stomped (a coin: its value)
    tick_s: float = TICK_S

    @cached_property
    def invulnerable_ticks(self) -> int:
        return round(self.invulnerable_time_s / self.tick_s)

    @cached_property
    def hopper_rest_ticks(self) -> int:
        return round(self.hopper_rest_s / self.tick_s)

    @cached_property
    def coyote_ticks(self) -> int:
        return round(self.coyote_time_s / self.tick_s)

    @cached_property
    def jump_buffer_ticks(self) -> int:
        return round(self.jump_buffer_s / self.tick_s)

    def with_map_properties(self, properties: Mapping[str, object]) -> Tuning:
        """This tuning with a level's physics properties (px/s or px/s²) applied as given."""
        names = {
            "gravity": "gravity_px_s2",
            "max_fall_speed": "max_fall_speed_px_s",
            "run_speed": "run_speed_px_s",
            "jump_speed": "jump_speed_px_s",
        }
        changes: dict[str, Any] = {}
        for key, field_name in names.items():
            value = properties.get(key)
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                changes[field_name] = float(value)
        return replace(self, **changes)
