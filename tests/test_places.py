"""How the levels look: six places that differ, hazards that stand out from everything safe,
and a camera that shows a pit's bottom whenever it shows the pit."""

from __future__ import annotations

import math
from pathlib import Path

import pygame
import pytest

from game.app.assets import Assets
from game.app.places import PLACES, place_of, recolour
from game.app.render import WorldRenderer, floor_line_px, pit_spans_px
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.levels import LEVELS_DIR, load_level
from game.levels.classes import SETTINGS
from game.levels.loader import check_level
from game.sim.world import World
from game.tools import art
from tests.campaign_run import campaign_played, pit_columns

SCRIPTS = Path(__file__).resolve().parent / "scripts"
SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))
# A hazard's mean colour is at least this far (Euclidean, in 0..255 RGB) from every safe
# tile's, in every place: about a quarter of the way across the colour cube's side.
MIN_HAZARD_DISTANCE = 64.0

RGBf = tuple[float, float, float]


def mean_colour(tile: pygame.Surface) -> RGBf:
    """The mean colour of a tile's opaque pixels."""
    pixels = [tile.get_at((x, y)) for x in range(tile.get_width())
              for y in range(tile.get_height())]
    seen = [p for p in pixels if p.a == 255]
    return (sum(p.r for p in seen) / len(seen), sum(p.g for p in seen) / len(seen),
            sum(p.b for p in seen) / len(seen))


def tile_image(sheet: pygame.Surface, tile_id: int) -> pygame.Surface:
    row, col = divmod(tile_id, art.TILESET_COLUMNS)
    return sheet.subsurface((col * art.TILE, row * art.TILE, art.TILE, art.TILE))


def hazard_distances() -> dict[str, float]:
    """For each place, the least distance between a hazard's mean colour and a safe tile's,
    the safe tiles of both tilesets (``tiles.png`` and the terrain's ``terrain.png``)."""
    sheet, terrain = art.draw_tileset(), art.draw_terrain_tileset()
    hazards = [tile_image(sheet, i) for i, kind in art.TILE_CLASSES.items() if kind == "Hazard"]
    safe = [tile_image(sheet, i) for i, kind in art.TILE_CLASSES.items()
            if kind in ("Solid", "OneWay")]
    safe += [tile_image(terrain, i) for i in art.TERRAIN_CLASSES]
    least = {}
    for name, place in PLACES.items():
        swap = place.ground_swap()
        hazard_means = [mean_colour(recolour(tile.copy(), swap)) for tile in hazards]
        safe_means = [mean_colour(recolour(tile.copy(), swap)) for tile in safe]
        least[name] = min(math.dist(h, s) for h in hazard_means for s in safe_means)
    return least


def test_hazards_differ_in_colour_from_every_safe_tile_in_every_place() -> None:
    least = hazard_distances()
    assert set(least) == set(SETTINGS)
    for name, distance in least.items():
        assert distance >= MIN_HAZARD_DISTANCE, f"{name}: spikes {distance:.1f} from a safe tile"


def test_the_twelve_shipped_levels_are_set_two_in_each_place() -> None:
    places = [place_of(load_level(path).properties).name for path in SHIPPED]
    assert sorted(places) == sorted(SETTINGS * 2)


def test_the_six_places_differ_in_sky_scenery_and_ground() -> None:
    skies = {pygame.image.tobytes(art.draw_place_sky(p), "RGB") for p in PLACES.values()}
    scenery = {pygame.image.tobytes(art.draw_place_scenery(p), "RGBA") for p in PLACES.values()}
    grounds = {p.ground for p in PLACES.values()}
    for place in PLACES.values():  # a swap done colour by colour must not swap twice
        swap = place.ground_swap()
        assert not set(swap.values()) & set(swap), place.name
    assert len(skies) == len(scenery) == len(grounds) == len(SETTINGS) == 6


def test_an_unknown_setting_is_an_error_that_lists_the_settings(tmp_path: Path) -> None:
    text = (LEVELS_DIR / "01-first-steps.tmx").read_text(encoding="utf-8")
    bad = tmp_path / "levels" / "bad.tmx"
    bad.parent.mkdir()
    (tmp_path / "assets").mkdir()
    for name in ("tiles.tsx", "tiles.png", "terrain.tsx", "terrain.png"):
        (tmp_path / "assets" / name).write_bytes((LEVELS_DIR.parent / "assets" / name).read_bytes())
    bad.write_text(text.replace('value="meadow"', 'value="moon"'), encoding="utf-8")
    findings = check_level(bad)
    messages = [str(error) for error in findings.errors]
    assert any("setting" in m and "'moon'" in m and "summit" in m for m in messages), messages


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_a_pit_in_view_shows_its_bottom_all_through_the_winning_run(level: Path) -> None:
    """Watched tick by tick in the campaign's one run by the winning scripts
    (tests/test_levels.py), which plays each level from its start by its own script."""
    assert pit_columns(load_level(level).grid), "every shipped level has a pit or a spike pit"
    played = campaign_played().levels[level.stem]
    assert played.pit_bottom_hidden == []
    assert played.pit_views > 0


