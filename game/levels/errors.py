"""The one error a level designer ever sees: file, place, what is wrong, how to fix it."""

from __future__ import annotations

from pathlib import Path


class LevelError(Exception):
    """A map the game cannot play.

    The message is one sentence in the contract's form::

        PATH: [layer 'NAME' | object #ID 'NAME' | tile (X,Y)]: message — how to fix

    >>> print(LevelError(Path("a.tmx"), "object #3 'Hero'", "two Player objects",
    ...                  "delete one of them in Tiled"))
    a.tmx: object #3 'Hero': two Player objects — delete one of them in Tiled
    """

    def __init__(self, path: Path | str, where: str, problem: str, fix: str) -> None:
        self.path = Path(path)
        self.where = where
        self.problem = problem
        self.fix = fix
        place = f"{where}: " if where else ""
        super().__init__(f"{path}: {place}{problem} — {fix}")
