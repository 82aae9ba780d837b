"""Read a whole number from untrusted text: digits only, and never too many of them.

Where it sits: under every reader of a number typed by a person or found in a file: an
input script's ticks (:mod:`game.sim.inputs`), the command lines' counts
(:mod:`game.app.arguments`, ``python -m game.levels``) and the whole numbers of a map
(:mod:`game.levels.attributes`).

What it teaches: ``int()`` is not a parser for untrusted text. Python refuses to convert a
string of more than 4,300 digits (:func:`sys.set_int_max_str_digits`, a guard against a
denial of service) with a ``ValueError`` that names no file and no line; and ``int()`` also
takes ``" 7 "``, ``"+7"``, ``"7_000"`` and Arabic-Indic digits. So the text is looked at
first (ASCII digits only, at most ``max_digits`` of them once leading zeros are dropped), and
only then converted; a refusal is a :class:`NumberTextError` whose message is a phrase the
caller puts into its own sentence, with the file and the place.

>>> read_whole("0045")
45
>>> read_whole("-3", signed=True)
-3
>>> read_whole("0" * 5000 + "7")
7
>>> read_whole("9" * 5000)
Traceback (most recent call last):
    ...
game.sim.whole_numbers.NumberTextError: '99999999999999999999...' (5,000 characters) is \
longer than 18 digits
>>> read_whole("7_000")
Traceback (most recent call last):
    ...
game.sim.whole_numbers.NumberTextError: '7_000' is not a whole number
"""

from __future__ import annotations

MAX_DIGITS = 18  # longer than any count, tick or id the game has a use for
MAX_QUOTED_CHARS = 40  # a refusal quotes at most this much of the text


class NumberTextError(ValueError):
    """Text that is not a whole number, or one too long to convert; the message is a phrase
    (``"'12x' is not a whole number"``) for the caller's sentence."""


def quoted(text: str) -> str:
    """``text`` as a refusal quotes it: whole if short, else its start and its length.

    >>> quoted("12x"), quoted("9" * 50)
    ("'12x'", "'99999999999999999999...' (50 characters)")
    """
    if len(text) <= MAX_QUOTED_CHARS:
        return repr(text)
    return f"{text[:MAX_QUOTED_CHARS // 2]!r}"[:-1] + f"...' ({len(text):,} characters)"


def is_digits(text: str) -> bool:
    """Is ``text`` one or more ASCII digits and nothing else?

    >>> is_digits("042"), is_digits(""), is_digits("٣"), is_digits("+1")
    (True, False, False, False)
    """
    return text.isascii() and text.isdigit()


def read_whole(text: str, max_digits: int = MAX_DIGITS, signed: bool = False) -> int:
    """``text`` (ASCII digits, with a leading ``-`` or ``+`` when ``signed``) as an int;
    :class:`NumberTextError` if it is anything else or has more than ``max_digits``
    digits once leading zeros are dropped."""
    digits = text[1:] if signed and text[:1] in ("-", "+") else text
    if not is_digits(digits):
        raise NumberTextError(f"{quoted(text)} is not a whole number")
    significant = digits.lstrip("0") or "0"
    if len(significant) > max_digits:
        raise NumberTextError(f"{quoted(text)} is longer than {max_digits} digits")
    value = int(significant)
    return -value if text[:1] == "-" and signed else value
