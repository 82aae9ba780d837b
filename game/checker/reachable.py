"""Everything the player could ever touch: a generous flood fill that can prove a map unwinnable.

Where it sits: ``python -m game.levels check`` and ``solve`` ask it before they search.
A search that finds nothing proves nothing; this module proves the opposite direction: if
the Exit lies outside the region computed here, *no* input wins the level, so the checker may
call the map impossible.

What it teaches: **over-approximation**. Instead of simulating the player exactly, follow one
point of it (the middle of its feet) through the tile cells, allowing *more* than the game
allows and never less:

* **Open cells.** Only a cell wholly filled by a Solid tile is closed; partial tiles, one-way
  tiles and spikes are all open (spikes can be crossed while invulnerable).
* **Launches.** Wherever the feet can rest (the top of any Solid or OneWay shape, any point
  of a moving platform's path, and an enemy's head, which gives a jump after a stomp) the
  player may jump. The rise allowed there is the highest a jump rises *in the game's own
  tick* (:func:`jump_rise`), or a stomp's bounce where that is faster, a little more for a
  platform's lift, plus an enemy's height and hop where enemies are.
* **Carried and pushed.** A moving platform carries a body on its top and pushes one at its
  sides or underside, so every cell the feet of a body touching its box can be in, anywhere
  along its path, is one group: reaching one reaches all, and each is a launch (a body
  carried or pushed there may leave it jumping or falling).
* **Stomps anywhere.** An enemy goes its own way whatever the player does (only a stomp
  ends it), so where its head can be is worked out once by a fill of the enemy's own
  (:func:`enemy_heads`: its body, its fastest speed, its hop, carried and pushed by the
  platforms) and every place in it is a launch.
* **The jump envelope.** After ``k`` ticks in the air (counting the coyote ticks before the
  jump) the feet are at most ``k`` ticks of full run speed to either side, and no higher than
  the best jump has risen by then. Every cell a jump could pass through, walls ignored for
  the bound but respected for the passage (the point moves only through open cells, to any of
  its 8 neighbours), is reached.
* **Falling.** Once the feet are well below where they left the ground, the fall is fast
  enough that each row down allows at most a bounded sideways step; the fill carries on
  downward with that rule, and any place the feet can rest starts a new launch.
* **Respawns.** A checkpoint whose column the reached region crosses adds its respawn place
  as a new start. The game works that place out when the flag counts, with the platforms
  where they are then; a flag a platform's route crosses over its foot may put the player
  elsewhere, anywhere within the range :func:`moved_respawns` gives, and the fill starts
  from all of it. Where no range is found, the fill says so (:attr:`Reach.unbounded`), and
  an Exit it misses then proves nothing.
* **Lives.** Spikes and enemies never stop the fill, and a lost life only sends the player
  to a start above, so lives never widen it.

Each rule only ever lets the point go further than the game would, so if an Exit's cells
are never reached, the map cannot be won. The converse does not hold: a reached Exit proves
nothing, which is what the search is for.

The fill's work is counted, never timed: each cell a jump or a fall looks at, and each point
of a moving platform's path, counts one step, and after :data:`MAX_FILL_STEPS` the fill gives
up and proves nothing (:func:`reachable` gives None, as for physics with no bound): on the
biggest map the game reads, with floors everywhere, the fill would otherwise take minutes.

Two questions, from cheap to sharp: :func:`open_path` (is there any open way at all, gravity
ignored?) and :func:`reachable` (is the Exit inside the jump envelope's fill?). Asked
``narrow``, :func:`reachable` rides platforms' tops only and stomps enemies only where they
start: a cheaper fill and a tighter guide for the search, which proves nothing, but where it
reaches an Exit the full fill does too.
"""

from __future__ import annotations

import math
from collections import deque
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, replace

from game.collision.aabb import Box
from game.collision.axis_sweep import ground_under
from game.collision.free_place import nearest_free_place
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.sim.level import Level
from game.sim.platforms import route_region
from game.sim.tuning import Tuning
from game.sim.world import World

Cell = tuple[int, int]
SLACK_PX = 0.5  # rounding room on every bound
FALL_DEPTH_PX = 24.0  # below the launch by this much, the fill switches to falling
MAX_AIR_TICKS = 10_000
MAX_FILL_STEPS = 3_000_000  # cells looked at (and path points walked) by one jump fill
RIDE_ROW = -(10**9)  # steps_to_exit's nodes for a platform ride sit in this row


class FillTooBig(Exception):
    """The jump fill would take more than :data:`MAX_FILL_STEPS` steps."""


