"""Tiles a map loads with but a designer would not mean: what the checker says of tile layers.

Where it sits: :mod:`game.checker.designer_checks` reads a loaded map's tile layers again and
asks these three questions of each; the game itself plays every such map as it is painted.

What it teaches: the game reads a tile's class and its flip flags, never its picture or its
layer's name; where those say something else, say so, at the first tile, with how many more.

* **A OneWay tile painted upside down or on its side** (the GID's vertical flip, or its
  diagonal flip, the one of a quarter turn) still blocks only a body coming down onto its
  top: a plank flipped as a ceiling does not stop a jump from below.
* **A tile that looks like ground but has no class**: the player falls through it. "Looks
  like ground" is decided from the tile and its cell, never guessed from a name: a tile
  with no class, whose picture is opaque over its whole cell (ground is; a bush, a flower
  or a fence has see-through pixels round it), painted on a layer that holds Solid tiles,
  in a cell with a Solid tile of that same layer beside it, above or below.
* **Colliding tiles on a layer whose name says it does not collide** ("background (no
  collision)", "decor": :func:`game.checker.wall_layers.says_it_does_not_collide`): every
  tile layer collides, whatever its name.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator, Sequence
from pathlib import Path

import pygame

from game.checker.wall_layers import says_it_does_not_collide
from game.collision.shapes import TileKind
from game.levels.classes import TILE_KINDS
from game.levels.errors import Findings, LevelError, Place, layer_place, tile_place
from game.levels.header import MapHeader
from game.levels.images import load_image
from game.levels.layers import LayerNode
from game.levels.tiledata import FLIPPED_D, FLIPPED_V, split
from game.levels.tilesets import Tileset, Tilesets

Finding = tuple[str, str, str, str]  # severity, where, message, fix
TileLayerData = tuple[LayerNode, Sequence[int]]
OPAQUE_ALPHA = 254  # a pixel whose alpha is above this hides what is behind it


def _kind(raw: int, tilesets: Tilesets) -> TileKind | None:
    tile = tilesets.tile(split(raw)[0])
    return TILE_KINDS.get(tile.cls) if tile is not None else None


def _kinds(gids: Sequence[int], tilesets: Tilesets) -> dict[int, TileKind | None]:
    """What each raw GID the layer holds collides as (None: nothing), worked out once per
    id: a layer of 250,000 cells holds a few dozen."""
    return {raw: _kind(raw, tilesets) for raw in set(gids) if raw}


def _more(count: int, what: str) -> str:
    return f" ({count:,} {what} on this layer)" if count > 1 else ""


def turned_one_ways(layers: Sequence[TileLayerData], tilesets: Tilesets,
                    header: MapHeader) -> Iterator[Finding]:
    """A warning per layer that paints OneWay tiles flipped vertically or turned on a side,
    at the first such tile."""
    for layer, gids in layers:
        wrong = {raw for raw, kind in _kinds(gids, tilesets).items()
                 if kind is TileKind.ONE_WAY and split(raw)[1] & (FLIPPED_V | FLIPPED_D)}
        if not wrong:
            continue
        turned = [index for index, raw in enumerate(gids) if raw in wrong]
        row, col = divmod(turned[0], header.cols)
        how = ("turned on its side (rotated)" if split(gids[turned[0]])[1] & FLIPPED_D
               else "flipped vertically, as a ceiling")
        yield ("warning", tile_place(col, row, layer.name),
               f"this OneWay tile is painted {how}, yet a OneWay tile blocks only a body "
               f"coming down onto its top, however it is turned, so a jump from below passes "
               f"through it{_more(len(turned), 'such tiles')}",
               "paint those planks again the right way up with the Stamp Brush (Y flips the "
               "stamp vertically and Z rotates it, until it shows the plank upright), or "
               "paint a Solid tile where a ceiling should stop the player")


def _beside(index: int, header: MapHeader) -> Iterator[int]:
    row, col = divmod(index, header.cols)
    if col > 0:
        yield index - 1
    if col + 1 < header.cols:
        yield index + 1
    if row > 0:
        yield index - header.cols
    if row + 1 < header.rows:
        yield index + header.cols


class _Pictures:
    """Whether a tile's picture fills its cell, each tileset image read once (through the
    loader's own image reading: sandboxed, size-bounded), only when a tile is in question."""

    def __init__(self, path: Path) -> None:
        self.findings = Findings(path)
        self.images: dict[Path, pygame.Surface | None] = {}

    def _image(self, source: Path) -> pygame.Surface | None:
        if source not in self.images:
            try:
                self.images[source] = load_image(source, self.findings, "", "tileset image")
            except (LevelError, OSError, ValueError, pygame.error):
                self.images[source] = None
        return self.images[source]

    def opaque(self, tileset: Tileset, tile_id: int) -> bool:
        """Is every pixel of tile ``tile_id``'s picture opaque? False when it cannot be told."""
        info = tileset.tiles.get(tile_id)
        if info is not None and info.image is not None:
            picture = self._image(info.image)
        elif tileset.image is not None and tileset.columns > 0:
            sheet = self._image(tileset.image)
            if sheet is None:
                return False
            row, col = divmod(tile_id, tileset.columns)
            area = pygame.Rect(tileset.margin + col * (tileset.tile_w + tileset.spacing),
                               tileset.margin + row * (tileset.tile_h + tileset.spacing),
                               tileset.tile_w, tileset.tile_h)
            if not sheet.get_rect().contains(area):
                return False
            picture = sheet.subsurface(area)
        else:
            return False
        if picture is None or picture.get_width() == 0 or picture.get_height() == 0:
            return False
        if tileset.trans and not picture.get_flags() & pygame.SRCALPHA:
            picture = picture.copy()
            try:
                picture.set_colorkey(pygame.Color(f"#{tileset.trans.lstrip('#')}"))
            except ValueError:
                return False
        mask = pygame.mask.from_surface(picture, OPAQUE_ALPHA)
        return bool(mask.count() == picture.get_width() * picture.get_height())


