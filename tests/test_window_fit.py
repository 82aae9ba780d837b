"""The window's size: the largest whole-number scale of 320x180 that leaves the desktop room."""

from __future__ import annotations

import pygame
import pytest

from game.app.window import DESKTOP_SHARE_PERCENT, fit_window, window_scale
from game.sim.camera import VIEW_H_PX, VIEW_W_PX


@pytest.mark.parametrize(("desktop", "window"), [
    ((1920, 1080), (1600, 900)),
    ((1280, 720), (960, 540)),
    ((2560, 1440), (2240, 1260)),
])
def test_the_window_is_the_largest_whole_scale_inside_ninety_percent_of_the_desktop(
        desktop: tuple[int, int], window: tuple[int, int]) -> None:
    scale = window_scale(desktop)
    assert (VIEW_W_PX * scale, VIEW_H_PX * scale) == window
    for size, side in zip(window, desktop, strict=True):
        assert size * 100 <= side * DESKTOP_SHARE_PERCENT < side * 100  # room is left
    bigger = (VIEW_W_PX * (scale + 1), VIEW_H_PX * (scale + 1))
    assert any(size * 100 > side * DESKTOP_SHARE_PERCENT
               for size, side in zip(bigger, desktop, strict=True))


def test_a_desktop_smaller_than_the_game_still_gets_a_window() -> None:
    assert window_scale((300, 200)) == 1


def test_fitting_sizes_the_window_to_its_scale_of_the_desktop() -> None:
    from pygame._sdl2.video import Window

    pygame.display.quit()  # a scaled window is made afresh, as the game's own is
    pygame.display.init()
    pygame.display.set_mode((VIEW_W_PX, VIEW_H_PX), pygame.SCALED | pygame.RESIZABLE)
    window = Window.from_display_module()
    fit_window(window)
    scale = window_scale(pygame.display.get_desktop_sizes()[window.display_index])
    assert tuple(window.size) == (VIEW_W_PX * scale, VIEW_H_PX * scale)
    pygame.display.quit()
