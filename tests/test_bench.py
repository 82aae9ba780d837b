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
from typing import NamedTuple

import pytest

import game.bench.run as bench_run
from game.bench import (
    broad,
    caching,
    game_step,
    grid_cells,
    main,
    narrow,
    peer,
    plain_sweep,
    targets,
    tunnelling,
    walls,
)
from game.bench.intervals import Interval, paired_ratio
from game.bench.records import COLUMNS, Row, read_csv
from game.bench.run import CHARTS, Chart, redraw, run
from game.bench.sizes import TINY
from game.bench.timing import Case, interleaved, percentile
from game.collision import methods
from game.collision.aabb import Box
from game.collision.axis_sweep import move_x, move_y
from game.collision.broad.brute_force import BruteForce
from game.collision.broad.spatial_grid import SpatialGrid
from game.levels import load_level

COMMITTED = Path(__file__).resolve().parent.parent / "assets" / "charts"

PNG_MAGIC = b"\x89PNG\r\n\x1a\n"


class TinyRun(NamedTuple):
    out: Path                          # where the run wrote its files
    measured: dict[str, list[Row]]     # the rows it measured, chart by chart


@pytest.fixture(scope="module")
def tiny(tmp_path_factory: pytest.TempPathFactory) -> TinyRun:
    out = tmp_path_factory.mktemp("charts")
    measured, _ = run(TINY, out, echo=lambda line: None)
    return TinyRun(out, measured)


@pytest.fixture(scope="module")
def tiny_run(tiny: TinyRun) -> Path:
    return tiny.out


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
    assert header == "target,measured,low,high,comparison,limit,unit,result,note"
    assert (tiny_run / "targets.md").read_text(encoding="utf-8").startswith("| target |")
    assert (tiny_run / "targets.png").read_bytes()[:8] == PNG_MAGIC
    readme = (tiny_run / "README.md").read_text(encoding="utf-8")
    assert all(f"{chart.name}.png" in readme for chart in CHARTS)
    assert "pygame" in readme and "Python" in readme  # the machine footnote


def test_timed_rows_have_one_value_per_round_and_the_targets_n_has_more(tiny_run: Path,
                                                                        ) -> None:
    rows = read_csv(tiny_run / "broad_phase.csv")
    timed = [r for r in rows if r.unit == "ms/frame" and r.method == broad.GRID]
    per_n: dict[str, list[int]] = {}
    for row in timed:
        per_n.setdefault(row.parameter, []).append(row.round)
    assert sorted(per_n.pop(str(TINY.target_n))) == list(range(TINY.verdict_rounds))
    assert all(sorted(rounds) == list(range(TINY.rounds)) for rounds in per_n.values())
    assert broad.verdict_n(rows) == TINY.target_n


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


def test_the_discrete_miss_rate_is_within_a_point_of_the_formula(tiny: TinyRun) -> None:
    rows = tiny.measured[tunnelling.CHART]
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
def narrow_errors(tiny: TinyRun) -> list[Row]:
    assert TINY.narrow_pairs >= 300     # the error rates below come from 300 pairs a family
    return [r for r in tiny.measured[narrow.CHART] if r.unit != "ns/test"]


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


def test_the_walls_maps_are_the_ones_the_readme_counts_whatever_the_shipped_levels() -> None:
    """The pattern is kept in the bench, not read from a level a designer may change: the
    200x40 map holds the 2,413 walls the README's figures were measured on."""
    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text(encoding="utf-8")
    assert "the 2,413 walls of a 200x40 map" in readme
    assert len(list(walls.repeated_map(walls.pattern(), 200, 40).shapes())) == 2_413


def test_the_wide_arena_has_the_same_bodies_on_a_map_twenty_times_wider() -> None:
    narrow_level, wide_level = game_step.arena(1), game_step.arena(game_step.WIDTH_FACTOR)
    assert wide_level.grid.cols == game_step.WIDTH_FACTOR * narrow_level.grid.cols
    assert (wide_level.spawn, wide_level.coins, wide_level.enemies) == (
        narrow_level.spawn, narrow_level.coins, narrow_level.enemies)


def test_the_platform_levels_differ_only_in_their_platforms_all_beyond_the_arena() -> None:
    levels = game_step.compared_levels()
    few, many = levels[game_step.FEW], levels[game_step.MANY]
    assert (len(few.platforms), len(many.platforms)) == (game_step.FEW_PLATFORMS,
                                                         game_step.MANY_PLATFORMS)
    assert few.platforms == many.platforms[:game_step.FEW_PLATFORMS]
    assert replace(few, platforms=()) == replace(many, platforms=()) == levels[game_step.WIDE]
    arena_right_px = 40 * game_step.TILE_PX
    assert all(min(x for x, _ in p.path.points) > arena_right_px for p in many.platforms)