@dataclass
class FillWork:
    """The steps a jump fill has taken, against its budget."""

    budget: int = field(default_factory=lambda: MAX_FILL_STEPS)
    steps: int = 0

    def spend(self, steps: int) -> None:
        self.steps += steps
        if self.steps > self.budget:
            raise FillTooBig(f"more than {self.budget:,} steps")


def jump_rise(tuning: Tuning) -> list[float]:
    """How far above its take-off a full jump has risen after each tick, using the tick's
    own rule (the jump sets the speed, gravity is added, then the body moves), until it comes
    back down to its take-off height.

    >>> round(max(jump_rise(Tuning())), 1)
    44.3
    """
    vy, y, heights = -tuning.jump_speed_px_s, 0.0, [0.0]
    for _ in range(MAX_AIR_TICKS):
        vy = min(vy + tuning.gravity_px_s2 * tuning.tick_s, tuning.max_fall_speed_px_s)
        y += vy * tuning.tick_s
        heights.append(-y)
        if y > 0:
            break
    return heights


def fall_speed_after(tuning: Tuning, depth_px: float) -> float:
    """The slowest a body can be falling once its feet are ``depth_px`` below where it left
    the ground (it left at rest: a jump only makes it faster there)."""
    vy, y = 0.0, 0.0
    for _ in range(MAX_AIR_TICKS):
        if y >= depth_px:
            return vy
        vy = min(vy + tuning.gravity_px_s2 * tuning.tick_s, tuning.max_fall_speed_px_s)
        y += vy * tuning.tick_s
    return vy


@dataclass(frozen=True)
class Envelope:
    """The jump envelope of one tuning: how high the feet may be at each sideways distance."""

    rise_by_tick: tuple[float, ...]  # the best height reachable by tick k (coyote included)
    step_px: float  # the farthest the feet move sideways in one tick
    slack_x_px: float  # corner correction and rounding
    extra_rise_px: float  # an enemy's head or a platform's lift, where they are
    air_ticks_to_depth: int  # ticks until the longest jump is FALL_DEPTH_PX below take-off
    sideways_cells_per_row: int  # the widest sideways step per row once falling

    def rise_at(self, distance_px: float) -> float:
        """The most the feet can be above take-off ``distance_px`` to one side of it."""
        if self.step_px <= 0:
            first = 0 if distance_px <= self.slack_x_px else len(self.rise_by_tick)
        else:
            first = max(0, math.ceil((distance_px - self.slack_x_px) / self.step_px - 1e-9))
        if first >= len(self.rise_by_tick):
            return -math.inf
        return self.rise_by_tick[first] + self.extra_rise_px

    @property
    def reach_x_px(self) -> float:
        return self.step_px * self.air_ticks_to_depth + self.slack_x_px


def envelope_of(level: Level, tuning: Tuning, enemies: bool = True) -> Envelope | None:
    """The envelope for ``level`` played with ``tuning``; None when gravity does not bring a
    jump back down (then no bound on the reach can be given). ``enemies``: whether the
    level's enemies add a stomp to the rise (False for an enemy's own envelope, which
    :func:`enemy_heads` and :func:`enemy_cells` work out)."""
    if tuning.gravity_px_s2 <= 0 or tuning.max_fall_speed_px_s <= 0:
        return None
    if enemies and level.enemies and tuning.stomp_bounce_px_s > tuning.jump_speed_px_s:
        tuning = replace(tuning, jump_speed_px_s=tuning.stomp_bounce_px_s)  # a stomp's rise
    rise = jump_rise(tuning)
    if rise[-1] >= 0:  # never came back down within the ticks looked at
        return None
    y, heights = -rise[-1], list(rise)  # carry on down to FALL_DEPTH_PX below take-off
    vy = (heights[-2] - heights[-1]) / tuning.tick_s
    while y < FALL_DEPTH_PX + SLACK_PX and len(heights) < MAX_AIR_TICKS:
        vy = min(vy + tuning.gravity_px_s2 * tuning.tick_s, tuning.max_fall_speed_px_s)
        y += vy * tuning.tick_s
        heights.append(-y)
    coyote = tuning.coyote_ticks + 1
    # At tick k since leaving the ground the jump may have started up to ``coyote`` ticks
    # late (the feet on or below take-off until then).
    at_tick = [max(0.0 if k < late else heights[k - late] if k - late < len(heights)
                   else -math.inf for late in range(coyote + 1))
               for k in range(len(heights) + coyote)]
    # A slower run reaches the same sideways distance later: the best at that tick or after.
    for k in range(len(at_tick) - 2, -1, -1):
        at_tick[k] = max(at_tick[k], at_tick[k + 1])
    lift = max((p.speed_px_s * tuning.tick_s for p in level.platforms), default=0.0)
    enemy = 0.0
    if enemies and level.enemies:
        enemy = max(e.box.h for e in level.enemies) + SLACK_PX
        if any(e.kind == "hopper" for e in level.enemies):
            hop = Tuning(jump_speed_px_s=tuning.hopper_jump_speed_px_s,
                         gravity_px_s2=tuning.gravity_px_s2,
                         max_fall_speed_px_s=tuning.max_fall_speed_px_s)
            enemy += max(jump_rise(hop))
    falling = fall_speed_after(tuning, FALL_DEPTH_PX)
    grid = level.grid
    sideways = (grid.cols if falling <= 0 else
                max(1, math.ceil(tuning.run_speed_px_s / falling * grid.tile_h / grid.tile_w)))
    return Envelope(tuple(at_tick), tuning.run_speed_px_s * tuning.tick_s,
                    tuning.corner_correction_px + SLACK_PX, lift + enemy + SLACK_PX,
                    len(at_tick), sideways)


