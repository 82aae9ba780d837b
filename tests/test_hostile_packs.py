"""Well-formed but hostile level packs: each is rebuilt from its description and must end in
one sentence, its exit status, no traceback, and nothing opened outside the pack's folder.

The packs: a project whose ``assets`` or ``levels`` is a link out, a map that is itself a
link, ``--watch`` led to files by elements the loader never reads, a GIF whose frame is
larger than its screen after a stray byte. Where ``strace`` is installed, the commands are
run under it and every file they open is compared with the pack's folder; the other commands
are called in this process (:mod:`tests.in_process`), but for Ctrl-C, an undecodable
argument and a window, which need the program itself.
"""

from __future__ import annotations

import os
import re
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import pygame
import pytest

from game.app import cli
from game.app import run as run_module
from game.app.run import input_script
from game.app.watch import FileWatcher, level_files
from game.checker.cli import main as levels_main
from game.collision.tile_grid import TileGrid, TileShape
from game.levels import LevelError, budget, check_level, errors, layers, load_level
from game.levels.images import header_size
from tests.hang_guard import HANG_S
from tests.in_process import Ran, call_main
from tests.test_loader import OBJECTS, TILESET, write_map

ROOT = Path(__file__).resolve().parent.parent
ENV = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy",
       "PYTHONDONTWRITEBYTECODE": "1", "PYTHONWARNINGS": "ignore"}
MAX_MESSAGE_CHARS = 1_000
CIRCLE_LEVELS = 20  # the limit of levels in one run, for the circle of levels below
STRACE = shutil.which("strace")
# The 47-byte GIF: a 16x16 screen, a stray byte, then a 65535x65535 frame.
HOSTILE_GIF = (b"GIF89a" + struct.pack("<HH", 16, 16) + b"\x80\0\0" + bytes(6)
               + b"!\xf9\x04" + bytes(4) + b"\0"  # a graphic control extension
               + b"\x00" + b"," + struct.pack("<HHHH", 0, 0, 65535, 65535) + b"\0"
               + b"\x02\x05\x44\x01\x00\x00\x00\0;")


def one_sentence(text: str) -> str:
    """The single line of ``text``; fail if it is empty, several lines or a traceback."""
    assert "Traceback" not in text, text
    lines = text.strip().splitlines()
    assert len(lines) == 1, text[:MAX_MESSAGE_CHARS]
    assert 0 < len(lines[0]) <= MAX_MESSAGE_CHARS and " — " in lines[0]
    return lines[0]


def run(args: list[str], cwd: Path, traced: Path | None = None
        ) -> subprocess.CompletedProcess[str]:
    """``python ARGS`` in ``cwd``; with ``traced``, under strace writing to that file."""
    command = [sys.executable, *args]
    if traced is not None:
        assert STRACE is not None
        command = [STRACE, "-f", "-qq", "-e", "trace=open,openat", "-o", str(traced), *command]
    return subprocess.run(command, cwd=cwd, env=ENV, capture_output=True, text=True,
                          timeout=120, check=False)


def checker(*args: str | Path) -> Ran:
    """``python -m game.levels check ARGS``, called in this process."""
    return call_main(levels_main, ["check", *args])


def game(*args: str | Path) -> Ran:
    """``python -m game ARGS``, called in this process (a FIFO must not be waited on)."""
    return call_main(cli.main, args, hang_s=HANG_S)


def opened_outside(trace: Path, pack: Path, secret: Path) -> list[str]:
    """Files under ``secret`` that the traced command opened (``pack`` is where it may)."""
    named = re.findall(r'open(?:at)?\([^"]*"([^"]+)"', trace.read_text(errors="replace"))
    return [name for name in named if name.startswith(str(secret))
            and not name.startswith(str(pack))]


def tiny_png(path: Path, size: tuple[int, int] = (64, 16)) -> None:
    pygame.image.save(pygame.Surface(size), str(path))


