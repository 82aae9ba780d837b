"""Check that an image a map uses is there and decodes, without a display.

Where it sits: the checker and windowed runs look at every tileset image, tile image and
image-layer image through :func:`check_image`; headless runs skip it and never open an
image file.

What it teaches: ``pygame.image.load`` works before ``pygame.display.set_mode`` (only
``convert`` needs a display), so a command-line checker can decode images. A PNG states its
size in its first 24 bytes, which is read first, so an image that would need gigabytes to
decode is refused before it is decoded.
"""

from __future__ import annotations

import stat
import struct
from pathlib import Path

import pygame

from game.levels.errors import Findings

MAX_IMAGE_BYTES = 64 * 1024 * 1024
MAX_IMAGE_PX = 16384  # per side
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"
FIX_IMAGE = "save the image as PNG next to the tileset and pick it again in Tiled"


def png_size(head: bytes) -> tuple[int, int] | None:
    """The width and height a PNG's header states, or None if ``head`` is not a PNG.

    >>> png_size(PNG_SIGNATURE + bytes(8) + struct.pack(">II", 128, 64))
    (128, 64)
    """
    if len(head) < 24 or not head.startswith(PNG_SIGNATURE):
        return None
    width, height = struct.unpack(">II", head[16:24])
    return int(width), int(height)


def check_image(path: Path, findings: Findings, where: str, what: str) -> tuple[int, int]:
    """Decode the image at ``path`` and return its size; fail with a sentence if it cannot
    be used."""
    name = f"the {what} {path.name}"
    try:
        status = path.stat()
    except (FileNotFoundError, NotADirectoryError):
        findings.fail(where, f"{name} is missing ({path})",
                      "put the image back, or pick another in the tileset's Image property")
    except (OSError, ValueError) as error:
        findings.fail(where, f"{name} cannot be read ({error})", FIX_IMAGE)
    too_big = f"{name} is not an image file of at most {MAX_IMAGE_PX} pixels a side"
    if not stat.S_ISREG(status.st_mode) or status.st_size > MAX_IMAGE_BYTES:
        findings.fail(where, too_big, FIX_IMAGE)
    try:
        with path.open("rb") as stream:
            size = png_size(stream.read(24))
    except OSError as error:
        findings.fail(where, f"{name} cannot be read ({error.strerror or error})", FIX_IMAGE)
    if size is not None and max(size) > MAX_IMAGE_PX:
        findings.fail(where, too_big, FIX_IMAGE)
    try:
        return pygame.image.load(str(path)).get_size()
    except (pygame.error, OSError, ValueError, MemoryError) as error:
        findings.fail(where, f"{name} cannot be decoded ({error})", FIX_IMAGE)
