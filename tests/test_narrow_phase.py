"""Narrow-phase shape tests: boxes against pygame, circles, SAT polygons, masks, composites.

Each exact test is checked against an oracle that does not share its code: pygame's own
``Rect.colliderect`` for boxes, dense point sampling for polygons and circles, whole-pixel
cells for composites, and the analytic shapes for masks.
"""

from __future__ import annotations

import math

import pygame
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box, rects_overlap
from game.collision.circles import Circle, bounding_circle, precheck_then_rect
from game.collision.composite import Composite, l_shape
from game.collision.masks import (
    Masked,
    MaskStats,
    circle_mask,
    collide,
    contact_point,
    polygon_mask,
)
from game.collision.sat import Polygon, oriented_box
from game.collision.sat import collide as sat_collide

QUICK = settings(max_examples=150, deadline=None)
SLOW = settings(max_examples=40, deadline=None)

# ---------------------------------------------------------------------------------------------
# Oracles and strategies shared below

Point = tuple[float, float]


def inside_by(point: Point, polygon: Polygon) -> float:
    """How far the point lies inside the convex polygon (negative: outside), by edge lines."""
    pts = polygon.points
    area2 = sum(pts[i - 1][0] * pts[i][1] - pts[i][0] * pts[i - 1][1] for i in range(len(pts)))
    winding = 1.0 if area2 > 0 else -1.0
    depth = math.inf
    for i in range(len(pts)):
        (x1, y1), (x2, y2) = pts[i - 1], pts[i]
        length = math.hypot(x2 - x1, y2 - y1)
        side = ((x2 - x1) * (point[1] - y1) - (y2 - y1) * (point[0] - x1)) / length
        depth = min(depth, winding * side)
    return depth


def sample_grid(box: Box, spacing: float) -> list[Point]:
    """Points at ``spacing`` apart covering the box (any disc of radius spacing/sqrt(2) in the
    box holds one)."""
    cols = math.ceil(box.w / spacing) + 1
    rows = math.ceil(box.h / spacing) + 1
    return [(box.x + i * spacing, box.y + j * spacing) for i in range(cols) for j in range(rows)]


def regular_polygon(cx: float, cy: float, radius: float, sides: int, turn: float) -> Polygon:
    return Polygon.of((cx + radius * math.cos(turn + 2 * math.pi * k / sides),
                       cy + radius * math.sin(turn + 2 * math.pi * k / sides))
                      for k in range(sides))


coords = st.floats(-15, 15, allow_nan=False)
angles = st.floats(0, 2 * math.pi, allow_nan=False)
oriented_boxes = st.builds(oriented_box, coords, coords, st.floats(2, 12), st.floats(2, 12),
                           angles)
regular_polygons = st.builds(regular_polygon, coords, coords, st.floats(2, 12),
                             st.integers(3, 8), angles)
fat_polygons = st.one_of(oriented_boxes, regular_polygons)

small = st.integers(-40, 40)
small_size = st.integers(-20, 20)
large = st.integers(-(2**29), 2**29)  # x + w stays inside pygame's 32-bit int


@st.composite
def int_rects(draw: st.DrawFn, non_negative: bool = False) -> pygame.Rect:
    pos = draw(st.one_of(small, large))
    pos_y = draw(st.one_of(small, large))
    size = st.integers(0, 20) if non_negative else st.one_of(small_size, large)
    return pygame.Rect(pos, pos_y, draw(size), draw(size))


# ---------------------------------------------------------------------------------------------
# Boxes against pygame.Rect.colliderect


@QUICK
@given(int_rects(), int_rects())
def test_rects_overlap_matches_colliderect_for_any_integer_rects(a: pygame.Rect,
                                                                 b: pygame.Rect) -> None:
    assert rects_overlap(Box.from_rect(a), Box.from_rect(b)) == a.colliderect(b)


