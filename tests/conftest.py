"""Shared test set-up: no window, no sound card, a collector that leaves the collected tests
alone, and small builders for levels."""

from __future__ import annotations

import gc
import os

os.environ["SDL_VIDEODRIVER"] = "dummy"
os.environ["SDL_AUDIODRIVER"] = "dummy"
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")

from collections.abc import Iterator

import pygame
import pytest

from game.app.assets import Assets, load_assets


def pytest_collection_finish(session: pytest.Session) -> None:
    """Once every test is collected, move what collecting made (the modules, the tests and
    their parameters: objects that live to the end of the run) out of the garbage collector's
    reach with :func:`gc.freeze`. A full collection then walks only what the tests themselves
    made, not the whole suite again each time; the bench's own ``gc.collect()`` before each
    timing is one of them."""
    gc.collect()
    gc.freeze()


@pytest.hookimpl(trylast=True)  # after the module's fixtures are torn down
def pytest_runtest_teardown(item: pytest.Item, nextitem: pytest.Item | None) -> None:
    """After a module's last test, the same for what its tests left alive (the caches that
    serve later modules too, such as the campaign's play and the shipped levels' fills)."""
    if nextitem is None or getattr(nextitem, "module", None) is not getattr(item, "module", None):
        gc.collect()
        gc.freeze()


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
