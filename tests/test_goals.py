"""Goals to chase: a level's target time and its medal (given at the target, not a tick
over), coins shown as "n of N" in the level select and the tally, and the assists: no
damage in the simulation, and an assisted finish marked and never kept as a best time."""

from __future__ import annotations

from pathlib import Path

import pytest

from game.app.banner import ASSISTED, MEDAL_WON, tally_lines
from game.app.goals import earns_medal, target_ticks
from game.app.menus import campaign_levels, level_entries
from game.app.saves import Attempt, Finish, Progress
from game.app.screens import level_row_values, win_rows
from game.levels import FIRST_LEVEL, LevelError, load_level
from game.sim.campaign import Campaign, LevelResult
from game.sim.inputs import NOTHING, Action
from game.sim.world import EventKind, World
from tests.maps import level_from_ascii, write_tmx

FLOOR_TO_EXIT = ["            ", " P        D ", "############"]


def test_a_map_s_target_seconds_is_read_by_the_loader_and_a_map_without_it_has_none(
        tmp_path: Path) -> None:
    with_target = write_tmx(tmp_path, FLOOR_TO_EXIT, "a.tmx",
                            {"target_seconds": ("float", 10.1)})
    without = write_tmx(tmp_path, FLOOR_TO_EXIT, "b.tmx")
    assert target_ticks(load_level(with_target, images=False).properties) == 606
    assert target_ticks(load_level(without, images=False).properties) is None
    bad = write_tmx(tmp_path, FLOOR_TO_EXIT, "c.tmx", {"target_seconds": ("float", -3)})
    with pytest.raises(LevelError, match="map property 'target_seconds'"):
        load_level(bad, images=False)


def test_the_medal_is_given_at_the_target_time_and_not_one_tick_over() -> None:
    target = target_ticks({"target_seconds": 12.5})  # 750 ticks
    assert target == 750
    assert earns_medal(750, target) and not earns_medal(751, target)
    assert not earns_medal(750, target, assisted=True)
    result = LevelResult(Path("a.tmx"), "A", 750, 1, 3, 0, 0, 1)
    assert tally_lines(result, None, target)[-1] == ("Target", f"12.50 s {MEDAL_WON}")
    late = LevelResult(Path("a.tmx"), "A", 751, 1, 3, 0, 0, 1)
    assert tally_lines(late, None, target)[-1] == ("Target", "12.50 s")


def test_the_level_select_shows_coins_as_n_of_n_and_a_medal_for_a_best_within_target(
        tmp_path: Path) -> None:
    first = write_tmx(tmp_path, ["            ", " P C C C  D ", "############"], "a.tmx",
                      {"target_seconds": ("float", 2.0)})
    levels = campaign_levels(first)
    assert levels[0].coins_total == 3
    progress = Progress()
    assert [level_row_values(e)[1] for e in level_entries(levels, progress)] == ["\u2014 of 3"]
    progress.complete_level("a.tmx", 120, 2, None)
    entry = level_entries(levels, progress)[0]
    assert level_row_values(entry) == ("2.00 s", "2 of 3") and entry.medal
    progress.best_ticks["a.tmx"] = 121
    assert not level_entries(levels, progress)[0].medal


def test_the_shipped_campaign_lists_each_level_s_coins_of_its_total() -> None:
    levels = campaign_levels(FIRST_LEVEL)
    totals = [len(load_level(info.path, images=False).coins) for info in levels]
    assert [info.coins_total for info in levels] == totals and sum(totals) > 0


def test_the_tally_shows_coins_and_stomps_of_their_totals() -> None:
    result = LevelResult(Path("a.tmx"), "A", 900, 9, 12, 1, 2, 14)
    lines = dict(tally_lines(result, None))
    assert (lines["Coins"], lines["Stomps"]) == ("9 of 12", "1 of 2")


def _touching_an_enemy(no_damage: bool) -> tuple[World, list[EventKind]]:
    world = World(level_from_ascii(["          ", " P E      ", "##########"]),
                  no_damage=no_damage)
    kinds = [event.kind for _ in range(60) for event in world.step(frozenset({Action.RIGHT}))]
    return world, kinds


def test_no_damage_lets_the_player_walk_through_an_enemy_and_spikes_unhurt() -> None:
    _, hurt = _touching_an_enemy(no_damage=False)
    assert EventKind.HURT in hurt  # the same walk without the assist costs a life
    world, kinds = _touching_an_enemy(no_damage=True)
    assert EventKind.HURT not in kinds and world.player.box.x > 4 * 16
    for no_damage in (False, True):  # standing in spikes: hurt without the assist only
        spikes = World(level_from_ascii(["      ", " P    ", " ^^^^ ", "######"]),
                       no_damage=no_damage)
        hurt = [event.kind for _ in range(60) for event in spikes.step(NOTHING)
                if event.kind is EventKind.HURT]
        assert bool(hurt) is not no_damage


def test_no_damage_makes_a_fall_into_the_void_a_free_respawn_the_same_every_run() -> None:
    pit = level_from_ascii(["       ", " P     ", "##   ##"])

    def fall() -> tuple[int, int, list[tuple[float, float]]]:
        campaign = Campaign(Path("pit.tmx"), loader=lambda _: pit, no_damage=True)
        places = []
        for _ in range(120):
            campaign.tick(frozenset({Action.RIGHT}) if campaign.ticks < 20 else NOTHING)
            places.append((campaign.world.player.box.x, campaign.world.player.box.y))
        return campaign.lives, campaign.deaths, places

    lives, deaths, places = fall()
    assert (lives, deaths) == (Campaign(Path("pit.tmx"), loader=lambda _: pit).lives, 0)
    assert any(y < 2 * 16 for _, y in places[40:])  # back at the spawn after the fall
    assert fall() == (lives, deaths, places)


def test_an_assisted_finish_is_marked_unlocks_the_next_level_and_sets_no_best_time() -> None:
    level = level_from_ascii(["          ", " P      D ", "##########"])
    campaign = Campaign(Path("a.tmx"), loader=lambda _: level)
    attempt = Attempt()
    campaign.set_assist(no_damage=False, slowed=True)  # the game played at less than 100 %
    campaign.set_assist(no_damage=False, slowed=False)  # once on in a level marks it
    finish = None
    while finish is None and campaign.ticks < 600:
        attempt.before_tick(campaign)
        finish = attempt.after_tick(campaign, campaign.tick(frozenset({Action.RIGHT})))
    assert finish is not None and finish.assisted and campaign.results[-1].assisted
    progress = Progress()
    progress.record(finish._replace(next_level="b.tmx"))
    assert progress.best_ticks == {} and progress.unlocked == {"b.tmx"}
    progress.record(Finish("a.tmx", 900, 0, None))
    progress.record(Finish("a.tmx", 100, 0, None, assisted=True))
    assert progress.best_ticks == {"a.tmx": 900}
    assert tally_lines(campaign.results[-1], 900, 10_000)[-2:] == [
        ("Best", ASSISTED), ("Target", "166.67 s")]
    assert win_rows(campaign)[0][0].endswith("(assist)")


def test_a_level_restarted_with_the_assists_off_is_not_marked() -> None:
    level = level_from_ascii(["          ", " P      D ", "##########"])
    campaign = Campaign(Path("a.tmx"), loader=lambda _: level, no_damage=True)
    campaign.set_assist(no_damage=False, slowed=False)
    campaign.restart_level()
    while not campaign.results and campaign.ticks < 600:
        campaign.tick(frozenset({Action.RIGHT}))
    assert campaign.results and not campaign.results[-1].assisted
