"""The designer's mistakes that a map loads with are found by the checker, each at its place:
a next level that does not load, a Checkpoint drawn where the player cannot stand or on
spikes, a Platform whose path runs through a wall, a Coin no jump reaches, the game's objects
on a hidden layer, OneWay tiles painted upside down, ground painted with a tile that has no
class, and colliding tiles on a layer named as if it did not collide. Each map is built here
with its answer known: the place is asserted as the line says it and as the JSON gives it."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pygame
import pytest

from game.checker.checking import Finding, Options, check_map
from game.checker.solver import Effort, solve
from game.checker.verdict import Kind
from game.collision.shapes import TileKind
from game.levels import LEVELS_DIR, load_level
from game.levels.tiledata import FLIPPED_D, FLIPPED_V
from tests.maps import write_tmx

OPEN = ["                ",
        "                ",
        " P           D  ",
        "################"]
NO_SEARCH = Options(solve=False)


def lines(path: Path) -> list[str]:
    return [f.text for f in check_map(path, NO_SEARCH).findings]


def test_a_next_level_that_does_not_exist_is_an_error(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, properties={"next_level": ("file", "missing.tmx")})
    report = check_map(path, NO_SEARCH)
    assert report.bad
    (line,) = [t for t in lines(path) if "next_level" in t]
    assert "map property 'next_level': the next level missing.tmx does not exist" in line
    assert "warning" not in line


def test_a_next_level_that_does_not_load_is_an_error(tmp_path: Path) -> None:
    (tmp_path / "broken.tmx").write_text("<map>", encoding="utf-8")
    path = write_tmx(tmp_path, OPEN, properties={"next_level": ("file", "broken.tmx")})
    assert any("the next level broken.tmx does not load" in t for t in lines(path))


def found(path: Path, words: str) -> list[Finding]:
    return [f for f in check_map(path, NO_SEARCH).findings if words in f.text]


def test_a_checkpoint_drawn_into_the_ground_is_a_warning_at_the_flag(tmp_path: Path) -> None:
    """The finding names the flag, so Tiled's Issues panel selects the flag, not a tile. The
    game plays the map (the player comes back at the nearest free place): it is playable."""
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" name="cave" '
                     'type="Checkpoint" x="96" y="40" width="16" height="16"/>')
    (finding,) = found(path, "Checkpoint")
    assert ": object #9 'cave': warning: a player coming back to this Checkpoint would stand " \
        "inside" in finding.text
    assert finding.severity == "warning"
    assert finding.as_json()["object_id"] == 9
    assert not check_map(path, NO_SEARCH).bad


# A block one tile high in the way, jumped over on the way to the Exit.
BLOCKED = ["                ",
           "                ",
           " P      #    D  ",
           "################"]
THIN_POLE = ('<object id="9" name="pole" type="Checkpoint" x="145" y="16" width="4" '
             'height="32"/>')  # its respawn, 12 px wide round the pole, overlaps the block 3 px


def recorded_win(path: Path, folder: Path) -> Path:
    """A win of the map at ``path`` written as an input script (as --record writes one)."""
    solution = solve(load_level(path), Effort(budget=20_000))
    assert solution.found
    script = folder / "win.txt"
    script.write_text(solution.script(), encoding="utf-8")
    return script


def test_a_thin_pole_whose_respawn_a_block_moves_3_px_is_a_warning_a_recorded_win_overrules(
        tmp_path: Path) -> None:
    path = write_tmx(tmp_path, BLOCKED, extra_objects=THIN_POLE)
    report = check_map(path, Options(proof=recorded_win(path, tmp_path)))
    (finding,) = [f for f in report.findings if "would stand inside Solid tiles" in f.text]
    assert finding.severity == "warning" and finding.object_id == 9
    assert "(144, 34) instead of (141, 34)" in finding.text
    assert not report.bad and report.verdict is Kind.SOLVED


def lift(points: str, width: int = 32, height: int = 8) -> str:
    """A Platform object (id 5, 'lift') whose polyline starts at (0, 0) and goes on by
    ``points`` (relative, as Tiled writes them)."""
    return (f'<object id="5" name="lift" type="Platform" x="88" y="36"><properties>'
            f'<property name="width" type="float" value="{width}"/><property name="height" '
            f'type="float" value="{height}"/></properties><polyline points="0,0 {points}"/>'
            '</object>')


def test_a_respawn_a_lift_fills_at_the_start_is_playable_and_named_as_on_its_path(
        tmp_path: Path) -> None:
    """The lift starts in the place over the flag's foot and rises out of it: the game
    plays the map (the respawn is worked out when the flag counts), so it is a warning that
    names the danger, at the flag, and a recorded win proves the map."""
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" name="flag" '
                     'type="Checkpoint" x="96" y="16" width="16" height="32"/>'
                     + lift("0,-36"))
    report = check_map(path, Options(proof=recorded_win(path, tmp_path)))
    assert not report.bad and report.verdict is Kind.SOLVED
    (finding,) = [f for f in report.findings if "on the path of the moving Platform" in f.text]
    assert finding.severity == "warning" and (finding.object_id, finding.tile) == (9, (6, 2))
    assert "object #9 'flag': warning: a player coming back to this Checkpoint stands at tile " \
        "(6,2), on the path of the moving Platform (object #5 'lift')" in finding.text


def test_a_respawn_under_a_crusher_is_named_and_one_off_its_path_is_not(
        tmp_path: Path) -> None:
    """A crusher that comes down onto the floor over the flag's foot: a player coming back
    there while it does is crushed again at once, every life in a few ticks."""
    flag = ('<object id="9" name="flag" type="Checkpoint" x="96" y="16" width="16" '
            'height="32"/>')
    crusher = lift("0,4", width=32, height=8).replace('y="36"', 'y="0"').replace(
        "0,0 0,4", "0,0 0,32")
    path = write_tmx(tmp_path, OPEN, extra_objects=flag + crusher)
    (finding,) = found(path, "on the path of the moving Platform")
    assert finding.object_id == 9 and finding.tile == (6, 2)
    clear = write_tmx(tmp_path, OPEN, "clear.tmx", extra_objects=flag + crusher.replace(
        'x="88"', 'x="150"'))
    assert not found(clear, "on the path of the moving Platform")


def test_a_checkpoint_standing_on_the_ground_is_fine(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" type="Checkpoint" x="96" '
                                                   'y="16" width="16" height="32"/>')
    assert not check_map(path, NO_SEARCH).bad


def test_an_exit_on_a_hidden_layer_is_warned_about_in_tiles_words(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    text = path.read_text(encoding="utf-8").replace(
        "</map>", ' <objectgroup id="5" name="old ideas" visible="0">\n'
        '  <object id="20" name="first exit" type="Exit" x="32" y="32" width="16" '
        'height="16"/>\n </objectgroup>\n</map>')
    path.write_text(text, encoding="utf-8")
    (line,) = [t for t in lines(path) if "hidden" in t]
    assert "object #20 'first exit': warning: this Exit is on the hidden layer 'old ideas' " \
           "(its eye is off in the Layers panel), yet the game plays it" in line


def test_a_wall_painted_on_a_decoration_layer_is_named_when_it_closes_the_way(
        tmp_path: Path) -> None:
    path = write_tmx(tmp_path, ["################", *OPEN[1:]])  # a cave: a ceiling
    cols, rows = 16, 4
    wall = [[1 if col == 9 and 0 < row < 3 else 0 for col in range(cols)]
            for row in range(rows)]
    data = ",\n".join(",".join(map(str, row)) for row in wall)
    layer = (f' <layer id="7" name="background (no collision)" width="{cols}" '
             f'height="{rows}">\n  <data encoding="csv">\n{data}\n</data>\n </layer>\n')
    text = path.read_text(encoding="utf-8").replace(' <objectgroup', layer + ' <objectgroup')
    path.write_text(text, encoding="utf-8")
    (line,) = [t for t in lines_of(check_map(path, Options())) if "impossible" in t]
    assert "no open path joins the spawn and an Exit" in line
    assert "without the Solid tiles of layer 'background (no collision)' there would be a " \
           "way" in line


def lines_of(report: object) -> list[str]:
    return [f.text for f in getattr(report, "findings", [])]


def test_a_checkpoint_standing_on_spikes_is_warned_about_at_the_flag(tmp_path: Path) -> None:
    rows = ["                ", "                ", " P      ^    D  ", "################"]
    path = write_tmx(tmp_path, rows, extra_objects='<object id="9" name="spiky" '
                     'type="Checkpoint" x="128" y="16" width="16" height="32"/>')
    (finding,) = found(path, "lands on Hazard tiles")
    assert ": object #9 'spiky': warning: a player coming back to this Checkpoint lands on " \
           "Hazard tiles, at tile (8,2)," in finding.text
    assert (finding.object_id, finding.tile) == (9, (8, 2))


def test_a_checkpoint_above_spikes_it_falls_onto_is_warned_about(tmp_path: Path) -> None:
    rows = ["                ", "                ", " P      ^    D  ", "################"]
    path = write_tmx(tmp_path, rows, extra_objects='<object id="9" type="Checkpoint" x="128" '
                     'y="0" width="16" height="32"/>')  # its bottom edge on the spikes' top
    (finding,) = found(path, "lands on Hazard tiles")
    assert finding.tile == (8, 2)


def test_a_checkpoint_beside_the_spikes_is_not_warned_about(tmp_path: Path) -> None:
    rows = ["                ", "                ", " P    ^      D  ", "################"]
    path = write_tmx(tmp_path, rows, extra_objects='<object id="9" type="Checkpoint" x="128" '
                     'y="16" width="16" height="32"/>')
    assert found(path, "Hazard") == []


WALLED = ["                ",
          "          #     ",
          " P        #  D  ",
          "################"]


def platform(points: str, kind: str = "polyline") -> str:
    return (f'<object id="9" name="lift" type="Platform" x="32" y="8"><{kind} '
            f'points="{points}"/></object>')


def test_a_platform_whose_path_runs_through_a_wall_is_named_with_the_first_tile(
        tmp_path: Path) -> None:
    """The platform (48 x 8, hanging from the line at y 8 to 16) meets the wall of column
    10 at row 1 when it has gone 112 px."""
    path = write_tmx(tmp_path, WALLED, extra_objects=platform("0,8 200,8"))
    (finding,) = found(path, "Platform's path")
    assert ": object #9 'lift': warning: this Platform's path runs into Solid tiles, first at " \
           "tile (10,1):" in finding.text
    assert (finding.object_id, finding.tile) == (9, (10, 1))


def test_a_looping_path_is_swept_back_to_its_first_point(tmp_path: Path) -> None:
    """A polygon's last leg, back to its first point, is a leg too: here only that one,
    slanting down from over the wall, meets it."""
    path = write_tmx(tmp_path, WALLED, extra_objects=platform("0,16 0,-8 168,-8", "polygon"))
    (finding,) = found(path, "Platform's path")
    assert finding.tile == (10, 1)


def test_a_platform_over_the_wall_is_fine(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, WALLED, extra_objects=platform("0,-8 200,-8"))
    assert found(path, "Platform's path") == []


def test_a_coin_no_jump_reaches_is_warned_about_and_one_in_reach_is_not(tmp_path: Path) -> None:
    """The jump lifts the feet 44 px: a coin 80 px over the floor is out of reach, one 24 px
    over it is not."""
    rows = ["        C       ", "                ", "                ", "                ",
            "     C          ", " P           D  ", "################"]
    path = write_tmx(tmp_path, rows)  # the coins are objects #1 (high) and #2 (low)
    (finding,) = found(path, "no jump reaches")
    assert ": object #1 '': warning: no jump reaches this Coin" in finding.text
    assert finding.object_id == 1


def one_way_row(tmp_path: Path, flags: int) -> Path:
    rows = ["                ", "    ---         ", " P           D  ", "################"]
    path = write_tmx(tmp_path, rows)
    text = path.read_text(encoding="utf-8")
    text = re.sub(r"(?<=[,\n])2(?=,)", str(2 | flags), text)
    path.write_text(text, encoding="utf-8")
    return path


def test_one_way_planks_painted_flipped_as_a_ceiling_are_warned_about(tmp_path: Path) -> None:
    (finding,) = found(one_way_row(tmp_path, FLIPPED_V), "OneWay tile is painted")
    assert ": tile (4,1) in layer 'ground': warning: this OneWay tile is painted flipped " \
           "vertically, as a ceiling, yet a OneWay tile blocks only a body coming down onto " \
           "its top" in finding.text
    assert "(3 such tiles on this layer)" in finding.text
    assert (finding.tile, finding.layer) == ((4, 1), "ground")


def test_one_way_planks_turned_on_their_side_are_warned_about(tmp_path: Path) -> None:
    (finding,) = found(one_way_row(tmp_path, FLIPPED_D), "OneWay tile is painted")
    assert "painted turned on its side (rotated)" in finding.text


def test_one_way_planks_painted_upright_are_fine(tmp_path: Path) -> None:
    assert found(one_way_row(tmp_path, 0), "OneWay") == []


def looks_tileset(folder: Path) -> None:
    """A tileset of four 16 px tiles: 0 Solid ground, 1 dark dirt with no class (opaque),
    2 a flower with no class (see-through round it), 3 Solid."""
    sheet = pygame.Surface((64, 16), pygame.SRCALPHA)
    sheet.fill((120, 80, 40, 255), (0, 0, 16, 16))
    sheet.fill((60, 40, 20, 255), (16, 0, 16, 16))
    sheet.fill((200, 40, 40, 255), (38, 6, 4, 10))  # a stalk and bloom on clear pixels
    sheet.fill((120, 80, 40, 255), (48, 0, 16, 16))
    pygame.image.save(sheet, str(folder / "looks.png"))
    (folder / "looks.tsx").write_text(
        '<?xml version="1.0" encoding="UTF-8"?>\n<tileset version="1.8" name="looks" '
        'tilewidth="16" tileheight="16" tilecount="4" columns="4">\n'
        ' <image source="looks.png" width="64" height="16"/>\n'
        ' <tile id="0" type="Solid"/>\n <tile id="3" type="Solid"/>\n</tileset>\n',
        encoding="utf-8")


def looks_map(folder: Path, rows: list[str], layer: str = "ground") -> Path:
    """``rows`` in the looks tileset: ``#`` ground, ``d`` dark dirt, ``f`` a flower."""
    looks_tileset(folder)
    gids = {"#": 1, "d": 2, "f": 3}
    data = ",\n".join(",".join(str(gids.get(c, 0)) for c in row) for row in rows)
    return one_layer_map(folder / "looks.tmx", "looks.tsx", layer, len(rows[0]), len(rows), data)


