"""The six places a level can be set in: each one's sky, scenery and ground colours.

Where it sits: a level names its place with the map property ``setting`` (one of
:data:`game.levels.classes.SETTINGS`); the renderer looks the :class:`Place` up here when a
level starts, draws that place's still sky and scrolling scenery behind the tiles, and
repaints the ground tiles from the tileset's own colours (the meadow's) to the place's.
``python -m game.tools.art`` draws every place's sky and scenery from the same colours, into
``assets/places/``.

What it teaches:
  * **A palette swap is a cheap new look.** One tileset is drawn once; a place is a table
    from the tileset's ground colours to its own (:func:`recolour`), applied to each tile
    picture once per level, never per frame. What hurts is never swapped: the spikes look
    the same in every place, so a player learns them once.
  * **Data, not code, for variety.** Adding a place is one more :class:`Place` value and a
    run of the art script; the renderer has no per-place branches.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import pygame

from game.levels.classes import DEFAULT_SETTING, SETTINGS

RGB = tuple[int, int, int]

# The tileset's ground colours, as art.py draws them: the meadow's grass and dirt.
GRASS_LIGHT: RGB = (164, 230, 92)
GRASS: RGB = (96, 190, 64)
GRASS_DARK: RGB = (46, 130, 60)
DIRT_LIGHT: RGB = (196, 136, 84)
DIRT: RGB = (158, 100, 62)
DIRT_DARK: RGB = (114, 68, 48)
PEBBLE: RGB = (226, 196, 156)
PEBBLE_SHADE: RGB = (184, 148, 112)
SCENERY_FLOOR_ROW = 150  # the scenery pictures' shapes end at this row: it sits on the floor
PIT_FADE_PX = 48  # below the floor line a pit fades from the place's pit colour to black
PIT_BANDS = 6  # in this many flat bands

GROUND_COLOURS: tuple[RGB, ...] = (GRASS_LIGHT, GRASS, GRASS_DARK, DIRT_LIGHT, DIRT, DIRT_DARK,
                                   PEBBLE, PEBBLE_SHADE)


@dataclass(frozen=True)
class Place:
    """How one setting looks. Colours run from light to dark within each group."""

    name: str
    sky: tuple[RGB, ...]  # the still sky, top to horizon, in flat bands
    far: tuple[RGB, RGB]  # the far scenery: lit rim, body
    near: tuple[RGB, RGB, RGB]  # the near scenery: lit rim, body, shade
    ground: tuple[RGB, ...]  # GROUND_COLOURS in this place, in the same order
    pit: RGB  # the colour a pit fades from at the floor line, down into black
    sun: RGB | None  # a sun or moon in the still sky, or none (underground)
    shapes: str  # what the scenery is: hills, cliffs, pines, caves, dunes or peaks

    def ground_swap(self) -> dict[RGB, RGB]:
        """Each tileset ground colour that changes here, with what it becomes."""
        return {base: new for base, new in zip(GROUND_COLOURS, self.ground, strict=True)
                if base != new}


PLACES: dict[str, Place] = {place.name: place for place in (
    Place("meadow",
          sky=((92, 150, 250), (108, 165, 251), (124, 180, 252), (143, 194, 253),
               (162, 208, 255), (184, 221, 255), (206, 234, 255)),
          far=((170, 216, 214), (140, 196, 200)),
          near=((124, 200, 124), (84, 168, 108), (62, 140, 98)),
          ground=GROUND_COLOURS, pit=(40, 52, 74), sun=(255, 244, 170), shapes="hills"),
    Place("cliffs",
          sky=((96, 160, 236), (118, 176, 238), (142, 192, 240), (168, 206, 240),
               (196, 220, 238), (222, 230, 226), (240, 232, 210)),
          far=((232, 214, 206), (214, 192, 186)),
          near=((226, 186, 166), (204, 160, 144), (176, 132, 122)),
          ground=((214, 220, 112), (164, 184, 72), (106, 132, 58), (232, 184, 126),
                  (200, 142, 94), (152, 100, 74), (244, 222, 184), (206, 172, 134)),
          pit=(54, 42, 58), sun=(255, 246, 200), shapes="cliffs"),
    Place("forest",
          sky=((126, 186, 196), (140, 196, 196), (156, 206, 196), (172, 214, 194),
               (188, 222, 192), (204, 230, 192), (220, 238, 196)),
          far=((118, 170, 140), (92, 148, 124)),
          near=((62, 132, 92), (40, 104, 78), (28, 80, 66)),
          ground=((120, 204, 84), (58, 156, 66), (30, 104, 62), (150, 112, 76),
                  (118, 82, 58), (84, 56, 46), (204, 182, 146), (160, 134, 106)),
          pit=(22, 40, 38), sun=(250, 250, 200), shapes="pines"),
    Place("caves",
          sky=((26, 24, 42), (30, 28, 48), (34, 32, 54), (38, 36, 60),
               (42, 40, 66), (46, 44, 72), (50, 48, 78)),
          far=((74, 70, 108), (60, 56, 92)),
          near=((96, 90, 130), (76, 72, 110), (58, 54, 90)),
          ground=((132, 214, 182), (72, 160, 146), (40, 108, 112), (140, 140, 170),
                  (104, 104, 138), (72, 70, 104), (196, 196, 214), (156, 156, 182)),
          pit=(20, 18, 34), sun=None, shapes="caves"),
    Place("dusk",
          sky=((62, 52, 120), (98, 64, 140), (142, 78, 150), (190, 96, 140),
               (228, 124, 120), (248, 160, 108), (255, 200, 120)),
          far=((150, 92, 140), (120, 72, 124)),
          near=((92, 70, 118), (70, 52, 100), (54, 40, 84)),
          ground=((176, 196, 104), (118, 150, 82), (72, 104, 76), (170, 116, 96),
                  (132, 86, 80), (96, 60, 66), (222, 184, 160), (180, 142, 128)),
          pit=(30, 22, 50), sun=(255, 224, 150), shapes="dunes"),
    Place("summit",
          sky=((118, 164, 232), (136, 178, 236), (156, 192, 240), (176, 206, 244),
               (196, 220, 248), (216, 232, 250), (234, 242, 252)),
          far=((220, 232, 246), (176, 194, 222)),
          near=((240, 246, 255), (196, 212, 236), (150, 170, 206)),
          ground=((255, 255, 255), (222, 236, 250), (168, 194, 228), (168, 168, 190),
                  (128, 128, 154), (92, 92, 120), (222, 226, 236), (180, 184, 204)),
          pit=(38, 46, 80), sun=(255, 252, 230), shapes="peaks"),
)}

if tuple(PLACES) != SETTINGS or DEFAULT_SETTING not in PLACES:  # pragma: no cover
    raise RuntimeError("game.app.places must describe exactly the settings the levels name")


def place_of(properties: Mapping[str, object]) -> Place:
    """The place a level's properties name; the default place when they name none.

    The loader has already refused a name that is not a setting, so any other value here
    means the map was not loaded through it: the default place is drawn.

    >>> place_of({"setting": "caves"}).name, place_of({}).name
    ('caves', 'meadow')
    """
    return PLACES.get(str(properties.get("setting", DEFAULT_SETTING)), PLACES[DEFAULT_SETTING])


def pit_darkness(place: Place, width: int) -> pygame.Surface:
    """What a pit shows below the level's floor line: flat bands from ``place.pit`` down to
    black over :data:`PIT_FADE_PX`, then black (the renderer fills below with black too)."""
    surface = pygame.Surface((width, PIT_FADE_PX))
    band_h = PIT_FADE_PX // PIT_BANDS
    for band in range(PIT_BANDS):
        amount = band / (PIT_BANDS - 1)
        colour = tuple(round(channel * (1 - amount)) for channel in place.pit)
        surface.fill(colour, (0, band * band_h, width, band_h))
    return surface


def recolour(image: pygame.Surface, swap: Mapping[RGB, RGB]) -> pygame.Surface:
    """A copy of ``image`` with every pixel of a colour in ``swap`` changed to its partner
    (alpha kept). ``image`` itself is returned when there is nothing to swap."""
    if not swap:
        return image
    copy = image.copy()
    pixels = pygame.PixelArray(copy)
    try:
        for old, new in swap.items():
            pixels.replace(old, new)
    finally:
        pixels.close()
    return copy
