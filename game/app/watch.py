"""``--watch``: notice when a level's files change on disk, so a save in Tiled shows at once.

Where it sits: polled by the window loop a few times a second; when the map or one of its
tilesets (or templates) has a new modification time, the window reloads the level through
:meth:`game.sim.campaign.Campaign.reload`. A save that does not load keeps the old level running
and puts the loader's message on screen until the next good save.

Polling the modification time is enough here: it needs no extra dependency, costs a few
``stat`` calls per second, and Tiled writes its files in one go.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

POLL_INTERVAL_S = 0.25  # how often the files are looked at: well inside the 1 s promise


def _sources(xml_file: Path) -> list[Path]:
    """The files one Tiled file names (tilesets, templates, images), relative to itself."""
    try:
        root = ET.parse(xml_file).getroot()
    except (OSError, ET.ParseError):
        return []
    found = []
    for node in root.iter():
        source = node.get("template") or (node.get("source") if node.tag in ("tileset", "image")
                                          else None)
        if source:
            found.append((xml_file.parent / source).resolve())
    return found


def level_files(level_path: Path) -> list[Path]:
    """The map, the tilesets and templates it names, and their images, as far as readable."""
    files = [level_path]
    for source in _sources(level_path):
        files.append(source)
        if source.suffix in (".tsx", ".tx"):
            files.extend(_sources(source))
    return list(dict.fromkeys(files))


def _stamp(path: Path) -> float | None:
    try:
        return path.stat().st_mtime_ns / 1e9
    except OSError:
        return None


@dataclass
class FileWatcher:
    """Remembers the modification times of a level's files; :meth:`poll` says if any moved."""

    level_path: Path
    _stamps: dict[Path, float | None] = field(default_factory=dict)
    _next_poll_s: float = 0.0

    def __post_init__(self) -> None:
        self._stamps = self._read()

    def _read(self) -> dict[Path, float | None]:
        return {path: _stamp(path) for path in level_files(self.level_path)}

    def poll(self, now_s: float) -> bool:
        """True once for each change seen; looks at the disk at most every POLL_INTERVAL_S."""
        if now_s < self._next_poll_s:
            return False
        self._next_poll_s = now_s + POLL_INTERVAL_S
        stamps = self._read()
        changed = stamps != self._stamps
        self._stamps = stamps
        return changed
