"""The overlay's panel informs without covering: small by default, in the corner away from
the player, one key (F5) from the full detail or from nothing; the colour key on screen; the
player drawn above the outlines."""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

import pygame
import pytest

from game.app import debug_overlay
from game.app.assets import Assets
from game.app.debug_overlay import (
    CELL_COLORS,
    PANEL_KEY,
    PanelMode,
    draw_debug,
    panel_rows,
    player_on_screen,
)
from game.app.hud import HUD_BAR_H_PX, draw_hud
from game.app.render import WorldRenderer, screen_offset
from game.app.run import input_script
from game.app.window import window_scale
from game.levels import load_level
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.sim.campaign import Campaign, Outcome
from game.sim.world import Measure

ROOT = Path(__file__).resolve().parent.parent
DESKTOP = (1920, 1080)
MOST_COVERED = 0.15  # the default panel covers at most this share of the view
LEVELS = ["01-first-steps", "04-moving-parts", "06-the-summit"]
EVERY_NTH_TICK = 40


def played(level: str, assets: Assets) -> Iterator[tuple[pygame.Surface, Campaign]]:
    """Frames (world and HUD, no overlay yet) of ``level`` played by its winning script,
    every few ticks; each is yielded while its tick is the campaign's last."""
    path = ROOT / "levels" / f"{level}.tmx"
    campaign = Campaign(path, loader=lambda p: load_level(p, images=True),
                        measure=Measure(queries=True))
    script = input_script(ROOT / "tests" / "scripts" / f"{level}.txt")
    renderer = WorldRenderer(assets)
    while campaign.outcome is Outcome.RUNNING and campaign.world.level.path == path:
        campaign.tick(script.held_at(campaign.ticks))
        if campaign.ticks % EVERY_NTH_TICK == 0 and campaign.world.level.path == path:
            frame = pygame.Surface((VIEW_W_PX, VIEW_H_PX))
            renderer.draw(frame, campaign.world, campaign.ticks)
            draw_hud(frame, campaign, assets)
            yield frame, campaign


@dataclass(frozen=True)
class Shot:
    """One frame of a play with the overlay drawn on it, once for each test below."""

    ticks: int
    panel: pygame.Rect  # where the default panel went, with the window's stepping lines
    hitbox: pygame.Rect  # the player's hitbox on the screen
    hidden: tuple[tuple[int, int], ...]  # pixels of the player's picture the overlay hid
    checked: int  # pixels of the player's picture looked at
    player_at: tuple[int, int]  # where the panel thinks the player is


def shots(level: str, assets: Assets) -> list[Shot]:
    """Every few ticks of ``level``'s play: the overlay drawn as the window draws it (with
    its stepping lines) on one copy of the frame, and as a picture draws it on another; the
    second is read back for the player's picture, pixel by pixel."""
    seen = []
    for frame, campaign in played(level, assets):
        world = campaign.world
        player = world.player
        offset = screen_offset(world.camera)
        panel = draw_debug(frame.copy(), world, assets, fps=59.5, update_ms=1.25,
                           extra_lines=("frozen at tick 1234", "F2 freeze F3 step F4 slow"))
        draw_debug(frame, world, assets, fps=60.0, update_ms=0.0)
        picture = player.rect.move(-offset[0], -offset[1])
        outlines = [thing.box.to_rect().move(-offset[0], -offset[1])
                    for thing in (*world.bodies(), *world.coins, *world.exits,
                                  *world.checkpoints, *world.platforms)]
        hidden = []
        checked = 0
        for x in range(picture.w):
            for y in range(picture.h):
                spot = (picture.x + x, picture.y + y)
                if player.image.get_at((x, y)).a < 255 or not frame.get_rect().collidepoint(spot):
                    continue
                on_outline = any(box.collidepoint(spot) and (
                    spot[0] in (box.left, box.right - 1) or spot[1] in (box.top, box.bottom - 1))
                    for box in outlines)
                if frame.get_at(spot) != player.image.get_at((x, y)) and not on_outline:
                    hidden.append(spot)
                checked += 1
        seen.append(Shot(campaign.ticks, panel, player.box.to_rect().move(*(-v for v in offset)),
                         tuple(hidden), checked, player_on_screen(world)))
    return seen


@pytest.fixture(scope="module")
def shots_of(assets: Assets) -> Callable[[str], list[Shot]]:
    """:func:`shots` of a level, made once for both tests that read them."""
    return functools.cache(lambda level: shots(level, assets))


