"""The shipped campaign: every map passes the checker and is won by its input script."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from game.app.run import input_script
from game.checker.cli import main as levels_main
from game.checker.reach import DEFAULT_LIMITS, measure_limits, measure_reach
from game.checker.verdict import PROOF_GRACE_TICKS
from game.collision.aabb import Box
from game.collision.shapes import TileKind
from game.levels import FIRST_LEVEL, LEVELS_DIR, load_level
from game.levels.loader import check_level
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Outcome
from game.sim.inputs import Action
from game.sim.tuning import Tuning
from game.sim.world import EventKind, World
from tests.campaign_run import campaign_played
from tests.in_process import call_main
from tests.maps import write_tmx
from tests.shipped_fills import share_fills

SCRIPTS = Path(__file__).resolve().parent / "scripts"
SHIPPED = sorted(LEVELS_DIR.glob("*.tmx"))


def test_the_campaign_has_at_least_two_levels_chained_from_the_first() -> None:
    assert len(SHIPPED) >= 2
    chain = [FIRST_LEVEL]
    while (following := load_level(chain[-1]).next_level) is not None:
        chain.append(following)
        assert len(chain) <= len(SHIPPED), "next_level goes round in a loop"
    assert sorted(p.resolve() for p in chain) == [p.resolve() for p in SHIPPED]


def test_the_checker_passes_every_shipped_level(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the search for a route: tests/test_solver.py solves every shipped level. The
    reach fills behind the unreachable-Coin warning are the ones worked out once for the
    shipped levels (:mod:`tests.shipped_fills`); the program itself, ``python -m game.levels
    check``, checks a shipped level in tests/test_readme.py."""
    own_fills = share_fills(monkeypatch)
    result = call_main(levels_main, ["check", "--no-solve", "--jobs", "1", *SHIPPED])
    assert result.returncode == 0, result.stdout + result.stderr
    assert own_fills == []  # each shipped level was checked with its own fill
    assert result.stdout.splitlines() == [
        f"checked {len(SHIPPED)} map(s): all playable; the player jumps 2.8 tiles high and "
        "3.6 tiles across at a run (16 px tiles); " + DEFAULT_LIMITS.describe()]


def test_the_checker_gives_the_reach_of_a_map_that_sets_its_own_physics() -> None:
    fast_fall = LEVELS_DIR / "showcase" / "fast-fall.tmx"    # gravity 512 times the default
    result = call_main(levels_main, ["check", "--no-solve", "--jobs", "1", fast_fall,
                                     FIRST_LEVEL])
    own_tuning = Tuning().with_map_properties(load_level(fast_fall).properties)
    own = measure_reach(own_tuning)
    assert own.height_px < measure_reach(Tuning()).height_px / 100
    assert result.stdout.splitlines() == [
        "checked 2 map(s): all playable; with the default physics the player jumps 2.8 tiles "
        f"high and 3.6 tiles across at a run (16 px tiles); {DEFAULT_LIMITS.describe()}; on "
        f"fast-fall.tmx, with its own physics, it {own.describe(16)}; "
        f"{measure_limits(own_tuning).describe()}"]


def test_the_checker_names_the_file_and_the_fix_for_a_bad_map(tmp_path: Path) -> None:
    level = write_tmx(tmp_path, ["      ", "  C   ", "######"])      # no Player
    result = call_main(levels_main, ["check", level])
    assert result.returncode == 1
    assert result.stdout.startswith(f"{level}: ") and "Player" in result.stdout
    assert " — " in result.stdout and "Traceback" not in result.stdout + result.stderr


def test_tile_layers_keep_tiled_document_order_around_object_layers() -> None:
    level = load_level(FIRST_LEVEL)
    assert [layer.name for layer in level.layers] == ["decor", "ground"]
    assert level.foreground == ()


def test_hazard_tiles_use_their_partial_collision_rectangle() -> None:
    path = LEVELS_DIR / "03-hop-along.tmx"
    spikes = [s for s in load_level(path).grid.shapes() if s.kind is TileKind.HAZARD]
    assert spikes
    for shape in spikes:
        assert shape.box.h == 8 and shape.box.w == 14           # drawn in Tiled: (1, 8) 14x8
        assert shape.box.x == shape.col * 16 + 1 and shape.box.y == shape.row * 16 + 8


