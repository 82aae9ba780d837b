"""Scene ``quadtree``: squares split into four as bodies crowd them.

What it shows: a :class:`~game.collision.broad.quadtree.Quadtree` over the area, capacity
``CAPACITY`` bodies a node, rebuilt every frame from where the bodies are. Click empty space
to add a body (A adds a handful at once, Backspace takes the last away) and watch a crowded
square split into four; straddlers stay in the parent. The panel gives the node count and
depth, the pair tests the tree made (its own stats) against brute force's n(n-1)/2, whether
both found the same pairs, and both times.
"""

from __future__ import annotations

import random

import pygame

from game.collision.aabb import Box
from game.collision.broad.brute_force import BruteForce
from game.collision.broad.quadtree import Quadtree
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.crowd import Crowd, CrowdScene
from game.lab.scene import AREA, Control, Layer, Point

CAPACITY = 4
MAX_DEPTH = 5
BODY_PX = 18.0
START_BODIES = 14
ADD_AT_ONCE = 6
TREE_AREA = Box(AREA.x + 8, AREA.y + 8, AREA.w - 16, AREA.h - 16)


class QuadtreeScene(CrowdScene):
    name = "quadtree"
    title = "the quadtree: crowded squares split into four"
    keys_help = "click: add a body; A add 6; Backspace remove"
    group = "broad phase"
    draws = (Layer.SHAPES, Layer.CONTACTS, Layer.CELLS)

    def reset(self) -> None:
        corner = Box(TREE_AREA.x, TREE_AREA.y, TREE_AREA.w / 2, TREE_AREA.h / 2)
        self.crowd = Crowd.random(11, START_BODIES, corner, (12.0, 24.0), 20.0)
        self.crowd.area = TREE_AREA
        self.rng = random.Random(12)
        self.meter = CostMeter(repeats=2)

    def add(self, point: Point) -> None:
        key = max(self.crowd.boxes, default=-1) + 1
        x = min(max(point[0] - BODY_PX / 2, TREE_AREA.left), TREE_AREA.right - BODY_PX)
        y = min(max(point[1] - BODY_PX / 2, TREE_AREA.top), TREE_AREA.bottom - BODY_PX)
        self.crowd.boxes[key] = Box(x, y, BODY_PX, BODY_PX)
        self.crowd.velocities[key] = (0.0, 0.0)

    def on_click(self, point: Point) -> None:
        if self.crowd.area.overlaps(Box(point[0], point[1], 1, 1)):
            self.add(point)

    def controls(self) -> list[Control]:
        return [Control(f"bodies: {len(self.crowd.boxes)} (A adds, Backspace removes)",
                        (pygame.K_a, pygame.K_BACKSPACE))]

    def on_key(self, key: int) -> None:
        if key == pygame.K_a:
            for _ in range(ADD_AT_ONCE):
                self.add((self.rng.uniform(TREE_AREA.left, TREE_AREA.right),
                          self.rng.uniform(TREE_AREA.top, TREE_AREA.bottom)))
        elif key == pygame.K_BACKSPACE and self.crowd.boxes:
            last = max(self.crowd.boxes)
            del self.crowd.boxes[last], self.crowd.velocities[last]

    def refresh(self) -> None:
        items = list(self.crowd.boxes.items())
        self.tree: Quadtree[int] = Quadtree(TREE_AREA, capacity=CAPACITY, max_depth=MAX_DEPTH)
        self.tree.rebuild(items)
        self.pairs = self.tree.pairs()
        tests, nodes_visited = self.tree.stats.pair_tests, self.tree.stats.cells_visited
        brute: BruteForce[int] = BruteForce()
        for key, box in items:
            brute.insert(key, box)
        same = brute.pairs() == self.pairs
        brute_tests = brute.stats.pair_tests
        n = len(items)
        self.meter.time("quadtree, all pairs", self.tree.pairs)
        self.meter.time("brute force, all pairs", brute.pairs)
        self.lines = [
            f"bodies: {n}; capacity {CAPACITY} a node",
            f"nodes: {self.tree.node_count()}; depth {self.tree.depth()}",
            f"quadtree: {tests} pair tests, {nodes_visited} nodes",
            f"brute force: {brute_tests} tests = n(n-1)/2 = {n * (n - 1) // 2}",
            f"pairs found: {len(self.pairs)}; same as brute force: {'yes' if same else 'NO'}",
            "the tree's pairs take "
            f"{self.meter.times('quadtree, all pairs', 'brute force, all pairs')} brute force's",
            "(the tree is rebuilt each frame; that",
            " time is not in the timing below)",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        if Layer.CELLS in layers:
            for node in self.tree.nodes():
                canvas.box(surface, node.bounds, canvas.TESTED if node.children is None
                           else canvas.GRID, 1)
                if node.items and node.children is not None:
                    for box in node.items.values():
                        canvas.box(surface, box, canvas.BOUNDS, 2)  # straddlers: kept up here
        if Layer.SHAPES in layers:
            for box in self.crowd.boxes.values():
                canvas.box(surface, box, canvas.STILL)
        if Layer.CONTACTS in layers:
            for a, b in self.pairs:
                canvas.box(surface, self.crowd.boxes[a], canvas.EXACT, 2)
                canvas.box(surface, self.crowd.boxes[b], canvas.EXACT, 2)