@QUICK
@given(int_rects(non_negative=True), int_rects(non_negative=True))
def test_overlaps_matches_colliderect_for_normalised_rects(a: pygame.Rect,
                                                           b: pygame.Rect) -> None:
    assert Box.from_rect(a).overlaps(Box.from_rect(b)) == a.colliderect(b)


@pytest.mark.parametrize("other", [Box(16, 0, 16, 16), Box(-16, 0, 16, 16), Box(0, 16, 16, 16),
                                   Box(0, -16, 16, 16)], ids=["right", "left", "below", "above"])
def test_touching_edges_do_not_collide(other: Box) -> None:
    a = Box(0, 0, 16, 16)
    assert not a.overlaps(other)
    assert not a.to_rect().colliderect(other.to_rect())


@pytest.mark.parametrize("other", [Box(16, 16, 8, 8), Box(-8, -8, 8, 8), Box(16, -8, 8, 8)])
def test_touching_corners_do_not_collide(other: Box) -> None:
    a = Box(0, 0, 16, 16)
    assert not a.overlaps(other)
    assert not a.to_rect().colliderect(other.to_rect())


@pytest.mark.parametrize("empty", [Box(5, 5, 0, 10), Box(5, 5, 10, 0), Box(5, 5, 0, 0)])
def test_zero_size_boxes_never_collide_even_inside_another(empty: Box) -> None:
    big = Box(0, 0, 20, 20)
    assert not empty.overlaps(big) and not big.overlaps(empty) and not empty.overlaps(empty)
    assert not empty.to_rect().colliderect(big.to_rect())
    assert not rects_overlap(empty, big)


def test_negative_sizes_are_flipped_by_pygame_but_empty_to_overlaps() -> None:
    flipped = pygame.Rect(10, 10, -10, -10)   # covers 0 <= x < 10, 0 <= y < 10
    inner = pygame.Rect(2, 2, 4, 4)
    assert flipped.colliderect(inner)
    assert not Box.from_rect(flipped).overlaps(Box.from_rect(inner))
    assert rects_overlap(Box.from_rect(flipped), Box.from_rect(inner))
    assert Box.from_rect(flipped).normalized() == Box(0, 0, 10, 10)


@QUICK
@given(st.builds(Box, small, small, st.integers(0, 20), st.integers(0, 20)))
def test_normalized_leaves_a_normalised_box_alone_and_from_rect_round_trips(box: Box) -> None:
    assert box.normalized() == box
    assert Box.from_rect(box.to_rect()) == box


@pytest.mark.parametrize("box", [Box(math.nan, 0, 1, 1), Box(0, 0, math.nan, 1),
                                 Box(math.inf, 0, 1, 1), Box(0, -math.inf, 1, 1)])
def test_to_rect_refuses_nan_and_infinity(box: Box) -> None:
    with pytest.raises(ValueError, match="non-finite"):
        box.to_rect()


@pytest.mark.parametrize("box", [Box(2.0**31, 0, 1, 1), Box(0, -(2.0**31) - 1, 1, 1),
                                 Box(2.0**31 - 1, 0, 2, 1)])
def test_to_rect_refuses_edges_beyond_the_32_bits_of_a_rect(box: Box) -> None:
    with pytest.raises(ValueError, match="outside"):
        box.to_rect()


@pytest.mark.parametrize(("x", "left"), [(-0.7, -1), (-0.5, -1), (-1.0, -1), (0.0, 0),
                                         (2.9, 2)])
def test_to_rect_floors_coordinates_towards_minus_infinity(x: float, left: int) -> None:
    assert Box(x, x, 1, 1).to_rect().topleft == (left, left)


def test_huge_and_far_away_boxes_follow_the_same_rule() -> None:
    far = 1e15  # floats are exact to 0.125 here
    assert Box(far, far, 10, 10).overlaps(Box(far + 9.5, far, 10, 10))
    assert not Box(far, far, 10, 10).overlaps(Box(far + 10, far, 10, 10))
    assert Box(-1e300, -1e300, 2e300, 2e300).overlaps(Box(0, 0, 1, 1))