DARK_LUMA = 60  # the brightest (0.299 r + 0.587 g + 0.114 b) a pit's darkness may be; the
# meadow's near hills are about 135, its sky over 150


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_below_the_floor_line_a_pit_shows_only_darkness(level: Path, assets: Assets) -> None:
    world = World(load_level(level, images=True))
    grid = world.level.grid
    floor_px = floor_line_px(grid)
    renderer = WorldRenderer(assets)
    target = pygame.display.get_surface()
    pits = pit_spans_px(grid, floor_px)
    if not pits:
        pytest.skip("no pit: every gap of this level has ground somewhere below it")
    drawn = {(col, row) for layer in (*world.level.layers, *world.level.foreground)
             for row, line in enumerate(layer.gids) for col, gid in enumerate(line) if gid}
    checked = 0
    for left, right in pits:
        world.camera.x = float(max(0, min(left - 100, grid.cols * grid.tile_w - 320)))
        world.camera.y = float(grid.rows * grid.tile_h - 180)
        renderer.draw(target, world, 0)
        boxes = [sprite.rect for sprite in renderer.sprites.sprites()]
        for x in range(left, right, 4):
            for y in range(floor_px + 1, grid.rows * grid.tile_h, 4):
                cell = (x // grid.tile_w, y // grid.tile_h)
                if cell in drawn or any(box.collidepoint(x, y) for box in boxes):
                    continue  # a tile or a sprite, not the background
                sx, sy = x - math.floor(world.camera.x), y - math.floor(world.camera.y)
                if 0 <= sx < 320 and 0 <= sy < 180:
                    colour = target.get_at((sx, sy))
                    luma = 0.299 * colour.r + 0.587 * colour.g + 0.114 * colour.b
                    assert luma <= DARK_LUMA, (level.stem, x, y, colour)
                    checked += 1
    assert checked > 0


def lowered_floor(grid: TileGrid, floor_px: int) -> dict[int, int]:
    """The columns whose ground is lower than the floor line: each with the row of its top."""
    floor_row = floor_px // grid.tile_h
    tops: dict[int, int] = {}
    for col in range(grid.cols):
        rows = [row for row in range(floor_row, grid.rows)
                if any(s.kind is TileKind.SOLID for s in grid.shapes_at(col, row))]
        if rows and rows[0] > floor_row:
            tops[col] = rows[0]
    return tops


def test_ground_lower_than_the_floor_line_is_drawn_over_scenery_not_the_pits_darkness(
        assets: Assets) -> None:
    level = LEVELS_DIR / "02-over-the-gaps.tmx"  # its floor steps down into dips
    world = World(load_level(level, images=True))
    grid = world.level.grid
    floor_px = floor_line_px(grid)
    lowered = lowered_floor(grid, floor_px)
    assert len(lowered) >= 10
    pits = pit_spans_px(grid, floor_px)
    assert not [col for col in lowered
                if any(left <= col * grid.tile_w < right for left, right in pits)]
    renderer = WorldRenderer(assets)
    target = pygame.display.get_surface()
    drawn = {(col, row) for layer in (*world.level.layers, *world.level.foreground)
             for row, line in enumerate(layer.gids) for col, gid in enumerate(line) if gid}
    world.camera.x = float((min(lowered) - 5) * grid.tile_w)  # the first dips in view
    world.camera.y = float(grid.rows * grid.tile_h - 180)
    renderer.draw(target, world, 0)
    checked = 0
    for col, top in lowered.items():
        for row in range(floor_px // grid.tile_h, top):  # the air above the lowered ground
            x, y = col * grid.tile_w + grid.tile_w // 2, row * grid.tile_h + grid.tile_h // 2
            sx, sy = x - math.floor(world.camera.x), y - math.floor(world.camera.y)
            if (col, row) in drawn or not (0 <= sx < 320 and 0 <= sy < 180):
                continue
            colour = target.get_at((sx, sy))
            assert 0.299 * colour.r + 0.587 * colour.g + 0.114 * colour.b > DARK_LUMA, (col, row)
            checked += 1
    assert checked >= 5
