"""The one way out: every file any command writes is written whole or not at all, a
temporary file beside it, put on the disk, then a rename.

Where it sits: under every file any command writes. ``python -m game.levels solve`` calls
:func:`replace_atomically` through :func:`write_output`, ``types --write`` and the terrain
tool call it directly, and the game, the lab, the bench and the asset tools through the
app's wrappers in :mod:`game.app.files`. :func:`refusal` says which paths an output may
never replace.

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
from game.levels.reading import was_read

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


class Refused(ValueError):
    """An output that must not be written where it was asked for; the message is the
    reason (``"it is a file this run reads"``)."""


def refusal(path: Path) -> str | None:
    """Why ``path`` must never be replaced by an output of this run, or None: a symbolic
    link (writing through it would change a file elsewhere, replacing it would break the
    link), a file this run has read (a map, a tileset, an image, a script: an output written
    there would destroy the input), a folder that is not there (no folder is made), or
    anything but a regular file (a rename over ``/dev/null`` would replace the device).

    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> refusal(folder / "new.txt") is None
    True
    >>> refusal(folder / "missing" / "new.txt")
    'its folder does not exist'
    """
    try:
        if path.is_symlink():
            return "it is a symbolic link"
        if not Path(os.path.abspath(path)).parent.is_dir():
            return "its folder does not exist"
        if path.exists() and not path.is_file():  # a rename would replace a device or pipe
            return ("it is a folder" if path.is_dir()
                    else "it is not a regular file (a pipe or a device?)")
    except (OSError, ValueError):
        return None  # a name the system refuses: the write itself will say so
    if was_read(path):
        return "it is a file this run reads"
    return None


def _sync(path: Path, flags: int) -> None:
    """Ask the system to put ``path`` on the disk now (a folder: its list of names)."""
    try:
        descriptor = os.open(path, flags)
    except OSError:
        return  # a folder that cannot be opened (some platforms): the rename still stands
    try:
        os.fsync(descriptor)
    except OSError:
        pass
    finally:
        os.close(descriptor)


def replace_atomically(path: Path, write: Callable[[Path], object],
                       suffix: str | None = None) -> None:
    """The one way out: call ``write`` on a temporary path beside ``path``, put it on the
    disk, then rename it over ``path``; on any error or interruption (Ctrl-C included) the
    temporary file is removed, the original left as it was, and the error raised.

    :class:`Refused` (a ValueError) when :func:`refusal` forbids the path."""
    refused = refusal(path)
    if refused is not None:
        raise Refused(refused)
    tmp = temporary_path(path, suffix)
    try:
        write(tmp)
        descriptor = os.open(tmp, os.O_RDONLY)
        try:
            os.fsync(descriptor)  # the new bytes are on the disk before the name moves
        finally:
            os.close(descriptor)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink(missing_ok=True)
        raise
    _sync(Path(os.path.abspath(path)).parent, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))


def _named(path: Path) -> str:
    """``path`` as printed: any byte or character that could forge output, escaped."""
    return escaped(os.fsdecode(path))


def unwritable(path: Path, what: str) -> str | None:
    """The sentence to print if ``what`` plainly cannot be written at ``path`` (its folder
    is missing, or is not one we may write in, the path is a folder, or :func:`refusal`
    forbids it: a link, a device, a file this run has read), else None.

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
            refused = refusal(path)
            if refused is None:
                return None
            reason = refused
    except (OSError, ValueError):
        return None  # a name the system refuses: the write will say so
    fix = ("give it another name" if reason == "it is a file this run reads"
           else "check the path")
    return f"{_named(path)}: {what} cannot be written ({reason}) — {fix}"


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
