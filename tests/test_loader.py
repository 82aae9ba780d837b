"""The Tiled loader, one rule per test: each pytmx 3.32 trap, each refusal and its fix.

Every map here is a few lines of TMX written by :func:`write_map`, so each test shows the
exact Tiled construct it is about.
"""

from __future__ import annotations

import base64
import os
import shutil
import zlib
from pathlib import Path

import pytest

from game.app import cli
from game.checker.cli import main as levels_main
from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.levels import LEVELS_DIR, LevelError, check_level, load_level
from game.sim.inputs import Action
from game.sim.level import Level
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.hang_guard import HANG_S, hang_guard
from tests.in_process import Ran, call_main

TILESET = """<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="4"
 columns="4">{image}
 <tile id="0" type="Solid"/>
 <tile id="1" class="OneWay"/>
 <tile id="2" type="Hazard"><objectgroup><object id="1" x="1" y="8" width="14" height="8"/>
 </objectgroup></tile>
</tileset>"""
GROUND = "0,0,0,0,\n0,0,0,0,\n1,1,1,1"
OBJECTS = """<objectgroup id="9" name="objects">
 <object id="1" name="hero" type="Player" x="2" y="2"><point/></object>
 <object id="2" type="Exit" x="48" y="16" width="16" height="16"/>
</objectgroup>"""


def layer(data: str = GROUND, name: str = "ground", attrs: str = "",
          encoding: str = 'encoding="csv"') -> str:
    return (f'<layer name="{name}" width="4" height="3" {attrs}>'
            f"<data {encoding}>{data}</data></layer>")


def write_map(folder: Path, body: str = "", *, tileset: str = TILESET.format(image=""),
              objects: str = OBJECTS, map_attrs: str = "", name: str = "level.tmx") -> Path:
    """A 4x3 map of 16 px tiles: ``body`` (layers) then ``objects``; a floor by default."""
    body = body or layer()
    attrs = map_attrs or 'orientation="orthogonal" width="4" height="3" tilewidth="16" ' \
                         'tileheight="16" infinite="0"'
    path = folder / name
    path.write_text(f'<?xml version="1.0" encoding="UTF-8"?>\n<map version="1.8" {attrs}>\n'
                    f'{tileset}\n{body}\n{objects}\n</map>\n', encoding="utf-8")
    return path


def refusal(path: Path) -> str:
    with pytest.raises(LevelError) as caught:
        load_level(path)
    message = str(caught.value)
    assert message.startswith(f"{path}: ") and " — " in message
    return message


def solids(level: Level) -> set[tuple[int, int, TileKind]]:
    return {(shape.col, shape.row, shape.kind) for shape in level.grid.shapes()}


# --- the shape of a map ------------------------------------------------------------------

def test_a_small_map_loads_its_floor_spawn_and_exit(tmp_path: Path) -> None:
    level = load_level(write_map(tmp_path))
    assert solids(level) == {(col, 2, TileKind.SOLID) for col in range(4)}
    assert level.spawn == Box(2, 2, Tuning().player_width_px, Tuning().player_height_px)
    assert level.exits == (Box(48, 16, 16, 16),)


def test_layers_keep_document_order_across_kinds_and_inside_groups(tmp_path: Path) -> None:
    body = (layer(name="back") + '<group name="g" offsetx="0.5">'
            + layer("0,0,0,0,0,0,0,0,0,0,0,0", "inner") + "</group>")  # drawn only: offset kept
    objects = OBJECTS + '<group name="top">' + layer("0,0,0,0,0,0,0,0,0,0,0,0", "front") + \
        "</group>"
    level = load_level(write_map(tmp_path, body, objects=objects))
    assert [tiles.name for tiles in level.layers] == ["back", "inner"]
    assert [tiles.name for tiles in level.foreground] == ["front"]
    assert level.layers[1].offset == (0.5, 0.0)


def test_tiles_in_a_layer_inside_a_group_collide(tmp_path: Path) -> None:
    body = '<group name="g">' + layer("0,0,0,0,0,0,0,0,0,2,0,0") + "</group>"
    assert solids(load_level(write_map(tmp_path, body))) == {(1, 2, TileKind.ONE_WAY)}


