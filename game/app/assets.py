"""Load the game's art and fonts once, and cut the sprite strips into frames.

Where it sits: called once by the app after the display mode is set, before the first
frame. The renderer, the HUD, the screens and the debug overlay receive the :class:`Assets`
it returns and only read it; nothing here runs per frame.

What it teaches:
  * **A sprite strip is one image, many frames.** :func:`strip` cuts it with
    ``Surface.subsurface``: each frame is a window onto the sheet's pixels, so nothing is
    copied and the frame order in ``assets/README.md`` is the only contract.
  * **``convert_alpha`` after ``set_mode``.** A loaded PNG is converted once to the display's
    pixel format so every blit is a plain copy rather than a per-pixel conversion. It needs
    a display mode to exist, which is why :func:`load_assets` must run after
    ``pygame.display.set_mode`` (a 1x1 window or ``SDL_VIDEODRIVER=dummy`` is enough).
  * **Paths are found from this file, not from the working directory,** so the game starts
    the same from any folder; each file is read through the one bounded open
    (:func:`game.app.files.load_image`, :func:`game.app.files.read_small_bytes`) and handed
    to pygame from memory.
"""

from __future__ import annotations

import io
from dataclasses import dataclass, field

import pygame

from game.app.files import FileProblem, load_image, read_small_bytes
from game.levels.classes import SETTINGS
from game.levels.shipped import ASSETS_DIR

ASSETS = ASSETS_DIR

SPRITE_PX = 16  # player and enemy frames are 16x16
COIN_PX = 8  # coin frames are 8x8
CHECKPOINT_SIZE_PX = (16, 32)  # checkpoint frames: a lantern on a post
MAX_ASSET_BYTES = 16 * 1024 * 1024  # each picture or font of the game's own: a few kB

# The game's own pixel font (game.tools.pixel_font), drawn at 1x: 7 px capitals, 2 px
# descenders. The title font is the same drawing with every pixel doubled.
FONT_FILE, FONT_PX = "font.bdf", 9  # the height each is drawn at: ascent and descent
BIG_FONT_FILE, BIG_FONT_PX = "font-big.bdf", 18


@dataclass(frozen=True)
class Assets:
    """Every image and font the drawing code uses, ready to blit."""

    player_frames: list[pygame.Surface]  # 0-1 idle, 2-5 run, 6 jump, 7 fall; facing right
    enemy_frames: list[pygame.Surface]  # 0-1 walk, 2 squashed, 3-4 hopper; facing right
    coin_frames: list[pygame.Surface]  # spin: face, narrow, edge, narrow
    exit_image: pygame.Surface  # 16x32 flag, its pole's foot at the bottom centre
    checkpoint_frames: list[pygame.Surface]  # 16x32 lantern on its post: unlit, then lit
    sky: pygame.Surface  # 320x180, opaque: the sky and its one sun, drawn still
    background: pygame.Surface  # 320x180 clouds and hills over clear sky; tiles horizontally
    heart: pygame.Surface  # 8x8 HUD life
    font: pygame.font.Font  # HUD and menu text
    big_font: pygame.font.Font  # titles
    small_font: pygame.font.Font  # the debug overlay
    # Each place's (still sky, scrolling scenery), by setting name; see game.app.places.
    places: dict[str, tuple[pygame.Surface, pygame.Surface]] = field(default_factory=dict)


def strip(sheet: pygame.Surface, frame_w: int, frame_h: int) -> list[pygame.Surface]:
    """Cut a horizontal strip into ``frame_w`` x ``frame_h`` frames, left to right.

    The frames are subsurfaces: they share the sheet's pixels.

    >>> sheet = pygame.Surface((48, 16))
    >>> [f.get_size() for f in strip(sheet, 16, 16)]
    [(16, 16), (16, 16), (16, 16)]
    >>> strip(pygame.Surface((40, 16)), 16, 16)
    Traceback (most recent call last):
        ...
    ValueError: a 40x16 strip does not split into 16x16 frames
    """
    width, height = sheet.get_size()
    if frame_w <= 0 or frame_h <= 0 or width % frame_w or height < frame_h:
        raise ValueError(f"a {width}x{height} strip does not split into {frame_w}x{frame_h} frames")
    return [sheet.subsurface((left, 0, frame_w, frame_h))
            for left in range(0, width, frame_w)]


def _image(name: str) -> pygame.Surface:
    """Load ``assets/<name>`` converted for fast blitting, or say which file is wrong."""
    path = ASSETS / name
    try:
        image: pygame.Surface = load_image(path, MAX_ASSET_BYTES, "the picture")
        return image.convert_alpha()
    except FileProblem as error:
        raise RuntimeError(f"cannot load {path}: {error} (regenerate with python -m game.tools.art)"
                           ) from None


def _font(name: str, size_px: int) -> pygame.font.Font:
    """Load the bitmap font ``assets/<name>`` at the one size it is drawn in."""
    path = ASSETS / name
    try:  # pygame reads the font from memory: the file goes through the one bounded open
        return pygame.font.Font(io.BytesIO(read_small_bytes(path, MAX_ASSET_BYTES, "the font")),
                                size_px)
    except (pygame.error, FileProblem, OSError) as error:
        raise RuntimeError(f"cannot load {path}: {error} (regenerate with "
                           "python -m game.tools.art)") from None


def load_assets() -> Assets:
    """Load every image and font.

    Requires ``pygame.display.set_mode`` to have been called first (``convert_alpha`` needs
    the display's pixel format); initialises ``pygame.font`` if it is not yet.
    """
    if not pygame.font.get_init():
        pygame.font.init()
    return Assets(
        player_frames=strip(_image("player.png"), SPRITE_PX, SPRITE_PX),
        enemy_frames=strip(_image("enemy.png"), SPRITE_PX, SPRITE_PX),
        coin_frames=strip(_image("coin.png"), COIN_PX, COIN_PX),
        exit_image=_image("exit.png"),
        checkpoint_frames=strip(_image("checkpoint.png"), *CHECKPOINT_SIZE_PX),
        sky=_image("sky.png"),
        background=_image("background.png"),
        heart=_image("heart.png"),
        font=_font(FONT_FILE, FONT_PX),
        big_font=_font(BIG_FONT_FILE, BIG_FONT_PX),
        small_font=_font(FONT_FILE, FONT_PX),
        places={name: (_image(f"places/{name}-sky.png"), _image(f"places/{name}-scenery.png"))
                for name in SETTINGS},
    )