def _closed_cells(grid: TileGrid) -> set[Cell]:
    """Cells wholly filled by one Solid tile shape."""
    return {(s.col, s.row) for s in grid.shapes()
            if s.kind is TileKind.SOLID and s.box.w >= grid.tile_w and s.box.h >= grid.tile_h}


def feet_cell(grid: TileGrid, x: float, feet_y: float) -> Cell:
    """The cell of the point ``x`` at feet height ``feet_y``, as the fill reads a body's
    feet (:data:`SLACK_PX` up, so feet flush on a top are in the cell above it)."""
    return math.floor(x / grid.tile_w), math.floor((feet_y - SLACK_PX) / grid.tile_h)


def target_cells(level: Level, body: Box) -> set[Cell]:
    """The cells the middle of the feet is in when the body touches an Exit."""
    grid = level.grid
    cells: set[Cell] = set()
    for goal in level.exits:
        left, right = goal.left - body.w / 2 - SLACK_PX, goal.right + body.w / 2 + SLACK_PX
        top, bottom = goal.top - SLACK_PX, goal.bottom + body.h + SLACK_PX
        for col in range(math.floor(left / grid.tile_w), math.floor(right / grid.tile_w) + 1):
            for row in range(math.floor(top / grid.tile_h),
                             math.floor(bottom / grid.tile_h) + 1):
                cells.add((col, row))
    return cells


@dataclass(frozen=True)
class Start:
    """Where the player (re)starts, with the columns whose crossing makes it count."""

    box: Box
    columns: frozenset[int]  # empty: the spawn, counted from the start
    # what the fill cannot bound about this start, said when it counts (else None)
    unbounded: str | None = None
    # where a platform may move the respawn to: the range of its top-left corner (else None)
    moved: Box | None = None


def starts(world: World) -> list[Start]:
    """The spawn, then each checkpoint's respawn place, found as the world finds it with the
    tiles alone. A flag some moving platform's route overlaps where the player comes back
    may be counted while the platform fills that place, and the respawn is then moved to
    wherever is free: the start gives the range it may be moved in (:attr:`Start.moved`),
    or says that none was found (:attr:`Start.unbounded`)."""
    level, grid = world.level, world.level.grid
    found = [Start(world.spawn, frozenset())]
    w, h = level.spawn.w, level.spawn.h
    for flag in level.checkpoints:
        standing = Box(flag.x + (flag.w - w) / 2, flag.bottom - h, w, h)
        place = nearest_free_place(grid, standing)
        first = math.floor((flag.left - w) / grid.tile_w)
        last = math.floor((flag.right + w) / grid.tile_w)
        columns = frozenset(range(first, last + 1))
        regions = [route_region(spec) for spec in level.platforms]
        if not any(region.overlaps(standing) for region in regions):
            found.append(Start(place, columns))
            continue
        area = moved_respawns(grid, standing, regions)
        col, row = math.floor(flag.x / grid.tile_w), math.floor(flag.y / grid.tile_h)
        found.append(Start(place, columns, None if area is not None else
                           f"a respawn moved by a moving Platform (the Checkpoint at tile "
                           f"({col},{row}) may be counted while a Platform fills the place "
                           "the player comes back to)", area))
    return found


