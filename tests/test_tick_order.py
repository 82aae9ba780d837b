"""The tick is written down three times, and the three say the same: the numbered comments in
``World.step`` (what runs), the list in ``game/sim/world.py``'s docstring, and the README's
tour of a tick. Each is read as a list of (number, name) and the lists must be equal. And
the tick stays short to read: ``World.step`` a table of contents of short phases, and a
tick of the first level a few hundred lines in a few files."""

from __future__ import annotations

import ast
import inspect
import re
import sys
import textwrap
from pathlib import Path
from types import CodeType, FrameType
from typing import Any

import pytest

from game.app.run import input_script
from game.collision import axis_sweep
from game.collision.shapes import Entry
from game.collision.tile_grid import TileGrid
from game.levels import LEVELS_DIR, load_level
from game.sim import world
from game.sim.platforms import Platform, PlatformIndex
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


def steps_text_of_the_readme() -> str:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    return readme.split("## How collision works here", 1)[1].split("\n## ", 1)[0]


def steps_in_the_readme() -> Steps:
    return numbered_bold_items(steps_text_of_the_readme())


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


PHASE_LINES = 40  # longest a phase of the tick may be (a method World.step calls)
STEP_LINES = 60   # longest World.step may be: a table of contents of its phases
TICK_FILES = 8    # the files of game/ a typical tick of level 1 runs code in
TICK_LINES = 400  # the lines of game/ the first ticks of level 1 run, all told; and the
# lines of code of the functions they enter (less blank lines, comments and docstrings)
TRACED_TICKS = 300
Lines = set[tuple[str, int]]


def traced_ticks(ticks: int, entered: set[CodeType] | None = None) -> list[Lines]:
    """Level 1 played by its winning script: the (file, line) pairs of ``game/`` each tick
    runs, counted by the interpreter's line tracer; the functions of ``game/`` the ticks
    call are added to ``entered``."""
    script = input_script(ROOT / "tests" / "scripts" / "01-first-steps.txt")
    world = World(load_level(LEVELS_DIR / "01-first-steps.tmx"))
    game = str(ROOT / "game")
    called: set[CodeType] = set() if entered is None else entered
    runs: list[Lines] = []
    ran: Lines = set()

    def each_line(frame: FrameType, event: str, _: object) -> Any:
        if event == "line":
            ran.add((frame.f_code.co_filename, frame.f_lineno))
        return each_line

    def each_call(frame: FrameType, _event: str, _arg: object) -> Any:
        if not frame.f_code.co_filename.startswith(game):
            return None
        called.add(frame.f_code)
        return each_line

    was = sys.gettrace()
    try:
        for tick in range(ticks):
            held = script.held_at(tick)
            ran = set()
            sys.settrace(each_call)
            world.step(held)
            sys.settrace(was)
            runs.append(ran)
    finally:
        sys.settrace(was)
    return runs


def lines_of_code(function: CodeType) -> Lines:
    """The (file, line) pairs of a function's source that a reader reads as code: its
    ``def`` to its end, less blank lines, comments and its docstring."""
    source, first = inspect.getsourcelines(function)
    body = ast.parse(textwrap.dedent("".join(source))).body[0]
    assert isinstance(body, (ast.FunctionDef, ast.AsyncFunctionDef))
    docstring: set[int] = set()
    if ast.get_docstring(body, clean=False) is not None:
        docstring = set(range(body.body[0].lineno, (body.body[0].end_lineno or 0) + 1))
    return {(function.co_filename, first + number - 1)
            for number, line in enumerate(source, 1)
            if line.strip() and not line.strip().startswith("#") and number not in docstring}


def lines_of_the_functions_entered(entered: set[CodeType]) -> Lines:
    """The lines of code of every named function entered (a comprehension's lines are its
    function's): what a reader following the tick reads, whole functions at a time."""
    return set().union(*(lines_of_code(code) for code in entered
                         if not code.co_name.startswith("<")))


def test_a_tick_is_a_short_table_of_contents_of_short_phases() -> None:
    assert len(inspect.getsource(World.step).splitlines()) <= STEP_LINES
    called = set(re.findall(r"self\.(_\w+)\(", inspect.getsource(World.step)))
    assert len(called) >= 8
    for name in called:
        assert len(inspect.getsource(getattr(World, name)).splitlines()) <= PHASE_LINES, name


def test_a_tick_of_the_first_level_runs_a_few_hundred_lines_in_a_few_files() -> None:
    """Counts of code run, not times: what a reader following a tick has to read. The
    lines run, and the whole functions they lie in, each at most ``TICK_LINES``, all in
    at most ``TICK_FILES`` files, on every one of the ticks and on all of them together."""
    entered: set[CodeType] = set()
    runs = traced_ticks(TRACED_TICKS, entered)
    ran = set().union(*runs)
    assert len(ran) <= TICK_LINES
    read = lines_of_the_functions_entered(entered)
    assert ran <= read  # every line run lies in a function read
    assert len(read) <= TICK_LINES
    assert len({path for path, _ in read}) <= TICK_FILES
    assert max(len({path for path, _ in tick}) for tick in runs) <= TICK_FILES


def test_the_platforms_query_the_tour_cites_is_the_one_a_tick_asks(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Step 3 of the README's tour names ``PlatformIndex.entries_in`` as the platforms'
    query: on a shipped level with platforms, the tick's lookups go through it."""
    tour = steps_text_of_the_readme()
    assert "PlatformIndex.entries_in" in tour
    asked: list[tuple[float, ...]] = []
    plain = PlatformIndex.entries_in

    def counted(index: PlatformIndex, left: float, top: float, right: float, bottom: float,
                leaving_out: Platform | None = None) -> list[Entry]:
        asked.append((left, top, right, bottom))
        return plain(index, left, top, right, bottom, leaving_out)

    monkeypatch.setattr(PlatformIndex, "entries_in", counted)
    script = input_script(ROOT / "tests" / "scripts" / "04-moving-parts.txt")
    world = World(load_level(LEVELS_DIR / "04-moving-parts.tmx"))
    for tick in range(TRACED_TICKS):
        world.step(script.held_at(tick))
    assert asked


TICK_MODULES = ["game/collision/axis_sweep.py", "game/collision/tile_grid.py",
                "game/sim/world.py", "game/sim/solids.py", "game/sim/body.py",
                "game/sim/player.py", "game/sim/enemy.py", "game/sim/pickups.py"]


@pytest.mark.parametrize("path", TICK_MODULES)
def test_the_tick_reads_plainly_each_name_for_what_it_is(path: str) -> None:
    """No module of a tick renames an enum's members (a side, a kind, an action read as a
    bare ``LEFT`` means one thing here and another there) or builds a tuple around its
    class's own constructor: the code says what it means, spelt as it reads."""
    source = (ROOT / path).read_text(encoding="utf-8")
    tree = ast.parse(source)
    for node in tree.body:
        if isinstance(node, ast.Assign):
            values = node.value.elts if isinstance(node.value, ast.Tuple) else [node.value]
            for value in values:
                assert not (isinstance(value, ast.Attribute) and value.attr.isupper()
                            and isinstance(value.value, ast.Name)
                            and value.value.id[:1].isupper()), (path, ast.unparse(node))
    assert "tuple.__new__" not in source
    assert "Speed, kept" not in source