def secret_tileset(folder: Path) -> Path:
    """A valid tileset and image somewhere a pack should never reach."""
    folder.mkdir()
    tiny_png(folder / "secret.png")
    (folder / "secret.tsx").write_text(
        TILESET.format(image='<image source="secret.png" width="64" height="16"/>')
        .replace('firstgid="1" ', ""), encoding="utf-8")
    return folder / "secret.tsx"


# -- one sandbox -----------------------------------------------------------------------------

def linked_project(tmp_path: Path, link: str) -> tuple[Path, Path, Path]:
    """A pack whose ``link`` folder (assets or levels) is a symbolic link to ``/``, and a map
    in it naming a tileset elsewhere on the machine through that link."""
    secret = secret_tileset(tmp_path / "secret")
    pack = tmp_path / "pack"
    pack.mkdir()
    for name in ("levels", "assets"):
        if name == link:
            os.symlink("/", pack / name)
        else:
            (pack / name).mkdir()
    folder = pack / "levels" if link == "assets" else pack
    reference = f"../{link}{secret}"
    tileset = f'<tileset firstgid="1" source="{reference}"/>'
    return pack, write_map(folder, tileset=tileset), secret


def test_a_project_whose_assets_folder_links_to_the_root_is_not_a_project(
        tmp_path: Path) -> None:
    pack, level, secret = linked_project(tmp_path, "assets")
    [error] = check_level(level).errors
    assert "leads outside the level's folder" in str(error)
    done = run(["-m", "game.levels", "check", str(level), "--no-solve"], pack,
               tmp_path / "trace" if STRACE else None)
    assert done.returncode == 1 and "Traceback" not in done.stderr + done.stdout
    assert "leads outside" in done.stdout and "all playable" not in done.stdout
    if STRACE:
        assert opened_outside(tmp_path / "trace", pack, secret.parent) == []


def test_a_project_whose_levels_folder_is_a_link_trusts_only_the_map_folder(
        tmp_path: Path) -> None:
    _pack, level, _secret = linked_project(tmp_path, "levels")
    [error] = check_level(level).errors
    assert "leads outside the level's folder" in str(error)


def test_a_map_that_is_a_link_to_a_map_elsewhere_is_refused_unread(tmp_path: Path) -> None:
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    real_map = write_map(elsewhere)
    pack = tmp_path / "pack"
    pack.mkdir()
    os.symlink(real_map, pack / "level.tmx")
    with pytest.raises(Exception) as caught:
        load_level(pack / "level.tmx")
    assert "the map is a link that leads outside its folder" in str(caught.value)
    done = run(["-m", "game.levels", "check", str(pack), "--no-solve"], tmp_path,
               tmp_path / "trace" if STRACE else None)
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "link that leads outside" in done.stdout
    if STRACE:
        assert opened_outside(tmp_path / "trace", pack, elsewhere) == []
    played = game("--headless", "--ticks", "5", "--level", pack / "level.tmx")
    assert played.returncode == 1
    assert "link that leads outside" in one_sentence(played.stderr)


def test_a_link_to_a_map_inside_the_same_folder_is_still_read(tmp_path: Path) -> None:
    level = write_map(tmp_path)
    os.symlink(level.name, tmp_path / "alias.tmx")
    assert load_level(tmp_path / "alias.tmx").spawn == load_level(level).spawn


# -- --watch watches what the loader read -----------------------------------------------------

