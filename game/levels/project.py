"""Write the game's classes where Tiled and pytmx look for them.

Where it sits: ``python -m game.levels types --write`` regenerates four files in
``levels/`` from :mod:`game.levels.classes`, and a test fails when the committed files
differ from what this module generates. Edit the classes in Python, never in Tiled.

================================  ========================================================
``tile-hopper.tiled-project``      the project for Tiled 1.9 and later: folders, the Play
                                   and Check commands, and the classes as
                                   ``propertyTypes`` (with their colours, defaults and the
                                   Enemy ``kind`` list). It names no object types file, so
                                   Tiled 1.9+ imports nothing over these classes, and it
                                   asks Tiled to write files Tiled 1.8 can read (a class is
                                   written as ``type=``, which Tiled 1.8 keeps).
``tile-hopper-1.8.tiled-project``  the project for Tiled 1.8: the same folders and
                                   commands, the ``kind`` list, and ``objecttypes.xml``
``objecttypes.xml``                the classes as Tiled 1.8's object types (defaults and
                                   colours); only the 1.8 project names it
``propertytypes.json``             the classes as Tiled's "Export Types" JSON, which pytmx
                                   reads with ``TiledMap(custom_property_filename=...)``
================================  ========================================================

The commands run ``python -I -m game.tools.tiled_commands play|check %mapfile`` with
``python`` from the ``PATH`` and the project's parent folder as the working folder. Tiled
quotes the map's path, so folders whose names hold spaces work; ``-I`` (isolated mode)
imports only the installed game, never a ``game/`` or ``argparse.py`` from the working
folder, and :mod:`game.tools.tiled_commands` refuses a path Tiled split into pieces.

What it teaches: generated files that are committed must be checked for staleness, or the
copy drifts from its source.

>>> [m["name"] for m in property_types()[-1]["members"]][:3]
['title', 'next_level', 'setting']
"""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path
from typing import Any

from game.levels import LEVELS_DIR
from game.levels.classes import CLASSES, Member, TiledClass
from game.levels.outputs import replace_atomically
from game.levels.reading import ReadProblem, read_text

PROJECT_FILE = LEVELS_DIR / "tile-hopper.tiled-project"
PROJECT_FILE_1_8 = LEVELS_DIR / "tile-hopper-1.8.tiled-project"
OBJECT_TYPES_FILE = LEVELS_DIR / "objecttypes.xml"
PROPERTY_TYPES_FILE = LEVELS_DIR / "propertytypes.json"
MAX_GENERATED_BYTES = 4 * 1024 * 1024  # each generated file is a few kB

PYTHON = "python"  # the first on the PATH: start Tiled where the game's Python is active
COMPATIBLE_WITH_TILED_1_8 = 1080  # Tiled's "compatibility version" for files 1.8 reads
ENTRY = "-I -m game.tools.tiled_commands"  # isolated: the installed game, nothing else
COMMANDS = (("Play this level", f"{ENTRY} play %mapfile", "F5"),
            ("Check this level", f"{ENTRY} check %mapfile", "F6"))


def enum_name(cls: TiledClass, member: Member) -> str:
    return f"{cls.name}{member.name.title()}"


def _member_json(cls: TiledClass, member: Member) -> dict[str, Any]:
    entry: dict[str, Any] = {"name": member.name, "type": member.type,
                             "value": member.default}
    if member.choices:
        entry["propertyType"] = enum_name(cls, member)
    return entry


def property_types(classes: tuple[TiledClass, ...] = CLASSES) -> list[dict[str, Any]]:
    """The classes (and the enums their members use) in Tiled's JSON form."""
    enums = [(cls, member) for cls in classes for member in cls.members if member.choices]
    types: list[dict[str, Any]] = [
        {"id": number, "name": enum_name(cls, member), "storageType": "string",
         "type": "enum", "values": list(member.choices), "valuesAsFlags": False}
        for number, (cls, member) in enumerate(enums, start=1)]
    types += [
        {"color": "#ff" + cls.color.lstrip("#"), "id": number, "name": cls.name,
         "members": [_member_json(cls, member) for member in cls.members],
         "type": "class", "useAs": [cls.use_as]}
        for number, cls in enumerate(classes, start=len(enums) + 1)]
    return types


def _commands() -> list[dict[str, Any]]:
    return [{"arguments": arguments, "command": PYTHON, "enabled": True, "name": name,
             "saveBeforeExecute": True, "shortcut": shortcut, "showOutput": True,
             "workingDirectory": "%projectpath/.."}
            for name, arguments, shortcut in COMMANDS]


def project() -> dict[str, Any]:
    """The project for Tiled 1.9 and later: the classes, and no object types file."""
    return {"automappingRulesFile": "", "commands": _commands(),
            "compatibilityVersion": COMPATIBLE_WITH_TILED_1_8, "extensionsPath": "extensions",
            "folders": [".", "../assets"], "objectTypesFile": "",
            "propertyTypes": property_types()}


def project_1_8() -> dict[str, Any]:
    """The project for Tiled 1.8: object types from ``objecttypes.xml``, and only the enums
    as property types (Tiled 1.8 has no object classes)."""
    enums = [entry for entry in property_types() if entry["type"] == "enum"]
    return {"automappingRulesFile": "", "commands": _commands(),
            "extensionsPath": "extensions", "folders": [".", "../assets"],
            "objectTypesFile": OBJECT_TYPES_FILE.name, "propertyTypes": enums}


def _default_text(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return f"{value:g}" if isinstance(value, float) else str(value)


def object_types() -> str:
    """Tiled 1.8's ``objecttypes.xml``: the object and tile classes with their defaults."""
    root = ET.Element("objecttypes")
    for cls in CLASSES:
        if cls.use_as == "map":
            continue  # object types apply to objects and tiles only
        node = ET.SubElement(root, "objecttype", {"name": cls.name, "color": cls.color})
        for member in cls.members:
            ET.SubElement(node, "property", {"name": member.name, "type": member.type,
                                             "default": _default_text(member.default)})
    ET.indent(root, space=" ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, "unicode") + "\n"


def _json_text(data: object) -> str:
    return json.dumps(data, indent=4, ensure_ascii=False) + "\n"


def generated_files() -> dict[Path, str]:
    """Each generated file and the text it should hold."""
    return {PROJECT_FILE: _json_text(project()),
            PROJECT_FILE_1_8: _json_text(project_1_8()),
            OBJECT_TYPES_FILE: object_types(),
            PROPERTY_TYPES_FILE: _json_text(property_types())}


def stale_files() -> list[Path]:
    """The generated files whose committed text differs from what would be generated."""
    stale = []
    for path, text in generated_files().items():
        try:  # read to be written again by write_files: not an input of the run
            current: str | None = read_text(path, MAX_GENERATED_BYTES, "the generated file",
                                            updated=True)
        except ReadProblem:
            current = None
        if current != text:
            stale.append(path)
    return stale


def write_files() -> list[Path]:
    """Write every generated file that changed, each through the one atomic write
    (:func:`game.levels.outputs.replace_atomically`); return the ones that changed."""
    changed = stale_files()
    for path, text in generated_files().items():
        if path in changed:
            replace_atomically(path, _text_writer(text))
    return changed


def _text_writer(text: str) -> Callable[[Path], None]:
    def write(tmp: Path) -> None:
        tmp.write_text(text, encoding="utf-8")

    return write
