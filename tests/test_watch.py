"""``--watch``: a save in Tiled reloads the running level; a broken save keeps the old one."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

from game.app.watch import POLL_INTERVAL_S, FileWatcher, level_files
from game.collision.aabb import Box
from game.sim.campaign import Campaign
from game.sim.inputs import NOTHING
from tests.maps import level_from_ascii, write_tmx

ROOT = Path(__file__).resolve().parent.parent
ROWS = ["            ",
        " P       E  ",
        "############"]


def test_the_watcher_sees_the_map_and_its_tileset_change(tmp_path: Path) -> None:
    level = write_tmx(tmp_path, ROWS)
    assert level_files(level)[:2] == [level, (tmp_path / "t.tsx").resolve()]
    watcher = FileWatcher(level)
    now = 100.0
    assert not watcher.poll(now)
    for changed in (level, tmp_path / "t.tsx"):
        stamp = changed.stat().st_mtime_ns + 1_000_000_000
        os.utime(changed, ns=(stamp, stamp))
        assert not watcher.poll(now + POLL_INTERVAL_S / 2)   # too soon to look again
        now += POLL_INTERVAL_S
        assert watcher.poll(now)                             # seen once...
        now += POLL_INTERVAL_S
        assert not watcher.poll(now)                         # ...and only once


def test_a_reload_keeps_the_player_where_it_was_when_that_place_is_free() -> None:
    level = level_from_ascii(ROWS)
    campaign = Campaign(Path("x.tmx"), loader=lambda _: level)
    for _ in range(20):
        campaign.tick(NOTHING)
    campaign.world.player.teleport(Box(100, 2, 12, 14))
    campaign.reload(level_from_ascii(["            ", " P          ", "############"]))
    assert campaign.world.player.box == Box(100, 2, 12, 14)
    assert len(campaign.world.enemies) == 0


def test_a_reload_that_walls_the_player_in_starts_it_at_the_spawn() -> None:
    campaign = Campaign(Path("x.tmx"), loader=lambda _: level_from_ascii(ROWS))
    campaign.world.player.teleport(Box(115, 18, 12, 14))
    walled = level_from_ascii(["            ", " P     ##   ", "############"])
    campaign.reload(walled)
    assert campaign.world.player.box == walled.spawn


def hand_over(fifo: Path, data: bytes, game: subprocess.Popen[str]) -> None:
    """Write ``data`` into a FIFO as soon as the game opens it (never blocking forever)."""
    deadline = time.monotonic() + 60
    while True:
        try:
            fd = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)
            break
        except OSError:  # no reader yet
            assert game.poll() is None, "the game ended before reading its input script"
            assert time.monotonic() < deadline, "the game never opened its input script"
            time.sleep(0.01)
    os.set_blocking(fd, True)
    with os.fdopen(fd, "wb") as pipe:
        pipe.write(data)


def watched_run(tmp_path: Path, new_text: str) -> dict[str, object]:
    """Play a level in a (dummy) window with --watch and save ``new_text`` over it mid-run."""
    level = write_tmx(tmp_path, ROWS)
    report = tmp_path / "report.json"
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    inputs = tmp_path / "in.fifo"
    os.mkfifo(inputs)
    game = subprocess.Popen(
        [sys.executable, "-m", "game", "--level", str(level), "--watch", "--ticks", "400",
         "--inputs", str(inputs), "--report", str(report)],
        cwd=ROOT, env=env, stderr=subprocess.PIPE, text=True)
    hand_over(inputs, b"0 -left\n", game)  # the game has opened its input script...
    time.sleep(1.5)                        # ...and then loads the level and opens a window
    level.write_text(new_text, encoding="utf-8")
    _, errors = game.communicate(timeout=60)
    assert game.returncode == 0, errors
    data: dict[str, object] = json.loads(report.read_text())
    return data


def test_saving_the_level_while_it_runs_reloads_it(tmp_path: Path) -> None:
    no_enemy = write_tmx(tmp_path / "..", ["            ", " P          ", "############"],
                         name=f"{tmp_path.name}-new.tmx").read_text()
    report = watched_run(tmp_path, no_enemy)
    assert report["enemies_left"] == 0


def test_a_broken_save_keeps_the_old_level_running(tmp_path: Path) -> None:
    report = watched_run(tmp_path, "<map><broken")
    assert report["enemies_left"] == 1 and report["ticks"] == 400
