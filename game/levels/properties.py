"""Custom properties and classes: what a designer types into Tiled's Properties panel.

Where it sits: read for the map, for objects and for templates by the readers in
:mod:`game.levels`; what the values mean is up to :mod:`game.levels.classes`.

What it teaches:
  * A property is written ``<property name="speed" type="float" value="50"/>``; with no
    ``type`` it is a string, and a multi-line string keeps its value as the element's text.
  * Tiled 1.8 added ``class`` properties (nested ``<properties>``) and Tiled 1.12 added
    ``list`` properties (``<item>`` children). They are read as dicts and lists, so a map
    that uses them loads; the game itself reads neither.
  * The Class of a tile or an object is written ``type="Coin"`` by Tiled up to 1.8 and
    ``class="Coin"`` by Tiled 1.9; both are read, in any letter case.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping

from game.levels.attributes import parse_number
from game.levels.errors import Findings

Value = str | int | float | bool | dict[str, "Value"] | list["Value"]

MAX_NESTING = 16  # class properties inside class properties: deeper than this is not Tiled's
FIX_TYPE = "type a value of the property's type in Tiled's Properties panel"


def class_of(attributes: Mapping[str, str]) -> str:
    """The Tiled class of a tile or object, from ``type=`` or Tiled 1.9's ``class=``
    (hand-written files may spell them ``Type=`` or ``CLASS=``), in lower case.

    >>> class_of({"class": "OneWay"}), class_of({"type": "SOLID"}), class_of({"Class": "X"})
    ('oneway', 'solid', 'x')
    """
    return class_name(attributes).lower()


def class_name(attributes: Mapping[str, str]) -> str:
    """The class as written, from the first non-empty ``type`` or ``class`` attribute."""
    for key in ("type", "class"):
        for name, value in attributes.items():
            if name.lower() == key and value.strip():
                return value.strip()
    return ""


def _typed(kind: str, text: str, findings: Findings, where: str, what: str) -> Value:
    """One plain value, cast by its Tiled type."""
    if kind in ("int", "object"):
        number = parse_number(text) if text.strip() else 0.0
        if number is None or number != int(number):
            findings.fail(where, f"{what} is {text!r}, not a whole number", FIX_TYPE)
        return int(number)
    if kind == "float":
        number = parse_number(text) if text.strip() else 0.0
        if number is None:
            findings.fail(where, f"{what} is {text!r}, not a finite number", FIX_TYPE)
        return number
    if kind == "bool":
        return text.strip().lower() in ("true", "1")
    return text  # string, color, file, enum values and types the game does not know


def _value(node: ET.Element, findings: Findings, where: str, what: str, depth: int) -> Value:
    """The value of a ``<property>`` or list ``<item>``, nested values included."""
    if depth > MAX_NESTING:
        findings.fail(where, f"{what} nests more than {MAX_NESTING} levels deep",
                      "simplify the property in Tiled")
    kind = node.get("type", "string")
    if kind == "class":
        return read_properties(node, findings, where, depth + 1)
    if kind == "list":
        return [_value(item, findings, where, f"an item of {what}", depth + 1)
                for item in node.findall("item")]
    text = node.get("value")
    return _typed(kind, text if text is not None else node.text or "", findings, where, what)


def read_properties(node: ET.Element, findings: Findings, where: str,
                    depth: int = 0) -> dict[str, Value]:
    """The custom properties of a map, layer, object or class value, typed.

    >>> from pathlib import Path
    >>> node = ET.fromstring('<object><properties><property name="value" type="int" '
    ...     'value="5"/><property name="note">two\\nlines</property></properties></object>')
    >>> read_properties(node, Findings(Path("a.tmx")), "object #1 ''")
    {'value': 5, 'note': 'two\\nlines'}
    """
    values: dict[str, Value] = {}
    for block in node.findall("properties"):
        for prop in block.findall("property"):
            name = prop.get("name", "")
            values[name] = _value(prop, findings, where, f"property '{name}'", depth)
    return values