SUNK_EXIT = """<objectgroup id="9" name="objects">
 <object id="1" name="hero" type="Player" x="2" y="18"><point/></object>
 <object id="2" type="Exit" x="48" y="24" width="16" height="16"/>
</objectgroup>"""  # an Exit half sunk into the floor of row 2


@pytest.mark.parametrize("copies", [1, 2])
def test_a_floor_painted_on_identical_layers_counts_once(tmp_path: Path, copies: int) -> None:
    """The same floor painted on two layers is one floor: an Exit half sunk into it is
    touched by walking right, as it is with one layer (the cells' shapes are not doubled)."""
    body = "".join(layer(name=f"ground {n}") for n in range(copies))
    path = write_map(tmp_path, body, objects=SUNK_EXIT)
    assert check_level(path).errors == []
    level = load_level(path)
    assert sorted((s.col, s.row, s.box) for s in level.grid.shapes()) == [
        (col, 2, Box(col * 16, 32, 16, 16)) for col in range(4)]
    world = World(level)
    won = any(event.kind is EventKind.EXIT for _ in range(120)
              for event in world.step(frozenset({Action.RIGHT})))
    assert won


def test_an_infinite_map_is_refused_with_the_map_properties_fix(tmp_path: Path) -> None:
    attrs = 'orientation="orthogonal" width="4" height="3" tilewidth="16" tileheight="16" ' \
            'infinite="1"'
    message = refusal(write_map(tmp_path, map_attrs=attrs))
    assert "infinite maps are not supported" in message and "Map Properties" in message


def test_chunked_tile_data_is_refused_as_an_infinite_map(tmp_path: Path) -> None:
    chunk = '<chunk x="0" y="0" width="4" height="3">' + GROUND + "</chunk>"
    message = refusal(write_map(tmp_path, layer(chunk)))
    assert "layer 'ground'" in message and "Infinite" in message


@pytest.mark.parametrize("orientation", ["isometric", "staggered", "hexagonal"])
def test_a_non_orthogonal_map_is_refused(tmp_path: Path, orientation: str) -> None:
    attrs = f'orientation="{orientation}" width="4" height="3" tilewidth="16" tileheight="16"'
    assert f"{orientation} maps are not supported" in refusal(write_map(tmp_path,
                                                                        map_attrs=attrs))


@pytest.mark.parametrize("size", ["0\" height=\"0", "100000\" height=\"100000"])
def test_a_map_of_no_tiles_or_of_far_too_many_is_refused(tmp_path: Path, size: str) -> None:
    attrs = f'orientation="orthogonal" width="{size}" tilewidth="16" tileheight="16"'
    assert "outside the playable size" in refusal(write_map(tmp_path, map_attrs=attrs))


def test_too_many_tiles_over_all_layers_are_refused_before_any_is_read(tmp_path: Path
                                                                       ) -> None:
    attrs = 'orientation="orthogonal" width="500" height="500" tilewidth="16" tileheight="16"'
    body = "".join(f'<layer name="l{i}" width="500" height="500"><data encoding="csv"/>'
                   "</layer>" for i in range(5))
    assert "more than the 1,000,000 tiles" in refusal(write_map(tmp_path, body,
                                                                map_attrs=attrs))


MANY = {
    "tilesets": '<tileset firstgid="{i}" name="t" tilewidth="16" tileheight="16"/>' * 1_001,
    "layers": '<objectgroup name="o{i}"/>' * 1_001,
    "objects": "<objectgroup>" + '<object type="Coin" x="1" y="1"/>' * 20_001 + "</objectgroup>",
}


@pytest.mark.parametrize("what", sorted(MANY))
def test_absurdly_many_tilesets_layers_or_objects_are_refused_by_count(tmp_path: Path,
                                                                       what: str) -> None:
    with hang_guard():
        message = refusal(write_map(tmp_path, MANY[what].replace("{i}", "1") + layer()))
    assert f"{what}, more than the" in message


@pytest.mark.parametrize("where", ["map", "tileset"])
def test_a_tile_size_of_0_is_refused(tmp_path: Path, where: str) -> None:
    if where == "map":
        attrs = 'orientation="orthogonal" width="4" height="3" tilewidth="0" tileheight="16"'
        path = write_map(tmp_path, map_attrs=attrs)
    else:
        path = write_map(tmp_path, tileset=TILESET.format(image="").replace(
            'tilewidth="16"', 'tilewidth="0"'))
    assert "tile size" in refusal(path)


