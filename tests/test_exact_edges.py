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
from game.checker.mechanic_bounds import patrol_span, touch_px
from game.checker.reach import DEFAULT_LIMITS, Limits, limits_of
from game.checker.solver import Effort
from game.checker.verdict import Kind, judge, prove_impossible
from game.collision.aabb import Box
from game.sim.inputs import Action
from game.sim.level import EnemySpec, Level
from game.sim.platforms import PlatformSpec, Route
from game.sim.tuning import Tuning
from game.sim.world import World
from tests.maps import level_from_ascii, level_from_boxes, write_tmx
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


def test_an_enemy_the_player_can_reach_makes_the_exact_proof_give_up_and_the_line_names_it(
        ) -> None:
    slime = gap_with(enemies=(EnemySpec(Box(80, FLOOR - 12, 14, 12)),))
    named = ("the enemy starting at tile (5,9) (the player's jumps come within where it can "
             "go: a stomp bounces the player)")
    assert exact_reach(World(slime)).unbounded == [named]
    verdict = judge(slime, SMALL)
    assert verdict.kind is Kind.UNDECIDED
    assert "the pixel-exact reach" in verdict.finding
    assert f"does not cover {named}" in verdict.finding


# A trough high over the start side, walled at both ends: an enemy in it cannot leave it,
# and no jump from the ground below comes near it.
TROUGH = (Box(16, FLOOR - 80, 96, 16), Box(16, FLOOR - 96, 16, 16), Box(96, FLOOR - 96, 16, 16))
IN_THE_TROUGH = EnemySpec(Box(48, FLOOR - 92, 14, 12))
# a lift high over the gap's near edge, its underside more than 50 px over the highest head
FAR_LIFT = PlatformSpec(Route(((150.0, 20.0), (150.0, 40.0))), 48.0, 8.0, 40.0)
AT_THE_EDGE = EnemySpec(Box(EDGE - 40, FLOOR - 12, 14, 12))  # walks to the gap's edge


def gap_and(width: int, enemies: tuple[EnemySpec, ...] = (),
            platforms: tuple[PlatformSpec, ...] = ()) -> Level:
    """A gap ``width`` px wide, with the trough over the start side, and enemies or lifts."""
    return level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64), *TROUGH,
                                         Box(EDGE + width, FLOOR, WIDTH - EDGE - width, 64)],
                            SPAWN, [exit_on(FLOOR)], enemies=enemies, platforms=platforms)


@pytest.mark.parametrize("extras", ["enemy", "lift", "both"])
def test_enemies_and_lifts_out_of_reach_leave_the_exact_proof_standing(extras: str) -> None:
    """An enemy that cannot leave its trough, or a lift whose whole route is high over the
    gap's near edge, is never within touching distance of any place the player can be: a gap
    one pixel past the widest is still proven impossible, with the exact bounds."""
    enemies = (IN_THE_TROUGH,) if extras in ("enemy", "both") else ()
    platforms = (FAR_LIFT,) if extras in ("lift", "both") else ()
    widest = DEFAULT_LIMITS.coyote_gap_px
    verdict = judge(gap_and(widest + 1, enemies, platforms), SMALL)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is None  # proven, not searched
    assert (f"it crosses gaps of at most {widest} px and lands on ledges at most "
            f"{DEFAULT_LIMITS.ledge_px} px high") in verdict.finding


@pytest.mark.parametrize("extras", ["enemy", "lift", "both"])
def test_the_widest_gap_beside_enemies_and_lifts_out_of_reach_is_in_the_exact_reach(
        extras: str) -> None:
    enemies = (IN_THE_TROUGH,) if extras in ("enemy", "both") else ()
    platforms = (FAR_LIFT,) if extras in ("lift", "both") else ()
    level = gap_and(DEFAULT_LIMITS.coyote_gap_px, enemies, platforms)
    exact = exact_reach(World(level))
    assert exact.touches_exit and not exact.unbounded
    assert not proven_impossible(level)


def test_a_walker_on_an_open_shelf_it_turns_back_on_leaves_the_exact_proof_standing() -> None:
    """A shelf high over the start side with no wall at either end: the cell fill lets an
    enemy walk off it and on to the gap, but a walker turns back at each end of an
    unbroken floor, so its patrol is all it can reach, far from any jump."""
    shelf = Box(16, FLOOR - 80, 96, 16)
    walker = EnemySpec(Box(48, FLOOR - 92, 14, 12))
    level = level_from_boxes(
        COLS, ROWS, [Box(0, FLOOR, EDGE, 64), shelf,
                     Box(EDGE + 77, FLOOR, WIDTH - EDGE - 77, 64)],
        SPAWN, [exit_on(FLOOR)], enemies=(walker,))
    world = World(level)
    assert patrol_span(world, 0) == Box(16 - 1.0, FLOOR - 92, 96 + 2.0, 12)
    verdict = judge(level, SMALL)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding


