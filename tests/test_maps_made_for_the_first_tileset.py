"""Maps made against the first ``tiles.tsx`` keep working: it still has 32 tiles, so a second
tileset at gid 33 (where Tiled puts it) does not overlap it, and each of its ids collides as
it did. The terrain tool adds ``terrain.tsx`` to such a map after its other tilesets."""

from __future__ import annotations

import shutil
from pathlib import Path

import pygame
import pytest

from game.levels import LEVELS_DIR, check_level, load_level
from game.tools import terrain
from tests.collision_grids import collision_grid

ASSETS = LEVELS_DIR.parent / "assets"
BANNER_GID = 33  # banner.tsx, the second tileset, where Tiled put it beside 32 tiles
# The first version's tiles, by the gid they have at firstgid 1: ground, dirt, fieldstone,
# the two grass ends, a plank, spikes, the lone block; then bush and flower (decor).
GIDS = {"G": 1, "d": 2, "s": 3, "L": 4, "R": 5, "-": 6, "^": 7, "o": 8, "b": 9, "f": 10,
        "B": BANNER_GID}
GROUND = (
    "............",
    "..........B.",
    "......o.....",
    "...---......",
    ".bf......bf.",
    "LGGR..^^sLGR",
    "ddddGGGGsddd",
    "dddddddsdddd",
)
# What each cell does, by the classes the first tiles.tsx gave its ids 0-7.
COLLIDES = [row.translate(str.maketrans("GdsLRo^-bfB", "######^-...")) for row in GROUND]


def old_map(folder: Path) -> Path:
    """A map as Tiled saved it against the first tileset, in ``folder/levels``, beside an
    ``assets`` folder holding only the tilesets it names."""
    (folder / "levels").mkdir()
    (folder / "assets").mkdir()
    for name in ("tiles.tsx", "tiles.png", "banner.tsx", "banner.png"):
        shutil.copy(ASSETS / name, folder / "assets" / name)
    width, height = len(GROUND[0]), len(GROUND)
    data = ",\n".join(",".join(str(GIDS.get(char, 0)) for char in row) for row in GROUND)
    path = folder / "levels" / "old.tmx"
    path.write_text(f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" \
width="{width}" height="{height}" tilewidth="16" tileheight="16" infinite="0" \
nextlayerid="3" nextobjectid="3">
 <tileset firstgid="1" source="../assets/tiles.tsx"/>
 <tileset firstgid="{BANNER_GID}" source="../assets/banner.tsx"/>
 <layer id="1" name="ground" width="{width}" height="{height}">
  <data encoding="csv">
{data}
</data>
 </layer>
 <objectgroup id="2" name="objects">
  <object id="1" type="Player" x="16" y="66" width="12" height="14"/>
  <object id="2" type="Exit" x="160" y="48" width="16" height="32"/>
 </objectgroup>
</map>
""", encoding="utf-8")
    return path


def test_a_map_with_a_second_tileset_at_gid_33_passes_the_checker(tmp_path: Path) -> None:
    findings = check_level(old_map(tmp_path))
    assert [str(error) for error in findings.errors] == []


def test_each_first_tileset_id_collides_as_it_did(tmp_path: Path) -> None:
    assert collision_grid(old_map(tmp_path)) == COLLIDES


def test_the_second_tileset_draws_its_own_tile_at_gid_33(tmp_path: Path) -> None:
    pygame.display.init()
    pygame.display.set_mode((1, 1))
    level = load_level(old_map(tmp_path), images=True)
    banner = pygame.image.load(str(ASSETS / "banner.png")).subsurface((0, 0, 16, 16))
    (ground,) = level.layers
    row = next(row for row, line in enumerate(GROUND) if "B" in line)
    drawn = ground.gids[row][GROUND[row].index("B")]  # the loader's own id for the cell
    assert drawn in level.animations  # the banner waves: its tile is animated
    picture = level.tile_images[drawn]
    assert pygame.image.tobytes(picture, "RGBA") == pygame.image.tobytes(banner.copy(), "RGBA")
    plank = level.tile_images[ground.gids[3][3]]
    assert pygame.image.tobytes(plank, "RGBA") == pygame.image.tobytes(
        pygame.image.load(str(ASSETS / "tiles.png")).subsurface((5 * 16, 0, 16, 16)).copy(),
        "RGBA")  # and tile 5 of tiles.png, the plank, is drawn at gid 6


def test_painting_terrain_adds_the_terrain_tileset_after_the_others(tmp_path: Path) -> None:
    path = old_map(tmp_path)
    for name in ("terrain.tsx", "terrain.png"):
        shutil.copy(ASSETS / name, tmp_path / "assets" / name)
    assert terrain.main([str(path)]) == 0
    text = path.read_text(encoding="utf-8")
    assert (' <tileset firstgid="1" source="../assets/tiles.tsx"/>\n'
            f' <tileset firstgid="{BANNER_GID}" source="../assets/banner.tsx"/>\n'
            ' <tileset firstgid="37" source="../assets/terrain.tsx"/>\n') in text
    gids = {int(n) for n in text.split("<data")[-1].replace("\n", ",").split(",")
            if n.strip().isdigit()}
    assert BANNER_GID in gids and gids - {0, BANNER_GID, 9, 10, 7} <= set(range(37, 37 + 56))
    assert collision_grid(path) == COLLIDES
    assert [str(error) for error in check_level(path).errors] == []
    assert terrain.main(["--check", str(path)]) == 0


def test_painting_terrain_where_a_tileset_is_missing_says_so_and_changes_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = old_map(tmp_path)
    (tmp_path / "assets" / "banner.tsx").unlink()
    before = path.read_text(encoding="utf-8")
    assert terrain.main([str(path)]) == 1
    error = capsys.readouterr().err
    assert error.startswith(f"{path}: tileset '../assets/banner.tsx': the tileset file "
                            "banner.tsx does not exist")
    assert error.count("\n") == 1 and "Traceback" not in error
    assert path.read_text(encoding="utf-8") == before
