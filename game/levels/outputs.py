"""Write a file the level tools make (a solver's script, a route picture) so that a failed
write leaves nothing behind: a temporary file beside it, then a rename.

Where it sits: under ``python -m game.levels solve``, and under the app's own outputs
(:mod:`game.app.files` names its temporary files and saves its pictures the same way).

What it teaches:
  * **The temporary name is the program's, not the user's.** It is made of plain ASCII
    and cut short, so a real name of 244 characters, or of bytes that are not UTF-8, still
    has a temporary name under the 255 bytes a name may take, and any library can open it.
    Only the final rename uses the real name, and the operating system takes any bytes.
  * **A library that picks a format by the name** (pygame's image saving) is given an open
    file and the format's name, so what it writes does not depend on the real name's ending,
    and a write error (a full disk) comes back as an error, never as a short file.
"""

from __future__ import annotations

import contextlib
import errno
import os
import re
import secrets
from collections.abc import Callable
from pathlib import Path

import pygame

from game.levels.errors import escaped

MAX_TEMPORARY_STEM_CHARS = 100  # far below the 255 bytes a name may take
IMAGE_SUFFIXES = (".png", ".bmp", ".tga", ".jpg", ".jpeg")  # what pygame writes by name
DISK_FULL = (errno.ENOSPC, errno.EFBIG, errno.EDQUOT)


def plain(text: str, limit: int = MAX_TEMPORARY_STEM_CHARS) -> str:
    """``text`` with every character but ASCII letters, digits, ``-`` and ``_`` made ``_``,
    cut to ``limit``.

    >>> plain("my level\\udcff (2)")
    'my_level___2_'
    """
    return re.sub(r"[^A-Za-z0-9_-]", "_", text)[:limit]


def temporary_path(path: Path, suffix: str | None = None) -> Path:
    """A fresh temporary name beside ``path``: ``.STEM.PID.RANDOM.SUFFIX``, all plain.

    >>> name = temporary_path(Path("out/" + "é" * 244 + ".png")).name
    >>> len(name.encode()) < 255 and name.startswith("._") and name.endswith(".png")
    True
    """
    ending = suffix if suffix is not None else "." + plain(path.suffix[1:], 16)
    return path.with_name(f".{plain(path.stem)}.{os.getpid()}.{secrets.token_hex(4)}"
                          f"{ending if ending != '.' else ''}")


def temporary_pattern(path: Path) -> re.Pattern[str]:
    """The names :func:`temporary_path` gives the temporary files of ``path``; group 1 is
    the process id of the writer."""
    return re.compile(rf"\.{re.escape(plain(path.stem))}\.(\d{{1,10}})\.[0-9a-f]{{8}}"
                      r"(\.[A-Za-z0-9_-]*)?")


def image_suffix(path: Path) -> str:
    """The format an image saved at ``path`` is written in: its ending if pygame writes
    that format, else PNG."""
    suffix = path.suffix.lower()
    return suffix if suffix in IMAGE_SUFFIXES else ".png"


def write_surface(surface: pygame.Surface, tmp: Path, suffix: str) -> None:
    """Save ``surface`` into the file ``tmp`` in the format ``suffix`` names; OSError if it
    cannot be written (pygame's own error says only "Error writing the PNG file.")."""
    with tmp.open("wb") as stream:
        try:
            pygame.image.save(surface, stream, f"image{suffix}")
        except pygame.error as error:
            try:
                full = os.statvfs(tmp.parent).f_bavail == 0
            except OSError:
                full = False
            raise OSError(errno.ENOSPC if full else errno.EIO,
                          os.strerror(errno.ENOSPC) if full else str(error)) from None


def replace_atomically(path: Path, write: Callable[[Path], object],
                       suffix: str | None = None) -> None:
    """Call ``write`` on a temporary path beside ``path``, then rename it over ``path``;
    on any error the temporary file is removed and the error raised."""
    tmp = temporary_path(path, suffix)
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink(missing_ok=True)
        raise


def _named(path: Path) -> str:
    """``path`` as printed: any byte or character that could forge output, escaped."""
    return escaped(os.fsdecode(path))


def unwritable(path: Path, what: str) -> str | None:
    """The sentence to print if ``what`` plainly cannot be written at ``path`` (its folder
    is missing, or is not one we may write in, or the path is a folder), else None.

    Asked before a long search, so a mistyped path costs nothing; a write can still fail
    later (a full disk, a name too long), which :func:`write_output` reports. Unlike the
    game's own outputs (:func:`game.app.files.output_problem`), a missing folder is a
    problem here: the level tools make no folders, so a failed write leaves nothing behind.
    """
    folder = Path(os.path.abspath(path)).parent
    try:
        if not folder.is_dir():
            reason = "its folder does not exist"
        elif not os.access(folder, os.W_OK | os.X_OK):
            reason = "its folder may not be written to"
        elif path.is_dir():
            reason = "it is a folder"
        else:
            return None
    except (OSError, ValueError):
        return None  # a name the system refuses: the write will say so
    return f"{_named(path)}: {what} cannot be written ({reason}) — check the path"


def write_output(path: Path, write: Callable[[Path], object], what: str,
                 suffix: str | None = None) -> str | None:
    """Write ``path`` atomically; the sentence to print if it could not be, else None."""
    try:
        replace_atomically(path, write, suffix)
    except (OSError, ValueError, pygame.error) as error:
        reason = (error.strerror if isinstance(error, OSError) else None) or str(error)
        fix = ("free some space" if isinstance(error, OSError) and error.errno in DISK_FULL
               else "check the path")
        return f"{_named(path)}: {what} cannot be written ({reason}) — {fix}"
    return None