# --- tile data ----------------------------------------------------------------------------

@pytest.mark.parametrize("data", ["0,0,0,0,0,0,0,0,1,1,1", "0,0,0,0,0,0,0,0,1,1,1,1,1"])
def test_too_little_or_too_much_layer_data_is_refused(tmp_path: Path, data: str) -> None:
    message = refusal(write_map(tmp_path, layer(data)))
    assert "layer 'ground'" in message and "where 12 belong" in message


def test_base64_data_that_inflates_beyond_the_layer_is_refused(tmp_path: Path) -> None:
    bomb = base64.b64encode(zlib.compress(bytes(4 * 1_000_000))).decode()
    message = refusal(write_map(tmp_path, layer(bomb, encoding='encoding="base64" '
                                                              'compression="zlib"')))
    assert "more than 12" in message


def test_zstd_tile_data_is_refused_naming_the_tile_layer_format(tmp_path: Path) -> None:
    path = write_map(tmp_path, layer("KLUv/QBYYQAAAQ==", encoding='encoding="base64" '
                                                                'compression="zstd"'))
    message = refusal(path)
    assert "zstd" in message and "Tile Layer Format" in message


def test_the_hexagonal_rotation_bit_is_masked(tmp_path: Path) -> None:
    data = f"0,0,0,0,0,0,0,0,{0x10000001},{0x90000001},1,1"
    assert solids(load_level(write_map(tmp_path, layer(data)))) == {
        (col, 2, TileKind.SOLID) for col in range(4)}


def test_a_tile_id_in_no_tileset_names_its_cell(tmp_path: Path) -> None:
    message = refusal(write_map(tmp_path, layer("0,0,0,0,0,0,0,0,1,1,1,99")))
    assert "tile (3,2) in layer 'ground'" in message and "99" in message


def test_a_flipped_tile_flips_its_collision_rectangle(tmp_path: Path) -> None:
    upside_down = 3 | 0x40000000  # the Hazard tile, whose spikes fill its lower half
    level = load_level(write_map(tmp_path, layer(f"0,0,0,0,0,{upside_down},0,0,1,1,1,1")))
    [spikes] = [s for s in level.grid.shapes() if s.kind is TileKind.HAZARD]
    assert spikes.box == Box(16 + 1, 16 + 0, 14, 8)


# --- tilesets ----------------------------------------------------------------------------

def test_overlapping_firstgid_ranges_are_refused(tmp_path: Path) -> None:
    second = TILESET.format(image="").replace('firstgid="1" name="t"', 'firstgid="3" name="u"')
    message = refusal(write_map(tmp_path, tileset=TILESET.format(image="") + second))
    assert "tileset 'u'" in message and "1-4" in message


def test_a_tsx_passed_as_the_map_is_refused(tmp_path: Path) -> None:
    tsx = tmp_path / "t.tsx"
    tsx.write_text(TILESET.format(image="").replace('firstgid="1" ', ""), encoding="utf-8")
    assert "this is a tileset (.tsx), not a map" in refusal(tsx)


@pytest.mark.parametrize("name", ["level.tmj", "level.json"])
def test_a_json_map_is_refused_with_save_as_tmx_advice(tmp_path: Path, name: str) -> None:
    path = tmp_path / name
    path.write_text('{"type": "map", "orientation": "orthogonal"}', encoding="utf-8")
    assert "JSON" in refusal(path) and ".tmx" in refusal(path)


