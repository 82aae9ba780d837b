"""Shared test set-up: no window, no sound card, and small builders for levels."""

from __future__ import annotations

import os

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ["SDL_AUDIODRIVER"] = "dummy"
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from collections.abc import Iterator

import pygame
import pytest

from game.app.assets import Assets, load_assets


@pytest.fixture(scope="module")
def assets() -> Iterator[Assets]:
    """The game's pictures, loaded on a 320x180 display that closes after the module."""
    pygame.display.init()
    pygame.display.set_mode((320, 180))
    yield load_assets()
    pygame.display.quit()


@pytest.fixture
def display() -> Iterator[None]:
    """A 320x180 display for tests that draw the game's screens; closed afterwards."""
    pygame.display.init()
    pygame.display.set_mode((320, 180))
    yield
    pygame.display.quit()


@pytest.fixture
def lab_display() -> Iterator[None]:
    """A display, fonts and an empty event queue, for the lab's scenes."""
    pygame.display.init()
    pygame.font.init()
    pygame.display.set_mode((1, 1))
    pygame.event.clear()
    yield
    pygame.event.clear()