def test_nan_boxes_overlap_nothing() -> None:
    assert not Box(math.nan, 0, 10, 10).overlaps(Box(0, 0, 10, 10))


# ---------------------------------------------------------------------------------------------
# Circles


def test_touching_circles_do_not_overlap() -> None:
    assert not Circle(0, 0, 2).overlaps(Circle(3, 4, 3))      # 3-4-5: exactly touching
    assert Circle(0, 0, 2).overlaps(Circle(3, 4, 3.001))


def test_zero_radius_circle_overlaps_nothing_even_inside() -> None:
    dot = Circle(5, 5, 0)
    assert not dot.overlaps(Circle(5, 5, 10))
    assert not dot.overlaps_box(Box(0, 0, 10, 10))


@pytest.mark.parametrize("args", [(math.nan, 0, 1), (0, math.inf, 1), (0, 0, -1), (0, 0, math.nan)])
def test_circle_refuses_nan_and_negative_radius(args: tuple[float, float, float]) -> None:
    with pytest.raises(ValueError, match="finite"):
        Circle(*args)


def test_circle_touching_a_box_edge_or_corner_does_not_overlap() -> None:
    box = Box(0, 0, 10, 10)
    assert not Circle(-3, 5, 3).overlaps_box(box)
    assert not Circle(-3, -4, 5).overlaps_box(box)            # corner at distance 5
    assert Circle(-3, -4, 5.001).overlaps_box(box)


def test_circle_with_its_centre_inside_a_box_overlaps_it() -> None:
    assert Circle(5, 5, 0.01).overlaps_box(Box(0, 0, 10, 10))


@SLOW
@given(st.builds(Circle, coords, coords, st.floats(1, 12)),
       st.builds(Box, coords, coords, st.floats(1, 15), st.floats(1, 15)))
def test_circle_vs_box_agrees_with_point_sampling_outside_a_half_pixel_band(
        circle: Circle, box: Box) -> None:
    nearest = (min(max(circle.cx, box.left), box.right), min(max(circle.cy, box.top), box.bottom))
    depth = circle.r - math.dist((circle.cx, circle.cy), nearest)
    sampled = any(math.dist(p, (circle.cx, circle.cy)) < circle.r
                  and box.left < p[0] < box.right and box.top < p[1] < box.bottom
                  for p in sample_grid(box, 0.25))
    if sampled:
        assert circle.overlaps_box(box)
    if depth > 0.5:  # a disc of radius 0.18 fits in the overlap: the 0.25 grid must hit it
        assert sampled and circle.overlaps_box(box)


@QUICK
@given(st.builds(Box, small, small, small_size, small_size))
def test_bounding_circle_passes_through_every_corner(box: Box) -> None:
    ring = bounding_circle(box)
    for corner in [(box.left, box.top), (box.right, box.top), (box.left, box.bottom),
                   (box.right, box.bottom)]:
        assert math.dist(corner, (ring.cx, ring.cy)) == pytest.approx(ring.r)


@QUICK
@given(int_rects(), int_rects())
def test_precheck_then_rect_always_gives_colliderects_answer(a: pygame.Rect,
                                                             b: pygame.Rect) -> None:
    assert precheck_then_rect(a, b) == a.colliderect(b)


class CountingRect(pygame.Rect):
    calls = 0

    def colliderect(self, rect: pygame.Rect) -> bool:  # type: ignore[override]
        CountingRect.calls += 1
        return super().colliderect(rect)


def test_precheck_skips_colliderect_for_far_apart_rects_only() -> None:
    CountingRect.calls = 0
    assert not precheck_then_rect(CountingRect(0, 0, 10, 10), pygame.Rect(100, 0, 10, 10))
    assert CountingRect.calls == 0
    assert precheck_then_rect(CountingRect(0, 0, 10, 10), pygame.Rect(5, 5, 10, 10))
    assert CountingRect.calls == 1


# ---------------------------------------------------------------------------------------------
# Separating axis theorem


