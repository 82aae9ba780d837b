"""What the level tools print is bounded, escaped and honest, and an output nobody reads
ends them quietly: each test is a hostile input the level tools must answer in one line.

Closed and full outputs need the program itself (a real descriptor 1); the rest is called
in this process (:mod:`tests.in_process`).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from types import FrameType
from typing import IO

import pygame
import pytest

from game.checker.cli import main as levels_main
from game.levels import load_level
from game.levels.errors import WARNINGS_SHOWN_PER_KIND, clipped, escaped
from game.sim.inputs import InputScript
from tests.in_process import Ran, call_main
from tests.maps import write_tmx
from tests.test_loader import GROUND, TILESET, write_map

ROOT = Path(__file__).resolve().parent.parent
ENV = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy",
       "PYTHONDONTWRITEBYTECODE": "1"}
TIMEOUT_S = 60  # a hang guard, not a speed limit


@contextmanager
def closed_or_full(kind: str) -> Iterator[IO[bytes] | int]:
    """A standard output that fails every write: a pipe whose reader has gone (``| head``
    after it stopped reading), or ``/dev/full``."""
    if kind == "full":
        with open("/dev/full", "wb") as full:
            yield full
        return
    reader, writer = os.pipe()
    os.close(reader)
    try:
        yield writer
    finally:
        os.close(writer)


def run_into(kind: str, args: list[str]) -> subprocess.CompletedProcess[str]:
    with closed_or_full(kind) as stdout:
        return subprocess.run([sys.executable, *args], cwd=ROOT, env=ENV, stdout=stdout,
                              stderr=subprocess.PIPE, text=True, timeout=TIMEOUT_S,
                              check=False)


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
@pytest.mark.parametrize("kind", ["closed", "full"])
@pytest.mark.parametrize("command", ["check", "check-json", "reach", "lab --list"])
def test_an_output_closed_or_full_ends_the_command_quietly_with_its_status(
        tmp_path: Path, kind: str, command: str) -> None:
    level = write_tmx(tmp_path, ["P   D", "#####"])
    args = {"check": ["-m", "game.levels", "check", str(level), "--jobs", "1"],
            "check-json": ["-m", "game.levels", "check", str(level), "--format", "json"],
            "reach": ["-m", "game.levels", "reach"],
            "lab --list": ["-m", "game.lab", "--list"]}[command]
    ran = run_into(kind, args)
    assert (ran.returncode, ran.stderr) == (0, "")


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
@pytest.mark.parametrize("kind", ["closed", "full"])
def test_solve_writes_its_route_whatever_becomes_of_its_output(tmp_path: Path,
                                                               kind: str) -> None:
    """With --out the route is a file, written whatever the output; without, a route that
    could not be printed is said (status 1), never lost in silence."""
    level = write_tmx(tmp_path, ["P   D", "#####"])
    script = tmp_path / "route.txt"
    written = run_into(kind, ["-m", "game.levels", "solve", str(level), "--out", str(script)])
    assert written.returncode == 0 and "Traceback" not in written.stderr
    assert script.read_text(encoding="utf-8").strip()
    printed = run_into(kind, ["-m", "game.levels", "solve", str(level)])
    assert printed.returncode == 1
    assert "Traceback" not in printed.stderr and "Exception ignored" not in printed.stderr
    assert "give --out SCRIPT" in printed.stderr.strip().splitlines()[-1]


def checker(*args: str | Path) -> Ran:
    return call_main(levels_main, ["check", "--jobs", "1", *map(str, args)])


def as_json(ran: Ran) -> dict[str, object]:
    document = json.loads(ran.stdout)
    assert isinstance(document, dict)
    return document


def test_a_tick_of_5000_digits_is_read_as_the_number_it_is() -> None:
    script = InputScript.parse("0" * 4999 + "7 +jump\n", "win.txt")
    assert [event.tick for event in script.events] == [7]


def test_a_firstgid_of_5000_digits_is_out_of_range_in_a_sentence(tmp_path: Path) -> None:
    level = write_tmx(tmp_path, ["P   D", "#####"])
    text = level.read_text(encoding="utf-8")
    level.write_text(text.replace('firstgid="1"', f'firstgid="{"1" * 5000}"'),
                     encoding="utf-8")
    ran = checker(level, "--no-solve")
    (line, _summary) = ran.stdout.splitlines()
    assert ran.returncode == 1 and "firstgid is '1111" in line
    assert "(5,000 characters), not a whole number from 1 to" in line


FOLDER_DEPTH = 300  # folders, one in the other, for the walk below
FRAMES_LEFT = 150  # Python frames the check may add to the test's (a shallow map needs 30)


def frames_in_use() -> int:
    """How many Python frames are on the stack now, this function's own included."""
    frame: FrameType | None = sys._getframe()
    frames = 0
    while frame is not None:
        frame, frames = frame.f_back, frames + 1
    return frames


