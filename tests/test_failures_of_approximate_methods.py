"""The known failures of the cheap methods, pinned: each test asserts the wrong answer.

If one of these starts failing, either the approximation got better (say so in its module)
or the case no longer shows the failure (fix the case, do not delete the lesson).
"""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.collision.circles import Circle
from game.collision.composite import l_shape
from game.collision.masks import circle_mask, collide, polygon_mask
from game.collision.sat import Polygon, oriented_box
from game.collision.sat import collide as sat_collide
from game.collision.swept import (
    clamp_speed,
    discrete_hit,
    position_at,
    steps_needed,
    substep_hit,
    sweep,
)

# ---------------------------------------------------------------------------------------------
# One box around a shape that is not a box


def test_aabb_reports_false_hits_for_circles_meeting_in_the_corner_region() -> None:
    a, b = Circle(0, 0, 10), Circle(15, 15, 10)     # centres 21.2 apart, radii sum 20
    assert a.bounds().overlaps(b.bounds())          # the boxes say hit...
    assert not a.overlaps(b)                        # ...the circles do not touch
    assert not collide(circle_mask(a), circle_mask(b))


@settings(max_examples=200, deadline=None)
@given(st.builds(Circle, st.floats(-20, 20), st.floats(-20, 20), st.floats(0.5, 10)),
       st.builds(Circle, st.floats(-20, 20), st.floats(-20, 20), st.floats(0.5, 10)))
def test_aabb_on_circles_only_ever_errs_towards_a_hit(a: Circle, b: Circle) -> None:
    if a.overlaps(b):
        assert a.bounds().overlaps(b.bounds())


def test_aabb_reports_false_hits_for_a_rotated_bar() -> None:
    bar = oriented_box(50, 50, 40, 3, math.pi / 4)  # a 80 x 6 bar on the diagonal
    coin = Box(65, 22, 8, 8)                        # in the empty top-right of its bounds
    assert bar.bounds().overlaps(coin)
    assert sat_collide(bar, Polygon.from_box(coin)) is None
    assert not collide(polygon_mask(bar), polygon_mask(Polygon.from_box(coin)))


def test_one_box_over_an_l_shape_reports_false_hits_the_composite_does_not() -> None:
    crate = l_shape(0, 0, width=48, height=48, thickness=16)
    in_the_notch = Box(24, 8, 12, 12)
    on_the_column = Box(4, 8, 12, 12)
    assert crate.bounds().overlaps(in_the_notch) and not crate.overlaps(in_the_notch)
    assert crate.bounds().overlaps(on_the_column) and crate.overlaps(on_the_column)


# ---------------------------------------------------------------------------------------------
# Checking positions instead of the path between them

BODY = Box(0, 0, 10, 10)
THIN_WALL = Box(30, 0, 4, 10)


def test_a_discrete_check_lets_a_fast_body_pass_through_a_thin_wall() -> None:
    assert not discrete_hit(BODY, 100, 0, THIN_WALL)            # the end position is clear
    assert sweep(BODY, 100, 0, THIN_WALL) == (0.2, -1, 0)        # but the path is not


def test_substepping_with_too_few_steps_also_tunnels() -> None:
    assert substep_hit(BODY, 100, 0, THIN_WALL, 2) is None      # samples at x = 50 and 100
    enough = steps_needed(BODY.w, 100)
    assert enough == 10
    assert substep_hit(BODY, 100, 0, THIN_WALL, enough) == 0.3  # x = 30: first overlap


def test_substepping_misses_a_clipped_corner_even_with_steps_needed() -> None:
    # Moving (10, 10) the body clips the bottom-left corner of the wall between t = 0.2 and
    # 0.7; one step per body size means one sample, at t = 1, below the wall.
    wall = Box(12, -20, 10, 27)
    steps = max(steps_needed(BODY.w, 10), steps_needed(BODY.h, 10))
    assert steps == 1
    assert substep_hit(BODY, 10, 10, wall, steps) is None
    assert sweep(BODY, 10, 10, wall) == (0.2, -1, 0)
    assert position_at(BODY, 10, 10, 0.5).overlaps(wall)        # the overlap is real


# ---------------------------------------------------------------------------------------------
# Clamping the speed


def contact_tick(gap_px: int, speed_px_per_tick: float, cap_px_per_tick: float) -> int:
    """Tick (1-based) in which a body ``gap_px`` from a wall, moving right at the clamped
    speed and checked by swept AABB, first makes contact."""
    body = BODY
    wall = Box(BODY.right + gap_px, 0, 16, 10)
    dx, _ = clamp_speed(speed_px_per_tick, 0, cap_px_per_tick)
    for tick in range(1, 10_000):
        if sweep(body, dx, 0, wall) is not None:
            return tick
        body = position_at(body, dx, 0, 1.0)
    raise AssertionError("no contact in 10 000 ticks")


def test_speed_clamping_delays_contact_by_a_computable_number_of_ticks() -> None:
    # 100 px away at 30 px/tick: 3 ticks cover 90 px, contact in tick 4.
    # Clamped to 8 px/tick: 12 ticks cover 96 px, contact in tick 13. Nine ticks late.
    assert contact_tick(100, 30, 1_000) == 4
    assert contact_tick(100, 30, 8) == 13


@settings(max_examples=150, deadline=None)
@given(st.integers(0, 200), st.integers(1, 60), st.integers(1, 60))
def test_the_delay_from_clamping_is_gap_over_cap_minus_gap_over_speed(gap: int, speed: int,
                                                                      cap: int) -> None:
    # Contact comes in tick gap // v + 1 (ending exactly flush is not contact: the next
    # tick starts flush and hits at t = 0), so clamping to ``cap`` costs this many ticks:
    delay = gap // min(speed, cap) - gap // speed
    assert contact_tick(gap, speed, cap) - contact_tick(gap, speed, 10_000) == delay
