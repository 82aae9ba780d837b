"""``--watch``: notice when a level's files change on disk, so a save in Tiled shows at once.

Where it sits: polled by the window loop a few times a second; when the map or one of the
files it uses (tilesets, templates, images) has a new modification time, the window reloads
the level through :meth:`game.sim.campaign.Campaign.reload`. A save that does not load keeps
the old level running and puts the loader's message on screen until the next good save.

Which files: exactly those the loader opened the last time it read the map
(:func:`game.levels.loader.files_read`), through its sandbox and its checks; the watcher
never parses a file or follows a path itself, so it cannot be led to a file outside the
level's folder, and it only ever calls ``stat`` (which never waits, even on a pipe). The
list is read again after every change seen, so a tileset added in Tiled is watched next.

Polling the modification time is enough here: it needs no extra dependency, costs a few
``stat`` calls per second, and Tiled writes its files in one go.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from game.levels.loader import files_read

POLL_INTERVAL_S = 0.25  # how often the files are looked at: well inside the 1 s promise


def level_files(level_path: Path) -> list[Path]:
    """The map, then every file the loader opened while reading it, as far as it got."""
    return list(files_read(level_path))


def _stamp(path: Path) -> float | None:
    try:
        return path.stat().st_mtime_ns / 1e9
    except (OSError, ValueError):
        return None


@dataclass
class FileWatcher:
    """Remembers the modification times of a level's files; :meth:`poll` says if any moved."""

    level_path: Path
    _files: list[Path] = field(default_factory=list)
    _stamps: dict[Path, float | None] = field(default_factory=dict)
    _next_poll_s: float = 0.0

    def __post_init__(self) -> None:
        self._files = level_files(self.level_path)
        self._stamps = self._read()

    def _read(self) -> dict[Path, float | None]:
        return {path: _stamp(path) for path in self._files}

    def poll(self, now_s: float) -> bool:
        """True once for each change seen; looks at the disk at most every POLL_INTERVAL_S."""
        if now_s < self._next_poll_s:
            return False
        self._next_poll_s = now_s + POLL_INTERVAL_S
        stamps = self._read()
        changed = stamps != self._stamps
        if changed:  # the map may name other files now: ask the loader again
            self._files = level_files(self.level_path)
            stamps = self._read()
        self._stamps = stamps
        return changed
