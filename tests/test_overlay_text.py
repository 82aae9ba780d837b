"""The overlay's panel says only what was measured: no frame rate for a picture without one."""

from __future__ import annotations

import pygame
import pytest

from game.app import debug_overlay
from game.app.frame import render_frame
from game.app.hud import Color
from game.levels import FIRST_LEVEL, load_level
from game.sim.campaign import Campaign


@pytest.mark.parametrize(("fps", "first_line"), [(None, "no window  tick"),
                                                  (59.5, "FPS 59.5  tick")])
def test_the_panel_shows_a_frame_rate_only_when_a_window_measured_one(
        monkeypatch: pytest.MonkeyPatch, fps: float | None, first_line: str) -> None:
    pygame.display.init()
    pygame.display.set_mode((320, 180))
    shown: list[str] = []
    face = debug_overlay._line_face

    def record(font: pygame.font.Font, line: str,
               color: Color = debug_overlay.PANEL_TEXT) -> pygame.Surface:
        shown.append(line)
        return face(font, line, color)

    monkeypatch.setattr(debug_overlay, "_line_face", record)
    campaign = Campaign(FIRST_LEVEL, loader=lambda p: load_level(p, images=True))
    campaign.tick(frozenset())
    render_frame(campaign, debug=True, fps=fps)
    assert shown[0].startswith(first_line)
    assert not any("FPS 0.0" in line for line in shown)