def moved_respawns(grid: TileGrid, standing: Box, regions: list[Box]) -> Box | None:
    """The range of top-left corners where the game may put a player coming back to a flag
    whose place (``standing``) some platforms' routes cross (``regions``, each route's box
    grown by its platform's size), or None if no bound is found.

    The game (:func:`~game.collision.free_place.nearest_free_place`, with the platforms
    where they are when the flag counts) tries, in a window it widens round the place, each
    coordinate where it was or flush with a face of a wall in the window, and stops at the
    nearest free place, or at the latest at the first window that holds the whole map, at
    the nearest place it tried there. A candidate of the tiles' faces alone, in one of those
    windows, that is free of the tiles and of every route is free wherever the platforms
    are: the game stops no farther from the place than that candidate, in x and in y."""
    w, h = standing.w, standing.h
    search, whole_map = 64.0, max(grid.width_px, grid.height_px)  # as the game's
    while True:
        window = Box(standing.x - search, standing.y - search, w + 2 * search, h + 2 * search)
        tiles = [s.box for s in grid.shapes_in(window) if s.kind is TileKind.SOLID]
        xs = {standing.x} | {b.left - w for b in tiles} | {b.right for b in tiles}
        ys = {standing.y} | {b.top - h for b in tiles} | {b.bottom for b in tiles}
        # a candidate ends at most a tile and its own size past the window
        around = Box(window.x - w - grid.tile_w, window.y - h - grid.tile_h,
                     window.w + 2 * (w + grid.tile_w), window.h + 2 * (h + grid.tile_h))
        walls = [*regions, *(s.box for s in grid.shapes_in(around) if s.kind is TileKind.SOLID)]
        free = [math.hypot(x - standing.x, y - standing.y) for x in xs for y in ys
                if not any(Box(x, y, w, h).overlaps(b) for b in walls)]
        if free:
            reach = min(free)
            return Box(standing.x - reach, standing.y - reach, 2 * reach, 2 * reach)
        if search >= whole_map:
            return None
        search *= 2


@dataclass
class Reach:
    """What a fill reached: the cells, and whether it touched an Exit."""

    cells: set[Cell]
    touches_exit: bool
    targets: set[Cell]
    # for each cell, the fewest steps of the fill from it to a target (the jump fill only)
    steps: dict[Cell, int] = field(default_factory=dict)
    # the mechanics met on the way that the fill does not bound: while there are any, an
    # Exit left out proves nothing
    unbounded: list[str] = field(default_factory=list)
    # the starts the fill began from: the spawn, then each checkpoint's as its flag counted
    counted: list[Start] = field(default_factory=list)

    def nearest_to_exit(self) -> Cell | None:
        """The reached cell closest (as the crow flies) to an Exit's cells."""
        if not self.cells or not self.targets:
            return None
        return min(sorted(self.cells),
                   key=lambda c: min(math.dist(c, t) for t in self.targets))


def _in_map(grid: TileGrid, cell: Cell, sky_rows: int) -> bool:
    return 0 <= cell[0] < grid.cols and -sky_rows <= cell[1] < grid.rows


def _flood(world: World, fill: _Fill) -> Reach:
    """Run ``fill`` from the spawn, adding each checkpoint's start once its columns are met
    (a flag counts when the player passes it)."""
    found = starts(world)
    pending = found[1:]
    unbounded: list[str] = []
    counted = found[:1]
    fill.seed(found[0].box, _standing(world, found[0].box))
    while True:
        reached = fill.run()
        columns = {col for col, _ in reached}
        woken = [start for start in pending if columns & start.columns]
        if not woken:
            break
        for start in woken:
            pending.remove(start)
            counted.append(start)
            fill.seed(start.box, _standing(world, start.box))
            if start.unbounded is not None:
                unbounded.append(start.unbounded)
            if start.moved is not None:
                fill.seed_anywhere(start.moved, world.spawn)
    targets = {cell for cell in target_cells(world.level, world.spawn) if fill.open(cell)}
    return Reach(reached, bool(reached & targets), targets, unbounded=unbounded,
                 counted=counted)


def _standing(world: World, box: Box) -> bool:
    return ground_under(world.solids, box) is not None


_NEIGHBOURS = tuple((dc, dr) for dc in (-1, 0, 1) for dr in (-1, 0, 1)
                    if dc or dr)  # the eight cells round a cell, in the order an arc visits them


