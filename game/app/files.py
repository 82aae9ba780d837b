"""The files a run reads and writes, handled so that no path can hang, crash or flood it.

Where it sits: under every file the app touches: ``--inputs``, ``--record``, ``--report``,
``--screenshot``, the player's ``settings.json`` and ``progress.json``, and the game's own
pictures, fonts and sounds. It wraps the two cores every command shares,
:func:`game.levels.reading.read_bounded` and :func:`game.levels.outputs.replace_atomically`,
in the app's sentences.

What it teaches:
  * **Check what you opened.** :func:`read_small_text` opens a path without blocking and
    asks the open descriptor what it is: a folder or a device such as ``/dev/zero`` (which
    never ends) is refused, and so is a file larger than the caller's limit, so nothing is
    read that could not fit. A named pipe, where the caller accepts one (an input script
    made by ``<(command)``), is read with time limits, so a pipe nobody writes to is a
    sentence after ten seconds instead of a hang.
  * **Write atomically.** :func:`write_atomically` writes a temporary file in the same
    folder, under a short plain name (:func:`game.levels.outputs.temporary_path`, so a real
    name of 244 characters or of bytes that are not UTF-8 still works), and renames it over
    the target: on every platform Python supports,
    :func:`os.replace` is atomic, so readers see the old file or the new one, never half.
    A temporary file left by a run that was killed mid-write is removed the next time the
    same file is read or written (:func:`remove_orphans`).
  * **Check an output before the work.** :func:`output_problem` says, before a long run,
    whether the path given for a report can be written at all (a folder, a path under a
    file, a read-only folder, a folder that is not there, a device that a rename would
    replace, a symbolic link, a file the run has read), so a run never ends by losing its
    result or an input.

Every problem is a :class:`FileProblem` whose message is one sentence naming the path.
"""

from __future__ import annotations

import contextlib
import errno
import io
import os
import re
import stat
from collections.abc import Callable
from pathlib import Path
from typing import Any

from game.levels.outputs import (
    image_suffix,
    refusal,
    replace_atomically,
    temporary_pattern,
    write_surface,
)
from game.levels.reading import FIX_REGULAR, ReadProblem, read_bounded, read_text

MAX_PATH_SHOWN_CHARS = 200  # a path longer than this is shown by its start and end
FIX_NOT_A_FILE = "give the path of a file, not a pipe, device or folder"  # not a Tiled file


class FileProblem(Exception):
    """A file that cannot be read or written; the message is one sentence for a person,
    and ``reason`` the short cause inside it (``"Permission denied"``)."""

    def __init__(self, sentence: str, reason: str = "") -> None:
        super().__init__(sentence)
        self.reason = reason or sentence


def shown(path: Path | str) -> str:
    """``path`` as a message quotes it: whole if short, else its start and its end.

    >>> shown("a/b.txt")
    'a/b.txt'
    >>> len(shown("x" * 100_000)) < 250
    True
    """
    text = str(path)
    if len(text) <= MAX_PATH_SHOWN_CHARS:
        return text
    half = MAX_PATH_SHOWN_CHARS // 2
    return f"{text[:half]}…({len(text) - 2 * half:,} characters)…{text[-half:]}"


def _cause(sentence: str) -> str:
    """The middle of ``PATH: cause — fix``."""
    return sentence.split(" — ", 1)[0].rpartition(": ")[2]


def _reason(error: OSError) -> str:
    return error.strerror or type(error).__name__


def read_small_text(path: Path, max_bytes: int, what: str, pipes: bool = False,
                    updated: bool = False) -> str:
    """The UTF-8 text of a regular file of at most ``max_bytes``; else a FileProblem.

    ``what`` names the file for the message (``"the input script"``). With ``pipes``, a
    named pipe (or a shell's ``<(command)``) is read too, with a time limit. ``updated``
    marks a file the run will write again (a save); any other file read is an input that
    no output of the run may replace. The reading itself is
    :func:`game.levels.reading.read_bounded`, the one every command reads through.
    """
    try:
        return read_text(path, max_bytes, what, pipes=pipes, updated=updated)
    except ReadProblem as problem:
        fix = FIX_NOT_A_FILE if problem.fix == FIX_REGULAR else problem.fix
        raise FileProblem(f"{shown(path)}: {problem.problem} — {fix}",
                          problem.problem.removeprefix(what).strip()) from None


