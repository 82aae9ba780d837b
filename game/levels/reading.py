"""The one way in: open a file any command reads as a regular file, never waiting, never more
than a limit, and remember it so that no output of the same run is written over it.

Where it sits: under every file any command reads. In :mod:`game.levels`, the map, its
tilesets and templates (:mod:`game.levels.tiledxml`) and every image
(:mod:`game.levels.images`) come through :func:`read_level_file`, after
:mod:`game.levels.paths` has said the path may be used; each file read is noted in the map's
:class:`~game.levels.errors.Findings`, which is how ``--watch`` knows what to watch. The
game's input scripts, saves and settings come through :func:`game.app.files.read_small_text`,
and input scripts given to the checker (``--proof``) through :func:`read_text`: all three
call :func:`read_bounded`, so every file is refused for the same reasons in the same words.

What it teaches:
  * **Check what you opened, not what you looked at.** A path is opened with
    ``O_NONBLOCK``, so a named pipe cannot make the program wait for a writer (and SIGTERM
    still ends it); then ``fstat`` on the open descriptor says what it really is, so a file
    swapped for a pipe or a device between a check and the open is still refused; and at
    most the limit plus one byte is read, so ``/dev/zero`` or a 10 GB file costs nothing.
  * **An input is never an output.** Each file read is remembered by its device, inode and
    time of change (:func:`was_read`), whatever name or link led to it; the one atomic write
    (:func:`game.levels.outputs.replace_atomically`) refuses to replace such a file, so
    ``--screenshot`` given the level's own name cannot turn the map into a picture. Files a
    run reads in order to update them (the player's saves) are read with ``updated=True``.

>>> import tempfile
>>> folder = Path(tempfile.mkdtemp())
>>> (folder / "a.tmx").write_bytes(b"<map/>")
6
>>> findings = Findings(folder / "a.tmx")
>>> read_level_file(folder / "a.tmx", findings, "", "map", 100)
b'<map/>'
>>> was_read(folder / "a.tmx")
True
>>> os.mkfifo(folder / "pipe.tsx")
>>> read_level_file(folder / "pipe.tsx", findings, "", "tileset file", 100)  # doctest: +ELLIPSIS
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: ...: the tileset file is not a regular file ... — ...
"""

from __future__ import annotations

import os
import stat
import time
from pathlib import Path

from game.levels.errors import Findings

FIX_READ = "check that the file is there and that you may read it"
FIX_REGULAR = "give the path of a file saved by Tiled, not a pipe, device or folder"
FIX_MISSING = "check the path, or save the file from Tiled first"
MAX_PIPE_WAIT_S = 10.0  # a pipe read for a file may stay silent this long, no longer
MAX_PIPE_READ_S = 60.0  # and may take this long in all, however often something comes
PIPE_POLL_S = 0.01
CHUNK_BYTES = 1 << 20  # read at most this much at a time

_read_this_run: set[tuple[int, int, int]] = set()  # (device, inode, mtime) of files read


class ReadProblem(Exception):
    """A file that cannot be read: ``problem`` says what is wrong (``"the map does not
    exist"``), ``fix`` what to do; the caller adds the file's name and place."""

    def __init__(self, problem: str, fix: str) -> None:
        super().__init__(f"{problem} — {fix}")
        self.problem = problem
        self.fix = fix


def reason(error: BaseException) -> str:
    """The short cause of an error, for a message."""
    return (error.strerror if isinstance(error, OSError) else None) or str(error)


def size_text(max_bytes: int) -> str:
    """A limit as a message gives it: in MB when it is whole megabytes, else in bytes.

    >>> size_text(8 * 2**20), size_text(65_536)
    ('8 MB', '65,536 bytes')
    """
    if max_bytes >= 2**20 and max_bytes % 2**20 == 0:
        return f"{max_bytes // 2**20} MB"
    return f"{max_bytes:,} bytes"


def was_read(path: Path) -> bool:
    """True when the file at ``path`` (whatever name or link leads to it) was read by this
    run through :func:`read_bounded` without ``updated``."""
    try:
        status = os.stat(path)
    except (OSError, ValueError):
        return False
    return _identity(status) in _read_this_run


def _identity(status: os.stat_result) -> tuple[int, int, int]:
    """A file as it was read: its device and inode, and its time of change, so that an
    inode freed and given to a new file is not taken for the file read."""
    return (status.st_dev, status.st_ino, status.st_mtime_ns)


