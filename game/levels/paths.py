"""Which files a level may use: the level's folder is a sandbox.

Where it sits: every path a map names (its tilesets, their images, its templates, the
``next_level`` that follows it) goes through :func:`resolve` before anything is opened.

The rule: a level may use the files in the folder that holds it (and the folders below),
and, when it sits in a project (a folder that holds both a ``levels/`` and an ``assets/``
folder, like this repository or the installed game), the files in that project's
``levels/`` and ``assets/``; so the shipped levels' ``../assets/tiles.tsx`` is fine. Any
other path (``../../elsewhere/tiles.tsx``, an absolute ``/home/someone/tiles.tsx``, or a
symbolic link inside the folder that points out of it) is refused, with the rule and the
fix: levels are shared and downloaded, and a level must not read files it was not given.

What it teaches: Tiled writes paths relative to the file that contains them (a tileset's
image is relative to the ``.tsx``, not to the map). A path is judged by where it really
leads: ``..`` is folded away *and* symbolic links are followed (:func:`os.path.realpath`)
before it is compared with the allowed folders, which are resolved the same way; the file
that is then opened is that real path, so what was checked is what is read.

>>> sandbox = Sandbox((Path("/game/levels"), Path("/game/assets")))
>>> sandbox.allows(Path("/game/levels/../assets/tiles.tsx"))
True
>>> sandbox.allows(Path("/game/levels/../../etc/passwd"))
False
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from game.levels.errors import Findings, escaped, excerpt

PROJECT_FOLDERS = ("levels", "assets")
FIX_OUTSIDE = ("move the file beside the map (or into the project's assets/ or levels/ "
               "folder) and pick it again in Tiled")


def real(path: Path) -> Path:
    """``path`` made absolute, ``..`` folded away and symbolic links followed."""
    return Path(os.path.realpath(path))


def _holds_project_folders(folder: Path) -> bool:
    """True when ``folder`` holds real ``levels/`` and ``assets/`` folders: a symbolic link
    in their place (``assets -> /``) would make every file on the machine a project file,
    so a folder with one is not a project."""
    return all((folder / name).is_dir() and not (folder / name).is_symlink()
               for name in PROJECT_FOLDERS)


@dataclass(frozen=True)
class Sandbox:
    """The folders one level's files must lie in, each made a real (resolved) path once,
    when the sandbox is made: every file the level names is then checked against them."""

    roots: tuple[Path, ...]

    def __post_init__(self) -> None:
        resolved = dict.fromkeys(real(root) for root in self.roots)  # in order, each once
        object.__setattr__(self, "roots", tuple(resolved))

    def allows(self, path: Path) -> bool:
        """True when ``path``, resolved, lies in one of the roots or below it."""
        target = real(path)
        return any(target.is_relative_to(root) for root in self.roots)

    def describe(self) -> str:
        """The allowed folders, for a message."""
        return " or ".join(escaped(str(root)) for root in self.roots)


def project_root(map_path: Path,
                 is_project: Callable[[Path], bool] = _holds_project_folders) -> Path | None:
    """The nearest folder above the map that holds ``levels/`` and ``assets/``, if any.

    >>> project_root(Path("/game/levels/01.tmx"), is_project=lambda p: p == Path("/game"))
    PosixPath('/game')
    """
    folder = Path(os.path.abspath(map_path)).parent
    for candidate in (folder, *folder.parents):
        try:
            if is_project(candidate):
                return candidate
        except (OSError, ValueError):
            break
    return None


def sandbox_for(map_path: Path, folder: Path | None = None) -> Sandbox:
    """The sandbox of the map at ``map_path``: its folder and its project's ``levels/`` and
    ``assets/``; or, when ``folder`` is given, that folder alone."""
    if folder is not None:
        return Sandbox((folder,))
    project = project_root(map_path)
    shared = tuple(project / name for name in PROJECT_FOLDERS) if project else ()
    return Sandbox((Path(os.path.abspath(map_path)).parent, *shared))


def check_map_file(map_path: Path, sandbox: Sandbox, findings: Findings) -> None:
    """Fail if the map itself is a symbolic link that leads out of its sandbox: a link named
    like a level is read like any other file the level names."""
    try:
        inside = sandbox.allows(map_path)
    except (OSError, ValueError):
        inside = False
    if not inside:
        findings.fail("", f"the map is a link that leads outside its folder; a level may "
                      f"only use files in {sandbox.describe()}",
                      "copy the map itself into the folder instead of linking to it")


def resolve(reference: str, relative_to: Path, sandbox: Sandbox, findings: Findings,
            where: str, what: str) -> Path:
    """The real file a Tiled path names; fail if it leads out of the sandbox.

    ``relative_to`` is the folder of the file the reference was written in.
    """
    if not reference.strip():
        findings.fail(where, f"the {what} has no file name",
                      "pick the file again in Tiled")
    try:
        target = real(relative_to / reference)
    except (OSError, ValueError):
        findings.fail(where, f"the {what} {excerpt(reference)} is not a usable path",
                      "pick the file again in Tiled")
    if not sandbox.allows(target):
        findings.fail(where, f"the {what} {excerpt(reference)} leads outside the level's "
                      f"folder; a level may only use files in {sandbox.describe()}",
                      FIX_OUTSIDE)
    return target
