"""The game's pixel font: every glyph drawn by hand on a grid, written out as a BDF font.

Where it sits: with the other tools that make assets (``python -m game.tools.art`` writes
``assets/font.bdf`` and ``assets/font-big.bdf`` through :func:`write_fonts`). The game loads
them with plain ``pygame.font.Font`` (FreeType reads BDF bitmap fonts), so the HUD, the menus
and the debug overlay draw text exactly as before, only crisp at 1x.

What it teaches:
  * **A bitmap font is a table of small pictures** plus three numbers per glyph: its box, where
    it sits on the baseline, and how far the pen moves after it (the advance).
  * **Even spacing comes from the advance, not the picture.** Each glyph is drawn as narrow as
    it needs to be and the pen always moves one empty column past it, so "Debug" and "shapes"
    read as words, never as "Deb ug" or "sha pes".
  * **Letters that look alike are drawn apart on purpose**: a slashed zero against a round O,
    a flagged 1 against a tailed l and a serifed I, an open s against a barred e, and a 6 whose
    top is open against a closed 8. ``tests/test_font.py`` renders every glyph through pygame
    and fails when two differ by fewer than :data:`MIN_GLYPH_DIFFERENCE_PX` pixels.

Each glyph is rows of ``#`` (ink) and ``.`` (paper). Rows 0-6 stand on the baseline (capitals
and digits fill all seven, lowercase letters start at row 2); rows 7-8 are descenders.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from pathlib import Path

from game.app.files import write_text_atomically

ASCENT_PX = 7  # rows above the baseline: capitals and digits are this tall
DESCENT_PX = 2  # rows below it: g j p q y , ;
LETTER_GAP_PX = 1  # the empty column after every glyph
SPACE_W_PX = 2  # a space is this wide, plus the letter gap
BIG_SCALE = 2  # the title font is the same drawing with each pixel doubled
MIN_GLYPH_DIFFERENCE_PX = 2  # any two glyphs differ by at least this many pixels
FONT_NAME = "TileHopper"

G = tuple[str, ...]

GLYPHS: Mapping[str, G] = {
    # Capitals: 5 wide (I and L narrower), 7 tall.
    "A": (".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"),
    "B": ("####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."),
    "C": (".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."),
    "D": ("###..", "#..#.", "#...#", "#...#", "#...#", "#..#.", "###.."),
    "E": ("#####", "#....", "#....", "####.", "#....", "#....", "#####"),
    "F": ("#####", "#....", "#....", "####.", "#....", "#....", "#...."),
    "G": (".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".####"),
    "H": ("#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"),
    "I": ("###", ".#.", ".#.", ".#.", ".#.", ".#.", "###"),
    "J": ("..###", "...#.", "...#.", "...#.", "#..#.", "#..#.", ".##.."),
    "K": ("#...#", "#..#.", "#.#..", "##...", "#.#..", "#..#.", "#...#"),
    "L": ("#...", "#...", "#...", "#...", "#...", "#...", "####"),
    "M": ("#...#", "##.##", "#.#.#", "#.#.#", "#...#", "#...#", "#...#"),
    "N": ("#...#", "##..#", "#.#.#", "#..##", "#...#", "#...#", "#...#"),
    "O": (".###.", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."),
    "P": ("####.", "#...#", "#...#", "####.", "#....", "#....", "#...."),
    "Q": (".###.", "#...#", "#...#", "#...#", "#.#.#", "#..#.", ".##.#"),
    "R": ("####.", "#...#", "#...#", "####.", "#.#..", "#..#.", "#...#"),
    "S": (".####", "#....", "#....", ".###.", "....#", "....#", "####."),
    "T": ("#####", "..#..", "..#..", "..#..", "..#..", "..#..", "..#.."),
    "U": ("#...#", "#...#", "#...#", "#...#", "#...#", "#...#", ".###."),
    "V": ("#...#", "#...#", "#...#", "#...#", "#...#", ".#.#.", "..#.."),
    "W": ("#...#", "#...#", "#...#", "#.#.#", "#.#.#", "##.##", "#...#"),
    "X": ("#...#", "#...#", ".#.#.", "..#..", ".#.#.", "#...#", "#...#"),
    "Y": ("#...#", "#...#", ".#.#.", "..#..", "..#..", "..#..", "..#.."),
    "Z": ("#####", "....#", "...#.", "..#..", ".#...", "#....", "#####"),
    # Lowercase: x-height 5 (rows 2-6), ascenders to row 0, descenders to row 8.
    "a": ("....", "....", ".##.", "...#", ".###", "#..#", ".###"),
    "b": ("#...", "#...", "###.", "#..#", "#..#", "#..#", "###."),
    "c": ("....", "....", ".###", "#...", "#...", "#...", ".###"),
    "d": ("...#", "...#", ".###", "#..#", "#..#", "#..#", ".###"),
    "e": ("....", "....", ".##.", "#..#", "####", "#...", ".###"),
    "f": (".##", "#..", "###", "#..", "#..", "#..", "#.."),
    "g": ("....", "....", ".###", "#..#", "#..#", "#..#", ".###", "...#", ".##."),
    "h": ("#...", "#...", "###.", "#..#", "#..#", "#..#", "#..#"),
    "i": (".#.", "...", "##.", ".#.", ".#.", ".#.", "###"),
    "j": ("..#", "...", ".##", "..#", "..#", "..#", "..#", "#.#", ".#."),
    "k": ("#...", "#...", "#..#", "#.#.", "##..", "#.#.", "#..#"),
    "l": ("#.", "#.", "#.", "#.", "#.", "#.", ".#"),
    "m": (".....", ".....", "##.#.", "#.#.#", "#.#.#", "#.#.#", "#.#.#"),
    "n": ("....", "....", "###.", "#..#", "#..#", "#..#", "#..#"),
    "o": ("....", "....", ".##.", "#..#", "#..#", "#..#", ".##."),
    "p": ("....", "....", "###.", "#..#", "#..#", "#..#", "###.", "#...", "#..."),
    "q": ("....", "....", ".###", "#..#", "#..#", "#..#", ".###", "...#", "...#"),
    "r": ("....", "....", "#.##", "##..", "#...", "#...", "#..."),
    "s": ("....", "....", ".###", "#...", ".##.", "...#", "###."),
    "t": (".#.", ".#.", "###", ".#.", ".#.", ".#.", "..#"),
    "u": ("....", "....", "#..#", "#..#", "#..#", "#..#", ".###"),
    "v": (".....", ".....", "#...#", "#...#", ".#.#.", ".#.#.", "..#.."),
    "w": (".....", ".....", "#...#", "#...#", "#.#.#", "#.#.#", ".#.#."),
    "x": (".....", ".....", "#...#", ".#.#.", "..#..", ".#.#.", "#...#"),
    "y": ("....", "....", "#..#", "#..#", "#..#", "#..#", ".###", "...#", ".##."),
    "z": ("....", "....", "####", "...#", ".##.", "#...", "####"),
    # Digits: 5 wide but the 1; a slashed zero, a 6 and a 9 open where the 8 is closed.
    "0": (".###.", "#...#", "#..##", "#.#.#", "##..#", "#...#", ".###."),
    "1": (".#.", "##.", ".#.", ".#.", ".#.", ".#.", "###"),
    "2": (".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"),
    "3": (".###.", "#...#", "....#", "..##.", "....#", "#...#", ".###."),
    "4": ("...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."),
    "5": ("#####", "#....", "####.", "....#", "....#", "#...#", ".###."),
    "6": ("..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."),
    "7": ("#####", "....#", "...#.", "..#..", "..#..", "..#..", "..#.."),
    "8": (".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."),
    "9": (".###.", "#...#", "#...#", ".####", "....#", "...#.", ".##.."),
    # Punctuation and signs.
    "!": ("#", "#", "#", "#", "#", ".", "#"),
    '"': ("#.#", "#.#"),
    "#": (".....", ".#.#.", "#####", ".#.#.", "#####", ".#.#."),
    "$": ("..#..", ".####", "#.#..", ".###.", "..#.#", "####.", "..#.."),
    "%": ("##..#", "##.#.", "...#.", "..#..", ".#...", ".#.##", "#..##"),
    "&": (".##..", "#..#.", "#.#..", ".#...", "#.#.#", "#..#.", ".##.#"),
    "'": ("#", "#"),
    "(": (".#", "#.", "#.", "#.", "#.", "#.", ".#"),
    ")": ("#.", ".#", ".#", ".#", ".#", ".#", "#."),
    "*": (".....", "..#..", "#.#.#", ".###.", "#.#.#", "..#..", "....."),
    "+": (".....", "..#..", "..#..", "#####", "..#..", "..#.."),
    ",": ("..", "..", "..", "..", "..", ".#", ".#", "#."),
    "-": ("....", "....", "....", "####"),
    ".": (".", ".", ".", ".", ".", ".", "#"),
    "/": ("....#", "...#.", "...#.", "..#..", ".#...", ".#...", "#...."),
    ":": (".", ".", "#", ".", ".", "#"),
    ";": ("..", "..", ".#", "..", "..", ".#", ".#", "#."),
    "<": ("...#", "..#.", ".#..", "#...", ".#..", "..#.", "...#"),
    "=": ("....", "....", "####", "....", "####"),
    ">": ("#...", ".#..", "..#.", "...#", "..#.", ".#..", "#..."),
    "?": (".###.", "#...#", "....#", "...#.", "..#..", ".....", "..#.."),
    "@": (".###.", "#...#", "#.###", "#.#.#", "#.###", "#....", ".####"),
    "[": ("##", "#.", "#.", "#.", "#.", "#.", "##"),
    "\\": ("#....", ".#...", ".#...", "..#..", "...#.", "...#.", "....#"),
    "]": ("##", ".#", ".#", ".#", ".#", ".#", "##"),
    "^": ("..#..", ".#.#.", "#...#"),
    "_": ("....", "....", "....", "....", "....", "....", "....", "####"),
    "`": ("#.", ".#"),
    "{": (".##", ".#.", ".#.", "#..", ".#.", ".#.", ".##"),
    "|": ("#", "#", "#", "#", "#", "#", "#", "#", "#"),
    "}": ("##.", ".#.", ".#.", "..#", ".#.", ".#.", "##."),
    "~": (".....", ".....", ".....", ".##.#", "#.##."),
    "\N{EM DASH}": ("......", "......", "......", "######"),
    "\N{HORIZONTAL ELLIPSIS}": (".....", ".....", ".....", ".....", ".....", ".....", "#.#.#"),
    "\N{DEGREE SIGN}": (".#.", "#.#", ".#."),
    "\N{SUPERSCRIPT TWO}": ("##.", "..#", ".#.", "###"),
    "\N{MIDDLE DOT}": (".", ".", ".", "#"),
    "\N{MULTIPLICATION SIGN}": ("...", "...", "...", "#.#", ".#.", "#.#"),
}
# Drawn for any character the font lacks, so nothing vanishes without a trace.
MISSING: G = ("####", "#..#", "#..#", "#..#", "#..#", "#..#", "####")


def glyph_width(rows: Sequence[str]) -> int:
    """How many columns a glyph's picture takes (its rows may be of any equal width)."""
    return max((len(row) for row in rows), default=0)


