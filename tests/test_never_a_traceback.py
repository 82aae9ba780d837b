"""Every command turns every bad path, file and number into one sentence and its exit status.

The cases are those a downloaded level or a mistyped command can bring: folders, pipes and
devices where a file belongs, outputs that cannot be written, numbers thousands of digits
long, JSON nested a hundred thousand deep, Ctrl-C. A property test then throws random
bytes, paths and numbers at the commands and the loaders.
"""

from __future__ import annotations

import contextlib
import errno
import io
import json
import os
import signal
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from game.app import cli
from game.app.hud import ELLIPSIS, fit_text
from game.app.saves import JsonFile, Progress
from game.app.settings import Settings
from game.bench import main as bench_main
from game.checker.cli import main as levels_main
from game.demos import stress
from game.levels import FIRST_LEVEL, LevelError, check_level, load_level, reading
from game.levels.closed_output import quiet_when_output_closes
from game.sim.campaign import Campaign
from game.sim.inputs import Action
from tests.in_process import call_main
from tests.test_watch import hand_over

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tests/scripts/01-first-steps.txt"
ENV = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
MAX_MESSAGE_CHARS = 1_000  # one sentence, with a path in it, is shorter than this
FIFO_TIMEOUT_S = 60  # generous for a busy machine; a run that waits on a pipe never ends
MAX_TEST_TICKS = 600  # random runs stay this short
STARTUP_S = 3.0  # a headless run is ticking after this long, even on a busy machine
# The CPU time a headless run spends after reading its input script, by when it is ticking
# (loading the level and making the world take a tenth of it).
TICKING_CPU_S = 0.3


