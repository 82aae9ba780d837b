"""The game's Tiled classes: one list that the loader, Tiled and the docs all read.

Where it sits: :mod:`game.levels.entities` applies these defaults and checks these types
when it turns objects into coins and enemies; :mod:`game.levels.project` writes the same
list into ``levels/tile-hopper.tiled-project`` (and the files Tiled 1.8 and pytmx read), so
the defaults a designer sees in Tiled are the ones the game uses.

What it teaches: keep one source of truth and generate the rest. Numbers that belong to the
game's feel (the enemies' patrol speed, gravity) come from :class:`game.sim.tuning.Tuning`.

>>> CLASSES_BY_NAME["coin"].defaults()
{'value': 1}
>>> find("ENEMY").defaults()["speed"] == Tuning().enemy_speed_px_s
True
>>> CLASSES_BY_NAME["coin"].member("value").coerce("7")
7
>>> CLASSES_BY_NAME["coin"].member("value").coerce(2.5)
Traceback (most recent call last):
    ...
ValueError: 2.5 is not a whole number
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from game.collision.shapes import TileKind
from game.levels.attributes import parse_number
from game.sim.enemy import EnemyKind
from game.sim.tuning import Tuning

MemberType = Literal["int", "float", "string", "bool", "file"]
UseAs = Literal["object", "tile", "map"]
Plain = int | float | str | bool

MAX_SPEED_PX_S = 1_000_000.0  # an enemy's or a platform's speed: past this a tick is a teleport
# The physics a map may set (Level properties), each within a range that keeps the game
# playable and every measurement of a map (the reach, the fill of reachable.py, the search)
# bounded. At the edges a full jump stays in the air at most about 30 s (jump_speed 1,000
# against gravity 200, falling back at 100 px/s), rises at most 2,500 px, and the player's
# own speeds move it at most 167 px a tick. Gravity or a fall speed of 0 would never bring
# a jump down. (levels/README.md lists them; a test keeps the two the same.)
GRAVITY_PX_S2 = (200.0, 1_000_000.0)  # 2/9 of the default up to any fall speed in one tick
MAX_FALL_SPEED_PX_S = (100.0, 10_000.0)  # a slow drift down to 10 tiles of 16 px a tick
RUN_SPEED_PX_S = (10.0, 10_000.0)  # a tile in 1.6 s up to 10 tiles of 16 px a tick
JUMP_SPEED_PX_S = (0.0, 1_000.0)  # no jump at all up to 3.4 times the default
MAX_COIN_VALUE = 1_000_000
TARGET_SECONDS = (0.0, 86_400.0)  # a level's target time, in s: 0 is none, at most a day
# The places a level can be set in (the map property ``setting``); game.app.places draws them.
SETTINGS = ("meadow", "cliffs", "forest", "caves", "dusk", "summit")
DEFAULT_SETTING = SETTINGS[0]
WHAT_TYPE = {"int": "a whole number", "float": "a number", "string": "text",
             "bool": "true or false", "file": "a file"}


def _plain(number: float) -> str:
    """A number as a designer types it: ``1,000,000``, ``0``, ``2.5``, ``1e+300``."""
    if number == int(number) and abs(number) < 1e15:
        return f"{int(number):,}"
    return f"{number:g}"


@dataclass(frozen=True)
class Member:
    """One property of a class: its name, type, default, allowed range and meaning."""

    name: str
    type: MemberType
    default: Plain
    doc: str
    low: float | None = None
    high: float | None = None
    choices: tuple[str, ...] = ()  # a string member that takes one of these (a Tiled enum)

    @property
    def expected(self) -> str:
        """What a value must be, in words.

        >>> speed("speed", 30.0, "patrol speed in px/s").expected
        'a number from 0 to 1,000,000'
        """
        if self.choices:
            return f"one of {', '.join(self.choices)}"
        if self.low is None or self.high is None:
            return WHAT_TYPE[self.type]
        return f"{WHAT_TYPE[self.type]} from {_plain(self.low)} to {_plain(self.high)}"

    def coerce(self, value: object) -> Plain:
        """``value`` as this member's type, or ValueError saying why not.

        Strings are accepted when they spell a value of the type, because a designer
        without the project file types ``value`` = ``5`` as a string.
        """
        if self.choices:
            if str(value).lower() not in self.choices:
                raise ValueError(f"{value!r} is not {self.expected}")
            return str(value).lower()
        if self.type in ("string", "file"):
            return str(value)
        if self.type == "bool":
            if isinstance(value, str) and value.strip().lower() in ("true", "false"):
                return value.strip().lower() == "true"
            if isinstance(value, bool):
                return value
            raise ValueError(f"{value!r} is not true or false")
        number = parse_number(value) if isinstance(value, str) else value
        if isinstance(number, bool) or not isinstance(number, (int, float)):
            raise ValueError(f"{value!r} is not a number")
        if self.type == "int" and number != int(number):
            raise ValueError(f"{value!r} is not a whole number")
        if (self.low is not None and number < self.low) or (
                self.high is not None and number > self.high):
            raise ValueError(f"{_plain(number)} is not {self.expected}")
        return int(number) if self.type == "int" else float(number)


@dataclass(frozen=True)
class TiledClass:
    """A class a tile, an object or a map can have in Tiled."""

    name: str
    use_as: UseAs
    color: str  # #rrggbb, how Tiled draws objects of this class
    doc: str
    members: tuple[Member, ...] = ()

    def defaults(self) -> dict[str, Plain]:
        return {member.name: member.default for member in self.members}

    def member(self, name: str) -> Member:
        return next(m for m in self.members if m.name == name)


def speed(name: str, default: float, doc: str,
          bounds: tuple[float, float] = (0.0, MAX_SPEED_PX_S)) -> Member:
    return Member(name, "float", default, doc, *bounds)


def classes_for(tuning: Tuning) -> tuple[TiledClass, ...]:
    """Every class, with the defaults that ``tuning`` implies."""
    return (
        TiledClass("Player", "object", "#3a7bd5",
                   "Where the player starts. A rectangle's size is the hitbox; a point gets "
                   f"the default {tuning.player_width_px}x{tuning.player_height_px} hitbox "
                   "with its top-left corner at the point. Exactly one per map."),
        TiledClass("Coin", "object", "#f0c020", "A coin to pick up.",
                   (Member("value", "int", 1, "points it is worth", -MAX_COIN_VALUE,
                           MAX_COIN_VALUE),)),
        TiledClass("Enemy", "object", "#d9534f",
                   "An enemy that patrols, turning at walls and ledges. Stomp it from above.",
                   (speed("speed", tuning.enemy_speed_px_s, "patrol speed in px/s"),
                    Member("kind", "string", EnemyKind.WALKER.value,
                           "walker patrols; hopper patrols in hops",
                           choices=tuple(kind.value for kind in EnemyKind)))),
        TiledClass("Exit", "object", "#5cb85c",
                   "A rectangle; touching it completes the level."),
        TiledClass("Checkpoint", "object", "#9b59b6",
                   "A rectangle; touching it makes the player come back here after a lost "
                   "life, standing at its bottom edge."),
        TiledClass("Platform", "object", "#e67e22",
                   "A moving platform: draw its path with the Polyline tool; the platform's "
                   "top-left corner travels along it, back and forth (or round, for a "
                   "Polygon). It carries what stands on it and pushes what is in its way.",
                   (Member("width", "float", 48.0, "the platform's width in px", 1.0, 4096.0),
                    Member("height", "float", 8.0, "the platform's height in px", 1.0, 4096.0),
                    speed("speed", 40.0, "travel speed along the path in px/s"))),
        TiledClass(TileKind.SOLID.value, "tile", "#8c6d46", "Blocks from every side."),
        TiledClass(TileKind.ONE_WAY.value, "tile", "#c8a165",
                   "Blocks only a body coming down onto its top."),
        TiledClass(TileKind.HAZARD.value, "tile", "#ff5050",
                   "Costs a life on touch; blocks nothing."),
        TiledClass("Level", "map", "#a0a0a4",
                   "A map's optional properties (set the map's class to Level in Tiled 1.9+ "
                   "to see them listed).",
                   (Member("title", "string", "", "shown when the level starts"),
                    Member("next_level", "file", "", "the map that follows this one"),
                    Member("setting", "string", DEFAULT_SETTING,
                           "where the level is set: its sky, scenery and ground",
                           choices=SETTINGS),
                    Member("target_seconds", "float", 0.0,
                           "the target time in s: a finish within it earns a medal; 0 is none",
                           *TARGET_SECONDS),
                    speed("gravity", tuning.gravity_px_s2, "downward pull in px/s²",
                          GRAVITY_PX_S2),
                    speed("max_fall_speed", tuning.max_fall_speed_px_s,
                          "fastest fall in px/s", MAX_FALL_SPEED_PX_S),
                    speed("run_speed", tuning.run_speed_px_s, "top running speed in px/s",
                          RUN_SPEED_PX_S),
                    speed("jump_speed", tuning.jump_speed_px_s,
                          "upward speed of a jump in px/s", JUMP_SPEED_PX_S))),
    )


CLASSES = classes_for(Tuning())
CLASSES_BY_NAME = {cls.name.lower(): cls for cls in CLASSES}
OBJECT_CLASSES = tuple(cls for cls in CLASSES if cls.use_as == "object")
TILE_KINDS = {kind.value.lower(): kind for kind in TileKind}
LEVEL = CLASSES_BY_NAME["level"]


def find(name: str) -> TiledClass:
    """The class named ``name``, in any letter case (KeyError if there is none)."""
    return CLASSES_BY_NAME[name.lower()]