def test_watch_never_follows_what_the_loader_does_not_read(tmp_path: Path) -> None:
    """A <tileset> hidden in a group, an absolute template on a layer and an image on a
    property: the loader reads none of them, so the watcher does not even stat them, and a
    FIFO among them cannot freeze it."""
    secret = secret_tileset(tmp_path / "secret")
    pack = tmp_path / "pack"
    pack.mkdir()
    os.mkfifo(pack / "trap.tsx")
    body = (f'<group name="g"><tileset firstgid="50" source="{secret}"/>'
            f'<tileset firstgid="60" source="trap.tsx"/></group>'
            f'<layer name="ground" width="4" height="3" template="{secret}">'
            '<data encoding="csv">0,0,0,0,\n0,0,0,0,\n1,1,1,1</data></layer>')
    level = write_map(pack, body)
    watched = level_files(level)
    assert watched == [level]
    assert not any(str(path).startswith(str(secret.parent)) for path in watched)
    assert not FileWatcher(level).poll(10.0)
    if STRACE:  # the watcher, started and polled, opens nothing the loader would not
        code = ("import sys; from pathlib import Path; from game.app.watch import FileWatcher;"
                " w = FileWatcher(Path(sys.argv[1])); w.poll(1e9); w.poll(2e9)")
        done = run(["-c", code, str(level)], tmp_path, tmp_path / "trace")
        assert done.returncode == 0, done.stderr
        assert opened_outside(tmp_path / "trace", pack, secret.parent) == []
        assert "trap.tsx" not in (tmp_path / "trace").read_text(errors="replace")


def test_watch_lists_the_tileset_and_images_the_loader_opened(tmp_path: Path) -> None:
    tiny_png(tmp_path / "t.png")
    (tmp_path / "t.tsx").write_text(TILESET.format(
        image='<image source="t.png" width="64" height="16"/>').replace('firstgid="1" ', ""),
        encoding="utf-8")
    level = write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsx"/>')
    assert level_files(level) == [level, (tmp_path / "t.tsx").resolve(),
                                  (tmp_path / "t.png").resolve()]


def test_a_fifo_named_as_a_tileset_is_refused_at_once(tmp_path: Path) -> None:
    os.mkfifo(tmp_path / "t.tsx")
    level = write_map(tmp_path, tileset='<tileset firstgid="1" source="t.tsx"/>')
    played = game("--headless", "--ticks", "5", "--level", level)
    assert played.returncode == 1
    assert "not a regular file" in one_sentence(played.stderr)


# -- the decoder's answer is the one checked --------------------------------------------------

def test_a_47_byte_gif_with_a_huge_frame_after_a_stray_byte_is_refused(tmp_path: Path) -> None:
    assert len(HOSTILE_GIF) == 47
    assert header_size(HOSTILE_GIF) == ("GIF", 65535, 65535)
    (tmp_path / "t.gif").write_bytes(HOSTILE_GIF)
    level = write_map(tmp_path, tileset=TILESET.format(
        image='<image source="t.gif" width="16" height="16"/>'))
    done = checker(level, "--no-solve")
    assert done.returncode == 1 and "Traceback" not in done.stderr
    [line] = [line for line in done.stdout.splitlines() if "t.gif" in line]
    assert "65535x65535 GIF" in line and "16384 pixels a side" in line
    game = run(["-m", "game", "--ticks", "1", "--level", str(level)], tmp_path)
    assert game.returncode == 1 and "65535x65535" in one_sentence(game.stderr)


def test_a_gif_frame_placed_past_its_screen_counts_where_it_ends() -> None:
    gif = (b"GIF89a" + struct.pack("<HH", 16, 16) + b"\0\0\0"
           + b"," + struct.pack("<HHHHB", 10, 0, 16, 16, 0) + b"\x02\x02\x44\x01\0"
           + b"," + struct.pack("<HHHHB", 0, 0, 9000, 4, 0) + b"\x02\x02\x44\x01\0;")
    assert header_size(gif) == ("GIF", 9000, 16)


def test_a_png_named_gif_is_decoded_as_what_it_was_measured_as(tmp_path: Path) -> None:
    tiny_png(tmp_path / "t.png")
    (tmp_path / "t.png").rename(tmp_path / "t.gif")
    level = write_map(tmp_path, tileset=TILESET.format(
        image='<image source="t.gif" width="64" height="16"/>'), objects=OBJECTS)
    assert check_level(level).errors == []


# -- a budget for everything a level makes ----------------------------------------------------