class _Fill:
    """A fill that can be seeded again and run on (the base: an open-cell flood)."""

    def __init__(self, level: Level, sky_rows: int) -> None:
        self.level = level
        self.grid = level.grid
        self.closed = _closed_cells(level.grid)
        self.sky_rows = sky_rows
        self.seen: set[Cell] = set()
        self.queue: deque[Cell] = deque()

    def open(self, cell: Cell) -> bool:
        return _in_map(self.grid, cell, self.sky_rows) and cell not in self.closed

    def seed(self, box: Box, standing: bool) -> None:
        del standing  # an open-cell flood ignores gravity
        cell = feet_cell(self.grid, box.x + box.w / 2, box.bottom)
        if cell not in self.seen:
            self.seen.add(cell)
            self.queue.append(cell)

    def cells_of(self, corners: Box, body: Box) -> Iterator[Cell]:
        """The open cells the middle of the feet is in for a body whose top-left corner is
        anywhere in ``corners``."""
        grid = self.grid
        first = feet_cell(grid, corners.left + body.w / 2, corners.top + body.h)
        last = feet_cell(grid, corners.right + body.w / 2, corners.bottom + body.h)
        for col in range(first[0], last[0] + 1):
            for row in range(first[1], last[1] + 1):
                if self.open((col, row)):
                    yield col, row

    def seed_anywhere(self, corners: Box, body: Box) -> None:
        """Start from anywhere a body whose top-left corner is in ``corners`` can be."""
        for cell in self.cells_of(corners, body):
            if cell not in self.seen:
                self.seen.add(cell)
                self.queue.append(cell)

    def run(self) -> set[Cell]:
        while self.queue:
            col, row = self.queue.popleft()
            for near in ((col + 1, row), (col - 1, row), (col, row + 1), (col, row - 1)):
                if near not in self.seen and self.open(near):
                    self.seen.add(near)
                    self.queue.append(near)
        return set(self.seen)


def open_path(world: World, opened: frozenset[Cell] = frozenset(),
              closed: frozenset[Cell] = frozenset()) -> Reach:
    """Cells joined to the spawn by open cells (4 neighbours), gravity ignored; the sky above
    the map is open along its whole width. ``opened``: closed cells to count as open (to ask
    whether some tiles are what closes the way); ``closed``: open cells to count as closed
    (to ask whether the way passes through them)."""
    fill = _Fill(world.level, sky_rows=2)
    fill.closed = (fill.closed - opened) | closed
    return _flood(world, fill)


