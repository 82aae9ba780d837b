"""A downloaded level is untrusted: it reads only the files beside it, and within limits.

Each test rebuilds one hostile level: an image that claims a huge size in a few bytes, a
tileset cut into millions of tiles, one tileset named a thousand times, a path or a symbolic
link that leads out of the level's folder, a ``next_level`` elsewhere or naming itself.
"""

from __future__ import annotations

import os
import struct
from pathlib import Path

import pygame
import pytest

from game.levels import check_level, load_level, tiledxml
from game.levels import tilesets as tilesets_module
from game.levels.images import header_size
from tests.test_loader import OBJECTS, TILESET, solids, write_map

MAX_MESSAGE_CHARS = 1_000
MAP_PROPERTIES = '<properties><property name="next_level" type="file" value="{}"/></properties>'


def errors_of(path: Path) -> list[str]:
    return [str(error) for error in check_level(path).errors]


def image_tileset(folder: Path, name: str, data: bytes, size: str = 'width="64" height="16"'
                  ) -> str:
    (folder / name).write_bytes(data)
    return TILESET.format(image=f'<image source="{name}" {size}/>')


def png_header(width: int, height: int) -> bytes:
    return b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" + struct.pack(
        ">II", width, height) + bytes(5)


# -- limits before work ---------------------------------------------------------------------

@pytest.mark.parametrize(("name", "data", "claim"), [
    ("big.gif", b"GIF89a" + struct.pack("<HH", 65535, 65535) + bytes(3) + b","
     + struct.pack("<HHHH", 0, 0, 65535, 65535) + b"\0;", "65535x65535 GIF"),
    ("big.bmp", b"BM" + bytes(12) + struct.pack("<Iii", 40, 23000, 23000) + bytes(28),
     "23000x23000 BMP"),
    ("big.png", png_header(100_000, 8), "100000x8 PNG"),
])
def test_an_image_claiming_a_huge_size_is_refused_before_it_is_decoded(
        tmp_path: Path, name: str, data: bytes, claim: str) -> None:
    path = write_map(tmp_path, tileset=image_tileset(tmp_path, name, data))
    [error] = errors_of(path)
    assert claim in error and "16384 pixels a side" in error


def test_a_gif_frame_larger_than_its_screen_is_measured_by_the_frame() -> None:
    gif = (b"GIF89a" + struct.pack("<HH", 8, 8) + b"\x80\0\0" + bytes(6)  # 2-colour palette
           + b"!\xf9\x04" + bytes(4) + b"\0"  # a graphic control extension
           + b"," + struct.pack("<HHHH", 0, 0, 60000, 60000) + b"\0;")
    assert header_size(gif) == ("GIF", 60000, 60000)


def test_a_jpeg_states_its_size_in_its_frame_header(tmp_path: Path) -> None:
    path = tmp_path / "photo.jpg"
    try:
        pygame.image.save(pygame.Surface((37, 21)), str(path))
    except pygame.error:
        pytest.skip("this pygame cannot write JPEG")
    assert header_size(path.read_bytes()) == ("JPEG", 37, 21)


def test_a_format_whose_size_cannot_be_read_first_is_refused(tmp_path: Path) -> None:
    svg = b'<svg xmlns="http://www.w3.org/2000/svg" width="99999" height="99999"/>'
    [error] = errors_of(write_map(tmp_path, tileset=image_tileset(tmp_path, "t.svg", svg)))
    assert "not a PNG, GIF, BMP or JPEG image" in error


def test_the_images_of_one_level_share_one_pixel_budget(tmp_path: Path) -> None:
    path = write_map(tmp_path, tileset=image_tileset(tmp_path, "wide.png",
                                                     png_header(16384, 16384)))
    [error] = errors_of(path)
    assert "over 16,777,216 pixels in all" in error


def test_a_tileset_cut_into_millions_of_tiles_is_refused_without_its_image(
        tmp_path: Path) -> None:
    tileset = ('<tileset firstgid="1" name="t" tilewidth="1" tileheight="1">'
               '<image source="missing.png" width="16384" height="16384"/></tileset>')
    with pytest.raises(Exception, match="cuts into 268,435,456 tiles"):
        load_level(write_map(tmp_path, tileset=tileset))  # headless: no image is opened