def walkers_on(rows: list[str], speed: float | None = None) -> World:
    """The enemies (``E``) of an ASCII map, standing on the cell's floor, at ``speed``
    (None: the default)."""
    level = level_from_ascii(rows)
    enemies = tuple(replace(e, box=e.box._replace(y=e.box.y + 16 - e.box.h), speed_px_s=speed)
                    for e in level.enemies)
    return World(replace(level, enemies=enemies))


FLOORS = {
    "a shelf": ["                ", "   E            ", "  #####         ", "                ",
                "P               ", "################"],
    "at the shelf's end": ["                ", "      E         ", "  #####         ",
                           "                ", "P               ", "################"],
    "one-way planks": ["                ", "    E           ", "  -----         ",
                       "                ", "P               ", "################"],
    "a gap a tile wide": ["                ", "   E            ", "  ###### ####   ",
                          "                ", "P               ", "################"],
    "spikes in the floor": ["                ", "  E             ", "  ####^^##      ",
                            "                ", "P               ", "################"],
    "a floor to the map's edge": ["                ", "                ", "P     E         ",
                                  "################"],
}


@pytest.mark.parametrize("floor", sorted(FLOORS))
@pytest.mark.parametrize("speed", [None, 7.0, 400.0])
def test_a_walkers_patrol_span_holds_every_place_the_game_puts_it(floor: str,
                                                                   speed: float | None) -> None:
    """Played for a minute, a walker the span bounds never leaves it (it turns back at a
    gap, and at spikes, which are no floor to it)."""
    world = walkers_on(FLOORS[floor], speed)
    spans = [patrol_span(world, number) for number in range(len(world.level.enemies))]
    assert all(span is not None for span in spans)
    for _ in range(60 * 60):
        world.step(frozenset())
        for number, span in enumerate(spans):
            enemy = world.enemy_by_number[number]
            assert span is not None and enemy.alive()
            box = enemy.box
            assert (span.left <= box.left and box.right <= span.right
                    and span.top <= box.top and box.bottom <= span.bottom), (box, span)


def floor_and_walker(floor: list[Box], walker: Box) -> World:
    return World(level_from_boxes(16, 6, floor, Box(0, 66, 12, 14), [],
                                  enemies=(EnemySpec(walker),)))


def test_a_walker_on_a_floor_it_may_leave_gets_no_patrol_span() -> None:
    """In the air; beside a step down half a pixel (it walks on to it); on a wall's side
    of its floor (the cell fill bounds those); overlapping the floor's end by less than
    its first step, taken before it looks ahead."""
    shelf = Box(32, 48, 80, 16)
    assert patrol_span(floor_and_walker([shelf], Box(48, 36, 14, 12)), 0) is not None
    assert patrol_span(floor_and_walker([shelf], Box(48, 30, 14, 12)), 0) is None
    lower = Box(112, 48.5, 32, 16)
    assert patrol_span(floor_and_walker([shelf, lower], Box(48, 36, 14, 12)), 0) is None
    wall = Box(96, 32, 16, 16)
    assert patrol_span(floor_and_walker([shelf, wall], Box(48, 36, 14, 12)), 0) is None
    assert patrol_span(floor_and_walker([shelf], Box(32 - 14 + 0.25, 36, 14, 12)), 0) is None
    assert patrol_span(floor_and_walker([shelf], Box(32 - 14 + 0.75, 36, 14, 12)), 0) is not None


def test_a_hopper_and_a_walker_going_the_other_way_get_no_patrol_span() -> None:
    world = walkers_on(FLOORS["a shelf"])
    hopper = replace(world.level, enemies=(replace(world.level.enemies[0], kind="hopper"),))
    assert patrol_span(World(hopper), 0) is None
    assert patrol_span(walkers_on(FLOORS["a shelf"], -30.0), 0) is None


def test_a_ledge_one_pixel_past_the_highest_beside_a_far_lift_is_proven_impossible() -> None:
    def with_lift(height: int) -> Level:
        return replace(ledge(height), platforms=(FAR_LIFT,))

    verdict = judge(with_lift(DEFAULT_LIMITS.ledge_px + 1), SMALL)
    assert verdict.kind is Kind.IMPOSSIBLE, verdict.finding
    assert verdict.solution is None
    assert exact_reach(World(with_lift(DEFAULT_LIMITS.ledge_px))).touches_exit


def test_an_enemy_patrolling_to_the_gaps_edge_is_named_and_the_map_not_decided() -> None:
    """A stomp on an enemy at the edge bounces the player, which the jump envelope does not
    bound: the gap one pixel past the widest is not decided, and the line names the enemy
    (a bounce at 200 px/s carries the player about 45 px: the search finds no way over)."""
    level = gap_and(DEFAULT_LIMITS.coyote_gap_px + 1, (IN_THE_TROUGH, AT_THE_EDGE))
    exact = exact_reach(World(level))
    assert exact.unbounded == ["the enemy starting at tile (9,9) (the player's jumps come "
                               "within where it can go: a stomp bounces the player)"]
    verdict = judge(level, SMALL)
    assert verdict.kind is Kind.UNDECIDED, verdict.finding
    assert "does not cover the enemy starting at tile (9,9)" in verdict.finding
    assert "tile (3,4)" not in verdict.finding  # the one in the trough is out of reach


