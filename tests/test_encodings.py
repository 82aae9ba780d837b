"""Every tile layer format Tiled writes gives the same level: CSV, base64, base64 + zlib,
base64 + gzip. The variants are made here from the shipped levels' CSV."""

from __future__ import annotations

import base64
import gzip
import shutil
import struct
import xml.etree.ElementTree as ET
import zlib
from collections.abc import Callable
from pathlib import Path

import pytest

from game.levels import LEVELS_DIR, load_level
from game.sim.level import Level

SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))


def _packed(gids: list[int]) -> bytes:
    return struct.pack(f"<{len(gids)}I", *gids)


def _base64(data: bytes) -> str:
    return "\n   " + base64.b64encode(data).decode() + "\n  "  # as Tiled indents it


ENCODINGS: dict[str, tuple[dict[str, str], Callable[[list[int]], str]]] = {
    "csv": ({"encoding": "csv"}, lambda gids: ",".join(map(str, gids))),
    "base64": ({"encoding": "base64"}, lambda gids: _base64(_packed(gids))),
    "base64-zlib": ({"encoding": "base64", "compression": "zlib"},
                    lambda gids: _base64(zlib.compress(_packed(gids)))),
    "base64-gzip": ({"encoding": "base64", "compression": "gzip"},
                    lambda gids: _base64(gzip.compress(_packed(gids)))),
}


def reencoded(level: Path, encoding: str, folder: Path) -> Path:
    """A copy of ``level`` in ``folder``/levels with its tile data in ``encoding``."""
    root = ET.parse(level).getroot()
    attributes, encode = ENCODINGS[encoding]
    for data in root.iter("data"):
        assert data.get("encoding") == "csv", "the shipped levels are saved as CSV"
        gids = [int(token) for token in (data.text or "").replace("\n", "").split(",")]
        data.attrib.clear()
        data.attrib.update(attributes)
        data.text = encode(gids)
    target = folder / "levels" / level.name
    target.write_bytes(ET.tostring(root, encoding="utf-8"))
    return target


def essentials(level: Level) -> tuple[object, ...]:
    """What the game plays: solids, bodies, pickups, exits and the drawn tiles."""
    shapes = sorted((s.box, s.kind.value, s.col, s.row) for s in level.grid.shapes())
    return (shapes, level.spawn, level.coins, level.enemies, level.exits,
            [(layer.name, layer.gids) for layer in (*level.layers, *level.foreground)])


@pytest.fixture(scope="module")
def project(tmp_path_factory: pytest.TempPathFactory) -> Path:
    root = tmp_path_factory.mktemp("project")
    (root / "levels").mkdir()
    shutil.copytree(LEVELS_DIR.parent / "assets", root / "assets")
    return root


@pytest.mark.parametrize("encoding", sorted(ENCODINGS))
@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_tile_layer_format_loads_to_the_same_level(level: Path, encoding: str,
                                                         project: Path) -> None:
    variant = reencoded(level, encoding, project)
    data = ET.parse(variant).getroot().find(".//data")
    assert data is not None and data.attrib == ENCODINGS[encoding][0]
    assert essentials(load_level(variant)) == essentials(load_level(level))
