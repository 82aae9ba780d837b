"""A frame of play stays cheap: what does not change between frames is not made again, and
what is drawn stays exactly what was drawn before (``python -m game.bench.window`` measures
the cost; these tests count the work and compare the pixels)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pygame
import pytest

from game.app import hud, menus
from game.app import window as window_module
from game.app.assets import Assets
from game.app.cli import parser
from game.app.render import WorldRenderer
from game.app.run import Run, input_script
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.world import World

ROOT = Path(__file__).resolve().parent.parent
SCRIPT = ROOT / "tests" / "scripts" / "01-first-steps.txt"
STILL_FRAMES = 30


def test_the_backdrop_is_painted_once_for_a_still_camera_and_frames_match_fresh_ones(
        display: None, assets: Assets, monkeypatch: pytest.MonkeyPatch) -> None:
    painted: list[int] = []
    paint = WorldRenderer._paint_sky

    def counted(self: WorldRenderer, target: pygame.Surface, world: World) -> None:
        painted.append(campaign.ticks)
        paint(self, target, world)

    monkeypatch.setattr(WorldRenderer, "_paint_sky", counted)
    screen = pygame.display.get_surface()
    campaign = Campaign(FIRST_LEVEL, loader=lambda path: load_level(path, images=True))
    kept = WorldRenderer(assets)
    for _ in range(STILL_FRAMES):
        kept.draw(screen, campaign.world, 0)
    assert len(painted) == 1
    script = input_script(SCRIPT)  # the winning run: the camera scrolls, frames must not lag
    while campaign.outcome is Outcome.RUNNING and campaign.levels_completed == 0:
        campaign.tick(script.held_at(campaign.ticks))
        kept.draw(screen, campaign.world, campaign.ticks)
        if campaign.ticks % 25 == 0:
            cached = pygame.image.tobytes(screen, "RGB")
            WorldRenderer(assets).draw(screen, campaign.world, campaign.ticks)
            assert cached == pygame.image.tobytes(screen, "RGB"), campaign.ticks
    assert STILL_FRAMES < len(painted) < campaign.ticks  # again only when the camera moved


def ringed_the_old_way(target: pygame.Surface, font: pygame.font.Font, text: str,
                       pos: tuple[int, int]) -> None:
    """Outlined text as the eight outline blits and the text, straight onto ``target``."""
    face = font.render(text, True, hud.TEXT_COLOR)
    edge = font.render(text, True, hud.OUTLINE_COLOR)
    rect = face.get_rect(topleft=pos)
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            if dx or dy:
                target.blit(edge, rect.move(dx, dy))
    target.blit(face, rect)


def test_the_hud_puts_each_outlined_text_together_once_and_draws_what_it_drew_before(
        display: None, assets: Assets) -> None:
    screen = pygame.display.get_surface()
    campaign = Campaign(FIRST_LEVEL, loader=lambda path: load_level(path, images=True))
    hud.outlined_text.cache_clear()
    for _ in range(STILL_FRAMES):
        shown = hud.draw_hud(screen, campaign, assets)
    assert hud.outlined_text.cache_info().misses == len(shown)  # coins, score, time, title
    for font in (assets.font, assets.big_font):
        for x in range(0, 320, 40):  # over stripes, so every outline pixel shows
            screen.fill((255, 0, 0) if x % 80 else (0, 90, 0), (x, 0, 40, 180))
        hud.draw_text(screen, font, "Level 7: Höhe!", (30, 40))
        drawn = pygame.image.tobytes(screen, "RGB")
        ringed_the_old_way(screen, font, "Level 7: Höhe!", (30, 40))
        assert drawn == pygame.image.tobytes(screen, "RGB")


class SteadyClock:
    """A clock whose every frame lasts 1/60 s, so the frames run without waiting."""

    def tick(self, framerate: int = 0) -> int:
        return 17

    def get_fps(self) -> float:
        return 60.0


def test_playing_builds_the_level_select_rows_only_off_the_playing_screen(
        display: None, monkeypatch: pytest.MonkeyPatch) -> None:
    built: list[int] = []
    entries = menus.level_entries

    def counted(*args: Any) -> Any:
        built.append(1)
        return entries(*args)

    monkeypatch.setattr("game.app.window.level_entries", counted)
    run = Run(Campaign(FIRST_LEVEL, loader=lambda path: load_level(path, images=True)), None,
              parser().parse_args(["--level", str(FIRST_LEVEL), "--ticks", "1000000"]))
    game = window_module.GameWindow(run)
    game.clock = SteadyClock()  # type: ignore[assignment]
    for _ in range(STILL_FRAMES):
        assert game.one_frame() is None
    assert len(built) == 1 and run.campaign.ticks >= STILL_FRAMES  # the one when it opened