def classless_ground(path: Path, layers: Sequence[TileLayerData], tilesets: Tilesets,
                     header: MapHeader) -> Iterator[Finding]:
    """A warning per layer and tile id: a tile with no class that looks like ground (see the
    module's rule), painted beside the layer's Solid tiles, at the first such cell."""
    pictures = _Pictures(path)
    looks: dict[int, bool] = {}  # gid -> its picture fills its cell
    for layer, gids in layers:
        kinds = _kinds(gids, tilesets)
        solid_ids = {raw for raw, kind in kinds.items() if kind is TileKind.SOLID}
        classless = {raw for raw, kind in kinds.items() if kind is None}
        if not solid_ids or not classless:
            continue
        for raw in classless:
            gid = split(raw)[0]
            tileset = tilesets.find(gid)
            if gid not in looks:
                looks[gid] = tileset is not None and pictures.opaque(tileset,
                                                                     gid - tileset.firstgid)
        ground_like = {raw for raw in classless if looks[split(raw)[0]]}
        if not ground_like:
            continue
        cells: dict[int, list[int]] = {}  # tile gid -> the cells it is painted in, in order
        for index, raw in enumerate(gids):
            if raw in ground_like and any(gids[near] in solid_ids
                                          for near in _beside(index, header)):
                cells.setdefault(split(raw)[0], []).append(index)
        for gid, where in cells.items():
            tileset = tilesets.find(gid)
            if tileset is None:
                continue
            row, col = divmod(where[0], header.cols)
            yield ("warning", tile_place(col, row, layer.name),
                   f"tile {gid - tileset.firstgid} of tileset '{tileset.name}' looks like "
                   "ground (its picture fills the cell) and is painted beside this layer's "
                   "Solid tiles, but it has no class, so the player falls or walks through "
                   f"it{_more(len(where), 'such cells')}",
                   "give the tile the class Solid in the Tileset Editor (its Type in Tiled "
                   "1.8), or paint those cells with a Solid tile; backdrop tiles belong on a "
                   "layer of their own")


def colliding_quiet_layers(layers: Sequence[TileLayerData], tilesets: Tilesets,
                           header: MapHeader) -> Iterator[Finding]:
    """A warning per layer whose name says it does not collide but which holds Solid,
    OneWay or Hazard tiles, naming how many of each and the first one's tile."""
    for layer, gids in layers:
        if not says_it_does_not_collide(layer.name):
            continue
        colliding = {raw: kind for raw, kind in _kinds(gids, tilesets).items()
                     if kind is not None}
        if not colliding:
            continue
        kinds: Counter[TileKind] = Counter()
        for raw, count in Counter(gids).items():
            if raw in colliding:
                kinds[colliding[raw]] += count
        first = next(index for index, raw in enumerate(gids) if raw in colliding)
        row, col = divmod(first, header.cols)
        held = ", ".join(f"{count:,} {kind.value}" for kind, count in
                         sorted(kinds.items(), key=lambda item: list(TileKind).index(item[0])))
        where = layer_place(layer.name)
        yield ("warning", Place(where, tile=(col, row), layer=layer.name),
               f"its name says it does not collide, yet it holds tiles that do ({held}; the "
               f"first at tile ({col},{row})), and the game collides with the Solid, OneWay "
               "and Hazard tiles of every tile layer, whatever its name",
               "paint that layer with tiles that have no class (decoration), and the walls, "
               "planks and spikes on the ground layer; or rename the layer if they are meant "
               "to collide")
