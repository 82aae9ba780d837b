"""Chart 4, walls: one body asking "which walls do I touch?" as the map grows.

Where it sits: the fourth chart of ``python -m game.bench``. It times the game's wall lookup,
:meth:`TileGrid.entries_in` (what :mod:`game.collision.axis_sweep` asks in every axis
pass), against the two ways a pygame program often does it: ``pygame.sprite.spritecollide``
over a group holding every wall sprite, and ``Rect.collidelistall`` over a list of every
wall rect.

What it teaches:
  * **A tile map is already a spatial index.** Dividing the body's edges by the tile size
    gives the few cells it covers, so the lookup costs the same on a map of 500 tiles or of
    128,000. Scanning every wall costs in proportion to the number of walls, however fast
    each single test is (``collidelistall`` runs its loop in C and still grows).
  * **The maps** are one pattern of tiles, :data:`PATTERN` (the first screens of First
    Steps as the game first shipped it: ground, ledges and pits, all whole solid tiles),
    repeated, or cut, to fill each size, so the share of solid tiles is the same at every
    size and the maps stay the same when the shipped levels change.
  * **The query** is the player's hitbox (12 x 14 px) at random whole-pixel places on the
    map. Every method must find exactly the same walls, and the bench checks that.
"""

from __future__ import annotations

import random
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from statistics import median
from typing import Any

import pygame

from game.bench import charts
from game.bench.intervals import paired_ratio
from game.bench.records import Row, values
from game.bench.sizes import Sizes
from game.bench.timing import Case, interleaved
from game.collision.aabb import Box
from game.collision.shapes import Entry, TileKind, TileShape
from game.collision.tile_grid import TileGrid

CHART = "walls"
SEED = 4
BODY_W_PX, BODY_H_PX = 12, 14
PIXEL = pygame.Surface((1, 1))   # every sprite needs an image; none is ever drawn here
LOOKUP = "tile grid (TileGrid.entries_in)"
SPRITES = "spritecollide over every wall sprite"
RECTS = "Rect.collidelistall over every wall rect"
SCAN_TESTS = 200_000   # wall tests a scanning method makes per timed call, at most
PATTERN = (  # the tiles every map here is made of ('#' a solid tile), from the top row down
    "....................................................................................",
    "....................................................................................",
    "....................................................................................",
    "....................................................................................",
    ".....................................................###............................",
    "....................................................................................",
    ".......................###........#######...........................................",
    "...........................................................................#........",
    "..............##..........................................................##........",
    "############################..########################..############################",
    "############################..########################..############################",
    "############################..########################..############################",
)
TILE_PX = 16  # the pattern's tile size, px


class Wall(pygame.sprite.Sprite):
    """A wall as a sprite: how a program without a tile grid would hold its walls."""

    image: pygame.Surface
    rect: pygame.Rect

    def __init__(self, box: Box, shape: TileShape | None = None) -> None:
        super().__init__()
        self.shape = shape
        self.image = PIXEL
        self.rect = box.to_rect()


def repeated_map(pattern: TileGrid, cols: int, rows: int) -> TileGrid:
    """A ``cols`` x ``rows`` map holding ``pattern``'s shapes repeated in both directions.

    Copies are stacked up from the bottom, so a map cut shorter than the pattern keeps its
    ground rather than its sky.
    """
    grid = TileGrid(cols, rows, pattern.tile_w, pattern.tile_h)
    shapes = list(pattern.shapes())
    for copy_row in range(rows - pattern.rows, -pattern.rows, -pattern.rows):
        for copy_col in range(0, cols, pattern.cols):
            for shape in shapes:
                col, row = shape.col + copy_col, shape.row + copy_row
                if col < cols and 0 <= row < rows:
                    box = shape.box.moved(copy_col * pattern.tile_w, copy_row * pattern.tile_h)
                    grid.put(col, row, TileShape(box, shape.kind, col, row))
    return grid


