"""Swept AABB: when, during one tick's move, a moving box first hits a still one.

Where it sits: taught, benchmarked and shown in the lab; **the game's moves do not run
it.** They are :mod:`game.collision.axis_sweep`, the same idea one axis at a time against
the tile grid; this module does it for a whole ``(dx, dy)`` move against one box, with the
cheaper methods it replaces set beside it for comparison. The level checker runs
:func:`sweep` to find where a moving platform's path first meets a wall
(:mod:`game.checker.designer_checks`).

What it teaches:
  * **Time of impact by slabs.** On each axis the two boxes' intervals overlap during an
    open window of time: they start overlapping at ``enter`` and cease at ``leave``, which
    are gaps divided by the speed. The boxes overlap while *both* windows are open, so the
    hit starts at the later ``enter`` and ends at the earlier ``leave``. It is a hit in this
    tick when that window is not empty and begins before ``t = 1``. Exact at any speed,
    even at corners.
  * **The normal is the axis that entered last**: the face the box actually struck.
  * **Strict, like everything here.** Ending the move exactly flush is not a hit (the next
    tick's move will start flush and hit at ``t = 0``); sliding along a face is not a hit;
    passing exactly over a corner is not a hit.
  * **The tie rule.** When both axes enter at the same instant (a corner struck dead on,
    e.g. ``dx == dy`` into an outer corner), **y wins**: the contact is a landing (or a head
    bump), never a wall. That is what the game's x-then-y movement passes do in the same
    case (the x step is free because y has not reached the block yet; the y step then lands
    on its top), and it is deterministic: the same input gives the same normal every run.
  * **What it replaces, and how they fail** (see ``tests/test_failures_of_approximate_methods``):
    a *discrete* check at the end of the move lets a fast body pass through a thin wall;
    *sub-stepping* with N checks costs N tests and still misses corners it clips between
    samples; *clamping the speed* hides tunnelling by making everything slower, so contact
    comes a computable number of ticks late.

>>> wall = Box(30, 0, 4, 40)
>>> sweep(Box(0, 10, 10, 10), 100, 0, wall)        # 20 px to the wall, 100 px per tick
Contact(t=0.2, nx=-1, ny=0)
>>> discrete_hit(Box(0, 10, 10, 10), 100, 0, wall) # the end position is past the wall
False
>>> sweep(Box(0, 0, 10, 10), 10, 10, Box(20, 20, 10, 10)) is None   # ends corner to corner
True
>>> sweep(Box(0, 0, 10, 10), 20, 20, Box(20, 20, 10, 10))   # a corner, dead on: y wins
Contact(t=0.5, nx=0, ny=-1)
"""

from __future__ import annotations

import math
from math import isfinite
from typing import NamedTuple

from game.collision.aabb import Box


class Contact(NamedTuple):
    """A hit at fraction ``t`` of the move (``0 <= t < 1``) on the face with normal ``(nx, ny)``.

    The normal points out of the still box, back towards the mover: ``(-1, 0)`` is the
    still box's left face, ``(0, -1)`` its top (a landing). ``(0, 0)`` means the boxes
    already overlapped at the start, so there is no face to name.
    """

    t: float
    nx: int
    ny: int


def _check_finite(box: Box, name: str) -> None:
    x, y, w, h = box
    if not (isfinite(x) and isfinite(y) and isfinite(w) and isfinite(h)
            and isfinite(x + w) and isfinite(y + h)):
        raise ValueError(f"{name} must have finite position, size and edges, got {box}")


def _check_move(dx: float, dy: float) -> None:
    if not (isfinite(dx) and isfinite(dy)):
        raise ValueError(f"a move must be a finite number of pixels, got ({dx}, {dy})")


def _sign(v: float) -> int:
    return (v > 0) - (v < 0)


