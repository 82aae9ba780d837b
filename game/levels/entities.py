"""From Tiled objects to the game's spawn, coins, enemies and exits.

Where it sits: the last step of loading. :mod:`game.levels.objects` has read the objects;
this module decides what each one is, applies the class defaults of
:mod:`game.levels.classes` and checks what the game needs: exactly one Player, shapes that
make sense for their class, values of the right type, everything inside the map.

What it teaches: validate at the boundary, all at once. Every object is checked and every
problem recorded, so a designer sees all the broken objects of a map in one run.
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass

from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.levels.budget import (
    MAX_COINS,
    MAX_ENEMIES,
    MAX_PLATFORMS,
    MAX_SPRITE_PIXELS,
)
from game.levels.classes import (
    CLASSES_BY_NAME,
    OBJECT_CLASSES,
    TILE_KINDS,
    Plain,
    TiledClass,
    classes_for,
)
from game.levels.errors import Findings
from game.levels.header import MapHeader
from game.levels.objects import MapObject
from game.levels.spelling import meant
from game.sim.level import CoinSpec, EnemySpec
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning

DEFAULT_COIN_PX = 8
MIN_SIZE_PX = 1.0  # a box thinner than a pixel slips between the grid's whole-pixel faces
BODY_SHAPES = ("rectangle", "point", "ellipse", "tile")  # what a body's box can come from
OBJECT_CLASS_NAMES = tuple(cls.name for cls in OBJECT_CLASSES)
CLASS_NAMES = ", ".join(OBJECT_CLASS_NAMES)
MUST_BE_REACHABLE = ("player", "exit", "checkpoint")  # inside a wall or off the map: no play


@dataclass(frozen=True)
class Entities:
    """What the objects of a map become."""

    spawn: Box
    coins: tuple[CoinSpec, ...]
    enemies: tuple[EnemySpec, ...]
    exits: tuple[Box, ...]
    platforms: tuple[PlatformSpec, ...] = ()
    checkpoints: tuple[Box, ...] = ()


def _a(name: str) -> str:
    """``name`` with its indefinite article.

    >>> _a("Exit"), _a("Coin")
    ('an Exit', 'a Coin')
    """
    return f"{'an' if name[:1].lower() in 'aeiou' else 'a'} {name}"


def _values(o: MapObject, cls: TiledClass, findings: Findings) -> dict[str, Plain]:
    """The object's properties for its class: defaults, then its own, each type-checked."""
    values = cls.defaults()
    names = {member.name for member in cls.members}
    for name, value in o.properties.items():
        if name not in names:
            known = ", ".join(sorted(names)) or "no properties"
            findings.warn(o.place, f"property '{name}' means nothing to {_a(cls.name)}",
                          f"{_a(cls.name)} reads {known}; rename or delete it")
            continue
        member = cls.member(name)
        try:
            values[name] = member.coerce(value)
        except ValueError as error:
            findings.error(o.place, f"property '{name}': {error}",
                           f"set '{name}' ({member.doc}) in the object's Properties")
    return values


def _box(o: MapObject, cls: TiledClass, point_size: tuple[float, float],
         findings: Findings) -> Box | None:
    """The object's box for the game; a point gets ``point_size`` with its corner there."""
    if o.shape not in BODY_SHAPES:
        findings.error(o.place, f"{_a(cls.name)} cannot be {_a(o.shape)}",
                       "draw it with the Rectangle or Point tool, or as a tile")
        return None
    if o.rotation:
        findings.warn(o.place, f"its rotation ({o.rotation:g}°) is ignored",
                      "set Rotation to 0 in its Properties")
    if o.is_point:
        return Box(o.box.x, o.box.y, *point_size)
    if o.box.w <= 0 or o.box.h <= 0:
        findings.error(o.place, f"the {cls.name} has no area",
                       "draw it as a point or as a rectangle with a size")
        return None
    if o.box.w < MIN_SIZE_PX or o.box.h < MIN_SIZE_PX:
        findings.error(o.place, f"the {cls.name} is {o.box.w:.3g}x{o.box.h:.3g} px, smaller "
                       f"than the {MIN_SIZE_PX:g} px a side the game can collide",
                       "make it at least 1 px wide and tall, or draw it as a point")
        return None
    return o.box


