"""The tick's shortcuts: each one skips work only where the work would have changed nothing.

A tick skips a lookup when something cheaper already knows its answer: the triggers and the
spikes when the player's path reaches no cell that holds one, an enemy's ledge look-ahead
when a tile it knows reaches under the square ahead. These tests play every shipped level
by its winning script (once, for both shortcuts) and, on every tick, compare each shortcut
with the full test it stands for; then they count what the shortcuts saved.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from game.app.run import input_script
from game.collision.aabb import Box
from game.collision.axis_sweep import BodyMoves, Edges
from game.collision.shapes import ShapeSource, TileKind
from game.levels import LEVELS_DIR, load_level
from game.sim.enemy import LEDGE_PROBE_PX, Enemy
from game.sim.level import Level
from game.sim.pickups import TriggerCells
from game.sim.world import PLAYER_KEY, ContactKey, Measure, World, crossed

SCRIPTS = Path(__file__).parent / "scripts"
LEVELS = sorted(LEVELS_DIR.glob("0[1-6]*.tmx"))  # the first round: each idea once


@functools.cache  # a world reads its level and never changes it: one load serves every play
def level_of(path: Path) -> Level:
    return load_level(path)


def _played(level_path: Path, measure: Measure | None = None) -> Iterator[World]:
    """The level played by its winning script: the world after each tick."""
    script = input_script(SCRIPTS / f"{level_path.stem}.txt")
    world = World(level_of(level_path), measure=measure or Measure())
    last = script.events[-1].tick if script.events else 0
    for tick in range(last + 1):
        world.step(script.held_at(tick))
        yield world


def _ground_ahead_by_lookup(world: World, enemy: Enemy) -> bool:
    """What the ledge look-ahead's lookup alone says, with no shortcut."""
    x, y, w, h = enemy.box
    front = x + w if enemy.direction > 0 else x - LEDGE_PROBE_PX
    feet = y + h
    return any(entry.kind is not TileKind.HAZARD for entry in world.solids.entries_in(
        front, feet, front + LEDGE_PROBE_PX, feet + LEDGE_PROBE_PX))


def _contacts_in_full(world: World, player: BodyMoves) -> set[tuple[ContactKey, ContactKey]]:
    """The player's contacts (its path: ``player``) by testing every exit, checkpoint,
    enemy and spike cell."""
    pairs: set[tuple[ContactKey, ContactKey]] = set()
    for number, goal in enumerate(world.exits):
        if crossed(player, goal):
            pairs.add((PLAYER_KEY, ("exit", number)))
    for number, flag in enumerate(world.checkpoints):
        if crossed(player, flag):
            pairs.add((PLAYER_KEY, ("checkpoint", number)))
    for number, enemy in world.enemy_by_number.items():
        if enemy.alive() and crossed(player, enemy):
            pairs.add((PLAYER_KEY, ("enemy", number)))
    for move in (player.x, player.y):
        for entry in world.grid.entries_in(*move.path_edges):
            if entry.kind is TileKind.HAZARD:
                pairs.add((PLAYER_KEY, ("hazard", entry.shape.row * world.grid.cols
                                        + entry.shape.col)))
    return pairs


@dataclass
class Audit:
    """What a play saw when each shortcut was set beside its full test, tick by tick."""

    contacts_differ: list[tuple[int, object, object]] = field(default_factory=list)
    coins_on_path: list[int] = field(default_factory=list)  # ticks with one left in play
    touched: int = 0  # ticks on which the player touched something
    ledge_differ: list[tuple[int, int]] = field(default_factory=list)  # (tick, enemy)
    ledge_checked: int = 0


@functools.cache  # one play of each level serves both tests below
def audit(level_path: Path) -> Audit:
    """Play ``level_path`` by its winning script; before each tick, ask every grounded enemy's
    ledge look-ahead and its lookup alone; inside each tick, make step 7 as the tick makes
    it and, beside it, the full tests at the same moment."""
    script = input_script(SCRIPTS / f"{level_path.stem}.txt")
    world = World(level_of(level_path))
    contacts_of_tick = world._player_contacts
    seen = Audit()
    tick = 0

    def checked(path: BodyMoves, edges: Edges, near_trigger: bool, hazards: ShapeSource,
                ) -> set[tuple[ContactKey, ContactKey]]:
        found = contacts_of_tick(path, edges, near_trigger, hazards)
        full = _contacts_in_full(world, path)
        if found != full:
            seen.contacts_differ.append((tick, found, full))
        # No coin left in play lies on the path (step 6, just before, took them).
        if any(crossed(path, coin) for coin in world.coins):
            seen.coins_on_path.append(tick)
        seen.touched += bool(found)
        return found

    world._player_contacts = checked  # type: ignore[method-assign]
    for tick in range((script.events[-1].tick if script.events else 0) + 1):
        for number, enemy in enumerate(world.enemies):
            if enemy.on_ground:
                remembered = enemy.ground_seen
                shortcut = enemy._ground_ahead(world.solids)
                enemy.ground_seen = remembered  # asking leaves the play as it would have been
                if shortcut != _ground_ahead_by_lookup(world, enemy):
                    seen.ledge_differ.append((tick, number))
                seen.ledge_checked += 1
        world.step(script.held_at(tick))
    return seen


@pytest.mark.parametrize("level_path", LEVELS, ids=lambda p: p.stem)
def test_the_trigger_and_spike_shortcuts_miss_no_contact(level_path: Path) -> None:
    seen = audit(level_path)
    assert seen.contacts_differ == []
    assert seen.coins_on_path == []
    assert seen.touched > 0   # every winning run touches something: at least the exit


@pytest.mark.parametrize("level_path", [p for p in LEVELS if level_of(p).enemies],
                         ids=lambda p: p.stem)
def test_the_ledge_look_ahead_answers_as_its_lookup_would(level_path: Path) -> None:
    seen = audit(level_path)
    assert seen.ledge_differ == []
    assert seen.ledge_checked > 100


def _lookups(world: World, purpose: str) -> int:
    return sum(query.purpose == purpose for query in world.query_log.queries)


def test_the_shortcuts_skip_most_lookups_on_the_summit() -> None:
    """Counted on the largest level: the look-ahead and spike lookups a tick no longer makes."""
    level_path = LEVELS_DIR / "06-the-summit.tmx"
    ledge = hazard = grounded_enemy_ticks = ticks = 0
    for world in _played(level_path, Measure(queries=True)):
        ticks += 1
        ledge += _lookups(world, "ledge look-ahead")
        hazard += _lookups(world, "hazards")
        grounded_enemy_ticks += sum(enemy.on_ground for enemy in world.enemies)
    assert ticks > 1000
    assert ledge < grounded_enemy_ticks / 10     # was one lookup per grounded enemy a tick
    assert hazard < ticks / 2                    # was two lookups every tick


@given(st.tuples(*[st.floats(-100, 100)] * 2, *[st.floats(0.001, 60)] * 2),
       st.tuples(*[st.floats(-100, 100)] * 2, *[st.floats(0.001, 60)] * 2),
       st.sampled_from([16, 12, 7]))
def test_a_path_that_overlaps_a_trigger_always_reaches_its_cells(
        trigger: tuple[float, float, float, float], path: tuple[float, float, float, float],
        tile_px: int) -> None:
    cells = TriggerCells(tile_px, tile_px)
    cells.file(Box(*trigger))
    x, y, w, h = path
    if Box(*path).overlaps(Box(*trigger)):
        assert cells.reached_by(x, y, x + w, y + h)