def _read_pipe(descriptor: int, max_bytes: int, what: str) -> bytes:
    """Everything written into the pipe until its writer closes it, waiting at most
    MAX_PIPE_WAIT_S for each piece and MAX_PIPE_READ_S in all: a pipe nobody writes to, or
    one written a byte at a time for ever, is a problem, not a hang.
    Until a writer has appeared, an empty read means "nobody yet", not "the end"."""
    data, writer_seen = bytearray(), False
    deadline = time.monotonic() + MAX_PIPE_WAIT_S
    end = time.monotonic() + MAX_PIPE_READ_S  # a writer sending a byte now and then
    while len(data) <= max_bytes:
        if time.monotonic() > end:
            raise ReadProblem(f"{what} is a pipe that was still being written after "
                              f"{MAX_PIPE_READ_S:g} s", "write it into a file first")
        try:
            chunk: bytes | None = os.read(descriptor, min(CHUNK_BYTES, max_bytes + 1))
        except BlockingIOError:  # a writer is there, with nothing to say yet
            chunk, writer_seen = None, True
        if chunk:
            data += chunk
            writer_seen, deadline = True, time.monotonic() + MAX_PIPE_WAIT_S
            continue
        if chunk == b"" and writer_seen:
            break  # the writer closed the pipe: that is all
        if time.monotonic() > deadline:
            raise ReadProblem(f"{what} is a pipe and nothing came through it for "
                              f"{MAX_PIPE_WAIT_S:g} s", "give the path of a file")
        time.sleep(PIPE_POLL_S)
    return bytes(data)


def read_bounded(path: Path, max_bytes: int, what: str, *, pipes: bool = False,
                 updated: bool = False, too_big_fix: str = "use a smaller file",
                 missing: tuple[str, str] | None = None,
                 not_regular_fix: str = FIX_REGULAR) -> bytes:
    """The bytes of the regular file at ``path``, at most ``max_bytes``; else a
    :class:`ReadProblem` whose problem names ``what`` (``"the input script"``).

    With ``pipes``, a named pipe (a shell's ``<(command)``) is read too, waiting a bounded
    time for its writer. ``updated`` marks a file this run reads in order to write it
    again (a save), which is therefore not remembered as an input. ``missing`` is the
    problem and fix to give when there is no file."""
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0)
                             | getattr(os, "O_NOCTTY", 0))
    except (FileNotFoundError, NotADirectoryError):
        raise ReadProblem(*(missing or (f"{what} does not exist", FIX_MISSING))) from None
    except IsADirectoryError:
        raise ReadProblem(f"{what} is a folder, not a file", not_regular_fix) from None
    except (OSError, ValueError) as error:
        raise ReadProblem(f"{what} cannot be opened ({reason(error)})", FIX_READ) from None
    too_big = ReadProblem(f"{what} is larger than {size_text(max_bytes)}", too_big_fix)
    try:
        status = os.fstat(descriptor)
        if stat.S_ISDIR(status.st_mode):
            raise ReadProblem(f"{what} is a folder, not a file", not_regular_fix)
        if pipes and stat.S_ISFIFO(status.st_mode):
            data = _read_pipe(descriptor, max_bytes, what)
        elif not stat.S_ISREG(status.st_mode):
            raise ReadProblem(f"{what} is not a regular file (a pipe or a device?)",
                              not_regular_fix)
        elif status.st_size > max_bytes:
            raise too_big
        else:
            chunks: list[bytes] = []
            left = max_bytes + 1
            while left > 0:
                chunk = os.read(descriptor, min(left, CHUNK_BYTES))
                if not chunk:
                    break
                chunks.append(chunk)
                left -= len(chunk)
            data = b"".join(chunks)
            if not updated:
                _read_this_run.add(_identity(status))
    except OSError as error:
        raise ReadProblem(f"{what} cannot be read ({reason(error)})", FIX_READ) from None
    finally:
        os.close(descriptor)
    if len(data) > max_bytes:  # it grew after fstat, or the pipe went on
        raise too_big
    return data


def read_text(path: Path, max_bytes: int, what: str, *, pipes: bool = False,
              updated: bool = False) -> str:
    """:func:`read_bounded`, decoded as UTF-8 (a byte order mark is dropped); a file that
    is not UTF-8 is a :class:`ReadProblem` too."""
    data = read_bounded(path, max_bytes, what, pipes=pipes, updated=updated)
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ReadProblem(f"{what} is not UTF-8 text", "save it as plain UTF-8 text") from None


def read_level_file(path: Path, findings: Findings, where: str, what: str, max_bytes: int,
                    too_big_fix: str = "use a smaller file",
                    missing: tuple[str, str] | None = None,
                    not_regular_fix: str = FIX_REGULAR) -> bytes:
    """The bytes of the regular file at ``path`` (at most ``max_bytes``); fail with one
    sentence naming ``what`` if it is missing (``missing``: the problem and fix to say
    then), not a regular file, or too large."""
    findings.opened(path)
    try:
        return read_bounded(path, max_bytes, f"the {what}", too_big_fix=too_big_fix,
                            missing=missing, not_regular_fix=not_regular_fix)
    except ReadProblem as problem:
        findings.fail(where, problem.problem, problem.fix)