def one_layer_map(path: Path, tileset: str, layer: str, width: int, height: int,
                  data: str) -> Path:
    """A map of one tile layer in ``tileset``, a Player at its left and an Exit at its right."""
    path.write_text(f"""<?xml version="1.0" encoding="UTF-8"?>
<map version="1.8" orientation="orthogonal" renderorder="right-down" width="{width}"
 height="{height}" tilewidth="16" tileheight="16" infinite="0">
 <tileset firstgid="1" source="{tileset}"/>
 <layer id="1" name="{layer}" width="{width}" height="{height}">
  <data encoding="csv">
{data}
</data>
 </layer>
 <objectgroup id="2" name="objects">
  <object id="1" type="Player" x="16" y="34" width="12" height="14"/>
  <object id="2" type="Exit" x="208" y="32" width="16" height="16"/>
 </objectgroup>
</map>
""", encoding="utf-8")
    return path


def test_ground_painted_with_a_tile_that_has_no_class_is_warned_about(tmp_path: Path) -> None:
    """Two dark dirt cells in the floor look like ground and let the player fall; the flower
    on the floor has see-through pixels round it, so it is decoration."""
    path = looks_map(tmp_path, ["              ", "              ", "   f          ",
                                "####dd########"])
    (finding,) = found(path, "looks like ground")
    assert ": tile (4,3) in layer 'ground': warning: tile 1 of tileset 'looks' looks like " \
           "ground (its picture fills the cell)" in finding.text
    assert "(2 such cells on this layer)" in finding.text
    assert "give the tile the class Solid in the Tileset Editor" in finding.text
    assert (finding.tile, finding.layer) == ((4, 3), "ground")


