"""The one way out: every file a command writes is written whole, beside its target, and
never over a file the same run reads, through a link, or into a folder that is not there.

Each case is a designer's or player's file that an earlier writer lost: a screenshot or a
solver's script named like the map, a recording named like the script it replays, a route
picture named like the tileset's image, a write cut short by Ctrl-C or a full disk.
"""

from __future__ import annotations

import ast
import errno
import os
import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

from game.app import cli, files
from game.checker.cli import main as levels_main
from game.levels import outputs, reading
from tests.in_process import call_main

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tests" / "scripts" / "01-first-steps.txt"


@pytest.fixture
def pack(tmp_path: Path) -> Path:
    """A copy of the project's levels and assets: a pack whose files can be lost."""
    for name in ("levels", "assets"):
        shutil.copytree(ROOT / name, tmp_path / name,
                        ignore=shutil.ignore_patterns("screenshots", "charts", "guide"))
    shutil.copy(SCRIPT, tmp_path / "win.txt")
    return tmp_path


def _refused_and_kept(ran_status: int, err: str, kept: Path, before: bytes) -> None:
    assert ran_status == 1, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert "this run reads" in err, err
    assert kept.read_bytes() == before


@pytest.mark.parametrize("option", ["--screenshot", "--report", "--record"])
def test_a_game_output_named_like_its_level_leaves_the_level_whole(pack: Path,
                                                                   option: str) -> None:
    level = pack / "levels" / "01-first-steps.tmx"
    before = level.read_bytes()
    ran = call_main(cli.main, ["--headless", "--level", level, "--ticks", "3", option, level])
    _refused_and_kept(ran.returncode, ran.stderr, level, before)


def test_a_recording_named_like_the_script_it_replays_leaves_the_script_whole(
        pack: Path) -> None:
    script = pack / "win.txt"
    before = script.read_bytes()
    ran = call_main(cli.main, ["--headless", "--level", pack / "levels" / "01-first-steps.tmx",
                               "--inputs", script, "--record", script])
    _refused_and_kept(ran.returncode, ran.stderr, script, before)


@pytest.mark.parametrize(("option", "target"), [
    ("--out", "levels/01-first-steps.tmx"),
    ("--picture", "assets/tiles.png"),
    ("--out", "assets/tiles.png"),
    ("--out", "assets/tiles.tsx"),
])
def test_a_solver_output_named_like_its_map_or_tileset_leaves_them_whole(
        pack: Path, option: str, target: str) -> None:
    kept = pack / target
    before = kept.read_bytes()
    ran = call_main(levels_main, ["solve", pack / "levels" / "01-first-steps.tmx", option, kept])
    _refused_and_kept(ran.returncode, ran.stdout + ran.stderr, kept, before)
    assert "moves" not in ran.stdout + ran.stderr  # said before the search, not after it


def test_a_file_read_through_a_link_is_still_known_as_read(tmp_path: Path) -> None:
    real = tmp_path / "script.txt"
    real.write_text("0 right\n", encoding="utf-8")
    (tmp_path / "alias.txt").symlink_to(real)
    reading.read_text(tmp_path / "alias.txt", 100, "the script")
    assert reading.was_read(real)
    assert outputs.refusal(real) == "it is a file this run reads"


def test_a_save_read_to_be_updated_may_be_written_again(tmp_path: Path) -> None:
    save = tmp_path / "progress.json"
    save.write_text("{}", encoding="utf-8")
    files.read_small_text(save, 100, "the file", updated=True)
    files.write_text_atomically(save, '{"a": 1}')
    assert save.read_text(encoding="utf-8") == '{"a": 1}'


def _writer_that_fails_halfway(failure: BaseException) -> Callable[[Path], None]:
    def write(tmp: Path) -> None:
        with tmp.open("wb") as stream:
            stream.write(b"half of the new")
        raise failure
    return write


