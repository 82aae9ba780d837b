"""The peer: the game's moves beside Arcade's platformer engine and the pygame tutorial loop.

Where it sits: a chart of ``python -m game.bench`` (``peer.png``). Arcade comes with the
optional extra ``pip install -e '.[peers]'``; without it the chart and the targets say the
peer was skipped, and everything else still runs.

What it teaches: what a move costs and what it gets right, side by side, on the same walls.

  * **The walls** are the solid tiles of *The Summit*, the largest shipped level (one-way
    and hazard tiles are left out: Arcade's engine has no such kinds).
  * **The moves** are recorded: *The Summit* is played to its exit by its winning script
    and every tick the player's box and its x and y move are kept. Each method then makes
    the same moves from the same boxes, and the bench counts where they end up alike.
    Each starts from the body's state in its own form: the game from a ``Box`` (what its
    bodies hold), made before the clock starts; the floor from bare floats; Arcade and the
    tutorial loop set their sprite's position or rect inside the timed move, since that is
    where they keep it.
  * **The methods.** The game's :func:`~game.collision.axis_sweep.move_x` then
    :func:`~game.collision.axis_sweep.move_y`; the same sweeps in plain floats
    (:mod:`game.bench.plain_sweep`, the floor); the loop of the pygame tutorials (move the
    float position, round it into the rect, ``spritecollide`` against a group of every wall,
    snap the rect to the face it hit, one axis at a time); Arcade's
    ``PhysicsEnginePlatformer.update`` (move, test the end position against a spatial hash,
    step back a pixel at a time or by halves until free); and the game's whole
    :meth:`World.step <game.sim.world.World.step>` on *The Summit*, per body it moves.
  * **Accuracy**, measured on small scenes with the same four movers:
    *tunnelled flights*: a 12 x 14 body flies at a one-tile (16 px) wall, across and
    falling, at 8 to 64 px per tick from 16 start phases each, and ends beyond it;
    *short of flush*: how far from the face a blocked move stops (0 is flush; the game's
    rule), *inside* if it stops overlapping the wall; *jitter at rest*: how far a body standing
    on a floor under gravity moves up and down over 90 ticks; *snags*: ticks on which a
    body running along a floor of 101 separate tiles is held back at one of the 100 seams.
  * Time per update is the median of interleaved rounds; the ratios the targets check
    carry bootstrap intervals (:mod:`game.bench.intervals`).
"""

from __future__ import annotations

import functools
import importlib
from collections.abc import Callable, Sequence
from pathlib import Path
from statistics import median
from typing import Any, NamedTuple, Protocol

import pygame

from game.app.run import input_script
from game.bench import charts, plain_sweep
from game.bench.intervals import median_interval, paired_ratio
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import clock, collector_off
from game.collision.aabb import Box
from game.collision.axis_sweep import move_x, move_y
from game.collision.shapes import TileKind, TileShape
from game.collision.tile_grid import TileGrid
from game.levels import LEVELS_DIR, load_level
from game.sim.tuning import Tuning
from game.sim.world import World

CHART = "peer"
LEVEL = LEVELS_DIR / "06-the-summit.tmx"
SCRIPT = LEVELS_DIR.parent / "tests" / "scripts" / "06-the-summit.txt"
SEED = 5
TILE_PX = 16
BODY_W_PX, BODY_H_PX = 12.0, 14.0
SPEEDS_PX = (8, 16, 24, 32, 40, 48, 56, 64)   # px per tick
PHASES = 16                                    # start phases per speed and axis
FLIGHTS_PER_SPEED = 2 * PHASES                 # across and falling
SEAMS = 100
REST_TICKS, SETTLE_TICKS = 120, 30
_TUNING = Tuning()
GRAVITY_PX_PER_TICK2 = _TUNING.gravity_px_s2 * _TUNING.tick_s ** 2
RUN_PX_PER_TICK = _TUNING.run_speed_px_s * _TUNING.tick_s

PLAIN = "plain-float sweep (the floor)"
GAME = "move_x + move_y (this game)"
STEP = "World.step per body (this game's whole tick)"
TUTORIAL = "spritecollide tutorial loop"
ARCADE = "Arcade PhysicsEnginePlatformer.update"
UPDATE = "µs/update"
SAME_PX = 0.01      # Arcade rounds its y to 1/100 px; "the same end position" allows that much
SAME = "same end position (±0.01 px) as move_x + move_y"
SKIPPED = "skipped (1 = Arcade is not installed)"
VERSION = "the version of Arcade installed (in the parameter column)"
PIXEL = pygame.Surface((1, 1))   # every sprite needs an image; none is ever drawn here


