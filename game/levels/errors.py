"""The one error a level designer ever sees: file, place, what is wrong, how to fix it.

Where it sits: every reader in :mod:`game.levels` reports through a :class:`Findings`, so a
problem found anywhere, in the map, a tileset or a template, comes out in the same form.

What it teaches:
  * **Errors are for people.** A message is one sentence in the contract's form,
    ``PATH: place: message — how to fix``, and the fix is said in Tiled's own words.
  * **Output that cannot lie.** Everything a message quotes from a file (a name, a path, a
    value) goes through :func:`escaped`: a newline, a carriage return, a C0 or C1 control or
    a bidi override is shown as an escape, so a layer named ``"x\\nchecked 1 map(s): all
    playable"`` cannot print a line of its own, and a long value is cut to an excerpt.
    Warnings of one kind are counted, and only the first few of each kind are kept.
  * **Fatal or not.** Some problems stop the reading at once (a map that is not XML);
    others are recorded and the reading carries on, so the checker can list every broken
    object in one run instead of one per run. Warnings never stop anything.

>>> findings = Findings(Path("a.tmx"))
>>> findings.warn("object #4 'sign'", "class 'Sign' means nothing", "use Coin or Exit")
>>> findings.error("object #3 'Hero'", "2 Player objects", "delete one")
>>> findings.error("", "this map has no Exit", "draw one with the Rectangle tool")
>>> for line in findings.lines():
...     print(line)
a.tmx: object #4 'sign': warning: class 'Sign' means nothing — use Coin or Exit
a.tmx: object #3 'Hero': 2 Player objects — delete one
a.tmx: this map has no Exit — draw one with the Rectangle tool
>>> findings.raise_errors()
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: a.tmx: object #3 'Hero': 2 Player objects — delete one
"""

from __future__ import annotations

import unicodedata
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import NoReturn

MAX_ERRORS_PER_MAP = 20  # past this many, the rest of the map is not worth reading
MAX_QUOTED_CHARS = 40  # a value from the file is quoted at most this long
MAX_PART_CHARS = 300  # the path, the place or the problem of a message, at most
WARNINGS_SHOWN_PER_KIND = 5  # of one kind of warning, this many are kept; the rest counted


def _escape(char: str) -> str:
    if char in "\n\r\t":
        return {"\n": "\\n", "\r": "\\r", "\t": "\\t"}[char]
    code = ord(char)
    if code <= 0xFF:
        return f"\\x{code:02x}"
    return f"\\u{code:04x}" if code <= 0xFFFF else f"\\U{code:08x}"


def _unsafe(char: str) -> bool:
    """Would ``char`` move the cursor, end a line, or turn the text round on a terminal?
    Controls (C0, C1), format characters (bidi overrides and isolates, zero-width joiners),
    line and paragraph separators, surrogates and unassigned code points all would."""
    return unicodedata.category(char) in ("Cc", "Cf", "Zl", "Zp", "Cs", "Co", "Cn")


def escaped(text: str) -> str:
    """``text`` with every character that could forge or hide output shown as an escape.

    >>> print(escaped("coin\\nchecked 1 map(s): all playable"))
    coin\\nchecked 1 map(s): all playable
    >>> escaped("\\x1b[2J\\x9b\\u202etxt.exe\\r")
    '\\\\x1b[2J\\\\x9b\\\\u202etxt.exe\\\\r'
    >>> escaped("Café ✓")
    'Café ✓'
    """
    if text.isprintable():
        return text
    return "".join(_escape(char) if _unsafe(char) else char for char in text)


def excerpt(value: object) -> str:
    """A value from a file as a message quotes it: escaped and quoted if short, else its
    start and its length, so a 30 MB attribute is never echoed whole.

    >>> excerpt("12.5"), excerpt("9" * 5000)
    ("'12.5'", "'99999999999999999999...' (5,000 characters)")
    >>> excerpt("a\\nb")
    "'a\\\\nb'"
    """
    text = value if isinstance(value, str) else str(value)
    if len(text) <= MAX_QUOTED_CHARS:
        return f"'{escaped(text)}'"
    return f"'{escaped(text[:MAX_QUOTED_CHARS // 2])}...' ({len(text):,} characters)"


def clipped(text: str) -> str:
    """``text`` escaped and cut to MAX_PART_CHARS, saying so: the last guard against a
    forged line or a flood, whatever the message was built from."""
    if len(text) > MAX_PART_CHARS:
        text = f"{text[:MAX_PART_CHARS]}... ({len(text):,} characters)"
    return escaped(text)


def sentence(path: Path | str, where: str, problem: str, fix: str, warning: bool) -> str:
    where, problem = clipped(where), clipped(problem)
    place = f"{where}: " if where else ""
    label = "warning: " if warning else ""
    return f"{clipped(str(path))}: {place}{label}{problem} — {clipped(fix)}"