@pytest.mark.parametrize("failure", [KeyboardInterrupt(), OSError(errno.ENOSPC, "No space")])
def test_a_write_cut_short_keeps_the_original_and_leaves_no_temporary_file(
        tmp_path: Path, failure: BaseException) -> None:
    target = tmp_path / "map.tmx"
    target.write_bytes(b"the designer's map")
    with pytest.raises(type(failure)):
        outputs.replace_atomically(target, _writer_that_fails_halfway(failure))
    assert target.read_bytes() == b"the designer's map"
    assert [p.name for p in tmp_path.iterdir()] == ["map.tmx"]


def test_a_full_disk_is_one_sentence_that_says_to_free_space(tmp_path: Path) -> None:
    target = tmp_path / "report.json"
    target.write_text("old", encoding="utf-8")
    with pytest.raises(files.FileProblem, match=r"free some space$"):
        files.write_atomically(target, _writer_that_fails_halfway(
            OSError(errno.ENOSPC, "No space left on device")))
    assert target.read_text(encoding="utf-8") == "old"


def test_the_new_bytes_are_on_the_disk_before_the_name_moves(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    target = tmp_path / "out.txt"
    events: list[str] = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(descriptor: int) -> None:
        events.append("fsync")
        real_fsync(descriptor)

    def replace(source: str | Path, destination: str | Path) -> None:
        events.append("replace")
        real_replace(source, destination)

    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", replace)
    outputs.replace_atomically(target, lambda tmp: tmp.write_text("new", encoding="utf-8"))
    assert events[:2] == ["fsync", "replace"]
    assert target.read_text(encoding="utf-8") == "new"


def test_an_output_that_is_a_link_is_refused_and_its_target_left_alone(
        tmp_path: Path) -> None:
    outside = tmp_path / "outside.txt"
    outside.write_text("someone else's", encoding="utf-8")
    link = tmp_path / "pack" / "report.json"
    link.parent.mkdir()
    link.symlink_to(outside)
    ran = call_main(cli.main, ["--headless", "--ticks", "2", "--report", link])
    assert ran.returncode == 1 and "symbolic link" in ran.stderr
    assert outside.read_text(encoding="utf-8") == "someone else's" and link.is_symlink()


def test_a_folder_that_is_not_there_is_an_error_and_is_not_made(tmp_path: Path) -> None:
    missing = tmp_path / "no" / "such" / "folder" / "report.json"
    ran = call_main(cli.main, ["--headless", "--ticks", "2", "--report", missing])
    assert ran.returncode == 1 and "does not exist" in ran.stderr
    assert not (tmp_path / "no").exists()


def test_an_output_on_a_pipe_or_device_is_refused_and_left_what_it_is(tmp_path: Path) -> None:
    fifo = tmp_path / "out.txt"
    os.mkfifo(fifo)
    ran = call_main(levels_main, ["solve", ROOT / "levels" / "01-first-steps.tmx",
                                  "--budget", "2000", "--out", fifo])
    assert ran.returncode == 1 and "not a regular file" in ran.stdout + ran.stderr
    assert fifo.is_fifo()
    assert outputs.refusal(Path("/dev/null")) == "it is not a regular file (a pipe or a device?)"


def _refused_before_the_run(ran_status: int, err: str, kept: dict[Path, bytes],
                            never_written: Path, says: str) -> None:
    assert ran_status == 1, err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert says in err, err
    assert {path: path.read_bytes() for path in kept} == kept
    assert not never_written.exists()  # the run never started, so no output was written


@pytest.mark.parametrize(("option", "target", "says"), [
    ("--screenshot", "levels/01-first-steps.tmx", "--screenshot names the level (--level)"),
    ("--report", "assets/tiles.png", "--report names a file the level uses"),
    ("--record", "levels/02-over-the-gaps.tmx", "the level that follows it (next_level)"),
    ("--report", "levels/../levels/01-first-steps.tmx", "names the level (--level)"),
])
def test_an_output_that_is_a_file_the_level_uses_is_refused_before_the_run(
        pack: Path, option: str, target: str, says: str) -> None:
    level, kept = pack / "levels" / "01-first-steps.tmx", pack / target
    before = {kept: kept.read_bytes(), level: level.read_bytes()}
    other = pack / "record.txt" if option != "--record" else pack / "report.json"
    other_option = "--record" if option != "--record" else "--report"
    ran = call_main(cli.main, ["--headless", "--level", level, "--ticks", "3",
                               option, kept, other_option, other])
    _refused_before_the_run(ran.returncode, ran.stderr, before, other, says)


def test_a_recording_named_like_its_script_is_refused_before_the_run(pack: Path) -> None:
    script, report = pack / "win.txt", pack / "report.json"
    ran = call_main(cli.main, ["--headless", "--level", pack / "levels" / "01-first-steps.tmx",
                               "--inputs", script, "--record", pack / "." / "win.txt",
                               "--report", report])
    _refused_before_the_run(ran.returncode, ran.stderr, {script: script.read_bytes()}, report,
                            "--record names the input script (--inputs)")


def test_two_outputs_that_are_one_file_are_refused_before_the_run(tmp_path: Path) -> None:
    out = tmp_path / "out.json"
    ran = call_main(cli.main, ["--headless", "--ticks", "3", "--report", out,
                               "--record", tmp_path / "." / "out.json"])
    _refused_before_the_run(ran.returncode, ran.stderr, {}, out,
                            "--record and --report name the same file")


# --- One way in, one way out, in the source ------------------------------------------------
#
# The rule, as the scan below applies it to every module of the game package:
#   * Only the core modules open files by name: ``game/levels/reading.py`` (the one bounded
#     open), ``game/levels/outputs.py`` (the one atomic write) and ``game/app/files.py``
#     (the app's wrappers of both).
#   * Anywhere else these calls are flagged: the built-in ``open``; ``.read_text``,
#     ``.read_bytes``, ``.write_text``, ``.write_bytes``; ``.open`` on a module (``os``,
#     ``io``, ``wave``, ...) or with a mode or encoding (a ``Path``); ``os.replace``,
#     ``os.rename``, ``shutil`` copies and moves; ``pygame.image.save``; ``pygame.image.load``,
#     ``pygame.font.Font``, ``pygame.mixer.Sound`` and ``pygame.mixer.music.load`` unless
#     handed bytes in memory (``io.BytesIO(...)``) or pygame's own font (``None``);
#     ``print_png`` and ``savefig``; ``ET.parse``; ``InputScript.load`` (a read by name).
#   * Except: a writer handed to the one atomic write writes the temporary file it is given,
#     always called ``tmp`` (``tmp.write_text``, ``tmp.open("wb")``, ``canvas.print_png(tmp)``);
#     ``os.open(os.devnull, ...)`` opens no file of anyone's.
#   * What remains is listed below, each with its reason; an entry that no longer matches a
#     call fails the test too, so the list only shrinks.

CORE = {"game/levels/reading.py", "game/levels/outputs.py", "game/app/files.py"}
READS_AND_WRITES = {"read_text", "read_bytes", "write_text", "write_bytes", "print_png",
                    "savefig"}
FILE_MODULES = {"os", "io", "codecs", "gzip", "bz2", "lzma", "zipfile", "tarfile", "wave",
                "tempfile", "shelve"}
SHUTIL = {"copy", "copy2", "copyfile", "copytree", "move"}
PYGAME_LOADS = {"pygame.image.load", "pygame.font.Font", "pygame.mixer.Sound",
                "pygame.mixer.music.load"}
ALLOWED = {
    ("game/tools/synth.py", "wave.open(buffer, 'wb')"):
        "the wave module writes into a buffer in memory; its bytes go out through "
        "write_bytes_atomically",
    ("game/app/audio.py", "pygame.mixer.music.load(self._music_stream, 'wav')"):
        "the stream is an io.BytesIO of the music read through read_small_bytes, kept "
        "while the mixer reads it",
    ("game/app/saves.py", "os.replace(self.path, backup)"):
        "a save that could not be read is renamed aside to a new name: no bytes are written, "
        "and the file is kept, never replaced",
}


def _dotted(node: ast.expr) -> str:
    """``pygame.image.load`` for that attribute chain; '' for anything else."""
    if isinstance(node, ast.Name):
        return node.id
    if isinstance(node, ast.Attribute):
        inner = _dotted(node.value)
        return f"{inner}.{node.attr}" if inner else ""
    return ""


def _in_memory(call: ast.Call) -> bool:
    """The call is handed bytes in memory (``io.BytesIO(...)``) or pygame's font (None)."""
    arguments = [*call.args, *(keyword.value for keyword in call.keywords)]
    first = arguments[0] if arguments else None
    return (isinstance(first, ast.Constant) and first.value is None) or (
        isinstance(first, ast.Call) and _dotted(first.func) in {"io.BytesIO", "BytesIO"})


def _names_tmp(call: ast.Call) -> bool:
    receiver = call.func.value if isinstance(call.func, ast.Attribute) else None
    return (isinstance(receiver, ast.Name) and receiver.id == "tmp") or any(
        isinstance(argument, ast.Name) and argument.id == "tmp" for argument in call.args)


def _flagged(call: ast.Call) -> bool:
    name = _dotted(call.func)
    attribute = call.func.attr if isinstance(call.func, ast.Attribute) else None
    if _names_tmp(call):
        return False  # a writer of the one atomic write, writing its temporary file
    if name == "open":
        return True
    if attribute in READS_AND_WRITES:
        return True
    if attribute == "open" and isinstance(call.func, ast.Attribute):
        receiver = _dotted(call.func.value)
        if name == "os.open":
            return not (call.args and _dotted(call.args[0]) == "os.devnull")
        with_mode = any(isinstance(a, ast.Constant) and isinstance(a.value, str)
                        for a in call.args) or any(k.arg in {"mode", "encoding"}
                                                   for k in call.keywords)
        return receiver in FILE_MODULES or with_mode
    if name in {"os.replace", "os.rename", "pygame.image.save", "ET.parse",
                "InputScript.load"} or name in {f"shutil.{n}" for n in SHUTIL}:
        return True
    return name in PYGAME_LOADS and not _in_memory(call)


def _calls_outside_the_core() -> dict[tuple[str, str], int]:
    found: dict[tuple[str, str], int] = {}
    for path in sorted((ROOT / "game").rglob("*.py")):
        module = path.relative_to(ROOT).as_posix()
        if module in CORE:
            continue
        tree = ast.parse(path.read_bytes(), module)
        for node in ast.walk(tree):
            if isinstance(node, ast.Call) and _flagged(node):
                found[(module, ast.unparse(node))] = node.lineno
    return found


def test_every_file_is_read_through_the_one_way_in_and_written_through_the_one_way_out(
        ) -> None:
    found = _calls_outside_the_core()
    unexplained = {f"{module}:{line}: {call}" for (module, call), line in found.items()
                   if (module, call) not in ALLOWED}
    assert unexplained == set(), "files opened by name outside the core"
    stale = {entry for entry in ALLOWED if entry not in found}
    assert stale == set(), "allowed calls that are no longer there: take them off the list"


@pytest.mark.parametrize("source", [
    "open(path, 'w')", "Path(p).write_text('x')", "out.write_bytes(data)",
    "pygame.image.save(surface, str(path))", "os.replace(a, b)", "path.open(encoding='utf-8')",
    "pygame.image.load(str(path))", "pygame.font.Font(str(path), 9)", "shutil.copy(a, b)",
    "InputScript.load(path)", "canvas.print_png(path)",
])
def test_the_scan_flags_each_way_a_file_can_be_opened_by_name(source: str) -> None:
    call = ast.parse(source).body[0]
    assert isinstance(call, ast.Expr) and isinstance(call.value, ast.Call)
    assert _flagged(call.value)


@pytest.mark.parametrize("source", [
    "tmp.write_text(text, encoding='utf-8')", "canvas.print_png(tmp)", "tmp.open('wb')",
    "os.open(os.devnull, os.O_WRONLY)", "pygame.image.load(io.BytesIO(data), 'a.png')",
    "pygame.font.Font(None, 28)", "self.open(name)", "fill.open(cell)",
])
def test_the_scan_lets_the_temporary_file_and_memory_through(source: str) -> None:
    call = ast.parse(source).body[0]
    assert isinstance(call, ast.Expr) and isinstance(call.value, ast.Call)
    assert not _flagged(call.value)
