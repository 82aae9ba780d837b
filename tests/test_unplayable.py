"""Maps that cannot be played as drawn are errors, each naming the place and the fix: a
Player, Exit or Checkpoint inside solid tiles or off any side of the map, and a class that
is a slip for one the game knows."""

from __future__ import annotations

from pathlib import Path

import pytest

from game.levels import LevelError, check_level, load_level
from tests.maps import write_tmx

OPEN = ["                ",
        "                ",
        " P           D  ",
        "################"]


def errors(path: Path) -> list[str]:
    return [str(error) for error in check_level(path).errors]


def warnings(path: Path) -> list[str]:
    return [str(warning) for warning in check_level(path).warnings]


def test_a_fair_map_has_no_errors(tmp_path: Path) -> None:
    assert errors(write_tmx(tmp_path, OPEN)) == []


def test_a_player_drawn_inside_a_wall_is_an_error(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, ["                ", "  #             ", "  P          D  ",
                                "################"])
    text = path.read_text(encoding="utf-8").replace('type="Player" x="32" y="32"',
                                                    'type="Player" x="34" y="20"')
    path.write_text(text, encoding="utf-8")
    with pytest.raises(LevelError, match=r"object #1 '': the Player starts inside a Solid"):
        load_level(path)


def test_an_exit_inside_solid_tiles_is_an_error(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" type="Exit" x="64" y="48" '
                                                   'width="16" height="16"/>')
    assert any("object #9 '': the Exit is inside Solid tiles" in e for e in errors(path))


@pytest.mark.parametrize(("x", "y", "side"), [(40, -40, "above"), (-40, 20, "left of"),
                                              (300, 20, "right of"), (40, 80, "below")])
def test_an_exit_off_any_side_of_the_map_is_an_error(tmp_path: Path, x: int, y: int,
                                                     side: str) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects=f'<object id="9" type="Exit" x="{x}" '
                                                   f'y="{y}" width="16" height="16"/>')
    assert any(f"object #9 '': the Exit is {side} the map" in e for e in errors(path))


def test_a_checkpoint_above_the_map_is_an_error_and_a_coin_there_a_warning(
        tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects=(
        '<object id="8" type="Checkpoint" x="40" y="-60" width="16" height="32"/>'
        '<object id="9" type="Coin" x="40" y="-30" width="8" height="8"/>'))
    assert any("object #8 '': the Checkpoint is above the map" in e for e in errors(path))
    assert any("object #9 '': warning: it is above the map" in w for w in warnings(path))


def test_a_player_above_the_map_is_an_error(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, [" " * 16, "             D  ", "#" * 16], extra_objects=(
        '<object id="9" type="Player" x="40" y="-60"/>'))
    assert any("object #9 '': the Player is above the map" in e for e in errors(path))


def test_a_misspelt_tile_class_names_the_tile_and_the_class_it_meant(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    tileset = tmp_path / "t.tsx"
    tileset.write_text(tileset.read_text(encoding="utf-8").replace('"Solid"', '"Soild"'),
                       encoding="utf-8")
    found = errors(path)
    assert any("t.tsx" in e and "tile 0: class 'Soild' is not a class the game knows; "
               "it looks like 'Solid' misspelt" in e and "set the tile's Class to Solid" in e
               for e in found), found


def test_a_misspelt_object_class_names_the_object_and_the_class_it_meant(
        tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" name="goal" type="Exitt" '
                                                   'x="200" y="32" width="16" height="16"/>')
    assert any("object #9 'goal': class 'Exitt' is not a class the game knows; it looks like "
               "'Exit' misspelt — set its Class to Exit" in e for e in errors(path))


def test_a_class_like_nothing_the_game_knows_stays_a_warning(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" type="Decoration" '
                                                   'x="200" y="32" width="16" height="16"/>')
    assert errors(path) == []
    assert any("class 'Decoration' means nothing to the game" in w for w in warnings(path))


def test_a_map_whose_classes_were_stripped_says_so_and_how_to_recover(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN)
    path.write_text(path.read_text(encoding="utf-8").replace(' type="Player"', "")
                    .replace(' type="Exit"', ""), encoding="utf-8")
    with pytest.raises(LevelError) as caught:
        load_level(path)
    message = str(caught.value)
    assert "none of the map's 2 objects has a Class" in message
    assert "Tiled 1.8 drops the classes" in message and "tile-hopper-1.8.tiled-project" in message
