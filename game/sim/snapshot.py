"""Snapshots of a world in play: save the state of a tick, step on, and come back to it.

Where it sits: beside :class:`game.sim.world.World`, for code that tries futures and keeps
the good ones (the level solver of :mod:`game.levels.solver`). Play never needs it.

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

import copy
from collections import deque
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


def _attributes(thing: object) -> dict[str, Any]:
    """The attributes of ``thing`` that a tick may change, copied one level deep."""
    return {name: copy.copy(value) if isinstance(value, _CONTAINERS) else value
            for name, value in vars(thing).items() if not _kept_apart(name, value)}


def _changing_things(world: World) -> list[object]:
    """The world and every object of it whose attributes may change while it plays: its
    camera and contact tracker, every enemy (alive or not) and every sprite in any
    of its groups."""
    things: dict[int, object] = {}
    for thing in (world, world.camera, world.contacts,
                  *world.enemy_by_number.values(), *_groups(world)):
        things.setdefault(id(thing), thing)
    for group in _groups(world):
        for sprite in group.sprites():
            things.setdefault(id(sprite), sprite)
    return [thing for thing in things.values()
            if not isinstance(thing, pygame.sprite.AbstractGroup)]


def _groups(world: World) -> list[pygame.sprite.AbstractGroup[Any]]:
    return [value for value in vars(world).values()
            if isinstance(value, pygame.sprite.AbstractGroup)]


@dataclass(frozen=True)
class Snapshot:
    """The changing state of one world at one tick."""

    attributes: tuple[tuple[object, dict[str, Any]], ...]
    members: tuple[tuple[pygame.sprite.AbstractGroup[Any], tuple[pygame.sprite.Sprite, ...]],
                   ...]

    @classmethod
    def of(cls, world: World) -> Snapshot:
        groups = _groups(world)
        return cls(tuple((thing, _attributes(thing)) for thing in _changing_things(world)),
                   tuple((group, tuple(group.sprites())) for group in groups))

    def restore(self, world: World) -> None:
        """Put ``world`` back as it was when this snapshot was taken."""
        for thing, saved in self.attributes:
            current = vars(thing)
            # An attribute set since the snapshot was a class default then: drop it, so the
            # default shows through again.
            for name in [name for name, value in current.items()
                         if name not in saved and not _kept_apart(name, value)]:
                del current[name]
            current.update({name: copy.copy(value) if isinstance(value, _CONTAINERS)
                            else value for name, value in saved.items()})
        for group, sprites in self.members:
            if tuple(group.sprites()) != sprites:
                group.empty()
                group.add(*sprites)
