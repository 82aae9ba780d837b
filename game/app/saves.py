"""The player's progress, and how the game keeps its files safe in the user's data folder.

Where it sits: beside the app, outside the simulation. Around each tick the window lets an
:class:`Attempt` watch the campaign; when it reports a :class:`Finish`, the window records
it in the :class:`Progress` and saves. :mod:`game.app.settings` stores its file the same way,
through :class:`JsonFile`.

What it teaches:
  * **Each platform has a usual place for an app's data** (:func:`data_dir`):
    ``$XDG_DATA_HOME`` or ``~/.local/share`` on Linux, ``~/Library/Application Support`` on
    macOS, ``%APPDATA%`` on Windows; never the working directory.
  * **Write atomically.** A save is written to a temporary file and renamed over the old one
    (:func:`game.app.files.write_text_atomically`), so a crash or a full disk mid-write leaves
    the old save, never half of a new one.
  * **Progress belongs to the campaign's own maps**, known by their files, not their names
    (:class:`CampaignMaps`): a downloaded ``01-first-steps.tmx`` played with ``--level``
    is another map that happens to share a name, so finishing it (or the level its
    ``next_level`` leads to) never changes a best time nor unlocks a level.
  * **Never wipe what you could not read.** A file that is not valid JSON, holds values of
    the wrong type, or cannot be opened is renamed aside
    (``progress.json.corrupt-20250131-142501``) before anything can overwrite it, and the
    caller gets one sentence saying so. The game starts with what it could read.

>>> p = Progress()
>>> p.complete_level("01-first-steps.tmx", ticks=900, coins=3, next_level="02-over-the-gaps.tmx")
True
>>> p.complete_level("01-first-steps.tmx", ticks=950, coins=5, next_level=None)
True
>>> p.best_ticks, p.best_coins, sorted(p.unlocked)
({'01-first-steps.tmx': 900}, {'01-first-steps.tmx': 5}, ['02-over-the-gaps.tmx'])
"""

from __future__ import annotations

import json
import os
import sys
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from datetime import datetime
from pathlib import Path
from typing import Any, NamedTuple, TypeVar

from game.app.files import FileProblem, read_small_text, remove_orphans, write_text_atomically
from game.sim.campaign import Campaign
from game.sim.inputs import NOTHING, Actions, Recorder
from game.sim.level import Level
from game.sim.world import Event, EventKind, World

APP_DIR_NAME = "tile-hopper"
PROGRESS_FILE = "progress.json"
PROGRESS_VERSION = 1  # written into the file; bump it if its layout ever changes
BACKUP_STAMP = "%Y%m%d-%H%M%S"  # progress.json.corrupt-20250131-142501
MAX_SAVE_BYTES = 1024 * 1024  # settings and progress are a few kB; more is not ours
MAX_PROBLEMS_SHOWN = 3  # a report names at most this many bad entries, then counts the rest
MAX_QUOTED_CHARS = 40  # a bad value is quoted back at most this long
MAX_COUNT = 10**12  # a tick count or coin count larger than this is not a real one

T = TypeVar("T")
Parse = Callable[[Any], tuple[T, list[str]]]


def data_dir(environ: Mapping[str, str] = os.environ, platform: str = sys.platform,
             home: Path | None = None) -> Path:
    """The folder where the game keeps settings and progress on this machine.

    >>> data_dir({"XDG_DATA_HOME": "/data"}, "linux", Path("/home/ann")).as_posix()
    '/data/tile-hopper'
    >>> data_dir({}, "linux", Path("/home/ann")).as_posix()
    '/home/ann/.local/share/tile-hopper'
    >>> data_dir({}, "darwin", Path("/Users/ann")).as_posix()
    '/Users/ann/Library/Application Support/tile-hopper'
    >>> data_dir({"APPDATA": "C:/Users/ann/AppData/Roaming"}, "win32").as_posix()
    'C:/Users/ann/AppData/Roaming/tile-hopper'
    """
    home = home or Path.home()
    xdg = environ.get("XDG_DATA_HOME", "")
    if xdg and Path(xdg).is_absolute():  # the XDG spec says to ignore a relative path
        return Path(xdg) / APP_DIR_NAME
    if platform == "win32":
        appdata = environ.get("APPDATA")
        return (Path(appdata) if appdata else home / "AppData" / "Roaming") / APP_DIR_NAME
    if platform == "darwin":
        return home / "Library" / "Application Support" / APP_DIR_NAME
    return home / ".local" / "share" / APP_DIR_NAME


