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

import pytest
import pytmx

from game.levels import LEVELS_DIR
from game.levels.__main__ import main as levels_main
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


@pytest.mark.parametrize("path", [PROJECT_FILE, PROJECT_FILE_1_8], ids=["1.9+", "1.8"])
def test_the_commands_play_and_check_the_open_map_from_any_folder(path: Path) -> None:
    commands = json.loads(path.read_text(encoding="utf-8"))["commands"]
    assert [c["arguments"] for c in commands] == ["-m game --level %mapfile --watch",
                                                  "-m game.levels check %mapfile"]
    # No path of one machine's: Python from the PATH (python.exe on Windows too); Tiled puts
    # %mapfile in quotes, and the working folder is not split into words.
    assert all(c["command"] == "python" for c in commands)
    assert all(c["workingDirectory"] == "%projectpath/.." for c in commands)


def test_the_check_command_works_from_a_folder_with_spaces(tmp_path: Path) -> None:
    folder = tmp_path / "my levels folder"
    shutil.copytree(LEVELS_DIR, folder / "levels")
    shutil.copytree(LEVELS_DIR.parent / "assets", folder / "assets")
    command = json.loads(PROJECT_FILE.read_text(encoding="utf-8"))["commands"][1]
    mapfile = folder / "levels" / "01-first-steps.tmx"
    arguments = command["arguments"].replace("%mapfile", str(mapfile)).split()
    arguments[arguments.index(str(mapfile).split()[0]):] = [str(mapfile)]  # Tiled's quotes
    result = subprocess.run([sys.executable, *arguments, "--no-solve"], capture_output=True,
                            text=True, timeout=60, check=False,
                            cwd=str(folder / "levels" / ".."))
    assert result.returncode == 0, result.stdout + result.stderr
    assert result.stdout.startswith("checked 1 map(s): all playable")


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
