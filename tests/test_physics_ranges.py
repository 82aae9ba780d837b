"""The physics a map may set: each within a range the designer's guide gives, and every
measurement that depends on them bounded by counted work (ticks of play, cells of a fill).

Each hostile map is rebuilt here from its description: physics all set to 1,000,000, gravity
or the fastest fall set to 0, a jump of 1,000,000 px/s, 600 maps each with its own gravity,
and a map as big as the game reads, with floors everywhere. None may end in a traceback, and
none may make the checker work without a bound.
"""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from game.checker.cli import main as levels_main
from game.checker.cli import reach_summary
from game.levels.classes import LEVEL
from game.levels.loader import check_level, load_level
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.hang_guard import HANG_S
from tests.in_process import call_main
from tests.maps import level_from_ascii, write_tmx

ROOT = Path(__file__).resolve().parent.parent
PHYSICS = ("gravity", "max_fall_speed", "run_speed", "jump_speed")
ROWS = ["            ", "            ", "  P      D  ", "############"]


def physics_map(folder: Path, physics: dict[str, float]) -> Path:
    """A small map with a floor, the spawn and an Exit, and these map properties."""
    folder.mkdir(parents=True, exist_ok=True)
    return write_tmx(folder, ROWS,
                     properties={key: ("float", value) for key, value in physics.items()})


def bounds(name: str) -> tuple[float, float]:
    member = LEVEL.member(name)
    assert member.low is not None and member.high is not None
    return member.low, member.high


def test_a_map_whose_physics_are_all_a_million_is_one_sentence_per_property(
        tmp_path: Path) -> None:
    level = physics_map(tmp_path, {name: 1_000_000 for name in PHYSICS})
    ran = call_main(levels_main, ["check", "--jobs", "1", level], hang_s=HANG_S)
    assert ran.returncode == 1 and "Traceback" not in ran.stdout + ran.stderr
    refused = {name for name in PHYSICS if bounds(name)[1] < 1_000_000}
    assert refused == {"max_fall_speed", "run_speed", "jump_speed"}
    lines = ran.stdout.splitlines()
    for name in refused:
        low, high = bounds(name)
        line = next(line for line in lines if f"map property '{name}'" in line)
        assert line == (f"{level}: map property '{name}': 1,000,000 is not a number from "
                        f"{low:,.0f} to {high:,.0f} — set '{name}' "
                        f"({LEVEL.member(name).doc}) in Map > Map Properties")


@pytest.mark.parametrize(("name", "value"), [("gravity", 0), ("max_fall_speed", 0),
                                             ("jump_speed", 1_000_000),
                                             ("run_speed", 1_000_000), ("gravity", -900)])
def test_physics_outside_their_range_are_refused_naming_map_property_and_range(
        tmp_path: Path, name: str, value: float) -> None:
    """Gravity or a fall of 0 never brings a jump down; a jump of 1,000,000 px/s went off
    the reach's test level (IndexError): now each is one sentence, before any measuring."""
    level = physics_map(tmp_path, {name: value})
    ran = call_main(levels_main, ["check", "--jobs", "1", level], hang_s=HANG_S)
    low, high = bounds(name)
    assert ran.returncode == 1 and "Traceback" not in ran.stdout + ran.stderr
    assert (f"{level}: map property '{name}': {value:,} is not a number from {low:,.0f} to "
            f"{high:,.0f} — set '{name}'") in ran.stdout
    assert "Map > Map Properties" in ran.stdout


# The ranges the designer's guide promises: a test of their edges must not read them from
# the code it tests.
PROMISED = {"gravity": (200.0, 1_000_000.0), "max_fall_speed": (100.0, 10_000.0),
            "run_speed": (10.0, 10_000.0), "jump_speed": (0.0, 1_000.0)}


@pytest.mark.parametrize("name", PHYSICS)
def test_the_ends_of_each_range_load_and_a_hair_beyond_them_does_not(
        tmp_path: Path, name: str) -> None:
    low, high = PROMISED[name]
    assert bounds(name) == (low, high)
    for end in (low, high):
        level = load_level(physics_map(tmp_path / f"{end:g}", {name: end}))
        assert level.properties[name] == end
    for beyond in (low - 0.5, high + 0.5):
        findings = check_level(physics_map(tmp_path / f"{beyond:g}", {name: beyond}))
        assert [error.where for error in findings.errors] == [f"map property '{name}'"]


CORNERS = list(itertools.product(*(bounds(name) for name in PHYSICS)))