def summarise(problems: list[str]) -> str:
    """Join a list of problems into one clause, naming at most a few.

    >>> summarise(["a", "b", "c", "d", "e"])
    'a; b; c; and 2 more'
    """
    shown = "; ".join(problems[:MAX_PROBLEMS_SHOWN])
    rest = len(problems) - MAX_PROBLEMS_SHOWN
    return f"{shown}; and {rest} more" if rest > 0 else shown


@dataclass
class JsonFile:
    """One JSON file in the data folder: read forgivingly, written atomically, never wiped
    unread. Methods return a sentence for the player instead of raising."""

    path: Path
    # Set when the file could not be read *and* could not be moved aside: writing over it
    # would destroy it, so :meth:`save` refuses and repeats this.
    blocked: str | None = None

    def load(self, parse: Parse[T], default: Callable[[], T]) -> tuple[T, str | None]:
        """Read and ``parse`` the file; on any problem keep it aside and explain.

        ``parse`` turns the decoded JSON into a value and a list of what it had to drop or
        replace. No file yet is not a problem: the result is ``default()``. Temporary files
        left beside it by a save that was interrupted are removed first.
        """
        remove_orphans(self.path)
        try:
            if not self.path.exists() and not self.path.is_symlink():
                return default(), None
            text = read_small_text(self.path, MAX_SAVE_BYTES, "the file", updated=True)
        except FileProblem as error:
            if not self.path.is_file():  # a folder or a pipe: not ours to move aside
                self.blocked = f"{error}; nothing will be saved over it this session."
                return default(), self.blocked
            return default(), self.keep_aside(f"could not be read ({error.reason})")
        except OSError as error:
            return default(), self.keep_aside(f"could not be read ({_reason(error)})")
        try:
            data = json.loads(text)
        except json.JSONDecodeError as error:
            return default(), self.keep_aside(
                f"is not valid JSON (line {error.lineno}: {error.msg})")
        except (ValueError, RecursionError) as error:  # 5,000-digit numbers, deep nesting
            what = ("nests too deeply" if isinstance(error, RecursionError)
                    else "holds a number too long to read")
            return default(), self.keep_aside(f"is not usable JSON (it {what})")
        value, problems = parse(data)
        if problems:
            return value, self.keep_aside(f"could not be used in full ({summarise(problems)})")
        return value, None

    def keep_aside(self, what_is_wrong: str) -> str:
        """Rename the file to a timestamped backup; return the sentence for the player."""
        stem = f"{self.path.name}.corrupt-{datetime.now().strftime(BACKUP_STAMP)}"
        backup, number = self.path.with_name(stem), 1
        while backup.exists():  # two in the same second: number the later ones
            number += 1
            backup = self.path.with_name(f"{stem}-{number}")
        try:
            os.replace(self.path, backup)
        except OSError as error:
            self.blocked = (f"{self.path} {what_is_wrong} and could not be moved aside "
                            f"({_reason(error)}), so it is left untouched and nothing will "
                            "be saved over it this session.")
            return self.blocked
        return f"{self.path} {what_is_wrong}; the original was kept as {backup.name}."

    def save(self, data: object) -> str | None:
        """Write ``data`` as JSON, atomically; return a sentence if it could not be saved."""
        if self.blocked is not None:
            return self.blocked
        try:
            self.path.parent.mkdir(parents=True, exist_ok=True)  # the game's own data folder
        except OSError as error:
            return f"Could not save {self.path} ({_reason(error)}); the previous file is intact."
        try:
            write_text_atomically(self.path, json.dumps(data, indent=2, sort_keys=True) + "\n")
        except FileProblem as error:
            return f"Could not save {self.path} ({error.reason}); the previous file is intact."
        return None