def _check_inside(o: MapObject, box: Box, header: MapHeader, findings: Findings) -> None:
    """Everything must fit in the map and overlap it: an object off any side, above it
    included, is out of reach. A Player, an Exit or a Checkpoint there makes the level
    unplayable (an error); anything else is only wasted (a warning)."""
    width, height = header.cols * header.tile_w, header.rows * header.tile_h
    on_map = box.right > 0 and box.left < width and box.bottom > 0 and box.top < height
    side = ("left of" if box.right <= 0 else "right of" if box.left >= width
            else "above" if box.bottom <= 0 else "below")
    if box.w > width or box.h > height:
        findings.error(o.place, "it is larger than the map", "make it smaller in Tiled")
    elif not on_map and o.cls in MUST_BE_REACHABLE:
        name = CLASSES_BY_NAME[o.cls].name
        findings.error(o.place, f"the {name} is {side} the map, where the player cannot "
                       f"{'start' if o.cls == 'player' else 'reach it'}",
                       "move it onto the map")
    elif not on_map:
        findings.warn(o.place, f"it is {side} the map, where nothing can reach it",
                      "move it onto the map")


def _inside_solid(box: Box, grid: TileGrid, fully: bool) -> bool:
    """Does ``box`` overlap a Solid tile's shape (``fully``: is all of it covered)?"""
    solids = [s.box for s in grid.shapes_in(box) if s.kind is TileKind.SOLID]
    if not fully:
        return bool(solids)
    covered = sum(max(0.0, min(box.right, s.right) - max(box.left, s.left))
                  * max(0.0, min(box.bottom, s.bottom) - max(box.top, s.top)) for s in solids)
    return covered >= box.w * box.h


def _rests_on_ground(box: Box, grid: TileGrid) -> bool:
    """Does the row of pixels just under ``box`` touch a Solid or OneWay tile?

    An Exit or a Checkpoint is a flag on a pole: it should stand on something, both to look
    built and so that a player walking along the ground runs into it."""
    under = Box(box.x, box.bottom, box.w, 1)
    return any(shape.kind in (TileKind.SOLID, TileKind.ONE_WAY)
               for shape in grid.shapes_in(under))


def _warn_unknown(objects: list[MapObject], findings: Findings) -> None:
    """One warning per class the game does not know, naming its first object."""
    by_class: dict[str, list[MapObject]] = defaultdict(list)
    for o in objects:
        slip = meant(o.class_name, OBJECT_CLASS_NAMES) if o.cls not in CLASSES_BY_NAME else None
        if slip is not None:
            findings.error(o.place, f"class '{o.class_name}' is not a class the game knows; "
                           f"it looks like '{slip}' misspelt", f"set its Class to {slip}")
        elif o.cls and o.cls not in CLASSES_BY_NAME:
            by_class[o.class_name].append(o)
        elif o.cls in TILE_KINDS:
            findings.warn(o.place, f"a {TILE_KINDS[o.cls].value} tile placed as an object "
                          "does not collide", "paint the tile on a tile layer instead")
    for cls, group in by_class.items():
        more = f" ({len(group)} objects have it)" if len(group) > 1 else ""
        findings.warn(group[0].place, f"class '{cls}' means nothing to the game{more}",
                      f"use one of {CLASS_NAMES}, or clear the class for notes")


def _check_budget(coins: list[CoinSpec], enemies: list[EnemySpec],
                  platforms: list[PlatformSpec], others: list[Box],
                  findings: Findings) -> None:
    """Fail if the map makes more bodies, or bodies of more pixels, than one level may
    (:mod:`game.levels.budget`): each is a sprite with a surface, moved or drawn each tick."""
    for count, limit, name in ((len(coins), MAX_COINS, "Coins"),
                               (len(enemies), MAX_ENEMIES, "Enemies"),
                               (len(platforms), MAX_PLATFORMS, "Platforms")):
        if count > limit:
            findings.fail("map", f"it has {count:,} {name}, more than the {limit:,} one "
                          "level may have (each is moved or drawn every tick)",
                          f"delete some {name}, or split the level into two maps")
    boxes = [*(c.box for c in coins), *(e.box for e in enemies), *others]
    pixels = sum(math.ceil(b.w) * math.ceil(b.h) for b in boxes) + sum(
        math.ceil(p.width_px) * math.ceil(p.height_px) for p in platforms)
    if pixels > MAX_SPRITE_PIXELS:
        findings.fail("map", f"its objects' boxes cover {pixels:,} pixels in all, more than "
                      f"the {MAX_SPRITE_PIXELS:,} the game draws sprites for in one level",
                      "make the Coins, Enemies, Platforms and Exits smaller, or use fewer")


