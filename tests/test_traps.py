"""Python's and pygame's own traps, shown: these tests pin how the libraries behave, not this
code. The README's pitfalls table cites them as the trap itself, beside the tests of this
code that fail if the game ever falls into it."""

from __future__ import annotations

import math

import pygame

from game.collision.aabb import Box
from game.sim.sprite import BoxSprite


def test_python_trap_removing_from_a_list_while_iterating_it_skips_the_next_item() -> None:
    coins = ["a", "b", "c", "d"]
    visited = []
    for coin in coins:
        visited.append(coin)
        coins.remove(coin)  # every coin is taken... or so it seems
    assert visited == ["a", "c"]  # the item after each removed one was never looked at
    assert coins == ["b", "d"]


def test_pygame_group_iterates_over_a_copy_so_killing_inside_the_loop_is_safe() -> None:
    group: pygame.sprite.Group[BoxSprite] = pygame.sprite.Group(
        BoxSprite(Box(x, 0, 1, 1)) for x in range(4))
    visited = 0
    for sprite in group:
        visited += 1
        sprite.kill()
    assert visited == 4 and len(group) == 0


def test_pygame_trap_rect_truncates_float_coordinates_towards_zero() -> None:
    assert pygame.Rect(-0.7, 0, 1, 1).x == 0  # the box starts left of 0, the Rect at 0
    rect = pygame.Rect(0, 0, 1, 1)
    for _ in range(10):
        rect.x += 0.4  # type: ignore[assignment]  # what pygame allows, and drops
    assert rect.x == 0


def test_pygame_trap_rect_turns_nan_into_the_smallest_int_silently() -> None:
    assert pygame.Rect(math.nan, 0, 1, 1).x == -(2**31)
    assert pygame.Rect(math.inf, 0, 1, 1).x == -(2**31)


def test_pygame_trap_rect_wraps_integers_past_32_bits_silently() -> None:
    assert pygame.Rect(2**32 + 5, 0, 1, 1).x == 5
    assert pygame.Rect(2**31, 0, 1, 1).x == -(2**31)