def quoted(value: object) -> str:
    """A decoded JSON value as a message quotes it: as JSON, cut short if long.

    >>> quoted("fast"), quoted([1, 2]), quoted("x" * 500)
    ('"fast"', '[1, 2]', '"xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx... (502 characters)')
    """
    try:
        text = json.dumps(value)
    except (ValueError, RecursionError):
        return "a value too large to show"
    if len(text) <= MAX_QUOTED_CHARS:
        return text
    return f"{text[:MAX_QUOTED_CHARS - 2]}... ({len(text):,} characters)"


def _reason(error: OSError | UnicodeDecodeError) -> str:
    if isinstance(error, UnicodeDecodeError):
        return "it is not UTF-8 text"
    return error.strerror or str(error)


def progress_file(directory: Path | None = None) -> JsonFile:
    """The progress file, in :func:`data_dir` unless another folder is given."""
    return JsonFile((directory or data_dir()) / PROGRESS_FILE)


@dataclass
class Progress:
    """What the player has achieved, by level file name (``"02-over-the-gaps.tmx"``)."""

    unlocked: set[str] = field(default_factory=set)  # levels the player may start
    best_ticks: dict[str, int] = field(default_factory=dict)  # fastest finish, in 1/60 s ticks
    best_coins: dict[str, int] = field(default_factory=dict)  # most coins in one finish

    def complete_level(self, level: str, ticks: int, coins: int,
                       next_level: str | None, *, timed: bool = True) -> bool:
        """Record a finished level and unlock the next; True if it set a best. A finish not
        ``timed`` (an assist was on) sets no best time."""
        if next_level is not None:
            self.unlocked.add(next_level)
        faster = timed and (level not in self.best_ticks or ticks < self.best_ticks[level])
        richer = coins > self.best_coins.get(level, -1)
        if faster:
            self.best_ticks[level] = ticks
        if richer:
            self.best_coins[level] = coins
        return faster or richer

    def record(self, finish: Finish) -> bool:
        """:meth:`complete_level` for a finish reported by :class:`Attempt`. A finish with an
        assist on unlocks the next level and counts its coins, but sets no best time."""
        return self.complete_level(finish.level, finish.ticks, finish.coins, finish.next_level,
                                   timed=not finish.assisted)

    def to_json(self) -> dict[str, Any]:
        return {"version": PROGRESS_VERSION, "unlocked": sorted(self.unlocked),
                "best_ticks": self.best_ticks, "best_coins": self.best_coins}

    @classmethod
    def from_json(cls, data: Any) -> tuple[Progress, list[str]]:
        """Rebuild progress from decoded JSON, keeping every entry that makes sense.

        >>> p, problems = Progress.from_json({"unlocked": ["b.tmx", 7],
        ...                                   "best_ticks": {"a.tmx": 900, "b.tmx": "fast"}})
        >>> sorted(p.unlocked), p.best_ticks, problems
        (['b.tmx'], {'a.tmx': 900}, ['unlocked: 7 is not a level file name', \
'best_ticks: "b.tmx" has "fast", not a whole number from 0 to 1,000,000,000,000'])
        """
        if not isinstance(data, dict):
            return cls(), [f"it holds {_json_type(data)}, not an object: nothing was kept"]
        problems: list[str] = []
        progress = cls()
        unlocked = data.get("unlocked", [])
        if isinstance(unlocked, list):
            for name in unlocked:
                if isinstance(name, str) and name:
                    progress.unlocked.add(name)
                else:
                    problems.append(f"unlocked: {quoted(name)} is not a level file name")
        else:
            problems.append("unlocked is not a list of level file names")
        for key, table in (("best_ticks", progress.best_ticks),
                           ("best_coins", progress.best_coins)):
            entries = data.get(key, {})
            if not isinstance(entries, dict):
                problems.append(f"{key} is not an object of level names and numbers")
                continue
            for level, number in entries.items():
                if _is_count(number):
                    table[level] = number
                else:
                    problems.append(f"{key}: {quoted(level)} has {quoted(number)}, "
                                    f"not a whole number from 0 to {MAX_COUNT:,}")
        return progress, problems


