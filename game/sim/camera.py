"""The camera: which part of the map the screen shows.

Where it sits: the last step of a tick. It follows the player's hitbox and never shows
anything outside the map; a map smaller than the screen is centred instead.

A map at most :data:`BOTTOM_HOLD_PX` taller than the screen is framed on its bottom edge:
the camera does not rise when the player jumps, so the bottom of every pit (its spikes or
its drop into darkness) is on screen whenever its edge is. A taller map scrolls up and down
with the player, as the whole of it could not be seen at once anyway.

>>> cam = Camera(view_w=320, view_h=180)
>>> cam.follow(Box(500, 50, 12, 14), map_w=1000, map_h=240)
>>> cam.x, cam.y
(346.0, 0.0)
>>> cam.follow(Box(0, 0, 12, 14), map_w=100, map_h=100)    # small map: centred
>>> cam.x, cam.y
(-110.0, -40.0)
>>> cam.follow(Box(500, 20, 12, 14), map_w=1000, map_h=192)  # a jump: the floor stays
>>> cam.y
12.0
"""

from __future__ import annotations

from dataclasses import dataclass

from game.collision.aabb import Box

VIEW_W_PX = 320  # the game's logical screen; the window scales it up
VIEW_H_PX = 180
LOOK_UP_PX = 20.0  # the camera sits this much above the player's centre to show more sky
BOTTOM_HOLD_PX = 32  # a map no more than this taller than the view is framed on its bottom


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
        if 0 < map_h - self.view_h <= BOTTOM_HOLD_PX:
            self.y = float(map_h - self.view_h)  # the floor and the pits' bottoms in view
        else:
            self.y = float(_clamp_axis(target.y + target.h / 2 - LOOK_UP_PX, self.view_h,
                                       map_h))

    def view(self) -> Box:
        return Box(self.x, self.y, self.view_w, self.view_h)