def outcome(command: Callable[[list[str]], int], args: list[str],
            capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    """Run a command in this process: its exit status and what it said on stderr.

    An exception escaping the command fails the test: that would be a traceback."""
    try:
        status = command(args)
    except SystemExit as leaving:  # argparse's usage errors
        status = int(leaving.code or 0)
    return status, capsys.readouterr().err


def assert_one_sentence(status: int, err: str, expected: int) -> None:
    assert status == expected, err
    assert "Traceback" not in err
    assert 0 < len(err) <= MAX_MESSAGE_CHARS, err[:MAX_MESSAGE_CHARS]


@pytest.fixture
def fifo(tmp_path: Path) -> Iterator[Path]:
    path = tmp_path / "pipe.txt"
    os.mkfifo(path)
    yield path


@pytest.fixture
def a_file(tmp_path: Path) -> Path:
    path = tmp_path / "notes.txt"
    path.write_text("not a folder\n", encoding="utf-8")
    return path


# -- python -m game ------------------------------------------------------------------------

def test_a_pipe_nobody_writes_to_is_a_sentence_not_a_hang(
        fifo: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(reading, "MAX_PIPE_WAIT_S", 0.2)
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--inputs", str(fifo)],
                          capsys)
    assert_one_sentence(status, err, 1)
    assert "nothing came through it" in err


def test_a_pipe_written_a_byte_at_a_time_for_ever_is_a_sentence_not_a_hang(
        fifo: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(reading, "MAX_PIPE_READ_S", 0.3)
    stop = threading.Event()

    def dribble() -> None:  # never silent for long, never done, until the test ends
        with fifo.open("w", encoding="utf-8") as pipe:
            while not stop.is_set():
                pipe.write("#")
                pipe.flush()
                time.sleep(0.02)

    writer = threading.Thread(target=dribble, daemon=True)
    writer.start()
    try:  # without a limit in all, the read would go on for as long as the writer does
        ran = call_main(cli.main, ["--headless", "--ticks", "5", "--inputs", fifo],
                        hang_s=FIFO_TIMEOUT_S)
    finally:
        stop.set()
    assert_one_sentence(ran.returncode, ran.stderr, 1)
    assert "still being written after 0.3 s" in ran.stderr


def test_a_script_written_into_a_pipe_is_played(fifo: Path, tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    def write() -> None:  # like the shell's --inputs <(command)
        with fifo.open("w", encoding="utf-8") as pipe:  # waits for the game to open it
            pipe.write("0 +right\n")

    writer = threading.Thread(target=write, daemon=True)
    writer.start()
    report = tmp_path / "report.json"
    status, err = outcome(cli.main, ["--headless", "--ticks", "30", "--inputs", str(fifo),
                                     "--report", str(report)], capsys)
    writer.join(timeout=5)
    assert status == 0, err
    player = json.loads(report.read_text(encoding="utf-8"))["player"]
    assert player["vx"] > 0


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/null"])
def test_a_device_given_as_input_script_is_refused(
        device: str, capsys: pytest.CaptureFixture[str]) -> None:
    if not Path(device).exists():
        pytest.skip(f"{device} is not on this system")
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--inputs", device], capsys)
    assert_one_sentence(status, err, 1)
    assert "Tiled" not in err  # an input script is not a file Tiled saves


def test_a_2_gib_input_script_is_refused_without_being_read(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    script = tmp_path / "huge.txt"
    with script.open("wb") as stream:  # sparse: 2 GiB long, nothing on the disk
        stream.truncate(2 * 1024**3)
    read: list[int] = []
    real_read = os.read

    def counted(descriptor: int, size: int) -> bytes:
        data = real_read(descriptor, size)
        read.append(len(data))
        return data

    monkeypatch.setattr(os, "read", counted)
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--inputs", str(script)],
                          capsys)
    assert_one_sentence(status, err, 1)
    assert "larger than 4 MB" in err and sum(read) == 0


@pytest.mark.parametrize("option", ["--level", "--inputs"])
def test_a_folder_where_a_file_belongs_is_one_sentence(
        option: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", option, str(tmp_path)],
                          capsys)
    assert_one_sentence(status, err, 1)
    assert "folder" in err


@pytest.mark.parametrize("option", ["--report", "--record", "--screenshot"])
def test_an_output_at_a_folder_is_refused_before_the_run(
        option: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", option, str(tmp_path)],
                          capsys)
    assert_one_sentence(status, err, 1)
    assert "is a folder" in err


@pytest.mark.parametrize("option", ["--report", "--record", "--screenshot"])
def test_an_output_under_a_file_is_refused_before_the_run(
        option: str, a_file: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", option,
                                     str(a_file / "out.png")], capsys)
    assert_one_sentence(status, err, 1)
    assert "is a file, not a folder" in err


def test_an_output_on_a_device_is_refused_and_the_device_left_alone(
        fifo: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--report", str(fifo)],
                          capsys)
    assert_one_sentence(status, err, 1)
    assert fifo.is_fifo()  # a rename would have replaced the pipe with a file


def test_an_output_that_fails_at_the_end_is_a_sentence_and_the_others_are_written(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    def full_disk(self: Path, *args: object, **kwargs: object) -> int:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Path, "write_text", full_disk)  # the report and the recording
    shot = tmp_path / "shot.png"
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--report",
                                     str(tmp_path / "r.json"), "--screenshot", str(shot)],
                          capsys)
    assert status == 1 and "No space left on device" in err and "Traceback" not in err
    assert shot.is_file()
    assert [p.name for p in tmp_path.iterdir()] == ["shot.png"]  # no temporary file left


def test_an_input_script_tick_of_5000_digits_is_a_bad_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    script = tmp_path / "script.txt"
    script.write_text("9" * 5000 + " +right\n", encoding="utf-8")
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--inputs", str(script)],
                          capsys)
    assert_one_sentence(status, err, 2)
    assert "line 1" in err and "5,000 characters" in err


