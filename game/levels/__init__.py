"""The loader: Tiled maps and tilesets in, a level for the simulation out, every problem a
sentence.

``load_level(path)`` reads a map for the game; ``check_level(path)`` lists everything wrong
with one. Judging whether a loaded map can be won is the checker's, a package of its own
(:mod:`game.checker`); ``python -m game.levels`` starts its command line (``check``,
``solve``, ``reach``, and ``types --write``, which regenerates the Tiled project's class
definitions: see ``levels/README.md``, the level designer's guide).

Its parts, in the order a map is read:

* :mod:`~game.levels.loader`: load or check a map; :mod:`~game.levels.errors`: file, place,
  what is wrong, how to fix it.
* The way in and out: :mod:`~game.levels.reading` (every file any command reads, one bounded
  way), :mod:`~game.levels.outputs` (every file any command writes, whole or not at all),
  :mod:`~game.levels.closed_output` (an output closed or full ends a command quietly),
  :mod:`~game.levels.paths` (the level's folder is a sandbox).
* Tiled's files: :mod:`~game.levels.tiledxml`, :mod:`~game.levels.header`,
  :mod:`~game.levels.attributes`, :mod:`~game.levels.tilesets`, :mod:`~game.levels.tiledata`,
  :mod:`~game.levels.layers`, :mod:`~game.levels.objects`, :mod:`~game.levels.templates`,
  :mod:`~game.levels.properties`, :mod:`~game.levels.images`, and
  :mod:`~game.levels.pytmx_bridge` (what pytmx is given).
* The game's meaning: :mod:`~game.levels.classes` (the game's Tiled classes),
  :mod:`~game.levels.solids` (tiles into collision shapes), :mod:`~game.levels.entities`
  (spawn, coins, enemies, exits), :mod:`~game.levels.spelling` (did you mean ...?),
  :mod:`~game.levels.budget` (how much a map may make).
* :mod:`~game.levels.shipped` (where the campaign and the art are) and
  :mod:`~game.levels.project` (the Tiled project's classes).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from game.levels.errors import Findings, LevelError, LevelWarning
from game.levels.shipped import ASSETS_DIR, FIRST_LEVEL, LEVELS_DIR

if TYPE_CHECKING:
    from game.levels.loader import check_level, load_level


def __getattr__(name: str) -> Any:
    """The loader, imported when first asked for: ``python -m game.levels`` imports this
    package before its ``__main__`` can guard against Ctrl-C, so the package itself loads
    nothing heavy (the loader brings pygame and pytmx)."""
    if name in ("check_level", "load_level"):
        from game.levels import loader

        return getattr(loader, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["ASSETS_DIR", "FIRST_LEVEL", "LEVELS_DIR", "Findings", "LevelError", "LevelWarning",
           "check_level", "load_level"]
