"""The tick is written down three times, and the three say the same: the numbered comments in
``World.step`` (what runs), the list in ``game/sim/world.py``'s docstring, and the README's
tour of a tick. Each is read as a list of (number, name) and the lists must be equal."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

from game.collision import axis_sweep
from game.collision.tile_grid import TileGrid
from game.sim import world
from game.sim.world import World

ROOT = Path(__file__).resolve().parent.parent
Steps = list[tuple[int, str]]


def steps_in_the_code() -> Steps:
    """``# 3. x pass: ...`` comments in the body of ``World.step``."""
    source = inspect.getsource(World.step)
    return [(int(n), name.strip()) for n, name in
            re.findall(r"^\s*# (\d+)\. ([^:]+):", source, re.MULTILINE)]


def numbered_bold_items(text: str) -> Steps:
    """``3. **x pass**: ...`` items of a Markdown or reStructuredText list."""
    return [(int(n), name) for n, name in
            re.findall(r"^(\d+)\. \*\*([^*]+)\*\*", text, re.MULTILINE)]


def steps_in_the_docstring() -> Steps:
    return numbered_bold_items(world.__doc__ or "")


def steps_in_the_readme() -> Steps:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    tour = readme.split("## How collision works here", 1)[1].split("\n## ", 1)[0]
    return numbered_bold_items(tour)


def test_the_code_numbers_its_steps_one_to_n_in_order() -> None:
    code = steps_in_the_code()
    assert [n for n, _ in code] == list(range(1, len(code) + 1))
    assert len(code) >= 10


def test_the_docstring_lists_the_steps_the_code_runs() -> None:
    assert steps_in_the_docstring() == steps_in_the_code()


def test_the_readmes_tour_lists_the_steps_the_code_runs() -> None:
    assert steps_in_the_readme() == steps_in_the_code()


def test_the_tick_and_the_collision_path_carry_no_logging_code() -> None:
    """The query log is a wrapper round the solids (game.sim.query_log): the tick only asks
    the source named for each step, and the lookup and the moves count and log nothing."""
    tick = inspect.getsource(World.step)
    assert "purpose" not in tick
    assert not re.search(r"^\s*(if|elif)\b[^\n]*\blog", tick, re.MULTILINE)
    for plain in (TileGrid.entries_in, axis_sweep.move_x, axis_sweep.move_y,
                  axis_sweep.ground_under, axis_sweep.slide_past_ceiling_corner):
        source = inspect.getsource(plain)
        assert not re.search(r"log|stats|purpose|count", source), plain.__qualname__