def big_map(folder: Path, cols: int, rows: int, gid: int = 1, *, tileset: str = "",
            objects: str = OBJECTS, body_extra: str = "") -> Path:
    """A ``cols`` x ``rows`` map whose bottom row is tile ``gid`` and the rest empty."""
    data = ",".join(["0"] * (cols * (rows - 1)) + [str(gid)] * cols)
    body = (f'<layer name="ground" width="{cols}" height="{rows}"><data encoding="csv">'
            f"{data}</data></layer>{body_extra}")
    attrs = (f'orientation="orthogonal" width="{cols}" height="{rows}" tilewidth="16" '
             'tileheight="16" infinite="0"')
    return write_map(folder, body, tileset=tileset or TILESET.format(image=""),
                     objects=objects, map_attrs=attrs)


def refusal(level: Path) -> str:
    """The one sentence the game says for ``level``, checked to be one line."""
    with pytest.raises(LevelError) as caught:
        load_level(level)
    return one_sentence(str(caught.value))


def test_forty_collision_rectangles_on_one_tile_are_refused_before_any_is_placed(
        tmp_path: Path) -> None:
    rects = "".join(f'<object id="{i}" x="{i % 16}" y="{i // 16}" width="1" height="1"/>'
                    for i in range(40))
    tileset = ('<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="1" '
               f'columns="1"><tile id="0" type="Solid"><objectgroup>{rects}</objectgroup>'
               '</tile></tileset>')
    level = big_map(tmp_path, 500, 498, tileset=tileset)
    message = refusal(level)
    assert f"more than {budget.MAX_SHAPES_PER_TILE} collision rectangles" in message


