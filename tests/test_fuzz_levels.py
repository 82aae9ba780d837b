"""Seeded fuzzing: hundreds of damaged copies of a shipped level only ever load or raise
LevelError, never another exception, never a hang.

Two kinds of damage, from one seeded generator so a failure can be replayed: bytes (flips,
cuts, repeats, random insertions, truncation, a strange encoding, groups nested deep) and
XML (an attribute set to a hostile value or removed, an element removed, repeated or
renamed, text replaced), on the map or on its tileset. The same damage drawn again (a
removal from an element with no attributes, an encoding or depth drawn twice) makes copies
read before: each different pair of files is read once.
"""

from __future__ import annotations

import random
import shutil
import xml.etree.ElementTree as ET
from collections.abc import Callable
from pathlib import Path

import pytest

from game.levels import LEVELS_DIR, LevelError, check_level, load_level
from tests.hang_guard import hang_guard

SEED = 20240607
MUTATIONS = 400
# The smallest shipped level with every kind of thing a level holds: each object type
# (Platforms with their paths, Checkpoints), object properties of each type, and few repeats.
LEVEL = LEVELS_DIR / "06-the-summit.tmx"
TILESET = LEVELS_DIR.parent / "assets" / "tiles.tsx"
HOSTILE = ["", " ", "-1", "0", "1", "2", "65535", "4294967296", "99999999999999999999",
           "1e309", "nan", "inf", "-inf", "1.5", "-0.5", "0x10", "abc", "é", "true",
           "../../../../etc/passwd", "/dev/zero", "tiles.tsj", "level.tmj", "zstd", "gzip",
           "zlib", "base64", "csv", "isometric", "1" * 40, "Player", "Exit", "Solid",
           "3221225473", "268435457", "#zzzzzz"]
TAGS = ["map", "tileset", "layer", "data", "objectgroup", "object", "group", "tile",
        "properties", "property", "point", "image", "template", "chunk"]

Mutation = Callable[[bytes, random.Random], bytes]


def flip_bytes(data: bytes, rng: random.Random) -> bytes:
    raw = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        raw[rng.randrange(len(raw))] = rng.randrange(256)
    return bytes(raw)


def cut(data: bytes, rng: random.Random) -> bytes:
    start = rng.randrange(len(data))
    return data[:start] + data[start + rng.randint(1, 200):]


def repeat(data: bytes, rng: random.Random) -> bytes:
    start = rng.randrange(len(data))
    return data[:start] + data[start:start + rng.randint(1, 400)] * 2 + data[start:]


def insert_random(data: bytes, rng: random.Random) -> bytes:
    start = rng.randrange(len(data))
    return data[:start] + rng.randbytes(rng.randint(1, 32)) + data[start:]


def truncate(data: bytes, rng: random.Random) -> bytes:
    return data[:rng.randrange(len(data))]


def declare_encoding(data: bytes, rng: random.Random) -> bytes:
    encoding = rng.choice(["x-unknown", "utf-16", "utf-32", "latin-1", "ascii", ""]).encode()
    return b'<?xml version="1.0" encoding="' + encoding + b'"?>' + data.split(b"?>", 1)[-1]


def nest_groups(data: bytes, rng: random.Random) -> bytes:
    depth = rng.choice([1, 5, 31, 40, 500])
    opened = data.replace(b"<layer", b"<group>" * depth + b"<layer", 1)
    return opened.replace(b"</layer>", b"</layer>" + b"</group>" * depth, 1)


def _xml_edit(edit: Callable[[ET.Element, ET.Element, random.Random], None]) -> Mutation:
    def mutation(data: bytes, rng: random.Random) -> bytes:
        root = ET.fromstring(data)
        parents = [(parent, child) for parent in root.iter() for child in parent]
        parent, child = rng.choice(parents) if parents else (root, root)
        edit(parent, child, rng)
        return ET.tostring(root)
    return mutation


def _set_attribute(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    target = rng.choice([parent, child])
    names = list(target.attrib) or ["x"]
    target.set(rng.choice([*names, "type", "class", "template", "encoding", "compression",
                           "infinite", "orientation", "source", "gid", "firstgid"]),
               rng.choice(HOSTILE))


def _remove_attribute(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    if child.attrib:
        del child.attrib[rng.choice(list(child.attrib))]


def _remove_element(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    parent.remove(child)


def _repeat_element(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    for _ in range(rng.randint(1, 3)):
        parent.append(child)


def _rename_element(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    child.tag = rng.choice(TAGS)


def _set_text(parent: ET.Element, child: ET.Element, rng: random.Random) -> None:
    child.text = rng.choice([*HOSTILE, "0," * rng.randint(0, 2000), "AAAA" * 300])


MUTATORS: list[Mutation] = [
    flip_bytes, cut, repeat, insert_random, truncate, declare_encoding, nest_groups,
    *[_xml_edit(edit) for edit in (_set_attribute, _set_attribute, _set_attribute,
                                  _remove_attribute, _remove_element, _repeat_element,
                                  _rename_element, _set_text)],
]


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A copy of the shipped levels and assets to damage."""
    root = tmp_path_factory.mktemp("project")
    shutil.copytree(LEVELS_DIR, root / "levels")
    shutil.copytree(TILESET.parent, root / "assets")
    return root


def test_damaged_levels_load_or_raise_level_error(project: Path) -> None:
    rng = random.Random(SEED)
    level = project / "levels" / LEVEL.name
    tileset = project / "assets" / TILESET.name
    originals = {level: LEVEL.read_bytes(), tileset: TILESET.read_bytes()}
    written = dict(originals)  # what each file holds now: a file is only written to change it
    seen: set[tuple[bytes, ...]] = set()  # the damaged copies already read: each is read once
    outcomes = {"loaded": 0, "refused": 0}
    for number in range(MUTATIONS):
        target = tileset if rng.random() < 0.2 else level
        mutator = rng.choice(MUTATORS)
        for path, data in originals.items():
            wanted = mutator(data, rng) if path == target else data
            if wanted != written[path]:
                path.write_bytes(wanted)
                written[path] = wanted
        if tuple(written.values()) in seen:  # the same files read again give the same answer
            continue
        seen.add(tuple(written.values()))
        case = f"mutation {number} ({mutator.__name__} on {target.name}, seed {SEED})"
        try:
            with hang_guard():
                load_level(level)
            outcomes["loaded"] += 1
        except LevelError as error:
            assert str(error).startswith(f"{level}: "), case
            outcomes["refused"] += 1
        except Exception as error:  # the point of the test: report which damage broke it
            pytest.fail(f"{case}: {type(error).__name__}: {error}")
        try:
            findings = check_level(level)
        except Exception as error:
            pytest.fail(f"{case}: check_level raised {type(error).__name__}: {error}")
        assert all(line.startswith(f"{level}: ") for line in findings.lines()), case
    assert outcomes["loaded"] > 20 and outcomes["refused"] > 100, outcomes
    assert len(seen) > 300  # hundreds of different damaged copies
