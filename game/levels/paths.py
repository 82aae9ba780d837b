"""Which files a level may use: the ones inside its folder tree.

Where it sits: every path a map names (its tilesets, their images, its templates) goes
through :func:`resolve` before anything is opened.

The rule: a map inside a project (a folder that holds both a ``levels/`` and an ``assets/``
folder, like this repository) may use any file in that project, so the shipped levels'
``../assets/tiles.tsx`` is fine. A map anywhere else may use files in its own folder and
the folders below it. A path that climbs out (``../../elsewhere/tiles.tsx``, or an absolute
``/home/someone/tiles.tsx``) works on one computer and breaks on the next, so it is refused.

What it teaches: Tiled writes paths relative to the file that contains them (a tileset's
image is relative to the ``.tsx``, not to the map), and a path is compared after folding
``..`` away, without following symbolic links, the way a designer reads it.

>>> root = project_root(Path("/game/levels/01.tmx"), is_project=lambda p: p == Path("/game"))
>>> root
PosixPath('/game')
>>> inside(Path("/game/levels/../assets/tiles.tsx"), root)
True
>>> inside(Path("/game/levels/../../etc/passwd"), root)
False
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

from game.levels.errors import Findings

PROJECT_FOLDERS = ("levels", "assets")


def _holds_project_folders(folder: Path) -> bool:
    return all((folder / name).is_dir() for name in PROJECT_FOLDERS)


def _absolute(path: Path) -> Path:
    """``path`` made absolute with ``..`` folded away, symbolic links left alone."""
    return Path(os.path.normpath(os.path.abspath(path)))


def project_root(map_path: Path,
                 is_project: Callable[[Path], bool] = _holds_project_folders) -> Path:
    """The folder a map's files must sit in: the nearest folder above the map that holds
    ``levels/`` and ``assets/``, or else the map's own folder."""
    folder = _absolute(map_path).parent
    for candidate in (folder, *folder.parents):
        try:
            if is_project(candidate):
                return candidate
        except OSError:
            break
    return folder


def inside(path: Path, root: Path) -> bool:
    """True when ``path``, with ``..`` folded away, lies in ``root`` or below it."""
    return _absolute(path).is_relative_to(root)


def resolve(reference: str, relative_to: Path, root: Path, findings: Findings,
            where: str, what: str) -> Path:
    """The file a Tiled path names, made absolute; fail if it leaves ``root``.

    ``relative_to`` is the folder of the file the reference was written in.
    """
    if not reference.strip():
        findings.fail(where, f"the {what} has no file name",
                      "pick the file again in Tiled")
    target = _absolute(relative_to / reference)
    if not inside(target, root):
        findings.fail(where, f"the {what} {reference!r} is outside the level's folder "
                      f"({root})",
                      "move the file into the project's assets/ or levels/ folder (or "
                      "beside the map) and pick it again in Tiled")
    return target