def advance(character: str) -> int:
    """How far the pen moves after ``character``: its width and one empty column.

    >>> advance("l"), advance("m"), advance(" ")
    (3, 6, 3)
    """
    if character == " ":
        return SPACE_W_PX + LETTER_GAP_PX
    return glyph_width(GLYPHS.get(character, MISSING)) + LETTER_GAP_PX


def _bdf_glyph(name: str, code: int, rows: Sequence[str], scale: int) -> list[str]:
    """One glyph's BDF record, its pixels each ``scale`` x ``scale``."""
    width = glyph_width(rows) * scale
    height = len(rows) * scale
    top_gap = (ASCENT_PX - len(rows)) * scale  # the glyph's bottom above the baseline
    bitmap: list[str] = []
    for row in rows:
        bits = "".join(("1" if ink == "#" else "0") * scale for ink in row.ljust(len(rows[0]),
                                                                                 "."))
        padded = bits.ljust(-(-max(1, len(bits)) // 8) * 8, "0")
        bitmap += [f"{int(padded, 2):0{len(padded) // 4}X}"] * scale
    step = (width + LETTER_GAP_PX * scale) if rows else (SPACE_W_PX + LETTER_GAP_PX) * scale
    return [f"STARTCHAR {name}", f"ENCODING {code}", f"SWIDTH {step * 1000 // 9} 0",
            f"DWIDTH {step} 0", f"BBX {width} {height} 0 {top_gap}", "BITMAP", *bitmap,
            "ENDCHAR"]


def bdf_text(scale: int = 1) -> str:
    """The whole font as BDF 2.1 text, each pixel drawn ``scale`` times as large."""
    ascent, descent = ASCENT_PX * scale, DESCENT_PX * scale
    size = ascent + descent
    chars: list[list[str]] = [_bdf_glyph("missing", 0, MISSING, scale),
                              _bdf_glyph("space", ord(" "), (), scale)]
    chars += [_bdf_glyph(f"U+{ord(ch):04X}", ord(ch), rows, scale)
              for ch, rows in GLYPHS.items()]
    widest = max(glyph_width(rows) for rows in GLYPHS.values()) * scale
    header = ["STARTFONT 2.1",
              f"FONT -tilehopper-{FONT_NAME}-medium-r-normal--{size}-{size * 10}-75-75-p-"
              f"{widest * 10}-iso10646-1",
              f"SIZE {size} 75 75", f"FONTBOUNDINGBOX {widest} {size} 0 {-descent}",
              "STARTPROPERTIES 4", f"FONT_ASCENT {ascent}", f"FONT_DESCENT {descent}",
              "DEFAULT_CHAR 0", 'COPYRIGHT "CC0 1.0, drawn by game/tools/pixel_font.py"',
              "ENDPROPERTIES", f"CHARS {len(chars)}"]
    return "\n".join([*header, *(line for glyph in chars for line in glyph), "ENDFONT"]) + "\n"


def font_size_px(scale: int = 1) -> int:
    """The pixel size to ask ``pygame.font.Font`` for, to get the font at ``scale``."""
    return (ASCENT_PX + DESCENT_PX) * scale


def write_fonts(folder: Path) -> list[Path]:
    """Write ``font.bdf`` (1x) and ``font-big.bdf`` (each pixel doubled) into ``folder``."""
    written = []
    for name, scale in (("font.bdf", 1), ("font-big.bdf", BIG_SCALE)):
        path = folder / name
        write_text_atomically(path, bdf_text(scale))  # ASCII: the same bytes in UTF-8
        written.append(path)
    return written
