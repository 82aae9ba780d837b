"""The swept moves against a brute-force oracle, on random maps of sub-tile shapes.

``move_x`` and ``move_y`` find the first face in the direction of travel from the shapes the
tile grid returns for the swept region. The oracle knows nothing of grids, regions or faces:
it walks the body along the move half a pixel at a time, testing every shape of the map at
every step, and stops before the first step that would overlap a solid (or cross a side of
the map). Every coordinate here is a multiple of half a pixel, so that walk is exact, and
the sweep must end exactly where the walk does, report a hit exactly when the walk was
stopped short, and never end inside, or pass through, a solid.

The maps are what Tiled's collision editor makes: several rectangles per tile, anywhere
inside it, full tiles side by side (seams), one-way tiles and hazards; the moves run from a
fraction of a pixel to many tiles in one tick.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache

from hypothesis import event, given, settings
from hypothesis import strategies as st

# Everything the tests use from the game, in one place.
from game.collision.aabb import Box
from game.collision.axis_sweep import Move, Side, ground_under, move_body, move_x, move_y
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid

T = 16
COLS, ROWS = 12, 8
STEP = 0.5  # every coordinate is a multiple of this, so walking by it is exact
EXAMPLES = settings(max_examples=100, deadline=None, derandomize=True, database=None)
KINDS = st.sampled_from([TileKind.SOLID] * 4 + [TileKind.ONE_WAY] * 3 + [TileKind.HAZARD])


@dataclass(frozen=True)
class Scene:
    """A map of shapes and a body placed in it overlapping no solid."""

    shapes: tuple[TileShape, ...]
    body: Box
    toward: int  # +1 or -1: the direction along the axis to the shape it was placed by

    def grid(self) -> TileGrid:
        grid = TileGrid(COLS, ROWS, T, T)
        for shape in self.shapes:
            grid.put(shape.col, shape.row, shape)
        return grid


@cache  # each strategy is built and checked once, not again at every draw
def halves(low: float, high: float) -> st.SearchStrategy[float]:
    return st.integers(int(low / STEP), int(high / STEP)).map(lambda n: n * STEP)


@st.composite
def tile_shapes(draw: st.DrawFn) -> TileShape:
    """One collision rectangle inside one tile: often the whole tile, else any part of it."""
    col, row = draw(st.integers(0, COLS - 1)), draw(st.integers(0, ROWS - 1))
    kind = draw(KINDS)
    if draw(st.booleans()):
        return TileShape(Box(col * T, row * T, T, T), kind, col, row)
    left, right = sorted((draw(halves(0, T)), draw(halves(0, T))))
    top, bottom = sorted((draw(halves(0, T)), draw(halves(0, T))))
    return TileShape(Box(col * T + left, row * T + top, right - left, bottom - top), kind,
                     col, row)


@st.composite
def runs(draw: st.DrawFn) -> list[TileShape]:
    """A floor, ceiling or wall of whole tiles side by side: a run of seams."""
    col, row = draw(st.integers(0, COLS - 1)), draw(st.integers(0, ROWS - 1))
    length, kind = draw(st.integers(2, 6)), draw(KINDS)
    if draw(st.booleans()):
        cells = [(c, row) for c in range(col, min(col + length, COLS))]
    else:
        cells = [(col, r) for r in range(row, min(row + length, ROWS))]
    return [TileShape(Box(c * T, r * T, T, T), kind, c, r) for c, r in cells]


@st.composite
def scenes(draw: st.DrawFn, across: str) -> Scene:
    """A map and a body; ``across`` ("x" or "y") is the axis the body will move along, and
    the body is mostly placed in the band of some shape across that axis, so that the move
    has something to meet."""
    shapes = draw(st.lists(tile_shapes(), min_size=4, max_size=16))
    shapes += [shape for run in draw(st.lists(runs(), min_size=1, max_size=3)) for shape in run]
    w, h = draw(halves(STEP, 2 * T)), draw(halves(STEP, 2 * T))
    x = draw(halves(0, COLS * T - w))
    y = draw(halves(-T, ROWS * T))
    toward = draw(st.sampled_from([1, -1]))
    solids = [shape for shape in shapes if shape.kind is TileKind.SOLID]
    if shapes and draw(st.integers(0, 9)) > 1:
        aim_at_a_solid = bool(solids) and draw(st.booleans())
        aim = draw(st.sampled_from(solids if aim_at_a_solid else shapes)).box
        if across == "x":
            # In the shape's band of rows: from just overlapping its top to its bottom, or
            # exactly flush against it (sliding along a face).
            y = draw(halves(aim.top - h, aim.bottom))
            x = draw(st.sampled_from([aim.left - w, aim.right])
                     | halves(aim.left - w - 3 * T, aim.right + 3 * T))
        else:
            x = draw(halves(aim.left - w, aim.right))
            y = draw(st.sampled_from([aim.top - h, aim.bottom])
                     | halves(aim.top - h - 3 * T, aim.bottom + 3 * T))
        toward = 1 if (aim.center[0] > x + w / 2 if across == "x" else
                       aim.center[1] > y + h / 2) else -1
    x = min(max(x, 0.0), COLS * T - w)   # the body starts inside the map's sides
    body = Box(x, y, w, h)
    # Solids the body would start inside are left out: a move starts from a free place.
    kept = tuple(s for s in shapes if s.kind is not TileKind.SOLID or not s.box.overlaps(body))
    return Scene(kept, body, toward)


def steps(scene: Scene, across: str) -> st.SearchStrategy[float]:
    """A move along one axis: a fraction of a pixel up to many tiles, mostly towards the
    shape the body was placed by; or one that ends exactly on a face or a side of the map,
    or half a pixel short of it or past it."""
    size = st.one_of(halves(STEP, 3), halves(3, 2 * T), halves(3, 12 * T))
    sign = st.sampled_from([scene.toward] * 4 + [-scene.toward])
    free = st.tuples(sign, size).map(lambda pair: pair[0] * pair[1])
    body = scene.body
    if across == "x":
        faces = [f - body.right for s in scene.shapes for f in (s.box.left, s.box.right)]
        faces += [f - body.left for s in scene.shapes for f in (s.box.left, s.box.right)]
        sides = [COLS * T - body.right, -body.left]
    else:
        faces = [f - body.bottom for s in scene.shapes for f in (s.box.top, s.box.bottom)]
        faces += [f - body.top for s in scene.shapes for f in (s.box.top, s.box.bottom)]
        sides = []
    exact = st.tuples(st.sampled_from(faces + sides), st.sampled_from([0.0, 0.0, STEP, -STEP]))
    exact_steps = exact.map(sum).filter(lambda d: d != 0)
    if not sides:
        return free | exact_steps
    to_a_side = st.sampled_from(sides).filter(lambda d: d != 0)
    return free | exact_steps | to_a_side


@dataclass(frozen=True)
class Walked:
    """Where the walk stopped, and what stopped it (nothing, a shape or a side of the map)."""

    box: Box
    stopped: bool
    blockers: tuple[TileShape, ...]


def walk(scene: Scene, dx: float, dy: float, through_one_way: bool = False) -> Walked:
    """Move the body half a pixel at a time, testing every shape of the map at every step."""
    body, count = scene.body, round(abs(dx + dy) / STEP)
    unit_x, unit_y = (STEP if dx > 0 else -STEP) if dx else 0.0, \
        (STEP if dy > 0 else -STEP) if dy else 0.0
    feet = body.bottom

    def blocks(shape: TileShape) -> bool:
        if shape.kind is TileKind.SOLID:
            return True
        return (shape.kind is TileKind.ONE_WAY and unit_y > 0 and not through_one_way
                and feet <= shape.box.top)

    # Only a shape inside the band from the start to the end of the whole move can meet a
    # step of it; testing the others too would find nothing more, slowly.
    band = body.union(body.moved(dx, dy))
    near = [s for s in scene.shapes if blocks(s) and band.overlaps(s.box)]
    at = body
    for _ in range(count):
        ahead = at.moved(unit_x, unit_y)
        blockers = tuple(s for s in near if ahead.overlaps(s.box))
        off_map = unit_x != 0 and (ahead.left < 0 or ahead.right > COLS * T)
        if blockers or off_map:
            return Walked(at, True, blockers)
        at = ahead
    return Walked(at, False, ())


def check(scene: Scene, move: Move, walked: Walked, side: Side) -> None:
    assert move.box == walked.box, f"{move} but the walk ended at {walked.box}"
    assert move.start == scene.body
    assert (move.hit is not None) == walked.stopped
    event("stopped by " + ("nothing" if not walked.stopped else
                           walked.blockers[0].kind.value if walked.blockers else "the map side"))
    event("touching a face at the start" if walked.stopped and move.box == scene.body
          else "moved")
    event("ended exactly on a face" if not walked.stopped and any(
        face in (move.box.left, move.box.right, move.box.top, move.box.bottom)
        for s in scene.shapes for face in s.box[:2]) else "ended elsewhere")
    if move.hit is not None:
        assert move.hit.side is side
        leading = {Side.RIGHT: move.box.right, Side.LEFT: move.box.left,
                   Side.BOTTOM: move.box.bottom, Side.TOP: move.box.top}[side]
        assert move.hit.face == leading
        if walked.blockers:
            assert move.hit.shape in walked.blockers
        else:
            assert move.hit.shape is None          # a side of the map
    # Never inside a solid, and never through one: the path it travelled is clear of them.
    path = scene.body.union(move.box)
    solids = [s.box for s in scene.shapes if s.kind is TileKind.SOLID]
    assert not any(path.overlaps(solid) for solid in solids)


@EXAMPLES
@given(scenes("x"), st.data())
def test_move_x_stops_where_walking_half_a_pixel_at_a_time_stops(
        scene: Scene, data: st.DataObject) -> None:
    dx = data.draw(steps(scene, "x"))
    move = move_x(scene.grid(), scene.body, dx)
    check(scene, move, walk(scene, dx, 0.0), Side.RIGHT if dx > 0 else Side.LEFT)


@EXAMPLES
@given(scenes("y"), st.data())
def test_move_y_stops_where_walking_half_a_pixel_at_a_time_stops(
        scene: Scene, data: st.DataObject) -> None:
    dy = data.draw(steps(scene, "y"))
    grid = scene.grid()
    for through_one_way in (False, True):  # landing on one-way tops, and dropping through
        move = move_y(grid, scene.body, dy, through_one_way=through_one_way)
        check(scene, move, walk(scene, 0.0, dy, through_one_way),
              Side.BOTTOM if dy > 0 else Side.TOP)


def test_the_oracle_itself_stops_flush_before_a_wall_and_at_the_map_side() -> None:
    """The walk is the reference, so it is checked by hand on one case of each kind."""
    wall = TileShape(Box(5 * T + 4, 0, 4, T), TileKind.SOLID, 5, 0)
    scene = Scene((wall,), Box(10, 2, 12, 12), 1)
    assert walk(scene, 100.0, 0.0) == Walked(Box(5 * T + 4 - 12, 2, 12, 12), True, (wall,))
    assert walk(scene, -100.0, 0.0) == Walked(Box(0, 2, 12, 12), True, ())
    assert walk(scene, 20.0, 0.0) == Walked(Box(30, 2, 12, 12), False, ())
    plank = TileShape(Box(0, 3 * T, T, 4), TileKind.ONE_WAY, 0, 3)
    above = Scene((plank,), Box(2, 3 * T - 12, 12, 12), 1)
    below = Scene((plank,), Box(2, 40, 12, 9), 1)
    assert walk(above, 0.0, 30.0).box.bottom == 3 * T
    assert walk(above, 0.0, 30.0, through_one_way=True).box.bottom == 3 * T + 30
    assert walk(below, 0.0, 30.0).stopped is False


@EXAMPLES
@given(scenes("y"), st.data())
def test_the_floor_a_fall_found_is_the_ground_the_probe_finds_there(
        scene: Scene, data: st.DataObject) -> None:
    """``move_body`` names the floor its fall landed on as the ground without probing again;
    its plain twin, the one-pixel probe at the box the move ended at, names the same shape
    (or None) after every move, also when the body started off the half-pixel steps (so
    its feet are where float arithmetic put them)."""
    dy = data.draw(steps(scene, "y"))
    nudge = data.draw(st.sampled_from([0.0, 0.1, 1 / 3, 0.7]))
    grid = scene.grid()
    body = scene.body.moved(0.0, nudge)
    if any(s.kind is TileKind.SOLID and s.box.overlaps(body) for s in scene.shapes):
        body = scene.body
    for through_one_way in (False, True):
        moves = move_body(grid, body, 0.0, dy, through_one_way=through_one_way)
        probed = ground_under(grid, moves.y.box, through_one_way=through_one_way)
        assert moves.ground is probed