def _pit_columns_and_spikes(level: Path) -> tuple[int, int]:
    """How many columns of ``level`` have no Solid tile in the bottom row (a fall there
    leaves the map), and how many Hazard tiles it has."""
    grid = load_level(level).grid
    floor = {shape.col for shape in grid.shapes()
             if shape.kind is TileKind.SOLID and shape.row == grid.rows - 1}
    spikes = sum(1 for shape in grid.shapes() if shape.kind is TileKind.HAZARD)
    return grid.cols - len(floor), spikes


def test_the_first_levels_bring_in_pits_then_spikes() -> None:
    """As the guide says: First Steps has no pit and no spike, Over the Gaps has the first
    pits, Hop Along the first spikes."""
    first, gaps, hops = (_pit_columns_and_spikes(LEVELS_DIR / name) for name in (
        "01-first-steps.tmx", "02-over-the-gaps.tmx", "03-hop-along.tmx"))
    assert first == (0, 0)
    assert gaps[0] > 0 and gaps[1] == 0
    assert hops[1] > 0


def exit_tick_said(script: Path) -> int:
    """The tick a winning script says, in its comment, that it reaches the exit."""
    said = re.search(r"^# reaches the exit at tick (\d+)$", script.read_text(encoding="utf-8"),
                     re.MULTILINE)
    assert said, f"{script.name} does not say the tick it reaches the exit"
    return int(said.group(1))


def test_the_whole_campaign_is_won_by_the_winning_scripts_at_the_ticks_they_say() -> None:
    """Each level's script, played on from the one before, reaches the exit at the tick its
    comment says, with no life lost and no overlap: every shipped script is replayed once.

    Each level starts a fresh world at its script's first tick, as ``check --proof`` plays
    a map alone; so each script, winning within the proof's grace after its last input, is
    one ``check --proof`` accepts (``tests/test_solver.py`` runs it on a level, and this
    module's checker test finds no error in any)."""
    played = campaign_played()
    for name, level in played.levels.items():
        assert level.won_at is not None, f"{name}: no exit in 5 minutes"
        assert level.deaths == 0, f"{name}: the script lost a life"
        script = input_script(SCRIPTS / f"{name}.txt")
        last_input = script.events[-1].tick if script.events else 0
        assert level.won_at <= last_input + PROOF_GRACE_TICKS, f"{name}: won after the grace"
    assert played.outcome is Outcome.WON and played.max_penetration_px == 0.0
    assert {name: level.won_at for name, level in played.levels.items()} == {
        path.stem: exit_tick_said(SCRIPTS / f"{path.stem}.txt") for path in SHIPPED}


CAMPAIGN_TICKS = 8 * 60 * 60  # the campaign lasts at least 8 minutes at the scripts' pace
LONG_LEVEL_TICKS = 40 * 60  # a level whose script takes longer than this has a Checkpoint
TARGET_SLACK = 1.3  # a level's target_seconds is at most this times its script's time, + 1 s


def test_the_campaign_is_twelve_levels_and_eight_minutes_at_the_scripts_pace() -> None:
    ticks = [exit_tick_said(SCRIPTS / f"{path.stem}.txt") for path in SHIPPED]
    assert len(SHIPPED) == 12 and sum(ticks) >= CAMPAIGN_TICKS


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_a_long_level_has_a_checkpoint_and_every_level_a_target_time_above_its_script(
        level: Path) -> None:
    loaded = load_level(level)
    seconds = exit_tick_said(SCRIPTS / f"{level.stem}.txt") / 60
    if seconds * 60 > LONG_LEVEL_TICKS:
        assert loaded.checkpoints, f"{level.name} lasts {seconds:.0f} s with no Checkpoint"
    target = loaded.properties.get("target_seconds")
    assert isinstance(target, float), f"{level.name} has no float target_seconds"
    assert seconds <= target <= seconds * TARGET_SLACK + 1


GUIDE = LEVELS_DIR / "README.md"