class Finish(NamedTuple):
    """A level completed: its file name, the time it took, the coins taken on the way."""

    level: str
    ticks: int
    coins: int
    next_level: str | None
    assisted: bool = False  # an assist was on: no best time is kept, and no ghost


@dataclass
class Attempt:
    """The try at a level now in play, watched around each tick, to time a finish.

    A restart, a reload or a new run each make a new :class:`World`; :meth:`before_tick`
    notices the new world and starts timing afresh, so callers need no hook for each.
    """

    world: World | None = None
    started_tick: int = 0  # campaign.ticks when the attempt's first tick began
    coins: int = 0
    inputs: Recorder = field(default_factory=Recorder)  # this attempt's, from its first tick

    def before_tick(self, campaign: Campaign) -> None:
        if campaign.world is not self.world:
            self.world, self.started_tick, self.coins = campaign.world, campaign.ticks, 0
            self.inputs = Recorder()

    def after_tick(self, campaign: Campaign, events: Sequence[Event],
                   held: Actions = NOTHING) -> Finish | None:
        """Count the tick's coins and keep what was ``held`` (in ``inputs``, for the ghost);
        at the exit, return the finish (the world has moved on)."""
        self.inputs.observe(campaign.ticks - 1 - self.started_tick, held)
        self.coins += sum(1 for event in events if event.kind is EventKind.COIN)
        if self.world is None or not any(event.kind is EventKind.EXIT for event in events):
            return None
        level = self.world.level
        following = level.next_level
        assisted = bool(campaign.results) and campaign.results[-1].assisted
        return Finish(level.path.name, campaign.ticks - self.started_tick, self.coins,
                      None if following is None else following.name, assisted)


@dataclass(frozen=True)
class CampaignMaps:
    """The campaign's own map files, by their real paths (links followed, ``..`` folded
    away): the only maps whose finishes the progress keeps.

    >>> import tempfile
    >>> shipped = Path(tempfile.mkdtemp()) / "01-first-steps.tmx"
    >>> maps = CampaignMaps.of([shipped])
    >>> maps.holds(shipped), maps.holds(Path(tempfile.mkdtemp()) / "01-first-steps.tmx")
    (True, False)
    """

    real_paths: frozenset[str]

    @classmethod
    def of(cls, paths: Iterable[Path]) -> CampaignMaps:
        return cls(frozenset(real for path in paths if (real := _real(path)) is not None))

    def holds(self, path: Path | None) -> bool:
        """True when ``path`` is one of the campaign's map files, by whatever name."""
        real = None if path is None else _real(path)
        return real is not None and real in self.real_paths

    def kept(self, finish: Finish, level: Level) -> Finish | None:
        """What of ``finish`` (of ``level``) the progress may keep: nothing when the map
        finished is not one of the campaign's files; no unlock when the map its
        ``next_level`` names is not one of them."""
        if not self.holds(level.path):
            return None
        if not self.holds(level.next_level):
            return finish._replace(next_level=None)
        return finish


def _real(path: Path) -> str | None:
    try:
        return os.path.realpath(path)
    except (OSError, ValueError):  # a name the system refuses is no campaign map
        return None


def _json_type(value: object) -> str:
    """What a decoded JSON value is, in JSON's words: ``a list``, ``a string``, ..."""
    if isinstance(value, bool):
        return "true or false"
    kinds = {list: "a list", str: "a string", int: "a number", float: "a number",
             dict: "an object", type(None): "null"}
    return kinds.get(type(value), type(value).__name__)


def _is_count(value: object) -> bool:
    """A whole number from 0 to MAX_COUNT; ``True`` is not a number here, though Python
    says so."""
    return isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= MAX_COUNT