def test_the_level_played_is_won_by_its_script(tiny_run: Path) -> None:
    rows = read_csv(tiny_run / "game_step.csv")
    assert [r.value for r in rows if r.parameter == "won"] == [1.0] * TINY.play_rounds


def test_the_p95_line_is_the_95th_percentile_of_the_line_drawn(tiny_run: Path) -> None:
    rows = read_csv(tiny_run / "game_step.csv")
    _, ticks, line = game_step.played_line(rows)
    assert len(ticks) == len(line) > 100
    assert game_step.p95_ms(rows) == percentile(line, 95)


def test_crossover_is_where_the_structure_wins_at_every_larger_n() -> None:
    def timed(method: str, ms: dict[int, float]) -> list[Row]:
        return [Row(broad.CHART, method, str(n), 0, v, "ms/frame") for n, v in ms.items()]
    rows = (timed("slow", {10: 1.0, 20: 2.0, 50: 9.0, 100: 40.0})
            + timed("fast", {10: 2.0, 20: 1.5, 50: 10.0, 100: 5.0, 200: 9.0}))
    assert broad.crossover(rows, "fast", "slow") == 100   # the win at 20 does not last
    assert broad.crossover(rows, "slow", "fast") is None


def test_a_target_passes_only_when_its_whole_interval_clears_the_limit() -> None:
    def target(low: float, high: float, comparison: str, **kw: object) -> targets.Target:
        return targets.Target("a", Interval((low + high) / 2, low, high), comparison, 15.0,
                              "x", **kw)  # type: ignore[arg-type]
    assert target(15.0, 20.0, ">=").passed
    assert not target(14.9, 20.0, ">=").passed          # the median clears it, the interval not
    assert target(10.0, 15.0, "<=").passed
    assert not target(10.0, 15.1, "<=").passed
    assert not target(30.0, 40.0, ">=", holds_also=False).passed
    skipped = target(30.0, 40.0, ">=", skipped="not installed")
    assert (skipped.passed, skipped.verdict) == (False, "skipped")


def test_a_paired_ratio_takes_each_round_apart_and_brackets_the_median() -> None:
    slow = [2.0, 4.0, 20.0, 2.2, 4.4] * 7      # the load swings both methods alike
    fast = [1.0, 2.0, 10.0, 1.1, 2.2] * 7
    ratio = paired_ratio(slow, fast)
    assert ratio.estimate == ratio.low == ratio.high == 2.0
    noisy = paired_ratio([3.0, 2.0, 2.5, 1.5] * 8, [1.0] * 32)
    assert noisy.low < noisy.estimate < noisy.high
    assert paired_ratio([3.0, 2.0, 2.5, 1.5] * 8, [1.0] * 32) == noisy   # seeded: repeatable
    with pytest.raises(ValueError, match="equally long"):
        paired_ratio([1.0, 2.0], [1.0])


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