def test_the_collision_shapes_of_a_whole_map_are_counted_before_they_are_made(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    rects = "".join(f'<object id="{i}" x="{i}" y="0" width="1" height="1"/>'
                    for i in range(budget.MAX_SHAPES_PER_TILE))
    tileset = ('<tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="1" '
               f'columns="1"><tile id="0" type="Solid"><objectgroup>{rects}</objectgroup>'
               '</tile></tileset>')
    cells = budget.MAX_SHAPES // budget.MAX_SHAPES_PER_TILE + 1
    level = big_map(tmp_path, cells, 3, tileset=tileset)
    made: list[TileShape] = []
    monkeypatch.setattr(TileGrid, "put", lambda _grid, _col, _row, shape: made.append(shape))
    assert f"more than {budget.MAX_SHAPES:,} collision shapes" in refusal(level)
    assert made == []  # not one of them was made


def objects_of(kind: str, count: int, size: int, extra: str = "") -> str:
    return ('<objectgroup id="9" name="objects">'
            '<object id="1" type="Player" x="2" y="2"><point/></object>'
            '<object id="2" type="Exit" x="48" y="16" width="16" height="16"/>'
            + "".join(f'<object id="{i + 3}" type="{kind}" x="{i % 40}" y="0" '
                      f'width="{size}" height="{size}">{extra}</object>'
                      for i in range(count)) + "</objectgroup>")


PLATFORM = ('<properties><property name="width" type="float" value="4096"/>'
            '<property name="height" type="float" value="4096"/></properties>'
            '<polyline points="0,0 32,0"/>')


@pytest.mark.parametrize(("kind", "count", "size", "extra", "said"), [
    ("Coin", budget.MAX_COINS + 1, 512, "", f"{budget.MAX_COINS + 1:,} Coins"),
    ("Enemy", budget.MAX_ENEMIES + 1, 16, "", f"{budget.MAX_ENEMIES + 1:,} Enemies"),
    ("Coin", 200, 4096, "", "pixels in all"),
    ("Platform", 200, 16, PLATFORM, "pixels in all"),
])
def test_sprites_and_their_pixels_are_counted_before_any_surface_is_made(
        tmp_path: Path, kind: str, count: int, size: int, extra: str, said: str) -> None:
    level = big_map(tmp_path, 260, 260, objects=objects_of(kind, count, size, extra))
    message = refusal(level)
    assert said in message and "one level" in message
    findings = check_level(level)
    assert findings.errors and "all playable" not in str(findings.errors)


def test_a_tileset_named_a_thousand_times_is_cut_within_the_budget(tmp_path: Path) -> None:
    (tmp_path / "strip.tsx").write_text(
        '<tileset name="strip" tilewidth="1" tileheight="1" tilecount="1" columns="1">'
        '<image source="strip.png" width="16384" height="16"/></tileset>', encoding="utf-8")
    mentions = "".join(f'<tileset firstgid="{1 + 2 * i}" source="strip.tsx"/>'
                       for i in range(999))
    level = write_map(tmp_path, tileset=TILESET.format(image="").replace(
        'firstgid="1"', 'firstgid="3000"') + mentions)
    message = refusal(level)
    assert f"at most {budget.MAX_TILES_CUT:,}" in message


def test_animated_cells_past_the_budget_are_refused(tmp_path: Path) -> None:
    frames = "".join(f'<frame tileid="{i % 2}" duration="100"/>' for i in range(1_000))
    tileset = TILESET.format(image='<image source="t.png" width="64" height="16"/>').replace(
        '<tile id="0" type="Solid"/>', f'<tile id="0" type="Solid"><animation>{frames}'
        '</animation></tile>')
    cells = budget.MAX_ANIMATED_CELLS + 1
    level = big_map(tmp_path, cells // 2 + 1, 3, tileset=tileset)
    data = level.read_text(encoding="utf-8").replace(',0,', ',1,', cells)
    level.write_text(data, encoding="utf-8")
    assert "animated tiles" in refusal(level)


def test_offsets_that_overflow_only_when_added_are_refused(tmp_path: Path) -> None:
    body = ('<group name="far" offsetx="1.7e308"><layer name="ground" width="4" height="3" '
            'offsetx="1.7e308"><data encoding="csv">0,0,0,0,\n0,0,0,0,\n1,1,1,1</data>'
            '</layer></group>')
    level = write_map(tmp_path, body)
    assert "its offset, added to its groups'" in refusal(level)
    done = checker(level, "--no-solve")
    assert done.returncode == 1 and "Traceback" not in done.stderr
    assert "all playable" not in done.stdout


def test_a_circle_of_levels_won_at_the_spawn_stops_with_a_sentence(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """At the budget's limit, here made 20 levels (each is read again from its file as it
    starts, so 1,000 would cost a second or two for the same sentence); the guide's table
    gives the real one (``test_the_designers_guide_gives_every_limit_of_the_budget``)."""
    assert vars(run_module)["MAX_LEVELS_PER_RUN"] == budget.MAX_LEVELS_PER_RUN  # the run's own
    monkeypatch.setattr(run_module, "MAX_LEVELS_PER_RUN", CIRCLE_LEVELS)
    exit_at_spawn = OBJECTS.replace('x="48" y="16"', 'x="0" y="0"')
    for name, other in (("a.tmx", "b.tmx"), ("b.tmx", "a.tmx")):
        write_map(tmp_path, objects=exit_at_spawn, name=name).write_text(
            (tmp_path / name).read_text(encoding="utf-8").replace(
                '<map version="1.8" ', '<map version="1.8" ').replace(
                "</map>", '<properties><property name="next_level" type="file" '
                f'value="{other}"/></properties></map>'), encoding="utf-8")
    played = game("--headless", "--level", tmp_path / "a.tmx")
    assert played.returncode == 1
    message = one_sentence(played.stderr)
    assert f"{CIRCLE_LEVELS} levels were completed" in message


# -- output that cannot lie -------------------------------------------------------------------

FORGED = "coin\nchecked 1 map(s): all playable\r\x9b2J\u202etxt.exe"


def test_a_name_cannot_forge_a_line_or_send_controls_to_the_terminal(tmp_path: Path) -> None:
    objects = OBJECTS.replace('name="hero"', f'name="{escape_xml(FORGED)}"').replace(
        '<object id="2" type="Exit"', f'<object id="3" name="{escape_xml(FORGED)}" '
        'type="Chest" x="1" y="1"/><object id="2" type="Exit"')
    level = write_map(tmp_path, layer_named(FORGED), objects=objects)
    done = checker(level, "--no-solve")
    assert "Traceback" not in done.stderr
    lines = done.stdout.splitlines()
    assert sum(line.startswith("checked 1 map(s)") for line in lines) == 1
    assert lines[-1].startswith("checked 1 map(s)")
    for char in ("\r", "\x9b", "\u202e", "\x1b"):
        assert char not in done.stdout
    assert "\\nchecked 1 map(s)" in done.stdout and "\\u202e" in done.stdout


def escape_xml(text: str) -> str:
    return "".join(f"&#{ord(c)};" if c in "\n\r" else c for c in text)


def layer_named(name: str) -> str:
    return (f'<layer name="{escape_xml(name)}" width="4" height="3">'
            '<properties><property name="gravity" value="1"/></properties>'
            '<data encoding="csv">0,0,0,0,\n0,0,0,0,\n1,1,1,1</data></layer>')


def test_warnings_of_one_kind_are_counted_and_shown_a_few_at_a_time(tmp_path: Path) -> None:
    floating = "".join(f'<object id="{i}" type="Exit" x="{i % 40}" y="0" width="4" height="4"/>'
                       for i in range(3, 1_003))
    level = big_map(tmp_path, 40, 3, objects=OBJECTS.replace("</objectgroup>", floating
                                                             + "</objectgroup>"))
    lines = list(check_level(level).lines())
    floats = [line for line in lines if "floats" in line]
    assert len(floats) == errors.WARNINGS_SHOWN_PER_KIND
    [more] = [line for line in lines if "… and" in line]
    assert f"… and {1_000 - errors.WARNINGS_SHOWN_PER_KIND:,} more" in more
    assert len(lines) < 20


# -- the command line's edges -----------------------------------------------------------------

def test_ctrl_c_while_the_modules_load_is_status_130_and_one_line(tmp_path: Path) -> None:
    """Python sets argv[0] to "-m" while ``python -m`` imports the packages; a SIGINT that
    lands in the imports after the package's first line is the guard's."""
    code = ("import os, signal, sys; sys.argv[0] = '-m'; import game; "
            "os.kill(os.getpid(), signal.SIGINT); import game.levels.loader; print('on')")
    done = run(["-c", code], tmp_path)
    assert done.returncode == 130 and done.stderr == "stopped by Ctrl-C\n"
    assert "on" not in done.stdout


# The headless run plays 12,000 ticks: longer than the latest Ctrl-C below (1 s), and short
# enough that a run the signal missed costs about a second, not the nine of 100,000 ticks.
@pytest.mark.parametrize("module", [["game.levels", "check", "levels", "--no-solve"],
                                    ["game.lab", "--list"],
                                    ["game", "--headless", "--ticks", "12000"]])
def test_ctrl_c_at_any_moment_never_shows_a_traceback_through_the_game(
        module: list[str]) -> None:
    import signal
    import time

    for delay in (0.1, 0.3, 0.6, 1.0):
        process = subprocess.Popen(
            [sys.executable, "-m", *module], cwd=ROOT, env=ENV, text=True,
            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        time.sleep(delay)
        process.send_signal(signal.SIGINT)
        _out, err = process.communicate(timeout=120)
        # Before the package's first line runs, the interpreter's own start-up is Python's.
        assert f"{os.sep}game{os.sep}" not in err, err
        if "Traceback" not in err and process.returncode not in (0, -signal.SIGINT):
            assert process.returncode == 130 and "stopped by Ctrl-C" in err


def outputs(folder: Path, name: str) -> list[str]:
    return ["--report", str(folder / f"{name}.json"), "--record", str(folder / f"{name}.txt"),
            "--screenshot", str(folder / name)]


@pytest.mark.parametrize("name", ["odd\udcff\udcfename", "x" * 240])
def test_output_names_of_any_bytes_and_any_length_are_written_under_that_name(
        tmp_path: Path, name: str) -> None:
    level = str(ROOT / "levels/01-first-steps.tmx")
    assert cli.main(["--headless", "--ticks", "5", "--level", level,
                     *outputs(tmp_path, name)]) == 0
    written = sorted(os.fsencode(p.name) for p in tmp_path.iterdir())
    expected = sorted(os.fsencode(n) for n in (f"{name}.json", f"{name}.txt", name))
    assert written == expected
    assert (tmp_path / name).read_bytes().startswith(b"\x89PNG")
    lab = subprocess.run([sys.executable, "-m", "game.lab", "--scene", "overlap",
                          "--screenshot", os.fsencode(tmp_path / f"{name}.png")], env=ENV,
                         capture_output=True, timeout=120, check=False)
    assert lab.returncode == 0, lab.stderr
    assert (tmp_path / f"{name}.png").read_bytes().startswith(b"\x89PNG")


def test_a_failed_picture_write_leaves_nothing_and_names_the_file(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    def full_disk(surface: object, stream: object, hint: str = "") -> None:
        assert hasattr(stream, "write")
        stream.write(b"\x89PNG\r\n\x1a\n" + bytes(8))
        raise pygame.error("Error writing the PNG file.")

    monkeypatch.setattr(pygame.image, "save", full_disk)
    shot = tmp_path / "shot"
    status = cli.main(["--headless", "--ticks", "5", "--level",
                       str(ROOT / "levels/01-first-steps.tmx"), "--screenshot", str(shot)])
    err = capsys.readouterr().err
    assert status == 1 and one_sentence(err).startswith(f"{shot}: could not be written")
    assert list(tmp_path.iterdir()) == []


def test_an_input_script_saved_with_a_byte_order_mark_is_read(tmp_path: Path) -> None:

    script = tmp_path / "in.txt"
    script.write_bytes(b"\xef\xbb\xbf0 +right\n")
    assert [str(e) for e in input_script(script).events] == ["0 +right"]


def test_a_run_that_does_not_record_keeps_no_input_history() -> None:
    import argparse

    from game.app.run import Run
    from game.sim.campaign import Campaign
    from game.sim.inputs import Action

    for record in (None, Path("r.txt")):
        args = argparse.Namespace(record=record, ticks=None)
        game = Run(Campaign(ROOT / "levels/01-first-steps.tmx", loader=load_level), None, args)
        for tick in range(100):
            game.tick(frozenset({Action.RIGHT}) if tick % 2 else frozenset())
        assert len(game.recorder.events) == (0 if record is None else 99)  # ticks 1..99


def test_the_designers_guide_gives_every_limit_of_the_budget() -> None:
    guide = (ROOT / "levels/README.md").read_text(encoding="utf-8")
    table = guide[guide.index("### Limits"):guide.index("### Which files")]
    for name in ("MAX_SHAPES_PER_TILE", "MAX_SHAPES", "MAX_COINS", "MAX_ENEMIES",
                 "MAX_PLATFORMS", "MAX_SPRITE_PIXELS", "MAX_TILES_CUT", "MAX_ANIMATED_CELLS",
                 "MAX_LEVELS_PER_RUN"):
        assert f"| {getattr(budget, name):,} |" in table, name
    assert f"| {layers.MAX_OFFSET_PX:,} px |" in table
    assert "five at a time" in table and errors.WARNINGS_SHOWN_PER_KIND == 5


def test_a_solver_script_that_cannot_be_written_names_the_file_and_leaves_nothing(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "missing" / ("é" * 120 + "\udcff.txt")
    status = levels_main(["solve", str(ROOT / "levels/01-first-steps.tmx"), "--out", str(out)])
    err = capsys.readouterr().err
    assert status == 1 and "the script cannot be written" in err and "Traceback" not in err
    assert "\\udcff" in err or "\\xff" in err
    assert not (tmp_path / "missing").exists()
