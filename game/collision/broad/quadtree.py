"""A quadtree: split crowded squares into four, so a question only visits the squares it touches.

Where it sits: a broad phase (see :mod:`game.collision.broad.brute_force` for the contract), for
worlds whose
items are unevenly spread or very different in size, where no single grid cell size suits.

What it teaches:
  * **Split where it is crowded.** Every node covers a rectangle of the world. A leaf holding
    more than ``capacity`` items splits into four children (NW, NE, SW, SE) and hands each
    item down to the child that holds it whole. Empty regions stay one big leaf, crowded
    ones become deep, so the tree adapts to where the items are.
  * **Straddlers stay up.** An item that crosses a child's border stays in the parent. (The
    other choice, a copy in every child it touches, needs the de-duplication the spatial grid
    does.) The price: an item on a centre line, or outside the root's bounds, stays in the
    root and is tested against everything below it.
  * **A depth limit.** A thousand crates stacked at one point never spread out however often
    their square splits, so splitting stops at ``max_depth``; the deepest leaves simply hold
    more than ``capacity``. Without the limit that insert would recurse forever.
  * **Pairs by walking down.** Two items can only overlap if they sit in the same node, or
    one sits in an ancestor of the other's node: sibling squares share only a border line,
    and strict overlap needs area. So the walk tests each node's items with each other and
    with the items of the nodes above it, and each pair is tested exactly once.
  * **Children share exact edges.** The west children end at ``mid_x`` and the east ones
    start at that same float, so no sliver of the plane belongs to two siblings.
  * **Rebuild or update.** Removing an item collapses a subtree that has become sparse. Many
    games simply :meth:`rebuild` the tree every tick; for a few hundred items that is cheap.

>>> tree: Quadtree[str] = Quadtree(Box(0, 0, 64, 64), capacity=2, max_depth=4)
>>> for key, box in [("a", Box(1, 1, 4, 4)), ("b", Box(3, 3, 4, 4)), ("c", Box(40, 40, 4, 4))]:
...     tree.insert(key, box)
>>> tree.node_count(), tree.depth()                  # three items > capacity 2: split once
(5, 1)
>>> tree.insert("wide", Box(30, 0, 8, 4))           # crosses x = 32: stays in the root
>>> sorted(tree.pairs())
[('a', 'b')]
>>> tree.query(Box(35, 35, 10, 10))
{'c'}
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from itertools import chain
from typing import Generic

from game.collision.aabb import Box
from game.collision.broad.brute_force import BroadPhaseStats, K, check_box, pair_of


@dataclass
class Node(Generic[K]):
    """One square of the tree: the items that live here and, once split, four children."""

    bounds: Box
    depth: int
    items: dict[K, Box] = field(default_factory=dict)
    children: list[Node[K]] | None = None  # NW, NE, SW, SE
    count: int = 0  # items here and in every node below

    def child_holding(self, box: Box) -> Node[K] | None:
        """The child whose bounds hold ``box`` whole (edges included), if any."""
        for child in self.children or ():
            inside = child.bounds
            if (inside.left <= box.left and box.right <= inside.right
                    and inside.top <= box.top and box.bottom <= inside.bottom):
                return child
        return None


def quadrants(bounds: Box) -> list[Box]:
    """The four children of ``bounds``: NW, NE, SW, SE, meeting on exactly shared edges.

    >>> for quarter in quadrants(Box(0, 0, 10, 6)):
    ...     print(quarter)
    Box(x=0, y=0, w=5.0, h=3.0)
    Box(x=5.0, y=0, w=5.0, h=3.0)
    Box(x=0, y=3.0, w=5.0, h=3.0)
    Box(x=5.0, y=3.0, w=5.0, h=3.0)
    """
    half_w, half_h = bounds.w / 2, bounds.h / 2
    mid_x, mid_y = bounds.x + half_w, bounds.y + half_h  # the west/north children end here
    east_w, south_h = bounds.right - mid_x, bounds.bottom - mid_y
    return [Box(bounds.x, bounds.y, half_w, half_h), Box(mid_x, bounds.y, east_w, half_h),
            Box(bounds.x, mid_y, half_w, south_h), Box(mid_x, mid_y, east_w, south_h)]


class Quadtree(Generic[K]):
    """Items in a tree of squares that split at ``capacity`` items, down to ``max_depth``."""

    def __init__(self, bounds: Box, capacity: int = 8, max_depth: int = 8) -> None:
        check_box(bounds)
        if bounds.w <= 0 or bounds.h <= 0:
            raise ValueError(f"a quadtree needs bounds with area, not {bounds}")
        if capacity < 1 or max_depth < 0:
            raise ValueError(f"capacity must be >= 1 and max_depth >= 0, "
                             f"not {capacity} and {max_depth}")
        self.bounds = bounds
        self.capacity = capacity
        self.max_depth = max_depth
        self.stats = BroadPhaseStats()
        self._boxes: dict[K, Box] = {}
        self._root: Node[K] = Node(bounds, 0)

    def __len__(self) -> int:
        return len(self._boxes)

    def nodes(self) -> Iterator[Node[K]]:
        """Every node, parents before children (the debug overlay draws their bounds)."""
        stack = [self._root]
        while stack:
            node = stack.pop()
            yield node
            stack.extend(reversed(node.children or ()))

    def node_count(self) -> int:
        return sum(1 for _ in self.nodes())

    def depth(self) -> int:
        """The depth of the deepest node; the root alone is depth 0."""
        return max(node.depth for node in self.nodes())

    def clear(self) -> None:
        self._boxes.clear()
        self._root = Node(self.bounds, 0)

    def rebuild(self, items: Iterable[tuple[K, Box]]) -> None:
        """Start again from these items: the simplest way to keep up with everything moving."""
        self.clear()
        for key, box in items:
            self.insert(key, box)

    def insert(self, key: K, box: Box) -> None:
        check_box(box)
        if key in self._boxes:
            raise ValueError(f"{key!r} is already in the quadtree; use move() to move it")
        self._boxes[key] = box
        node = self._root
        while True:
            node.count += 1
            child = node.child_holding(box)
            if child is None:
                break
            node = child
        node.items[key] = box
        if node.children is None:
            self._split_if_crowded(node)

    def remove(self, key: K) -> None:
        box = self._boxes.pop(key)
        path = [self._root]
        while key not in path[-1].items:
            child = path[-1].child_holding(box)
            assert child is not None, "an item always lives on its box's path down the tree"
            path.append(child)
        del path[-1].items[key]
        for node in path:
            node.count -= 1
        for node in path:  # the highest node that is no longer crowded takes its subtree back
            if node.children is not None and node.count <= self.capacity:
                self._collapse(node)
                break

    def move(self, key: K, box: Box) -> None:
        check_box(box)
        if key not in self._boxes:
            raise KeyError(key)
        self.remove(key)
        self.insert(key, box)

    def query(self, box: Box) -> set[K]:
        check_box(box)
        found: set[K] = set()
        stats = self.stats
        stack = [self._root]  # the root is always visited: it holds items outside its bounds
        while stack:
            node = stack.pop()
            stats.cells_visited += 1
            for key, item in node.items.items():
                stats.pair_tests += 1
                if item.overlaps(box):
                    found.add(key)
            stack.extend(child for child in node.children or ()
                         if child.count and child.bounds.overlaps(box))
        return found

    def pairs(self) -> set[tuple[K, K]]:
        found: set[tuple[K, K]] = set()
        stats = self.stats
        # Each entry: a node, and the items of every node above it.
        stack: list[tuple[Node[K], list[tuple[K, Box]]]] = [(self._root, [])]
        while stack:
            node, above = stack.pop()
            stats.cells_visited += 1
            here = list(node.items.items())
            for i, (key, box) in enumerate(here):
                for other, other_box in chain(here[i + 1:], above):
                    stats.pair_tests += 1
                    if box.overlaps(other_box):
                        found.add(pair_of(key, other))
            for child in node.children or ():
                if child.count:
                    stack.append((child, above + here))
        return found

    def _split_if_crowded(self, leaf: Node[K]) -> None:
        """Split a leaf holding more than ``capacity`` items, unless it is at ``max_depth``."""
        if len(leaf.items) <= self.capacity or leaf.depth >= self.max_depth:
            return
        leaf.children = [Node(quarter, leaf.depth + 1) for quarter in quadrants(leaf.bounds)]
        staying: dict[K, Box] = {}
        for key, box in leaf.items.items():
            child = leaf.child_holding(box)
            if child is None:
                staying[key] = box
            else:
                child.items[key] = box
                child.count += 1
        leaf.items = staying
        for child in leaf.children:
            self._split_if_crowded(child)  # at most max_depth deep

    def _collapse(self, node: Node[K]) -> None:
        """Pull every item below ``node`` back into it and drop its children."""
        gathered: dict[K, Box] = {}
        stack = [node]
        while stack:
            below = stack.pop()
            gathered.update(below.items)
            stack.extend(below.children or ())
        node.items = gathered
        node.children = None
