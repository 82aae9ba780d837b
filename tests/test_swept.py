"""Swept AABB: faces, flush stops, the corner tie rule, bad numbers, and the sub-step oracle."""

from __future__ import annotations

import math

import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.collision.swept import (
    Contact,
    clamp_speed,
    discrete_hit,
    position_at,
    steps_needed,
    substep_hit,
    sweep,
)

QUICK = settings(max_examples=200, deadline=None)
BODY = Box(0, 0, 10, 10)

# ---------------------------------------------------------------------------------------------
# Faces and flush contacts


@pytest.mark.parametrize(("dx", "dy", "wall", "expected"), [
    (20, 0, Box(15, 0, 5, 10), Contact(0.25, -1, 0)),    # right, into a left face
    (-20, 0, Box(-10, 0, 5, 10), Contact(0.25, 1, 0)),   # left, into a right face
    (0, 20, Box(0, 15, 10, 5), Contact(0.25, 0, -1)),    # down, onto a top: a landing
    (0, -20, Box(0, -10, 10, 5), Contact(0.25, 0, 1)),   # up, into a bottom: a head bump
], ids=["right", "left", "down", "up"])
def test_a_straight_move_hits_the_face_in_front(dx: float, dy: float, wall: Box,
                                                expected: Contact) -> None:
    assert sweep(BODY, dx, dy, wall) == expected


def test_ending_exactly_flush_is_not_a_hit() -> None:
    assert sweep(BODY, 5, 0, Box(15, 0, 5, 10)) is None


def test_starting_flush_and_pushing_in_hits_at_time_zero() -> None:
    assert sweep(BODY, 3, 0, Box(10, 0, 5, 10)) == Contact(0.0, -1, 0)


def test_starting_flush_and_moving_away_is_not_a_hit() -> None:
    assert sweep(BODY, -3, 0, Box(10, 0, 5, 10)) is None


def test_sliding_along_a_floor_is_not_a_hit() -> None:
    assert sweep(BODY, 50, 0, Box(-100, 10, 300, 16)) is None


def test_starting_inside_reports_time_zero_and_no_face() -> None:
    assert sweep(BODY, 4, 4, Box(5, 5, 10, 10)) == Contact(0.0, 0, 0)
    assert sweep(BODY, 0, 0, Box(5, 5, 10, 10)) == Contact(0.0, 0, 0)
    assert sweep(BODY, 20, 0, Box(9, 0, 10, 10)) == Contact(0.0, 0, 0)   # 1 px deep, fast


def test_standing_still_next_to_a_wall_is_not_a_hit() -> None:
    assert sweep(BODY, 0, 0, Box(10, 0, 5, 10)) is None


def test_passing_exactly_over_a_corner_is_not_a_hit() -> None:
    # At t = 0.5 the body's bottom-right corner is the wall's top-left corner, then it leaves.
    assert sweep(BODY, 20, -20, Box(20, 0, 10, 10)) is None
    assert substep_hit(BODY, 20, -20, Box(20, 0, 10, 10), 1024) is None


@pytest.mark.parametrize("empty", [Box(20, 0, 0, 10), Box(20, 0, 10, 0), Box(20, 0, -5, 10)])
def test_empty_walls_are_never_hit(empty: Box) -> None:
    assert sweep(BODY, 40, 0, empty) is None
    assert sweep(Box(0, 0, 0, 10), 40, 0, Box(20, 0, 10, 10)) is None


# ---------------------------------------------------------------------------------------------
# The corner tie rule: both axes enter at once, y wins, every run


@pytest.mark.parametrize(("dx", "dy", "wall", "normal"), [
    (20, 20, Box(20, 20, 10, 10), (0, -1)),      # down-right onto a top-left corner
    (-20, 20, Box(-20, 20, 10, 10), (0, -1)),    # down-left onto a top-right corner
    (20, -20, Box(20, -20, 10, 10), (0, 1)),     # up-right into a bottom-left corner
    (-20, -20, Box(-20, -20, 10, 10), (0, 1)),   # up-left into a bottom-right corner
], ids=["down-right", "down-left", "up-right", "up-left"])
def test_an_outer_corner_hit_dead_on_resolves_on_the_y_axis(dx: float, dy: float, wall: Box,
                                                            normal: tuple[int, int]) -> None:
    results = {sweep(BODY, dx, dy, wall) for _ in range(5)}
    assert results == {Contact(0.5, *normal)}


def test_a_corner_just_off_the_diagonal_names_the_face_that_entered_last() -> None:
    assert sweep(BODY, 20, 20, Box(20, 21, 10, 10)) == Contact(0.55, 0, -1)
    assert sweep(BODY, 20, 20, Box(21, 20, 10, 10)) == Contact(0.55, -1, 0)


def test_a_corner_touch_at_the_start_pushing_diagonally_in_resolves_on_y() -> None:
    assert sweep(BODY, 1, 1, Box(10, 10, 10, 10)) == Contact(0.0, 0, -1)


# ---------------------------------------------------------------------------------------------
# Stability: sub-pixel speeds, negative and huge coordinates, bad numbers


def test_a_sub_pixel_speed_reaches_the_wall_on_the_tick_it_should() -> None:
    body, wall, speed = BODY, Box(10.3, 0, 4, 10), 0.125   # 0.3 px gap, 1/8 px per tick
    contacts = []
    for _ in range(3):
        contacts.append(sweep(body, speed, 0, wall))
        body = position_at(body, speed, 0, 1.0)
    # After 2 ticks the gap is 0.05 px: 0.4 of the third tick's move.
    assert contacts[:2] == [None, None]
    assert contacts[2] is not None and contacts[2].t == pytest.approx(0.4)