class Sample(NamedTuple):
    """One recorded move: the box it starts from (top-left, y down) and its x and y steps."""

    x: float
    y: float
    w: float
    h: float
    dx: float
    dy: float


class Mover(Protocol):
    """A method: from ``(x, y)``, move by ``(dx, dy)`` against its walls; the new top-left."""

    def move(self, x: float, y: float, w: float, h: float, dx: float,
             dy: float) -> tuple[float, float]: ...


def arcade_module() -> Any | None:
    """Arcade if the ``peers`` extra is installed (it needs no window for this), else None."""
    try:
        return importlib.import_module("arcade")
    except Exception:   # not installed, or it cannot load here: either way, no peer
        return None


def solid_grid(grid: TileGrid) -> TileGrid:
    """A copy of the grid holding its solid shapes only (the walls every method shares)."""
    solid = TileGrid(grid.cols, grid.rows, grid.tile_w, grid.tile_h)
    for shape in grid.shapes():
        if shape.kind is TileKind.SOLID:
            solid.put(shape.col, shape.row, shape)
    return solid


# --- the movers ---------------------------------------------------------------------------

class GameMover:
    """The game's own axis moves, as :meth:`World.step` makes them."""

    def __init__(self, grid: TileGrid) -> None:
        self.grid = grid

    def move(self, x: float, y: float, w: float, h: float, dx: float,
             dy: float) -> tuple[float, float]:
        return self.move_box(Box(x, y, w, h), dx, dy)

    def move_box(self, box: Box, dx: float, dy: float) -> tuple[float, float]:
        """The move from a body's own state: a level's bodies hold their place as a Box."""
        across = move_x(self.grid, box, dx)
        down = move_y(self.grid, across.box, dy)
        return down.box.x, down.box.y


class PlainMover:
    """The same sweeps on plain floats (:mod:`game.bench.plain_sweep`)."""

    def __init__(self, grid: TileGrid) -> None:
        self.walls = plain_sweep.PlainWalls.from_grid(grid)

    def move(self, x: float, y: float, w: float, h: float, dx: float,
             dy: float) -> tuple[float, float]:
        x = plain_sweep.sweep_x(self.walls, x, y, w, h, dx)
        return x, plain_sweep.sweep_y(self.walls, x, y, w, h, dy)


class _Sprite(pygame.sprite.Sprite):
    image: pygame.Surface
    rect: pygame.Rect

    def __init__(self, rect: pygame.Rect) -> None:
        super().__init__()
        self.image = PIXEL
        self.rect = rect


class TutorialMover:
    """The pygame tutorial loop: float position, rounded rect, ``spritecollide``, snap."""

    def __init__(self, grid: TileGrid) -> None:
        self.walls: pygame.sprite.Group[_Sprite] = pygame.sprite.Group(
            _Sprite(shape.box.to_rect()) for shape in grid.shapes())
        self.body = _Sprite(pygame.Rect(0, 0, 1, 1))

    def move(self, x: float, y: float, w: float, h: float, dx: float,
             dy: float) -> tuple[float, float]:
        body, walls, rect = self.body, self.walls, self.body.rect
        rect.size = (round(w), round(h))
        x += dx
        rect.topleft = (round(x), round(y))
        for wall in pygame.sprite.spritecollide(body, walls, False):
            if dx > 0:
                rect.right = wall.rect.left
            elif dx < 0:
                rect.left = wall.rect.right
            x = rect.x
        y += dy
        rect.y = round(y)
        for wall in pygame.sprite.spritecollide(body, walls, False):
            if dy > 0:
                rect.bottom = wall.rect.top
            elif dy < 0:
                rect.top = wall.rect.bottom
            y = rect.y
        return x, y


