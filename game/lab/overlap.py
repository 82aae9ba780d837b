"""Scene ``overlap``: test the overlap. Colliding, touching and apart are three answers.

What it shows: a red player and a blue wall, and the "Collision status" the reference gives:
**colliding** when :meth:`~game.collision.aabb.Box.overlaps` (strict inequalities, like
``Rect.colliderect``) says they share interior, **touching** when
:meth:`~game.collision.aabb.Box.touches` says they only meet along an edge or at a corner, and
**apart** otherwise. The player starts flush against the wall: touching, not colliding. Z turns
the player into a zero-width box, which overlaps nothing, not even from inside the wall.
"""

from __future__ import annotations

import pygame

from game.collision.aabb import Box
from game.lab import canvas
from game.lab.scene import AREA, Layer, Scene

WALL = Box(AREA.x + 330, AREA.y + 110, 60, 260)  # where the wall starts
PLAYER_W_PX, PLAYER_H_PX = 48.0, 72.0
NUDGES = {pygame.K_LEFT: (-1.0, 0.0), pygame.K_RIGHT: (1.0, 0.0),
          pygame.K_UP: (0.0, -1.0), pygame.K_DOWN: (0.0, 1.0)}


def collision_status(player: Box, wall: Box) -> str:
    """The reference's three answers, in words."""
    if player.overlaps(wall):
        return "colliding"
    if player.touches(wall):
        return "touching"
    return "apart"


class Overlap(Scene):
    name = "overlap"
    title = "test the overlap: colliding, touching or apart"
    keys_help = "drag player or wall; arrows nudge 1 px; Z zero-width player"

    def reset(self) -> None:
        self.pos = {"wall": (WALL.x, WALL.y),
                    "player": (WALL.left - PLAYER_W_PX, AREA.y + 200)}  # flush: touching
        self.zero_width = False

    def player(self) -> Box:
        x, y = self.pos["player"]
        return Box(x, y, 0.0 if self.zero_width else PLAYER_W_PX, PLAYER_H_PX)

    def wall(self) -> Box:
        return WALL._replace(x=self.pos["wall"][0], y=self.pos["wall"][1])

    def grab_boxes(self) -> dict[str, Box]:
        x, y = self.pos["player"]
        return {"wall": self.wall(), "player": Box(x - 4, y, PLAYER_W_PX + 8, PLAYER_H_PX)}

    def on_key(self, key: int) -> None:
        if key in NUDGES:
            dx, dy = NUDGES[key]
            x, y = self.pos["player"]
            self.pos["player"] = (x + dx, y + dy)
        elif key == pygame.K_z:
            self.zero_width = not self.zero_width

    def refresh(self) -> None:
        player, wall = self.player(), self.wall()
        self.answer = collision_status(player, wall)
        self.lines = [
            f"Collision status: {self.answer}",
            "",
            f"player  Box({player.x:.1f}, {player.y:.1f}, {player.w:g}, {player.h:g})",
            f"wall    Box({wall.x:g}, {wall.y:g}, {wall.w:g}, {wall.h:g})",
            f"Box.overlaps: {player.overlaps(wall)}",
            f"Box.touches:  {player.touches(wall)}",
            f"penetration:  {player.penetration(wall):g} px",
            f"Rect.colliderect: {player.to_rect().colliderect(wall.to_rect())}",
            "",
            "right edge = wall's left edge:",
            "  touching, not colliding (strict <)",
        ]
        if self.zero_width:
            self.lines.append("zero width: overlaps nothing")

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        player, wall = self.player(), self.wall()
        color = {"colliding": canvas.WRONG, "touching": canvas.EXACT, "apart": canvas.DIM}
        if Layer.SHAPES in layers:
            canvas.box(surface, wall, canvas.STILL)
            canvas.box(surface, player, canvas.MOVER)
        if Layer.CONTACTS in layers:
            canvas.box(surface, player, color[self.answer], 3)
        canvas.text(surface, f"Collision Status: {self.answer}", (AREA.x + 16, AREA.y + 16),
                    color[self.answer], canvas.TITLE_PT)
