"""Mistakes a map loads with but a designer would not mean: the checker's extra findings.

Where it sits: :func:`game.levels.checking.check_map` calls :func:`designer_findings` on a
map that loaded. The game plays these maps; the checker says where play goes wrong.

What it teaches: an error names its place and says what happens in play, in Tiled's words.

* **A next level that does not load** ends the run when the level is finished: an error on
  ``map property 'next_level'`` (the loader only warns, so the level itself still plays).
* **A Checkpoint whose respawn place differs from where it stands**: the player comes back
  standing on the flag's bottom edge, moved to the nearest free place when that is in a
  wall, so a flag drawn into the ground puts the player somewhere else: an error at the flag.
* **Objects on hidden layers** still count in the game (Tiled only hides them from view): a
  warning on each object of a class the game knows, so a forgotten Exit is found.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

from game.collision.aabb import Box
from game.collision.free_place import nearest_free_place
from game.levels.classes import OBJECT_CLASSES
from game.levels.errors import Findings, LevelError, Place, object_place, tile_place
from game.levels.layers import walk_layers
from game.levels.loader import load_level
from game.levels.tiledxml import read_tiled_xml
from game.sim.level import Level
from game.sim.whole_numbers import NumberTextError, read_whole
from game.sim.world import World

SAME_PLACE_PX = 0.5  # a respawn place this close to the flag's is the same place

Finding = tuple[str, str, str, str]  # severity, where, message, fix


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


def _checkpoints(level: Level) -> Iterator[Finding]:
    world = World(level)
    w, h = level.spawn.w, level.spawn.h
    for flag in level.checkpoints:
        standing = Box(flag.x + (flag.w - w) / 2, flag.bottom - h, w, h)
        place = nearest_free_place(world.solids, standing)
        if abs(place.x - standing.x) > SAME_PLACE_PX or abs(place.y - standing.y) > SAME_PLACE_PX:
            col = int(flag.x // level.grid.tile_w)
            row = int(flag.y // level.grid.tile_h)
            yield ("error", tile_place(col, row), "a player coming back to this Checkpoint "
                   "would stand inside Solid tiles, so the game moves it to the nearest free "
                   f"place, ({place.x:g}, {place.y:g}) instead of ({standing.x:g}, "
                   f"{standing.y:g})", "move the Checkpoint so that its bottom edge rests on "
                   "the ground with open space above it")


def _object_place(node: ET.Element) -> Place:
    """An object's place, its id read as the loader read it (the map has loaded)."""
    try:
        return object_place(read_whole(node.get("id", "")), node.get("name", ""))
    except NumberTextError:
        return Place(f"object #{node.get('id', '?')} '{node.get('name', '')}'")


def _hidden_objects(path: Path) -> Iterator[Finding]:
    findings = Findings(path)
    try:
        root = read_tiled_xml(path, "map", findings)
        layers = walk_layers(root, findings)
    except LevelError:
        return
    known = {cls.name.lower() for cls in OBJECT_CLASSES}
    for layer in layers:
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
    return [*_next_level(level), *_checkpoints(level), *_hidden_objects(path)]