def build_entities(objects: list[MapObject], header: MapHeader, grid: TileGrid,
                   tuning: Tuning, findings: Findings) -> Entities:
    """Turn objects into the level's spawn, coins, enemies and exits, or record why not.

    Class defaults (a Coin's value, an Enemy's speed) are those ``tuning`` implies."""
    _warn_unknown(objects, findings)
    classes = {cls.name.lower(): cls for cls in classes_for(tuning)}
    spawns: list[Box] = []
    coins: list[CoinSpec] = []
    enemies: list[EnemySpec] = []
    exits: list[Box] = []
    platforms: list[PlatformSpec] = []
    checkpoints: list[Box] = []
    sizes = {"player": (tuning.player_width_px, tuning.player_height_px),
             "enemy": (tuning.enemy_width_px, tuning.enemy_height_px),
             "coin": (DEFAULT_COIN_PX, DEFAULT_COIN_PX)}
    for o in objects:
        cls = classes.get(o.cls)
        if cls is None or cls.use_as != "object":
            continue
        values = _values(o, cls, findings)
        if o.cls == "platform":
            platform = _platform(o, values, findings)
            if platform is not None:
                platforms.append(platform)
            continue
        if o.cls in ("exit", "checkpoint") and o.is_point:
            findings.error(o.place, f"{_a(cls.name)} must be a rectangle",
                           f"draw the {cls.name} with the Rectangle tool")
            continue
        box = _box(o, cls, sizes.get(o.cls, (0, 0)), findings)
        if box is None:
            continue
        _check_inside(o, box, header, findings)
        if o.cls == "player":
            spawns.append(box)
            if len(spawns) == 2:
                findings.error(o.place, "a second Player object",
                               "keep exactly one object with Class 'Player'")
            if _inside_solid(box, grid, fully=False):
                findings.error(o.place, "the Player starts inside a Solid tile",
                               "move the Player into open space"
                               + (" (a point is the top-left corner of its hitbox)"
                                  if o.is_point else ""))
        elif o.cls == "coin":
            coins.append(CoinSpec(box, int(values["value"])))
        elif o.cls == "enemy":
            enemies.append(EnemySpec(box, float(values["speed"]), str(values["kind"])))
        else:
            (checkpoints if o.cls == "checkpoint" else exits).append(box)
            if _inside_solid(box, grid, fully=True):
                findings.error(o.place, f"the {cls.name} is inside Solid tiles, where the "
                               "player cannot touch it", f"move the {cls.name} into open "
                               "space, its bottom edge on the ground")
            elif not _rests_on_ground(box, grid):
                findings.warn(o.place, f"the {cls.name} floats: no Solid or OneWay tile is "
                              "right under it", f"move the {cls.name} down until its bottom "
                              "edge rests on the ground")
    _check_budget(coins, enemies, platforms, [*exits, *checkpoints], findings)
    if not spawns and objects and not any(o.cls for o in objects):
        findings.fail("", f"none of the map's {len(objects)} objects has a Class, so this "
                      "map has no Player object; Tiled 1.8 drops the classes of a map saved "
                      "by Tiled 1.9 or later (it cannot read class=) when it saves it again",
                      "get the map back from before Tiled 1.8 saved it (version control, a "
                      "backup), or set each object's Type again; open the levels in Tiled "
                      "1.8 through levels/tile-hopper-1.8.tiled-project and in Tiled 1.9+ "
                      "through levels/tile-hopper.tiled-project, which makes Tiled 1.9+ "
                      "write classes that Tiled 1.8 keeps")
    if not spawns:
        findings.fail("", "this map has no Player object",
                      "add a point or rectangle with Class 'Player' on an object layer")
    if not exits:
        findings.warn("", "this map has no Exit, so it can never be completed",
                      "draw a rectangle with Class 'Exit' on an object layer")
    return Entities(spawns[0], tuple(coins), tuple(enemies), tuple(exits), tuple(platforms),
                    tuple(checkpoints))


def _platform(o: MapObject, values: dict[str, Plain], findings: Findings,
              ) -> PlatformSpec | None:
    """A Platform: a polyline (back and forth) or polygon (round and round) to follow."""
    if o.shape not in ("polyline", "polygon") or len(o.points) < 2:
        findings.error(o.place, "a Platform needs a path of two or more points",
                       "draw the Platform with the Polyline tool, from where it starts")
        return None
    return PlatformSpec(Route(o.points, loop=o.shape == "polygon"), float(values["width"]),
                        float(values["height"]), float(values["speed"]))
