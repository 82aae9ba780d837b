"""Snapshots of a world in play: save the state of a tick, step on, and come back to it.

Where it sits: beside :class:`game.sim.world.World`, for code that tries futures and keeps
the good ones (the level solver of :mod:`game.checker.solver`). Play never needs it.

What it teaches: the state of a simulation is its *mutable attributes*, nothing more. A
snapshot copies, for the world and every object that may change during a tick (every
sprite in its groups, every enemy, the camera, the contact tracker), the values of its attributes,
and for every sprite group, which sprites are in it. It copies no pictures (``Surface``\\s)
and no level data (the tile grid, the tuning): those never change in a tick and are shared.
Restoring writes the values back in place, so everything holding a reference to the world
or its sprites stays valid, and removes attributes set since (they were class defaults then,
like a platform's distance travelled before its first tick). Values are immutable (floats,
boxes, frozen records) or containers copied one level deep, so stepping on never changes a
snapshot already taken.

>>> from game.sim.level import Level
>>> from game.collision.tile_grid import TileGrid
>>> from game.collision.aabb import Box
>>> from game.sim.inputs import Action
>>> world = World(Level(Path("demo"), TileGrid(10, 10, 16, 16), Box(0, 0, 12, 14)))
>>> saved = Snapshot.of(world)
>>> for _ in range(30):
...     _ = world.step(frozenset({Action.RIGHT}))
>>> world.player.box.x > 0
True
>>> saved.restore(world)
>>> world.player.box.x, world.player.vx
(0, 0.0)
"""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path  # noqa: F401  (the doctest above uses it)
from typing import Any

import pygame

from game.sim.world import World

_SPRITE_GROUPS = "_Sprite__g"  # pygame's record of a sprite's groups: rebuilt by the groups
_CONTAINERS = (list, set, dict, deque, bytearray)


def _kept_apart(name: str, value: object) -> bool:
    """Attributes a snapshot neither copies nor restores: pictures, groups, group records."""
    return name == _SPRITE_GROUPS or isinstance(
        value, (pygame.Surface, pygame.sprite.AbstractGroup))


class _Recipe:
    """For one class, what a snapshot does with each attribute name: leave it out (a
    picture or a group), copy its value (a container), or keep the value as it is.

    Sorting names once per class, rather than looking at every value each time, made
    taking a snapshot of The Summit 2.6x cheaper and restoring one 3x cheaper (59 µs against
    153 and 33 µs against 98, each the mean of 3,000 calls; writing every thing back in one
    loop, not a call each, has since brought a restore to about 20 µs, on the same shared
    machine). An attribute keeps its kind for
    the life of the class: a name that held a container holds one later. A name first seen
    holding None is looked at again, on each snapshot, until it holds something else.
    """

    __slots__ = ("apart", "copied", "known", "unsettled")

    def __init__(self) -> None:
        self.known: set[str] = set()
        self.apart: set[str] = set()
        self.copied: set[str] = set()
        self.unsettled: set[str] = set()  # seen only as None so far

    def learn(self, state: dict[str, Any]) -> None:
        """Sort the names of ``state`` not sorted yet."""
        for name, value in state.items():
            if name in self.known and name not in self.unsettled:
                continue
            self.known.add(name)
            self.unsettled.discard(name)
            if value is None:
                self.unsettled.add(name)
            elif _kept_apart(name, value):
                self.apart.add(name)
            elif isinstance(value, _CONTAINERS):
                self.copied.add(name)


_RECIPES: dict[type, _Recipe] = {}
Members = tuple[tuple[pygame.sprite.AbstractGroup[Any], tuple[pygame.sprite.Sprite, ...]], ...]


def _recipe(thing: object, state: dict[str, Any]) -> _Recipe:
    recipe = _RECIPES.get(type(thing))
    if recipe is None:
        recipe = _RECIPES[type(thing)] = _Recipe()
    if recipe.known.issuperset(state):
        for name in recipe.unsettled:
            if state.get(name) is not None:
                break  # a name seen only holding None holds something now
        else:
            return recipe
    recipe.learn(state)
    return recipe


