"""The terrain tileset: Tiled can paint it, the shipped maps are painted with it, painting it
changed nothing that collides, and the 32-tile tileset that maps made before it rely on is as
it was."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pygame
import pytest

from game.levels import LEVELS_DIR
from game.tools import art, terrain
from tests.collision_grids import all_grids, shipped_maps

ASSETS = LEVELS_DIR.parent / "assets"
RECORDED = Path(__file__).resolve().parent / "data" / "collision-grids.txt"


def test_every_shipped_map_collides_exactly_as_before_its_ground_was_repainted() -> None:
    assert all_grids() == RECORDED.read_text(encoding="utf-8")


def test_the_tileset_files_are_the_ones_the_art_script_writes() -> None:
    assert (ASSETS / "tiles.tsx").read_text(encoding="utf-8") == art.tileset_tsx()
    assert (ASSETS / "terrain.tsx").read_text(encoding="utf-8") == art.terrain_tsx()


@pytest.mark.parametrize("name", ["tiles.png", "terrain.png"])
def test_the_tileset_images_are_the_ones_the_art_script_draws(name: str) -> None:
    draw, size = art.IMAGES[name]
    committed = pygame.image.load(str(ASSETS / name))
    assert committed.get_size() == size
    assert pygame.image.tobytes(committed, "RGBA") == pygame.image.tobytes(draw(), "RGBA")


def test_the_tileset_keeps_its_32_tiles_and_their_classes() -> None:
    root = ET.parse(ASSETS / "tiles.tsx").getroot()
    assert root.get("tilecount") == "32" and root.find("wangsets") is None
    classes = {int(t.get("id", "-1")): t.get("type") for t in root.iter("tile")}
    assert classes == {0: "Solid", 1: "Solid", 2: "Solid", 3: "Solid", 4: "Solid",
                       5: "OneWay", 6: "Hazard", 7: "Solid"}  # as the first version had them


def test_the_terrain_tileset_declares_a_mixed_terrain_set_with_every_edge_and_corner() -> None:
    root = ET.parse(ASSETS / "terrain.tsx").getroot()
    wangsets = root.findall("wangsets/wangset")
    assert [(w.get("name"), w.get("type")) for w in wangsets] == [("Ground", "mixed"),
                                                                  ("Planks", "edge")]
    tiles = {int(t.get("tileid", "-1")): t.get("wangid", "") for t in wangsets[0].iter("wangtile")}
    classes = {int(t.get("id", "-1")): t.get("type") for t in root.iter("tile")}
    assert len(tiles) == 46  # the 47 blob looks, less the lone block, which has no neighbour
    assert all(classes[tile_id] == "Solid" for tile_id in tiles)
    ids = set(tiles.values())
    assert len(ids) == len(tiles), "no two terrain tiles claim the same neighbours"
    top = "0,0,1,1,1,1,1,0"              # ground left, right and below: a grass top
    inside = "1,1,1,1,1,1,1,1"
    corner = "0,0,1,1,1,0,0,0"           # ground only right and below: a top-left corner
    inner = "1,0,1,1,1,1,1,1"            # all round but the top right: an inside corner
    side = "1,1,1,1,1,0,0,0"             # open on the left: a wall's side
    assert {top, inside, corner, inner, side} <= ids
    for wang in ids:                      # a corner is ground only if both its edges are
        parts = [int(p) for p in wang.split(",")]
        for corner_at in (1, 3, 5, 7):
            if parts[corner_at]:
                assert parts[corner_at - 1] and parts[(corner_at + 1) % 8], wang


def test_every_shipped_map_is_painted_with_the_terrain_tiles() -> None:
    maps = shipped_maps()
    assert terrain.main(["--check", *map(str, maps)]) == 0
    for path in maps:
        text = path.read_text(encoding="utf-8")
        assert '<tileset firstgid="1" source="' in text, path.name
        assert 'firstgid="33" source="../assets/terrain.tsx"' in text.replace("../../", "../")
        used = {int(n) - 33 for n in text.split("<data")[-1].replace("\n", ",").split(",")
                if n.strip().isdigit()}
        assert used & set(art.TERRAIN_IDS) - {art.terrain_tile_id(0)}, path.name


def test_repainting_a_map_fixes_a_hand_placed_ground_tile() -> None:
    path = LEVELS_DIR / "01-first-steps.tmx"
    text = path.read_text(encoding="utf-8")
    start = text.index('name="ground"')
    data_at = text.index("<data", start)
    # put the dirt-fill tile (a hand-placed inside tile) on the top of the first grass run
    rows = text[text.index("\n", data_at) + 1:text.index("</data>", data_at)].splitlines()
    first_grass = next(i for i, row in enumerate(rows) if any(v not in ("", "0")
                                                               for v in row.split(",")))
    row = rows[first_grass].split(",")
    col = next(i for i, v in enumerate(row) if v not in ("", "0"))
    row[col] = str(1 + art.DIRT_FILL)
    spoiled = text.replace(rows[first_grass], ",".join(row), 1)
    assert spoiled != text
    assert terrain.repaint_map(spoiled) == text


def test_the_planks_end_where_their_row_stops_and_stay_one_way() -> None:
    root = ET.parse(ASSETS / "terrain.tsx").getroot()
    planks = root.findall("wangsets/wangset")[1]
    classes = {int(t.get("id", "-1")): t.get("type") for t in root.iter("tile")}
    wang = {t.get("wangid"): int(t.get("tileid", "-1")) for t in planks.iter("wangtile")}
    assert set(wang) == {"0,0,1,0,0,0,1,0", "0,0,1,0,0,0,0,0", "0,0,0,0,0,0,1,0"}
    assert all(classes[tile_id] == "OneWay" for tile_id in wang.values())
    first, terrain_first = 1, 33  # the tilesets' first gids in a map
    row = [[0, first + art.ONE_WAY, first + art.ONE_WAY, first + art.ONE_WAY, 0,
            first + art.ONE_WAY]]
    assert terrain.repaint_rows(row, first, terrain_first) == [[
        0, terrain_first + art.PLANK_LEFT, terrain_first + art.PLANK_MIDDLE,
        terrain_first + art.PLANK_RIGHT, 0, terrain_first + art.PLANK_LONE]]
