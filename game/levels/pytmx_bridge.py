"""What pytmx is given: a clean copy of the map that holds only what pytmx is good at.

Where it sits: the last step of loading. By now the map, its tilesets and its tile data
have been read and checked; pytmx is asked for the two things it does well, numbering the
tiles as they are used (each flipped variant gets its own id) and cutting, flipping and
converting the tile images, and for nothing else.

What it teaches: wrap a library you cannot fix. pytmx 3.32 trips over a dozen real-world
things (templates, ``class=``, fractional offsets, tile collision shapes in embedded
tilesets, the hexagonal flag, list properties, zstd, images without a size...). Rather
than patch it, the loader builds a small document without any of them: tilesets with
absolute image paths and no properties or collision shapes, and the tile layers, in
document order, as CSV of ids already checked. So pytmx only ever sees input it handles,
and anything it still raises becomes a :class:`~game.levels.errors.LevelError`.

>>> header = MapHeader(cols=2, rows=1, tile_w=16, tile_h=16, background=None)
>>> layer = LayerNode(ET.Element("layer"), "ground", (0.0, 0.0), 1.0, True)
>>> ET.tostring(clean_map(header, Tilesets([]), [(layer, [1, 0x80000001])]), "unicode")
'<map version="1.8" orientation="orthogonal" renderorder="right-down" width="2" \
height="1" tilewidth="16" tileheight="16" infinite="0"><layer name="ground" width="2" \
height="1"><data encoding="csv">1,2147483649</data></layer></map>'
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, NamedTuple

import pygame
from pytmx.util_pygame import handle_transformation

from game.levels.errors import Findings, LevelError, excerpt
from game.levels.header import MapHeader
from game.levels.images import load_image
from game.levels.layers import LayerNode
from game.levels.tilesets import Tileset, Tilesets
from game.sim.level import Animation, TileLayer

FIX_IMAGES = "re-save the tileset image as PNG and pick it again in Tiled"


def _tileset_element(tileset: Tileset) -> ET.Element:
    node = ET.Element("tileset", {
        "firstgid": str(tileset.firstgid), "name": tileset.name,
        "tilewidth": str(tileset.tile_w), "tileheight": str(tileset.tile_h),
        "spacing": str(tileset.spacing), "margin": str(tileset.margin),
        "tilecount": str(tileset.tilecount), "columns": str(tileset.columns)})
    if tileset.image is not None:
        image = {"source": str(tileset.image), "width": str(tileset.image_size[0]),
                 "height": str(tileset.image_size[1])}
        if tileset.trans:
            image["trans"] = tileset.trans
        ET.SubElement(node, "image", image)
    for tile_id, tile in sorted(tileset.tiles.items()):
        if tile.image is None and not tile.animation:
            continue
        tile_node = ET.SubElement(node, "tile", {"id": str(tile_id)})
        if tile.image is not None:
            ET.SubElement(tile_node, "image", {
                "source": str(tile.image), "width": str(tile.image_size[0]),
                "height": str(tile.image_size[1])})
        if tile.animation:
            frames = ET.SubElement(tile_node, "animation")
            for frame_id, duration_ms in tile.animation:
                ET.SubElement(frames, "frame", {"tileid": str(frame_id),
                                                "duration": str(duration_ms)})
    return node


def clean_map(header: MapHeader, tilesets: Tilesets,
              layers: Sequence[tuple[LayerNode, Sequence[int]]]) -> ET.Element:
    """The document pytmx parses: grid, tilesets and tile layers as CSV, nothing more."""
    root = ET.Element("map", {
        "version": "1.8", "orientation": "orthogonal", "renderorder": "right-down",
        "width": str(header.cols), "height": str(header.rows),
        "tilewidth": str(header.tile_w), "tileheight": str(header.tile_h), "infinite": "0"})
    root.extend(_tileset_element(tileset) for tileset in tilesets.all)
    for layer, gids in layers:
        node = ET.SubElement(root, "layer", {"name": layer.name, "width": str(header.cols),
                                             "height": str(header.rows)})
        ET.SubElement(node, "data", {"encoding": "csv"}).text = ",".join(map(str, gids))
    return root


def _image_loader(findings: Findings) -> Callable[..., Any]:
    """pytmx's image loader, but every image comes through :func:`load_image`: read by the
    sandbox's open, measured and decoded from the same bytes (and decoded once, if the
    checks already did), never opened by pytmx from a path."""
    from pytmx.util_pygame import smart_convert

    def load(filename: str, colorkey: Any, **kwargs: Any) -> Callable[..., pygame.Surface]:
        image = load_image(Path(filename), findings, "", "tile image")
        key = pygame.Color(f"#{colorkey}") if colorkey else None
        pixelalpha = kwargs.get("pixelalpha", True)

        def cut(rect: Any = None, flags: Any = None) -> pygame.Surface:
            tile = image.subsurface(rect) if rect else image.copy()
            if flags:
                tile = handle_transformation(tile, flags)
            converted: pygame.Surface = smart_convert(tile, key, pixelalpha)
            return converted

        return cut

    return load


def parse(path: Path, document: ET.Element, images: bool, findings: Findings) -> Any:
    """pytmx's TiledMap of the clean document; with ``images``, tile images are loaded
    (which needs ``pygame.display.set_mode`` first)."""
    import pytmx  # here, not at the top: only a load that gets this far pays for it
    import pytmx.pytmx
    import pytmx.util_pygame

    loader = _image_loader(findings) if images else pytmx.pytmx.default_image_loader
    try:
        tmx = pytmx.TiledMap(image_loader=loader, allow_duplicate_names=True)
        tmx.filename = str(path)  # pytmx joins image paths to its folder; ours are absolute
        tmx.parse_xml(document)
    except LevelError:  # an image refused by load_image: its own sentence
        raise
    except (FileNotFoundError, pygame.error, ValueError) as error:
        findings.fail("", f"a tile image cannot be loaded ({excerpt(str(error))})", FIX_IMAGES)
    except Exception as error:  # pytmx raises bare Exceptions
        findings.fail("", f"pytmx could not read the map ({type(error).__name__}: "
                      f"{excerpt(str(error))})",
                      "open the map in Tiled and save it again")
    return tmx


def drawn_layers(tmx: Any, layers: Sequence[LayerNode], colliding: Sequence[bool],
                 ) -> list[TileLayer]:
    """The tile layers to draw, with pytmx's ids (the keys of the level's tile images).
    A layer that collides is drawn where it collides: with no offset and no parallax."""
    return [TileLayer(layer.name, tuple(tuple(row) for row in parsed.data), layer.opacity,
                      (0.0, 0.0) if collides else layer.offset,
                      (1.0, 1.0) if collides else layer.parallax)
            for layer, parsed, collides in zip(layers, tmx.layers, colliding, strict=True)]


class Animated(NamedTuple):
    """The animations of the tiles the layers use, in pytmx's ids, and the frames that must
    be shown turned: each under a new id (after all of pytmx's), with its frame and turn."""

    animations: dict[int, Animation]
    turned: dict[int, tuple[int, Any]]


def _turned(flags: Any) -> bool:
    return flags is not None and bool(flags.flipped_horizontally or flags.flipped_vertically
                                      or flags.flipped_diagonally)


def _used(layers: Sequence[TileLayer]) -> set[int]:
    return {gid for layer in layers for row in layer.gids for gid in row if gid}


def animated_tiles(tmx: Any, layers: Sequence[TileLayer]) -> Animated:
    """The animation of every animated tile id the layers use: (frame id, ms) per frame.

    pytmx gives a flipped or rotated tile an id of its own, with its image turned, but its
    animation lists the plain frames: shown as they are, a mirrored torch would flicker the
    wrong way round. So each frame of a turned tile gets a new id, for its frame turned the
    same way (:func:`tile_images` draws it).
    """
    turn_of = {gid: flags for variants in tmx.gidmap.values() for gid, flags in variants}
    animations: dict[int, Animation] = {}
    new_ids: dict[tuple[int, Any], int] = {}
    for gid in sorted(_used(layers)):
        properties = tmx.get_tile_properties_by_gid(gid) or {}
        turn = turn_of.get(gid)
        frames = []
        for frame in properties.get("frames", ()):
            frame_gid = int(frame.gid)
            if _turned(turn):
                frame_gid = new_ids.setdefault((frame_gid, turn), len(tmx.images) + len(new_ids))
            frames.append((frame_gid, int(frame.duration)))
        if frames:
            animations[gid] = tuple(frames)
    return Animated(animations, {new_id: key for key, new_id in new_ids.items()})


def tile_images(tmx: Any, layers: Sequence[TileLayer], animated: Animated,
                ) -> dict[int, pygame.Surface]:
    """The image of every tile id the layers use, and of every frame of their animations
    (a turned frame turned as its tile is)."""
    used = _used(layers) | {frame for frames in animated.animations.values()
                            for frame, _ in frames}
    images: dict[int, pygame.Surface] = {}
    for gid in used:
        source, turn = animated.turned.get(gid, (gid, None))
        image = tmx.images[source] if source < len(tmx.images) else None
        if isinstance(image, pygame.Surface):
            images[gid] = image if turn is None else handle_transformation(image, turn)
    return images
