"""Push-out, momentum exchange, and the crate scene that uses both: the laws they must keep."""

from __future__ import annotations

import functools
import math

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhase, BruteForce
from game.collision.broad.quadtree import Quadtree
from game.collision.broad.sort_and_sweep import SortAndSweep
from game.collision.broad.spatial_grid import SpatialGrid
from game.collision.response import (
    DOWN,
    LEFT,
    RIGHT,
    UP,
    ZERO,
    PointMass,
    Vec,
    exchange,
    push_out,
    separate,
)
from game.demos.crates import Crate, CrateScene, CrateTuning

SETTINGS = settings(max_examples=100, deadline=None)
REL = 1e-9  # relative tolerance for sums of floats

coords = st.floats(-1000, 1000, allow_nan=False)
sizes = st.floats(0.5, 200, allow_nan=False)
boxes = st.builds(Box, coords, coords, sizes, sizes)
inside = st.floats(0, 1, exclude_min=True, exclude_max=True)


@st.composite
def overlapping(draw: st.DrawFn) -> tuple[Box, Box]:
    """Two boxes that overlap: the second placed somewhere it shares area with the first."""
    first = draw(boxes)
    w, h = draw(sizes), draw(sizes)
    x = first.x - w + draw(inside) * (first.w + w)
    y = first.y - h + draw(inside) * (first.h + h)
    second = Box(x, y, w, h)
    assume(first.overlaps(second))  # rounding can, rarely, land it just outside
    return (first, second) if draw(st.booleans()) else (second, first)

masses = st.one_of(st.floats(0.01, 1000), st.just(math.inf))
finite_masses = st.floats(0.01, 1000)
speeds = st.floats(-500, 500, allow_nan=False)
velocities = st.builds(Vec, speeds, speeds)
units = st.sampled_from([UP, DOWN, LEFT, RIGHT]) | st.floats(0, 2 * math.pi).map(
    lambda angle: Vec(math.cos(angle), math.sin(angle)))


def close(a: float, b: float, scale: float) -> bool:
    return abs(a - b) <= REL * max(1.0, scale)


def gap(box: Box, solid: Box, normal: Vec) -> float:
    """How far ``box`` sits from the face of ``solid`` it was pushed out through."""
    if normal == UP:
        return solid.top - box.bottom
    if normal == DOWN:
        return box.top - solid.bottom
    if normal == LEFT:
        return solid.left - box.right
    return box.left - solid.right


def momentum(*bodies: PointMass) -> Vec:
    total = ZERO
    for body in bodies:
        total = total.plus(body.velocity_px_s.scaled(body.mass_kg))
    return total


def energy(*bodies: PointMass) -> float:
    return sum(0.5 * b.mass_kg * b.velocity_px_s.dot(b.velocity_px_s)
               for b in bodies if math.isfinite(b.mass_kg))


# --- push out ---------------------------------------------------------------------------------

@SETTINGS
@given(pair=overlapping())
def test_push_out_leaves_the_boxes_touching_not_overlapping(pair: tuple[Box, Box]) -> None:
    mover, solid = pair
    push = push_out(mover, solid)
    assert push is not None
    assert not push.box.overlaps(solid)
    assert 0 <= gap(push.box, solid, push.normal) <= REL * max(1.0, abs(solid.x), abs(solid.y))
    assert (push.box.w, push.box.h) == (mover.w, mover.h)


@SETTINGS
@given(pair=overlapping())
def test_push_out_takes_the_shortest_of_the_four_ways_out(pair: tuple[Box, Box]) -> None:
    mover, solid = pair
    push = push_out(mover, solid)
    assert push is not None
    shortest = min(mover.bottom - solid.top, solid.bottom - mover.top,
                   mover.right - solid.left, solid.right - mover.left)
    moved = abs(push.correction.x) + abs(push.correction.y)
    assert close(moved, shortest, abs(solid.x) + abs(solid.y) + abs(mover.x) + abs(mover.y))
    assert push.correction.x == 0 or push.correction.y == 0


