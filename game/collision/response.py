"""Collision response: push overlapping boxes apart, then trade momentum along the contact.

Where it sits: after a broad phase has found an overlapping pair (the crate demo in
:mod:`game.demos.crates`). The player never goes through here:
:mod:`game.collision.axis_sweep` sweeps each move and stops flush, so the player never
overlaps a wall in the first place. Response is for things that *do* end up inside each
other after a tick, such as crates that are simply moved by their velocity.

What it teaches:
  * **The shortest way out.** An overlapping box can leave another in four ways: up, down,
    left or right. :func:`push_out` takes the shortest, which is the axis of least
    penetration, and puts the box exactly flush: touching, not overlapping. Ties go to y
    before x (a box landing exactly on a corner is put on top, not beside), and within an
    axis to the negative side (up before down, left before right).
  * **Heavier things move less.** :func:`separate` shares the push between two boxes in
    inverse proportion to their masses; an infinite mass (``math.inf``) is a static body
    that never moves.
  * **Impulses, not positions, change velocity.** :func:`exchange` applies an equal and
    opposite impulse along the contact normal, so momentum ``m·v`` is conserved. The
    *coefficient of restitution* ``e`` says how much of the closing speed comes back: 1
    bounces perfectly (equal masses head-on swap velocities), 0 leaves both moving together.
    Bodies already moving apart get no impulse.
  * **Friction** acts along the tangent (the contact surface), opposing sliding, and is
    capped at ``friction * normal impulse`` (Coulomb's law): it can stop the sliding,
    never reverse it. Neither term can add kinetic energy.

>>> push = push_out(Box(0, 0, 10, 10), Box(8, 2, 10, 10))   # 2 px in from the left
>>> push.box, push.correction, push.normal
(Box(x=-2, y=0, w=10, h=10), Vec(x=-2, y=0), Vec(x=-1.0, y=0.0))
>>> a, b = exchange(PointMass(1.0, Vec(30, 0)), PointMass(1.0, Vec(-10, 0)),
...                 normal=Vec(1, 0), restitution=1.0)
>>> a.velocity_px_s, b.velocity_px_s                       # equal masses swap
(Vec(x=-10.0, y=0.0), Vec(x=30.0, y=0.0))
"""

from __future__ import annotations

import math
from typing import NamedTuple

from game.collision.aabb import Box


class Vec(NamedTuple):
    """A 2D vector: a velocity in px/s, a correction in px, a unit normal."""

    x: float
    y: float

    def plus(self, other: Vec) -> Vec:
        return Vec(self.x + other.x, self.y + other.y)

    def minus(self, other: Vec) -> Vec:
        return Vec(self.x - other.x, self.y - other.y)

    def scaled(self, factor: float) -> Vec:
        return Vec(self.x * factor, self.y * factor)

    def dot(self, other: Vec) -> float:
        return self.x * other.x + self.y * other.y

    def opposite(self) -> Vec:
        """The vector pointing the other way (``+ 0.0`` keeps zeros from printing as -0.0)."""
        return Vec(-self.x + 0.0, -self.y + 0.0)

    def length(self) -> float:
        return math.hypot(self.x, self.y)


ZERO = Vec(0.0, 0.0)
UP, DOWN, LEFT, RIGHT = Vec(0.0, -1.0), Vec(0.0, 1.0), Vec(-1.0, 0.0), Vec(1.0, 0.0)


class PointMass(NamedTuple):
    """What a collision needs to know of a body: its mass (``math.inf`` if static), its velocity."""

    mass_kg: float
    velocity_px_s: Vec


class Push(NamedTuple):
    """Where a pushed-out box ends up, how far it moved, and which way (a unit vector)."""

    box: Box
    correction: Vec
    normal: Vec


class Separation(NamedTuple):
    """Two boxes pushed apart, and the unit normal pointing from the first to the second."""

    a: Box
    b: Box
    normal: Vec


def _inverse(mass_kg: float) -> float:
    if not mass_kg > 0:
        raise ValueError(f"a mass must be positive (math.inf for a static body), not {mass_kg}")
    return 0.0 if math.isinf(mass_kg) else 1.0 / mass_kg


def _start_flush_before(face: float, size: float) -> float:
    """The start coordinate that puts a ``size``-long span's far end at ``face`` or just short.

    ``face - size`` is the answer on paper, but adding ``size`` back can round to a hair past
    the face, which would leave the boxes overlapping by that hair. Step back until it does
    not; rounding is off by an ulp or so, so this takes one or two steps at most.
    """
    start = face - size
    while start + size > face:
        start -= max(math.ulp(start), (start + size) - face)
    return start


def push_out(mover: Box, solid: Box) -> Push | None:
    """Move ``mover`` the shortest way out of ``solid``; None if they do not overlap.

    >>> push_out(Box(0, 0, 10, 10), Box(10, 0, 10, 10)) is None   # touching is fine
    True
    >>> push_out(Box(3, 3, 4, 4), Box(0, 0, 10, 10)).normal      # dead centre: a tie, goes up
    Vec(x=0.0, y=-1.0)
    """
    if not mover.overlaps(solid):
        return None
    # How far the mover must travel in each direction to clear the solid, in tie order.
    ways_out = [
        (mover.bottom - solid.top, UP),
        (solid.bottom - mover.top, DOWN),
        (mover.right - solid.left, LEFT),
        (solid.right - mover.left, RIGHT),
    ]
    _, way = min(ways_out, key=lambda option: option[0])  # min keeps the first of equals
    box = place_beside(mover, solid, way)
    return Push(box, Vec(box.x - mover.x, box.y - mover.y), way)