def test_a_json_tileset_is_refused_with_save_as_tsx_advice(tmp_path: Path) -> None:
    (tmp_path / "t.tsj").write_text("{}", encoding="utf-8")
    message = refusal(write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsj"/>'))
    assert "JSON" in message and ".tsx" in message


def test_a_tileset_outside_the_levels_folder_is_refused(tmp_path: Path) -> None:
    (tmp_path / "elsewhere").mkdir()
    (tmp_path / "elsewhere" / "t.tsx").write_text(TILESET.format(image=""))
    (tmp_path / "maps").mkdir()
    path = write_map(tmp_path / "maps", tileset='<tileset firstgid="1" '
                                                'source="../elsewhere/t.tsx"/>')
    assert "outside the level's folder" in refusal(path)


def test_a_project_map_may_use_the_projects_assets_folder(tmp_path: Path) -> None:
    for folder in ("levels", "assets"):
        (tmp_path / folder).mkdir()
    (tmp_path / "assets" / "t.tsx").write_text(TILESET.format(image="").replace(
        'firstgid="1" ', ""))
    path = write_map(tmp_path / "levels", tileset='<tileset firstgid="1" '
                                                  'source="../assets/t.tsx"/>')
    assert len(solids(load_level(path))) == 4


def test_a_tileset_image_without_width_and_height_loads(tmp_path: Path) -> None:
    image = '<image source="missing.png"/>'
    level = load_level(write_map(tmp_path, tileset=TILESET.format(image=image)))
    assert len(solids(level)) == 4


def test_headless_loading_needs_no_image_but_the_checker_reports_it(tmp_path: Path) -> None:
    image = '<image source="missing.png" width="64" height="16"/>'
    path = write_map(tmp_path, tileset=TILESET.format(image=image))
    assert len(solids(load_level(path))) == 4
    [error] = check_level(path).errors
    assert "missing.png is missing" in str(error) and "tileset 't'" in str(error)


def test_an_unreadable_image_is_reported_by_the_checker(tmp_path: Path) -> None:
    (tmp_path / "tiles.png").write_bytes(b"not a png at all")
    image = '<image source="tiles.png" width="64" height="16"/>'
    [error] = check_level(write_map(tmp_path, tileset=TILESET.format(image=image))).errors
    assert "tiles.png is not a PNG, GIF, BMP or JPEG image" in str(error)


def test_embedded_collision_shapes_make_no_phantom_layer_nor_clobber_ids(tmp_path: Path
                                                                         ) -> None:
    level = load_level(write_map(tmp_path, layer("0,0,0,0,0,0,0,0,1,1,3,1")))
    assert [tiles.name for tiles in level.layers] == ["ground"]
    assert level.spawn.x == 2 and len(level.exits) == 1  # object #1 is still the Player
    [spikes] = [s for s in level.grid.shapes() if s.kind is TileKind.HAZARD]
    assert spikes.box == Box(32 + 1, 32 + 8, 14, 8)


# --- classes and properties -------------------------------------------------------------

@pytest.mark.parametrize("attr", ["type", "class", "TYPE", "Class"])
def test_the_class_is_read_from_type_or_class_in_any_case(tmp_path: Path, attr: str) -> None:
    tileset = TILESET.format(image="").replace('type="Solid"', f'{attr}="SOLID"')
    objects = OBJECTS.replace('type="Player"', f'{attr.lower()}="player"')
    assert len(solids(load_level(write_map(tmp_path, tileset=tileset, objects=objects)))) == 4


def test_custom_properties_named_type_name_or_id_load(tmp_path: Path) -> None:
    props = "".join(f'<property name="{name}" value="x"/>' for name in ("type", "name", "id"))
    objects = OBJECTS.replace("<point/>", f"<properties>{props}</properties><point/>")
    body = layer().replace("<data", f"<properties>{props}</properties><data")
    assert load_level(write_map(tmp_path, body, objects=objects)).spawn.x == 2


def test_list_and_class_properties_load(tmp_path: Path) -> None:
    props = ('<property name="tags" type="list"><item type="int" value="1"/>'
             '<item type="list"><item type="bool" value="true"/></item></property>'
             '<property name="body" type="class" propertytype="Body"><properties>'
             '<property name="mass" type="float" value="2"/></properties></property>')
    objects = OBJECTS.replace("<point/>", f"<properties>{props}</properties><point/>")
    map_props = f"<properties>{props}</properties>"
    level = load_level(write_map(tmp_path, map_props + layer(), objects=objects))
    assert level.properties["tags"] == [1, [True]]
    assert level.properties["body"] == {"mass": 2.0}


def test_class_defaults_apply_coin_value_1_and_the_games_enemy_speed(tmp_path: Path) -> None:
    objects = OBJECTS.replace("</objectgroup>", (
        '<object id="3" type="Coin" x="20" y="8" width="8" height="8"/>'
        '<object id="4" type="Coin" x="30" y="8"><properties><property name="value" '
        'value="5"/></properties><point/></object>'
        '<object id="5" type="Enemy" x="40" y="20" width="14" height="12"/></objectgroup>'))
    level = load_level(write_map(tmp_path, objects=objects))
    assert [coin.value for coin in level.coins] == [1, 5]  # "5" typed as a string still counts
    assert [enemy.speed_px_s for enemy in level.enemies] == [Tuning().enemy_speed_px_s]


def test_every_broken_object_is_listed_by_the_checker(tmp_path: Path) -> None:
    objects = OBJECTS.replace("</objectgroup>", (
        '<object id="3" name="a" type="Coin" x="20" y="8"><properties><property '
        'name="value" value="lots"/></properties><point/></object>'
        '<object id="4" name="b" type="Exit" x="30" y="8"><point/></object>'
        '<object id="5" name="c" type="Enemy" x="40" y="8"><properties><property '
        'name="kind" value="flyer"/></properties><point/></object></objectgroup>'))
    findings = check_level(write_map(tmp_path, objects=objects))
    places = [error.where for error in findings.errors]
    assert places == ["object #3 'a'", "object #4 'b'", "object #5 'c'"]


@pytest.mark.parametrize("value", ["nan", "inf", "-1e400"])
def test_a_non_finite_position_is_refused(tmp_path: Path, value: str) -> None:
    message = refusal(write_map(tmp_path, objects=OBJECTS.replace('x="48"', f'x="{value}"')))
    assert "object #2" in message and "not a finite number" in message


def test_an_object_template_is_resolved_and_the_instance_wins(tmp_path: Path) -> None:
    (tmp_path / "coin.tx").write_text(
        '<template><object type="Coin" width="8" height="8"><properties><property '
        'name="value" type="int" value="3"/></properties></object></template>')
    objects = OBJECTS.replace("</objectgroup>", (
        '<object id="3" template="coin.tx" x="20" y="8"/>'
        '<object id="4" template="coin.tx" x="30" y="8"><properties><property name="value" '
        'type="int" value="9"/></properties></object></objectgroup>'))
    level = load_level(write_map(tmp_path, objects=objects))
    assert [(coin.box, coin.value) for coin in level.coins] == [
        (Box(20, 8, 8, 8), 3), (Box(30, 8, 8, 8), 9)]


def test_a_tile_object_takes_its_tiles_class_and_stands_on_its_corner(tmp_path: Path) -> None:
    tileset = TILESET.format(image="").replace("</tileset>", '<tile id="3" type="Coin"/>'
                                                             "</tileset>")
    objects = OBJECTS.replace("</objectgroup>", '<object id="3" gid="4" x="16" y="32" '
                                                'width="8" height="8"/></objectgroup>')
    level = load_level(write_map(tmp_path, tileset=tileset, objects=objects))
    assert [coin.box for coin in level.coins] == [Box(16, 24, 8, 8)]


def test_an_object_layers_offset_moves_its_objects(tmp_path: Path) -> None:
    objects = OBJECTS.replace('name="objects"', 'name="objects" offsetx="3.5" offsety="-1"')
    assert load_level(write_map(tmp_path, objects=objects)).spawn[:2] == (5.5, 1.0)


def test_an_image_layer_without_an_image_loads_with_a_warning(tmp_path: Path) -> None:
    path = write_map(tmp_path, '<imagelayer name="sky"/>' + layer())
    assert load_level(path).layers[0].name == "ground"
    findings = check_level(path)
    assert not findings.errors
    assert any("image layers" in str(warning) for warning in findings.warnings)


def test_a_map_without_a_player_names_the_fix(tmp_path: Path) -> None:
    message = refusal(write_map(tmp_path, objects='<objectgroup name="o"/>'))
    assert "no Player object" in message and "Class 'Player'" in message


def test_a_missing_next_level_is_a_warning_not_an_error(tmp_path: Path) -> None:
    props = '<properties><property name="next_level" type="file" value="nope.tmx"/>' \
            "</properties>"
    findings = check_level(write_map(tmp_path, props + layer()))
    assert not findings.errors
    assert [w.where for w in findings.warnings] == ["map property 'next_level'"]


@pytest.mark.parametrize(("value", "ok"), [("450", True), ("-5", False), ("fast", False)])
def test_physics_properties_are_checked(tmp_path: Path, value: str, ok: bool) -> None:
    props = f'<properties><property name="gravity" value="{value}"/></properties>'
    path = write_map(tmp_path, props + layer())
    if ok:
        assert load_level(path).properties["gravity"] == 450.0
    else:
        assert "map property 'gravity'" in refusal(path)


# --- the checker's command line -----------------------------------------------------------

def checker(*paths: Path) -> Ran:
    """The checker on ``paths``, without its search for a route (tests/test_solver.py),
    called in this process (tests/test_levels.py starts the program itself)."""
    return call_main(levels_main, ["check", "--no-solve", "--jobs", "1", *paths],
                     hang_s=HANG_S)


def test_the_checker_answers_every_kind_of_bad_path_in_one_sentence(tmp_path: Path) -> None:
    garbage = tmp_path / "garbage.tmx"
    garbage.write_bytes(bytes(range(256)) * 8)
    huge = tmp_path / "huge.tmx"
    with huge.open("wb") as stream:
        stream.truncate(40 * 2**20)  # sparse: large, yet costs no disk
    pipe = tmp_path / "pipe.tmx"
    os.mkfifo(pipe)
    empty_folder = tmp_path / "nothing here"
    empty_folder.mkdir()
    damaged = tmp_path / "damaged.tmx"
    damaged.write_text("<map><layer>")
    bad = [garbage, huge, pipe, empty_folder, damaged, tmp_path / "missing.tmx"]
    result = checker(*bad)
    *lines, summary = result.stdout.splitlines()
    assert result.returncode == 1 and "Traceback" not in result.stdout + result.stderr
    assert [line.split(": ")[0] for line in lines] == [str(path) for path in bad]
    assert summary.startswith(f"checked {len(bad)} map(s): {len(bad)} not playable")
    assert all(" — " in line for line in lines)


@pytest.mark.parametrize("encoding", ["x-unknown", "utf-32", "utf-16"])
def test_an_xml_encoding_python_cannot_read_is_refused(tmp_path: Path, encoding: str) -> None:
    path = tmp_path / "level.tmx"
    path.write_text(f'<?xml version="1.0" encoding="{encoding}"?><map/>')
    assert "level.tmx" in refusal(path)


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads every file")
def test_the_checker_reports_a_map_it_may_not_read(tmp_path: Path) -> None:
    path = write_map(tmp_path)
    path.chmod(0)
    result = checker(path)
    assert result.returncode == 1 and "Permission denied" in result.stdout


def test_warnings_do_not_change_the_checkers_exit_status(tmp_path: Path) -> None:
    objects = OBJECTS.replace("</objectgroup>", '<object id="3" type="Sign" x="1" y="1"/>'
                                                "</objectgroup>")
    path = write_map(tmp_path, objects=objects)
    result = checker(path)
    assert result.returncode == 0
    assert result.stdout.splitlines()[:-1] == [
        f"{path}: object #3 '': warning: class 'Sign' means nothing to the game — use one of "
        "Player, Coin, Enemy, Exit, Checkpoint, Platform, or clear the class for notes"]
    assert result.stdout.splitlines()[-1].startswith("checked 1 map(s): all playable;")


def test_a_folder_stands_for_the_maps_inside_it(tmp_path: Path) -> None:
    write_map(tmp_path, name="a.tmx")
    write_map(tmp_path, objects="", name="b.tmx")
    result = checker(tmp_path)
    assert result.returncode == 1
    assert result.stdout.startswith(f"{tmp_path / 'b.tmx'}: this map has no Player object")
    assert "checked 2 map(s): 1 not playable" in result.stdout


def test_a_headless_run_needs_no_tile_images_but_the_checker_does(tmp_path: Path) -> None:
    shutil.copytree(LEVELS_DIR, tmp_path / "levels")
    shutil.copytree(LEVELS_DIR.parent / "assets", tmp_path / "assets")
    (tmp_path / "assets" / "tiles.png").unlink()
    level = tmp_path / "levels" / "01-first-steps.tmx"
    run = call_main(cli.main, ["--headless", "--ticks", "5", "--level", level])
    assert run.returncode == 0, run.stderr
    result = checker(level)
    assert result.returncode == 1 and "tiles.png is missing" in result.stdout
