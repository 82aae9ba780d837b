"""Nothing Tiled offers is dropped in silence: tile animations play, parallax factors scroll
layers that do not collide, and what the game still ignores gets a warning."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pygame
import pytest
import pytmx.util_pygame

from game.app.render import LayerCache, animation_frame
from game.levels import LEVELS_DIR, check_level, load_level
from game.sim.level import TileLayer
from tests.maps import write_tmx

HOP_ALONG = LEVELS_DIR / "03-hop-along.tmx"
OPEN = ["                ", " P           D  ", "################"]
RED, BLUE = (255, 0, 0), (0, 0, 255)


def warnings(path: Path) -> list[str]:
    return [str(warning) for warning in check_level(path).warnings]


def test_hop_along_has_an_animated_tile_and_a_parallax_layer() -> None:
    level = load_level(HOP_ALONG)
    assert level.animations and all(len(frames) == 4 for frames in level.animations.values())
    drawn = {layer.name: layer for layer in level.layers}
    assert drawn["far fence"].parallax == (0.5, 1.0)
    assert drawn["ground"].parallax == (1.0, 1.0)
    used = {gid for layer in level.layers for row in layer.gids for gid in row}
    assert used & set(level.animations)


def test_the_frames_of_an_animated_tile_are_loaded_with_the_images() -> None:
    pygame.display.init()
    try:
        pygame.display.set_mode((1, 1))
        level = load_level(HOP_ALONG, images=True)
    finally:
        pygame.display.quit()  # leave no window behind for the next test
    for frames in level.animations.values():
        assert all(gid in level.tile_images for gid, _ in frames)


def one_tile_layer(gid: int, parallax: tuple[float, float] = (1.0, 1.0)) -> TileLayer:
    return TileLayer("test", ((0, 0, 0, 0), (0, 0, gid, 0)), parallax=parallax)


def tile_image(color: tuple[int, int, int]) -> pygame.Surface:
    image = pygame.Surface((16, 16))
    image.fill(color)
    return image


def test_an_animated_tile_shows_the_frame_its_animation_has_reached() -> None:
    images = {1: tile_image(RED), 2: tile_image(BLUE)}
    animation = ((1, 100), (2, 100))  # ms per frame; at 60 frames a second, 6 frames each
    cache = LayerCache(one_tile_layer(1), images, (16, 16), (0, 0), {1: animation})
    seen = []
    for frame in (0, 6, 12):
        target = pygame.Surface((64, 32))
        cache.draw(target, (0, 0), frame)
        seen.append(tuple(target.get_at((40, 24)))[:3])
    assert seen == [RED, BLUE, RED]
    assert animation_frame(animation, 150) == 2


def test_a_parallax_factor_scales_how_far_the_layer_scrolls() -> None:
    images = {1: tile_image(RED)}
    target = pygame.Surface((64, 32))
    LayerCache(one_tile_layer(1, (0.5, 1.0)), images, (16, 16), (0, 0)).draw(target, (20, 0))
    # The tile at x=32 moves 10 px (half the camera's 20), not 20: it now starts at x=22.
    assert tuple(target.get_at((22, 24)))[:3] == RED
    assert tuple(target.get_at((21, 24)))[:3] != RED
    assert tuple(target.get_at((37, 24)))[:3] == RED


def test_an_offset_on_a_colliding_layer_is_a_warning_and_is_not_drawn(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    text = path.read_text(encoding="utf-8").replace('name="ground"',
                                                    'name="ground" offsetx="8" offsety="-4"')
    path.write_text(text, encoding="utf-8")
    assert any("layer 'ground': warning: its offset (8, -4) would move the drawing but not "
               "the collision" in w for w in warnings(path))
    assert load_level(path).layers[0].offset == (0.0, 0.0)


def test_parallax_on_a_colliding_layer_is_a_warning_and_is_not_used(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    text = path.read_text(encoding="utf-8").replace('name="ground"',
                                                    'name="ground" parallaxx="0.5"')
    path.write_text(text, encoding="utf-8")
    assert any("layer 'ground': warning: its parallax factor (0.5, 1)" in w
               for w in warnings(path))
    assert load_level(path).layers[0].parallax == (1.0, 1.0)


@pytest.mark.parametrize(("name", "says"), [("gravity", "move 'gravity' to Map > Map "
                                                       "Properties"),
                                            ("note", "means nothing to the game")])
def test_a_property_on_a_layer_is_a_warning(tmp_path: Path, name: str, says: str) -> None:
    path = write_tmx(tmp_path, OPEN)
    text = path.read_text(encoding="utf-8").replace(
        '<objectgroup id="2" name="objects">',
        f'<objectgroup id="2" name="objects"><properties><property name="{name}" '
        'type="float" value="100"/></properties>')
    path.write_text(text, encoding="utf-8")
    assert any(w.startswith(f"{path}: layer 'objects': warning: property '{name}'")
               and says in w for w in warnings(path))


def test_an_animation_frame_the_tileset_lacks_is_an_error(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    tileset = tmp_path / "t.tsx"
    tileset.write_text(tileset.read_text(encoding="utf-8").replace(
        '<tile id="1" type="OneWay"/>',
        '<tile id="1" type="OneWay"><animation><frame tileid="1" duration="100"/>'
        '<frame tileid="40" duration="100"/></animation></tile>'), encoding="utf-8")
    errors = [str(error) for error in check_level(path).errors]
    assert any("tile 1: its animation shows tile 40, which the tileset does not have" in e
               for e in errors), errors


def mirrored_banner_level(tmp_path: Path) -> tuple[Path, int]:
    """Hop Along with its first animated banner tile mirrored (Tiled's flip flag on its gid)."""
    shutil.copytree(LEVELS_DIR.parent / "assets", tmp_path / "assets")
    (tmp_path / "levels").mkdir()
    text = HOP_ALONG.read_text(encoding="utf-8")
    start = text.index('name="banners"')
    head, data = text[start:].split('<data encoding="csv">', 1)
    gid = next(int(n) for n in re.findall(r"\d+", data) if int(n))
    data = re.sub(rf"\b{gid}\b", str(gid | 0x80000000), data, count=1)  # flipped across
    path = tmp_path / "levels" / "mirrored.tmx"
    path.write_text(text[:start] + head + '<data encoding="csv">' + data, encoding="utf-8")
    return path, gid


def test_a_mirrored_animated_tile_shows_mirrored_frames(tmp_path: Path) -> None:
    path, banner = mirrored_banner_level(tmp_path)
    pygame.display.init()
    try:
        pygame.display.set_mode((1, 1))
        level = load_level(path, images=True)
        tmx = pytmx.util_pygame.load_pygame(str(path))
    finally:
        pygame.display.quit()

    def pictures(gid: int) -> list[bytes]:
        return [pygame.image.tobytes(level.tile_images[frame], "RGBA")
                for frame, _ in level.animations[gid]]

    one, other = sorted(level.animations)   # the banner, plain and mirrored
    for gid in (one, other):                # each starts on its own tile's picture
        assert pictures(gid)[0] == pygame.image.tobytes(level.tile_images[gid], "RGBA")
    assert pictures(other) == [
        pygame.image.tobytes(pygame.transform.flip(level.tile_images[frame], True, False),
                             "RGBA") for frame, _ in level.animations[one]]
    # pytmx alone lists the plain frames for the mirrored tile: drawn as they are, the
    # banner would flutter the wrong way round.
    by_flip = {bool(flags.flipped_horizontally): gid for gid, flags in tmx.gidmap[banner]}
    plain, mirrored = by_flip[False], by_flip[True]

    def frames_by_pytmx(gid: int) -> list[int]:
        return [frame.gid for frame in tmx.get_tile_properties_by_gid(gid)["frames"]]

    assert frames_by_pytmx(mirrored) == frames_by_pytmx(plain)
