"""The terrain tileset: Tiled can paint it, the shipped maps are painted with it, painting it
changed nothing that collides, and the 32-tile tileset that maps made before it rely on is as
it was. And the terrain tool: it repaints only maps inside the folder given, knows the game's
tilesets by what they hold, writes nothing that would collide otherwise or not load, says what
it changed, and leaves every map old or new, never in part, whatever it is given."""

from __future__ import annotations

import contextlib
import errno
import io
import os
import re
import shutil
import xml.etree.ElementTree as ET
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import Any

import pygame
import pytest

from game.levels import LEVELS_DIR, load_level
from game.tools import art, terrain
from tests.collision_grids import all_grids, collision_grid, shipped_maps
from tests.hang_guard import hang_guard

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
                       5: "OneWay", 6: "Hazard", 7: "Solid",  # as the first version had them
                       14: "Solid", 15: "Solid"}  # the dark stone and dirt, which look so


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
    level = load_level(path)
    assert terrain.repaint_text(spoiled, level.grid.cols, level.grid.rows, 1, 33) == (text, 1)


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


# -- The tool, on a pack of levels of its own (a folder outside any project) ------------------

TERRAIN_FIRST = 33  # where terrain.tsx starts in a map, after the 32 tiles of tiles.tsx
LONE = TERRAIN_FIRST + art.terrain_tile_id(0)  # the terrain's lone block: ground to repaint
PACK_GIDS = {"G": 1 + art.GROUND, "d": 1 + art.DIRT_FILL, "-": 1 + art.ONE_WAY,
             "^": 1 + art.SPIKES, "T": LONE}
PACK_ROWS = (
    "..........",
    "..........",
    "....---...",
    "..........",
    "GGGG..GGGG",
    "dddd^^dddd",
)
BOTH = ((1, "tiles.tsx"), (TERRAIN_FIRST, "terrain.tsx"))


def map_text(rows: Sequence[str] = PACK_ROWS,
             tilesets: Sequence[tuple[int, str]] = BOTH, encoding: str = "UTF-8",
             title: str = "A pack's level") -> str:
    """A map as Tiled saves it: the tilesets given, one tile layer, a Player and an Exit."""
    width, height = len(rows[0]), len(rows)
    data = ",\n".join(",".join(str(PACK_GIDS.get(char, 0)) for char in row) for row in rows)
    lines = "\n".join(f' <tileset firstgid="{first}" source="{source}"/>'
                      for first, source in tilesets)
    return f"""<?xml version="1.0" encoding="{encoding}"?>
<map version="1.8" tiledversion="1.8.2" orientation="orthogonal" renderorder="right-down" \
width="{width}" height="{height}" tilewidth="16" tileheight="16" infinite="0" \
nextlayerid="3" nextobjectid="3">
 <properties>
  <property name="title" value="{title}"/>
 </properties>
{lines}
 <layer id="1" name="ground" width="{width}" height="{height}">
  <data encoding="csv">
{data}
</data>
 </layer>
 <objectgroup id="2" name="objects">
  <object id="1" type="Player" x="16" y="48" width="12" height="14"/>
  <object id="2" type="Exit" x="130" y="32" width="16" height="32"/>
 </objectgroup>
</map>
"""


def make_pack(folder: Path, text: str | None = None, names: Sequence[str] = (
        "tiles.tsx", "tiles.png", "terrain.tsx", "terrain.png")) -> Path:
    """``folder/level.tmx`` beside copies of the game's tileset files ``names``."""
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        shutil.copy(ASSETS / name, folder / name)
    path = folder / "level.tmx"
    path.write_text(map_text() if text is None else text, encoding="utf-8")
    return path


def one_line(text: str) -> str:
    """The one line ``text`` holds (a message), failing if it holds more or a traceback."""
    assert text.count("\n") == 1 and text.endswith("\n"), text
    assert "Traceback" not in text
    return text.rstrip("\n")


def cell_gids(path: Path) -> list[int]:
    text = path.read_text(encoding="latin-1")
    data = text[text.index('<data encoding="csv">') + 21:text.index("</data>")]
    return [int(value) for value in data.replace("\n", "").split(",")]