def test_ticks_of_5000_digits_are_bad_usage(capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(cli.main, ["--headless", "--ticks", "9" * 5000], capsys)
    assert status == 2 and "5,000 characters" in err and len(err) < MAX_MESSAGE_CHARS


def cpu_s(pid: int) -> float | None:
    """The CPU time the process has used (None once it has ended, or with no /proc)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


def wait_until_ticking(process: subprocess.Popen[str]) -> None:
    """Return once ``process``, a headless run that has just read its input script, has
    spent TICKING_CPU_S more of CPU time; without /proc, after STARTUP_S."""
    start = cpu_s(process.pid)
    if start is None:
        time.sleep(STARTUP_S)
        return
    deadline = time.monotonic() + FIFO_TIMEOUT_S  # a guard against a hang, not a speed limit
    while (used := cpu_s(process.pid)) is not None and used - start < TICKING_CPU_S:
        assert process.poll() is None and time.monotonic() < deadline, "the run never ticked"
        time.sleep(0.02)


def test_ctrl_c_exits_130_and_a_headless_run_still_writes_its_report(tmp_path: Path) -> None:
    """The input script comes through a pipe, handed over once the run opens it: then the
    run is past Python's start-up and its imports, and the Ctrl-C is sent once it has spent
    the CPU time that ticking takes to begin (not after a wait for the start-up, while the
    run ticks on)."""
    report, record = tmp_path / "report.json", tmp_path / "record.txt"
    inputs = tmp_path / "inputs.fifo"
    os.mkfifo(inputs)
    process = subprocess.Popen(
        [sys.executable, "-m", "game", "--headless", "--ticks", "100000000", "--inputs",
         str(inputs), "--report", str(report), "--record", str(record)],
        cwd=ROOT, env=ENV, stderr=subprocess.PIPE, text=True,
        preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    hand_over(inputs, SCRIPT.read_bytes(), process)
    wait_until_ticking(process)
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=5)
    assert process.returncode == 130, err
    assert "Traceback" not in err and "Ctrl-C" in err
    data = json.loads(report.read_text(encoding="utf-8"))
    assert data["outcome"] == "running" and data["ticks"] > 0
    assert record.read_text(encoding="utf-8").startswith("#")


# -- the stress scene, the bench and the checker ---------------------------------------------

@pytest.mark.parametrize("args", [["--crates", "-5"], ["--ticks", "-1"], ["--ticks", "0"],
                                  ["--crates", "9" * 5000], ["--crates", "1e9"]])
def test_the_stress_scene_refuses_bad_numbers(args: list[str],
                                              capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(stress.main, args, capsys)
    assert status == 2 and "not a whole number" in err and len(err) < MAX_MESSAGE_CHARS


def test_the_bench_refuses_a_file_as_its_output_folder(
        a_file: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, err = outcome(bench_main, ["--quick", "--out", str(a_file)], capsys)
    assert status == 2 and "not a folder" in err


def test_the_checker_says_a_pipe_is_not_a_map(fifo: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    status = levels_main(["check", str(fifo)])
    out = capsys.readouterr().out
    assert status == 1 and "not a regular file" in out


# -- the player's files ----------------------------------------------------------------------

@pytest.mark.parametrize("text", [
    "[" * 100_000 + "]" * 100_000,
    '{"best_ticks": {"a.tmx": ' + "9" * 5000 + "}}",
    '{"music_volume": ' + "1" * 5000 + "}",
])
def test_a_save_of_deep_json_or_huge_numbers_is_kept_aside(tmp_path: Path, text: str) -> None:
    for parse, default in ((Settings.from_json, Settings), (Progress.from_json, Progress)):
        path = tmp_path / "save.json"
        path.write_text(text, encoding="utf-8")
        value, problem = JsonFile(path).load(parse, default)
        assert value == default()
        assert problem is not None and len(problem) < MAX_MESSAGE_CHARS


def test_a_save_that_is_a_pipe_is_not_waited_for(fifo: Path) -> None:
    settings, problem = JsonFile(fifo).load(Settings.from_json, Settings)
    assert settings == Settings()
    assert problem is not None and "not a regular file" in problem
    assert fifo.is_fifo()


# -- random input: a sentence and an exit status, never an exception --------------------------

def _paths(base: Path) -> list[str]:
    """Paths of every awkward kind, made under ``base``."""
    folder = base / "folder"
    folder.mkdir(exist_ok=True)
    plain = base / "plain.txt"
    plain.write_text("0 +right\n", encoding="utf-8")
    pipe = base / "pipe"
    if not pipe.exists():
        os.mkfifo(pipe)
    level = base / "level.tmx"  # outputs may land on any of these: all are in ``base``
    level.write_bytes(FIRST_LEVEL.read_bytes())
    return [str(folder), str(plain), str(plain / "under.txt"), str(pipe), "/dev/zero",
            str(base / "missing" / "deep.txt"), str(base / ("long" * 2000)),
            str(base / "nul\0byte"), "", str(level)]


OPTIONS = ["--level", "--inputs", "--report", "--record", "--screenshot"]
DIGITS = st.tuples(st.sampled_from(["", "-", "+"]), st.text("0123456789", min_size=1,
                                                               max_size=6000))
NUMBERS = st.one_of(st.integers().map(str), DIGITS.map("".join), st.floats().map(repr),
                    st.text(max_size=30))


def short_run(ticks: str) -> bool:
    """False for a tick count that would make a valid run longer than a test should take."""
    digits = ticks.strip().removeprefix("+")
    return not (digits.isascii() and digits.isdigit() and len(digits) < 19
                and int(digits) > MAX_TEST_TICKS)


@settings(max_examples=40, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(choices=st.lists(st.tuples(st.sampled_from(OPTIONS), st.integers(0, 9)), max_size=3),
       ticks=NUMBERS.filter(short_run), content=st.binary(max_size=2000))
def test_the_game_answers_random_paths_numbers_and_bytes_with_a_status(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch,
        choices: list[tuple[str, int]], ticks: str, content: bytes) -> None:
    monkeypatch.setattr(reading, "MAX_PIPE_WAIT_S", 0.05)
    paths = _paths(tmp_path)
    (tmp_path / "plain.txt").write_bytes(content)  # random bytes as a script or a level
    args = ["--headless", "--ticks", ticks]
    for option, which in choices:
        args += [option, paths[which]]
    status, err = outcome(cli.main, args, capsys)
    assert status in (0, 1, 2), err
    assert "Traceback" not in err
    assert status == 0 or len(err) <= 4 * MAX_MESSAGE_CHARS  # a usage line and a sentence
    assert Path("/dev/zero").is_char_device() or not Path("/dev/zero").exists()


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(content=st.binary(max_size=3000))
def test_random_bytes_as_a_map_or_a_save_never_raise(tmp_path: Path, content: bytes) -> None:
    level = tmp_path / "level.tmx"
    level.write_bytes(content)
    findings = check_level(level)
    assert findings.errors
    with pytest.raises(LevelError):
        load_level(level)
    save = tmp_path / "settings.json"
    save.write_bytes(content)
    JsonFile(save).load(Settings.from_json, Settings)


TEMPLATE = FIRST_LEVEL.read_text(encoding="utf-8").replace('source="../assets/', 'source="')


@settings(max_examples=60, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(number=NUMBERS, where=st.sampled_from(["csv", "x", "width", "points", "gravity"]))
def test_random_numbers_anywhere_in_a_map_are_one_sentence_or_a_playable_level(
        tmp_path: Path, number: str, where: str) -> None:
    for name in ("tiles.tsx", "tiles.png", "terrain.tsx", "terrain.png"):
        (tmp_path / name).write_bytes((ROOT / "assets" / name).read_bytes())
    quoted = number.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")
    quoted = "".join(c for c in quoted if c.isprintable())
    text = TEMPLATE
    if where == "csv":
        text = text.replace("0,0,0,0,9,", f"0,0,0,0,{quoted},", 1)
    elif where == "x":
        text = text.replace('type="Player" x="34"', f'type="Player" x="{quoted}"')
    elif where == "width":
        text = text.replace('width="12" height="14"', f'width="{quoted}" height="14"')
    elif where == "gravity":
        text = text.replace("</properties>", f'<property name="gravity" type="float" '
                            f'value="{quoted}"/></properties>', 1)
    else:
        text = text.replace("</map>", '<objectgroup id="90" name="p"><object id="900" '
                            f'type="Platform" x="0" y="0"><polyline points="0,0 {quoted},0"/>'
                            "</object></objectgroup></map>")
    path = tmp_path / "level.tmx"
    path.write_text(text.replace('value="02-over-the-gaps.tmx"', 'value=""'), encoding="utf-8")
    errors = check_level(path).errors
    for problem in errors:
        assert len(str(problem)) <= MAX_MESSAGE_CHARS
    if not errors:  # what the checker passes, the game plays
        campaign = Campaign(path, loader=load_level)
        for _ in range(60):
            campaign.tick(frozenset({Action.RIGHT, Action.JUMP}))


def test_a_temporary_file_left_by_a_killed_run_goes_when_its_output_is_next_written(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    dead = 2**22 + 12345  # above Linux's largest process id, so no process has it
    orphan = tmp_path / f".report.{dead}.0123abcd.json"
    orphan.write_text("{", encoding="utf-8")
    status, err = outcome(cli.main, ["--headless", "--ticks", "5", "--report",
                                     str(tmp_path / "report.json")], capsys)
    assert status == 0, err
    assert [p.name for p in tmp_path.iterdir()] == ["report.json"]


def test_a_20000_character_title_is_fitted_in_a_few_measurements() -> None:
    class CountingFont:
        """Measures like a font of 6 px a character, and counts the measurements."""

        def __init__(self) -> None:
            self.measured = 0

        def size(self, text: str) -> tuple[int, int]:
            self.measured += 1
            return 6 * len(text), 9

    font = CountingFont()
    fitted = fit_text(font, "W" * 20_000, 200)  # type: ignore[arg-type]
    assert fitted.endswith(ELLIPSIS) and 6 * len(fitted) <= 200 < 6 * (len(fitted) + 1)
    assert font.measured <= 20  # one per halving, not one per character


def _with_standard_output(how: str, args: list[str]) -> subprocess.CompletedProcess[str]:
    """``python -m ARGS`` with its standard output a pipe nobody reads any more (``| head``
    having gone) or the full device (``> /dev/full``)."""
    if how == "closed":
        read, write = os.pipe()
        os.close(read)
        try:
            return subprocess.run([sys.executable, "-m", *args], stdout=write, env=ENV,
                                  stderr=subprocess.PIPE, text=True, timeout=120, check=False)
        finally:
            os.close(write)
    with open("/dev/full", "w", encoding="utf-8") as full:
        return subprocess.run([sys.executable, "-m", *args], stdout=full, env=ENV,
                              stderr=subprocess.PIPE, text=True, timeout=120, check=False)


@pytest.mark.parametrize(("how", "status"), [("closed", 0), ("full", 0)])
def test_a_closed_or_full_standard_output_ends_a_command_quietly(how: str,
                                                                status: int) -> None:
    if how == "full" and not Path("/dev/full").exists():
        pytest.skip("/dev/full is not on this system")
    ran = _with_standard_output(how, ["game.demos.stress", "--crates", "8", "--ticks", "2"])
    assert (ran.returncode, ran.stderr) == (status, "")  # no traceback, no "Exception ignored"


def test_a_command_goes_on_to_its_end_and_status_when_its_reader_stops() -> None:
    class Closed(io.StringIO):
        def write(self, text: str) -> int:
            raise BrokenPipeError(errno.EPIPE, "Broken pipe")

    done: list[str] = []

    def command() -> int:
        print("first line")
        print("second line")
        done.append("the files it writes")
        return 3

    with contextlib.redirect_stdout(Closed()):
        assert quiet_when_output_closes(command) == 3
    assert done == ["the files it writes"]


def test_every_program_beside_the_game_starts_through_the_quiet_guard() -> None:
    """Each ``__main__`` of the tools ends with ``sys.exit(quiet_when_output_closes(main))``;
    the game, the bench, the stress scene and the lab start through ``run_command``."""
    for path in sorted((ROOT / "game" / "tools").glob("*.py")):
        source = path.read_text(encoding="utf-8")
        if 'if __name__ == "__main__":' in source and path.name != "terrain.py":
            assert "sys.exit(quiet_when_output_closes(main))" in source, path.name
    assert "quiet_when_output_closes(main)" in (ROOT / "game/app/arguments.py").read_text(
        encoding="utf-8")