class _JumpFill(_Fill):
    """The jump envelope's fill: launches, arcs within the envelope, and falls."""

    def __init__(self, level: Level, envelope: Envelope, body: Box, work: FillWork,
                 heads: Iterable[tuple[float, float, float]] = (), narrow: bool = False,
                 ) -> None:
        grid = level.grid
        self.work = work
        self.narrow = narrow
        groups = self._platform_groups(level, body, work, narrow)
        launches = self._launch_heights(level, body, work, [] if narrow else groups, heads)
        top = min([row for _, row in launches] + [0])
        rise_rows = math.ceil(max(envelope.rise_by_tick) + envelope.extra_rise_px) // max(
            1, grid.tile_h) + 2
        super().__init__(level, sky_rows=max(0, -top) + rise_rows)
        self.envelope = envelope
        self.launch_y = launches  # cell -> the highest feet height resting in it
        self.launched: set[Cell] = set()
        self.moves: dict[Cell, set[Cell]] = {}  # every step from cell to cell the fill made
        self.falling: set[tuple[int, int, bool]] = set()
        self.fall_queue: deque[tuple[int, int, bool]] = deque()
        self.platform_cells = groups

    @staticmethod
    def _launch_heights(level: Level, body: Box, work: FillWork, groups: list[set[Cell]],
                        heads: Iterable[tuple[float, float, float]]) -> dict[Cell, float]:
        grid = level.grid
        heights: dict[Cell, float] = {}

        def rest(left: float, right: float, top: float) -> None:
            row = math.floor((top - SLACK_PX) / grid.tile_h)
            first = math.floor((left - body.w / 2) / grid.tile_w)
            last = math.floor((right + body.w / 2) / grid.tile_w)
            work.spend(max(1, last - first + 1))
            for col in range(first, last + 1):
                if heights.get((col, row), math.inf) > top:
                    heights[(col, row)] = top

        closed = _closed_cells(grid)
        for shape in grid.shapes():
            buried = (shape.box.top == shape.row * grid.tile_h
                      and (shape.col, shape.row - 1) in closed)  # a wall's inside
            if shape.kind is not TileKind.HAZARD and not buried:
                rest(shape.box.left, shape.box.right, shape.box.top)
        for spec in level.platforms:
            for x, y in _along(spec.path.legs, spec.path.points, min(grid.tile_w, grid.tile_h) / 4):
                rest(x, x + spec.width_px, y)
        for group in groups:  # carried or pushed there, the player may leave from anywhere
            work.spend(len(group))
            for col, row in group:
                if heights.get((col, row), math.inf) > row * grid.tile_h:
                    heights[(col, row)] = row * grid.tile_h
        for left, right, top in heads:  # a stomp wherever an enemy's head can be
            rest(left, right, top)
        return heights

    @staticmethod
    def _platform_groups(level: Level, body: Box, work: FillWork,
                         narrow: bool = False) -> list[set[Cell]]:
        """For each platform, every cell the feet of a body touching its box can be in,
        anywhere along its path: riding its top, pushed by its sides, pushed down by its
        underside; carried or pushed, the body goes wherever the platform goes.
        ``narrow``: only riding its top (a guide, not a bound)."""
        grid = level.grid
        groups: list[set[Cell]] = []
        for spec in level.platforms:
            cells: set[Cell] = set()
            for x, y in _along(spec.path.legs, spec.path.points, min(grid.tile_w, grid.tile_h) / 4):
                top = math.floor((y - SLACK_PX) / grid.tile_h) - 1  # pushed up a little
                bottom = (top + 2 if narrow else  # or down a little
                          math.floor((y + spec.height_px + body.h) / grid.tile_h) + 1)
                first = math.floor((x - body.w / 2 - SLACK_PX) / grid.tile_w)
                last = math.floor((x + spec.width_px + body.w / 2 + SLACK_PX) / grid.tile_w)
                work.spend((last - first + 1) * (bottom - top + 1))
                for col in range(first, last + 1):
                    for row in range(top, bottom + 1):
                        cells.add((col, row))
            groups.append(cells)
        return groups

    def seed(self, box: Box, standing: bool) -> None:
        """Start at ``box``: a jump from where it stands, or a fall from where it floats."""
        cell = feet_cell(self.grid, box.x + box.w / 2, box.bottom)
        if self.narrow:
            self.seen.add(cell)
        else:  # a start on a platform's route rides or is pushed from there
            self._reach_cell(cell)
        if standing:
            self.launch_y[cell] = min(self.launch_y.get(cell, math.inf), box.bottom)
            self.queue.append(cell)
        else:
            self._arc(cell, box.bottom, max_rise=0.0)

    def seed_anywhere(self, corners: Box, body: Box) -> None:
        """Start from anywhere a body whose top-left corner is in ``corners`` can be: a
        jump from each of those cells, from its top (more than a fall from rest allows)."""
        for cell in self.cells_of(corners, body):
            self.work.spend(1)
            self.launch_y[cell] = min(self.launch_y.get(cell, math.inf),
                                      cell[1] * self.grid.tile_h)
            self.launched.discard(cell)
            self._reach_cell(cell)
            self.queue.append(cell)

    def _reach_cell(self, cell: Cell) -> None:
        if cell not in self.seen:
            self.work.spend(1 + len(self.platform_cells))
            self.seen.add(cell)
            if cell in self.launch_y:
                self.queue.append(cell)
            for group in self.platform_cells:
                if cell in group:
                    for carried in group:
                        if carried not in self.seen and self.open(carried):
                            self.seen.add(carried)
                            if carried in self.launch_y:
                                self.queue.append(carried)

    def run(self) -> set[Cell]:
        while self.queue or self.fall_queue:
            while self.queue:
                cell = self.queue.popleft()
                if cell not in self.launched and cell in self.launch_y:
                    self.launched.add(cell)
                    self._arc(cell, self.launch_y[cell])
            while self.fall_queue:
                self._fall_step(self.fall_queue.popleft())
        return set(self.seen)

    def _arc(self, start: Cell, feet_y: float, max_rise: float = math.inf) -> None:
        """Every open cell a jump from ``start`` (feet at ``feet_y``) could pass through,
        rising at most ``max_rise`` (0: a fall from rest). The sideways distance to each
        column and the most a jump rises there are worked out once per arc, and
        :meth:`open` is written out in the loop: this loop is most of a check's time."""
        grid, env = self.grid, self.envelope
        tile_w, tile_h = grid.tile_w, grid.tile_h
        cols, rows, top = grid.cols, grid.rows, -self.sky_rows
        closed, moves, spend = self.closed, self.moves, self.work.spend
        reach_x_px = env.reach_x_px
        x_lo, x_hi = start[0] * tile_w, (start[0] + 1) * tile_w  # the feet's x is in here
        by_column: dict[int, tuple[float, float]] = {}  # (sideways distance, rise)
        local: set[Cell] = {start}
        queue: deque[Cell] = deque([start])
        while queue:
            cell = queue.popleft()
            col, row = cell
            spend(8)
            leads_to: set[Cell] | None = None
            for dc, dr in _NEIGHBOURS:
                near = (col + dc, row + dr)
                if not (0 <= near[0] < cols and top <= near[1] < rows) or near in closed:
                    continue
                known = by_column.get(near[0])
                if known is None:
                    c_lo = near[0] * tile_w
                    distance = max(0.0, c_lo - x_hi, x_lo - c_lo - tile_w)
                    known = by_column[near[0]] = (distance, min(max_rise,
                                                                env.rise_at(distance)))
                distance, rise = known
                lowest_y = (near[1] + 1) * tile_h  # the cell's bottom: the least rise
                if lowest_y <= feet_y - rise:
                    continue  # wholly above what a jump reaches at that distance
                if leads_to is None:
                    leads_to = moves.setdefault(cell, set())
                leads_to.add(near)
                if near in local:
                    continue
                local.add(near)
                depth = near[1] * tile_h - feet_y  # how far below take-off, at least
                if depth >= FALL_DEPTH_PX:
                    self._start_fall(near)
                elif distance > reach_x_px:
                    continue
                else:
                    queue.append(near)
        for cell in local:
            self._reach_cell(cell)

    def _start_fall(self, cell: Cell) -> None:
        state = (cell[0], cell[1], False)
        if state not in self.falling:
            self.falling.add(state)
            self.fall_queue.append(state)

    def _fall_step(self, state: tuple[int, int, bool]) -> None:
        """Falling: one row down to any of three cells, or one sideways step per row (a
        step wider than one cell must pass the open cells between)."""
        col, row, stepped = state
        self._reach_cell((col, row))
        sideways = min(self.envelope.sideways_cells_per_row, self.grid.cols)
        rows = [(row + 1, False)] + ([] if stepped else [(row, True)])
        for near_row, sideways_step in rows:
            if not sideways_step and self.open((col, near_row)):
                self._fall_to((col, row), (col, near_row, False))
            for direction in (-1, 1):
                for dc in range(1, sideways + 1):
                    self.work.spend(1)
                    near = (col + direction * dc, near_row, sideways_step)
                    if not self.open((near[0], near[1])):
                        break  # no wider step passes a closed cell
                    self._fall_to((col, row), near)

    def _fall_to(self, cell: Cell, near: tuple[int, int, bool]) -> None:
        """One move of a fall from ``cell`` to the open place ``near``."""
        self.moves.setdefault(cell, set()).add((near[0], near[1]))
        if near not in self.falling:
            self.falling.add(near)
            self.fall_queue.append(near)