def read_small_bytes(path: Path, max_bytes: int, what: str) -> bytes:
    """The bytes of a regular file of at most ``max_bytes``; else a FileProblem naming it.

    >>> import tempfile
    >>> sound = Path(tempfile.mkdtemp()) / "jump.wav"
    >>> _ = sound.write_bytes(b"RIFF")
    >>> read_small_bytes(sound, 100, "the sound")
    b'RIFF'
    """
    try:
        return read_bounded(path, max_bytes, what)
    except ReadProblem as problem:
        fix = FIX_NOT_A_FILE if problem.fix == FIX_REGULAR else problem.fix
        raise FileProblem(f"{shown(path)}: {problem.problem} — {fix}",
                          problem.problem.removeprefix(what).strip()) from None


def load_image(path: Path, max_bytes: int, what: str = "the image") -> Any:
    """A pygame Surface decoded from the file at ``path``, read through the one bounded
    open (:func:`read_small_bytes`) and handed to pygame from memory; pygame picks the
    format by the name's ending. A file pygame cannot decode is a FileProblem too."""
    import pygame

    data = read_small_bytes(path, max_bytes, what)
    try:
        return pygame.image.load(io.BytesIO(data), f"image{path.suffix.lower()}")
    except pygame.error as error:
        raise FileProblem(f"{shown(path)}: {what} cannot be decoded ({error}) — save it "
                          "again as PNG", str(error)) from None


def output_problem(path: Path) -> str | None:
    """Why ``path`` cannot take an output file, or None if it looks writable.

    Looked at before a run starts; a write can still fail later (a full disk), which
    :func:`write_atomically` reports as a FileProblem.

    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> output_problem(folder / "report.json") is None
    True
    >>> output_problem(folder)  # doctest: +ELLIPSIS
    '...: it is a folder — give the name of a file inside it'
    """
    name = shown(path)
    try:
        status = path.stat()
    except (FileNotFoundError, NotADirectoryError):
        status = None
    except (OSError, ValueError) as error:
        reason = _reason(error) if isinstance(error, OSError) else "not a usable path"
        return f"{name}: cannot be written ({reason}) — give another path"
    if status is not None and stat.S_ISDIR(status.st_mode):
        return f"{name}: it is a folder — give the name of a file inside it"
    if status is not None and not stat.S_ISREG(status.st_mode):
        return (f"{name}: it is not a regular file (a pipe or a device?), and writing would "
                "replace it — give the path of a file")
    folder = _writable_folder_problem(name, Path(os.path.abspath(path)).parent)
    refused = refusal(path)
    if folder is None and refused is not None:
        return f"{name}: it cannot be written ({refused}) — give another path"
    return folder


def folder_problem(path: Path) -> str | None:
    """Why ``path`` cannot be (or become) a folder to write files in, or None.

    >>> import tempfile
    >>> output_file = Path(tempfile.mkdtemp()) / "notes.txt"
    >>> _ = output_file.write_text("")
    >>> folder_problem(output_file.parent / "charts") is None
    True
    >>> folder_problem(output_file)  # doctest: +ELLIPSIS
    '...notes.txt: it is a file, not a folder — give the path of a folder'
    """
    name = shown(path)
    try:
        if path.exists() and not path.is_dir():
            return f"{name}: it is a file, not a folder — give the path of a folder"
    except (OSError, ValueError):
        return f"{name}: it cannot be used as a folder — give another path"
    folder = Path(os.path.abspath(path))
    if not folder.is_dir() and not folder.parent.is_dir():
        return (f"{name}: the folder {shown(folder.parent)} that would hold it does not exist "
                "— make it first, or give another path")
    return _writable_folder_problem(name, folder)


def _writable_folder_problem(name: str, folder: Path) -> str | None:
    """Why files cannot be written in ``folder`` (or, when it is missing, in the folder
    above it, where it would be made), or None."""
    while True:  # the nearest folder that exists must be a folder we may write in
        try:
            folder_status = folder.stat()
        except (FileNotFoundError, NotADirectoryError):
            folder = folder.parent
            continue
        except OSError as error:
            return f"{name}: its folder cannot be used ({_reason(error)}) — give another path"
        break
    if not stat.S_ISDIR(folder_status.st_mode):
        return (f"{name}: {shown(folder)} is a file, not a folder, so nothing can be written "
                "under it — give another path")
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"{name}: {shown(folder)} may not be written to — give a path you may write"
    return None


