"""The code teaches: every module opens with a syllabus, collision modules carry doctests."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

GAME = Path(__file__).resolve().parent.parent / "game"
MODULES = sorted(p for p in GAME.rglob("*.py"))
COLLISION_MODULES = ["collision/aabb", "collision/circles", "collision/sat", "collision/masks",
                     "collision/composite", "collision/swept", "collision/tile_grid",
                     "collision/axis_sweep", "collision/shapes", "collision/free_place",
                     "collision/broad/spatial_grid", "collision/broad/quadtree",
                     "collision/broad/sort_and_sweep", "collision/broad/brute_force",
                     "collision/response", "collision/contacts", "sim/fixed_step", "sim/camera"]


@pytest.mark.parametrize("path", MODULES, ids=[str(p.relative_to(GAME)) for p in MODULES])
def test_every_module_opens_with_a_syllabus_docstring(path: Path) -> None:
    docstring = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8")))
    assert docstring, f"{path} has no module docstring"
    if path.name != "__main__.py":
        assert len(docstring.split()) >= 12, f"{path}: the docstring is too short to teach"


@pytest.mark.parametrize("name", COLLISION_MODULES)
def test_every_collision_module_carries_doctest_examples(name: str) -> None:
    assert ">>> " in (GAME / f"{name}.py").read_text(encoding="utf-8")
