"""How much each measurement does: a full run, ``--quick``, and the tests' tiny run.

Where it sits: chosen by :mod:`game.bench.__main__` and passed to every bench module, so the
modules hold no size of their own and the tests can run all of them in seconds.

What it teaches: the sizes are the experiment's design, so they are written down in one
place. A full run keeps the whole range of N and enough rounds for stable medians; the quick
run keeps the same methods and shapes with fewer rounds and a smaller top N; both check the
same targets.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Sizes:
    """Every size the bench uses; ``rounds`` is the number of interleaved timing rounds of
    a chart no target reads, ``verdict_rounds`` (30 or more) of every figure a target reads."""

    name: str
    rounds: int
    verdict_rounds: int
    min_s: float                      # each timed case runs for at least this long per round
    narrow_pairs: int                 # random pairs per shape family, for the error rates
    narrow_timed_pairs: int           # of those, how many one timed call runs through
    tunnel_flights: int               # head-on flights per speed and method
    tunnel_speeds: tuple[float, ...]  # tiles per tick
    broad_ns: tuple[int, ...]
    broad_budget_s: float             # no method runs where a frame would take longer than this
    grid_cell_factors: tuple[float, ...]
    grid_cell_n: int
    wall_maps: tuple[tuple[int, int], ...]   # (columns, rows)
    wall_queries: int
    cache_objects: int
    play_rounds: int                  # full plays of the shipped level
    width_ticks: int                  # ticks per round of the levels compared in game_step
    target_n: int                     # the broad-phase targets' N
    target_maps: tuple[tuple[int, int], tuple[int, int]]  # the lookup's flatness, small to big
    baseline_map: tuple[int, int]     # where the lookup is set against scanning every wall
    peer_moves: int                   # recorded moves of The Summit replayed per round
    peer_world_ticks: int             # ticks of The Summit per round of World.step


SPEEDS = tuple(k / 4 for k in range(1, 25))  # 0.25 to 6 tiles per tick

FULL = Sizes(
    name="full", rounds=7, verdict_rounds=40, min_s=0.005,
    narrow_pairs=4000, narrow_timed_pairs=400,
    tunnel_flights=2000, tunnel_speeds=SPEEDS,
    broad_ns=(10, 15, 20, 30, 50, 70, 100, 150, 200, 300, 500, 1000, 2000, 5000, 10000, 20000),
    broad_budget_s=2.0, grid_cell_factors=(1.0, 1.5, 2.0, 3.0, 4.0, 6.0), grid_cell_n=2000,
    wall_maps=((25, 5), (50, 10), (100, 20), (200, 40), (400, 80), (800, 160)), wall_queries=200,
    cache_objects=1000, play_rounds=5, width_ticks=120,
    target_n=1000, target_maps=((50, 10), (800, 160)), baseline_map=(200, 40),
    peer_moves=2000, peer_world_ticks=1200,
)

QUICK = Sizes(
    name="quick", rounds=3, verdict_rounds=30, min_s=0.002,
    narrow_pairs=400, narrow_timed_pairs=200,
    tunnel_flights=400, tunnel_speeds=SPEEDS[1::2],
    broad_ns=(10, 20, 30, 50, 100, 200, 500, 1000),
    broad_budget_s=0.1, grid_cell_factors=(1.0, 2.0, 3.0, 4.0), grid_cell_n=1000,
    wall_maps=((25, 5), (50, 10), (100, 20), (200, 40), (800, 160)), wall_queries=100,
    cache_objects=1000, play_rounds=1, width_ticks=30,
    target_n=1000, target_maps=((50, 10), (800, 160)), baseline_map=(200, 40),
    peer_moves=300, peer_world_ticks=120,
)

# The tests' run: every chart at these sizes. Its rows are checked for answers, not times;
# the narrow phase's error rates there come from 300 pairs of each family.
TINY = Sizes(
    name="tiny", rounds=2, verdict_rounds=3, min_s=0.0,
    narrow_pairs=300, narrow_timed_pairs=20,
    tunnel_flights=200, tunnel_speeds=(0.25, 1.0, 2.5, 6.0),
    broad_ns=(10, 40, 120), broad_budget_s=0.05, grid_cell_factors=(1.0, 2.0), grid_cell_n=60,
    wall_maps=((20, 6), (80, 12)), wall_queries=10,
    cache_objects=20, play_rounds=1, width_ticks=5,
    target_n=120, target_maps=((20, 6), (80, 12)), baseline_map=(80, 12),
    peer_moves=20, peer_world_ticks=10,
)