def place_beside(mover: Box, solid: Box, side: Vec) -> Box:
    """``mover`` moved along one axis to sit flush against ``solid`` on ``side`` (UP, ...).

    >>> place_beside(Box(3, 3, 4, 4), Box(0, 0, 10, 10), RIGHT)
    Box(x=10, y=3, w=4, h=4)
    """
    if side == UP:
        return mover._replace(y=_start_flush_before(solid.top, mover.h))
    if side == DOWN:
        return mover._replace(y=solid.bottom)
    if side == LEFT:
        return mover._replace(x=_start_flush_before(solid.left, mover.w))
    if side == RIGHT:
        return mover._replace(x=solid.right)
    raise ValueError(f"a side is one of UP, DOWN, LEFT or RIGHT, not {side}")


def separate(a: Box, b: Box, mass_a_kg: float, mass_b_kg: float) -> Separation | None:
    """Push two overlapping boxes apart, each moving in inverse proportion to its mass.

    The lighter box moves more; a static box (``math.inf``) does not move at all. The
    boxes end exactly touching. None if they do not overlap.

    >>> s = separate(Box(0, 0, 10, 10), Box(7, 0, 10, 10), 1.0, 2.0)   # 3 px deep
    >>> s.a.x, s.b.x, s.normal
    (-2.0, 8.0, Vec(x=1.0, y=0.0))
    >>> separate(Box(0, 0, 10, 10), Box(7, 0, 10, 10), 1.0, math.inf).a.x
    -3
    """
    inv_a, inv_b = _inverse(mass_a_kg), _inverse(mass_b_kg)
    if inv_a == 0 and inv_b == 0:
        raise ValueError("two static bodies cannot be pushed apart; give one of them a mass")
    push = push_out(a, b)
    if push is None:
        return None
    normal = push.normal.opposite()  # from a towards b
    if inv_a == 0:  # a is static: b takes the whole push, the other way
        return Separation(a, place_beside(b, a, normal), normal)
    if inv_b == 0:
        return Separation(push.box, b, normal)
    # Move b its share, then push a the rest of the way out, which also makes them flush.
    b_share = push.correction.scaled(-inv_b / (inv_a + inv_b))
    b_moved = b.moved(b_share.x, b_share.y)
    a_push = push_out(a, b_moved)
    return Separation(a_push.box if a_push else a, b_moved, normal)


def exchange(a: PointMass, b: PointMass, normal: Vec, restitution: float,
             friction: float = 0.0) -> tuple[PointMass, PointMass]:
    """The velocities after an impulse along ``normal`` (pointing from ``a`` towards ``b``).

    ``restitution`` is in [0, 1]; ``friction`` (>= 0) is the Coulomb coefficient. If the
    bodies are not closing along the normal, or both are static, nothing changes.

    >>> wall = PointMass(math.inf, ZERO)
    >>> ball, _ = exchange(PointMass(2.0, Vec(5, 3)), wall, RIGHT, restitution=1.0)
    >>> ball.velocity_px_s                                     # reflected off a static body
    Vec(x=-5.0, y=3.0)
    >>> a, b = exchange(PointMass(1.0, Vec(6, 0)), PointMass(2.0, ZERO), RIGHT, restitution=0)
    >>> a.velocity_px_s, b.velocity_px_s                       # restitution 0: move together
    (Vec(x=2.0, y=0.0), Vec(x=2.0, y=0.0))
    """
    if not 0.0 <= restitution <= 1.0:
        raise ValueError(f"restitution must be between 0 and 1, not {restitution}")
    if not friction >= 0.0:
        raise ValueError(f"friction must be zero or more, not {friction}")
    size = normal.length()
    if not (math.isfinite(size) and size > 0):
        raise ValueError(f"a contact normal needs a direction, not {normal}")
    normal = normal.scaled(1.0 / size)
    inv_a, inv_b = _inverse(a.mass_kg), _inverse(b.mass_kg)
    inv_sum = inv_a + inv_b
    relative = b.velocity_px_s.minus(a.velocity_px_s)
    closing = relative.dot(normal)
    if inv_sum == 0 or closing >= 0:
        return a, b
    # Normal impulse: undo the closing speed and give back ``restitution`` of it.
    normal_impulse = -(1.0 + restitution) * closing / inv_sum
    impulse = normal.scaled(normal_impulse)
    # Friction impulse: stop the sliding along the tangent, but no more than Coulomb allows.
    tangent = Vec(-normal.y, normal.x)
    limit = friction * normal_impulse
    tangent_impulse = max(-limit, min(limit, -relative.dot(tangent) / inv_sum))
    impulse = impulse.plus(tangent.scaled(tangent_impulse))
    return (PointMass(a.mass_kg, a.velocity_px_s.minus(impulse.scaled(inv_a))),
            PointMass(b.mass_kg, b.velocity_px_s.plus(impulse.scaled(inv_b))))