def _along(legs: Iterable[tuple[tuple[float, float], tuple[float, float]]],
           points: tuple[tuple[float, float], ...], step: float,
           ) -> Iterator[tuple[float, float]]:
    """Points along a path no more than ``step`` apart (its corners included)."""
    yield from points
    for (x0, y0), (x1, y1) in legs:
        count = max(1, math.ceil(math.dist((x0, y0), (x1, y1)) / max(step, 1e-9)))
        for i in range(1, count):
            yield x0 + (x1 - x0) * i / count, y0 + (y1 - y0) * i / count


def steps_to_exit(world: World) -> dict[Cell, int] | None:
    """For every cell the fill reached, the fewest of its steps (cell to cell, as the fill
    moved) to a cell where the player touches an Exit; a cell from which no step leads
    there is left out. None when the tuning gives no bound. A guide for the search: a place
    left out is one from which, by the proof above, no route can go on to an Exit. The
    narrow fill's steps when it reaches an Exit (they lead more tightly); the full fill's
    otherwise, and none (empty) when it met a mechanic it does not bound."""
    guide = reachable(world, narrow=True)
    if guide is None or guide.touches_exit:
        return None if guide is None else guide.steps
    reach = reachable(world)
    if reach is None:
        return None
    return {} if reach.unbounded and not reach.touches_exit else reach.steps


def _steps_back(fill: _JumpFill, reach: Reach) -> dict[Cell, int]:
    """:attr:`Reach.steps`: a breadth-first walk back along the fill's moves from the
    targets (a moving platform's cells all join through one node: its ride)."""
    back: dict[Cell, list[Cell]] = {}
    for cell, nears in fill.moves.items():
        for near in nears:
            back.setdefault(near, []).append(cell)
    for number, group in enumerate(fill.platform_cells):  # a ride: any of its cells to any
        ride = (-1 - number, RIDE_ROW)  # a node standing for the whole ride
        back[ride] = sorted(group & reach.cells)
        for cell in back[ride]:
            back.setdefault(cell, []).append(ride)
    steps = {cell: 0 for cell in reach.targets}
    queue = deque(sorted(reach.targets))
    while queue:
        cell = queue.popleft()
        for before in back.get(cell, ()):
            if before not in steps:
                steps[before] = steps[cell] + 1
                queue.append(before)
    return steps


