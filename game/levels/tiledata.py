"""Decode a tile layer's ``<data>``: CSV or base64, plain, zlib or gzip, and its GID flags.

Where it sits: the loader decodes every tile layer here, checks the count and the ids, and
only then hands clean data to pytmx (which would silently accept a layer one row short,
and which does not know the hexagonal-rotation bit).

What it teaches:
  * A layer is ``width * height`` global tile ids (GIDs), row by row; 0 is an empty cell.
    Base64 data is those ids as little-endian 32-bit unsigned integers, maybe compressed.
  * The top four bits of a GID are flags, not part of the id: flipped horizontally,
    vertically, diagonally (the three combine into the eight rotations and mirrorings),
    and, on hexagonal maps, rotated by 120°. :func:`split` takes them apart.
  * Untrusted compressed data is decompressed with a size limit: a layer can only ever
    need ``4 * width * height`` bytes, so a few bytes that inflate to gigabytes stop there.

>>> split(0x80000003)
(3, 2147483648)
>>> decode_csv("1,2,\\n0,3", 4)
[1, 2, 0, 3]
"""

from __future__ import annotations

import base64
import binascii
import json
import re
import struct
import xml.etree.ElementTree as ET
import zlib

FLIPPED_H = 0x80000000
FLIPPED_V = 0x40000000
FLIPPED_D = 0x20000000
ROTATED_120 = 0x10000000  # hexagonal maps only
FLIP_BITS = FLIPPED_H | FLIPPED_V | FLIPPED_D
FLAG_BITS = FLIP_BITS | ROTATED_120
MAX_GID = 0xFFFFFFFF
MAX_GID_DIGITS = 10  # 4294967295; a longer token is out of range before it is converted

DIGITS_COMMAS_SPACES = re.compile(r"[0-9,\s]*", re.ASCII)
ZLIB_WBITS = {"zlib": zlib.MAX_WBITS, "gzip": 16 + zlib.MAX_WBITS}
FIX_FORMAT = "choose CSV or Base64 (zlib or gzip) in Map > Map Properties > Tile Layer Format"
FIX_DAMAGED = "undo the hand edit, or restore the map from a backup and save it from Tiled"


class TileDataError(ValueError):
    """The layer's data cannot be read; the message says why and ``fix`` how."""

    def __init__(self, problem: str, fix: str = FIX_DAMAGED) -> None:
        super().__init__(problem)
        self.fix = fix


def split(raw: int) -> tuple[int, int]:
    """A raw GID as ``(tile gid, flip bits)``; the 120° bit is dropped (orthogonal maps)."""
    return raw & ~FLAG_BITS, raw & FLIP_BITS


def decode_csv(text: str, count: int) -> list[int]:
    """CSV tile data; the number of entries is checked before any is converted."""
    text = text.strip().removesuffix(",")  # Tiled ends each row with a comma but the last
    found = text.count(",") + 1 if text else 0
    if found != count:
        raise TileDataError(f"the layer has {found} tiles of data where {count} belong")
    if text and DIGITS_COMMAS_SPACES.fullmatch(text):
        # The usual case. Such text in brackets is a JSON array, and the json module's C
        # parser converts it in one go, several times quicker than token by token. What it
        # refuses (an empty entry, a leading zero) is looked at token by token below.
        try:
            gids: list[int] = json.loads(f"[{text}]")
        except ValueError:
            pass
        else:
            if max(gids) <= MAX_GID:
                return gids
    gids = []
    for piece in text.split(","):
        token = piece.strip()
        if not (token.isascii() and token.isdigit()) or len(token) > MAX_GID_DIGITS or (
                int(token) > MAX_GID):
            raise TileDataError(f"the tile data holds {token[:20]!r} where a tile id belongs")
        gids.append(int(token))
    return gids


def decode_base64(text: str, compression: str, count: int) -> list[int]:
    """Base64 tile data, decompressed with a limit of the bytes ``count`` tiles need."""
    try:
        data = base64.b64decode("".join(text.split()), validate=True)
    except (binascii.Error, ValueError):
        raise TileDataError("the base64 tile data is damaged") from None
    size = 4 * count
    if compression:
        if compression == "zstd":
            raise TileDataError("the tile data is compressed with zstd, which the game "
                                "cannot read", FIX_FORMAT)
        if compression not in ZLIB_WBITS:
            raise TileDataError(f"the tile data uses an unknown compression "
                                f"{compression!r}", FIX_FORMAT)
        inflater = zlib.decompressobj(ZLIB_WBITS[compression])
        try:
            data = inflater.decompress(data, size + 1)
        except zlib.error:
            raise TileDataError(f"the {compression} tile data is damaged") from None
    if len(data) != size:
        found = f"more than {count}" if len(data) > size else f"{len(data) / 4:g}"
        raise TileDataError(f"the layer has {found} tiles of data where {count} belong")
    return list(struct.unpack(f"<{count}I", data))


def decode(data: ET.Element | None, count: int) -> list[int]:
    """The raw GIDs (flags included) of a layer's ``<data>`` element."""
    if data is None:
        raise TileDataError("the layer has no <data> element")
    if data.find("chunk") is not None:
        raise TileDataError("the layer is stored in chunks, as infinite maps are",
                            "untick Map > Map Properties > Infinite to make the map finite")
    encoding = data.get("encoding", "")
    if encoding == "csv":
        return decode_csv(data.text or "", count)
    if encoding == "base64":
        return decode_base64(data.text or "", data.get("compression", ""), count)
    if not encoding:
        raise TileDataError("the tile data uses Tiled's old XML format", FIX_FORMAT)
    raise TileDataError(f"the tile data uses an unknown encoding {encoding!r}", FIX_FORMAT)