def test_push_out_uses_the_axis_of_least_penetration() -> None:
    push = push_out(Box(0, 0, 10, 10), Box(2, 9, 10, 10))   # 8 deep on x, 1 deep on y
    assert push is not None
    assert push.normal == UP
    assert push.correction == Vec(0, -1)


def test_push_out_ties_go_to_y_then_to_the_negative_side() -> None:
    corner = push_out(Box(0, 0, 10, 10), Box(7, 7, 10, 10))  # 3 deep on both axes
    assert corner is not None and corner.normal == UP
    centred = push_out(Box(0, 0, 10, 10), Box(0, 0, 10, 10))
    assert centred is not None and centred.normal == UP
    wide = push_out(Box(0, 0, 10, 30), Box(0, 0, 10, 30))    # x is shallower: left wins
    assert wide is not None and wide.normal == LEFT


def test_push_out_of_boxes_that_only_touch_is_none() -> None:
    assert push_out(Box(0, 0, 10, 10), Box(10, 0, 10, 10)) is None
    assert push_out(Box(0, 0, 10, 10), Box(3, 3, 0, 0)) is None


@SETTINGS
@given(pair=overlapping(), mass_a=masses, mass_b=finite_masses, swap=st.booleans())
def test_separate_leaves_the_boxes_touching_and_spares_a_static_box(
        pair: tuple[Box, Box], mass_a: float, mass_b: float, swap: bool) -> None:
    a, b = pair
    if swap:
        mass_a, mass_b = mass_b, mass_a
    apart = separate(a, b, mass_a, mass_b)
    assert apart is not None
    assert not apart.a.overlaps(apart.b)
    assert apart.normal in (UP, DOWN, LEFT, RIGHT)
    assert abs(gap(apart.b, apart.a, apart.normal)) <= 1e-9 * max(1.0, abs(a.x), abs(a.y),
                                                                   abs(b.x), abs(b.y))
    if math.isinf(mass_a):
        assert apart.a == a
    if math.isinf(mass_b):
        assert apart.b == b


def test_separate_moves_each_box_in_inverse_proportion_to_its_mass() -> None:
    apart = separate(Box(0, 0, 10, 10), Box(4, 0, 10, 10), 1.0, 5.0)    # 6 px deep
    assert apart is not None
    assert apart.a.x == pytest.approx(-5.0)
    assert apart.b.x == pytest.approx(5.0)
    assert apart.normal == RIGHT


def test_separating_two_static_bodies_is_an_error() -> None:
    with pytest.raises(ValueError, match="static"):
        separate(Box(0, 0, 10, 10), Box(4, 0, 10, 10), math.inf, math.inf)


# --- momentum exchange ------------------------------------------------------------------------

@SETTINGS
@given(closing=st.floats(1, 500), drift=speeds, normal=units)
def test_equal_masses_head_on_with_restitution_1_swap_velocities(
        closing: float, drift: float, normal: Vec) -> None:
    va, vb = normal.scaled(closing + drift), normal.scaled(drift)
    a, b = exchange(PointMass(3.0, va), PointMass(3.0, vb), normal, restitution=1.0)
    for got, want in [(a.velocity_px_s, vb), (b.velocity_px_s, va)]:
        assert got.x == pytest.approx(want.x, abs=1e-9)
        assert got.y == pytest.approx(want.y, abs=1e-9)


@SETTINGS
@given(ma=finite_masses, mb=finite_masses, va=velocities, vb=velocities, normal=units)
def test_restitution_0_leaves_both_bodies_with_a_common_normal_velocity(
        ma: float, mb: float, va: Vec, vb: Vec, normal: Vec) -> None:
    if vb.minus(va).dot(normal) > 0:
        va, vb = vb, va  # drawn moving apart: the same speeds the other way round close
    assume(vb.minus(va).dot(normal) < 0)
    a, b = exchange(PointMass(ma, va), PointMass(mb, vb), normal, restitution=0.0)
    assert a.velocity_px_s.dot(normal) == pytest.approx(b.velocity_px_s.dot(normal), abs=1e-6)