def test_a_folder_deeper_than_the_recursion_limit_is_walked_without_recursion(
        tmp_path: Path) -> None:
    """The check may recurse ``FRAMES_LEFT`` frames deeper than the test, half the folders'
    depth: a walk (or a path's resolving) that took a frame for each folder would fail, as
    it would at 1,000 folders with Python's own limit, and the walk costs a sixteenth."""
    deepest = tmp_path
    for _ in range(FOLDER_DEPTH):  # os.makedirs would itself recurse
        deepest = deepest / "a"
        deepest.mkdir()
    write_tmx(deepest, ["P   D", "#####"])
    limit = sys.getrecursionlimit()
    try:
        sys.setrecursionlimit(frames_in_use() + FRAMES_LEFT)
        try:
            ran = checker(tmp_path, "--no-solve")
        finally:
            sys.setrecursionlimit(limit)
        assert ran.returncode == 0 and ran.stdout.startswith("checked 1 map(s): all playable")
    finally:
        while deepest != tmp_path:  # shutil.rmtree recurses too
            for child in deepest.iterdir():
                child.unlink()
            deepest.rmdir()
            deepest = deepest.parent


def test_a_proof_that_is_a_pipe_is_refused_at_once(tmp_path: Path) -> None:
    level = write_tmx(tmp_path, ["P   D", "#####"])
    pipe = tmp_path / "win.txt"
    os.mkfifo(pipe)
    ran = call_main(levels_main, ["check", str(level), "--proof", str(pipe)], hang_s=20)
    line = ran.stdout.splitlines()[0]
    assert ran.returncode == 1
    assert line.startswith(f"{pipe}: the input script is not a regular file")


@pytest.mark.parametrize(("content", "problem"), [
    (b"0 +right\n" + b"9" * 5000 + b" +jump\n", "line 2: the tick '9999"),
    (b"0 +right\n3 +fly\n", "line 2: unknown action 'fly'"),
    (b"0 +right\n\xe9 +jump\n", "the input script is not UTF-8 text"),
])
def test_a_bad_proof_is_said_of_the_script_and_its_line_not_of_the_map(
        tmp_path: Path, content: bytes, problem: str) -> None:
    level = write_tmx(tmp_path, ["P   D", "#####"])
    script = tmp_path / "win.txt"
    script.write_bytes(content)
    ran = checker(level, "--proof", script)
    line = ran.stdout.splitlines()[0]
    assert ran.returncode == 1 and line.startswith(f"{script}: {problem}"), line
    assert " — " in line and "could not be read" not in line
    summary = ran.stdout.splitlines()[-1]  # the map is not counted as bad for the script
    assert "not playable" not in summary
    assert "1 not judged (the --proof script cannot be read)" in summary


