"""Checking maps side by side: the same lines in the same order as one at a time, the
biggest map started first, never more processes than cores, and none left behind: not
after SIGTERM, and not waiting for a worker that was killed."""

from __future__ import annotations

import multiprocessing
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from game.checker import side_by_side
from game.checker.checking import Options
from game.checker.cli import check
from game.checker.side_by_side import check_maps
from game.checker.solver import Effort
from tests.hang_guard import HANG_S
from tests.maps import write_tmx

SMALL = Options(effort=Effort(budget=2_000))
ROOT = Path(__file__).resolve().parent.parent


def _folder(tmp_path: Path) -> Path:
    """Four small maps: two winnable (one much bigger), one walled off, one bad."""
    write_tmx(tmp_path, ["P   D", "#####"], "a-short.tmx")
    write_tmx(tmp_path, ["P" + " " * 40 + "D", "#" * 42], "b-long.tmx")
    write_tmx(tmp_path, ["   #  ", "   #  ", "   #  ", "   #  ", "P  # D", "######"],
              "c-walled.tmx")
    write_tmx(tmp_path, ["    D", "#####"], "d-no-spawn.tmx")
    return tmp_path


def test_checking_side_by_side_prints_what_one_at_a_time_prints(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    folder = _folder(tmp_path)
    monkeypatch.setattr(side_by_side, "usable_cores", lambda: 2)
    alone = check([folder], SMALL, jobs=1)
    one_at_a_time = capsys.readouterr().out
    together = check([folder], SMALL, jobs=2)
    assert together == alone == 1
    assert capsys.readouterr().out == one_at_a_time
    assert one_at_a_time.index("c-walled.tmx") < one_at_a_time.index("d-no-spawn.tmx")


def test_the_biggest_map_starts_first_and_reports_keep_their_order(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    folder = _folder(tmp_path)
    paths = sorted(folder.glob("*.tmx"))
    started: list[list[str]] = []

    class Recorder:
        """A pool that runs its jobs here, in the order it was given them."""

        def __init__(self, processes: int, initializer: object) -> None:
            assert processes == 2

        def __enter__(self) -> Recorder:
            return self

        def __exit__(self, *_: object) -> None:
            return None

        def imap_unordered(self, work: object, jobs: list[tuple[int, Path, Options]],
                           ) -> list[tuple[int, object]]:
            started.append([path.name for _, path, _ in jobs])
            done = [side_by_side._check(job) for job in jobs]
            return list(reversed(done))  # back in the worst order

    monkeypatch.setattr(side_by_side, "usable_cores", lambda: 8)
    monkeypatch.setattr(multiprocessing, "Pool", Recorder)
    reports = list(check_maps(paths, SMALL, jobs=2))
    (order,) = started
    sizes = [(folder / name).stat().st_size for name in order]
    assert order[0] == "b-long.tmx" and sizes == sorted(sizes, reverse=True)
    assert [report.path for report in reports] == paths


def test_no_more_processes_than_cores(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    def no_pool(*_: object, **__: object) -> None:
        raise AssertionError("one core: no pool")

    monkeypatch.setattr(side_by_side, "usable_cores", lambda: 1)
    monkeypatch.setattr(multiprocessing, "Pool", no_pool)
    paths = sorted(_folder(tmp_path).glob("*.tmx"))
    assert [r.path for r in check_maps(paths, SMALL, jobs=64)] == paths


# Ctrl-C at two moments while the pool starts: inside a fork's own clean-up (the signal was
# lost there), and once the pool's first thread runs (its workers outlived the command).
_CTRL_C_WHILE_THE_POOL_STARTS = """
import os, signal, sys, threading
from game.checker import side_by_side
from game.checker.cli import main

side_by_side.usable_cores = lambda: 2
moment = sys.argv[2]
if moment == "fork":
    os.register_at_fork(after_in_parent=lambda: os.kill(os.getpid(), signal.SIGINT))
else:
    real_start = threading.Thread.start

    def start_then_ctrl_c(thread):
        real_start(thread)
        threading.Thread.start = real_start
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread.start = start_then_ctrl_c
signal.signal(signal.SIGINT, signal.default_int_handler)
sys.exit(main(["check", sys.argv[1], "--no-solve", "--jobs", "2"]))
"""


@pytest.mark.skipif(not hasattr(signal, "pthread_sigmask"), reason="workers fork on POSIX")
@pytest.mark.parametrize("moment", ["fork", "first thread"])
def test_ctrl_c_while_the_pool_starts_stops_the_command_and_every_worker(
        tmp_path: Path, moment: str) -> None:
    """Status 130 and one line, and no worker left running: the command's output closes."""
    process = subprocess.Popen(
        [sys.executable, "-c", _CTRL_C_WHILE_THE_POOL_STARTS, str(_folder(tmp_path)), moment],
        cwd=ROOT, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        start_new_session=True, preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        _out, err = process.communicate(timeout=30)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        pytest.fail("a worker outlived the command and held its output open")
    assert (process.returncode, err) == (130, "stopped by Ctrl-C\n")


def _long_folder(tmp_path: Path) -> Path:
    """Two maps whose searches keep a worker busy for a while, and one short map."""
    for name in ("a-flat.tmx", "b-flat.tmx"):
        write_tmx(tmp_path, ["P" + " " * 200 + "D", "#" * 202], name)
    write_tmx(tmp_path, ["P   D", "#####"], "c-short.tmx")
    return tmp_path


def _children(pid: int) -> list[int]:
    """The processes whose parent is ``pid``."""
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rpartition(")")[2].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.append(int(stat.parent.name))
    return found


def _cpu_ticks(pid: int) -> int:
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except OSError:
        return 0
    return int(fields[11]) + int(fields[12])  # utime + stime


def _busy_workers(process: subprocess.Popen[str]) -> list[int]:
    """The check's two workers, once both are searching (they have used CPU time)."""
    for _ in range(int(HANG_S / 0.05)):  # a guard against a hang, not a speed limit
        workers = [pid for pid in _children(process.pid) if _cpu_ticks(pid) >= 10]
        if len(workers) == 2:
            return workers
        time.sleep(0.05)
    process.kill()
    pytest.fail("the check never had two workers searching")


def _check_side_by_side(folder: Path) -> subprocess.Popen[str]:
    return subprocess.Popen(
        [sys.executable, "-m", "game.levels", "check", str(folder), "--jobs", "2"],
        cwd=ROOT, text=True, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        start_new_session=True)


def _left_in(session: int) -> bool:
    try:
        os.killpg(session, 0)
    except ProcessLookupError:
        return False
    return True


needs_two_cores = pytest.mark.skipif(
    side_by_side.usable_cores() < 2 or not Path("/proc/self/stat").exists(),
    reason="two workers, seen through /proc")


def _ended(process: subprocess.Popen[str], failure: str) -> tuple[str, str]:
    """What the check printed once it ended; a failure (and the check killed) if it hangs."""
    try:
        return process.communicate(timeout=HANG_S)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        pytest.fail(failure)


@needs_two_cores
def test_sigterm_ends_every_worker_with_the_check(tmp_path: Path) -> None:
    process = _check_side_by_side(_long_folder(tmp_path))
    _busy_workers(process)
    os.kill(process.pid, signal.SIGTERM)
    _out, err = _ended(process, "the check did not end")
    assert (process.returncode, err) == (143, "stopped by SIGTERM\n")
    assert not _left_in(process.pid), "a worker outlived the check"


@needs_two_cores
def test_a_worker_killed_mid_check_is_reported_and_the_rest_are_checked(
        tmp_path: Path) -> None:
    process = _check_side_by_side(_long_folder(tmp_path))
    os.kill(_busy_workers(process)[0], signal.SIGKILL)  # as the out-of-memory killer does
    out, err = _ended(process, "the check waited for ever for the map of the killed worker")
    lines = out.splitlines()
    assert (process.returncode, err) == (1, "")
    (killed,) = [line for line in lines if "was killed by signal 9" in line]
    assert killed.startswith(str(tmp_path / "a-flat.tmx")) or killed.startswith(
        str(tmp_path / "b-flat.tmx"))
    assert " — check this map alone (--jobs 1)" in killed
    assert lines[-1].startswith("checked 3 map(s): 1 not playable, 2 solved;")
    assert not _left_in(process.pid)