@SETTINGS
@given(mass=finite_masses, velocity=velocities, normal=units,
       restitution=st.floats(0, 1))
def test_a_static_body_reflects_the_normal_velocity_and_does_not_move(
        mass: float, velocity: Vec, normal: Vec, restitution: float) -> None:
    if velocity.dot(normal) < 0:
        velocity = velocity.scaled(-1)  # drawn moving away: the reverse heads for the wall
    assume(velocity.dot(normal) > 0)
    wall = PointMass(math.inf, ZERO)
    body, after_wall = exchange(PointMass(mass, velocity), wall, normal, restitution)
    assert after_wall == wall
    assert body.velocity_px_s.dot(normal) == pytest.approx(
        -restitution * velocity.dot(normal), abs=1e-9)
    tangent = Vec(-normal.y, normal.x)
    assert body.velocity_px_s.dot(tangent) == pytest.approx(velocity.dot(tangent), abs=1e-9)


@SETTINGS
@given(ma=finite_masses, mb=finite_masses, va=velocities, vb=velocities, normal=units,
       restitution=st.floats(0, 1), friction=st.floats(0, 2))
def test_every_exchange_conserves_momentum_and_never_adds_energy(
        ma: float, mb: float, va: Vec, vb: Vec, normal: Vec, restitution: float,
        friction: float) -> None:
    before = (PointMass(ma, va), PointMass(mb, vb))
    after = exchange(*before, normal, restitution, friction)
    p0, p1 = momentum(*before), momentum(*after)
    scale = ma * va.length() + mb * vb.length()
    assert close(p0.x, p1.x, scale) and close(p0.y, p1.y, scale)
    assert energy(*after) <= energy(*before) * (1 + REL) + 1e-9


@SETTINGS
@given(ma=finite_masses, mb=finite_masses, va=velocities, vb=velocities, normal=units,
       friction=st.floats(0, 5))
def test_friction_can_stop_sliding_but_never_reverse_it(
        ma: float, mb: float, va: Vec, vb: Vec, normal: Vec, friction: float) -> None:
    tangent = Vec(-normal.y, normal.x)
    a, b = exchange(PointMass(ma, va), PointMass(mb, vb), normal, 0.5, friction)
    sliding_before = vb.minus(va).dot(tangent)
    sliding_after = b.velocity_px_s.minus(a.velocity_px_s).dot(tangent)
    assert sliding_before * sliding_after >= -1e-9 * max(1.0, sliding_before ** 2)
    assert abs(sliding_after) <= abs(sliding_before) + 1e-9


def test_bodies_already_moving_apart_are_left_alone() -> None:
    a, b = PointMass(1.0, Vec(-5, 0)), PointMass(1.0, Vec(5, 0))
    assert exchange(a, b, RIGHT, restitution=1.0, friction=1.0) == (a, b)


@pytest.mark.parametrize(("restitution", "friction", "normal"), [
    (1.5, 0.0, RIGHT), (-0.1, 0.0, RIGHT), (1.0, -1.0, RIGHT), (1.0, 0.0, ZERO)])
def test_exchange_refuses_impossible_settings(restitution: float, friction: float,
                                              normal: Vec) -> None:
    with pytest.raises(ValueError):
        exchange(PointMass(1.0, ZERO), PointMass(1.0, ZERO), normal, restitution, friction)


# --- the crate scene --------------------------------------------------------------------------

ELASTIC = CrateTuning(arena_w_px=10_000, arena_h_px=10_000, restitution=1.0, friction=0.0)
CENTRE_PX = 5000.0


def crowd(seed: int, count: int) -> list[Crate]:
    """Crates jumbled together (overlapping, too) in the middle of a huge arena."""
    scene = CrateScene.random(seed, CrateTuning(crate_count=count, arena_w_px=120,
                                                arena_h_px=120, spawn_gap_px=0))
    return [Crate(c.key, c.box.moved(CENTRE_PX, CENTRE_PX), c.mass_kg, c.velocity_px_s)
            for c in scene.crates.values()]