@pytest.mark.parametrize("corner", CORNERS, ids=[",".join(f"{v:g}" for v in c)
                                                  for c in CORNERS])
def test_at_every_corner_of_the_ranges_the_reach_is_measured_within_its_budget(
        corner: tuple[float, float, float, float]) -> None:
    """No IndexError off the test level, and the limits stop at their budget of ticks."""
    from game.checker import reach

    tuning = Tuning().with_map_properties(dict(zip(PHYSICS, corner, strict=True)))
    counted: list[int] = []
    original = reach._Meter.step

    def step(meter: reach._Meter, world: World, held: frozenset[object]) -> None:
        counted.append(1)
        original(meter, world, held)  # type: ignore[arg-type]

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reach._Meter, "step", step)
        limits = reach.limits_of(tuning, budget_ticks=3_000)
    assert len(counted) <= 3_001  # the tick past the budget is refused, not played
    assert isinstance(limits, (reach.Limits, reach.Unmeasured))
    jump = reach.measure_reach(tuning)
    assert 0 <= jump.height_px <= 2_500 and jump.distance_px >= 0


def test_the_widest_jump_at_the_ranges_ends_lands_on_its_test_level() -> None:
    """The longest jump the ranges allow (30 s in the air at 10,000 px/s) lands on the
    floor jump_path lays for it, however far that is."""
    from game.checker.reach import jump_path

    tuning = Tuning(gravity_px_s2=200.0, jump_speed_px_s=1_000.0, max_fall_speed_px_s=100.0,
                    run_speed_px_s=10_000.0)
    path = jump_path(tuning)
    assert path[-1].bottom == path[0].bottom and path[-1].x - path[0].x > 290_000