def sweep(box: Box, dx: float, dy: float, wall: Box) -> Contact | None:
    """The first moment moving ``box`` by ``(dx, dy)`` makes it overlap the still ``wall``.

    Boxes must be normalised; empty boxes never hit anything. Refuses NaN and infinities.
    The arithmetic is on plain floats: the only object made is the :class:`Contact`.
    """
    _check_finite(box, "the moving box")
    _check_finite(wall, "the still box")
    _check_move(dx, dy)
    x, y, w, h = box
    wall_x, wall_y, wall_w, wall_h = wall
    if w <= 0 or h <= 0 or wall_w <= 0 or wall_h <= 0:
        return None
    right, bottom, wall_right, wall_bottom = x + w, y + h, wall_x + wall_w, wall_y + wall_h
    # Each axis: the open window of time (enter, leave) during which the intervals overlap.
    if dx == 0:
        if not (x < wall_right and wall_x < right):
            return None  # never overlapping on x, so never at all
        x_enter, x_leave = -math.inf, math.inf
    elif dx > 0:
        x_enter, x_leave = (wall_x - right) / dx, (wall_right - x) / dx
    else:
        x_enter, x_leave = (wall_right - x) / dx, (wall_x - right) / dx
    if dy == 0:
        if not (y < wall_bottom and wall_y < bottom):
            return None
        y_enter, y_leave = -math.inf, math.inf
    elif dy > 0:
        y_enter, y_leave = (wall_y - bottom) / dy, (wall_bottom - y) / dy
    else:
        y_enter, y_leave = (wall_bottom - y) / dy, (wall_y - bottom) / dy
    enter, leave = max(x_enter, y_enter), min(x_leave, y_leave)
    if not (enter < leave and enter < 1 and leave > 0):
        return None
    if enter < 0:
        return Contact(0.0, 0, 0)
    t = enter if enter > 0 else 0.0  # never -0.0
    if y_enter >= x_enter:  # the tie rule: y wins
        return Contact(t, 0, -_sign(dy))
    return Contact(t, -_sign(dx), 0)


def position_at(box: Box, dx: float, dy: float, t: float) -> Box:
    """Where the box is at fraction ``t`` of the move (each time from the start, no drift)."""
    return box.moved(dx * t, dy * t)


def discrete_hit(box: Box, dx: float, dy: float, wall: Box) -> bool:
    """The cheapest method: move, then test the end position only. Tunnels at speed."""
    _check_finite(box, "the moving box")
    _check_finite(wall, "the still box")
    _check_move(dx, dy)
    return position_at(box, dx, dy, 1.0).overlaps(wall)


def substep_hit(box: Box, dx: float, dy: float, wall: Box, steps: int) -> float | None:
    """Test the box at ``t = 1/steps, 2/steps, ..., 1``; the first ``t`` that overlaps, or None.

    The start (``t = 0``) is not tested: it was the previous tick's end, tested then.
    """
    _check_finite(box, "the moving box")
    _check_finite(wall, "the still box")
    _check_move(dx, dy)
    if type(steps) is not int or steps < 1:
        raise ValueError(f"sub-stepping needs a whole number of steps >= 1, got {steps!r}")
    for k in range(1, steps + 1):
        t = k / steps
        if position_at(box, dx, dy, t).overlaps(wall):
            return t
    return None


def steps_needed(size_px: float, speed_px_per_tick: float) -> int:
    """Sub-steps so that no step moves the body further than its own size on that axis.

    Then the positions tested overlap or abut each other, so on a straight run no wall of
    any thickness fits between two of them: ``ceil(speed / size)``, and at least 1. Moving
    diagonally, use the larger count of the two axes; a corner clipped between two samples
    can still be missed (the failure tests show one).

    >>> steps_needed(10, 30), steps_needed(10, 31), steps_needed(10, 0)
    (3, 4, 1)
    """
    if not (math.isfinite(size_px) and size_px > 0):
        raise ValueError(f"the body's size must be finite and > 0, got {size_px}")
    if not math.isfinite(speed_px_per_tick):
        raise ValueError(f"the speed must be finite, got {speed_px_per_tick}")
    return max(1, math.ceil(abs(speed_px_per_tick) / size_px))


def clamp_speed(dx: float, dy: float, max_px_per_tick: float) -> tuple[float, float]:
    """Limit each axis of a move to ``max_px_per_tick`` either way (a terminal velocity).

    >>> clamp_speed(30, -2.5, 8)
    (8, -2.5)
    """
    _check_move(dx, dy)
    if not (math.isfinite(max_px_per_tick) and max_px_per_tick >= 0):
        raise ValueError(f"the speed limit must be finite and >= 0, got {max_px_per_tick}")
    return (max(-max_px_per_tick, min(dx, max_px_per_tick)),
            max(-max_px_per_tick, min(dy, max_px_per_tick)))