def test_a_tileset_named_a_thousand_times_is_read_once(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "t.tsx").write_text(TILESET.replace('firstgid="1" ', ""), encoding="utf-8")
    tilesets = "".join(f'<tileset firstgid="{1 + 4 * n}" source="t.tsx"/>'
                       for n in range(1000))
    reads: list[Path] = []
    read = tiledxml.read_tiled_xml

    def counting(path: Path, *args: object, **kwargs: object) -> object:
        reads.append(path)
        return read(path, *args, **kwargs)  # type: ignore[arg-type]

    monkeypatch.setattr(tilesets_module, "read_tiled_xml", counting)
    level = load_level(write_map(tmp_path, tileset=tilesets))
    assert len(reads) == 1
    assert len(solids(level)) == 4  # the floor of four tiles


def test_a_30_mb_attribute_is_quoted_by_an_excerpt(tmp_path: Path) -> None:
    attrs = (f'orientation="orthogonal" width="{"9" * 1_000_000}" height="3" '
             'tilewidth="16" tileheight="16"')
    [error] = errors_of(write_map(tmp_path, map_attrs=attrs))
    assert "(1,000,000 characters)" in error and len(error) < MAX_MESSAGE_CHARS


def test_a_long_title_is_cut_with_a_warning(tmp_path: Path) -> None:
    properties = '<properties><property name="title" value="{}"/></properties>'
    path = write_map(tmp_path, tileset=properties.format("W" * 20_000)
                     + TILESET.format(image=""))
    assert len(load_level(path).title) == 60
    assert any("20,000 characters" in str(w) for w in check_level(path).warnings)


# -- the level's folder is a sandbox --------------------------------------------------------

def next_level_map(folder: Path, next_level: str) -> Path:
    return write_map(folder, tileset=MAP_PROPERTIES.format(next_level)
                     + TILESET.format(image=""))


@pytest.mark.parametrize("elsewhere", ["../elsewhere/other.tmx", "{absolute}"])
def test_a_next_level_outside_the_folder_is_refused(tmp_path: Path, elsewhere: str) -> None:
    other = tmp_path / "elsewhere"
    other.mkdir()
    write_map(other, name="other.tmx")
    (tmp_path / "mine").mkdir()
    path = next_level_map(tmp_path / "mine",
                          elsewhere.format(absolute=(other / "other.tmx").as_posix()))
    [error] = errors_of(path)
    assert "leads outside the level's folder" in error and "next level" in error
    with pytest.raises(Exception, match="leads outside"):
        load_level(path)


def test_a_level_naming_itself_as_next_is_refused(tmp_path: Path) -> None:
    [error] = errors_of(next_level_map(tmp_path, "level.tmx"))
    assert "names itself" in error


def test_a_next_level_beside_the_map_is_allowed(tmp_path: Path) -> None:
    write_map(tmp_path, name="two.tmx")
    level = load_level(next_level_map(tmp_path, "two.tmx"))
    assert level.next_level is not None and level.next_level.name == "two.tmx"


@pytest.mark.parametrize("what", ["tileset", "image", "folder"])
def test_a_symbolic_link_leading_out_of_the_folder_is_refused(tmp_path: Path,
                                                              what: str) -> None:
    outside, level_dir = tmp_path / "outside", tmp_path / "level"
    outside.mkdir()
    level_dir.mkdir()
    (outside / "t.tsx").write_text(TILESET.replace('firstgid="1" ', ""), encoding="utf-8")
    pygame.image.save(pygame.Surface((64, 16)), str(outside / "t.png"))
    if what == "tileset":
        os.symlink(outside / "t.tsx", level_dir / "t.tsx")
        tileset = '<tileset firstgid="1" source="t.tsx"/>'
    elif what == "image":
        os.symlink(outside / "t.png", level_dir / "t.png")
        tileset = TILESET.format(image='<image source="t.png" width="64" height="16"/>')
    else:
        os.symlink(outside, level_dir / "shared")
        tileset = '<tileset firstgid="1" source="shared/t.tsx"/>'
    [error] = errors_of(write_map(level_dir, tileset=tileset, objects=OBJECTS))
    assert "leads outside the level's folder" in error


def test_a_symbolic_link_that_stays_inside_the_folder_is_followed(tmp_path: Path) -> None:
    (tmp_path / "real.tsx").write_text(TILESET.replace('firstgid="1" ', ""), encoding="utf-8")
    os.symlink(tmp_path / "real.tsx", tmp_path / "t.tsx")
    level = load_level(write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsx"/>'))
    assert solids(level)