def test_a_lift_the_player_can_reach_is_named() -> None:
    near = PlatformSpec(Route(((48.0, FLOOR - 40), (96.0, FLOOR - 40))), 32.0, 8.0, 40.0)
    exact = exact_reach(World(gap_and(DEFAULT_LIMITS.coyote_gap_px + 1, platforms=(near,))))
    assert exact.unbounded == ["the moving Platform starting at tile (3,7) (the player's "
                               "jumps come within its route: it pushes and carries)"]


def test_a_respawn_a_lift_may_move_makes_the_exact_proof_give_up() -> None:
    """A flag the player counts whose respawn place a lift's route crosses: the game puts
    the player back wherever is free when the flag counts, so the proof says so."""
    flag = Box(EDGE - 48, FLOOR - 32, 16, 32)
    lift = PlatformSpec(Route(((EDGE - 56.0, FLOOR - 20), (EDGE - 56.0, FLOOR - 100))),
                        32.0, 8.0, 40.0)
    level = level_from_boxes(COLS, ROWS, [Box(0, FLOOR, EDGE, 64),
                                          Box(EDGE + 77, FLOOR, WIDTH - EDGE - 77, 64)],
                             SPAWN, [exit_on(FLOOR)], checkpoints=(flag,), platforms=(lift,))
    (said,) = exact_reach(World(level)).unbounded
    assert said.startswith("a respawn moved by a moving Platform (the Checkpoint at tile "
                           "(9,8)")


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


def enemy_walled_in_on_a_layer_of_its_own(folder: Path) -> Path:
    """A floor with a gap five tiles wide (80 px, which the cell fill lets a jump cross),
    and high over the start a trough whose two walls are painted on a layer of their own,
    with an enemy in it: the walls keep it from ever coming down to the player."""
    rows = ["                          ", "                          ",
            "  E                       ", " ####                     ",
            "                          ", "                          ",
            "                          ", " P                    D   ",
            "###########     ##########"]
    path = write_tmx(folder, rows)
    cols = len(rows[0])
    walls = [[1 if row == 2 and col in (1, 4) else 0 for col in range(cols)]
             for row in range(len(rows))]
    data = ",\n".join(",".join(map(str, row)) for row in walls)
    layer = (f' <layer id="7" name="trough walls" width="{cols}" height="{len(rows)}">\n'
             f'  <data encoding="csv">\n{data}\n</data>\n </layer>\n')
    text = path.read_text(encoding="utf-8").replace(' <objectgroup', layer + ' <objectgroup')
    path.write_text(text, encoding="utf-8")
    return path


def test_a_layer_that_only_walls_an_enemy_in_is_not_said_to_close_the_way(
        tmp_path: Path) -> None:
    """Without the trough's walls the enemy could come down to the player, so the proof
    would say nothing; but no way to the Exit opens, so the layer is not named."""
    report = check_map(enemy_walled_in_on_a_layer_of_its_own(tmp_path), Options(effort=SMALL))
    (finding,) = [f for f in report.findings if "impossible" in f.text]
    assert ("impossible: the Exit lies outside everything the player's jumps can touch (it "
            "crosses gaps of at most 76 px") in finding.text
    assert "layer '" not in finding.text and finding.layer is None


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


def test_a_lift_is_named_just_within_touching_distance_of_the_highest_head_not_beyond(
        ) -> None:
    """Touching distance is the corner slide and 2 px more (:func:`touch_px`: the 1 px probe
    under the feet, and rounding): a lift over
    the start whose underside is that far over the highest the head gets in the game, less
    half a pixel, is named; half a pixel further up, it is left out and the proof stands."""
    world = World(gap_and(DEFAULT_LIMITS.coyote_gap_px + 1))
    highest_head = world.player.box.y
    for _ in range(120):  # a jump held from the spawn, to its top and down again
        world.step(frozenset({Action.JUMP}))
        highest_head = min(highest_head, world.player.box.y)
    margin = world.tuning.corner_correction_px + 2.0
    assert touch_px(world) == margin

    def lift_with_underside_at(y: float) -> PlatformSpec:  # a short lift, up and down
        return PlatformSpec(Route(((SPAWN.x - 8, y - 18.0), (SPAWN.x - 8, y - 8.0))),
                            32.0, 8.0, 10.0)

    def named(y: float) -> bool:
        level = gap_and(DEFAULT_LIMITS.coyote_gap_px + 1, platforms=(lift_with_underside_at(y),))
        return bool(exact_reach(World(level)).unbounded)

    assert named(highest_head - margin + 0.5)
    assert not named(highest_head - margin - 0.5)
    assert proven_impossible(gap_and(DEFAULT_LIMITS.coyote_gap_px + 1, platforms=(
        lift_with_underside_at(highest_head - margin - 0.5),)))
