"""Scene ``party-grid``: a uniform grid finds the few pairs worth testing in a crowd.

What it shows: seventy bodies drifting (pause with P, then hover at leisure), filed by a
:class:`~game.collision.broad.spatial_grid.SpatialGrid` whose cell size comes from
:func:`~game.collision.methods.grid_cell_size_px`. Hover a body: the cells it is filed under
(:meth:`~game.collision.broad.spatial_grid.SpatialGrid.cell_range`) light up, and the bodies
sharing those cells, the only neighbours its query tests, are outlined in white; the panel
prints that query's counts from the grid's own
:class:`~game.collision.broad.brute_force.BroadPhaseStats`.
(This grid files a body under every cell its box covers, so a query needs only those cells,
not the ring of eight neighbours a grid that files each body under one cell must check.)
For the whole crowd it sets the grid's pair tests against brute force's n(n-1)/2, checks both
found the same pairs, and times both per frame and per test.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.collision.broad.brute_force import BruteForce
from game.collision.broad.spatial_grid import SpatialGrid
from game.collision.methods import grid_cell_size_px
from game.lab import canvas
from game.lab.cost import CostMeter, format_ns
from game.lab.crowd import Crowd, CrowdScene
from game.lab.scene import AREA, Layer

BODIES = 70
SEED = 3
SIZES_PX = (12.0, 28.0)
HOVER_REACH_PX = 60.0  # the nearest body this close to the mouse counts as hovered
CROWD_AREA = Box(AREA.x + 8, AREA.y + 8, AREA.w - 16, AREA.h - 16)


def plural(count: int, noun: str, nouns: str | None = None) -> str:
    """``1 cell``, ``4 cells``, ``2 bodies``.

    >>> plural(1, "cell"), plural(4, "cell"), plural(2, "body", "bodies")
    ('1 cell', '4 cells', '2 bodies')
    """
    return f"{count} {noun}" if count == 1 else f"{count} {nouns or noun + 's'}"


GRID, BRUTE = "grid, all pairs", "brute force, all pairs"  # timed every frame


class PartyGrid(CrowdScene):
    name = "party-grid"
    title = "the party grid: only bodies in one cell are tested"
    keys_help = "hover a body; drag bodies"
    group = "broad phase"
    draws = (Layer.SHAPES, Layer.PAIRS, Layer.CONTACTS, Layer.CELLS)

    def reset(self) -> None:
        self.crowd = Crowd.random(SEED, BODIES, CROWD_AREA, SIZES_PX)
        self.cell_px = grid_cell_size_px(sum(SIZES_PX) / 2)
        self.grid: SpatialGrid[int] = SpatialGrid(cell_size_px=self.cell_px)
        self.brute: BruteForce[int] = BruteForce()
        for key, box in self.crowd.boxes.items():
            self.grid.insert(key, box)
            self.brute.insert(key, box)
        self.meter = CostMeter(repeats=2)
        self.mouse = (AREA.x + 300.0, AREA.y + 240.0)

    def refresh(self) -> None:
        for key, box in self.crowd.boxes.items():
            self.grid.move(key, box)
            self.brute.move(key, box)
        self.grid.stats.reset()
        self.pairs = self.grid.pairs()
        self.grid_tests = self.grid.stats.pair_tests
        self.grid_cells = self.grid.stats.cells_visited
        self.brute.stats.reset()
        self.brute_pairs = self.brute.pairs()
        self.brute_tests = self.brute.stats.pair_tests
        n = len(self.crowd.boxes)
        self.meter.time(GRID, self.grid.pairs)
        self.meter.time(BRUTE, self.brute.pairs)
        grid_ns, brute_ns = self.meter.median(GRID), self.meter.median(BRUTE)
        per_grid = grid_ns / max(1, self.grid_tests)
        per_brute = brute_ns / max(1, self.brute_tests)
        self.lines = [
            f"bodies: {n}; cell {self.cell_px:g} px (methods)",
            f"grid: {self.grid_tests} pair tests, {self.grid_cells} cells",
            f"brute force: {self.brute_tests} tests = n(n-1)/2 = {n * (n - 1) // 2}",
            f"pairs found: {len(self.pairs)}; same as brute force: "
            + ("yes" if self.pairs == self.brute_pairs else "NO"),
            f"per pair test (a frame's median / its tests): grid {format_ns(per_grid)},",
            f"  brute {format_ns(per_brute)}: a grid test costs "
            f"{per_grid / max(per_brute, 1e-9):.1f}x a brute one,",
            "  as the grid also files boxes and walks cells;" if per_grid > per_brute else
            "  filing boxes and walking cells included;",
            f"  but it makes {self.brute_tests / max(1, self.grid_tests):.0f}x fewer tests, "
            f"so its frame takes {grid_ns / max(brute_ns, 1e-9):.2f}x",
            "  brute force's",
            "",
        ]
        self.hovered = self.crowd.key_at(self.mouse, HOVER_REACH_PX)
        self.hover_cells: list[tuple[int, int]] = []
        self.neighbours: list[int] = []
        if self.hovered is None:
            self.lines.append("hover a body to see its query")
            return
        box = self.crowd.boxes[self.hovered]
        cells = self.grid.cell_range(box)
        self.hover_cells = list(cells.cells())
        self.neighbours = [key for key, other in self.crowd.boxes.items() if key != self.hovered
                           and any(cells.holds(c) for c in self.grid.cell_range(other).cells())]
        self.grid.stats.reset()
        found = self.grid.query(box) - {self.hovered}
        self.query_tests = self.grid.stats.pair_tests
        self.query_cells = self.grid.stats.cells_visited
        self.lines += [
            f"body {self.hovered}: filed in {plural(len(self.hover_cells), 'cell')}",
            f"  its query visits {plural(self.query_cells, 'cell')} and",
            f"  tests {plural(self.query_tests, 'body', 'bodies')} (itself too),",
            f"  not all {n}; overlapping it: {len(found)}",
            "a body is filed under every cell it",
            "covers, so no ring of neighbour cells",
            "is needed: sharing a cell is enough",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        size = self.cell_px
        if Layer.CELLS in layers:
            x = CROWD_AREA.left - CROWD_AREA.left % size
            while x < AREA.right:
                pygame.draw.line(surface, canvas.GRID, (x, AREA.top), (x, AREA.bottom))
                x += size
            y = AREA.top - AREA.top % size
            while y < AREA.bottom:
                pygame.draw.line(surface, canvas.GRID, (AREA.left, y), (AREA.right, y))
                y += size
            for col, row in self.hover_cells:
                canvas.wash(surface, Box(col * size, row * size, size, size), canvas.TESTED, 90)
        if Layer.SHAPES in layers:
            for key, box in self.crowd.boxes.items():
                color = canvas.MOVER if key == self.hovered else canvas.STILL
                canvas.box(surface, box, color)
        if Layer.CONTACTS in layers:
            for a, b in self.pairs:
                canvas.box(surface, self.crowd.boxes[a], canvas.EXACT, 2)
                canvas.box(surface, self.crowd.boxes[b], canvas.EXACT, 2)
        if Layer.PAIRS in layers:
            for key in self.neighbours:
                canvas.box(surface, self.crowd.boxes[key], canvas.WHITE, 2)