dyadic = st.integers(-4000, 4000).map(lambda n: n / 8)   # exact in binary floating point


@QUICK
@given(dyadic, dyadic, st.integers(-60, 60), st.integers(-60, 60),
       st.builds(Box, st.integers(-40, 40), st.integers(-40, 40), st.integers(1, 30),
                 st.integers(1, 30)))
def test_moving_the_whole_scene_changes_nothing(ox: float, oy: float, dx: int, dy: int,
                                                wall: Box) -> None:
    here = sweep(BODY, dx, dy, wall)
    there = sweep(BODY.moved(ox - 1000, oy - 1000), dx, dy, wall.moved(ox - 1000, oy - 1000))
    assert here == there


def test_far_from_the_origin_the_time_is_still_exact() -> None:
    far = 2.0**40
    assert sweep(BODY.moved(far, -far), 20, 0, Box(far + 15, -far, 5, 10)) == Contact(0.25, -1, 0)


def test_huge_boxes_and_moves_still_give_the_right_face() -> None:
    assert sweep(Box(0, 0, 1e300, 10), 1e300, 0, Box(1.5e300, 0, 1e300, 10)) == Contact(0.5, -1, 0)


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_nan_and_infinite_moves_are_refused(bad: float) -> None:
    wall = Box(20, 0, 10, 10)
    for call in (lambda: sweep(BODY, bad, 0, wall), lambda: sweep(BODY, 0, bad, wall),
                 lambda: discrete_hit(BODY, bad, 0, wall),
                 lambda: substep_hit(BODY, bad, 0, wall, 4),
                 lambda: clamp_speed(bad, 0, 8), lambda: steps_needed(10, bad)):
        with pytest.raises(ValueError, match="finite"):
            call()


@pytest.mark.parametrize("bad", [Box(math.nan, 0, 10, 10), Box(0, 0, math.inf, 10),
                                 Box(1.7e308, 0, 1.7e308, 10)],
                         ids=["nan", "inf", "edge-overflows"])
def test_nan_infinite_or_overflowing_boxes_are_refused(bad: Box) -> None:
    with pytest.raises(ValueError, match="finite"):
        sweep(bad, 1, 0, Box(20, 0, 10, 10))
    with pytest.raises(ValueError, match="finite"):
        sweep(BODY, 1, 0, bad)
    with pytest.raises(ValueError, match="finite"):
        discrete_hit(BODY, 1, 0, bad)
    with pytest.raises(ValueError, match="finite"):
        substep_hit(BODY, 1, 0, bad, 4)


@pytest.mark.parametrize("steps", [0, -1, 2.0])
def test_substepping_needs_a_whole_number_of_steps(steps: int) -> None:
    with pytest.raises(ValueError, match="whole number"):
        substep_hit(BODY, 10, 0, Box(20, 0, 10, 10), steps)


@pytest.mark.parametrize("size", [0, -1, math.nan])
def test_steps_needed_refuses_a_body_with_no_size(size: float) -> None:
    with pytest.raises(ValueError, match="size"):
        steps_needed(size, 30)


def test_clamp_speed_limits_each_axis_both_ways() -> None:
    assert clamp_speed(30, -30, 8) == (8, -8)
    assert clamp_speed(0.5, -2, 8) == (0.5, -2)
    with pytest.raises(ValueError, match="limit"):
        clamp_speed(1, 1, -1)


# ---------------------------------------------------------------------------------------------
# The oracle: fine sub-stepping


SAMPLES = 64  # a power of two: with whole-pixel inputs every sampled position is exact


@QUICK
@given(st.builds(Box, st.integers(-30, 30), st.integers(-30, 30), st.integers(1, 20),
                 st.integers(1, 20)),
       st.integers(-100, 100), st.integers(-100, 100),
       st.builds(Box, st.integers(-60, 60), st.integers(-60, 60), st.integers(1, 20),
                 st.integers(1, 20)))
def test_swept_agrees_with_fine_substepping_within_one_substep(body: Box, dx: int, dy: int,
                                                               wall: Box) -> None:
    # Sub-stepping sees the box at t = k/64. The true overlap is an open window of time, so:
    # * if sample k/64 is the first inside it, the window opened in [(k-1)/64, k/64);
    # * if no sample falls inside it, the window is shorter than 1/64: one sub-step after
    #   the swept time of impact the box must be out again (to float rounding, 1e-9 px).
    contact = sweep(body, dx, dy, wall)
    first = substep_hit(body, dx, dy, wall, SAMPLES)
    if first is not None:
        assert contact is not None
        assert first - 1 / SAMPLES <= contact.t < first
    elif contact is not None:
        later = position_at(body, dx, dy, contact.t + 1 / SAMPLES)
        assert later.penetration(wall) < 1e-9
    if discrete_hit(body, dx, dy, wall):
        assert contact is not None


@QUICK
@given(st.integers(1, 20), st.integers(-30, 30), st.integers(-300, 300),
       st.builds(Box, st.integers(-300, 300), st.just(0), st.integers(1, 20), st.just(10)))
@example(width=10, x=0, dx=19, wall=Box(12, 0, 4, 10))   # 19 px is two steps, not one
def test_steps_needed_catches_every_wall_on_a_straight_run(width: int, x: int, dx: int,
                                                           wall: Box) -> None:
    body = Box(x, 0, width, 10)
    if body.overlaps(wall):
        return  # starting inside is the previous tick's business
    caught = substep_hit(body, dx, 0, wall, steps_needed(width, dx)) is not None
    assert caught == (sweep(body, dx, 0, wall) is not None)