DISK_FULL = (errno.ENOSPC, errno.EFBIG, errno.EDQUOT)


def write_atomically(path: Path, write: Callable[[Path], None],
                     suffix: str | None = None) -> None:
    """Call ``write`` on a temporary path beside ``path``, then rename it into place, through
    the one atomic write every command uses
    (:func:`game.levels.outputs.replace_atomically`).

    A path that cannot be written (a folder, a device, a full disk, a missing folder, a
    symbolic link, a file this run reads) is a FileProblem naming ``path`` itself, and no
    temporary file is left behind. ``suffix`` is the temporary file's ending, when the
    writer picks its format by name."""
    problem = output_problem(path)
    if problem is not None:
        raise FileProblem(problem, _cause(problem))
    remove_orphans(path)  # what a killed writer of this same file left behind
    try:
        replace_atomically(path, write, suffix)
    except (OSError, ValueError) as error:
        code = error.errno if isinstance(error, OSError) else None
        reason = _reason(error) if isinstance(error, OSError) else str(error)
        fix = "free some space" if code in DISK_FULL else "give another path"
        raise FileProblem(f"{shown(path)}: could not be written ({reason}) — {fix}",
                          reason) from None


def save_image(surface: Any, path: Path) -> None:
    """Write ``surface`` (a pygame Surface) to ``path`` atomically: as PNG, or as BMP, TGA
    or JPEG when the name ends so; a write that fails (a full disk) is a FileProblem naming
    ``path``, and leaves no file behind."""
    suffix = image_suffix(path)
    write_atomically(path, lambda tmp: write_surface(surface, tmp, suffix), suffix)


def write_text_atomically(path: Path, text: str) -> None:
    """Atomically replace ``path`` with ``text`` (UTF-8).

    >>> import tempfile, pathlib
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "out.txt"
    >>> write_text_atomically(target, "hello")
    >>> target.read_text()
    'hello'
    """
    def write(tmp: Path) -> None:
        tmp.write_text(text, encoding="utf-8")

    write_atomically(path, write)


def write_bytes_atomically(path: Path, data: bytes, mode: int | None = None) -> None:
    """Atomically replace ``path`` with ``data``; ``mode`` sets its permission bits (the
    temporary file is made with the process's defaults).

    >>> import tempfile, pathlib
    >>> target = pathlib.Path(tempfile.mkdtemp()) / "out.bin"
    >>> write_bytes_atomically(target, b"\\x00\\x01")
    >>> target.read_bytes()
    b'\\x00\\x01'
    """
    def write(tmp: Path) -> None:
        tmp.write_bytes(data)
        if mode is not None:
            tmp.chmod(mode)

    write_atomically(path, write)


def _temporary_name(path: Path) -> re.Pattern[str]:
    """The names :func:`write_atomically` gives the temporary files of ``path``."""
    return temporary_pattern(path)


def _running(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (OSError, OverflowError):
        return True  # someone else's process, or a number we cannot ask about: leave it
    return True


def remove_orphans(path: Path) -> list[Path]:
    """Delete the temporary files of ``path`` left by writers that are no longer running
    (a save interrupted by a crash or a power cut); return what was removed.

    >>> import tempfile
    >>> folder = Path(tempfile.mkdtemp())
    >>> (folder / ".progress.999999999.0123abcd.json").write_text("{")
    1
    >>> [p.name for p in remove_orphans(folder / "progress.json")]
    ['.progress.999999999.0123abcd.json']
    """
    pattern = _temporary_name(path)
    removed: list[Path] = []
    try:
        candidates = [p for p in path.parent.iterdir() if pattern.fullmatch(p.name)]
    except OSError:
        return removed
    for candidate in candidates:
        match = pattern.fullmatch(candidate.name)
        if match is None or _running(int(match.group(1))):
            continue
        with contextlib.suppress(OSError):
            candidate.unlink()
            removed.append(candidate)
    return removed
