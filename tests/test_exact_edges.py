"""The proof of impossibility is exact at the measured limits: a gap or a ledge at the limit
is never called impossible, one a pixel past it is, for the default physics and for a map's
own; the limits the summary prints are the bounds the proof uses; a mechanic the
pixel-exact reach does not bound makes it prove nothing, and the line names it; a layer
whose Solid tiles put the Exit out of reach is named at one of its tiles."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from game.checker.checking import Options, check_map
from game.checker.jump_envelope import air_envelope, exact_reach
from game.checker.reach import DEFAULT_LIMITS, Limits, limits_of
from game.checker.solver import Effort
from game.checker.verdict import Kind, judge, prove_impossible
from game.collision.aabb import Box
from game.sim.level import EnemySpec, Level
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.maps import level_from_boxes, write_tmx
from tests.test_verdicts import COLS, EDGE, FLOOR, ROWS, SPAWN, WIDTH, exit_on, gap, ledge

# Physics a map may set: floatier; slower with a lower jump (its widest gap ends a fraction
# of a pixel past a whole one, which start places a quarter pixel apart used to miss); and
# faster, whose widest jump carries exactly a whole number of pixels (one pixel wider is
# missed by a float's last bit, and proven so).
OWN_PHYSICS = {
    "floaty": {"gravity": 650.0},
    "slow": {"run_speed": 70.0, "jump_speed": 250.0},
    "fast": {"run_speed": 120.0, "jump_speed": 320.0},
}
SMALL = Effort(budget=300)  # the search is not what these tests are about


def own(level: Level, physics: str) -> Level:
    return replace(level, properties=OWN_PHYSICS[physics])


def tuning_of(physics: str) -> Tuning:
    return Tuning().with_map_properties(OWN_PHYSICS[physics])


def proven_impossible(level: Level) -> bool:
    verdict, _ = prove_impossible(level)
    return verdict is not None and verdict.kind is Kind.IMPOSSIBLE


def test_a_gap_up_to_the_widest_is_in_reach_and_one_pixel_wider_is_proven_impossible(
        ) -> None:
    for width in (64, 74, 75, DEFAULT_LIMITS.coyote_gap_px):
        assert exact_reach(World(gap(width))).touches_exit
        assert not proven_impossible(gap(width))
    verdict = judge(gap(DEFAULT_LIMITS.coyote_gap_px + 1), SMALL)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is None  # proven, not searched
    assert (f"it crosses gaps of at most {DEFAULT_LIMITS.coyote_gap_px} px and lands on "
            f"ledges at most {DEFAULT_LIMITS.ledge_px} px high") in verdict.finding


def test_a_ledge_up_to_the_highest_is_in_reach_and_one_pixel_higher_is_proven_impossible(
        ) -> None:
    for height in (32, DEFAULT_LIMITS.ledge_px):
        assert exact_reach(World(ledge(height))).touches_exit
        assert not proven_impossible(ledge(height))
    verdict = judge(ledge(DEFAULT_LIMITS.ledge_px + 1), SMALL)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is None


@pytest.mark.parametrize("physics", sorted(OWN_PHYSICS))
def test_a_maps_own_physics_move_the_edges_to_the_limits_the_summary_prints(
        physics: str) -> None:
    """The summary's limits (measured by play) are the bounds the proof uses: at them the
    map is in reach, a pixel past them it is proven impossible."""
    tuning = tuning_of(physics)
    limits, envelope = limits_of(tuning), air_envelope(tuning)
    assert isinstance(limits, Limits) and envelope is not None
    assert (envelope.widest_gap_px(), envelope.highest_ledge_px()) == (
        limits.coyote_gap_px, limits.ledge_px)
    assert (limits.coyote_gap_px, limits.ledge_px) != (DEFAULT_LIMITS.coyote_gap_px,
                                                       DEFAULT_LIMITS.ledge_px)
    assert exact_reach(World(own(gap(limits.coyote_gap_px), physics))).touches_exit
    assert exact_reach(World(own(ledge(limits.ledge_px), physics))).touches_exit
    assert proven_impossible(own(gap(limits.coyote_gap_px + 1), physics))
    assert proven_impossible(own(ledge(limits.ledge_px + 1), physics))


def test_the_default_limits_are_the_bounds_the_proof_uses() -> None:
    envelope = air_envelope(Tuning())
    assert envelope is not None
    assert limits_of(Tuning()) == DEFAULT_LIMITS
    assert (envelope.widest_gap_px(), envelope.highest_ledge_px()) == (
        DEFAULT_LIMITS.coyote_gap_px, DEFAULT_LIMITS.ledge_px)
    assert proven_impossible(gap(DEFAULT_LIMITS.coyote_gap_px + 1))


def test_the_slow_physics_cross_the_gap_a_start_place_a_quarter_pixel_apart_missed() -> None:
    limits = limits_of(tuning_of("slow"))
    assert isinstance(limits, Limits) and limits.coyote_gap_px == 55


def gap_with(enemies: tuple[EnemySpec, ...] = (), flags: tuple[Box, ...] = ()) -> Level:
    """A gap one pixel past the widest, with enemies or Checkpoints."""
    width = DEFAULT_LIMITS.coyote_gap_px + 1
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                         Box(EDGE + width, FLOOR, WIDTH - EDGE - width, 64)],
                            SPAWN, [exit_on(FLOOR)], checkpoints=flags, enemies=enemies)


def test_an_enemy_makes_the_exact_proof_give_up_and_the_line_says_so() -> None:
    slime = gap_with(enemies=(EnemySpec(Box(80, FLOOR - 12, 14, 12)),))
    assert exact_reach(World(slime)).unbounded == ["an enemy (a stomp bounces the player)"]
    verdict = judge(slime, SMALL)
    assert verdict.kind is Kind.UNDECIDED
    assert "the pixel-exact reach" in verdict.finding
    assert "does not cover an enemy (a stomp bounces the player)" in verdict.finding


def test_a_respawn_counts_as_a_start_only_once_its_flag_can_be_counted() -> None:
    """A flag past the gap is counted by no jump, so it adds no start, and one before it
    adds nothing new. A wide flag reaching back over the gap to the near edge, whose foot's
    middle is across it, is touched from the near side: the player, losing a life, comes
    back across the gap, so the Exit is in reach."""
    past = Box(EDGE + 120, FLOOR - 32, 16, 32)
    before = Box(EDGE - 48, FLOOR - 32, 16, 32)
    assert proven_impossible(gap_with(flags=(past,)))
    assert proven_impossible(gap_with(flags=(before,)))
    wide = DEFAULT_LIMITS.coyote_gap_px + 1
    over = gap_with(flags=(Box(EDGE - 8, FLOOR - 32, 2 * (wide + 20), 32),))
    assert exact_reach(World(over)).touches_exit
    assert not proven_impossible(over)


def wall_on_a_decoration_layer(folder: Path) -> Path:
    """An open field with a wall three tiles high (higher than any jump, open sky above
    it) painted on a layer named as decoration, the Exit behind it."""
    rows = ["                ", "                ", "                ", "                ",
            " P           D  ", "################"]
    path = write_tmx(folder, rows)
    cols = len(rows[0])
    wall = [[1 if col == 8 and 2 <= row <= 4 else 0 for col in range(cols)]
            for row in range(len(rows))]
    data = ",\n".join(",".join(map(str, row)) for row in wall)
    layer = (f' <layer id="7" name="background (no collision)" width="{cols}" '
             f'height="{len(rows)}">\n  <data encoding="csv">\n{data}\n</data>\n </layer>\n')
    text = path.read_text(encoding="utf-8").replace(' <objectgroup', layer + ' <objectgroup')
    path.write_text(text, encoding="utf-8")
    return path


def test_a_wall_out_of_reach_on_a_decoration_layer_is_named_at_its_tile(
        tmp_path: Path) -> None:
    report = check_map(wall_on_a_decoration_layer(tmp_path), Options(effort=SMALL))
    (finding,) = [f for f in report.findings if "impossible" in f.text]
    assert "the Exit lies outside everything the player's jumps can touch" in finding.text
    assert "without the Solid tiles of layer 'background (no collision)' there would be a " \
           "way" in finding.text
    assert finding.layer == "background (no collision)"
    assert finding.tile is not None and finding.tile[0] == 8 and 2 <= finding.tile[1] <= 4


def test_a_ceiling_near_the_take_off_does_not_move_the_edge() -> None:
    """A corner correction leaves the body flush with a ceiling's corner, from where it
    runs on: a roof over the near side, or a block over the spawn, carries no jump further
    than a run off the edge does."""
    for roof in (Box(96, FLOOR - 40, 80, 16), Box(16, FLOOR - 40, 32, 16)):
        for width, impossible in ((DEFAULT_LIMITS.coyote_gap_px, False),
                                  (DEFAULT_LIMITS.coyote_gap_px + 1, True)):
            level = level_from_boxes(
                COLS, ROWS, [Box(0, FLOOR, EDGE, 64), roof,
                             Box(EDGE + width, FLOOR, WIDTH - EDGE - width, 64)],
                SPAWN, [exit_on(FLOOR)])
            assert proven_impossible(level) is impossible