def reachable(world: World, work: FillWork | None = None, narrow: bool = False,
              ) -> Reach | None:
    """The jump envelope's fill from the spawn (and each checkpoint's respawn once met), for
    the world's level and tuning, with the steps back to an Exit from each cell it reached
    (:func:`steps_to_exit`); None when the tuning gives no bound (a jump that never comes
    down) or the fill would take more than its budget of steps (``work``, by default
    :data:`MAX_FILL_STEPS`; it counts the steps taken).

    ``narrow``: a cheaper fill that is a guide, never a proof: it lets the player ride a
    platform's top but not be pushed by its sides, and stomp an enemy only where it starts.
    Its steps lead a search more tightly; where it reaches an Exit, the full fill would too,
    so no proof is lost by asking it first (:func:`game.checker.verdict.prove_impossible`)."""
    envelope = envelope_of(world.level, world.tuning)
    if envelope is None:
        return None
    work = work if work is not None else FillWork()
    try:
        if narrow:
            heads: list[tuple[float, float, float]] | None = [
                (e.box.left, e.box.right, e.box.top) for e in world.level.enemies]
        else:
            heads = enemy_heads(world, work)
        if heads is None:
            return None
        fill = _JumpFill(world.level, envelope, world.spawn, work, heads, narrow)
        reach = _flood(world, fill)
        reach.steps = _steps_back(fill, reach)
        if narrow:
            reach.unbounded.append("being pushed by a moving Platform's side or a stomp on "
                                   "an enemy away from where it starts")
    except FillTooBig:
        return None
    return reach


def enemy_heads(world: World, work: FillWork) -> list[tuple[float, float, float]] | None:
    """Everywhere an enemy's head can ever be, as (left, right, top) spans the player's feet
    may stomp (so bounce) from: each kind and size of enemy gets a jump fill of its own
    body, its fastest speed and its hop (a walker's rise is nothing), seeded where each of
    them starts, carried and pushed by the platforms as the player is. An enemy goes its
    own way whatever the player does (only a stomp ends it), so this covers every bounce.
    None when physics give no bound."""
    level, tuning, grid = world.level, world.tuning, world.level.grid
    kinds: dict[tuple[bool, float, float], list[Box]] = {}
    speeds: dict[tuple[bool, float, float], float] = {}
    for enemy in level.enemies:
        kind = (enemy.kind == "hopper", enemy.box.w, enemy.box.h)
        kinds.setdefault(kind, []).append(enemy.box)
        speed = tuning.enemy_speed_px_s if enemy.speed_px_s is None else enemy.speed_px_s
        speeds[kind] = max(speeds.get(kind, 0.0), abs(speed))
    heads = [(e.box.left, e.box.right, e.box.top) for e in level.enemies]  # as they start
    for (hopper, w, h), boxes in kinds.items():
        own = replace(tuning, run_speed_px_s=speeds[(hopper, w, h)],
                      jump_speed_px_s=tuning.hopper_jump_speed_px_s if hopper else 0.0)
        envelope = envelope_of(level, own, enemies=False)
        if envelope is None:
            return None
        fill = _JumpFill(level, envelope, boxes[0], work)
        for box in boxes:
            fill.seed(box, _standing(world, box))
        for col, row in fill.run():
            heads.append((col * grid.tile_w - w / 2, (col + 1) * grid.tile_w + w / 2,
                          row * grid.tile_h - h))
    return heads


def enemy_cells(world: World, number: int, work: FillWork) -> set[Cell] | None:
    """Every cell the middle of enemy ``number``'s feet can ever be in: a jump fill of its
    own body from where the world puts it, at its own speed with its hop (a walker's rise
    is nothing), walking off every ledge (where the game turns it back), falling, carried
    and pushed by the platforms as the player is. None when physics give no bound; the
    steps are counted in ``work`` (:class:`FillTooBig` past its budget)."""
    spec, level, tuning = world.level.enemies[number], world.level, world.tuning
    box = world.enemy_by_number[number].box
    speed = tuning.enemy_speed_px_s if spec.speed_px_s is None else spec.speed_px_s
    hopper = spec.kind == "hopper"
    own = replace(tuning, run_speed_px_s=abs(speed),
                  jump_speed_px_s=tuning.hopper_jump_speed_px_s if hopper else 0.0)
    envelope = envelope_of(level, own, enemies=False)
    if envelope is None:
        return None
    fill = _JumpFill(level, envelope, box, work)
    fill.seed(box, _standing(world, box))
    return fill.run()
