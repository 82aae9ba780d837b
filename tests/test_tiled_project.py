"""The game's classes in Tiled: the committed project files are the generated ones, and
Tiled (1.8.2 here) and pytmx both read them."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest
import pytmx

from game.checker.cli import main as levels_main
from game.levels import LEVELS_DIR
from game.levels.classes import CLASSES, find
from game.levels.project import (
    OBJECT_TYPES_FILE,
    PROJECT_FILE,
    PROJECT_FILE_1_8,
    PROPERTY_TYPES_FILE,
    generated_files,
)
from game.sim.tuning import Tuning
from tests.in_process import call_main
from tests.maps import HOP_OVER, write_tmx

TILED = shutil.which("tiled")


def test_the_committed_tiled_files_are_the_generated_ones() -> None:
    for path, text in generated_files().items():
        assert path.read_text(encoding="utf-8") == text, (
            f"{path.name} is stale: run python -m game.levels types --write")


def test_the_types_command_reports_up_to_date_files() -> None:
    result = call_main(levels_main, ["types"])
    assert result.returncode == 0 and result.stdout == ""


def test_the_project_has_every_class_and_no_object_types_for_tiled_1_9_to_import() -> None:
    project = json.loads(PROJECT_FILE.read_text(encoding="utf-8"))
    assert {"automappingRulesFile", "commands", "extensionsPath", "folders",
            "objectTypesFile", "propertyTypes"} <= set(project)
    assert "." in project["folders"]
    assert project["objectTypesFile"] == ""  # else Tiled 1.9+ imports it over the classes
    assert project["compatibilityVersion"] == 1080  # classes written as type=, kept by 1.8
    classes = {t["name"]: t for t in project["propertyTypes"] if t["type"] == "class"}
    assert set(classes) == {cls.name for cls in CLASSES}
    assert classes["Coin"]["useAs"] == ["object"] and classes["Solid"]["useAs"] == ["tile"]
    assert classes["Enemy"]["color"].startswith("#ff")
    members = {m["name"]: m for m in classes["Enemy"]["members"]}
    assert members["speed"] == {"name": "speed", "type": "float",
                                "value": Tuning().enemy_speed_px_s}
    assert members["kind"]["propertyType"] == "EnemyKind"
    ids = [t["id"] for t in project["propertyTypes"]]
    assert len(ids) == len(set(ids))


def test_the_tiled_1_8_project_reads_the_object_types_and_keeps_the_enums() -> None:
    project = json.loads(PROJECT_FILE_1_8.read_text(encoding="utf-8"))
    assert (PROJECT_FILE_1_8.parent / project["objectTypesFile"]) == OBJECT_TYPES_FILE
    assert [t["name"] for t in project["propertyTypes"]] == ["EnemyKind", "LevelSetting"]
    assert "compatibilityVersion" not in project


def split_command(line: str) -> list[str]:
    """Qt 5.15's ``QProcess::splitCommand``, which Tiled 1.8 uses to turn a command line into
    arguments: double quotes group, and three in a row stand for one quote character."""
    args: list[str] = []
    piece, quotes, quoted = "", 0, False
    for char in line:
        if char == '"':
            quotes += 1
            if quotes == 3:
                quotes = 0
                piece += char
            continue
        if quotes:
            if quotes == 1:
                quoted = not quoted
            quotes = 0
        if not quoted and char.isspace():
            if piece:
                args.append(piece)
                piece = ""
        else:
            piece += char
    if piece:
        args.append(piece)
    return args


def tiled_runs(command: dict[str, Any], mapfile: Path, project: Path) -> tuple[list[str], Path]:
    """The arguments and working folder Tiled 1.8 runs a project command with
    (``Command::finalCommand``: the executable quoted, then every variable replaced by its
    value in double quotes, then the line split)."""
    values = {"%mapfile": str(mapfile), "%mappath": str(mapfile.parent),
              "%projectpath": str(project)}
    line = f'"{command["command"]}" {command["arguments"]}'
    folder = command["workingDirectory"]
    for name, value in values.items():
        line = line.replace(name, f'"{value}"')
        folder = folder.replace(name, value)
    return split_command(line), Path(folder)


def run_like_tiled(command: dict[str, Any], mapfile: Path,
                   project: Path) -> subprocess.CompletedProcess[str]:
    args, folder = tiled_runs(command, mapfile, project)
    assert args[0] == "python"  # from the PATH: here, the Python the tests run in
    env = {k: v for k, v in os.environ.items() if not k.startswith("PYTHON")}
    return subprocess.run([sys.executable, *args[1:]], capture_output=True, text=True,
                          timeout=60, check=False, cwd=folder, env=env)


def files_in(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and "__pycache__" not in p.parts}


def test_the_split_matches_qt() -> None:
    assert split_command('"python" -m x "/a b/c.tmx" --w') == ["python", "-m", "x",
                                                                "/a b/c.tmx", "--w"]
    assert split_command('"/d/x" --report README.md "y.tmx"') == ["/d/x", "--report",
                                                                  "README.md", "y.tmx"]
    assert split_command('a """b"""') == ["a", '"b"']


@pytest.mark.parametrize("path", [PROJECT_FILE, PROJECT_FILE_1_8], ids=["1.9+", "1.8"])
def test_the_commands_play_and_check_the_open_map_from_any_folder(path: Path) -> None:
    commands = json.loads(path.read_text(encoding="utf-8"))["commands"]
    entry = "-I -m game.tools.tiled_commands"
    assert [c["arguments"] for c in commands] == [f"{entry} play %mapfile",
                                                  f"{entry} check %mapfile"]
    # No path of one machine's: Python from the PATH (python.exe on Windows too); Tiled puts
    # %mapfile in quotes, and the working folder is not split into words.
    assert all(c["command"] == "python" for c in commands)
    assert all(c["workingDirectory"] == "%projectpath/.." for c in commands)


def copied_project(tmp_path: Path) -> Path:
    folder = tmp_path / "my levels folder"
    shutil.copytree(LEVELS_DIR, folder / "levels")
    shutil.copytree(LEVELS_DIR.parent / "assets", folder / "assets")
    (folder / "README.md").write_text("the project's own README\n", encoding="utf-8")
    return folder


def small_map(project: Path) -> Path:
    """A map in a folder of the project whose only route jumps a block: checked and solved
    in a moment, with the default physics, whose reach the checker knows already (the
    shipped maps are checked in tests/test_levels.py, and solved in tests/test_solver.py)."""
    return write_tmx(project / "levels" / "showcase", HOP_OVER, name="hop over.tmx")


def test_the_check_command_works_from_a_folder_with_spaces(tmp_path: Path) -> None:
    folder = copied_project(tmp_path)
    command = json.loads(PROJECT_FILE.read_text(encoding="utf-8"))["commands"][1]
    mapfile = small_map(folder)
    result = run_like_tiled(command, mapfile, folder / "levels")
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.startswith("checked 1 map(s): all playable, 1 solved")


@pytest.mark.parametrize("which", [0, 1], ids=["play", "check"])
def test_a_map_name_with_a_quote_is_refused_not_split_into_options(tmp_path: Path,
                                                                   which: int) -> None:
    """Tiled puts the path in quotes and splits the line again, so a quote in the name
    makes options of the rest: the command refuses such a name and writes nothing."""
    folder = copied_project(tmp_path)
    name = '01-first-steps.tmx" --headless --ticks 1 --report README.md --record "x.tmx'
    mapfile = folder / "levels" / name
    shutil.copy(LEVELS_DIR / "01-first-steps.tmx", mapfile)
    before = files_in(folder)
    command = json.loads(PROJECT_FILE.read_text(encoding="utf-8"))["commands"][which]
    args, _ = tiled_runs(command, mapfile, folder / "levels")
    assert args[args.index("--report") + 1] == "README.md"  # what Tiled passes: split
    result = run_like_tiled(command, mapfile, folder / "levels")
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.count("\n") == 1
    assert "map: Tiled split the map's path into 8 pieces" in result.stderr, result.stderr
    assert "— rename the map without" in result.stderr
    assert files_in(folder) == before


@pytest.mark.parametrize("which", [0, 1], ids=["play", "check"])
def test_the_commands_run_no_code_from_the_working_folder(tmp_path: Path, which: int) -> None:
    """A folder holding its own ``game/`` package and ``argparse.py`` (a pack laid out like
    the project) runs none of them: the commands import the installed game only."""
    folder = copied_project(tmp_path)
    marker = tmp_path / "ran"
    plant = f"open({str(marker)!r}, 'a').write(__name__ + '\\n')\n"
    for top in (folder, folder / "levels"):
        (top / "game" / "levels").mkdir(parents=True)
        for module in ("__init__.py", "__main__.py", "levels/__init__.py",
                       "levels/__main__.py", "levels/tiled_commands.py"):
            (top / "game" / module).write_text(plant, encoding="utf-8")
        (top / "argparse.py").write_text(plant, encoding="utf-8")
    mapfile = folder / "levels" / "no such map.tmx"  # refused at once: nothing plays
    if which == 1:
        mapfile = small_map(folder)
    command = json.loads(PROJECT_FILE.read_text(encoding="utf-8"))["commands"][which]
    env_before = files_in(folder)
    result = run_like_tiled(command, mapfile, folder / "levels")
    assert not marker.exists(), marker.read_text(encoding="utf-8")
    if which == 1:
        assert result.returncode == 0 and "1 solved" in result.stdout, result.stderr
    else:
        assert result.returncode == 2 and "no such map file" in result.stderr, result.stderr
    assert files_in(folder) == env_before


def test_pytmx_reads_the_exported_property_types() -> None:
    tmx = pytmx.TiledMap(custom_property_filename=str(PROPERTY_TYPES_FILE))
    assert tmx.custom_types["Coin"].value == 1
    assert tmx.custom_types["Enemy"].speed == find("enemy").defaults()["speed"]
    assert set(tmx.custom_types) == {cls.name for cls in CLASSES}


def test_the_object_types_match_the_classes() -> None:
    root = ET.parse(OBJECT_TYPES_FILE).getroot()
    types = {node.get("name"): {p.get("name"): p.get("default") for p in node}
             for node in root}
    assert types["Coin"] == {"value": "1"}
    assert types["Enemy"]["speed"] == f"{Tuning().enemy_speed_px_s:g}"
    assert "Level" not in types  # object types are for objects and tiles


@pytest.mark.skipif(TILED is None, reason="Tiled is not installed")
def test_tiled_applies_the_object_type_defaults(tmp_path: Path) -> None:
    """Tiled 1.8's command line reads object types from its data folder, not the project,
    so the file is put there; --resolve-types-and-properties writes the defaults out."""
    data_home = tmp_path / "data"
    (data_home / "tiled").mkdir(parents=True)
    shutil.copy(OBJECT_TYPES_FILE, data_home / "tiled" / "objecttypes.xml")
    exported = tmp_path / "levels" / "out.tmx"
    exported.parent.mkdir()
    shutil.copytree(LEVELS_DIR.parent / "assets", tmp_path / "assets")
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(tmp_path),
           "XDG_CONFIG_HOME": str(tmp_path / "config"), "XDG_DATA_HOME": str(data_home),
           "XDG_RUNTIME_DIR": str(tmp_path)}
    tmp_path.chmod(0o700)
    result = subprocess.run([str(TILED), "--export-map", "--resolve-types-and-properties",
                             str(LEVELS_DIR / "01-first-steps.tmx"), str(exported)],
                            env=env, capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    objects = ET.parse(exported).getroot().iter("object")
    values = {(o.get("type"), p.get("name"), p.get("value")) for o in objects
              for p in o.iter("property")}
    assert ("Coin", "value", "1") in values
    assert ("Enemy", "speed", f"{Tuning().enemy_speed_px_s:g}") in values
    assert ("Enemy", "kind", "walker") in values


def _row(readme: str, first_cell: str) -> str:
    return next(line for line in readme.splitlines() if line.startswith(f"| {first_cell} |"))


def _shown(value: object) -> str:
    return f"{value:g}" if isinstance(value, float) else str(value)


def test_the_designers_guide_lists_every_class_with_its_defaults() -> None:
    readme = (LEVELS_DIR / "README.md").read_text(encoding="utf-8")
    for cls in CLASSES:
        if cls.use_as == "map":
            for member in cls.members:
                row = _row(readme, f"`{member.name}`")
                assert member.type in row
                assert not member.default or f"`{_shown(member.default)}`" in row, row
        else:
            row = _row(readme, f"`{cls.name}`")
            for member in cls.members:
                assert f"`{member.name}`" in row, row
                assert f"default `{_shown(member.default)}`" in row, row
