"""The solver and the checker's verdicts on real maps: snapshots restore a world exactly, every
shipped level is solved within the default budget by a route that replays, a committed winning
script is accepted as proof (``tests/test_levels.py`` plays every one as a proof is played), a
walled-in Exit is proven impossible, a search out of budget or time is "not decided" with its
own exit status, and the reach is measured."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections.abc import Sequence
from pathlib import Path

import pytest

import game.checker.solver as solver
from game.app.run import input_script
from game.checker import reach
from game.checker.checking import Options, check_map
from game.checker.cli import check, command_name
from game.checker.cli import main as levels_main
from game.checker.reach import DEFAULT_LIMITS, Limits, measure_limits, measure_reach
from game.checker.route_picture import PLATFORM, draw_route
from game.checker.solver import (
    FIRST_PLAIN_SHARE,
    MOVE_TICKS,
    WAIT_TICKS,
    Effort,
    _Search,
    replay,
    solve,
)
from game.checker.verdict import Kind
from game.collision.aabb import Box
from game.levels import LEVELS_DIR, load_level
from game.sim.inputs import Action, Actions
from game.sim.level import Level
from game.sim.snapshot import Snapshot
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.in_process import call_main
from tests.maps import HOP_OVER, write_tmx
from tests.shipped_fills import share_fills
from tests.shipped_solves import solved

ROOT = Path(__file__).resolve().parent.parent
SCRIPTS = Path(__file__).resolve().parent / "scripts"
SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))
FIRST = LEVELS_DIR / "01-first-steps.tmx"
SOLID_GID = 1  # the first tile of assets/tiles.tsx is Solid


def state(world: World) -> tuple[object, ...]:
    """Everything about a world that play shows: bodies, platforms, coins, contacts."""
    return (world.player.box, world.player.vx, world.player.vy, world.player.on_ground,
            tuple(enemy.box for enemy in world.enemies), len(world.enemies),
            tuple(platform.box for platform in world.platforms), len(world.coins),
            world.contacts.touching, world.spawn, len(world.squashed))


@pytest.mark.parametrize("name", ["03-hop-along", "04-moving-parts"])
def test_a_restored_snapshot_replays_exactly_as_the_first_time(name: str) -> None:
    level = load_level(LEVELS_DIR / f"{name}.tmx")
    world = World(level)
    script = input_script(SCRIPTS / f"{name}.txt")
    for tick in range(300):
        world.step(script.held_at(tick))
    saved = Snapshot.of(world)
    first = []
    for tick in range(300, 1500):
        world.step(script.held_at(tick))
        first.append(state(world))
    saved.restore(world)
    script = input_script(SCRIPTS / f"{name}.txt")
    script.held_at(299)
    again = []
    for tick in range(300, 1500):
        world.step(script.held_at(tick))
        again.append(state(world))
    assert again == first
    assert len({s[0] for s in first}) > 200  # the player really moved in between


def run_right(world: World, ticks: int) -> list[tuple[object, ...]]:
    states = [state(world)]
    for _ in range(ticks):
        world.step(frozenset({Action.RIGHT}))
        states.append(state(world))
    return states


def test_a_snapshot_taken_before_the_first_tick_restores_the_start() -> None:
    level = load_level(LEVELS_DIR / "04-moving-parts.tmx")
    world = World(level)
    saved = Snapshot.of(world)
    right = frozenset({Action.RIGHT})
    for _ in range(200):
        world.step(right)
    saved.restore(world)
    assert run_right(world, 200) == run_right(World(level), 200)


def test_stepping_on_after_a_snapshot_does_not_change_it() -> None:
    world = World(load_level(FIRST))
    saved = Snapshot.of(world)
    before = state(world)
    for _ in range(120):
        world.step(frozenset({Action.RIGHT, Action.JUMP}))
    assert state(world) != before
    saved.restore(world)
    assert state(world) == before


def test_an_attribute_first_seen_as_none_is_copied_once_it_holds_a_list() -> None:
    world = World(load_level(FIRST))
    camera = world.camera
    camera.trail = None  # type: ignore[attr-defined]  # a name the snapshot has not met
    Snapshot.of(world)
    camera.trail = [1]  # type: ignore[attr-defined]
    saved = Snapshot.of(world)
    camera.trail.append(2)  # type: ignore[attr-defined]
    saved.restore(world)
    assert camera.trail == [1]  # type: ignore[attr-defined]
    camera.trail.append(3)  # type: ignore[attr-defined]
    saved.restore(world)
    assert camera.trail == [1]  # type: ignore[attr-defined]


@pytest.mark.slow
@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_the_solver_solves_every_shipped_level_within_the_default_budget(level: Path) -> None:
    """Within the map's own budget, and by the plain moves alone in their first turn: no
    shipped level needs the timed inputs, or gives them a turn, so checking them costs what
    it did. A route found is a route the game replays: :func:`solve` replays it from the
    spawn before it says so (``test_a_route_that_does_not_replay_is_never_called_found``
    breaks that replay)."""
    solution = solved(level)  # one solving, shared with tests/test_solver_search.py
    assert solution.found and solution.own_budget and not solution.timed
    assert solution.moves_tried < solution.budget * FIRST_PLAIN_SHARE
    assert len(solution.route) == solution.exit_tick - 1  # the replay's place after each tick


@pytest.fixture
def fills_shared(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    """The map checks' reach fill of each shipped level, worked out once for the tests that
    check them (:mod:`tests.shipped_fills`)."""
    return share_fills(monkeypatch)


def test_check_accepts_a_committed_winning_script_as_proof(fills_shared: list[Path]) -> None:
    """The ``--proof`` path, on one shipped level; that every committed script wins its
    level within the proof's grace, from a fresh world as ``--proof`` plays it, the
    campaign's run shows (``tests/test_levels.py``)."""
    level = LEVELS_DIR / "05-spike-gauntlet.tmx"  # the shortest script
    report = check_map(level, Options(proof=SCRIPTS / f"{level.stem}.txt"))
    assert report.verdict is Kind.SOLVED and not report.bad, report.findings
    assert fills_shared == []