def test_a_tile_with_no_class_away_from_the_ground_is_not_called_ground(tmp_path: Path) -> None:
    path = looks_map(tmp_path, ["              ", "  d           ", "   f          ",
                                "##############"])
    assert found(path, "looks like ground") == []


def decor_layer(path: Path, name: str, cells: dict[tuple[int, int], int]) -> None:
    cols, rows = 16, 4
    data = ",\n".join(",".join(str(cells.get((col, row), 0)) for col in range(cols))
                      for row in range(rows))
    layer = (f' <layer id="7" name="{name}" width="{cols}" height="{rows}">\n'
             f'  <data encoding="csv">\n{data}\n</data>\n </layer>\n')
    text = path.read_text(encoding="utf-8").replace(' <objectgroup', layer + ' <objectgroup')
    path.write_text(text, encoding="utf-8")


@pytest.mark.parametrize("name", ["background (no collision)", "Decor", "far_backdrop",
                                  "scenery-2"])
def test_colliding_tiles_on_a_layer_named_as_decoration_are_warned_about_at_the_layer(
        tmp_path: Path, name: str) -> None:
    """Even where they close no way (a wall high up here), and counted by class."""
    path = write_tmx(tmp_path, OPEN)
    decor_layer(path, name, {(9, 0): 1, (10, 0): 1, (3, 1): 3})
    (finding,) = found(path, "its name says it does not collide")
    assert f": layer '{name}': warning: its name says it does not collide, yet it holds " \
           "tiles that do (2 Solid, 1 Hazard; the first at tile (9,0))" in finding.text
    assert (finding.layer, finding.tile, finding.object_id) == (name, (9, 0), None)