@pytest.mark.parametrize("level", LEVELS)
def test_the_default_panel_covers_at_most_15_percent_of_a_1920x1080_window_and_not_the_player(
        shots_of: Callable[[str], list[Shot]], level: str) -> None:
    scale = window_scale(DESKTOP)
    assert scale == 5  # a 1600x900 window
    view = pygame.Rect(0, 0, VIEW_W_PX * scale, VIEW_H_PX * scale)
    checked = 0
    for shot in shots_of(level):
        panel = shot.panel
        on_window = pygame.Rect(panel.x * scale, panel.y * scale, panel.w * scale,
                                panel.h * scale)
        assert view.contains(on_window)
        assert on_window.w * on_window.h <= MOST_COVERED * view.w * view.h, on_window
        assert not panel.colliderect(shot.hitbox), (level, shot.ticks, panel, shot.hitbox)
        checked += 1
    assert checked >= 5


def test_the_panel_goes_to_the_corner_diagonally_opposite_the_player(assets: Assets) -> None:
    font = assets.small_font
    view = pygame.Rect(0, 0, VIEW_W_PX, VIEW_H_PX)
    rows = ("a line", (("player", (0, 255, 0)),))
    corners = {}
    for at in ((20, 30), (300, 30), (20, 170), (300, 170)):
        corners[at] = debug_overlay.panel_rect(rows, font, view, at)
    assert corners[20, 30].bottomright == (VIEW_W_PX, VIEW_H_PX - debug_overlay.PANEL_GAP_PX)
    assert corners[300, 170].left == 0 and corners[300, 170].top > HUD_BAR_H_PX
    assert corners[300, 30].left == 0 and corners[300, 30].bottom < VIEW_H_PX
    assert corners[20, 170].right == VIEW_W_PX and corners[20, 170].top < VIEW_H_PX // 2


def words_of(rows: tuple[debug_overlay.Row, ...]) -> list[str]:
    return [row if isinstance(row, str) else " ".join(word for word, _ in row) for row in rows]


def test_f5_cycles_compact_full_hidden_and_the_full_panel_keys_every_colour(
        assets: Assets) -> None:
    frame, campaign = next(shot for i, shot in enumerate(played("01-first-steps", assets))
                           if i == 3)
    world = campaign.world
    mode, seen = PanelMode.COMPACT, []
    for _ in range(3):
        seen.append(mode)
        mode = mode.next()
    assert seen == [PanelMode.COMPACT, PanelMode.FULL, PanelMode.HIDDEN] and mode is seen[0]
    compact = panel_rows(world, 60.0, 1.0, ("running", "F2 freeze"), PanelMode.COMPACT)
    full = panel_rows(world, 60.0, 1.0, ("running", "F2 freeze"), PanelMode.FULL)
    assert panel_rows(world, 60.0, 1.0, (), PanelMode.HIDDEN) == ()
    assert len(compact) < len(full)
    assert words_of(compact)[2:4] == ["running", pygame.key.name(PANEL_KEY).upper() + " more"]
    shown = " ".join(words_of(full))
    # The key names every colour the overlay paints with, the lookups' squares included.
    for word in ["player", "enemy", "coin", "exit", "solid", "one-way", "hazard", "platform",
                 "sweep x", "y", "hit", *CELL_COLORS]:
        assert word in shown, word
    hidden = draw_debug(frame.copy(), world, assets, 60.0, 1.0, panel=PanelMode.HIDDEN)
    assert hidden.w * hidden.h == 0
    wide = draw_debug(frame.copy(), world, assets, 60.0, 1.0, panel=PanelMode.FULL)
    small = draw_debug(frame.copy(), world, assets, 60.0, 1.0, panel=PanelMode.COMPACT)
    assert wide.h > small.h


@pytest.mark.parametrize("level", LEVELS)
def test_the_player_is_drawn_above_the_outlines_only_the_hitboxes_cross_him(
        shots_of: Callable[[str], list[Shot]], level: str) -> None:
    """Every opaque pixel of the player's picture shows on top of the overlay, even where a
    bush of the foreground hid it, except where a hitbox's 1 px outline crosses it."""
    for shot in shots_of(level):
        assert shot.hidden == (), (level, shot.ticks, shot.player_at)
    assert sum(shot.checked for shot in shots_of(level)) > 0


def test_the_readme_gives_the_compact_panels_size_as_measured(assets: Assets) -> None:
    """The README's figures for the compact panel in a 1600x900 window, worked out again."""
    frame, campaign = next(iter(played("01-first-steps", assets)))
    world = campaign.world
    scale = window_scale(DESKTOP)
    window = draw_debug(frame, world, assets, 59.5, 1.25,
                        ("frozen at tick 12345", "F2 freeze F3 step F4 slow"))
    picture = draw_debug(frame, world, assets, None, 1.25)
    view = VIEW_W_PX * VIEW_H_PX

    def share(rect: pygame.Rect) -> str:
        return f"{rect.w * rect.h / view:.1%}".replace("%", " %")

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert (f"it takes {window.w * scale}x{window.h * scale} pixels, {share(window)} of the view"
            f" ({share(picture)} in the pictures below") in " ".join(readme.split())
