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
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Control, Layer, Scene

WALL = Box(AREA.x + 270, AREA.y + 80, 60, 240)  # where the wall starts
PLAYER_W_PX, PLAYER_H_PX = 48.0, 72.0
NUDGES = {pygame.K_LEFT: (-1.0, 0.0), pygame.K_RIGHT: (1.0, 0.0),
          pygame.K_UP: (0.0, -1.0), pygame.K_DOWN: (0.0, 1.0)}
NUDGE_KEYS = tuple(NUDGES)


def edge_gaps(player: Box, wall: Box) -> tuple[float, float]:
    """How far apart the boxes are along x and along y: positive a gap, zero edges that
    meet, negative an overlap that deep.

    >>> edge_gaps(Box(0, 0, 10, 10), Box(10, 5, 10, 10))
    (0, -5)
    """
    return (max(wall.left - player.right, player.left - wall.right),
            max(wall.top - player.bottom, player.top - wall.bottom))


def edge_words(player: Box, wall: Box) -> list[str]:
    """What the edges say about the answer, worked out from the two boxes as they are."""
    gap_x, gap_y = edge_gaps(player, wall)
    if player.w <= 0 or player.h <= 0:
        return ["a box with no width or height has no inside:",
                "  it overlaps nothing (strict <)"]
    if gap_x > 0 or gap_y > 0:
        axis, gap = ("x", gap_x) if gap_x > 0 else ("y", gap_y)
        return [f"a gap of {gap:g} px along {axis}:", "  apart"]
    meeting = [axis for axis, gap in (("x", gap_x), ("y", gap_y)) if gap == 0]
    if meeting:
        edge = {"x": ("right edge = wall's left edge" if player.right == wall.left
                      else "left edge = wall's right edge"),
                "y": ("bottom edge = wall's top edge" if player.bottom == wall.top
                      else "top edge = wall's bottom edge")}[meeting[0]]
        return [f"{edge} ({'corner: ' if len(meeting) == 2 else ''}no shared inside):",
                "  touching, not colliding (strict <)"]
    return [f"the edges cross: {-gap_x:g} px deep along x, {-gap_y:g} along y:",
            "  colliding (strict < holds both ways)"]


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
    group = "narrow phase"
    draws = (Layer.SHAPES, Layer.CONTACTS)

    def reset(self) -> None:
        self.pos = {"wall": (WALL.x, WALL.y),
                    "player": (WALL.left - PLAYER_W_PX, AREA.y + 170)}  # flush: touching
        self.zero_width = False
        self.meter = CostMeter()

    def controls(self) -> list[Control]:
        return [Control("nudge the player 1 px", NUDGE_KEYS),
                Control(f"zero-width player: {'on' if self.zero_width else 'off'}",
                        (pygame.K_z,))]

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
        self.meter.time("Box.overlaps", lambda: player.overlaps(wall))
        self.meter.time("Box.touches", lambda: player.touches(wall))
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
            *edge_words(player, wall),
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        player, wall = self.player(), self.wall()
        color = {"colliding": canvas.EXACT, "touching": canvas.TEXT, "apart": canvas.DIM}
        if Layer.SHAPES in layers:
            canvas.box(surface, wall, canvas.STILL)
            canvas.box(surface, player, canvas.MOVER)
        if Layer.CONTACTS in layers:
            canvas.box(surface, player, color[self.answer], 3)
        canvas.text(surface, f"Collision Status: {self.answer}", (AREA.x + 16, AREA.y + 16),
                    color[self.answer], canvas.TITLE_PT)