def test_polygons_sharing_an_edge_do_not_collide() -> None:
    a = Polygon.of([(0, 0), (10, 0), (10, 10)])
    b = Polygon.of([(0, 0), (10, 10), (0, 10)])
    assert sat_collide(a, b) is None


def test_boxes_sharing_only_a_corner_do_not_collide() -> None:
    a = Polygon.from_box(Box(0, 0, 10, 10))
    assert sat_collide(a, Polygon.from_box(Box(10, 10, 10, 10))) is None


def test_mtv_points_the_way_to_push_a_out_of_b() -> None:
    a = Polygon.from_box(Box(0, 0, 10, 10))
    assert sat_collide(a, Polygon.from_box(Box(8, 1, 10, 10))) == (-1.0, 0.0, 2.0)
    assert sat_collide(a, Polygon.from_box(Box(1, -7, 10, 10))) == (0.0, 1.0, 3.0)


@QUICK
@given(st.builds(Box, small, small, st.integers(1, 20), st.integers(1, 20)),
       st.builds(Box, small, small, st.integers(1, 20), st.integers(1, 20)))
def test_sat_on_axis_aligned_boxes_matches_box_overlap(a: Box, b: Box) -> None:
    mtv = sat_collide(Polygon.from_box(a), Polygon.from_box(b))
    assert (mtv is not None) == a.overlaps(b)
    if mtv is not None:
        assert mtv.depth >= a.penetration(b)  # equal unless one contains the other on an axis


@SLOW
@given(fat_polygons, fat_polygons)
def test_sat_agrees_with_dense_point_sampling_outside_a_one_pixel_band(a: Polygon,
                                                                       b: Polygon) -> None:
    # Grid points 0.5 px apart: any disc of radius 0.36 holds one. Two fat shapes that
    # overlap by more than 1 px share such a disc; shapes overlapping less are the thin band.
    mtv = sat_collide(a, b)
    region = a.bounds()
    found = any(inside_by(p, a) > 1e-9 and inside_by(p, b) > 1e-9
                for p in sample_grid(region, 0.5))
    if found:
        assert mtv is not None
    if mtv is not None and mtv.depth > 1.0:
        assert found


@SLOW
@given(fat_polygons, fat_polygons)
def test_moving_by_the_mtv_parts_the_shapes_and_less_does_not(a: Polygon, b: Polygon) -> None:
    mtv = sat_collide(a, b)
    if mtv is None:
        return
    nudge = mtv.depth * 1e-9 + 1e-9
    assert sat_collide(a.moved(mtv.nx * (mtv.depth + nudge), mtv.ny * (mtv.depth + nudge)),
                       b) is None
    if mtv.depth > 1e-6:
        assert sat_collide(a.moved(*(0.9 * v for v in mtv.vector)), b) is not None


@pytest.mark.parametrize(("points", "why"), [
    ([(0, 0), (1, 0)], "at least 3"),
    ([(0, 0), (1, 0), (math.nan, 1)], "finite"),
    ([(0, 0), (10, 0), (10, 10), (5, 2), (0, 10)], "not convex"),
    ([(0, 0), (5, 0), (10, 0), (10, 10)], "one line"),
    ([(0, 0), (10, 0), (10, 0), (10, 10)], "one line"),
    ([(0, -10), (5.9, 8.1), (-9.5, -3.1), (9.5, -3.1), (-5.9, 8.1)], "crosses itself"),
])
def test_polygon_refuses_bad_points_and_says_why(points: list[Point], why: str) -> None:
    with pytest.raises(ValueError, match=why):
        Polygon.of(points)


@pytest.mark.parametrize("half", [(0, 5), (5, -1), (math.nan, 5)])
def test_oriented_box_refuses_empty_or_nan_sizes(half: tuple[float, float]) -> None:
    with pytest.raises(ValueError, match="oriented box"):
        oriented_box(0, 0, half[0], half[1], 0.3)


# ---------------------------------------------------------------------------------------------
# Masks


def full(w: int, h: int) -> pygame.mask.Mask:
    return pygame.mask.Mask((w, h), fill=True)