class Place(str):
    """Where a finding is, as its message says it (``object #3 'Hero'``), with the parts a
    program needs kept apart: the object's id, the tile, the layer's name. They are set
    from the map's structure where the finding is made, never read back out of the text,
    so a layer named ``object #2 tile (7,3)`` points at no object and no tile.

    >>> place = tile_place(7, 3, "ground")
    >>> str(place), place.tile, place.layer, place.object_id
    ("tile (7,3) in layer 'ground'", (7, 3), 'ground', None)
    >>> layer_place("object #2 tile (7,3)").object_id is None
    True
    """

    object_id: int | None
    tile: tuple[int, int] | None
    layer: str | None

    def __new__(cls, text: str, object_id: int | None = None,
                tile: tuple[int, int] | None = None, layer: str | None = None) -> Place:
        place = super().__new__(cls, text)
        place.object_id, place.tile, place.layer = object_id, tile, layer
        return place

    def __reduce__(self) -> tuple[object, ...]:  # to a worker process and back
        return Place, (str(self), self.object_id, self.tile, self.layer)


def object_place(object_id: int, name: str) -> Place:
    return Place(f"object #{object_id} '{name}'", object_id=object_id)


def layer_place(name: str) -> Place:
    return Place(f"layer '{name}'", layer=name)


def tile_place(col: int, row: int, layer: str | None = None) -> Place:
    text = f"tile ({col},{row})" + (f" in layer '{layer}'" if layer is not None else "")
    return Place(text, tile=(col, row), layer=layer)


def within(where: str, text: str) -> Place:
    """``text``, a longer place inside ``where``, keeping the parts of ``where``."""
    return Place(text, getattr(where, "object_id", None), getattr(where, "tile", None),
                 getattr(where, "layer", None))


class LevelError(Exception):
    """A map the game cannot play.

    The message is one sentence in the contract's form::

        PATH: [layer 'NAME' | object #ID 'NAME' | tile (X,Y)]: message — how to fix

    ``others`` holds the further errors found in the same map, for the checker to list.

    >>> print(LevelError(Path("a.tmx"), "object #3 'Hero'", "two Player objects",
    ...                  "delete one of them in Tiled"))
    a.tmx: object #3 'Hero': two Player objects — delete one of them in Tiled
    """

    def __init__(self, path: Path | str, where: str, problem: str, fix: str,
                 others: Sequence[LevelError] = ()) -> None:
        self.path = Path(path)
        self.where = where
        self.problem = problem
        self.fix = fix
        self.others = tuple(others)
        super().__init__(sentence(path, where, problem, fix, warning=False))

    def all_errors(self) -> tuple[LevelError, ...]:
        """This error and the others found with it, in the order they were found."""
        return (self, *self.others)


@dataclass(frozen=True)
class LevelWarning:
    """Something the game can play around, but the designer should know about."""

    path: Path
    where: str
    problem: str
    fix: str

    def __str__(self) -> str:
        return sentence(self.path, self.where, self.problem, self.fix, warning=True)


class Findings:
    """What reading one map found: warnings, and errors that need not stop the reading."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self.warnings: list[LevelWarning] = []
        self.errors: list[LevelError] = []
        self.unshown: dict[str, int] = {}  # warnings past the first few of their kind, by fix
        self.files: list[Path] = []  # every file opened for this map, in order
        self._kinds: dict[str, int] = {}
        self._opened: set[Path] = set()

    def warn(self, where: str, problem: str, fix: str) -> None:
        """Note something the game plays around (the checker prints it; exit status 0).
        Warnings of one kind (the same fix) are kept WARNINGS_SHOWN_PER_KIND at a time and
        the rest only counted, so a map that repeats one slip 400,000 times stays short."""
        seen = self._kinds[fix] = self._kinds.get(fix, 0) + 1
        if seen > WARNINGS_SHOWN_PER_KIND:
            self.unshown[fix] = seen - WARNINGS_SHOWN_PER_KIND
            return
        self.warnings.append(LevelWarning(self.path, where, problem, fix))

    def opened(self, path: Path) -> None:
        """Note a file opened for this map (what ``--watch`` watches)."""
        if path not in self._opened:
            self._opened.add(path)
            self.files.append(path)

    def error(self, where: str, problem: str, fix: str) -> None:
        """Note a problem that makes the map unplayable, and carry on reading."""
        self.errors.append(LevelError(self.path, where, problem, fix))
        if len(self.errors) >= MAX_ERRORS_PER_MAP:
            self.fail("", f"{MAX_ERRORS_PER_MAP} problems found; the rest were not checked",
                      "fix these first, then check the map again")

    def fail(self, where: str, problem: str, fix: str) -> NoReturn:
        """Stop reading: nothing after this problem can be trusted."""
        self.errors.append(LevelError(self.path, where, problem, fix))
        self.raise_errors()
        raise AssertionError("unreachable")  # pragma: no cover

    def raise_errors(self) -> None:
        """Raise the first error found, carrying the others; do nothing if there are none."""
        if self.errors:
            first, *others = self.errors
            raise LevelError(first.path, first.where, first.problem, first.fix, others)

    def lines(self) -> Iterator[str]:
        """Every finding as the checker prints it: warnings first, then errors."""
        for warning in self.warnings:
            yield str(warning)
        for fix, count in self.unshown.items():
            yield str(LevelWarning(self.path, "", f"… and {count:,} more like the warnings "
                                   "above", fix))
        for error in self.errors:
            yield str(error)
