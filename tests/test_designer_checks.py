"""The designer's mistakes that a map loads with are found by the checker, each at its place:
a next level that does not load, a Checkpoint drawn where the player cannot stand, and the
game's objects on a hidden layer."""

from __future__ import annotations

from pathlib import Path

from game.levels.checking import Options, check_map
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


def test_a_checkpoint_drawn_into_the_ground_is_an_error_at_its_tile(tmp_path: Path) -> None:
    path = write_tmx(tmp_path, OPEN, extra_objects='<object id="9" type="Checkpoint" x="96" '
                                                   'y="40" width="16" height="16"/>')
    (line,) = [t for t in lines(path) if "Checkpoint" in t]
    assert ": tile (6,2): a player coming back to this Checkpoint would stand inside" in line


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
