"""Read numbers from XML attributes, refusing junk, NaN and infinity with a sentence.

Where it sits: under every reader in :mod:`game.levels`. A Tiled file is text; a hand edit,
a merge conflict or another tool can leave ``x="nan"``, ``width="1e400"`` or ``id="3.5"``
in it, and Python's ``float()`` accepts the first two without complaint.

What it teaches: parse once, at the edge, into the type the game needs (a finite float, a
whole number within limits), and say which attribute was wrong and where. A number is a
number at any length: leading zeros are dropped before the text's length is judged, and a
whole number is read by :func:`game.sim.whole_numbers.read_whole`, never by ``int()`` of the
text (which raises on 4,300 digits), so ``firstgid`` of 5,000 digits is out of range, said
in a sentence.

>>> from pathlib import Path
>>> from game.levels.errors import Findings, excerpt
>>> findings = Findings(Path("a.tmx"))
>>> number({"x": "12.5"}, "x", findings, "object #1 ''")
12.5
>>> whole({}, "spacing", findings, "tileset 't'", default=0)
0
>>> number({"x": "nan"}, "x", findings, "object #1 ''")
Traceback (most recent call last):
    ...
game.levels.errors.LevelError: a.tmx: object #1 '': x is 'nan', not a finite number — \
move or resize it in Tiled, or type an ordinary number in its Properties
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from game.levels.errors import Findings, excerpt
from game.sim.whole_numbers import NumberTextError, is_digits, read_whole

MAX_NUMBER_CHARS = 400  # longer than any number Tiled writes
FIX_NUMBER = "move or resize it in Tiled, or type an ordinary number in its Properties"


def parse_number(text: str) -> float | None:
    """``text`` as a finite float, or None.

    >>> parse_number(" 3 "), parse_number("inf"), parse_number("1e400"), parse_number("x")
    (3.0, None, None, None)
    >>> parse_number("0" * 5000 + "2.5"), parse_number("1" * 5000)
    (2.5, None)
    """
    if len(text) > MAX_NUMBER_CHARS:  # float() of a megabyte of digits takes its time
        sign, body = ("-", text.strip()[1:]) if text.strip()[:1] == "-" else ("", text.strip())
        text = sign + (body.lstrip("0") or "0")
        if len(text) > MAX_NUMBER_CHARS:  # a finite float has at most 309 digits before "."
            return None
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def number(attributes: Mapping[str, str], name: str, findings: Findings, where: str,
           default: float | None = None) -> float:
    """Attribute ``name`` as a finite float; ``default`` when absent (None: it is required)."""
    text = attributes.get(name)
    if text is None:
        if default is None:
            findings.fail(where, f"the {name} attribute is missing",
                          "open the file in Tiled and save it again")
        return default
    value = parse_number(text)
    if value is None:
        findings.fail(where, f"{name} is {excerpt(text)}, not a finite number", FIX_NUMBER)
    return value


def whole(attributes: Mapping[str, str], name: str, findings: Findings, where: str,
          default: int | None = None, low: int = 0, high: int = 2**31 - 1) -> int:
    """Attribute ``name`` as a whole number in ``low..high``; ``default`` when absent.
    Digits (as Tiled writes them) are read as a whole number whatever their length; other
    text (``"3.0"``) as a number that must be whole."""
    text = attributes.get(name)
    digits = text.strip() if text is not None else ""
    if is_digits(digits.removeprefix("-")):
        try:
            value: float = read_whole(digits, signed=True)
        except NumberTextError:  # more digits than any limit: out of range, said below
            value = math.inf
    else:
        value = number(attributes, name, findings, where,
                       None if default is None else float(default))
    if not (low <= value <= high and value == int(value)):
        findings.fail(where, f"{name} is {excerpt(text)}, not a whole number "
                      f"from {low} to {high}",
                      "open the file in Tiled and save it again, or undo the hand edit")
    return int(value)