@pytest.mark.parametrize("name", ["ground 2", "debug", "backgrounds"])
def test_a_layer_not_named_as_decoration_may_collide(tmp_path: Path, name: str) -> None:
    path = write_tmx(tmp_path, OPEN)
    decor_layer(path, name, {(9, 0): 1})
    assert found(path, "its name says") == []


def test_a_decoration_layer_of_tiles_with_no_class_is_fine(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    decor_layer(path, "decor", {(9, 0): 4})  # tile 3 of t.tsx: no class
    assert found(path, "its name says") == []


def test_the_shipped_dark_stone_and_dark_dirt_are_ground(tmp_path: Path) -> None:
    """Tiles 14 and 15 of assets/tiles.tsx look like ground (their pictures fill the cell),
    so a floor painted with them holds the player up, and is not called classless."""
    (tmp_path / "assets").mkdir()
    (tmp_path / "levels").mkdir()
    for name in ("tiles.tsx", "tiles.png"):
        shutil.copy(LEVELS_DIR.parent / "assets" / name, tmp_path / "assets" / name)
    floor = ["1"] * 6 + ["15", "16"] + ["1"] * 8  # tile 0 is ground; gid 15 is tile 14
    data = ",\n".join([",".join(["0"] * 16)] * 3 + [",".join(floor)])
    path = one_layer_map(tmp_path / "levels" / "dark.tmx", "../assets/tiles.tsx", "ground",
                         16, 4, data)
    assert found(path, "looks like ground") == []
    kinds = {(s.col, s.row): s.kind for s in load_level(path).grid.shapes()}
    assert kinds[(6, 3)] is kinds[(7, 3)] is TileKind.SOLID
