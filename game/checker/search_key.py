"""When are two states of a search "the same"? The key the solver files them under.

Where it sits: :mod:`game.checker.solver` keeps only the first state it meets under each key,
so the key decides how much of the game's state space the search may skip.

What it teaches: **pruning on a grid.** Two states whose player is within a few pixels and a
few px/s of each other, standing or not, holding jump or not, with the same enemies left and
the same respawn place, almost always have the same futures; keeping one of them saves the
search from exploring both. Moving platforms matter too, but only those the player could
meet soon: a platform far away has time to come round again, so its place along its route
is left out of the key until the player comes near its route (:data:`NEAR_PX`). Without that,
every tick of waiting would make a new state for each far platform's phase. The phase is
counted in steps of :data:`PLATFORM_PHASE_PX` (two tiles): finer steps made the platform
levels cost more moves to solve, not fewer.

The key is a heuristic: it may merge two states whose futures differ, which can only make the
search miss a route, never report one that does not replay (every route is replayed).
"""

from __future__ import annotations

import math

from game.collision.aabb import Box
from game.sim.inputs import Action, Actions
from game.sim.platforms import Platform
from game.sim.world import World

SAME_PLACE_PX = 4.0  # states closer than this (and alike in speed) count as one
SAME_SPEED_PX_S = 30.0
FINE_PLACE_PX = 1.0  # ... or this, where inputs are timed to the tick
PLATFORM_PHASE_PX = 32.0  # moving platforms this close along their paths count as alike
NEAR_PX = 96.0  # a platform whose route comes this close to the player is in the key

StateKey = tuple[object, ...]


def route_box(platform: Platform) -> Box:
    """The region a platform's route sweeps (its box at every point of the path)."""
    xs = [x for x, _ in platform.spec.path.points]
    ys = [y for _, y in platform.spec.path.points]
    return Box(min(xs), min(ys), max(xs) - min(xs) + platform.spec.width_px,
               max(ys) - min(ys) + platform.spec.height_px)


def route_is_near(player: Box, region: Box) -> bool:
    dx = max(0.0, region.left - player.right, player.left - region.right)
    dy = max(0.0, region.top - player.bottom, player.top - region.bottom)
    return dx <= NEAR_PX and dy <= NEAR_PX


def _phase(platform: Platform) -> int:
    """Where a platform is along its round trip, in steps of PLATFORM_PHASE_PX."""
    spec = platform.spec
    steps = max(1, math.floor(2 * spec.path.length / PLATFORM_PHASE_PX))
    return math.floor(platform.travelled_px / PLATFORM_PHASE_PX) % steps


def state_key(world: World, held: Actions, routes: list[Box],
              place_px: float = SAME_PLACE_PX) -> StateKey:
    """The key of ``world``'s state after a move that held ``held`` (holding jump matters: a
    new jump needs a fresh press). ``routes``: each platform's :func:`route_box`;
    ``place_px``: how close two places must be to count as one (the solver's timed stage,
    which times its inputs to the tick, tells apart places :data:`FINE_PLACE_PX` apart)."""
    player = world.player
    box = player.box
    phases = tuple(_phase(platform) if route_is_near(box, region) else None
                   for platform, region in zip(world.platforms, routes, strict=True))
    return (round(box.x / place_px), round(box.y / place_px),
            round(player.vx / SAME_SPEED_PX_S), round(player.vy / SAME_SPEED_PX_S),
            player.on_ground, player.dropping_through, Action.JUMP in held,
            phases, len(world.enemies), world.spawn)
