"""The benchmark's machinery on tiny sizes, and the parts of it that are not timing.

Nothing here asserts a time: timings belong to the bench's own run and its targets. These
tests check that a run writes what it promises (long-format CSVs, PNG charts, targets and
README) and that the answers being timed are right: every broad phase finds the same pairs,
the discrete miss rate matches its formula, the swept test never lets a flight through.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import pytest

from game.bench import broad, game_step, main, narrow, targets, tunnelling, walls
from game.bench.records import COLUMNS, Row, read_csv
from game.bench.run import CHARTS, run
from game.bench.sizes import TINY
from game.bench.timing import Case, interleaved, percentile
from game.collision import methods
from game.collision.broad.brute_force import BruteForce
from game.collision.broad.spatial_grid import SpatialGrid

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def tiny_run(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("charts")
    run(TINY, out, echo=lambda line: None)
    return out


@pytest.mark.parametrize("chart", [c.name for c in CHARTS])
def test_a_run_writes_a_long_format_csv_and_a_png_for_every_chart(tiny_run: Path,
                                                                   chart: str) -> None:
    csv_path, png_path = tiny_run / f"{chart}.csv", tiny_run / f"{chart}.png"
    assert csv_path.read_text(encoding="utf-8").splitlines()[0] == ",".join(COLUMNS)
    rows = read_csv(csv_path)
    assert rows and all(row.chart == chart and row.unit for row in rows)
    assert all(math.isfinite(row.value) for row in rows)
    assert png_path.read_bytes()[:8] == PNG_MAGIC


def test_a_run_writes_the_targets_and_a_readme_naming_every_chart(tiny_run: Path) -> None:
    header = (tiny_run / "targets.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header == "target,measured,comparison,limit,unit,passed,note"
    assert (tiny_run / "targets.md").read_text(encoding="utf-8").startswith("| target |")
    readme = (tiny_run / "README.md").read_text(encoding="utf-8")
    assert all(f"{chart.name}.png" in readme for chart in CHARTS)
    assert "pygame" in readme and "Python" in readme  # the machine footnote


def test_timed_rows_have_one_value_per_round(tiny_run: Path) -> None:
    rows = read_csv(tiny_run / "broad_phase.csv")
    timed = [r for r in rows if r.unit == "ms/frame" and r.method == broad.GRID]
    per_n: dict[str, list[int]] = {}
    for row in timed:
        per_n.setdefault(row.parameter, []).append(row.round)
    assert all(sorted(rounds) == list(range(TINY.rounds)) for rounds in per_n.values())


@pytest.mark.parametrize("n", [1, 50, 400])
def test_every_broad_phase_finds_the_same_pairs_as_groupcollide(n: int) -> None:
    found = broad.pair_sets(broad.METHODS, n)
    reference = found[broad.GROUPCOLLIDE]
    assert all(pairs == reference for pairs in found.values())
    assert n < 400 or reference  # the crowd is dense enough to have pairs at all


def test_the_run_records_no_pair_set_differences(tiny_run: Path) -> None:
    rows = read_csv(tiny_run / "broad_phase.csv")
    differences = [r for r in rows if r.unit == "pairs unlike the grid's"]
    assert differences and all(r.value == 0 for r in differences)


def test_the_discrete_miss_rate_is_within_a_point_of_the_formula() -> None:
    rows = tunnelling.measure(TINY)
    assert tunnelling.worst_gap(rows, tunnelling.DISCRETE, tunnelling.ANALYTIC) <= 1.0


def test_swept_aabb_never_lets_a_flight_through_up_to_six_tiles_per_tick() -> None:
    swept = next(m for m in tunnelling.METHODS if m.name == tunnelling.SWEPT)
    for tiles in (0.25, 1.5, 1.75, 2.0, 3.5, 6.0):
        speed = tiles * tunnelling.TILE_PX
        hits = [tunnelling.fly(swept, gap, speed)
                for gap in tunnelling.gaps(speed, 300, tunnelling.SEED)]
        assert all(h is not None and h.depth_px == pytest.approx(0, abs=1e-9) for h in hits)


def test_a_discrete_check_misses_every_flight_that_steps_over_the_wall() -> None:
    discrete = tunnelling.METHODS[0]
    speed = 100.0      # > T + S = 28 px: a start 40 px short of the wall ends 32 px past it
    assert tunnelling.fly(discrete, 40.0, speed) is None
    assert tunnelling.analytic_miss_rate(speed) == pytest.approx(0.72)


def test_the_clamp_never_misses_but_arrives_late() -> None:
    clamp = next(m for m in tunnelling.METHODS if m.max_px_per_tick is not None)
    detection = tunnelling.fly(clamp, 64.0, 96.0)
    assert detection is not None and detection.time_ticks > 64.0 / 96.0 + 4


@pytest.fixture(scope="module")
def narrow_errors() -> list[Row]:
    sizes = replace(TINY, narrow_pairs=300, narrow_timed_pairs=1)
    return [r for r in narrow.measure(sizes) if r.unit != "ns/test"]


def test_the_exact_methods_make_no_mistakes_on_their_own_family(
        narrow_errors: list[Row]) -> None:
    exact = {"boxes": "Box.overlaps", "circles": "circle test", "rotated bars": "SAT",
             "L-shapes": "composite boxes"}
    for family, method in exact.items():
        assert wrong(narrow_errors, method, family, "% false hits") == 0
        assert wrong(narrow_errors, method, family, "% missed hits") == 0


def test_bounding_boxes_and_circles_err_only_towards_a_hit(narrow_errors: list[Row]) -> None:
    for family in narrow.FAMILIES:
        assert wrong(narrow_errors, "Box.overlaps", family, "% missed hits") == 0
        assert wrong(narrow_errors, "circle test", family, "% missed hits") == 0


def test_the_pairs_are_hard_cases_about_half_of_them_touching() -> None:
    for family in narrow.FAMILIES:
        pairs = narrow.random_pairs(family, 400, narrow.SEED)
        touching = sum(narrow.oracle(a, b) for a, b in pairs) / len(pairs)
        assert 0.35 < touching < 0.65, family


def wrong(rows: list[Row], method: str, family: str, unit: str) -> float:
    return next(r.value for r in rows if (r.method, r.parameter, r.unit) == (method, family,
                                                                              unit))


def test_the_wall_lookups_find_the_same_walls() -> None:
    wall_map = walls.WallMap.build(walls.pattern(), 90, 30, 60)
    assert wall_map.answers_agree()
    assert len(wall_map.shapes) > 2 * len(list(walls.pattern().shapes()))


def test_the_wide_arena_has_the_same_bodies_on_a_map_twenty_times_wider() -> None:
    narrow_level, wide_level = game_step.arena(1), game_step.arena(game_step.WIDTH_FACTOR)
    assert wide_level.grid.cols == game_step.WIDTH_FACTOR * narrow_level.grid.cols
    assert (wide_level.spawn, wide_level.coins, wide_level.enemies) == (
        narrow_level.spawn, narrow_level.coins, narrow_level.enemies)


def test_the_level_played_for_the_budget_is_won_by_its_script(tiny_run: Path) -> None:
    rows = read_csv(tiny_run / "game_step.csv")
    assert [r.value for r in rows if r.parameter == "won"] == [1.0] * TINY.play_rounds


def test_crossover_is_where_the_structure_wins_at_every_larger_n() -> None:
    def timed(method: str, ms: dict[int, float]) -> list[Row]:
        return [Row(broad.CHART, method, str(n), 0, v, "ms/frame") for n, v in ms.items()]
    rows = (timed("slow", {10: 1.0, 20: 2.0, 50: 9.0, 100: 40.0})
            + timed("fast", {10: 2.0, 20: 1.5, 50: 10.0, 100: 5.0, 200: 9.0}))
    assert broad.crossover(rows, "fast", "slow") == 100   # the win at 20 does not last
    assert broad.crossover(rows, "slow", "fast") is None


def test_a_target_passes_only_inside_its_limit_and_with_same_answers() -> None:
    assert targets.Target("a", 15.0, ">=", 15.0, "x faster").passed
    assert not targets.Target("a", 14.9, ">=", 15.0, "x faster").passed
    assert targets.Target("b", 1.5, "<=", 1.5, "x the time").passed
    assert not targets.Target("c", 99.0, ">=", 15.0, "x faster", holds_also=False).passed


def test_interleaved_timing_gives_one_figure_per_round_for_every_case() -> None:
    cases = [Case("a", lambda: None), Case("b", lambda: sum(range(10)), ops=10)]
    times = interleaved(cases, rounds=4, min_s=0.0)
    assert {name: len(v) for name, v in times.items()} == {"a": 4, "b": 4}
    with pytest.raises(ValueError, match="own name"):
        interleaved([Case("a", lambda: None)] * 2, rounds=1)
    assert percentile([3.0, 1.0, 2.0], 100) == 3.0


def test_the_scene_gets_brute_force_below_the_crossover_and_a_grid_from_it() -> None:
    n = methods.BROAD_PHASE_CROSSOVER_N
    assert isinstance(methods.build_broad_phase(n - 1, 16), BruteForce)
    grid = methods.build_broad_phase(n, 16)
    assert isinstance(grid, SpatialGrid)
    assert grid.cell_size_px == methods.GRID_CELL_SIZE_FACTOR * 16


def test_bad_usage_exits_with_status_2(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stopped:
        main(["--no-such-option"])
    assert stopped.value.code == 2
    assert "usage" in capsys.readouterr().err