@dataclass(frozen=True)
class WallMap:
    """One map in the three forms the methods need, and the queries to ask it."""

    name: str
    grid: TileGrid
    walls: pygame.sprite.Group[Wall]
    rects: list[pygame.Rect]
    shapes: list[TileShape]
    queries: list[Box]

    @classmethod
    def build(cls, pattern: TileGrid, cols: int, rows: int, queries: int) -> WallMap:
        grid = repeated_map(pattern, cols, rows)
        shapes = list(grid.shapes())
        rng = random.Random(f"{SEED}:{cols}x{rows}")
        boxes = [Box(rng.randrange(grid.width_px - BODY_W_PX),
                     rng.randrange(grid.height_px - BODY_H_PX), BODY_W_PX, BODY_H_PX)
                 for _ in range(queries)]
        return cls(f"{cols}x{rows}", grid, pygame.sprite.Group(Wall(s.box, s) for s in shapes),
                   [s.box.to_rect() for s in shapes], shapes, boxes)

    def scan_queries(self) -> int:
        """How many of the queries a scan of every wall answers per timed call: enough to
        time, few enough that a scan of 38,000 walls does not take the run's minute."""
        return max(3, min(len(self.queries), SCAN_TESTS // max(1, len(self.shapes))))

    def methods(self, scanned: int | None = None) -> dict[str, Callable[[], Any]]:
        """The three lookups; each answers the queries once (the scans the first
        ``scanned`` of them) and returns its answers."""
        grid, walls, rects, queries = self.grid, self.walls, self.rects, self.queries
        body = Wall(Box(0, 0, BODY_W_PX, BODY_H_PX))   # the querying body, as a sprite
        query_rects = [box.to_rect() for box in queries[:scanned]]
        query_edges = [(b.x, b.y, b.x + b.w, b.y + b.h) for b in queries]

        def lookup() -> list[list[Entry]]:
            entries_in = grid.entries_in
            return [entries_in(*edges) for edges in query_edges]

        def sprites() -> list[list[Wall]]:
            found = []
            for rect in query_rects:
                body.rect = rect
                found.append(pygame.sprite.spritecollide(body, walls, False))
            return found

        def all_rects() -> list[list[int]]:
            return [rect.collidelistall(rects) for rect in query_rects]

        return {LOOKUP: lookup, SPRITES: sprites, RECTS: all_rects}

    def answers_agree(self) -> bool:
        """Do the three methods find the same walls for every query?"""
        found = self.methods()
        by_lookup = [{id(entry.shape) for entry in hits} for hits in found[LOOKUP]()]
        by_sprites = [{id(w.shape) for w in hits} for hits in found[SPRITES]()]
        by_rects = [{id(self.shapes[i]) for i in hits} for hits in found[RECTS]()]
        return by_lookup == by_sprites == by_rects


def pattern() -> TileGrid:
    """:data:`PATTERN` as a map of whole-tile solid shapes: what every map here is made of."""
    grid = TileGrid(len(PATTERN[0]), len(PATTERN), TILE_PX, TILE_PX)
    for row, line in enumerate(PATTERN):
        for col, char in enumerate(line):
            if char == "#":
                box = Box(col * TILE_PX, row * TILE_PX, TILE_PX, TILE_PX)
                grid.put(col, row, TileShape(box, TileKind.SOLID, col, row))
    return grid


def measure(sizes: Sizes) -> list[Row]:
    """Every map and method in the same interleaved rounds (``verdict_rounds`` of them:
    the targets read these rows)."""
    rows: list[Row] = []
    cases: list[Case] = []
    tiles = pattern()
    for cols, map_rows in sorted({*sizes.wall_maps, *sizes.target_maps}):
        wall_map = WallMap.build(tiles, cols, map_rows, sizes.wall_queries)
        rows.append(Row(CHART, "map", wall_map.name, 0, len(wall_map.shapes), "walls"))
        rows.append(Row(CHART, "map", wall_map.name, 0, float(wall_map.answers_agree()),
                        "methods agree (1 = yes)"))
        scanned = wall_map.scan_queries()
        cases += [Case(f"{method}|{wall_map.name}", run,
                       ops=len(wall_map.queries) if method == LOOKUP else scanned)
                  for method, run in wall_map.methods(scanned).items()]
    for name, seconds in interleaved(cases, sizes.verdict_rounds, sizes.min_s).items():
        method, map_name = name.split("|")
        rows += [Row(CHART, method, map_name, r, s * 1e6, "µs/query")
                 for r, s in enumerate(seconds)]
    return rows


def lookup_wins_from(rows: list[Row]) -> str | None:
    """The smallest map from which the tile lookup beats ``collidelistall`` over all walls on
    every bigger map measured: ``collidelistall``'s time over the lookup's, round by round,
    has its whole 95 % interval above 1. None if it never does."""
    maps = sorted({r.parameter for r in rows if r.unit == "µs/query"}, key=tiles_of)
    winning_from: str | None = None
    for wall_map in maps:
        lead = paired_ratio(values(rows, method=RECTS, parameter=wall_map, unit="µs/query"),
                            values(rows, method=LOOKUP, parameter=wall_map, unit="µs/query"))
        if not lead.clears(">=", 1.0):
            winning_from = None
        elif winning_from is None:
            winning_from = wall_map
    return winning_from


def tiles_of(map_name: str) -> int:
    cols, rows = map_name.split("x")
    return int(cols) * int(rows)


def draw(rows: list[Row], out: Path, footnote: str) -> Path:
    figure = charts.new_figure("Walls: one body's wall lookup against the size of the map",
                               width_in=9.5, height_in=6)
    axes = figure.add_subplot()
    maps = sorted({r.parameter for r in rows if r.unit == "µs/query"}, key=tiles_of)
    for index, method in enumerate((LOOKUP, SPRITES, RECTS)):
        axes.plot([tiles_of(m) for m in maps],
                  [median(values(rows, method=method, parameter=m, unit="µs/query"))
                   for m in maps], marker="o", color=charts.colour(index), label=method)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xticks([tiles_of(m) for m in maps],
                    [f"{m}\n{values(rows, method='map', parameter=m, unit='walls')[0]:,.0f} walls"
                     for m in maps], fontsize=8)
    axes.minorticks_off()
    axes.set_xlabel("map size (tiles, log scale): columns x rows, and the walls it holds")
    axes.set_ylabel("time per query, median (µs, log scale)")
    axes.grid(True, which="both", alpha=0.3)
    axes.legend(fontsize=9, loc="upper left")
    small, big = maps[0], maps[-1]
    flat = paired_ratio(values(rows, method=LOOKUP, parameter=big, unit="µs/query"),
                            values(rows, method=LOOKUP, parameter=small, unit="µs/query"))
    wins = lookup_wins_from(rows)
    axes.annotate(f"tile lookup on {big}: {flat.text()}x its time on {small} [95 % interval]\n"
                  + (f"it beats collidelistall over all walls from the {wins} map on"
                     if wins else "it never beats collidelistall over all walls here"),
                  (0.99, 0.03), xycoords="axes fraction", ha="right", va="bottom", fontsize=8,
                  color="#444444")
    return charts.save(figure, out / f"{CHART}.png", footnote)
