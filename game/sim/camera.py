"""The camera: which part of the map the screen shows.

Where it sits: the last step of a tick. It follows the player's hitbox and never shows
anything outside the map; a map smaller than the screen is centred instead.

>>> cam = Camera(view_w=320, view_h=180)
>>> cam.follow(Box(500, 50, 12, 14), map_w=1000, map_h=240)
>>> cam.x, cam.y
(346.0, 0.0)
>>> cam.follow(Box(0, 0, 12, 14), map_w=100, map_h=100)    # small map: centred
>>> cam.x, cam.y
(-110.0, -40.0)
"""

from __future__ import annotations

from dataclasses import dataclass

from game.collision.aabb import Box

VIEW_W_PX = 320  # the game's logical screen; the window scales it up
VIEW_H_PX = 180
LOOK_UP_PX = 20.0  # the camera sits this much above the player's centre to show more sky


def _clamp_axis(centre: float, view: float, world: float) -> float:
    if world <= view:
        return (world - view) / 2
    return min(max(centre - view / 2, 0.0), world - view)


@dataclass
class Camera:
    view_w: int = VIEW_W_PX
    view_h: int = VIEW_H_PX
    x: float = 0.0
    y: float = 0.0

    def follow(self, target: Box, map_w: float, map_h: float) -> None:
        """Centre on ``target``, then clamp so the view stays inside the map."""
        self.x = float(_clamp_axis(target.x + target.w / 2, self.view_w, map_w))
        self.y = float(_clamp_axis(target.y + target.h / 2 - LOOK_UP_PX, self.view_h, map_h))

    def view(self) -> Box:
        return Box(self.x, self.y, self.view_w, self.view_h)
