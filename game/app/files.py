"""Write files so that a crash or a full disk never leaves half of one behind.

Where it sits: used by ``--record``, ``--report`` and ``--screenshot``. A temporary file in
the same folder is written and flushed, then renamed over the target: on every platform
Python supports, :func:`os.replace` is atomic, so readers see the old file or the new one.
"""

from __future__ import annotations

import os
import secrets
from collections.abc import Callable
from pathlib import Path


def write_atomically(path: Path, write: Callable[[Path], None]) -> None:
    """Call ``write`` on a temporary path beside ``path``, then rename it into place."""
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_name(f".{path.stem}.{os.getpid()}.{secrets.token_hex(4)}{path.suffix}")
    try:
        write(tmp)
        os.replace(tmp, path)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


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
