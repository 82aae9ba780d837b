"""The contact tracker reports when a touch starts and ends, once each, not every tick."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from game.collision.contacts import Change, ContactTracker
from game.demos.crates import CrateScene, CrateTuning


def test_a_pair_touching_for_100_ticks_gives_exactly_one_start_and_one_end() -> None:
    tracker: ContactTracker[str] = ContactTracker()
    tracker.update(set())
    for _ in range(100):
        tracker.update({("crate", "floor")})
    tracker.update(set())
    tracker.update(set())
    assert [(e.tick, e.pair, e.change) for e in tracker.log] == [
        (2, ("crate", "floor"), Change.STARTED),
        (102, ("crate", "floor"), Change.ENDED),
    ]


def test_either_spelling_of_a_pair_is_the_same_contact() -> None:
    tracker: ContactTracker[int] = ContactTracker()
    tracker.update({(1, 2)})
    changes = tracker.update({(2, 1)})
    assert not changes.started and not changes.ended
    assert tracker.touching == {(1, 2)}


def test_pairs_start_and_end_independently() -> None:
    tracker: ContactTracker[int] = ContactTracker()
    tracker.update({(1, 2)})
    changes = tracker.update({(1, 2), (3, 4)})
    assert changes.started == {(3, 4)} and not changes.ended
    changes = tracker.update({(3, 4)})
    assert changes.ended == {(1, 2)} and not changes.started


def test_the_log_keeps_only_the_most_recent_events() -> None:
    tracker: ContactTracker[int] = ContactTracker(log_size=4)
    for tick in range(10):
        tracker.update({(tick, tick + 100)})   # one ends and one starts every tick
    assert len(tracker.log) == 4
    assert str(tracker.log[-1]) == "tick 10: (9, 109) started"
    assert str(tracker.log[-2]) == "tick 10: (8, 108) ended"


@settings(max_examples=60, deadline=None)
@given(ticks=st.lists(st.frozensets(st.sampled_from([(0, 1), (0, 2), (1, 2)])), max_size=60))
def test_each_run_of_touching_ticks_gives_one_start_and_one_end(
        ticks: list[frozenset[tuple[int, int]]]) -> None:
    tracker: ContactTracker[int] = ContactTracker(log_size=1000)
    for touching in [*ticks, frozenset()]:
        tracker.update(touching)
    for pair in [(0, 1), (0, 2), (1, 2)]:
        runs = sum(1 for i, now in enumerate(ticks)
                   if pair in now and (i == 0 or pair not in ticks[i - 1]))
        events = [e.change for e in tracker.log if e.pair == pair]
        assert events == [Change.STARTED, Change.ENDED] * runs


def test_the_crate_scene_reports_each_collision_starting_and_ending() -> None:
    scene = CrateScene.random(2, CrateTuning(crate_count=30))
    started = ended = 0
    for _ in range(300):
        changes = scene.step(1 / 60).changes
        started += len(changes.started)
        ended += len(changes.ended)
    assert scene.contacts.tick == 300
    assert started > 0
    assert started - ended == len(scene.contacts.touching)