def layer_named(name: str, attrs: str = "") -> str:
    """A 4x3 tile layer named ``name`` (as XML), with ``attrs``."""
    escaped_name = (name.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
                    .replace("\n", "&#10;"))
    return (f'<layer name="{escaped_name}" width="4" height="3" {attrs}>'
            f'<data encoding="csv">{GROUND}</data></layer>')


@pytest.mark.parametrize("name", ["object #2 tile (7,3)", "object #" + "9" * 5000,
                                  "tile (" + "1" * 5000 + ",2)"])
def test_a_json_finding_takes_its_object_and_tile_from_the_map_not_from_names(
        tmp_path: Path, name: str) -> None:
    level = write_map(tmp_path, layer_named(name, 'offsetx="nan"'))
    ran = checker(level, "--format", "json", "--no-solve")
    (finding,) = as_json(ran)["maps"][0]["findings"]  # type: ignore[index]
    assert ran.returncode == 1 and "offsetx" in finding["message"]
    assert (finding["object_id"], finding["tile"]) == (None, None)
    assert finding["layer"] == clipped(name)


def test_json_escapes_what_the_text_escapes(tmp_path: Path) -> None:
    name = "sky\nchecked 1 map(s): all playable \u202egnp.exe"
    level = write_map(tmp_path, layer_named(name, 'offsetx="nan"'))
    text = checker(level, "--no-solve").stdout.splitlines()[0]
    ran = checker(level, "--format", "json", "--no-solve")
    report = as_json(ran)["maps"][0]  # type: ignore[index]
    (finding,) = report["findings"]
    assert finding["text"] == text and "\\n" in text and "\\u202e" in text
    for value in (finding["text"], finding["place"], finding["layer"], report["path"]):
        assert escaped(value) == value


def test_json_is_bounded_as_the_text_is(tmp_path: Path) -> None:
    """Long names and one slip repeated: the JSON holds what the lines hold, no more."""
    props = '<properties><property name="note" value="x"/></properties>'
    layers = "".join(f'<objectgroup name="{chr(65 + i) * 100_000}">{props}</objectgroup>'
                     for i in range(20))
    level = write_map(tmp_path, layer_named("ground") + layers)
    text = checker(level, "--no-solve").stdout
    ran = checker(level, "--format", "json", "--no-solve")
    findings = as_json(ran)["maps"][0]["findings"]  # type: ignore[index]
    assert len(text) < 10_000 and len(ran.stdout) < 4 * len(text)
    assert findings[-1]["message"] == "… and 15 more like the warnings above"


def test_warnings_about_hidden_objects_are_bounded_per_kind(tmp_path: Path) -> None:
    coins = "".join(f'<object id="{10 + i}" type="Coin" x="40" y="8" width="8" height="8"/>'
                    for i in range(2_000))
    hidden = f'<objectgroup name="{"h" * 50_000}" visible="0">{coins}</objectgroup>'
    level = write_map(tmp_path, layer_named("ground") + hidden)
    ran = checker(level, "--no-solve")
    lines = ran.stdout.splitlines()
    assert len(lines) == WARNINGS_SHOWN_PER_KIND + 2, lines[-3:]
    assert lines[-2].endswith("… and 1,995 more like the warnings above — show the layer "
                              "if the object belongs in the level, or delete it if it is "
                              "left over")
    assert max(len(line) for line in lines) < 1_500


@pytest.mark.usefixtures("display")
def test_the_checker_and_the_game_spend_the_same_pixel_budget(tmp_path: Path) -> None:
    """An image of 3008x3008 (more than half the budget) passes the check, so the game,
    which checks it and then hands it to pytmx, must load it too: counted once."""
    pygame.image.save(pygame.Surface((3_008, 3_008)), str(tmp_path / "big.png"))
    image = '<image source="big.png" width="3008" height="3008"/>'
    level = write_map(tmp_path, tileset=TILESET.format(image=image))
    assert checker(level, "--no-solve").returncode == 0
    assert load_level(level, images=True).tile_images
