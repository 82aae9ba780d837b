"""Open one Tiled XML file (a map, a tileset or a template) without trusting it.

Where it sits: the first step of loading a level, and of every tileset and template the
level uses; the file itself is opened by :mod:`game.levels.reading`.

What it teaches: a file from outside is checked before it is parsed. Only a regular file is
read (a folder, a pipe or ``/dev/zero`` is refused, so nothing can hang waiting for input);
its size is capped; JSON (Tiled's other format) and binary data are recognised and named;
the XML may not declare entities (Tiled never writes them, and they are how a small file
expands into gigabytes; the ``<!DOCTYPE>`` line of old Tiled files is harmless and allowed);
and the root element must be the kind of file that was expected.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Literal

from game.levels.errors import Findings, escaped, excerpt
from game.levels.reading import read_level_file

Kind = Literal["map", "tileset", "template"]

MAX_FILE_BYTES = 32 * 1024 * 1024
JSON_SUFFIXES = (".tmj", ".tsj", ".tj", ".json")
TMX_SUFFIX: dict[Kind, str] = {"map": ".tmx", "tileset": ".tsx", "template": ".tx"}
SAVE_AS: dict[Kind, str] = {
    "map": "open it in Tiled and use File > Save As… with the .tmx format",
    "tileset": "open it in Tiled, use File > Export As… with the .tsx format, "
               "and add the .tsx to the map instead",
    "template": "open it in Tiled, save the template as .tx, and use that one instead",
}


def is_json_name(name: str) -> bool:
    """True for Tiled's JSON file names.

    >>> is_json_name("level.tmj"), is_json_name("tiles.TSJ"), is_json_name("level.tmx")
    (True, True, False)
    """
    return name.lower().endswith(JSON_SUFFIXES)


def refuse_json(findings: Findings, where: str, kind: Kind, name: str) -> None:
    """Fail with Tiled's advice when ``name`` is a JSON file."""
    if is_json_name(name):
        findings.fail(where, f"{excerpt(name)} is Tiled's JSON format; the game reads "
                      f"{TMX_SUFFIX[kind]} files", SAVE_AS[kind])


def _read_bytes(path: Path, findings: Findings, where: str, kind: Kind) -> bytes:
    what = "map" if kind == "map" else f"{kind} file {escaped(path.name)}"
    refuse_json(findings, where, kind, path.name)
    return read_level_file(path, findings, where, what, MAX_FILE_BYTES,
                           "split the level into smaller maps, or use base64-zlib tile data")


def _sniff(data: bytes, findings: Findings, where: str, kind: Kind) -> None:
    """Refuse what is plainly not Tiled XML before the parser sees it."""
    start = data.lstrip(b"\xef\xbb\xbf \t\r\n")[:1]
    if start in (b"{", b"["):
        findings.fail(where, f"this is Tiled's JSON format; the game reads "
                      f"{TMX_SUFFIX[kind]} files", SAVE_AS[kind])
    if start != b"<" or b"\0" in data[:4096]:
        findings.fail(where, f"this is not a Tiled {kind} file (it is not XML text)",
                      f"give the path of a {TMX_SUFFIX[kind]} file saved by Tiled")
    if b"<!ENTITY" in data:
        findings.fail(where, "the XML declares entities, which Tiled never writes",
                      "open the map in Tiled and save it again")


def read_tiled_xml(path: Path, kind: Kind, findings: Findings, where: str = "",
                   data: bytes | None = None) -> ET.Element:
    """Parse ``path`` and return its root element, which must be a ``<map>``,
    ``<tileset>`` or ``<template>`` as ``kind`` says. ``data``, when given, is what the
    file would hold (a map not written yet), checked and parsed instead of the file."""
    if data is None:
        data = _read_bytes(path, findings, where, kind)
    else:
        refuse_json(findings, where, kind, path.name)
        if len(data) > MAX_FILE_BYTES:
            findings.fail(where, f"the {kind} would be larger than "
                          f"{MAX_FILE_BYTES // 2**20} MB", "split the level into smaller "
                          "maps, or use base64-zlib tile data")
    _sniff(data, findings, where, kind)
    try:
        root = ET.fromstring(data)
    except ET.ParseError as error:
        line, column = error.position
        findings.fail(where, f"the XML of {excerpt(path.name)} is damaged at line {line}, "
                      f"column {column}",
                      "undo the hand edit, or restore the file from a backup")
    except (LookupError, ValueError) as error:  # an encoding="..." Python cannot decode
        findings.fail(where, f"the XML of {excerpt(path.name)} is in a text encoding the "
                      f"game cannot read ({excerpt(str(error))})",
                      "save it from Tiled, which writes UTF-8")
    if root.tag == kind:
        return root
    if root.tag == "tileset" and kind == "map":
        findings.fail(where, "this is a tileset (.tsx), not a map",
                      "check the .tmx map that uses it instead")
    findings.fail(where, f"{excerpt(path.name)} holds a <{excerpt(root.tag)}>, not a Tiled {kind}",
                  f"give the path of a {TMX_SUFFIX[kind]} file saved by Tiled")
