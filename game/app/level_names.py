"""Shipped levels by name: ``--level first-steps`` as well as ``--level PATH``.

Where it sits: in the app, under :mod:`game.app.cli`, which turns the ``--level`` it was
given into the map the run starts at, and lists the names for ``--list-levels``. The shipped
maps are whatever ``.tmx`` files the campaign's folder holds
(:data:`game.levels.shipped.LEVELS_DIR`): no list of them is written down here.

What it teaches: **an installed program is started by names, not by its inside paths.**
Installed, the campaign lives in the package (``game/data/levels`` in ``site-packages``),
where no player would type its path. So a text that is not a path is looked up among the
shipped maps: by its file name (``01-first-steps.tmx``), its stem (``01-first-steps``), the
stem without its leading number (``first-steps``) or the number alone (``1``); case, spaces
and underscores do not matter, so a level's title (``First Steps``) finds it too. A path
works as before: a text with a folder separator in it, or naming a file that is there, is a
path, and so is a ``.tmx`` name no shipped map has (the loader then says what is wrong).

>>> from game.levels.shipped import LEVELS_DIR
>>> level_path(Path("First Steps")) == LEVELS_DIR / "01-first-steps.tmx"
True
>>> level_path(Path("elsewhere/first-steps")).as_posix()
'elsewhere/first-steps'
"""

from __future__ import annotations

import os
import re
from pathlib import Path

from game.app.arguments import excerpt
from game.levels.errors import escaped
from game.levels.shipped import LEVELS_DIR

NUMBERED = re.compile(r"(\d+)-(.+)")  # a campaign map's stem: its place, a hyphen, its name
SEPARATORS = re.compile(r"[\s_]+")  # in a name, these read as a hyphen


class UnknownLevel(Exception):
    """``--level`` names no file and no shipped level, or several shipped levels; the
    message is the one sentence to end with."""


def level_names(folder: Path = LEVELS_DIR) -> list[str]:
    """The names of the shipped maps (their file stems), in the campaign's order.

    >>> level_names()[0]
    '01-first-steps'
    """
    return sorted(path.stem for path in folder.glob("*.tmx") if path.is_file())


def _key(text: str) -> str:
    """``text`` as names are compared: no case, spaces and underscores as hyphens.

    >>> _key(" First_Steps "), _key("01-First steps.TMX")
    ('first-steps', '01-first-steps.tmx')
    """
    return SEPARATORS.sub("-", text.strip()).casefold()


def _aliases(stem: str) -> set[str]:
    """Every name a shipped map with this stem answers to.

    >>> sorted(_aliases("01-first-steps"))
    ['01-first-steps', '01-first-steps.tmx', '1', 'first-steps']
    """
    names = {_key(stem), _key(stem) + ".tmx"}
    if numbered := NUMBERED.fullmatch(stem):
        names |= {str(int(numbered[1])), _key(numbered[2])}
    return names


def _is_path(given: Path) -> bool:
    """Whether ``--level`` reads as a path: a folder separator in it, or a file there."""
    text = str(given)
    if any(sep and sep in text for sep in (os.sep, os.altsep, "/")):
        return True
    try:
        return given.exists()
    except (OSError, ValueError):  # a name too long, or with a NUL: the loader says so
        return True


def level_path(given: Path, folder: Path = LEVELS_DIR,
               program: str = "python -m game") -> Path:
    """The map ``--level`` names: ``given`` itself when it reads as a path, else the shipped
    map whose name it is. :class:`UnknownLevel` when it names none or more than one."""
    if _is_path(given):
        return given
    key = _key(str(given))
    names = level_names(folder)
    found = [name for name in names if key in _aliases(name)]
    if len(found) == 1:
        return folder / f"{found[0]}.tmx"
    quoted = escaped(excerpt(str(given)))
    if found:
        raise UnknownLevel(f"{program}: --level {quoted}: names {len(found)} shipped levels, "
                       f"{', '.join(found)} — give one of those names whole")
    if given.suffix.lower() == ".tmx":
        return given  # a map's path after all: the loader says it is not there
    listed = ", ".join(escaped(name) for name in names) or "none"
    raise UnknownLevel(f"{program}: --level {quoted}: there is no such file and no shipped level "
                   f"of that name — give a .tmx map's path or a shipped level's name ({listed}; "
                   f"{program} --list-levels lists them)")
