"""Mistakes a map loads with but a designer would not mean: the checker's extra findings.

Where it sits: :func:`game.checker.checking.check_map` calls :func:`designer_findings` on a
map that loaded. The game plays these maps; the checker says where play goes wrong.

What it teaches: an error names its place and says what happens in play, in Tiled's words.

* **A next level that does not load** ends the run when the level is finished: an error on
  ``map property 'next_level'`` (the loader only warns, so the level itself still plays).
* **A Checkpoint whose respawn place differs from where it stands**: the player comes back
  standing on the flag's bottom edge, moved to the nearest free place when that is in a
  wall, so a flag drawn into the ground puts the player somewhere else: a warning at the
  flag (the game plays it; a recorded win given with ``--proof`` shows the place works).
* **A Checkpoint whose respawn place is on a moving Platform's path**: a player coming back
  there while the platform passes is pushed into the ground and crushed at each respawn,
  until the lives run out: a warning at the flag, naming the platform and the tile.
* **A Checkpoint standing on spikes**: Hazard tiles inside the place the player comes back
  to, or under it where the player would fall: a warning at the flag, naming the tile.
* **A moving Platform whose path runs into Solid tiles**: the platform passes through the
  wall, while a player riding it is stopped by the wall and crushed: a warning at the
  platform, naming the first tile its box meets along the path (a swept box, so a wall
  thinner than a step is not missed).
* **A Coin no jump reaches**: outside everything the reach fill of
  :mod:`game.checker.reachable` lets the player touch (an over-approximation, so a Coin it
  names can never be collected): a warning at the coin.
* **Objects on hidden layers** still count in the game (Tiled only hides them from view): a
  warning on each object of a class the game knows, so a forgotten Exit is found.
* And the tile layers' mistakes of :mod:`game.checker.tile_mistakes`.

Each finding about an object names the object (``object #ID 'NAME'``), so the Tiled
extension selects the object, not a tile under it; the tile it concerns is kept in the
place too (:class:`~game.levels.errors.Place`).
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path

from game.checker import tile_mistakes
from game.checker.reachable import SLACK_PX, reachable
from game.collision.aabb import Box
from game.collision.axis_sweep import ground_under
from game.collision.free_place import nearest_free_place
from game.collision.shapes import TileKind, TileShape
from game.collision.swept import sweep
from game.collision.tile_grid import TileGrid
from game.levels.classes import OBJECT_CLASSES
from game.levels.errors import Findings, LevelError, Place, object_place
from game.levels.header import MapHeader, read_header
from game.levels.layers import LayerNode, walk_layers
from game.levels.loader import load_level
from game.levels.objects import MapObject, read_objects
from game.levels.paths import sandbox_for
from game.levels.templates import Templates
from game.levels.tiledata import decode
from game.levels.tiledxml import read_tiled_xml
from game.levels.tilesets import Tilesets, read_tilesets
from game.sim.level import Level
from game.sim.platforms import PlatformSpec
from game.sim.whole_numbers import NumberTextError, read_whole
from game.sim.world import World

SAME_PLACE_PX = 0.5  # a respawn place this close to the flag's is the same place

Finding = tile_mistakes.Finding  # severity, where, message, fix


@dataclass(frozen=True)
class _Map:
    """A map that loaded, read again with the loader's own readers: its layers (tile layers
    decoded), tilesets and objects, for what the loaded level does not keep (ids, names,
    flip flags)."""

    header: MapHeader
    tilesets: Tilesets
    layers: list[LayerNode]
    tile_layers: list[tuple[LayerNode, list[int]]]
    objects: list[MapObject]

    def of_class(self, cls: str) -> list[MapObject]:
        return [o for o in self.objects if o.cls == cls]


def _read_again(path: Path) -> _Map | None:
    """The map at ``path`` read again; None if it cannot be (it changed on disk since)."""
    findings = Findings(path)
    try:
        root = read_tiled_xml(path, "map", findings)
        header = read_header(root, findings)
        sandbox = sandbox_for(path)
        tilesets = read_tilesets(root, path, sandbox, findings, False)
        layers = walk_layers(root, findings)
        tile_layers = [(layer, decode(layer.node.find("data"), header.cells))
                       for layer in layers if layer.kind == "layer"]
        objects = read_objects(layers, tilesets, Templates(path, sandbox, tilesets, findings,
                                                           False), findings)
    except (LevelError, ValueError, OSError):
        return None
    return _Map(header, tilesets, layers, tile_layers, objects)


def _tile_of(grid: TileGrid, x: float, y: float) -> tuple[int, int]:
    return math.floor(x / grid.tile_w), math.floor(y / grid.tile_h)


def _places(objects: Sequence[MapObject], boxes: Sequence[Box], grid: TileGrid) -> list[Place]:
    """Where to say each of ``boxes`` is: the object it was made from (a map that loaded
    makes one of each, in order), else its top-left tile."""
    if len(objects) == len(boxes):
        return [Place(o.place, o.id, _tile_of(grid, b.x, b.y)) for o, b in zip(objects, boxes,
                                                                                  strict=True)]
    return [Place(f"tile ({col},{row})", tile=(col, row))
            for col, row in (_tile_of(grid, b.x, b.y) for b in boxes)]


def _next_level(level: Level) -> Iterator[Finding]:
    target = level.next_level
    if target is None:
        return
    where = "map property 'next_level'"
    if not target.is_file():
        yield ("error", where, f"the next level {target.name} does not exist, so finishing this "
               "level ends the game with an error", "pick the next map again in Map > Map "
               "Properties, or clear next_level if this is the last level")
        return
    try:
        load_level(target)
    except LevelError as error:
        yield ("error", where, f"the next level {target.name} does not load ({error.problem}), "
               "so finishing this level ends the game with an error",
               f"check {target.name} with the checker and fix it, or pick another next level")
    except OSError as error:
        yield ("error", where, f"the next level {target.name} cannot be read "
               f"({error.strerror or error})", "pick the next map again in Map > Map Properties")


def _respawn_place(world: World, flag: Box) -> tuple[Box, Box]:
    """Where a player coming back to ``flag`` is put when no moving platform is in the way
    (the tiles alone), and where it would stand if free."""
    w, h = world.level.spawn.w, world.level.spawn.h
    standing = Box(flag.x + (flag.w - w) / 2, flag.bottom - h, w, h)
    return nearest_free_place(world.level.grid, standing), standing


def _checkpoints(level: Level, world: World, places: Sequence[Place]) -> Iterator[Finding]:
    """A respawn the tiles move: a warning (the game plays it, and a recorded win that
    passes the flag shows the place works)."""
    for flag, where in zip(level.checkpoints, places, strict=True):
        place, standing = _respawn_place(world, flag)
        if abs(place.x - standing.x) > SAME_PLACE_PX or abs(place.y - standing.y) > SAME_PLACE_PX:
            yield ("warning", where, "a player coming back to this Checkpoint "
                   "would stand inside Solid tiles, so the game moves it to the nearest free "
                   f"place, ({place.x:g}, {place.y:g}) instead of ({standing.x:g}, "
                   f"{standing.y:g})", "move the Checkpoint so that its bottom edge rests on "
                   "the ground with open space above it")


def _crushing_checkpoints(level: Level, world: World, flags: Sequence[Place],
                          platforms: Sequence[Place]) -> Iterator[Finding]:
    """A respawn place some moving platform's box passes through: a player coming back
    there while the platform passes is pushed, into the ground or a wall if it stands on
    one, and crushed at each respawn (a crush costs a life even while blinking), so every
    life goes in as many ticks. Counted while the platform is there, the flag also moves
    the respawn out of its way (:func:`game.checker.reachable.starts`)."""
    for flag, where in zip(level.checkpoints, flags, strict=True):
        place, _ = _respawn_place(world, flag)
        for spec, platform in zip(level.platforms, platforms, strict=True):
            if not _passes_through(spec, place):
                continue
            col, row = _tile_of(level.grid, place.x + place.w / 2, place.bottom - SLACK_PX)
            yield ("warning", Place(where, where.object_id, (col, row)),
                   f"a player coming back to this Checkpoint stands at tile ({col},{row}), on "
                   f"the path of the moving Platform ({platform}): when it passes, it pushes the "
                   "player into whatever the player stands on and crushes it again at each "
                   "respawn, until the lives run out", "move the Checkpoint out of the "
                   "platform's way, or move the platform's path (Edit Polygons tool) clear of "
                   "the place above the flag's bottom edge")
            break


def _passes_through(spec: PlatformSpec, box: Box) -> bool:
    """Does the platform's box overlap ``box`` somewhere along its path (swept leg by leg,
    round to the first point for a polygon)?"""
    w, h = spec.width_px, spec.height_px
    legs = spec.path.legs or ((spec.path.points[0], spec.path.points[0]),)
    for (x0, y0), (x1, y1) in legs:
        if Box(x0, y0, w, h).overlaps(box):
            return True
        contact = sweep(Box(x0, y0, w, h), x1 - x0, y1 - y0, box)
        if contact is not None and contact.t < 1.0:
            return True
    return False


def _first(shapes: list[TileShape]) -> TileShape | None:
    return min(shapes, key=lambda s: (s.row, s.col), default=None)


def _spiked_checkpoints(level: Level, world: World,
                        places: Sequence[Place]) -> Iterator[Finding]:
    """Hazard tiles inside the respawn place, or under it when nothing holds it up."""
    grid = level.grid
    for flag, where in zip(level.checkpoints, places, strict=True):
        place, _ = _respawn_place(world, flag)
        region = place if ground_under(world.solids, place) is not None else Box(
            place.x, place.y, place.w, place.h + grid.tile_h)  # it falls onto what is below
        spikes = _first([s for s in grid.shapes_in(region) if s.kind is TileKind.HAZARD])
        if spikes is None:
            continue
        yield ("warning", Place(where, where.object_id, (spikes.col, spikes.row)),
               f"a player coming back to this Checkpoint lands on Hazard tiles, at tile "
               f"({spikes.col},{spikes.row}), and loses a life again when the blinking after "
               "the last one ends", "move the Checkpoint onto ground with no spikes, or clear "
               "the Hazard tiles under it")


def _first_wall(spec: PlatformSpec, grid: TileGrid) -> TileShape | None:
    """The first Solid tile shape the platform's box meets along its path, swept leg by
    leg (from its first point, round the loop if it is a polygon), or None."""
    w, h = spec.width_px, spec.height_px
    legs = spec.path.legs or ((spec.path.points[0], spec.path.points[0]),)
    for (x0, y0), (x1, y1) in legs:
        start = Box(x0, y0, w, h)
        region = Box(min(x0, x1), min(y0, y1), abs(x1 - x0) + w, abs(y1 - y0) + h)
        hits = []
        for shape in grid.shapes_in(region):
            if shape.kind is TileKind.SOLID:
                contact = sweep(start, x1 - x0, y1 - y0, shape.box)
                if contact is not None:  # overlapping from the start is t = 0
                    hits.append((contact.t, shape.row, shape.col, shape))
        if hits:
            return min(hits, key=lambda hit: hit[:3])[3]
    return None


def _walled_platforms(level: Level, places: Sequence[Place]) -> Iterator[Finding]:
    for spec, where in zip(level.platforms, places, strict=True):
        wall = _first_wall(spec, level.grid)
        if wall is None:
            continue
        yield ("warning", Place(where, where.object_id, (wall.col, wall.row)),
               f"this Platform's path runs into Solid tiles, first at tile ({wall.col},"
               f"{wall.row}): the platform passes through the wall, but a player riding it "
               "is stopped by the wall and crushed", "move the path's points (Edit Polygons "
               "tool) so that the platform's box, hanging from the line by its top-left "
               "corner, clears the walls, or clear the Solid tiles in its way")


def _unreachable_coins(level: Level, world: World,
                       places: Sequence[Place]) -> Iterator[Finding]:
    """Coins none of whose cells the reach fill touches (the cells the middle of the feet is
    in when the body overlaps the coin, as the fill counts an Exit's)."""
    if not level.coins:
        return
    body, grid = world.spawn, level.grid
    missed: list[tuple[set[tuple[int, int]], Place]] = []
    guide = reachable(world, narrow=True)  # cheaper: most coins are in it, and so in the proof
    for coin, where in zip(level.coins, places, strict=True):
        left, right = coin.box.left - body.w / 2 - SLACK_PX, coin.box.right + body.w / 2 + SLACK_PX
        top, bottom = coin.box.top - SLACK_PX, coin.box.bottom + body.h + SLACK_PX
        first, last = _tile_of(grid, left, top), _tile_of(grid, right, bottom)
        cells = {(col, row) for col in range(first[0], last[0] + 1)
                 for row in range(first[1], last[1] + 1)}
        if guide is None or not cells & guide.cells:
            missed.append((cells, where))
    reach = reachable(world) if missed else None
    if reach is None or reach.unbounded:
        return
    for cells, where in missed:
        if cells & reach.cells:
            continue
        yield ("warning", where, "no jump reaches this Coin: it lies outside everything the "
               "player's jumps can touch from the spawn (and the Checkpoints), so it can never "
               "be collected", "move the Coin down within a jump of the ground, or add a "
               "ledge or a Platform on the way to it (the checker's summary gives the "
               "player's reach)")


def _object_place(node: ET.Element) -> Place:
    """An object's place, its id read as the loader read it (the map has loaded)."""
    try:
        return object_place(read_whole(node.get("id", "")), node.get("name", ""))
    except NumberTextError:
        return Place(f"object #{node.get('id', '?')} '{node.get('name', '')}'")


def _hidden_objects(parts: _Map) -> Iterator[Finding]:
    known = {cls.name.lower() for cls in OBJECT_CLASSES}
    for layer in parts.layers:
        if layer.kind != "objectgroup" or layer.visible:
            continue
        for node in layer.node.iter("object"):
            cls = (node.get("type") or node.get("class") or "").strip()
            if cls.lower() in known:
                yield ("warning", _object_place(node),
                       f"this {cls} is on the hidden layer '{layer.name}' (its eye is off in "
                       "the Layers panel), yet the game plays it as if it were shown",
                       "show the layer if the object belongs in the level, or delete it if "
                       "it is left over")


def designer_findings(path: Path, level: Level) -> list[Finding]:
    """Every finding of this module for a map that loaded, in the order above."""
    world = World(level)
    parts = _read_again(path)
    if parts is None:
        return [*_next_level(level)]
    grid = level.grid
    flags = _places(parts.of_class("checkpoint"), level.checkpoints, grid)
    platforms = _places(parts.of_class("platform"), [Box(*s.path.points[0], s.width_px,
                                                         s.height_px) for s in level.platforms],
                        grid)
    coins = _places(parts.of_class("coin"), [c.box for c in level.coins], grid)
    layers, tilesets, header = parts.tile_layers, parts.tilesets, parts.header
    return [*_next_level(level), *_checkpoints(level, world, flags),
            *_crushing_checkpoints(level, world, flags, platforms),
            *_spiked_checkpoints(level, world, flags), *_walled_platforms(level, platforms),
            *_unreachable_coins(level, world, coins), *_hidden_objects(parts),
            *tile_mistakes.turned_one_ways(layers, tilesets, header),
            *tile_mistakes.classless_ground(path, layers, tilesets, header),
            *tile_mistakes.colliding_quiet_layers(layers, tilesets, header)]