def test_mask_offset_math_gives_world_pixels_at_negative_coordinates() -> None:
    a = Masked(full(5, 5), -10, -10)
    b = Masked(full(1, 1), -7, -8)
    assert contact_point(a, b) == (-7, -8)
    assert contact_point(b, a) == (-7, -8)


def test_masks_touching_edges_do_not_collide() -> None:
    assert not collide(Masked(full(4, 4), 0, 0), Masked(full(4, 4), 4, 0))
    assert not collide(Masked(full(4, 4), 0, 0), Masked(full(4, 4), 4, 4))
    assert collide(Masked(full(4, 4), 0, 0), Masked(full(4, 4), 3, 3))


def test_masks_are_read_only_when_the_rects_overlap() -> None:
    stats = MaskStats()
    assert not collide(circle_mask(Circle(0, 0, 5)), circle_mask(Circle(50, 0, 5)), stats)
    assert (stats.rect_checks, stats.mask_checks) == (1, 0)
    # Rects overlap in a corner the round shapes do not reach: the masks are read, and say no.
    assert not collide(circle_mask(Circle(0, 0, 5)), circle_mask(Circle(8, 8, 5)), stats)
    assert (stats.rect_checks, stats.mask_checks) == (2, 1)


def test_masked_needs_whole_pixels_and_at_floors_negative_positions() -> None:
    with pytest.raises(ValueError, match="whole pixels"):
        Masked(full(1, 1), 0.5, 0)  # type: ignore[arg-type]
    placed = Masked.at(full(1, 1), -0.5, 2.7)
    assert (placed.x, placed.y) == (-1, 2)
    with pytest.raises(ValueError, match="non-finite"):
        Masked.at(full(1, 1), math.nan, 0)


def assert_mask_matches_within_one_pixel(masked: Masked, fully_inside: object,
                                         fully_outside: object) -> None:
    """Every pixel square wholly inside the shape is solid, every one wholly outside is
    clear; only the pixels the outline crosses may go either way. (Put the other way round,
    which asks each pixel one question: no solid pixel lies wholly outside, no clear one
    wholly inside.)"""
    assert callable(fully_inside) and callable(fully_outside)
    width, height = masked.mask.get_size()
    for i in range(-2, width + 2):
        for j in range(-2, height + 2):
            pixel = Box(masked.x + i, masked.y + j, 1, 1)
            solid = 0 <= i < width and 0 <= j < height and bool(masked.mask.get_at((i, j)))
            if solid:
                assert not fully_outside(pixel), pixel
            else:
                assert not fully_inside(pixel), pixel


def corners_of(box: Box) -> list[Point]:
    return [(box.left, box.top), (box.right, box.top), (box.left, box.bottom),
            (box.right, box.bottom)]


@SLOW
@given(st.builds(Circle, coords, coords, st.floats(0.5, 15)))
def test_circle_mask_agrees_with_the_circle_within_one_pixel(circle: Circle) -> None:
    centre = (circle.cx, circle.cy)
    assert_mask_matches_within_one_pixel(
        circle_mask(circle),
        lambda px: all(math.dist(c, centre) < circle.r for c in corners_of(px)),
        lambda px: not circle.overlaps_box(px))


@SLOW
@given(oriented_boxes)
def test_bar_mask_agrees_with_the_bar_within_one_pixel(bar: Polygon) -> None:
    assert_mask_matches_within_one_pixel(
        polygon_mask(bar),
        lambda px: all(inside_by(c, bar) > 0 for c in corners_of(px)),
        # A pixel whose centre lies inside the bar is not wholly outside it; SAT decides
        # only for the others.
        lambda px: (inside_by(px.center, bar) <= 0
                    and sat_collide(Polygon.from_box(px), bar) is None))


