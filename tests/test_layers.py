"""The package layout is the architecture: dependencies point one way, and no two modules
import each other.

The layers, lowest first (each may import only those before it):

1. ``game.collision``: the collision reference, pure geometry a reader can copy.
2. ``game.sim``: the headless simulation that uses it.
3. ``game.levels``: the Tiled loader, which builds a simulation's level.
4. ``game.checker`` and ``game.app``, side by side (neither imports the other): the level
   checker, which judges what the loader built, and the window, screens, rendering, files
   and the command line.
5. ``game.demos``, ``game.tools``, ``game.bench``, ``game.lab``: programs beside the game.

A package's ``__main__`` only starts a program, so it sits on top, like ``game.__main__``
(``python -m game.levels`` starts the checker's command line).

Every ``import`` counts, including those inside functions: a lazy import is still a
dependency, it only hides it.
"""

from __future__ import annotations

import ast
from collections.abc import Iterator
from pathlib import Path

import pytest

GAME = Path(__file__).resolve().parent.parent / "game"

LAYER = {"collision": 1, "sim": 2, "levels": 3, "checker": 4, "app": 4,
         "demos": 5, "tools": 5, "bench": 5, "lab": 5}


def module_name(path: Path) -> str:
    parts = path.relative_to(GAME.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


# The fields that hold a block of statements (an ``except`` clause's and a ``case``'s own
# block sit one level down): an ``import`` is a statement, found only in these.
BLOCKS = ("body", "orelse", "finalbody", "handlers", "cases")


def statements(module: ast.Module) -> Iterator[ast.AST]:
    """Every statement of the module, however deeply nested in functions, classes and
    blocks; the expressions inside them, which hold no ``import``, are not walked."""
    todo: list[ast.AST] = [module]
    while todo:
        node = todo.pop()
        yield node
        for field in BLOCKS:
            block = getattr(node, field, None)
            if isinstance(block, list):
                todo.extend(block)


def imports_of(path: Path) -> set[str]:
    """Every ``game`` module this file imports, anywhere in it, resolved to a module name."""
    here = module_name(path)
    package = here if path.name == "__init__.py" else here.rpartition(".")[0]
    found: set[str] = set()
    for node in statements(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(a.name for a in node.names if a.name.split(".")[0] == "game")
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[: len(package.split(".")) - node.level + 1]
                name = ".".join(base + ([node.module] if node.module else []))
            else:
                name = node.module or ""
            if name.split(".")[0] != "game":
                continue
            # `from game.sim import world` names a module, not a symbol: count the module,
            # and the package only when a symbol of its own is imported.
            for alias in node.names:
                submodule = f"{name}.{alias.name}"
                if (GAME.parent / submodule.replace(".", "/")).with_suffix(".py").exists():
                    found.add(submodule)
                else:
                    found.add(name)
    return found - {here}


MODULES = {module_name(p): p for p in sorted(GAME.rglob("*.py"))}
GRAPH = {name: {m for m in imports_of(path) if m in MODULES} for name, path in MODULES.items()}


def layer_of(module: str) -> int | None:
    parts = module.split(".")
    if parts[-1] == "__main__":
        return None  # a program's start, on top of every layer
    return LAYER.get(parts[1]) if len(parts) > 1 else None


def test_every_module_of_the_game_sits_in_a_layer() -> None:
    top_level = {"game"}
    loose = [m for m in MODULES if m not in top_level and layer_of(m) is None
             and not m.endswith(".__main__")]
    assert loose == [], f"modules outside the layered packages: {loose}"


@pytest.mark.parametrize("module", sorted(MODULES))
def test_no_module_imports_a_higher_layer(module: str) -> None:
    mine = layer_of(module)
    if mine is None:
        return  # game/__init__.py and every __main__.py sit on top
    upward = sorted(m for m in GRAPH[module] if (layer_of(m) or 99) > mine)
    assert upward == [], f"{module} (layer {mine}) imports a higher layer: {upward}"


def test_the_collision_reference_imports_nothing_else_of_the_game() -> None:
    outside = {m: sorted(d for d in deps if layer_of(d) != 1)
               for m, deps in GRAPH.items() if layer_of(m) == 1}
    assert {m: d for m, d in outside.items() if d} == {}


def test_the_checker_and_the_app_do_not_import_each_other() -> None:
    crossing = {m: sorted(d for d in deps if layer_of(d) == 4
                          and d.split(".")[1] != m.split(".")[1])
                for m, deps in GRAPH.items() if layer_of(m) == 4}
    assert {m: d for m, d in crossing.items() if d} == {}


def test_the_loader_knows_nothing_of_the_checker() -> None:
    """The loader reads maps into levels; judging them is the checker's: a loader reader
    never has to open the checker (only ``python -m game.levels`` starts it)."""
    assert {m: sorted(d for d in deps if d.startswith("game.checker"))
            for m, deps in GRAPH.items()
            if m.startswith("game.levels.") and m != "game.levels.__main__"
            and any(d.startswith("game.checker") for d in deps)} == {}


def test_demos_tools_and_bench_do_not_import_each_other() -> None:
    side = {"demos", "tools", "bench", "lab"}
    crossing = {m: sorted(d for d in deps if d.split(".")[1] in side
                          and d.split(".")[1] != m.split(".")[1])
                for m, deps in GRAPH.items() if layer_of(m) == 5}
    assert {m: d for m, d in crossing.items() if d} == {}


def test_no_import_cycles() -> None:
    """A depth-first search that meets a module already on its own path has found a cycle."""
    on_path: list[str] = []
    done: set[str] = set()
    cycles: list[list[str]] = []

    def visit(module: str) -> None:
        if module in done:
            return
        if module in on_path:
            cycles.append([*on_path[on_path.index(module):], module])
            return
        on_path.append(module)
        for dep in sorted(GRAPH[module]):
            visit(dep)
        on_path.pop()
        done.add(module)

    for module in sorted(GRAPH):
        visit(module)
    assert cycles == []


def test_the_import_reader_finds_known_imports() -> None:
    """The import reader itself works: it resolves absolute, relative and `from package import
    module` forms, so the tests above cannot pass by reading nothing."""
    assert "game.sim.world" in GRAPH["game.sim.campaign"]
    assert "game.collision.aabb" in GRAPH["game.collision.axis_sweep"]
    assert "game.levels.errors" in GRAPH["game.levels"]
    assert len(MODULES) > 50


def test_the_tick_runs_the_collision_path_of_the_reference() -> None:
    """The swept moves and the tile lookup the world runs are the reference's own: the
    simulation imports them from ``game.collision`` and defines no moves of its own."""
    assert {"game.collision.axis_sweep", "game.collision.shapes"} <= GRAPH["game.sim.world"]
    assert "game.collision.tile_grid" in GRAPH["game.sim.solids"]
    sim = [p for p in (GAME / "sim").glob("*.py")]
    defined = {node.name for p in sim for node in ast.walk(ast.parse(p.read_text("utf-8")))
               if isinstance(node, ast.FunctionDef)}
    assert not defined & {"move_x", "move_y", "ground_under", "slide_past_ceiling_corner"}
