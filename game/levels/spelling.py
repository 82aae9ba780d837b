"""Did you mean ...? A class name close to one the game knows is taken for a typing slip.

Where it sits: the tileset reader (:mod:`game.levels.tilesets`) and the object checks
(:mod:`game.levels.entities`) ask it about every class the game does not know. A slip
(``Soild`` for ``Solid``) is an error that names the class meant, because the level cannot
be played as drawn: a ground row of ``Soild`` tiles lets the player fall through. A name
nothing like the game's (``Decor``) is a designer's own note and only a warning.

What it teaches: ``difflib.get_close_matches`` ranks by ``SequenceMatcher.ratio()``, twice
the matching characters over the total; :data:`CLOSE_RATIO` is where a slip ends and a
different word begins (``Plyer``/``Player`` 0.91, ``Soild``/``Solid`` 0.8, ``Sign``/``Coin``
0.5).

>>> meant("Soild", ["Solid", "OneWay", "Hazard"])
'Solid'
>>> meant("solid", ["Solid", "OneWay", "Hazard"]) is None   # letter case is no slip
True
>>> meant("Decor", ["Player", "Coin", "Enemy", "Exit"]) is None
True
"""

from __future__ import annotations

import difflib
from collections.abc import Sequence

CLOSE_RATIO = 0.75  # how alike two names must be for one to be a slip for the other


def meant(name: str, known: Sequence[str]) -> str | None:
    """The known class ``name`` is probably a slip for, or None (also when it is one)."""
    lowered = {k.lower(): k for k in known}
    if not name or name.lower() in lowered:
        return None
    close = difflib.get_close_matches(name.lower(), list(lowered), n=1, cutoff=CLOSE_RATIO)
    return lowered[close[0]] if close else None