@pytest.mark.parametrize("seed", range(6))
def test_crate_collisions_conserve_momentum_with_restitution_1_and_no_friction(
        seed: int) -> None:
    scene = CrateScene(crowd(seed, 25), ELASTIC)
    start, energy_start = scene.momentum(), scene.kinetic_energy()
    scale = sum(c.mass_kg * c.velocity_px_s.length() for c in scene.crates.values())
    hits = 0
    for _ in range(120):  # 2 s at <= 120 px/s: nobody gets near a wall 4,800 px away
        report = scene.step(1 / 60)
        assert report.wall_hits == 0
        hits += report.crate_hits
        now = scene.momentum()
        assert close(now.x, start.x, scale) and close(now.y, start.y, scale)
    assert hits > 0
    assert scene.kinetic_energy() == pytest.approx(energy_start, rel=1e-9)


def test_two_equal_crates_meeting_head_on_swap_velocities() -> None:
    crates = [Crate(0, Box(100, 100, 10, 10), 1.0, Vec(60, 0)),
              Crate(1, Box(115, 100, 10, 10), 1.0, Vec(-30, 0))]
    scene = CrateScene(crates, ELASTIC)
    for _ in range(10):
        scene.step(1 / 60)
    assert scene.crates[0].velocity_px_s == Vec(-30, 0)
    assert scene.crates[1].velocity_px_s == Vec(60, 0)
    assert not scene.crates[0].box.overlaps(scene.crates[1].box)


@settings(max_examples=12, deadline=None)
@given(seed=st.integers(0, 10_000), restitution=st.floats(0, 1), friction=st.floats(0, 1))
def test_crate_scene_energy_never_increases(seed: int, restitution: float,
                                            friction: float) -> None:
    tuning = CrateTuning(crate_count=30, restitution=restitution, friction=friction,
                         max_speed_px_s=400)
    scene = CrateScene.random(seed, tuning)
    energy_before = scene.kinetic_energy()
    for _ in range(90):
        scene.step(1 / 60)
        energy_now = scene.kinetic_energy()
        assert energy_now <= energy_before * (1 + REL)
        energy_before = energy_now


def test_crates_stay_inside_the_arena() -> None:
    scene = CrateScene.random(3, CrateTuning(crate_count=20, max_speed_px_s=2000))
    walls_hit = sum(scene.step(1 / 60).wall_hits for _ in range(120))
    assert walls_hit > 0
    for crate in scene.crates.values():
        assert not any(crate.box.overlaps(wall) for wall in scene.walls)


def test_the_same_seed_gives_the_same_run_and_another_seed_does_not() -> None:
    def run(seed: int) -> list[tuple[Box, Vec]]:
        scene = CrateScene.random(seed)
        for _ in range(120):
            scene.step(1 / 60)
        return [(c.box, c.velocity_px_s) for c in scene.crates.values()]

    assert run(11) == run(11)
    assert run(11) != run(12)


def crate_run(broad_phase: BroadPhase[int] | None = None) -> tuple[list[int], list[Box]]:
    """Seed 5's scene for 2 s: the crate hits of each step, and where the crates end."""
    scene = CrateScene.random(5, CrateTuning(crate_count=30), broad_phase)
    hits = [scene.step(1 / 60).crate_hits for _ in range(120)]
    return hits, [c.box for c in scene.crates.values()]


REFERENCE_RUN = functools.cache(crate_run)  # the scene's own choice, run once for all four


@pytest.mark.parametrize("broad_phase", [
    BruteForce(), SortAndSweep(), SpatialGrid(cell_size_px=7.0),
    Quadtree(Box(0, 0, 320, 180), capacity=2, max_depth=5)],
    ids=["brute_force", "sort_and_sweep", "odd_grid", "quadtree"])
def test_every_broad_phase_runs_the_crate_scene_identically(
        broad_phase: BroadPhase[int]) -> None:
    assert crate_run(broad_phase) == REFERENCE_RUN()


def test_too_many_crates_for_the_arena_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="do not fit"):
        CrateScene.random(0, CrateTuning(crate_count=1000))
