"""Levels: the shipped campaign, and the loader that turns Tiled maps into playable levels.

``load_level(path)`` reads a map for the game; ``check_level(path)`` lists everything wrong
with one. ``python -m game.levels check PATH...`` prints those findings and proves each map
can be won with :mod:`game.levels.solver` (``python -m game.levels solve MAP`` shows the
route), and
``python -m game.levels types --write`` regenerates the Tiled project's class definitions
(see ``levels/README.md``, the level designer's guide).
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
