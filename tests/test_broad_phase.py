"""Broad phases against the brute-force oracle, plus the rules each structure promises.

Every structure must give exactly the pairs and query answers brute force gives, on any boxes:
empty ones, negative coordinates, huge ones, ones touching exactly (never a pair), ones
straddling cell borders, all piled at one point. Work is checked by counts, never by time.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhase, BruteForce, pair_of
from game.collision.broad.quadtree import Quadtree, quadrants
from game.collision.broad.sort_and_sweep import SortAndSweep
from game.collision.broad.spatial_grid import SpatialGrid

CELL_PX = 16.0
TREE_BOUNDS = Box(-256, -256, 512, 512)

Factory = Callable[[], BroadPhase[int]]
FACTORIES: dict[str, Factory] = {
    "grid": lambda: SpatialGrid(cell_size_px=CELL_PX),
    "grid_odd_cells": lambda: SpatialGrid(cell_size_px=7.3),
    "grid_tiny_cells": lambda: SpatialGrid(cell_size_px=0.5, max_cells_per_item=16),
    "quadtree": lambda: Quadtree(TREE_BOUNDS, capacity=2, max_depth=5),
    "quadtree_roomy": lambda: Quadtree(TREE_BOUNDS, capacity=8, max_depth=8),
    "sort_and_sweep": lambda: SortAndSweep(),
}
EVERY_PHASE = pytest.mark.parametrize("make", FACTORIES.values(), ids=FACTORIES.keys())

ORACLE = settings(max_examples=60, deadline=None)

coords = st.one_of(
    st.integers(-6, 6).map(lambda i: i * CELL_PX),          # exactly on cell borders
    st.builds(lambda i, d: i * 8.0 + d,                      # near cell and quadrant borders
              st.integers(-40, 40), st.floats(-2, 2)),
    st.integers(-300, 300).map(float),
    st.floats(-600, 600, allow_nan=False, allow_infinity=False),
    st.floats(-1e5, 1e5, allow_nan=False, allow_infinity=False),
)
sizes = st.one_of(
    st.just(0.0),
    st.integers(1, 3).map(lambda i: i * CELL_PX),            # whole cells: edges on borders
    st.floats(0, 4, allow_nan=False),
    st.floats(0, 40, allow_nan=False),
    st.floats(1e3, 1e6, allow_nan=False),                    # huge
)
boxes = st.builds(Box, coords, coords, sizes, sizes)
piles = st.builds(lambda box, n: [box] * n, boxes, st.integers(1, 12))  # all at one point
# Crowds around the origin: a cell corner, and where the quadtree's centre lines cross.
near_origin = st.one_of(st.integers(-12, 12).map(lambda i: i / 4), st.floats(-3, 3))
small = st.one_of(st.integers(0, 12).map(lambda i: i / 4), st.floats(0, 3))
crowds = st.lists(st.builds(Box, near_origin, near_origin, small, small),
                  min_size=8, max_size=30)
box_lists = st.one_of(st.lists(boxes, max_size=25), piles, crowds,
                      st.builds(lambda a, b: a + b, st.lists(boxes, max_size=10), piles))


Phase = TypeVar("Phase", bound=BroadPhase[int])


def filled(phase: Phase, items: list[Box]) -> Phase:
    for key, box in enumerate(items):
        phase.insert(key, box)
    return phase


def oracle(items: list[Box]) -> BruteForce[int]:
    reference: BruteForce[int] = BruteForce()
    filled(reference, items)
    return reference


# --- the oracle ---------------------------------------------------------------------------

# Each example is given to every structure in turn (the failure names the structure): every
# structure meets as many examples as if it had a test of its own, and they are drawn once.

@ORACLE
@given(items=box_lists)
def test_every_broad_phase_finds_exactly_the_brute_force_pairs(items: list[Box]) -> None:
    expected = oracle(items).pairs()
    for name, make in FACTORIES.items():
        assert filled(make(), items).pairs() == expected, name


@ORACLE
@given(items=box_lists, probe=boxes)
def test_every_broad_phase_query_matches_brute_force(items: list[Box], probe: Box) -> None:
    reference = oracle(items)
    for name, make in FACTORIES.items():
        phase = filled(make(), items)
        assert phase.query(probe) == reference.query(probe), name
        for box in items[:5]:  # a query with an item's own box finds at least its overlaps
            assert phase.query(box) == reference.query(box), name


operations = st.lists(
    st.tuples(st.sampled_from(["insert", "remove", "move"]), st.integers(0, 9), boxes),
    max_size=40)


@ORACLE
@given(ops=operations, probe=boxes)
def test_random_insert_remove_move_sequences_keep_matching_brute_force(
        ops: list[tuple[str, int, Box]], probe: Box) -> None:
    phases, reference = {name: make() for name, make in FACTORIES.items()}, oracle([])
    present: set[int] = set()
    for op, key, box in ops:
        for phase in [*phases.values(), reference]:
            if op == "insert" and key not in present:
                phase.insert(key, box)
            elif op == "remove" and key in present:
                phase.remove(key)
            elif key in present:
                phase.move(key, box)
        if op == "insert":
            present.add(key)
        elif op == "remove":
            present.discard(key)
        expected = reference.pairs()
        for name, phase in phases.items():
            assert phase.pairs() == expected, name
    expected_found = reference.query(probe)
    for name, phase in phases.items():
        assert phase.query(probe) == expected_found, name


# --- the rules every structure shares -----------------------------------------------------

@EVERY_PHASE
def test_boxes_touching_exactly_never_pair(make: Factory) -> None:
    # A 4 x 4 block of cell-sized boxes, every edge on a cell border, each touching its
    # neighbours on edges and corners.
    items = [Box(col * CELL_PX, row * CELL_PX, CELL_PX, CELL_PX)
             for row in range(-2, 2) for col in range(-2, 2)]
    phase = filled(make(), items)
    assert phase.pairs() == set()
    assert phase.query(Box(-CELL_PX, -CELL_PX, CELL_PX, CELL_PX)) == {5}


@EVERY_PHASE
def test_boxes_piled_at_one_point_all_pair_with_each_other(make: Factory) -> None:
    count = 30
    phase = filled(make(), [Box(3.5, -7.25, 2, 2)] * count)
    assert len(phase.pairs()) == count * (count - 1) // 2


@EVERY_PHASE
def test_empty_boxes_pair_with_nothing_not_even_at_the_same_point(make: Factory) -> None:
    phase = filled(make(), [Box(5, 5, 0, 10), Box(5, 5, 10, 0), Box(5, 5, 0, 0),
                            Box(0, 0, 20, 20)])
    assert phase.pairs() == set()
    assert phase.query(Box(5, 5, 0, 0)) == set()
    assert phase.query(Box(4, 4, 2, 2)) == {3}


@EVERY_PHASE
def test_pairs_are_spelled_smaller_key_first(make: Factory) -> None:
    phase = make()
    phase.insert(9, Box(0, 0, 10, 10))
    phase.insert(2, Box(5, 5, 10, 10))
    assert phase.pairs() == {(2, 9)} == {pair_of(9, 2)}


@EVERY_PHASE
def test_inserting_a_key_twice_is_an_error(make: Factory) -> None:
    phase = make()
    phase.insert(1, Box(0, 0, 1, 1))
    with pytest.raises(ValueError, match="already"):
        phase.insert(1, Box(5, 5, 1, 1))


@EVERY_PHASE
def test_removing_or_moving_an_unknown_key_is_a_key_error(make: Factory) -> None:
    phase = make()
    with pytest.raises(KeyError):
        phase.remove(4)
    with pytest.raises(KeyError):
        phase.move(4, Box(0, 0, 1, 1))


@EVERY_PHASE
@pytest.mark.parametrize("bad", [Box(float("nan"), 0, 1, 1), Box(0, 0, float("inf"), 1),
                                 Box(1e308, 0, 1e308, 1)])
def test_non_finite_boxes_are_refused(make: Factory, bad: Box) -> None:
    with pytest.raises(ValueError, match="finite"):
        make().insert(1, bad)


# --- brute force ------------------------------------------------------------------------------

def test_brute_force_tests_every_pair_exactly_once() -> None:
    phase = oracle([Box(i * 100, 0, 10, 10) for i in range(10)])
    phase.pairs()
    assert phase.stats.pair_tests == 10 * 9 // 2


# --- spatial grid -----------------------------------------------------------------------------

def test_grid_files_negative_coordinates_with_floor_not_truncation() -> None:
    grid: SpatialGrid[int] = SpatialGrid(cell_size_px=CELL_PX)
    cells = grid.cell_range(Box(-0.5, -17.5, 1, 1))
    assert (cells.first_col, cells.last_col) == (-1, 0)
    assert (cells.first_row, cells.last_row) == (-2, -2)


def test_grid_files_a_box_whose_width_is_lost_to_rounding() -> None:
    # 0.5 + 1e-59 == 0.5, so the right edge equals the left; Box.overlaps still counts it.
    grid = filled(SpatialGrid[int](cell_size_px=0.5), [Box(0, 0, 1, 1), Box(0.5, 0, 1e-59, 1)])
    assert grid.pairs() == {(0, 1)}


def test_grid_box_larger_than_a_cell_is_filed_in_every_cell_it_covers() -> None:
    grid: SpatialGrid[int] = SpatialGrid(cell_size_px=CELL_PX)
    grid.insert(1, Box(1, 1, 40, 20))     # cols 0..2, rows 0..1
    assert grid.occupied_cells() == {(c, r) for c in range(3) for r in range(2)}
    grid.insert(2, Box(40, 20, 1, 1))     # only in cell (2, 1), the far corner
    assert grid.pairs() == {(1, 2)}


def test_grid_never_tests_boxes_in_distant_cells() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(i * 50 + 1, 1, 10, 10)
                                                      for i in range(20)])
    assert grid.pairs() == set()
    assert grid.stats.pair_tests == 0


def test_grid_tests_a_pair_sharing_many_cells_only_once() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(1, 1, 40, 40), Box(2, 2, 40, 40)])
    assert len(grid.occupied_cells()) == 9
    assert grid.pairs() == {(0, 1)}
    assert grid.stats.pair_tests == 1


def test_grid_query_visits_only_the_cells_it_covers() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(i * 20 + 1, j * 20 + 1, 4, 4)
                                                      for i in range(10) for j in range(10)])
    grid.stats.reset()
    assert grid.query(Box(21, 21, 8, 8)) == {11}
    assert grid.stats.cells_visited == 1
    assert grid.stats.pair_tests == 1


def test_grid_huge_box_is_kept_aside_and_still_pairs() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX),
                  [Box(-1e6, -1e6, 2e6, 2e6), Box(5, 5, 2, 2), Box(2e6, 0, 1, 1)])
    assert grid.oversize() == {0}
    assert grid.occupied_cells() == {(0, 0), (125000, 0)}
    assert grid.pairs() == {(0, 1)}


def test_grid_huge_query_looks_at_occupied_cells_not_every_covered_one() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(5, 5, 2, 2), Box(500, 500, 2, 2)])
    grid.stats.reset()
    assert grid.query(Box(-1e6, -1e6, 2e6, 2e6)) == {0, 1}
    assert grid.stats.cells_visited == 2


def test_grid_move_within_the_same_cells_keeps_the_filing() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(1, 1, 4, 4)])
    grid.move(0, Box(9, 9, 4, 4))
    assert grid.occupied_cells() == {(0, 0)}
    grid.move(0, Box(-9, 9, 4, 4))
    assert grid.occupied_cells() == {(-1, 0)}
    assert grid.query(Box(-8, 10, 1, 1)) == {0}


def test_grid_removing_every_item_leaves_no_cells_behind() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(i * 7.0, -i * 3.0, 30, 30)
                                                      for i in range(15)])
    for key in range(15):
        grid.remove(key)
    assert grid.occupied_cells() == frozenset()
    assert len(grid) == 0


@settings(max_examples=60, deadline=None)
@given(items=box_lists, probes=st.lists(boxes, min_size=1, max_size=10))
def test_a_grid_query_never_changes_the_grid(items: list[Box], probes: list[Box]) -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX, max_cells_per_item=16), items)
    cells, oversize, pairs = grid.occupied_cells(), grid.oversize(), grid.pairs()
    for probe in probes:
        grid.query(probe)
    assert grid.occupied_cells() == cells
    assert grid.oversize() == oversize
    assert grid.pairs() == pairs


def test_a_grid_query_in_empty_space_creates_no_cells() -> None:
    grid = filled(SpatialGrid[int](cell_size_px=CELL_PX), [Box(0, 0, 4, 4)])
    assert grid.query(Box(100, 100, 64, 64)) == set()
    assert grid.occupied_cells() == {(0, 0)}


def test_grid_refuses_a_cell_size_that_is_not_positive() -> None:
    with pytest.raises(ValueError, match="cell_size_px"):
        SpatialGrid(cell_size_px=0)


# --- quadtree ---------------------------------------------------------------------------------

@settings(max_examples=100, deadline=None)
@given(bounds=st.builds(Box, st.floats(-1e4, 1e4), st.floats(-1e4, 1e4),
                        st.floats(1e-3, 1e4), st.floats(1e-3, 1e4)))
def test_quadrants_meet_on_exactly_shared_edges(bounds: Box) -> None:
    nw, ne, sw, se = quadrants(bounds)
    assert nw.right == ne.left == sw.right == se.left
    assert nw.bottom == sw.top == ne.bottom == se.top
    assert (nw.left, nw.top, ne.top, sw.left) == (bounds.left, bounds.top, bounds.top,
                                                   bounds.left)
    assert not any(a.overlaps(b) for a, b in [(nw, ne), (nw, sw), (nw, se), (ne, sw),
                                              (ne, se), (sw, se)])


def test_quadtree_depth_limit_holds_with_1000_identical_boxes() -> None:
    tree: Quadtree[int] = Quadtree(TREE_BOUNDS, capacity=4, max_depth=6)
    for key in range(1000):
        tree.insert(key, Box(10, 10, 1, 1))
    assert tree.depth() == 6
    assert tree.query(Box(10.5, 10.5, 1, 1)) == set(range(1000))


def test_quadtree_splits_only_when_a_leaf_exceeds_capacity() -> None:
    tree: Quadtree[int] = Quadtree(TREE_BOUNDS, capacity=3, max_depth=6)
    for key in range(3):
        tree.insert(key, Box(key * 100 - 200, -200, 4, 4))
    assert tree.node_count() == 1
    tree.insert(3, Box(150, 150, 4, 4))
    assert tree.node_count() == 5


def test_quadtree_item_straddling_a_child_border_stays_in_the_parent() -> None:
    tree: Quadtree[int] = Quadtree(Box(0, 0, 64, 64), capacity=1, max_depth=4)
    tree.insert(0, Box(1, 1, 2, 2))
    tree.insert(1, Box(30, 30, 4, 4))     # crosses the root's centre lines
    tree.insert(2, Box(40, 1, 2, 2))
    root = next(tree.nodes())
    assert set(root.items) == {1}
    assert tree.depth() == 1


def test_quadtree_items_outside_its_bounds_are_still_found() -> None:
    tree = filled(Quadtree[int](Box(0, 0, 64, 64), capacity=1, max_depth=4),
                  [Box(-100, -100, 10, 10), Box(-95, -95, 10, 10), Box(10, 10, 4, 4)])
    assert tree.pairs() == {(0, 1)}
    assert tree.query(Box(-92, -92, 1, 1)) == {0, 1}


def test_quadtree_query_skips_subtrees_it_does_not_touch() -> None:
    tree = filled(Quadtree[int](TREE_BOUNDS, capacity=1, max_depth=6),
                  [Box(x, y, 4, 4) for x in range(-250, 250, 40) for y in range(-250, 250, 40)])
    tree.stats.reset()
    assert tree.query(Box(-249, -249, 2, 2)) == {0}
    assert tree.stats.cells_visited < tree.node_count() // 4


def test_quadtree_collapses_when_removals_leave_it_sparse() -> None:
    tree = filled(Quadtree[int](TREE_BOUNDS, capacity=2, max_depth=6),
                  [Box(i * 30 - 200, i * 30 - 200, 4, 4) for i in range(12)])
    assert tree.node_count() > 1
    for key in range(10):
        tree.remove(key)
    assert tree.node_count() == 1
    assert tree.pairs() == set()
    assert len(tree) == 2


def test_quadtree_query_never_changes_the_tree() -> None:
    tree = filled(Quadtree[int](TREE_BOUNDS, capacity=2, max_depth=6),
                  [Box(i * 13.0 - 200, i * 7.0 - 100, 9, 9) for i in range(40)])
    shape = [(node.bounds, set(node.items)) for node in tree.nodes()]
    for probe in [Box(-300, -300, 600, 600), Box(5, 5, 1, 1), Box(1e5, 1e5, 1, 1)]:
        tree.query(probe)
    assert [(node.bounds, set(node.items)) for node in tree.nodes()] == shape


def test_quadtree_rebuild_matches_a_fresh_tree() -> None:
    items = [(i, Box(i * 11.0 - 100, (i * 37) % 200 - 100, 12, 12)) for i in range(30)]
    tree: Quadtree[int] = Quadtree(TREE_BOUNDS, capacity=2, max_depth=6)
    tree.rebuild(items[:10])
    tree.rebuild(items)
    assert tree.pairs() == oracle([box for _, box in items]).pairs()
    tree.clear()
    assert len(tree) == 0 and tree.pairs() == set()


# --- sort and sweep ---------------------------------------------------------------------------

def test_sort_and_sweep_never_tests_boxes_apart_on_x() -> None:
    sweep = filled(SortAndSweep[int](), [Box(i * 20.0, (i % 3) * 5.0, 10, 10) for i in range(50)])
    assert sweep.pairs() == set()
    assert sweep.stats.pair_tests == 0


def test_sort_and_sweep_tests_a_column_of_boxes_against_each_other() -> None:
    # Its worst case: everything overlaps on x, so only the y test separates them.
    sweep = filled(SortAndSweep[int](), [Box(0, i * 20.0, 10, 10) for i in range(10)])
    assert sweep.pairs() == set()
    assert sweep.stats.pair_tests == 10 * 9 // 2


def test_sort_and_sweep_query_stops_at_boxes_starting_right_of_it() -> None:
    sweep = filled(SortAndSweep[int](), [Box(i * 20.0, 0, 10, 10) for i in range(50)])
    assert sweep.query(Box(25, 5, 10, 1)) == {1}
    assert sweep.stats.pair_tests == 2       # boxes 0 and 1; box 2 starts right of x = 35
