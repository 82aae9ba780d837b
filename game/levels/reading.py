"""Open one file of a level: a regular file, never waiting, never more than a limit.

Where it sits: the only place in :mod:`game.levels` that opens a file. The map, its tilesets
and templates (:mod:`game.levels.tiledxml`) and every image (:mod:`game.levels.images`) are
read through :func:`read_level_file`, after :mod:`game.levels.paths` has said the path may
be used; each file read is noted in the map's :class:`~game.levels.errors.Findings`, which
is how ``--watch`` knows what to watch.

What it teaches: check what you opened, not what you looked at. A path is opened with
``O_NONBLOCK``, so a named pipe cannot make the game wait for a writer (and SIGTERM still
ends it); then ``fstat`` on the open descriptor says what it really is, so a file swapped
for a pipe or a device between a check and the open is still refused; and at most the
limit plus one byte is read, so ``/dev/zero`` or a 10 GB file costs nothing.

>>> import tempfile
>>> folder = Path(tempfile.mkdtemp())
>>> (folder / "a.tmx").write_bytes(b"<map/>")
6
>>> findings = Findings(folder / "a.tmx")
>>> read_level_file(folder / "a.tmx", findings, "", "map", 100)
b'<map/>'
>>> os.mkfifo(folder / "pipe.tsx")
>>> read_level_file(folder / "pipe.tsx", findings, "", "tileset file", 100)  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: ...: the tileset file is not a regular file ... — ...
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

from game.levels.errors import Findings

FIX_READ = "check that the file is there and that you may read it"
FIX_REGULAR = "give the path of a file saved by Tiled, not a pipe, device or folder"


def reason(error: BaseException) -> str:
    """The short cause of an error, for a message."""
    return (error.strerror if isinstance(error, OSError) else None) or str(error)


def read_level_file(path: Path, findings: Findings, where: str, what: str, max_bytes: int,
                    too_big_fix: str = "use a smaller file",
                    missing: tuple[str, str] | None = None,
                    not_regular_fix: str = FIX_REGULAR) -> bytes:
    """The bytes of the regular file at ``path`` (at most ``max_bytes``); fail with one
    sentence naming ``what`` if it is missing (``missing``: the problem and fix to say
    then), not a regular file, or too large."""
    findings.opened(path)
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)
                             | getattr(os, "O_NOCTTY", 0))
    except (FileNotFoundError, NotADirectoryError):
        findings.fail(where, *(missing or (f"the {what} does not exist",
                                           "check the path, or save the file from Tiled first")))
    except (OSError, ValueError) as error:
        findings.fail(where, f"the {what} cannot be opened ({reason(error)})", FIX_READ)
    try:
        status = os.fstat(descriptor)
        if stat.S_ISDIR(status.st_mode):
            findings.fail(where, f"the {what} is a folder, not a file", not_regular_fix)
        if not stat.S_ISREG(status.st_mode):
            findings.fail(where, f"the {what} is not a regular file (a pipe or a device?)",
                          not_regular_fix)
        if status.st_size > max_bytes:
            findings.fail(where, f"the {what} is larger than {max_bytes // 2**20} MB",
                          too_big_fix)
        chunks: list[bytes] = []
        left = max_bytes + 1
        while left > 0:
            chunk = os.read(descriptor, min(left, 1 << 20))
            if not chunk:
                break
            chunks.append(chunk)
            left -= len(chunk)
    except OSError as error:
        findings.fail(where, f"the {what} cannot be read ({reason(error)})", FIX_READ)
    finally:
        os.close(descriptor)
    data = b"".join(chunks)
    if len(data) > max_bytes:  # it grew after fstat
        findings.fail(where, f"the {what} is larger than {max_bytes // 2**20} MB", too_big_fix)
    return data
