"""Check that an image a map uses is there, is small enough, and decodes, without a display.

Where it sits: the checker and windowed runs look at every tileset image, tile image and
image-layer image through :func:`check_image`; headless runs skip it and never open an
image file.

What it teaches:
  * **The decoder's answer is the one checked.** The file is read once (through
    :mod:`game.levels.reading`), measured, and those same bytes are decoded, typed as the
    format that was measured; a GIF is walked frame by frame the way SDL_image walks it
    (stray bytes skipped), so a frame larger than its screen is seen before it is decoded.
  * **Read the size from the header, before decoding.** Every image format the game
    accepts (PNG, GIF, BMP, JPEG) states its width and height in its first bytes
    (:func:`header_size`). A 40-byte GIF can claim 65535x65535 pixels, which would take
    16 GB to decode, so the claim is read and refused first. Any other format is refused
    with a sentence, because its size cannot be checked before it is decoded.
  * **One budget per level.** Each image may be at most ``MAX_IMAGE_PX`` a side, and all
    the images of one level together at most ``MAX_LEVEL_PIXELS``, counted as they are
    checked (:class:`PixelBudget`); a level of a thousand small images is as bounded as one
    of a single huge one.
  * ``pygame.image.load`` works before ``pygame.display.set_mode`` (only ``convert`` needs
    a display), so a command-line checker can decode images.

>>> header_size(PNG_SIGNATURE + bytes(8) + struct.pack(">II", 128, 64))
('PNG', 128, 64)
>>> header_size(b"GIF89a" + struct.pack("<HH", 65535, 65535) + bytes(3) + b";")
('GIF', 65535, 65535)
>>> header_size(b"<svg>") is None
True
"""

from __future__ import annotations

import io
import struct
from dataclasses import dataclass
from pathlib import Path
from weakref import WeakKeyDictionary

import pygame

from game.levels.errors import Findings, escaped, excerpt
from game.levels.reading import read_level_file

MAX_IMAGE_BYTES = 64 * 1024 * 1024
MAX_IMAGE_PX = 16384  # per side
MAX_LEVEL_PIXELS = 4096 * 4096  # all images of one level: 64 MB decoded, as 32-bit pixels
MAX_GIF_STEPS = 1_000_000  # blocks and sub-blocks walked in one GIF: 255 MB of real data
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
FORMATS = "PNG, GIF, BMP or JPEG"
FIX_IMAGE = "save the image as PNG next to the tileset and pick it again in Tiled"
JPEG_SIZE_MARKERS = frozenset(range(0xC0, 0xD0)) - {0xC4, 0xC8, 0xCC}  # SOF0..SOF15

Size = tuple[str, int, int]  # format, width, height


def _png(head: bytes) -> Size | None:
    if len(head) < 24:
        return None
    width, height = struct.unpack(">II", head[16:24])
    return "PNG", int(width), int(height)


def _gif(head: bytes) -> Size | None:
    """The logical screen, grown to hold every frame: walked the way SDL_image walks it.

    SDL_image skips a stray byte between blocks and sizes the picture by the frame, which
    may be far larger than the screen it claims to sit in; so every image descriptor in the
    file is found the same way and measured, not only one after a well-formed start.
    """
    if len(head) < 13:
        return None
    width, height = struct.unpack("<HH", head[6:10])
    at, steps = 13, 0
    if head[10] & 0x80:  # a global colour table follows the screen descriptor
        at += 3 * (2 << (head[10] & 0x07))
    while at < len(head) and steps < MAX_GIF_STEPS:
        block = head[at]
        steps += 1
        if block == 0x3B:  # the trailer
            break
        if block == 0x2C:  # image descriptor: left, top, width, height, flags
            if at + 10 > len(head):
                break
            left, top, frame_w, frame_h, flags = struct.unpack("<HHHHB", head[at + 1:at + 10])
            width, height = max(width, left + frame_w), max(height, top + frame_h)
            at += 10 + (3 * (2 << (flags & 0x07)) if flags & 0x80 else 0) + 1  # + LZW size
        elif block == 0x21:  # extension: introducer and label
            at += 2
        else:  # SDL_image ignores a stray byte; so does this walk
            at += 1
            continue
        while at < len(head) and head[at] and steps < MAX_GIF_STEPS:  # data sub-blocks
            at += head[at] + 1
            steps += 1
        at += 1
    if steps >= MAX_GIF_STEPS:
        return None  # too many blocks to measure: its size cannot be known before decoding
    return "GIF", width, height


def _bmp(head: bytes) -> Size | None:
    if len(head) < 26:
        return None
    (dib_size,) = struct.unpack("<I", head[14:18])
    if dib_size == 12:  # the old OS/2 header: 16-bit sizes
        width, height = struct.unpack("<HH", head[18:22])
    else:  # a negative height means rows stored top to bottom
        width, height = struct.unpack("<ii", head[18:26])
    return "BMP", abs(int(width)), abs(int(height))