@contextlib.contextmanager
def interrupted_writes(error: BaseException) -> Iterator[list[Path]]:
    """Every file opened for writing takes half of what is written into it (at most 4,096
    bytes), then ``error`` is raised, as Ctrl-C or a full disk would. Yields the files."""
    real_open = io.open
    opened: list[Path] = []

    class HalfWritten:
        def __init__(self, stream: Any) -> None:
            self.stream = stream

        def __enter__(self) -> HalfWritten:
            return self

        def __exit__(self, *exc: object) -> None:
            self.stream.close()

        def write(self, data: Any) -> int:
            self.stream.write(data[:min(4096, len(data) // 2)])
            self.stream.flush()
            raise error

    def half_open(file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
        stream = real_open(file, mode, *args, **kwargs)
        if "w" not in mode:
            return stream
        opened.append(Path(file))
        return HalfWritten(stream)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(io, "open", half_open)
        yield opened


def no_endless_wait(seconds: float = 60.0) -> contextlib.AbstractContextManager[None]:
    """Turn a wait on a pipe nobody writes to into a failure instead of a hung test run
    (the limit is a guard, not a measure: the tool must not open the pipe to wait at all)."""
    return hang_guard(seconds)


@pytest.mark.parametrize("leads_to", ["outside the folder", "inside the folder"])
def test_a_map_that_is_a_link_is_refused_and_what_it_leads_to_is_left_alone(
        tmp_path: Path, leads_to: str, capsys: pytest.CaptureFixture[str]) -> None:
    pack = tmp_path / "pack"
    target = make_pack(tmp_path / "elsewhere" if leads_to == "outside the folder" else pack)
    if leads_to == "inside the folder":
        target = target.rename(pack / "real.tmx")
    before = target.read_bytes()
    pack.mkdir(exist_ok=True)
    link = pack / "level.tmx"
    link.symlink_to(target)
    assert terrain.main([str(link)]) == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{link}: the map ")
    assert ("leads outside" if leads_to == "outside the folder" else "symbolic link") in error
    assert target.read_bytes() == before and link.is_symlink()


def test_ctrl_c_while_a_map_is_written_leaves_it_as_it_was_with_one_line_and_status_130(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = make_pack(tmp_path / "pack")
    before = path.read_bytes()
    with interrupted_writes(KeyboardInterrupt()) as opened:
        try:
            status: int | None = terrain.main([str(path)])
        except KeyboardInterrupt:  # not caught: a traceback, and whatever was half written
            status = None
    assert opened, "the tool wrote nothing, so nothing was interrupted"
    assert status == 130
    assert "Ctrl-C" in one_line(capsys.readouterr().err)
    assert path.read_bytes() == before
    assert sorted(p.name for p in path.parent.iterdir()) == [
        "level.tmx", "terrain.png", "terrain.tsx", "tiles.png", "tiles.tsx"]


def test_a_full_disk_leaves_the_map_as_it_was_with_one_sentence(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = make_pack(tmp_path / "pack")
    before = path.read_bytes()
    full = OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    with interrupted_writes(full) as opened:
        status = terrain.main([str(path)])
    assert opened and status == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: the repainted map cannot be written (")
    assert error.endswith("so it is left as it was — free some space")
    assert path.read_bytes() == before
    assert not [p for p in path.parent.iterdir() if p.name.startswith(".")]


def test_a_packs_own_tiles_tsx_is_not_taken_for_the_games(tmp_path: Path) -> None:
    pack = tmp_path / "pack"
    path = make_pack(pack, map_text(("TT........", "..........", "..........", "..........",
                                     "GGGGGGGGGG", "GGGGG....."), BOTH),
                     names=("tiles.png", "terrain.tsx", "terrain.png"))
    own = art.tileset_tsx().replace('<tile id="0" type="Solid"/>',
                                    '<tile id="0" type="Hazard"/>')  # its tile 0 hurts
    assert own != art.tileset_tsx()
    (pack / "tiles.tsx").write_text(own, encoding="utf-8")
    shutil.copy(path, pack / "before.tmx")  # loaded here, so that the map itself is not
    grid = collision_grid(pack / "before.tmx")  # a file this run has read before the tool
    assert terrain.main([str(path)]) == 0
    assert collision_grid(path) == grid
    gids = cell_gids(path)
    assert gids.count(1 + art.GROUND) == 15  # every cell of the pack's tile 0 stays as it was
    assert LONE not in gids[:2]  # the game's terrain tiles are still repainted


@pytest.mark.parametrize("terrain_tsx", ["missing", "the pack's own"])
def test_terrain_tsx_is_added_only_if_it_is_there_and_is_the_games(
        tmp_path: Path, terrain_tsx: str, capsys: pytest.CaptureFixture[str]) -> None:
    pack = tmp_path / "pack"
    path = make_pack(pack, map_text(tilesets=((1, "tiles.tsx"),)),
                     names=("tiles.tsx", "tiles.png"))
    if terrain_tsx == "the pack's own":
        shutil.copy(ASSETS / "terrain.png", pack / "terrain.png")
        (pack / "terrain.tsx").write_text(art.terrain_tsx().replace(
            '<tile id="0" type="Solid"/>', '<tile id="0" type="Hazard"/>'), encoding="utf-8")
    before = path.read_bytes()
    assert terrain.main([str(path)]) == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: its ground needs the terrain tileset")
    assert "'terrain.tsx'" in error and "Add External Tileset" in error
    assert path.read_bytes() == before
    load_level(path)  # and the map still loads


@pytest.mark.parametrize("pipe", ["a tileset", "the map"])
def test_a_pipe_is_refused_at_once_instead_of_waited_on(
        tmp_path: Path, pipe: str, capsys: pytest.CaptureFixture[str]) -> None:
    pack = tmp_path / "pack"
    path = make_pack(pack, map_text(tilesets=((1, "tiles.tsx"), (TERRAIN_FIRST, "props.tsx"))),
                     names=("tiles.tsx", "tiles.png"))
    if pipe == "the map":
        path.unlink()
    os.mkfifo(path if pipe == "the map" else pack / "props.tsx")
    with no_endless_wait():
        status = terrain.main([str(path)])
    assert status == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: ") and "not a regular file" in error
    if pipe == "a tileset":
        assert "props.tsx" in error


def blank_cell(folder: Path) -> Path:
    path = make_pack(folder)
    text = path.read_text(encoding="utf-8").replace(f"\n{PACK_GIDS['G']},", "\n,", 1)
    path.write_text(text, encoding="utf-8")
    return path


def latin1_undeclared(folder: Path) -> Path:
    path = make_pack(folder)
    path.write_bytes(map_text(title="Café").encode("latin-1"))  # but it says UTF-8
    return path


@pytest.mark.parametrize("make, says", [
    (blank_cell, "layer 'ground': the tile data holds '' where a tile id belongs"),
    (latin1_undeclared, "the XML of 'level.tmx' is damaged at line"),
    (lambda folder: folder / "missing.tmx", "the map does not exist"),
], ids=["a blank CSV cell", "a Latin-1 map that says it is UTF-8", "a missing map"])
def test_a_map_the_game_cannot_read_gets_one_sentence_and_is_left_alone(
        tmp_path: Path, make: Callable[[Path], Path], says: str,
        capsys: pytest.CaptureFixture[str]) -> None:
    path = make(tmp_path / "pack")
    before = path.read_bytes() if path.exists() else None
    assert terrain.main([str(path)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and one_line(err).startswith(f"{path}: {says}")
    assert (path.read_bytes() if path.exists() else None) == before


def test_a_latin1_map_is_repainted_and_stays_latin1(tmp_path: Path) -> None:
    path = make_pack(tmp_path / "pack")
    path.write_bytes(map_text(encoding="ISO-8859-1", title="Café").encode("latin-1"))
    assert terrain.main([str(path)]) == 0
    assert b'value="Caf\xe9"' in path.read_bytes()
    assert load_level(path).title == "Café"
    assert PACK_GIDS["G"] not in cell_gids(path)


def test_a_folder_stands_for_every_map_in_it_and_each_gets_a_line_saying_what_changed(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pack = tmp_path / "pack"
    first = make_pack(pack)
    second = make_pack(pack / "more")
    (pack / "notes.txt").write_text("not a map", encoding="utf-8")
    before = first.read_bytes(), second.read_bytes()
    assert terrain.main(["--check", str(pack)]) == 1
    would = capsys.readouterr().out.splitlines()
    assert (first.read_bytes(), second.read_bytes()) == before  # --check writes nothing
    ground = sum(char in "Gd-" for row in PACK_ROWS for char in row)
    assert would == [f"{path}: would repaint {ground} cells — run python -m game.tools.terrain "
                     "on it" for path in (first, second)]
    assert terrain.main([str(pack)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        f"{path}: repainted {ground} cells" for path in (first, second)]
    assert terrain.main(["--check", str(pack)]) == 0
    assert capsys.readouterr().out.splitlines() == [
        f"{path}: unchanged: its ground is painted with the terrain tiles"
        for path in (first, second)]


def test_the_line_says_when_the_terrain_tileset_was_added(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    path = make_pack(tmp_path / "pack", map_text(tilesets=((1, "tiles.tsx"),)))
    assert terrain.main([str(path)]) == 0
    line = one_line(capsys.readouterr().out)
    assert re.fullmatch(rf"{re.escape(str(path))}: repainted \d+ cells and added terrain.tsx "
                        rf"at gid {TERRAIN_FIRST}", line), line
    assert f'<tileset firstgid="{TERRAIN_FIRST}" source="terrain.tsx"/>' in path.read_text(
        encoding="utf-8")


def test_a_repaint_that_would_change_what_collides_is_not_written(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    path = make_pack(tmp_path / "pack")
    before = path.read_bytes()
    plank = art.PLANK_MIDDLE

    def planks_everywhere(rows: Sequence[Sequence[int]], tiles_first: int | None,
                          terrain_first: int) -> list[list[int]]:
        return [[terrain_first + plank if gid else 0 for gid in row] for row in rows]

    monkeypatch.setattr(terrain, "repaint_rows", planks_everywhere)
    assert terrain.main([str(path)]) == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: tile (0,4): repainting would change what collides there")
    assert path.read_bytes() == before


def test_a_map_saved_again_while_it_was_being_repainted_is_not_overwritten(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    path = make_pack(tmp_path / "pack")
    saved = map_text(title="Saved from Tiled while the tool ran")
    paint = terrain.paint

    def paint_then_save(map_path: Path, folder: Path) -> terrain.Painting:
        painting = paint(map_path, folder)
        map_path.write_text(saved, encoding="utf-8")
        return painting

    monkeypatch.setattr(terrain, "paint", paint_then_save)
    assert terrain.main([str(path)]) == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: the repainted map cannot be written (it changed on the "
                            "disk while it was being repainted)")
    assert path.read_text(encoding="utf-8") == saved


def test_a_folder_without_maps_is_bad_usage(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "notes.txt").write_text("not a map", encoding="utf-8")
    assert terrain.main([str(tmp_path)]) == 2
    assert one_line(capsys.readouterr().err) == (
        f"{tmp_path}: the folder holds no .tmx maps — give a map or a folder of maps")


def test_the_designers_guide_gives_the_terrain_tools_limits() -> None:
    guide = (LEVELS_DIR / "README.md").read_text(encoding="utf-8")
    section = guide[guide.index("### Repainting a map in one go"):guide.index("## Places")]
    assert f"at most {terrain.MAX_MAPS:,} maps, among at most " \
           f"{terrain.MAX_FOLDER_ENTRIES:,} names" in section.replace("\n  ", " ")
    assert f"{terrain.EXIT_INTERRUPTED} after Ctrl-C" in section


def test_a_tileset_outside_the_levels_sandbox_is_refused_and_the_map_left_alone(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    shared = tmp_path / "shared"  # beside the pack, but no project's assets/ folder
    make_pack(shared).unlink()
    path = make_pack(tmp_path / "pack", map_text(tilesets=(
        (1, "../shared/tiles.tsx"), (TERRAIN_FIRST, "../shared/terrain.tsx"))), names=())
    before = path.read_bytes()
    assert terrain.main([str(path)]) == 1
    error = one_line(capsys.readouterr().err)
    assert error.startswith(f"{path}: tileset '../shared/tiles.tsx': ")
    assert "leads outside the level's folder" in error
    assert path.read_bytes() == before