def test_six_hundred_maps_each_with_its_own_gravity_are_measured_for_four(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """The summary gives the reach on the first maps with their own physics and counts the
    rest: measuring each took a second, and 600 took ten minutes."""
    from game.checker import reach

    measured: list[Tuning] = []

    def limits(tuning: Tuning) -> reach.Limits:
        measured.append(tuning)
        return reach.Limits(1, 2, 3)

    monkeypatch.setattr(reach, "measure_limits", limits)
    own = [(Path(f"m{number:03}.tmx"), Tuning(gravity_px_s2=600.0 + number))
           for number in range(600)]
    text = reach_summary(own)
    assert len(measured) == reach.MAX_OWN_PHYSICS < 600
    assert text.endswith(f"; {600 - reach.MAX_OWN_PHYSICS} more map(s) set their own physics "
                         "(reach MAP measures one)")
    assert text.count("with its own physics") == reach.MAX_OWN_PHYSICS


def test_the_summary_spends_one_budget_of_ticks_on_every_map_together(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from game.checker import reach

    own = [(Path(f"m{number}.tmx"), Tuning(gravity_px_s2=600.0 + number))
           for number in range(3)]
    jumps = sum(reach.RUN_UP_TICKS + len(reach.jump_path(tuning)) - 1 for _, tuning in own)
    monkeypatch.setattr(reach, "SUMMARY_MEASURE_TICKS", 2_000)
    played: list[int] = []
    original = World.step

    def step(world: World, held: frozenset[object]) -> object:
        played.append(1)
        return original(world, held)  # type: ignore[arg-type]

    monkeypatch.setattr(World, "step", step)
    shown, more = reach.own_reaches(own)
    budgets = [item.limits.budget_ticks for item in shown
               if isinstance(item.limits, reach.Unmeasured)]
    assert more == 0 and budgets == [666, 667, 667]  # a share each of what was left
    assert "not measured within the 666 ticks of play" in shown[0].limits.describe()
    assert jumps < len(played) <= jumps + 2_000  # each map's jump, then the one budget


def floors(cols: int, rows: int) -> list[str]:
    """A map with a floor on every third row, gaps in each, the spawn top left, the Exit
    bottom right: every floor launches jumps."""
    art = [" " * cols if row % 3 != 2 else
           "".join("#" if col % 7 < 5 else " " for col in range(cols)) for row in range(rows)]
    art[0] = "  P" + art[0][3:]
    art[-2] = art[-2][:-3] + "D  "
    art[-1] = "#" * cols
    return art


def test_the_jump_fill_of_a_big_map_stops_at_its_budget_of_steps() -> None:
    """A 500x500 map of floors took the fill 66 s; its steps are now counted, and past the
    budget it gives up (proving nothing) instead of taking minutes."""
    from game.checker.reachable import FillWork, reachable

    level = level_from_ascii(floors(50, 30))
    work = FillWork(budget=5_000)
    assert reachable(World(level), work) is None
    assert 5_000 < work.steps <= 5_000 + 8  # the last look past it, then no more
    enough = FillWork(budget=10**9)
    reach = reachable(World(level), enough)
    assert reach is not None and reach.touches_exit and enough.steps > 5_000


def test_the_biggest_shipped_level_fills_within_a_thirtieth_of_the_budget() -> None:
    """The fill a check runs on a shipped level (the narrow one: it reaches the Exit, so the
    full proof is not needed) within a thirtieth; the full proof, with every platform's push
    and every enemy's way, within a fifth."""
    from game.checker.reachable import MAX_FILL_STEPS, FillWork, reachable

    for path in [ROOT / "levels/06-the-summit.tmx"]:
        work = FillWork()
        guide = reachable(World(load_level(path)), work, narrow=True)
        assert guide is not None and guide.touches_exit
        assert work.steps < MAX_FILL_STEPS / 30, path.name
        work = FillWork()
        assert reachable(World(load_level(path)), work) is not None
        assert work.steps < MAX_FILL_STEPS / 5, path.name


def test_a_map_whose_fill_gives_up_is_still_searched_and_solved(
        monkeypatch: pytest.MonkeyPatch) -> None:
    from game.checker import reachable as fill
    from game.checker.solver import Effort
    from game.checker.verdict import Kind, judge

    monkeypatch.setattr(fill, "MAX_FILL_STEPS", 100)
    tried: list[int] = []
    original = fill.reachable

    def counted(world: World, work: fill.FillWork | None = None,
                narrow: bool = False) -> fill.Reach | None:
        tried.append(1)
        return original(world, work, narrow)

    def again(world: World) -> None:
        tried.append(2)

    monkeypatch.setattr("game.checker.verdict.reachable", counted)
    monkeypatch.setattr("game.checker.solver.steps_to_exit", again)
    verdict = judge(level_from_ascii(["          ", "  P    D  ", "##########"]), Effort())
    assert verdict.kind is Kind.SOLVED
    assert tried == [1]  # the fill ran once, gave up, and the search did not try it again


def test_the_designers_guide_gives_the_range_of_every_physics_property() -> None:
    guide = (ROOT / "levels/README.md").read_text(encoding="utf-8")
    table = guide[guide.index("## Map properties"):guide.index("**How far the player")]
    for name in PHYSICS:
        low, high = bounds(name)
        row = next(line for line in table.splitlines() if line.startswith(f"| `{name}` |"))
        assert row.endswith(f"| {low:,.0f} to {high:,.0f} |"), name


def test_a_move_on_a_crowded_map_counts_as_the_work_it_does() -> None:
    """Within every budget of its level, a map of 100 enemies, 300 platforms or 5,000 coins
    made each move of the search 20 to 140 times dearer: 50,000 moves took minutes. Now such
    a move counts as several, so the budget bounds the work, not only the moves."""
    from game.checker.solver import BODIES_PER_MOVE, COINS_PER_MOVE, Effort, move_weight, solve

    coins = 2 * COINS_PER_MOVE
    art = ["C" * coins + " " * 100, "  P" + " " * (coins + 96) + "D", "#" * (coins + 100)]
    level = level_from_ascii(art)
    assert move_weight(level) == 3
    crowd = level_from_ascii(["E" * BODIES_PER_MOVE + "   ", "P" + " " * 18, "#" * 19])
    assert move_weight(crowd) == 2
    solution = solve(level, Effort(budget=600))
    assert not solution.found and solution.moves_tried >= 600
    assert solution.states <= 600 // 3  # each state kept cost at least one weighted move


def test_the_designers_guide_gives_every_bound_on_the_checkers_work() -> None:
    from game.checker import reach, reachable, solver

    guide = " ".join((ROOT / "levels/README.md").read_text(encoding="utf-8").split())
    assert f"after looking at {reachable.MAX_FILL_STEPS:,} cells" in guide
    assert f"the summary spends at most {reach.SUMMARY_MEASURE_TICKS:,}" in guide
    assert f"`reach` at most {reach.MAX_MEASURE_TICKS:,} on one" in guide
    assert f"for the first {reach.MAX_OWN_PHYSICS} such maps" in guide
    assert (f"one move more for every {solver.BODIES_PER_MOVE} enemies and platforms together "
            f"and for every {solver.COINS_PER_MOVE} coins") in guide
    assert f"counts each move as {1 + 5_000 // solver.COINS_PER_MOVE}" in guide