def _jpeg(head: bytes) -> Size | None:
    at = 2
    while at + 9 < len(head):
        if head[at] != 0xFF:
            return None
        marker = head[at + 1]
        if marker == 0xFF:  # fill byte
            at += 1
            continue
        if marker in (0x01, *range(0xD0, 0xD9)):  # markers without a length
            at += 2
            continue
        (length,) = struct.unpack(">H", head[at + 2:at + 4])
        if marker in JPEG_SIZE_MARKERS:
            height, width = struct.unpack(">HH", head[at + 5:at + 9])
            return "JPEG", int(width), int(height)
        at += 2 + length
    return None


def header_size(head: bytes) -> Size | None:
    """The format, width and height an image's first bytes state; None for a format the game
    does not accept, or a header too damaged to say."""
    if head.startswith(PNG_SIGNATURE):
        return _png(head)
    if head[:6] in (b"GIF87a", b"GIF89a"):
        return _gif(head)
    if head.startswith(b"BM"):
        return _bmp(head)
    if head.startswith(b"\xff\xd8"):
        return _jpeg(head)
    return None


@dataclass
class PixelBudget:
    """The pixels one level's images may take, all together; spent as images are checked.

    >>> budget = PixelBudget(limit=100)
    >>> budget.spend(8, 8), budget.spend(8, 8)
    (True, False)
    """

    limit: int = MAX_LEVEL_PIXELS
    used: int = 0

    def spend(self, width: int, height: int) -> bool:
        """Count an image of ``width`` x ``height``; False if it takes the level over."""
        self.used += width * height
        return self.used <= self.limit


_BUDGETS: WeakKeyDictionary[Findings, PixelBudget] = WeakKeyDictionary()  # one per level read


def charge_pixels(findings: Findings, where: str, path: Path, width: int, height: int,
                  budget: PixelBudget | None = None) -> None:
    """Count an image against the pixels of the level ``findings`` belongs to (or against
    ``budget``); fail if it takes the level over."""
    budget = budget or _BUDGETS.setdefault(findings, PixelBudget())
    if not budget.spend(width, height):
        findings.fail(where, f"the image {escaped(path.name)} ({width}x{height}) takes the "
                      f"level's images over {budget.limit:,} pixels in all",
                      "use fewer or smaller images: one tileset image can hold many tiles")


_DECODED: WeakKeyDictionary[Findings, dict[Path, pygame.Surface]] = WeakKeyDictionary()


def load_image(path: Path, findings: Findings, where: str, what: str,
               budget: PixelBudget | None = None) -> pygame.Surface:
    """The image at ``path``, decoded from the very bytes whose header was measured; fail
    with a sentence if it cannot be used. Each image is read, decoded and counted against
    the level's pixels once per level read: the game, which checks a tileset's image and
    then hands it to pytmx, spends the same budget as the checker, which only checks it."""
    known = _DECODED.setdefault(findings, {})
    if path in known:
        return known[path]
    name = f"the {what} {escaped(path.name)}"
    data = read_level_file(path, findings, where, name.removeprefix("the "), MAX_IMAGE_BYTES,
                           FIX_IMAGE, missing=(f"{name} is missing ({escaped(str(path))})",
                                               "put the image back, or pick another in the "
                                               "tileset's Image property"))
    size = header_size(data)
    if size is None:
        findings.fail(where, f"{name} is not a {FORMATS} image whose size the game can read",
                      FIX_IMAGE)
    kind, width, height = size
    if not (1 <= width <= MAX_IMAGE_PX and 1 <= height <= MAX_IMAGE_PX):
        findings.fail(where, f"{name} says it is a {width}x{height} {kind}; the game reads "
                      f"images of 1 to {MAX_IMAGE_PX} pixels a side", FIX_IMAGE)
    charge_pixels(findings, where, path, width, height, budget)
    try:  # the same bytes, typed by what they were measured as: no other decoder is asked
        image = pygame.image.load(io.BytesIO(data), f"image.{kind.lower()}")
    except (pygame.error, OSError, ValueError, MemoryError) as error:
        findings.fail(where, f"{name} cannot be decoded ({excerpt(str(error))})", FIX_IMAGE)
    decoded = image.get_size()
    if decoded != (width, height):
        findings.fail(where, f"{name} decodes to {decoded[0]}x{decoded[1]}, not the "
                      f"{width}x{height} its header says", FIX_IMAGE)
    known[path] = image
    return image


def check_image(path: Path, findings: Findings, where: str, what: str,
                budget: PixelBudget | None = None) -> tuple[int, int]:
    """Check the image at ``path`` (its header, then the budget, then the decoding) and
    return its size; fail with a sentence if it cannot be used.

    ``budget`` defaults to the one of the level ``findings`` belongs to, so every image
    checked while reading one level counts against that level's pixels."""
    width, height = load_image(path, findings, where, what, budget).get_size()
    return width, height
