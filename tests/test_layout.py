"""The README's layout table says what is there: every package of ``game/`` has a row; the
rows of the first four roles, the reference (with its broad phases), the simulation, the
loader and the app, name every one of their modules (``__main__`` too); and the sentence
about what the game uses from the reference names exactly the reference modules that the
simulation, the loader and the app import."""

from __future__ import annotations

import re
from pathlib import Path

from tests.test_layers import GRAPH, MODULES

ROOT = Path(__file__).resolve().parent.parent
GAME = ROOT / "game"
README = (ROOT / "README.md").read_text(encoding="utf-8")
LAYOUT = README.split("## Layout", 1)[1].split("\n## ", 1)[0]
LISTED_IN_FULL = ("game/collision/", "game/collision/broad/", "game/sim/", "game/levels/",
                  "game/checker/",
                  "game/app/")


def rows() -> dict[str, str]:
    """The table's rows: the path in its first cell, the text of the second."""
    return {path: what for path, what in re.findall(r"^\| `([^`]+)` \| (.+) \|$", LAYOUT,
                                                    re.MULTILINE)}


def packages() -> list[str]:
    return sorted(f"{p.parent.relative_to(ROOT).as_posix()}/" for p in GAME.rglob("__init__.py")
                  if p.parent != GAME)


def test_the_layout_table_has_a_row_for_every_package() -> None:
    missing = [package for package in packages() if package not in rows()]
    assert missing == [], f"packages the README's layout table leaves out: {missing}"


def test_the_layout_table_names_every_module_of_the_first_four_roles() -> None:
    table = rows()
    for package in LISTED_IN_FULL:
        named = set(re.findall(r"`(\w+)`", table[package]))
        modules = {p.stem for p in (ROOT / package).glob("*.py") if p.stem != "__init__"}
        assert modules - named == set(), f"{package}: not in the README's row"
        assert named - modules == set(), f"{package}: the README names modules not there"


def test_the_readme_names_exactly_what_the_game_imports_from_the_reference() -> None:
    game_side = [m for m in MODULES
                 if m.split(".")[1:2] in (["sim"], ["levels"], ["checker"], ["app"])]
    used = {target.rsplit(".", 1)[1] for m in game_side for target in GRAPH[m]
            if target.startswith("game.collision.")}
    sentence = LAYOUT.split("What the game itself", 1)[1].split("Its moves", 1)[0]
    reference = {p.stem for p in (GAME / "collision").rglob("*.py")}
    assert used
    assert set(re.findall(r"`(\w+)`", sentence)) & reference == used


def test_the_crowd_scenes_choose_their_broad_phase_from_methods_and_the_game_does_not() -> None:
    readers = {m for m, targets in GRAPH.items() if "game.collision.methods" in targets}
    assert "game.demos.crates" in readers          # and stress, which runs crate scenes
    assert "game.demos.crates" in GRAPH["game.demos.stress"]
    assert not {m for m in readers if m.split(".")[1] in ("sim", "levels", "app")}