def test_a_circle_drawn_by_pygame_agrees_with_the_circle_within_one_pixel() -> None:
    surface = pygame.Surface((40, 40), pygame.SRCALPHA)     # no display needed
    pygame.draw.circle(surface, (255, 255, 255, 255), (20, 20), 12)
    drawn = Masked.from_surface(surface, 100, -50)
    circle = Circle(120, -30, 12)
    assert_mask_matches_within_one_pixel(
        drawn,
        lambda px: all(math.dist(c, (circle.cx, circle.cy)) < circle.r for c in corners_of(px)),
        lambda px: not circle.overlaps_box(px))


@SLOW
@given(st.builds(Circle, coords, coords, st.floats(1, 12)),
       st.builds(Circle, coords, coords, st.floats(1, 12)))
def test_mask_collision_agrees_with_circles_outside_a_one_pixel_diagonal_band(
        a: Circle, b: Circle) -> None:
    # A shared solid pixel has its centre inside both circles, so a mask hit is a true hit.
    # Circles overlapping deeper than a pixel's diagonal share a disc holding a pixel centre.
    hit = collide(circle_mask(a), circle_mask(b))
    depth = a.r + b.r - math.dist((a.cx, a.cy), (b.cx, b.cy))
    if hit:
        assert a.overlaps(b)
    if depth > math.sqrt(2):
        assert hit


@SLOW
@given(oriented_boxes, oriented_boxes)
def test_mask_collision_agrees_with_sat_for_bars_outside_a_one_pixel_diagonal_band(
        a: Polygon, b: Polygon) -> None:
    hit = collide(polygon_mask(a), polygon_mask(b))
    mtv = sat_collide(a, b)
    if hit:
        assert mtv is not None
    if mtv is not None and mtv.depth > 2 * math.sqrt(2):
        assert hit


# ---------------------------------------------------------------------------------------------
# Composite colliders


def cells(box: Box) -> set[tuple[int, int]]:
    """The unit pixel cells an integer box covers: the oracle for composites."""
    return {(int(box.x) + i, int(box.y) + j) for i in range(int(box.w)) for j in range(int(box.h))}


int_boxes = st.builds(Box, st.integers(-10, 10), st.integers(-10, 10), st.integers(1, 8),
                      st.integers(1, 8))


@QUICK
@given(st.integers(-10, 10), st.integers(-10, 10), st.lists(int_boxes, min_size=1, max_size=4),
       int_boxes)
def test_composite_overlap_matches_the_pixel_cells_it_covers(x: int, y: int, parts: list[Box],
                                                             other: Box) -> None:
    body = Composite(x, y, tuple(parts))
    covered = set().union(*(cells(p) for p in body.world_parts()))
    assert body.overlaps(other) == bool(covered & cells(other))


def test_composites_touching_along_an_edge_do_not_collide() -> None:
    a = l_shape(0, 0, width=30, height=30, thickness=10)
    assert not a.overlaps(a.moved(dx=30))
    assert not a.overlaps(a.moved(dy=30))
    assert a.overlaps(a.moved(dx=29))


def test_two_ls_can_nest_without_touching() -> None:
    corner = l_shape(0, 0, width=30, height=30, thickness=10)
    flipped = Composite(10, -10, (Box(10, 0, 10, 30), Box(-10, 0, 30, 10)))   # a 7 shape
    assert corner.bounds().overlaps(flipped.bounds())
    assert not corner.overlaps(flipped)


def test_composite_bounds_is_the_union_of_its_parts() -> None:
    body = Composite(5, -5, (Box(0, 0, 2, 2), Box(10, 20, 3, 1)))
    assert body.bounds() == Box(5, -5, 13, 21)


@pytest.mark.parametrize("parts", [(), (Box(0, 0, 0, 5),), (Box(0, 0, -3, 5),),
                                   (Box(math.nan, 0, 1, 1),)])
def test_composite_refuses_missing_empty_or_nan_parts(parts: tuple[Box, ...]) -> None:
    with pytest.raises(ValueError, match="part"):
        Composite(0, 0, parts)


def test_l_shape_refuses_a_thickness_that_fills_it() -> None:
    with pytest.raises(ValueError, match="thickness"):
        l_shape(0, 0, width=10, height=20, thickness=10)