def test_a_proof_that_does_not_win_is_not_taken_as_solved(tmp_path: Path) -> None:
    script = tmp_path / "short.txt"
    script.write_text("0 +right\n30 -right\n", encoding="utf-8")
    report = check_map(FIRST, Options(proof=script))
    assert report.verdict is Kind.UNDECIDED
    assert any("does not finish the level" in f.text for f in report.findings)


EXIT_COL = int(load_level(FIRST).exits[0].x) // 16  # the first level's Exit, and its column
BEFORE_THE_EXIT = range(EXIT_COL - 13, EXIT_COL + 1)  # the columns up to the wall before it


def walled_in_copy(folder: Path) -> Path:
    """The first level with solid tiles all round its Exit (and no next level)."""
    tree = ET.parse(FIRST)
    root = tree.getroot()
    for properties in root.findall("properties"):  # the next level is not copied with it
        for prop in properties.findall("property"):
            if prop.get("name") == "next_level":
                properties.remove(prop)
    cols = int(root.get("width", "0"))
    exit_object = next(o for o in root.iter("object") if o.get("type") == "Exit")
    col = int(float(exit_object.get("x", "0"))) // 16
    row = int(float(exit_object.get("y", "0"))) // 16
    ground = next(layer for layer in root.iter("layer") if layer.get("name") == "ground")
    data = ground.find("data")
    assert data is not None and data.text is not None
    gids = [int(g) for g in data.text.replace("\n", "").split(",")]
    for c in range(col - 1, min(col + 2, cols)):
        for r in range(0, row + 3):
            if c in (col - 1, col + 1) or r < row:
                gids[r * cols + c] = SOLID_GID
    rows = [gids[r * cols:(r + 1) * cols] for r in range(len(gids) // cols)]
    data.text = "\n" + ",\n".join(",".join(map(str, r)) for r in rows) + "\n"
    shutil.copytree(LEVELS_DIR.parent / "assets", folder / "assets")  # ../assets/tiles.tsx
    (folder / "levels").mkdir()
    path = folder / "levels" / "walled-in.tmx"
    tree.write(path, encoding="UTF-8", xml_declaration=True)
    return path


def test_check_proves_a_level_whose_exit_is_walled_in_impossible_naming_the_place(
        tmp_path: Path) -> None:
    level = walled_in_copy(tmp_path)
    result = call_main(levels_main, ["check", level], cwd=ROOT)
    assert result.returncode == 1, result.stdout + result.stderr
    line = next(line for line in result.stdout.splitlines() if "impossible" in line)
    assert line.startswith(f"{level}: tile (")
    assert "no open path joins the spawn and an Exit" in line and " — " in line
    col = int(line.split("tile (")[1].split(",")[0])
    assert col in BEFORE_THE_EXIT  # beside the wall round the Exit
    assert "0 solved, 1 impossible" in result.stdout.splitlines()[-1]


def test_check_can_skip_the_search(tmp_path: Path) -> None:
    level = walled_in_copy(tmp_path)
    result = call_main(levels_main, ["check", "--no-solve", level], cwd=ROOT)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "not reached" not in result.stdout


def test_solve_writes_a_script_the_game_replays_to_the_exit_and_a_picture(
        tmp_path: Path) -> None:
    """Both programs themselves, end to end, on a map whose route needs a jump (the search
    of a shipped level is the test that solves them all); the other commands here are
    called in-process."""
    level = write_tmx(tmp_path, HOP_OVER)
    script, picture, report = tmp_path / "route.txt", tmp_path / "route.png", tmp_path / "r.json"
    solved = subprocess.run([sys.executable, "-m", "game.levels", "solve", str(level),
                             "--out", str(script), "--picture", str(picture)],
                            capture_output=True, text=True, timeout=600, check=False, cwd=ROOT)
    assert solved.returncode == 0, solved.stderr
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "+jump" in script.read_text(encoding="utf-8")
    played = subprocess.run([sys.executable, "-m", "game", "--headless", "--level", str(level),
                             "--inputs", str(script), "--report", str(report),
                             "--ticks", "600"],
                            capture_output=True, text=True, timeout=600, check=False, cwd=ROOT)
    assert played.returncode == 0, played.stderr
    assert '"levels_completed": 1' in report.read_text(encoding="utf-8")


def test_a_route_that_does_not_replay_is_never_called_found(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    """:func:`solve` replays the route it found from the spawn, as the game plays it, and
    says so only if the replay reaches the Exit: here the replay loses the route's last
    tick, the one that reaches it."""
    def short_of_the_exit(level_path: Path, held: Sequence[Actions],
                          level: Level | None = None) -> tuple[bool, list[Box]]:
        return replay(level_path, held[:-1], level)

    monkeypatch.setattr(solver, "replay", short_of_the_exit)
    with pytest.raises(AssertionError, match="the route found does not replay"):
        solve(load_level(write_tmx(tmp_path, HOP_OVER)))


def test_solve_says_how_far_it_got_when_the_exit_is_walled_in(tmp_path: Path) -> None:
    level = walled_in_copy(tmp_path)
    result = call_main(levels_main, ["solve", level, "--out", tmp_path / "none.txt"], cwd=ROOT)
    assert result.returncode == 1
    assert result.stderr.startswith(f"{level}: tile (") and "impossible" in result.stderr
    assert not (tmp_path / "none.txt").exists()


@pytest.mark.parametrize("option", ["--out", "--picture"])
def test_solve_says_an_output_cannot_be_written_before_it_searches(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, option: str) -> None:
    def no_search(*_: object) -> None:
        raise AssertionError("searched for a route that could not be written")

    monkeypatch.setattr("game.checker.cli.judge", no_search)
    for target, reason in ((tmp_path / "missing" / "route.txt", "its folder does not exist"),
                           (tmp_path, "it is a folder")):
        result = call_main(levels_main, ["solve", FIRST, option, target], cwd=ROOT)
        assert result.returncode == 1
        assert result.stderr.startswith(f"{target}: the ") and reason in result.stderr
    assert list(tmp_path.iterdir()) == []


def test_a_search_out_of_time_gives_up_and_says_so() -> None:
    solution = solve(load_level(FIRST), Effort(seconds=0.01))
    assert not solution.found and solution.timed_out


def test_the_reach_is_measured_from_the_tuning() -> None:
    default = measure_reach(Tuning())
    assert 2.5 * 16 < default.height_px < 3 * 16          # about 44 px: a plank 3 tiles up is out
    higher = measure_reach(Tuning(jump_speed_px_s=400.0))
    assert higher.height_px > default.height_px and higher.distance_px > default.distance_px


def test_the_kept_limits_are_what_the_game_measures() -> None:
    """The highest ledge and the widest gaps the checker and the guide quote, played out;
    the gaps as foreseen, before any is played, are already these."""
    assert measure_limits(Tuning()) == DEFAULT_LIMITS == Limits(44, 68, 76)
    assert reach._gaps_foreseen(Tuning()) == (68, 76)


@pytest.mark.parametrize("foreseen", [(30, 33), (28, 33), (30, 35), (31, 33), (30, 32)])
def test_the_widest_gaps_foreseen_are_kept_only_when_playing_them_agrees(
        monkeypatch: pytest.MonkeyPatch, foreseen: tuple[int, int]) -> None:
    """Played out (here by a stand-in: plain jumps cross up to 30 px, coyote jumps 33), the
    gaps foreseen are kept after four plays; a wrong one sends every gap to be played."""
    played: list[int] = []

    def crosses(_tuning: Tuning, gap_px: int) -> tuple[bool, bool]:
        played.append(gap_px)
        return gap_px <= 30, gap_px <= 33

    monkeypatch.setattr(reach, "_crosses", crosses)
    monkeypatch.setattr(reach, "_gaps_foreseen", lambda _tuning: foreseen)
    limits = reach.measure_limits.__wrapped__(Tuning())
    assert (limits.gap_px, limits.coyote_gap_px) == (30, 33)
    assert (len(played) == 4) == (foreseen == (30, 33))


def test_the_guide_quotes_the_measured_reach_and_its_pictures_exist() -> None:
    guide = (LEVELS_DIR / "README.md").read_text(encoding="utf-8")
    reach = measure_reach(Tuning())
    assert (f"lifts the feet\n{reach.height_px / 16:.1f} tiles ({reach.height_px:.0f} px) and "
            f"carries them {reach.distance_px / 16:.1f} tiles ({reach.distance_px:.0f} px)"
            in guide)
    limits = DEFAULT_LIMITS
    for figure in (f"highest ledge the player lands on is **{limits.ledge_px} px**",
                   f"**{limits.gap_px} px** with a running jump",
                   f"**{limits.coyote_gap_px} px** with a coyote jump"):
        assert figure in " ".join(guide.split()), figure
    pictures = re.findall(r"\]\((\.\./assets/guide/[^)]+)\)", guide)
    assert len(pictures) >= 5
    assert all((LEVELS_DIR / picture).is_file() for picture in pictures)


def test_check_says_not_decided_with_its_own_exit_status_when_the_budget_runs_out() -> None:
    """The program itself: its exit status 3 is the one a script sees."""
    result = subprocess.run([sys.executable, "-m", "game.levels", "check", "--budget", "20",
                             str(FIRST)], capture_output=True, text=True, timeout=120,
                            check=False, cwd=ROOT)
    assert result.returncode == 3, result.stdout + result.stderr
    assert "warning: not decided: the search found no route within its budget of 20 moves" \
        in result.stdout
    assert "--budget 80" in result.stdout
    summary = result.stdout.splitlines()[-1]
    assert "0 solved, 1 not decided" in summary and "none bad" in summary
    assert "all playable" not in summary  # a search that found nothing proves nothing


def test_check_with_seconds_still_stops_and_is_not_decided() -> None:
    result = call_main(levels_main, ["check", "--solve-seconds", "0.01", FIRST], cwd=ROOT)
    assert result.returncode == 3, result.stdout + result.stderr
    assert "not decided: the search found no route within its 0.01 s" in result.stdout


def test_check_with_no_path_checks_the_shipped_campaign_and_can_speak_json(
        capsys: pytest.CaptureFixture[str], fills_shared: list[Path]) -> None:
    assert check([], Options(solve=False), "json") == 0
    assert fills_shared == []
    document = json.loads(capsys.readouterr().out)
    assert [Path(m["path"]).name for m in document["maps"]] == [p.name for p in SHIPPED]
    assert document["status"] == 0
    assert document["summary"].startswith(f"checked {len(SHIPPED)} map(s)")


def test_json_findings_carry_the_object_and_the_tile(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    level = walled_in_copy(tmp_path)
    assert check([level], Options(), "json") == 1
    (found,) = json.loads(capsys.readouterr().out)["maps"]
    assert found["verdict"] == "impossible"
    (finding,) = [f for f in found["findings"] if f["severity"] == "error"]
    assert finding["tile"][0] in BEFORE_THE_EXIT and finding["object_id"] is None


def test_usage_names_the_command_that_was_typed() -> None:
    assert command_name("/home/me/.venv/bin/tile-hopper-levels") == "tile-hopper-levels"
    assert command_name("/src/game/levels/__main__.py") == "python -m game.levels"


def test_the_route_picture_shows_each_moving_platform_and_its_route() -> None:
    level = load_level(LEVELS_DIR / "04-moving-parts.tmx")
    assert level.platforms
    picture = draw_route(level, [], None)
    for platform in level.platforms:
        x, y = platform.path.points[0]
        assert picture.get_at((round(x), round(y)))[:3] == PLATFORM[:3]   # its outline
        (x0, y0), (x1, y1) = platform.path.points[:2]
        middle = (round((x0 + x1) / 2 + platform.width_px / 2),
                  round((y0 + y1) / 2 + platform.height_px / 2))
        assert picture.get_at(middle)[:3] == PLATFORM[:3]                 # its route


EXTENSION = LEVELS_DIR / "extensions" / "tile-hopper-check.js"


def test_the_tiled_extension_parses() -> None:
    node = shutil.which("node")
    if node is None:
        pytest.skip("node is not installed")
    result = subprocess.run([node, "--check", str(EXTENSION)], capture_output=True, text=True,
                            timeout=60, check=False)
    assert result.returncode == 0, result.stderr


def test_the_tiled_extension_reads_what_the_checker_writes(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    script = EXTENSION.read_text(encoding="utf-8")
    assert '"game.levels", "check", "--format", "json"' in script
    level = walled_in_copy(tmp_path)
    check([level], Options(solve=False), "json")
    document = json.loads(capsys.readouterr().out)
    for key in ("maps", "summary"):
        assert key in document and f"report.{key}" in script
    for key in ("findings", "severity", "text", "object_id", "tile"):
        assert f".{key}" in script


def test_the_wait_move_is_offered_only_near_a_moving_platform_and_counts_its_ticks() -> None:
    plain = _Search(load_level(FIRST), Effort())
    assert all(ticks == MOVE_TICKS for _, ticks in plain.moves)
    ferry = _Search(load_level(LEVELS_DIR / "04-moving-parts.tmx"), Effort())
    assert (frozenset(), WAIT_TICKS) in ferry.moves
    for _ in range(60):  # let the player land at the spawn and stand still
        ferry.world.step(frozenset())
    assert ferry.world.player.on_ground and not ferry.waiting_helps()  # no route near
    ferry.try_move(Snapshot.of(ferry.world), 60, frozenset(), WAIT_TICKS)
    assert ferry.moves_tried == -(-WAIT_TICKS // MOVE_TICKS)
