"""An output is never an input, nor another output: asked before the run starts.

Where it sits: :mod:`game.app.run` asks :func:`clashes` once the first level has loaded and
before its first tick. The one atomic write (:func:`game.levels.outputs.replace_atomically`)
refuses at write time to replace a file the run has read; asking first means a
``--screenshot`` named like the map, or a ``--record`` named like the ``--inputs`` script it
replays, costs one sentence instead of a run whose output is then lost.

What it teaches:
  * **Same file, not same name.** Two paths name one file when the system says so:
    ``os.stat``'s device and inode for a file that is there (whatever link, ``..`` or
    spelling leads to it), the real path (:func:`os.path.realpath`) for one not yet made.
  * **The inputs are all the files the level uses**: the map, its tilesets, templates and
    images, as the loader opened them (:func:`game.levels.loader.files_read`), and the map
    its ``next_level`` names, which the run may load later.

>>> import tempfile
>>> folder = Path(tempfile.mkdtemp())
>>> script = folder / "win.txt"
>>> _ = script.write_text("0 +right\\n")
>>> clashes([("record", folder / "." / "win.txt")], [("the input script (--inputs)", script)])
... # doctest: +ELLIPSIS
['.../win.txt: --record names the input script (--inputs), a file this run reads — give the \
output another name']
>>> clashes([("report", folder / "a.json"), ("record", folder / "a.json")], [])
... # doctest: +ELLIPSIS
['.../a.json: --report and --record name the same file — give each output its own name']
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from game.app.files import shown
from game.levels.errors import escaped
from game.levels.loader import files_read
from game.sim.level import Level

Named = tuple[str, Path]  # what a path is (an option's name, or what the run reads it as)


def file_key(path: Path) -> tuple[object, ...] | None:
    """What makes ``path`` the file it is: its device and inode when it is there, else its
    real path; None for a name the system refuses (the write will say so)."""
    try:
        status = os.stat(path)
    except (FileNotFoundError, NotADirectoryError):
        try:
            return ("path", os.path.realpath(path))
        except (OSError, ValueError):
            return None
    except (OSError, ValueError):
        return None
    return ("file", status.st_dev, status.st_ino)


def level_inputs(level: Level, given: bool) -> list[Named]:
    """The files a run of ``level`` reads: the map, every file it uses, and the map its
    ``next_level`` names; ``given`` when the map came from ``--level``."""
    name = "the level (--level)" if given else "the first level of the campaign"
    map_file, *used = files_read(level.path)
    inputs: list[Named] = [(name, map_file), *(("a file the level uses", path) for path in used)]
    if level.next_level is not None:
        inputs.append(("the level that follows it (next_level)", level.next_level))
    return inputs


def clashes(outputs: Sequence[Named], inputs: Sequence[Named]) -> list[str]:
    """One sentence for each output (an option's name and its path) that is one of the
    ``inputs`` or an output named before it; empty when every output has a file of its own."""
    keys = [(what, key) for what, path in inputs if (key := file_key(path)) is not None]
    problems: list[str] = []
    seen: list[tuple[str, tuple[object, ...]]] = []
    for option, path in outputs:
        key = file_key(path)
        if key is None:
            continue
        name = escaped(shown(path))
        read = next((what for what, input_key in keys if input_key == key), None)
        earlier = next((other for other, other_key in seen if other_key == key), None)
        if read is not None:
            problems.append(f"{name}: --{option} names {read}, a file this run reads — "
                            "give the output another name")
        elif earlier is not None:
            problems.append(f"{name}: --{earlier} and --{option} name the same file — give "
                            "each output its own name")
        seen.append((option, key))
    return problems
