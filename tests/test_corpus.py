"""Real Tiled maps from other projects: each loads, or is refused in one sentence, and none
hangs.

The maps live in ``../shared/third_party_maps`` beside the repository (see its README) and
are only read in place. A fresh clone does not have them, so these tests skip.

Each map is loaded twice: with the game's folder rule (most of them use files in sibling
folders, which the rule refuses) and with the rule widened to the map's source repository,
so that the loader reads everything else about them too. A map the tests below name again
is not read again: its outcome is kept.
"""

from __future__ import annotations

import functools
from pathlib import Path

import pytest

from game.levels import Findings, LevelError, check_level, load_level
from tests.hang_guard import hang_guard

CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "third_party_maps"
MAPS = sorted(CORPUS.rglob("*.tmx")) if CORPUS.is_dir() else []

pytestmark = pytest.mark.skipif(not MAPS, reason=f"no third-party maps in {CORPUS}")


def repository(path: Path) -> Path:
    return CORPUS / path.relative_to(CORPUS).parts[0]


@functools.cache  # the maps are only read: a second look would see the same
def checked(path: Path, folder: Path | None) -> Findings:
    """What the checker says of the map."""
    with hang_guard():
        return check_level(path, folder=folder)


@functools.cache
def outcome(path: Path, folder: Path | None) -> str:
    """'loaded', or the refusal's message; any other exception fails the test."""
    with hang_guard():
        try:
            load_level(path, folder=folder)
            result = "loaded"
        except LevelError as error:
            assert str(error).startswith(f"{path}: ") and " — " in str(error)
            result = str(error)
    findings = checked(path, folder)
    assert all(line.startswith(f"{path}: ") for line in findings.lines())
    assert (result == "loaded") == (not findings.errors) or "image" in str(findings.errors)
    return result


@pytest.mark.parametrize("path", MAPS, ids=[str(p.relative_to(CORPUS)) for p in MAPS])
def test_a_real_map_loads_or_is_refused_in_one_sentence(path: Path) -> None:
    outcome(path, folder=None)
    outcome(path, folder=repository(path))


# The pytmx 3.32 traps, each on the real map that shows it: what the loader says now.
# "no Player object" means the map was read through to its objects: the trap is behind it.
TRAPS = {
    "mapeditor-tiled/examples/isometric_staggered_grass_and_water.tmx": "maps are not supp",
    "mapeditor-rs-tiled/assets/tiled_base64_zlib_infinite.tmx": "infinite maps are not",
    "mapeditor-rs-tiled/assets/tiled_base64_zstandard.tmx": "zstd",
    "baylej-tmx/examples/data/b64zstd.tmx": "zstd",
    "baylej-tmx/examples/data/csv.tmx": "no Player object",  # class properties, 1.10 classes
    "baylej-tmx/examples/data/objecttemplates.tmx": "no Player object",  # templates
    "mapeditor-rs-tiled/assets/tiled_object_template.tmx": "no Player object",
    "mapeditor-rs-tiled/assets/tiled_class_property.tmx": "no Player object",
    "mapeditor-rs-tiled/assets/tiled_object_list_property.tmx": "no Player object",
    "mapeditor-rs-tiled/assets/tiled_object_nested_list_property.tmx": "no Player object",
    "mapeditor-tiled/examples/perspective_walls.tmx": "no Player object",  # image, no size
    "mapeditor-rs-tiled/assets/tiled_image_layers.tmx": "no Player object",  # no image
    "pythonarcade-pytiled_parser/tests/test_data/layer_tests/infinite_map/map.tmx":
        "infinite maps are not",  # fractional offsets, too
    "bitcraft-pytmx/apps/data/acid0.tmx": "no Player object",  # embedded collision shapes
    "mapeditor-tiled/tests/errors/tileset_not_found.tmx": "does not exist",
    "pythonarcade-pytiled_parser/tests/test_data/map_tests/cross_format_tileset/map.tmx":
        "JSON format",
    "mapeditor-rs-tiled/assets/tiled_xml.tmx": "old XML format",
    "mapeditor-rs-tiled/assets/folder/tiled_relative_paths.tmx": "no Player object",
}


@pytest.mark.parametrize("name", sorted(TRAPS))
def test_each_pytmx_trap_on_a_real_map_gets_the_loaders_answer(name: str) -> None:
    path = CORPUS / name
    assert TRAPS[name] in outcome(path, folder=repository(path))


def test_a_map_whose_image_is_missing_is_reported_by_the_checker_only() -> None:
    path = CORPUS / "mapeditor-tiled/util/java/libtiled-java/src/test/resources/" \
                    "desert_missing_image/desert.tmx"
    assert "no Player object" in outcome(path, folder=None)  # headless: images not needed
    assert any("is missing" in str(error) for error in checked(path, None).errors)
