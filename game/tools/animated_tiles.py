"""Draw the animated tiles and write their Tiled tileset, with the animation in it.

Run from the repository root::

    python -m game.tools.animated_tiles

This (re)writes ``assets/banner.png`` (four 16x16 frames of a pennant waving on a pole)
and ``assets/banner.tsx``, a Tiled tileset whose tile 0 plays the four frames in a loop
(Tiled's Tile Animation Editor writes the same ``<animation>`` element). A level that paints
tile 0 shows the pennant waving, in Tiled and in the game alike.

What it teaches: a Tiled tile animation is data in the tileset, frame tile ids and
durations in milliseconds; the art is an ordinary strip. Everything is drawn with plain
pygame calls on off-screen surfaces, deterministically, so it can be released as CC0.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pygame

from game.app.files import save_image, write_text_atomically
from game.levels.closed_output import quiet_when_output_closes

ASSETS = Path(__file__).resolve().parents[2] / "assets"
TILE = 16
FRAMES = 4
FRAME_MS = 150  # each frame shows this long: the whole wave takes 0.6 s
POLE = (90, 62, 40)
POLE_LIGHT = (150, 110, 70)
CLOTH = (240, 196, 60)
CLOTH_DARK = (200, 140, 30)
OUTLINE = (38, 30, 56)
CLOTH_ROWS = range(2, 8)  # the pennant hangs from the top of the pole, 6 px deep
CLOTH_LENGTH_PX = 10
WAVE_PX = 1.5  # how far the cloth ripples up and down


def draw_frame(phase: float) -> pygame.Surface:
    """One frame: a pole on the ground and a pennant rippling at ``phase`` (radians)."""
    tile = pygame.Surface((TILE, TILE), pygame.SRCALPHA)
    pygame.draw.rect(tile, OUTLINE, (2, 1, 3, TILE - 1))
    pygame.draw.line(tile, POLE, (3, 2), (3, TILE - 1))
    pygame.draw.line(tile, POLE_LIGHT, (3, 2), (3, 5))
    for step in range(CLOTH_LENGTH_PX):
        x = 5 + step
        lift = round(WAVE_PX * math.sin(phase + step * 0.7) * step / CLOTH_LENGTH_PX)
        taper = step * (len(CLOTH_ROWS) - 1) // (2 * CLOTH_LENGTH_PX)
        top, bottom = CLOTH_ROWS.start + taper + lift, CLOTH_ROWS.stop - 1 - taper + lift
        pygame.draw.line(tile, OUTLINE, (x, top - 1), (x, bottom + 1))
        pygame.draw.line(tile, CLOTH, (x, top), (x, bottom))
        if (step + round(phase * 2)) % 4 == 0:
            pygame.draw.line(tile, CLOTH_DARK, (x, top), (x, bottom))
    return tile


def draw_strip() -> pygame.Surface:
    strip = pygame.Surface((TILE * FRAMES, TILE), pygame.SRCALPHA)
    for frame in range(FRAMES):
        strip.blit(draw_frame(2 * math.pi * frame / FRAMES), (frame * TILE, 0))
    return strip


def tileset_tsx() -> str:
    """The Tiled 1.8 tileset of the strip; tile 0 plays every frame."""
    frames = "\n".join(f'   <frame tileid="{frame}" duration="{FRAME_MS}"/>'
                       for frame in range(FRAMES))
    return (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        f'<tileset version="1.8" tiledversion="1.8.2" name="banner" tilewidth="{TILE}" '
        f'tileheight="{TILE}" tilecount="{FRAMES}" columns="{FRAMES}">\n'
        f' <image source="banner.png" width="{TILE * FRAMES}" height="{TILE}"/>\n'
        ' <tile id="0">\n  <animation>\n'
        f"{frames}\n"
        "  </animation>\n </tile>\n</tileset>\n")


def main() -> None:
    save_image(draw_strip(), ASSETS / "banner.png")
    write_text_atomically(ASSETS / "banner.tsx", tileset_tsx())


if __name__ == "__main__":
    sys.exit(quiet_when_output_closes(main))
