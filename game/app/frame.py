"""One frame of play: the world, the ghost, the HUD and, when on, the debug overlay, in order.

Where it sits: in the app, below :mod:`game.app.window` and :mod:`game.app.run`, which both
draw frames with it (the window every frame, a headless run once for ``--screenshot``).
"""

from __future__ import annotations

from collections.abc import Sequence

import pygame

from game.app.assets import Assets, load_assets
from game.app.debug_overlay import PanelMode, draw_debug
from game.app.ghosts import Replay, draw_ghost
from game.app.hud import draw_hud
from game.app.render import WorldRenderer
from game.sim.campaign import Campaign
from game.sim.world import World


def render_frame(campaign: Campaign, *, debug: bool, assets: Assets | None = None,
                 renderer: WorldRenderer | None = None, frame: int = 0, fps: float | None = None,
                 update_ms: float = 0.0, world: World | None = None,
                 debug_lines: Sequence[str] = (), panel: PanelMode = PanelMode.COMPACT,
                 timer: bool = True, ghost: Replay | None = None) -> pygame.Surface:
    """Draw the current state of play on the display surface and return it: the campaign's
    world, or ``world`` (a level just finished, still on screen under its banner).

    A window passes the same ``renderer`` every frame, so its caches last; without one, a
    renderer is made for this frame alone (a screenshot). ``panel`` is how much of the
    overlay's panel shows (F5 in the window). ``timer``: the HUD shows the level's time (the
    player's setting). ``ghost``: the best run's replay, drawn see-through over the world.
    """
    target = pygame.display.get_surface()
    if renderer is None:
        renderer = WorldRenderer(assets or load_assets())
    assets = renderer.assets
    world = world or campaign.world
    renderer.draw(target, world, frame or campaign.ticks)
    if ghost is not None:
        draw_ghost(target, assets, ghost, world.camera)
    draw_hud(target, campaign, assets, world, timer=timer)
    if debug:
        draw_debug(target, world, assets, fps, update_ms, debug_lines, panel)
    return target