def test_a_redraw_hands_every_chart_the_rows_measured_and_gives_the_same_targets(
        tiny: TinyRun, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    for chart in CHARTS:
        (tmp_path / f"{chart.name}.csv").write_bytes((tiny.out / f"{chart.name}.csv").read_bytes())
    # Every chart's draw is handed its rows; the smallest chart alone is drawn again, since the
    # run drew every chart from the same rows (as the assert below shows, to six digits).
    handed: dict[str, list[Row]] = {}

    def keeping_rows(chart: Chart) -> Chart:
        def draw(rows: list[Row], out: Path, footnote: str) -> Path:
            handed[chart.name] = rows
            if chart.name == grid_cells.CHART:
                return chart.draw(rows, out, footnote)
            return out / f"{chart.name}.png"
        return replace(chart, draw=draw)

    monkeypatch.setattr(bench_run, "CHARTS", tuple(keeping_rows(c) for c in CHARTS))
    read_back, checked = redraw(TINY, tmp_path, echo=lambda line: None)
    as_written = {name: [r._replace(value=float(f"{r.value:.6g}")) for r in rows]
                  for name, rows in tiny.measured.items()}   # the CSVs keep six digits
    assert handed == read_back == as_written
    assert targets.markdown(checked) + "\n" == (tiny.out / "targets.md").read_text(
        encoding="utf-8")
    assert (tmp_path / "grid_cells.png").read_bytes()[:8] == PNG_MAGIC
    assert (tmp_path / "targets.png").read_bytes()[:8] == PNG_MAGIC


def test_a_redraw_with_no_csvs_says_so_and_exits_with_status_2(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--redraw", "--out", str(tmp_path)]) == 2
    assert "no peer.csv to redraw from" in capsys.readouterr().err


def test_bad_usage_exits_with_status_2(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stopped:
        main(["--no-such-option"])
    assert stopped.value.code == 2
    assert "usage" in capsys.readouterr().err


def test_the_plain_sweep_ends_every_recorded_move_where_the_game_does() -> None:
    grid = peer.solid_grid(load_level(peer.LEVEL).grid)
    walls_plain = plain_sweep.PlainWalls.from_grid(grid)
    moves = peer.recorded_moves(400)
    assert len(moves) == 400 and any(m.dx for m in moves) and any(m.dy for m in moves)
    blocked = 0
    for x, y, w, h, dx, dy in moves:
        across = move_x(grid, Box(x, y, w, h), dx)
        down = move_y(grid, across.box, dy)
        px = plain_sweep.sweep_x(walls_plain, x, y, w, h, dx)
        assert (px, plain_sweep.sweep_y(walls_plain, px, y, w, h, dy)) == (down.box.x,
                                                                          down.box.y)
        blocked += across.hit is not None or down.hit is not None
    assert blocked > 50      # the moves meet walls, not only open air


def test_the_game_never_tunnels_snags_or_jitters_and_stops_flush() -> None:
    rows = peer.accuracy(arcade=None)
    for method in (peer.GAME, peer.PLAIN):
        assert peer.tunnelled(rows, method) == 0
        assert peer.figure_of(rows, method, "px short of flush (max)") == 0.0
        assert peer.figure_of(rows, method, "stops inside the wall") == 0
        assert peer.figure_of(rows, method, "px jitter at rest") == 0.0
        assert peer.figure_of(rows, method, f"snags on {peer.SEAMS} seams") == 0


def test_the_tutorial_loop_tunnels_once_a_tick_steps_over_wall_and_body() -> None:
    rows = peer.accuracy(arcade=None)
    per_speed = {v: values_of(rows, peer.TUTORIAL, str(v)) for v in peer.SPEEDS_PX}
    assert all(per_speed[v] == 0 for v in peer.SPEEDS_PX if v <= 24)   # v <= T + S = 28 px
    assert per_speed[64] > per_speed[32] > 0
    assert peer.figure_of(rows, peer.TUTORIAL, "px jitter at rest") > 0


def values_of(rows: list[Row], method: str, speed: str) -> float:
    return next(r.value for r in rows if (r.method, r.parameter) == (method, speed)
                and r.unit.startswith("tunnelled"))


def test_without_arcade_the_peer_is_skipped_and_said_to_be(
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(peer, "arcade_module", lambda: None)
    rows = peer.measure(TINY)
    assert peer.skipped(rows) and peer.ARCADE not in peer.timed_methods(rows)
    arcade_target = [t for t in targets.peer_targets(rows) if "Arcade" in t.claim]
    assert [t.verdict for t in arcade_target] == ["skipped"]
    assert "not installed" in arcade_target[0].row()[3]


def test_with_arcade_its_engine_makes_the_same_moves_and_tunnels_at_speed() -> None:
    arcade = peer.arcade_module()
    if arcade is None:
        pytest.skip("Arcade is not installed (pip install -e '.[peers]')")
    grid = peer.solid_grid(load_level(peer.LEVEL).grid)
    moves = peer.recorded_moves(200)
    on_summit = peer.movers(grid, arcade)
    assert peer.agreement(on_summit[peer.ARCADE], on_summit[peer.GAME], moves) > 150
    rows = peer.accuracy(arcade)
    assert values_of(rows, peer.ARCADE, "64") > 0 == peer.tunnelled(rows, peer.GAME)


def test_the_caching_table_shows_differences_not_ratios(tiny_run: Path) -> None:
    header, body = caching.table(read_csv(tiny_run / "caching.csv"))
    assert header[-1] == "more than obj.rect (ns)"
    assert not any(cell.endswith("x") for row in body for cell in row)


def test_the_constants_in_the_code_are_the_committed_runs() -> None:
    broad_rows = read_csv(COMMITTED / "broad_phase.csv")
    crossover = broad.crossover(broad_rows, broad.GRID, broad.BRUTE)
    assert crossover == methods.BROAD_PHASE_CROSSOVER_N
    cells = read_csv(COMMITTED / "grid_cells.csv")
    assert float(grid_cells.fastest(cells)) == methods.GRID_CELL_SIZE_FACTOR
    wins = walls.lookup_wins_from(read_csv(COMMITTED / "walls.csv"))
    assert wins is not None and walls.tiles_of(wins) == methods.TILE_LOOKUP_FROM_TILES


def test_the_committed_run_is_a_full_one_and_its_readme_quotes_its_targets() -> None:
    readme = (COMMITTED / "README.md").read_text(encoding="utf-8")
    assert "(full run)" in readme
    assert targets_table(COMMITTED / "targets.md") in readme
    top = (COMMITTED.parent.parent / "README.md").read_text(encoding="utf-8")
    assert targets_table(COMMITTED / "targets.md") in top


def targets_table(path: Path) -> str:
    return path.read_text(encoding="utf-8").strip()