def test_the_guides_table_and_total_are_the_scripts_and_the_maps_targets() -> None:
    """The designer's guide gives each level's script time and target, and the total: each
    is what the script's comment says and the map's ``target_seconds`` hold."""
    guide = GUIDE.read_text(encoding="utf-8")
    rows = re.findall(r"^\| \d+ \| [^|]*\(`([\w-]+)\.tmx`\) \|.*\| ([\d.]+) s \| ([\d.]+) s \|$",
                      guide, re.MULTILINE)
    assert [stem for stem, _, _ in rows] == [path.stem for path in SHIPPED]
    ticks = {path.stem: exit_tick_said(SCRIPTS / f"{path.stem}.txt") for path in SHIPPED}
    for stem, script_s, target_s in rows:
        assert abs(float(script_s) - ticks[stem] / 60) <= 0.05, stem  # to a tenth of a second
        target = load_level(LEVELS_DIR / f"{stem}.tmx").properties.get("target_seconds")
        assert float(target_s) == target, stem
    total = sum(ticks.values())
    assert f"Together the scripts take {total:,} ticks ({total / 3600:.1f} minutes)" in " ".join(
        guide.split())


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_moving_platform_travels_within_one_view(level: Path) -> None:
    """Its whole box, from one end of its route to the other, fits in the 320 x 180 view, so
    a player waiting at one end sees the platform wherever it is."""
    for spec in load_level(level).platforms:
        xs = [x for x, _ in spec.path.points]
        ys = [y for _, y in spec.path.points]
        assert max(xs) - min(xs) + spec.width_px <= VIEW_W_PX, spec
        assert max(ys) - min(ys) + spec.height_px <= VIEW_H_PX, spec


def _copy_of_first_level(folder: Path, lift_exit_px: int) -> Path:
    """The first level and its tileset copied into ``folder``, its Exit raised ``lift_exit_px``."""
    assets = LEVELS_DIR.parent / "assets"
    (folder / "levels").mkdir()
    (folder / "assets").mkdir()
    for name in ("tiles.tsx", "tiles.png", "terrain.tsx", "terrain.png"):
        (folder / "assets" / name).write_bytes((assets / name).read_bytes())
    text = FIRST_LEVEL.read_text(encoding="utf-8")
    exit_box = load_level(FIRST_LEVEL).exits[0]
    old = f'type="Exit" x="{exit_box.x:g}" y="{exit_box.y:g}"'
    assert old in text
    copy = folder / "levels" / FIRST_LEVEL.name
    copy.write_text(text.replace(old, f'type="Exit" x="{exit_box.x:g}" '
                                      f'y="{exit_box.y - lift_exit_px:g}"'), encoding="utf-8")
    return copy


@pytest.mark.parametrize("lift_px", [0, 16])
def test_an_exit_lifted_off_the_ground_gets_the_floating_warning(tmp_path: Path,
                                                                 lift_px: int) -> None:
    findings = check_level(_copy_of_first_level(tmp_path, lift_px))
    floating = [str(w) for w in findings.warnings if "floats" in str(w)]
    assert findings.errors == []
    if lift_px:
        assert len(floating) == 1 and "object #14 'Exit'" in floating[0]
    else:
        assert floating == []


@pytest.mark.parametrize("level", SHIPPED, ids=[p.stem for p in SHIPPED])
def test_every_exit_is_reached_by_walking_along_the_ground_to_it(level: Path) -> None:
    """Start on the ground three tiles before each Exit and hold the way to it: no jump."""
    loaded = load_level(level)
    for goal in loaded.exits:
        world = World(loaded)
        towards = Action.RIGHT if goal.x > world.player.box.x else Action.LEFT
        side = -1 if towards is Action.RIGHT else 1
        start = Box(goal.x + side * 3 * loaded.grid.tile_w, goal.bottom - world.player.box.h,
                    world.player.box.w, world.player.box.h)
        world.player.teleport(start)
        world.probe_ground(world.player)
        assert world.player.on_ground, f"no ground to stand on before the exit at {goal}"
        events = [event.kind for _ in range(60) for event in world.step(frozenset({towards}))]
        assert EventKind.EXIT in events and EventKind.JUMP not in events