def state_of(thing: object) -> dict[str, Any]:
    """The attributes of ``thing`` that a tick may change, copied one level deep."""
    return _taken(thing)[1]


def put_state(thing: object, saved: dict[str, Any]) -> None:
    """Write back into ``thing`` the attributes :func:`state_of` took (``saved`` stays as
    it is, so it can be written back again)."""
    recipe = _RECIPES[type(thing)]
    _write_back(((vars(thing), saved, recipe.apart,
                  tuple(name for name in recipe.copied if name in saved)),))


# What a snapshot keeps of one thing: its attributes themselves (the ``__dict__``, written
# back in place), the values taken, the names its class keeps apart and the names of the
# values taken that are containers (copied again on the way back).
_Taken = tuple[dict[str, Any], dict[str, Any], set[str], tuple[str, ...]]


def _taken(thing: object) -> _Taken:
    state = vars(thing)
    recipe = _recipe(thing, state)
    saved = state.copy()
    for name in recipe.apart:
        saved.pop(name, None)
    if not recipe.copied:
        return state, saved, recipe.apart, ()
    copied = tuple(name for name in recipe.copied if name in saved)
    for name in copied:
        saved[name] = saved[name].copy()
    return state, saved, recipe.apart, copied


def _write_back(taken: Iterable[_Taken]) -> None:
    """Write back the values taken, thing by thing, in one loop (a restore writes back
    dozens of things: a call for each would cost as much as the writing)."""
    for current, saved, apart, copied in taken:
        current.update(saved)
        # Now ``current`` holds every name of ``saved``: if besides those it holds exactly
        # the names kept apart, no attribute was set since, and the set differences below,
        # which find such an attribute, are not needed.
        if not (len(current) == len(saved) + len(apart) and apart.isdisjoint(saved)
                and current.keys() >= apart):
            # An attribute set since the state was taken was a class default then: drop
            # it, so the default shows through again.
            for name in current.keys() - saved.keys() - apart:
                del current[name]
        for name in copied:
            current[name] = saved[name].copy()


def _changing_things(world: World, members: Members) -> list[object]:
    """The world and every object of it whose attributes may change while it plays: its
    camera and contact tracker, every enemy (alive or not) and every sprite in any of its
    groups (``members``: each group with its sprites). The list of the last world asked is
    kept, and given again while its groups hold the same sprites (most snapshots of a
    search: a coin taken or an enemy stomped changes them)."""
    for (was, camera, contacts, had), things_then in _last_things:
        if (was is world and camera is world.camera and contacts is world.contacts
                and had == members):
            return things_then
    things: dict[int, object] = {}
    for thing in (world, world.camera, world.contacts, *world.enemy_by_number.values()):
        things[id(thing)] = thing
    for _, sprites in members:
        for sprite in sprites:
            things[id(sprite)] = sprite
    listed = list(things.values())
    _last_things[:] = [((world, world.camera, world.contacts, members), listed)]
    return listed


# the last world asked, with its camera, tracker and members, and its things
_last_things: list[tuple[tuple[World, object, object, Members], list[object]]] = []


def _groups(world: World, names: set[str]) -> list[pygame.sprite.AbstractGroup[Any]]:
    """The world's groups, among its attributes ``names`` (those its recipe keeps apart),
    in the order the world holds them."""
    return [value for name, value in vars(world).items()
            if name in names and isinstance(value, pygame.sprite.AbstractGroup)]


@dataclass(frozen=True)
class Snapshot:
    """The changing state of one world at one tick."""

    attributes: tuple[_Taken, ...]
    members: Members

    @classmethod
    def of(cls, world: World) -> Snapshot:
        first = _taken(world)  # its recipe knows which of its attributes hold groups
        members = tuple((group, tuple(group.sprites())) for group in _groups(world, first[2]))
        things = _changing_things(world, members)  # the world first
        return cls((first, *(_taken(thing) for thing in things[1:])), members)

    def restore(self, world: World) -> None:
        """Put ``world`` back as it was when this snapshot was taken."""
        _write_back(self.attributes)
        for group, sprites in self.members:
            if tuple(group.sprites()) != sprites:
                group.empty()
                group.add(*sprites)
