"""The pixel font: every glyph renders, no two look alike, and the spacing is even."""

from __future__ import annotations

import itertools
import string

import pygame
import pytest

from game.app.assets import ASSETS, BIG_FONT_FILE, BIG_FONT_PX, FONT_FILE, FONT_PX
from game.tools import pixel_font
from game.tools.pixel_font import GLYPHS, LETTER_GAP_PX, MIN_GLYPH_DIFFERENCE_PX, advance

LETTERS_AND_DIGITS = set(string.ascii_letters + string.digits)
LOOK_ALIKES = [("s", "e"), ("6", "8"), ("0", "O"), ("1", "l"), ("1", "I"), ("l", "I"),
               ("5", "S"), ("2", "Z"), ("8", "B")]
LOOK_ALIKE_DIFFERENCE_PX = 3  # the pairs people misread differ by more than the minimum


@pytest.fixture(scope="module")
def font() -> pygame.font.Font:
    pygame.font.init()
    return pygame.font.Font(str(ASSETS / FONT_FILE), FONT_PX)


def ink(font: pygame.font.Font, text: str) -> set[tuple[int, int]]:
    """The pixels ``text`` inks, rendered as the game renders it."""
    surface = font.render(text, False, (255, 255, 255), (0, 0, 0))
    return {(x, y) for x in range(surface.get_width()) for y in range(surface.get_height())
            if surface.get_at((x, y)).r > 127}


def test_the_shipped_fonts_are_what_the_art_code_draws() -> None:
    assert (ASSETS / FONT_FILE).read_text(encoding="ascii") == pixel_font.bdf_text(1)
    assert (ASSETS / BIG_FONT_FILE).read_text(encoding="ascii") == pixel_font.bdf_text(
        pixel_font.BIG_SCALE)
    sizes = (pixel_font.font_size_px(1), pixel_font.font_size_px(pixel_font.BIG_SCALE))
    assert sizes == (FONT_PX, BIG_FONT_PX)


def test_every_glyph_renders_its_drawing_and_no_two_are_too_alike(
        font: pygame.font.Font) -> None:
    pictures = {ch: ink(font, ch) for ch in GLYPHS}
    for ch, rows in GLYPHS.items():
        drawn = {(x, y) for y, row in enumerate(rows) for x, c in enumerate(row) if c == "#"}
        top = min(y for _, y in pictures[ch]) - min(y for _, y in drawn)
        assert pictures[ch] == {(x, y + top) for x, y in drawn}, f"{ch!r} renders wrong"
    for a, b in itertools.combinations(pictures, 2):
        differ = len(pictures[a] ^ pictures[b])
        least = MIN_GLYPH_DIFFERENCE_PX if {a, b} <= LETTERS_AND_DIGITS else 1
        assert differ >= least, f"{a!r} and {b!r} differ by only {differ} pixels"
    for a, b in LOOK_ALIKES:
        assert len(pictures[a] ^ pictures[b]) >= LOOK_ALIKE_DIFFERENCE_PX, (a, b)


@pytest.mark.parametrize("word", ["walls", "Debug", "shapes", "brute", "Pause", "0123456789"])
def test_letters_are_spaced_evenly_one_empty_column_apart(font: pygame.font.Font,
                                                          word: str) -> None:
    assert font.size(word)[0] == sum(advance(ch) for ch in word)
    columns = {x for x, _ in ink(font, word)}
    x = 0
    for ch in word:
        width = advance(ch) - LETTER_GAP_PX
        assert x + width - 1 in columns and x + width not in columns, (word, ch)
        x += advance(ch)


def test_a_character_the_font_lacks_shows_a_box_not_nothing(font: pygame.font.Font) -> None:
    assert len(ink(font, "\N{SNOWMAN}")) == len(ink(font, "\N{REPLACEMENT CHARACTER}")) > 0
