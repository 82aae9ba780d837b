"""Scene ``x-ray``: the rects behind the sprites, and a round sprite in its square box.

What it shows: the game's own player, slime and coin sprites (``assets/``, drawn 4x) and a
round ball sprite. X switches x-ray on and off: with it on, every sprite's ``rect``, the box
pygame collides it by, is drawn over its picture, and the ball also shows its true circle.
Drag the player into the ball: ``pygame.sprite.collide_rect`` answers for the square boxes,
:meth:`~game.collision.circles.Circle.overlaps_box` for the ball's real shape, and the panel
says when the square box is wrong (a hit in its empty corner).
"""

from __future__ import annotations

import pygame

from game.app.assets import ASSETS, COIN_PX, MAX_ASSET_BYTES, SPRITE_PX, strip
from game.app.files import load_image
from game.collision.aabb import Box
from game.collision.circles import Circle
from game.lab import canvas
from game.lab.cost import CostMeter
from game.lab.scene import AREA, Control, Layer, Scene

SCALE = 4
BALL_R_PX = 40


class Prop(pygame.sprite.Sprite):
    """A sprite with the image it is drawn with and the rect it collides by."""

    def __init__(self, image: pygame.Surface, topleft: tuple[int, int]) -> None:
        super().__init__()
        self.image = image
        self.rect = image.get_rect(topleft=topleft)


def load_frame(name: str, frame_px: int) -> pygame.Surface:
    """The first frame of a sprite strip in ``assets/``, drawn ``SCALE`` times bigger."""
    sheet = load_image(ASSETS / name, MAX_ASSET_BYTES, "the sprite sheet")
    frame = strip(sheet, frame_px, frame_px)[0]
    return pygame.transform.scale(frame, (frame_px * SCALE, frame_px * SCALE))


def ball_image() -> pygame.Surface:
    image = pygame.Surface((2 * BALL_R_PX, 2 * BALL_R_PX), pygame.SRCALPHA)
    pygame.draw.circle(image, (236, 200, 80), (BALL_R_PX, BALL_R_PX), BALL_R_PX)
    pygame.draw.circle(image, (255, 240, 170), (BALL_R_PX - 12, BALL_R_PX - 12), 9)
    return image


class XRay(Scene):
    name = "x-ray"
    title = "the rects behind the sprites, a round sprite in its square"
    keys_help = "X x-ray on/off; drag the sprites"
    group = "game"
    draws = (Layer.SHAPES, Layer.BOUNDS, Layer.CONTACTS)

    def reset(self) -> None:
        self.images = {"player": load_frame("player.png", SPRITE_PX),
                       "slime": load_frame("enemy.png", SPRITE_PX),
                       "coin": load_frame("coin.png", COIN_PX),
                       "ball": ball_image()}
        self.pos = {"slime": (AREA.x + 60.0, AREA.y + 260.0),
                    "coin": (AREA.x + 400.0, AREA.y + 70.0),
                    "ball": (AREA.x + 300.0, AREA.y + 180.0),
                    "player": (AREA.x + 244.0, AREA.y + 128.0)}
        self.xray = True
        self.meter = CostMeter()

    def controls(self) -> list[Control]:
        return [Control(f"x-ray: {'on' if self.xray else 'off'}", (pygame.K_x,))]

    def sprites(self) -> dict[str, Prop]:
        return {key: Prop(self.images[key], (round(x), round(y)))
                for key, (x, y) in self.pos.items()}

    def ball_circle(self) -> Circle:
        x, y = self.pos["ball"]
        return Circle(round(x) + BALL_R_PX, round(y) + BALL_R_PX, BALL_R_PX)

    def grab_boxes(self) -> dict[str, Box]:
        return {key: Box.from_rect(sprite.rect) for key, sprite in self.sprites().items()}

    def on_key(self, key: int) -> None:
        if key == pygame.K_x:
            self.xray = not self.xray

    def refresh(self) -> None:
        sprites = self.sprites()
        player = sprites.pop("player")
        group = pygame.sprite.Group(*sprites.values())
        touched = pygame.sprite.spritecollide(player, group, False, pygame.sprite.collide_rect)
        names = {id(sprite): key for key, sprite in sprites.items()}
        self.rect_hits = sorted(names[id(sprite)] for sprite in touched)
        self.ball_rect_hit = "ball" in self.rect_hits
        self.ball_true_hit = self.ball_circle().overlaps_box(Box.from_rect(player.rect))
        wrong = self.ball_rect_hit and not self.ball_true_hit
        ball, held = self.ball_circle(), Box.from_rect(player.rect)
        ball_rect = sprites["ball"].rect
        self.meter.time("square rect: colliderect", lambda: player.rect.colliderect(ball_rect))
        self.meter.time("circle: Circle.overlaps_box", lambda: ball.overlaps_box(held))
        self.lines = [
            f"x-ray: {'on' if self.xray else 'off'} (X)",
            f"player rect {tuple(player.rect)}",
            "spritecollide(collide_rect): "
            + (", ".join(self.rect_hits) if self.rect_hits else "nothing"),
            f"ball by its square rect: {canvas.yes_no(self.ball_rect_hit)}",
            f"ball by its circle:      {canvas.yes_no(self.ball_true_hit)}",
            "  the square box is wrong: empty corner" if wrong else "",
        ]

    def draw(self, surface: pygame.Surface, layers: set[Layer]) -> None:
        sprites = self.sprites()
        if Layer.SHAPES in layers:
            for sprite in sprites.values():
                surface.blit(sprite.image, sprite.rect)
        if not self.xray:
            return
        if Layer.BOUNDS in layers:
            for key, sprite in sprites.items():
                color = canvas.WRONG if key == "ball" and self.ball_rect_hit and \
                    not self.ball_true_hit else canvas.BOUNDS
                pygame.draw.rect(surface, color, sprite.rect, 2)
                canvas.text(surface, key, (sprite.rect.x, sprite.rect.bottom + 2), canvas.DIM, 16)
        if Layer.CONTACTS in layers:
            circle = self.ball_circle()
            pygame.draw.circle(surface, canvas.EXACT if self.ball_true_hit else canvas.TEXT,
                               (circle.cx, circle.cy), circle.r, 2)
