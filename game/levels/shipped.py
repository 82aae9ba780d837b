"""Where the game's own files are: the campaign in ``levels/`` and the art, tileset and
sounds in ``assets/``, found the same way in a clone and in an installed copy.

Where it sits: read once at import by whatever needs a shipped file (the first level, the
sprite sheets, the sounds). Nothing here depends on the working folder, so the game starts
the same from any folder.

What it teaches: **a program carries its data.** In the repository the two folders sit at
the top, beside ``game/``, where a level designer finds them. A wheel cannot put folders at
the top of ``site-packages``, so the build maps them into the package as
``game/data/levels`` and ``game/data/assets`` (see ``pyproject.toml``). :func:`data_root`
looks for the installed copy first and falls back to the repository's top.

>>> (LEVELS_DIR / "01-first-steps.tmx").is_file(), (ASSETS_DIR / "tiles.tsx").is_file()
(True, True)
"""

from __future__ import annotations

from pathlib import Path

PACKAGE_DIR = Path(__file__).resolve().parent.parent  # game/


def data_root(package: Path = PACKAGE_DIR) -> Path:
    """The folder that holds ``levels/`` and ``assets/``: ``game/data`` when installed,
    else the repository's top folder.

    >>> data_root(Path("/nowhere/game")).as_posix()
    '/nowhere'
    """
    installed = package / "data"
    if (installed / "levels").is_dir():
        return installed
    return package.parent


DATA_ROOT = data_root()
LEVELS_DIR = DATA_ROOT / "levels"
ASSETS_DIR = DATA_ROOT / "assets"
FIRST_LEVEL = LEVELS_DIR / "01-first-steps.tmx"