class ArcadeMover:
    """Arcade's platformer engine with no gravity of its own: the move is given to it.

    Arcade's y axis points up, so a box's top-left ``(x, y)`` in map pixels is the sprite
    centre ``(x + w / 2, H - y - h / 2)`` on a map ``H`` px tall.
    """

    def __init__(self, grid: TileGrid, arcade: Any) -> None:
        self.height_px = grid.height_px
        walls = arcade.SpriteList(use_spatial_hash=True)
        for shape in grid.shapes():
            b = shape.box
            walls.append(arcade.SpriteSolidColor(
                b.w, b.h, center_x=b.x + b.w / 2, center_y=self.height_px - b.y - b.h / 2,
                color=arcade.color.WHITE))
        self.sprite = arcade.SpriteSolidColor(int(BODY_W_PX), int(BODY_H_PX),
                                              color=arcade.color.WHITE)
        self.size = (BODY_W_PX, BODY_H_PX)
        self.engine = arcade.PhysicsEnginePlatformer(self.sprite, walls=walls,
                                                     gravity_constant=0.0)

    def move(self, x: float, y: float, w: float, h: float, dx: float,
             dy: float) -> tuple[float, float]:
        if (w, h) != self.size:
            self.sprite.width, self.sprite.height = w, h
            self.size = (w, h)
        sprite, height_px = self.sprite, self.height_px
        sprite.position = (x + w / 2, height_px - y - h / 2)
        sprite.change_x, sprite.change_y = dx, -dy
        self.engine.update()
        return sprite.left, height_px - sprite.top


def movers(grid: TileGrid, arcade: Any | None) -> dict[str, Mover]:
    """Every mover on one set of walls (Arcade's only when it is installed)."""
    built: dict[str, Mover] = {PLAIN: PlainMover(grid), GAME: GameMover(grid),
                               TUTORIAL: TutorialMover(grid)}
    if arcade is not None:
        built[ARCADE] = ArcadeMover(grid, arcade)
    return built


# --- the recorded moves -------------------------------------------------------------------

