"""``python -m game.bench.drawing`` plays the bench's level and times each part of every tick."""

from __future__ import annotations

from game.bench.drawing import main, measure


def test_the_drawing_bench_times_tick_frame_and_overlay_in_the_same_ticks() -> None:
    cost = measure(max_ticks=30)
    assert cost.ticks == 30
    assert min(cost.tick_ms, cost.frame_ms, cost.overlay_ms) > 0
    assert "overlay / frame" in "\n".join(cost.lines())


def test_the_drawing_bench_runs_from_its_command_line() -> None:
    assert main(["--ticks", "5"]) == 0
