"""Levels: the shipped campaign and the loader that turns Tiled maps into playable levels.

``python -m game.levels check PATH...`` checks maps the way the game loads them.
"""

from __future__ import annotations

from pathlib import Path

from game.levels.errors import LevelError
from game.levels.loader import load_level

LEVELS_DIR = Path(__file__).resolve().parent.parent.parent / "levels"
FIRST_LEVEL = LEVELS_DIR / "01-first-steps.tmx"

__all__ = ["FIRST_LEVEL", "LEVELS_DIR", "LevelError", "load_level"]