def recorded_moves(count: int) -> list[Sample]:
    """Up to ``count`` of the player's moves while The Summit is played to its exit,
    evenly spaced over the play."""
    samples = played_moves()
    if len(samples) <= count:
        return list(samples)
    return [samples[i * len(samples) // count] for i in range(count)]


@functools.cache
def played_moves() -> tuple[Sample, ...]:
    """Every move of the player while The Summit is played to its exit by its script.

    The play is the same every time (the tick is deterministic), so it is played once.
    """
    script = input_script(SCRIPT)
    world = World(load_level(LEVEL))
    last = script.events[-1].tick if script.events else 0
    samples: list[Sample] = []
    for tick in range(last + 1):
        world.step(script.held_at(tick))
        moves = world.moves.get(world.player)
        if moves is not None:
            across, down = moves.x, moves.y
            b = across.start
            samples.append(Sample(b.x, b.y, b.w, b.h, across.dx, down.dy))
    return tuple(samples)


def agreement(mover: Mover, reference: Mover, moves: Sequence[Sample]) -> int:
    """On how many moves the two movers end within ``SAME_PX`` of each other on both axes."""
    same = 0
    for s in moves:
        ax, ay = mover.move(*s)
        bx, by = reference.move(*s)
        same += abs(ax - bx) <= SAME_PX and abs(ay - by) <= SAME_PX
    return same


# --- accuracy scenes ----------------------------------------------------------------------

def scene(cols: int, rows: int, cells: Sequence[tuple[int, int]]) -> TileGrid:
    """A map of whole solid tiles in the given cells."""
    grid = TileGrid(cols, rows, TILE_PX, TILE_PX)
    for col, row in cells:
        grid.put(col, row, TileShape(Box(col * TILE_PX, row * TILE_PX, TILE_PX, TILE_PX),
                                     TileKind.SOLID, col, row))
    return grid


WALL_COL, FLOOR_ROW = 30, 15
WALL_SCENE = (40, 20, [(WALL_COL, r) for r in range(20)])            # a one-tile wall
FLOOR_SCENE = (40, 20, [(c, FLOOR_ROW) for c in range(40)])          # a one-tile floor
SEAM_SCENE = (SEAMS + 10, 20, [(c, FLOOR_ROW) for c in range(SEAMS + 1)])


class Flight(NamedTuple):
    tunnelled: bool
    short_px: float   # gap left to the face when stopped (negative: stopped inside)


def fly(mover: Mover, speed_px: float, gap_px: float, falling: bool) -> Flight:
    """One flight at a one-tile wall (across) or floor (falling) from ``gap_px`` away."""
    face = (WALL_COL if not falling else FLOOR_ROW) * TILE_PX
    w, h = BODY_W_PX, BODY_H_PX
    x, y = (face - gap_px - w, 5 * TILE_PX + 1.0) if not falling else (100.25, face - gap_px - h)
    for _ in range(int((gap_px + 2 * TILE_PX) / speed_px) + 3):
        dx, dy = (speed_px, 0.0) if not falling else (0.0, speed_px)
        nx, ny = mover.move(x, y, w, h, dx, dy)
        ahead, moved = (nx, nx - x) if not falling else (ny, ny - y)
        if ahead >= face + TILE_PX:
            return Flight(True, 0.0)
        if moved < speed_px - 1e-9:
            return Flight(False, face - (ahead + (w if not falling else h)))
        x, y = nx, ny
    return Flight(False, face - ((x + w) if not falling else (y + h)))


def flights(mover: Mover, speed_px: float, falling: bool) -> list[Flight]:
    """``PHASES`` flights, each starting at its own fraction of a tick's move away."""
    gaps = [TILE_PX + speed_px * (k + 0.5) / PHASES + 0.3 for k in range(PHASES)]
    return [fly(mover, speed_px, gap, falling) for gap in gaps]


def rest(mover: Mover) -> tuple[float, float]:
    """A body standing on a floor under gravity: (jitter: highest less lowest y after
    settling, mean height above flush), in px."""
    w, h = BODY_W_PX, BODY_H_PX
    flush = FLOOR_ROW * TILE_PX - h
    x, y, vy = 100.25, flush, 0.0
    heights: list[float] = []
    for tick in range(REST_TICKS):
        vy += GRAVITY_PX_PER_TICK2
        x, ny = mover.move(x, y, w, h, 0.0, vy)
        if ny - y < vy - 1e-9:
            vy = 0.0
        y = ny
        if tick >= SETTLE_TICKS:
            heights.append(y)
    return max(heights) - min(heights), sum(flush - v for v in heights) / len(heights)


def seams(mover: Mover) -> int:
    """Ticks on which a body running along a floor of separate tiles is held back."""
    w, h = BODY_W_PX, BODY_H_PX
    x, y, vy = 2.0, FLOOR_ROW * TILE_PX - h, 0.0
    snags = 0
    while x + w < SEAMS * TILE_PX + TILE_PX / 2:
        vy += GRAVITY_PX_PER_TICK2
        nx, ny = mover.move(x, y, w, h, RUN_PX_PER_TICK, vy)
        snags += nx - x < RUN_PX_PER_TICK - 1e-9
        if ny - y < vy - 1e-9:
            vy = 0.0
        x, y = (nx if nx > x else x + RUN_PX_PER_TICK), ny   # a snag is counted, then passed
    return snags


def accuracy(arcade: Any | None) -> list[Row]:
    """Every accuracy figure for every mover."""
    rows: list[Row] = []
    walls = movers(scene(*WALL_SCENE), arcade)
    floors = movers(scene(*FLOOR_SCENE), arcade)
    seam_floors = movers(scene(*SEAM_SCENE), arcade)
    for name in walls:
        stopped: list[float] = []
        for speed in SPEEDS_PX:
            done = flights(walls[name], speed, False) + flights(floors[name], speed, True)
            rows.append(Row(CHART, name, str(speed), 0, sum(f.tunnelled for f in done),
                            f"tunnelled flights (of {FLIGHTS_PER_SPEED})"))
            stopped += [f.short_px for f in done if not f.tunnelled]
        shorts = [max(0.0, s) for s in stopped]
        rows += [Row(CHART, name, "flush", 0, sum(shorts) / len(shorts) if shorts else 0.0,
                     "px short of flush (mean)"),
                 Row(CHART, name, "flush", 0, max(shorts, default=0.0), "px short of flush (max)"),
                 Row(CHART, name, "flush", 0, sum(s < 0 for s in stopped),
                     "stops inside the wall")]
        jitter, above = rest(floors[name])
        rows += [Row(CHART, name, "rest", 0, jitter, "px jitter at rest"),
                 Row(CHART, name, "rest", 0, above, "px above flush at rest (mean)"),
                 Row(CHART, name, "seams", 0, seams(seam_floors[name]),
                     f"snags on {SEAMS} seams")]
    return rows


# --- timing -------------------------------------------------------------------------------

def _replay(mover: Mover, moves: Sequence[Sample]) -> Callable[[], tuple[float, int]]:
    """Replay the moves from each method's own form of the body's state, made before the
    clock starts where the method keeps one (the game's Box; Arcade's sprite and the
    tutorial's rect are set inside the move, as they must be from floats)."""
    call: Callable[..., tuple[float, float]] = mover.move
    calls: list[tuple[Any, ...]] = list(moves)
    if isinstance(mover, GameMover):
        call, calls = mover.move_box, [(Box(s.x, s.y, s.w, s.h), s.dx, s.dy) for s in moves]

    def run() -> tuple[float, int]:
        started = clock()
        for arguments in calls:
            call(*arguments)
        return clock() - started, len(calls)
    return run


def _world_steps(ticks: int) -> Callable[[], tuple[float, int]]:
    """Play The Summit's first ``ticks`` ticks on a fresh world: time in steps, bodies moved."""
    level, script = load_level(LEVEL), input_script(SCRIPT)
    held = [script.held_at(tick) for tick in range(ticks)]

    def run() -> tuple[float, int]:
        world = World(level)
        spent, bodies = 0.0, 0
        for actions in held:
            bodies += len(world.bodies())
            started = clock()
            world.step(actions)
            spent += clock() - started
        return spent, bodies
    return run


def time_updates(cases: dict[str, Callable[[], tuple[float, int]]], rounds: int,
                 ) -> dict[str, list[float]]:
    """Seconds per update for every case, one figure per round, rounds interleaved."""
    times: dict[str, list[float]] = {name: [] for name in cases}
    names = list(cases)
    with collector_off():
        for name in names:   # one warm-up pass each, not kept
            cases[name]()
        for round_no in range(rounds):
            shift = round_no % len(names)
            for name in [*names[shift:], *names[:shift]]:
                seconds, ops = cases[name]()
                times[name].append(seconds / ops)
    return times


def measure(sizes: Sizes) -> list[Row]:
    arcade = arcade_module()
    grid = solid_grid(load_level(LEVEL).grid)
    moves = recorded_moves(sizes.peer_moves)
    on_summit = movers(grid, arcade)
    rows = [Row(CHART, ARCADE, "installed", 0, float(arcade is None), SKIPPED),
            Row(CHART, ARCADE, getattr(arcade, "__version__", "none"), 0, 1.0, VERSION),
            Row(CHART, "The Summit", "walls", 0, len(list(grid.shapes())), "solid tiles"),
            Row(CHART, "The Summit", "moves", 0, len(moves), "recorded moves")]
    for name, mover in on_summit.items():
        rows.append(Row(CHART, name, "moves", 0, agreement(mover, on_summit[GAME], moves),
                        SAME))
    cases = {name: _replay(mover, moves) for name, mover in on_summit.items()}
    cases[STEP] = _world_steps(sizes.peer_world_ticks)
    for name, seconds in time_updates(cases, sizes.verdict_rounds).items():
        rows += [Row(CHART, name, "update", r, s * 1e6, UPDATE) for r, s in enumerate(seconds)]
    return rows + accuracy(arcade)


# --- reading the rows ---------------------------------------------------------------------

def skipped(rows: list[Row]) -> bool:
    """Was Arcade missing in this run?"""
    return bool(values(rows, method=ARCADE, unit=SKIPPED)[0])


def version(rows: list[Row]) -> str:
    """Arcade's version in this run ("none" when it was skipped)."""
    return next(r.parameter for r in rows if r.unit == VERSION)


def per_update(rows: list[Row], method: str) -> list[float]:
    return values(rows, method=method, parameter="update", unit=UPDATE)


def timed_methods(rows: list[Row]) -> list[str]:
    """The methods timed in this run, in chart order."""
    return [m for m in (PLAIN, GAME, STEP, TUTORIAL, ARCADE) if per_update(rows, m)]


def tunnelled(rows: list[Row], method: str) -> int:
    return int(sum(values(rows, method=method, unit=f"tunnelled flights (of "
                                                    f"{FLIGHTS_PER_SPEED})")))


def figure_of(rows: list[Row], method: str, unit: str) -> float:
    return values(rows, method=method, unit=unit)[0]


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("The peer: time per update against accuracy, same walls and "
                               "moves (The Summit)", width_in=14, height_in=8.5)
    grid = figure.add_gridspec(2, 2, height_ratios=(1.25, 1))
    left, right = figure.add_subplot(grid[0, 0]), figure.add_subplot(grid[0, 1])
    methods = timed_methods(rows)
    colours = {m: charts.colour(i) for i, m in enumerate((PLAIN, GAME, STEP, TUTORIAL, ARCADE))}
    for index, method in enumerate(methods):
        spread = median_interval(per_update(rows, method))
        left.barh(index, spread.estimate, color=colours[method],
                  xerr=[[spread.estimate - spread.low], [spread.high - spread.estimate]],
                  capsize=4)
        left.annotate(f" {spread.text()} µs", (spread.high, index), va="center", fontsize=8)
    left.set_yticks(range(len(methods)), methods, fontsize=8)
    left.invert_yaxis()
    left.set_xlabel("time per update, median of interleaved rounds [95 % interval] (µs)")
    left.set_xlim(right=max(median(per_update(rows, m)) for m in methods) * 1.6)
    left.grid(True, axis="x", alpha=0.3)
    if skipped(rows):
        left.set_title("Arcade skipped: not installed (pip install -e '.[peers]')",
                       fontsize=9, color="#aa0000")
    else:
        ratio = paired_ratio(per_update(rows, ARCADE), per_update(rows, GAME))
        left.set_title(f"Arcade {version(rows)}: its update takes {ratio.text()}x as long as "
                       "move_x + move_y", fontsize=9)
    for method in [m for m in methods if m != STEP]:
        right.plot(SPEEDS_PX, [values(rows, method=method, parameter=str(v),
                                      unit=f"tunnelled flights (of {FLIGHTS_PER_SPEED})")[0]
                               for v in SPEEDS_PX],
                   marker="o", color=colours[method], label=method,
                   linestyle="--" if method == GAME else "-", markersize=7 if method == PLAIN
                   else 4)
    right.set_xticks(SPEEDS_PX)
    right.set_xlabel("speed (px per tick) at a one-tile (16 px) wall or floor")
    right.set_ylabel(f"tunnelled flights (of {FLIGHTS_PER_SPEED})")
    right.set_title("Flights that ended beyond the wall", fontsize=10)
    right.set_ylim(-1, FLIGHTS_PER_SPEED + 1)
    right.grid(True, alpha=0.3)
    right.legend(fontsize=8)
    table = figure.add_subplot(grid[1, :])
    table.axis("off")
    moves = int(figure_of(rows, "The Summit", "recorded moves"))
    header = ["method", "µs per update", "tunnelled flights\n(8-64 px/tick)",
              "short of flush,\nmean / max (px)", "stops inside\nthe wall",
              "jitter at rest\n(px)", f"snags on\n{SEAMS} seams",
              f"same end as\nmove_x + move_y\n(±{SAME_PX:g} px, of {moves})"]
    body = []
    short = {PLAIN: "plain-float sweep", GAME: "move_x + move_y", STEP: "World.step per body",
             TUTORIAL: "spritecollide loop", ARCADE: f"Arcade {version(rows)} update"}
    for method in methods:
        if method == STEP:
            body.append([short[method], median_interval(per_update(rows, method)).text()]
                        + ["its moves are"] + ["move_x + move_y"] + [""] * 4)
            continue
        body.append([
            short[method], median_interval(per_update(rows, method)).text(),
            f"{tunnelled(rows, method)} of {FLIGHTS_PER_SPEED * len(SPEEDS_PX)}",
            f"{figure_of(rows, method, 'px short of flush (mean)'):.3f} / "
            f"{figure_of(rows, method, 'px short of flush (max)'):.3f}",
            f"{figure_of(rows, method, 'stops inside the wall'):.0f}",
            f"{figure_of(rows, method, 'px jitter at rest'):.3f}",
            f"{figure_of(rows, method, f'snags on {SEAMS} seams'):.0f}",
            f"{figure_of(rows, method, SAME):.0f}"])
    drawn = table.table(cellText=body, colLabels=header, loc="center", cellLoc="left",
                        colLoc="left", colWidths=[0.16] + [0.12] * 7)
    drawn.auto_set_font_size(False)
    drawn.set_fontsize(8)
    drawn.scale(1.0, 2.2)
    return charts.save(figure, out / f"{CHART}.png", footnote)
