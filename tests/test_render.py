"""What is drawn is what collides: every sprite is drawn as its ``image`` at its ``rect``, the
rect follows the float box every tick, drawing never changes the simulation, and static tile
layers are drawn once into cached chunks that show exactly the tiles."""

from __future__ import annotations

import math
from dataclasses import replace

import pygame
import pytest

from game.app.assets import Assets
from game.app.render import (
    CHUNK_PX,
    Layer,
    LayerCache,
    WorldRenderer,
    layer_caches,
    screen_offset,
)
from game.collision.aabb import Box
from game.sim.camera import Camera
from game.sim.enemy import Squashed
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.level import Level, TileLayer
from game.sim.platforms import PlatformSpec, Route
from game.sim.player import Player
from game.sim.sprite import BoxSprite
from game.sim.tuning import Tuning
from game.sim.world import SQUASH_TICKS, EventKind, World
from tests.maps import level_from_ascii

RIGHT = frozenset({Action.RIGHT})
JUMP_RIGHT = frozenset({Action.RIGHT, Action.JUMP})
OPAQUE = 255

# A level with one of everything that is drawn: a coin, an exit, a checkpoint, two
# enemies (one to stomp), a moving platform, and the player.
ROWS = [
    "                          ",
    "                          ",
    " P      C         E    D  ",
    "#######     E    #########",
    "#######  ######  #########",
]


def everything_level() -> Level:
    level = level_from_ascii(ROWS)
    ferry = PlatformSpec(Route(((112.0, 40.0), (176.0, 40.0))), 32.0, 8.0, 30.0)
    return replace(level, platforms=(ferry,), checkpoints=(Box(64.0, 16.0, 16.0, 32.0),))


def script(tick: int) -> Actions:
    """Run right, jumping now and then: over the gap, onto an enemy, into the coin."""
    return JUMP_RIGHT if tick % 50 < 12 else RIGHT


def screen_rect(sprite: BoxSprite, camera: Camera) -> pygame.Rect:
    dx, dy = screen_offset(camera)
    return sprite.rect.move(-dx, -dy)


def expected_place(sprite: BoxSprite, camera: Camera) -> tuple[int, int]:
    """Where the picture belongs on screen, worked out from the box alone: bottom-centred
    on it (feet on the floor), centred on it (a coin) or at its corner (a platform)."""
    w, h = sprite.image.get_size()
    box = sprite.box
    dx, dy = screen_offset(camera)
    if sprite.anchor.value == "top-left":
        return math.floor(box.x) - dx, math.floor(box.y) - dy
    x = math.floor(box.x + box.w / 2 - w / 2) - dx
    if sprite.anchor.value == "centre":
        return x, math.floor(box.y + box.h / 2 - h / 2) - dy
    return x, math.floor(box.bottom) - h - dy


def mismatched_pixels(target: pygame.Surface, image: pygame.Surface,
                      topleft: tuple[int, int]) -> int:
    """How many of ``image``'s opaque pixels are not on ``target`` at ``topleft``."""
    bad = 0
    for y in range(image.get_height()):
        for x in range(image.get_width()):
            colour = image.get_at((x, y))
            at = (topleft[0] + x, topleft[1] + y)
            if colour.a == OPAQUE and target.get_rect().collidepoint(at):
                bad += target.get_at(at)[:3] != colour[:3]
    return bad


def visible_alone(sprite: BoxSprite, drawn: list[BoxSprite], camera: Camera) -> bool:
    """On screen, and not under a sprite drawn after it."""
    mine = screen_rect(sprite, camera)
    later = drawn[drawn.index(sprite) + 1:]
    return (mine.colliderect(pygame.Rect(0, 0, 320, 180))
            and not any(mine.colliderect(screen_rect(s, camera)) for s in later))


def test_every_sprite_is_drawn_as_its_image_standing_where_its_box_is(assets: Assets) -> None:
    world = World(everything_level())
    renderer = WorldRenderer(assets)
    target = pygame.Surface((320, 180))
    checked: set[str] = set()
    for tick in range(240):
        events = world.step(script(tick))
        for sprite in renderer.sprites:  # moved by the tick, not yet redrawn: no lag either
            assert screen_rect(sprite, world.camera).topleft == expected_place(sprite,
                                                                               world.camera)
        renderer.draw(target, world, tick)
        drawn = renderer.sprites.sprites()
        assert set(drawn) >= {world.player, *world.enemies, *world.coins, *world.exits,
                              *world.checkpoints, *world.platforms}
        for sprite in drawn:
            assert sprite.rect.size == sprite.image.get_size()
            if not visible_alone(sprite, drawn, world.camera):
                continue
            place = expected_place(sprite, world.camera)
            assert screen_rect(sprite, world.camera).topleft == place, (tick, sprite)
            assert mismatched_pixels(target, sprite.image, place) == 0, (tick, sprite)
            checked.add(type(sprite).__name__)
        if any(e.kind is EventKind.STOMP for e in events):
            checked.add("stomp")
    assert checked >= {"Player", "Enemy", "Coin", "Exit", "Checkpoint", "Platform",
                       "Squashed", "stomp"}


def test_a_sprites_rect_follows_its_box_in_the_same_call_that_moves_it() -> None:
    world = World(everything_level())
    for tick in range(120):
        world.step(script(tick))
        for sprite in [world.player, *world.enemies, *world.platforms]:
            assert sprite.rect == sprite.box.to_rect()  # no pictures: the box itself


def test_drawing_every_frame_never_changes_the_simulation(assets: Assets) -> None:
    drawn, plain = World(everything_level()), World(everything_level())
    renderer = WorldRenderer(assets)
    target = pygame.Surface((320, 180))
    for tick in range(300):
        assert drawn.step(script(tick)) == plain.step(script(tick))
        renderer.draw(target, drawn, tick)
        renderer.draw(target, drawn, tick + 7)  # any frame count, any number of times
        for a, b in zip(drawn.bodies(), plain.bodies(), strict=True):
            assert (a.box, a.vx, a.vy, a.on_ground) == (b.box, b.vx, b.vy, b.on_ground)
    assert len(drawn.coins) == len(plain.coins) and len(drawn.enemies) == len(plain.enemies)


def test_sprites_are_drawn_in_the_stated_layer_order(assets: Assets) -> None:
    world = World(everything_level())
    renderer = WorldRenderer(assets)
    renderer.draw(pygame.Surface((320, 180)), world, 0)
    layers = [renderer.sprites.get_layer_of_sprite(s) for s in renderer.sprites.sprites()]
    assert layers == sorted(layers)
    assert renderer.sprites.get_top_sprite() is world.player
    assert set(layers) == {Layer.PLATFORMS, Layer.FLAGS, Layer.COINS, Layer.ENEMIES,
                           Layer.PLAYER}


def test_a_stomped_enemy_is_drawn_flat_for_a_while_then_leaves_the_group(assets: Assets
                                                                         ) -> None:
    level = level_from_ascii(["   P    ", "        ", "        ", "   E    ", "########"])
    world = World(level, Tuning(enemy_speed_px_s=0.0))
    renderer = WorldRenderer(assets)
    target = pygame.Surface((320, 180))
    stomped_at = None
    for tick in range(200):
        events = world.step(NOTHING)
        renderer.draw(target, world, tick)
        squashed = [s for s in renderer.sprites if isinstance(s, Squashed)]
        if any(e.kind is EventKind.STOMP for e in events):
            stomped_at = tick
        if stomped_at is None:
            assert squashed == []
        elif tick - stomped_at < SQUASH_TICKS:
            assert len(squashed) == 1 and not world.enemies
        else:
            assert squashed == []
    assert stomped_at is not None


def test_the_player_blinks_while_invulnerable_and_faces_the_way_it_runs(assets: Assets
                                                                        ) -> None:
    world = World(level_from_ascii(["          ", " P        ", "##########"]))
    renderer = WorldRenderer(assets)
    target = pygame.Surface((320, 180))
    world.step(RIGHT)
    renderer.draw(target, world, 0)
    player: Player = world.player
    assert player.strip is not None
    facing_right = player.image
    world.player.facing = -1
    renderer.draw(target, world, 0)
    assert player.image is player.strip.left[player.strip.right.index(facing_right)]
    world.player.invulnerable_ticks_left = 60
    shown = set()
    for frame in range(12):
        renderer.draw(target, world, frame)
        shown.add(player.image is player.strip.blank)
    assert shown == {True, False}


# Static tile layers: drawn once into chunks, and the chunks show exactly the tiles.

def tile_level(layers: tuple[TileLayer, ...]) -> Level:
    rows = ["P" + " " * 59] + [" " * 60] * 29
    images = {1: pygame.Surface((16, 16)), 2: pygame.Surface((16, 16)),
              3: pygame.Surface((32, 48), pygame.SRCALPHA)}
    images[1].fill((200, 40, 40))
    images[2].fill((40, 200, 40))
    images[3].fill((40, 40, 200, 180))
    return replace(level_from_ascii(rows), layers=layers, tile_images=images)


def pattern_layer(name: str, opacity: float = 1.0,
                  offset: tuple[float, float] = (0.0, 0.0)) -> TileLayer:
    gids = tuple(tuple((1 + (col * 7 + row * 3) % 5) % 4 if (col + row) % 3 else 0
                       for col in range(60)) for row in range(30))
    return TileLayer(name, gids, opacity, offset)


def tile_by_tile(target: pygame.Surface, level: Level, layer: TileLayer,
                 camera: Camera) -> None:
    """The plain way: every tile of the map blitted on its own, no culling, no cache."""
    canvas = pygame.Surface(target.get_size(), pygame.SRCALPHA)
    dx, dy = screen_offset(camera)
    ox, oy = math.floor(layer.offset[0]), math.floor(layer.offset[1])
    for row, line in enumerate(layer.gids):
        for col, gid in enumerate(line):
            image = level.tile_images.get(gid)
            if image is not None:
                canvas.blit(image, (col * 16 + ox - dx, (row + 1) * 16 - image.get_height()
                                    + oy - dy))
    canvas.set_alpha(round(layer.opacity * OPAQUE))
    target.blit(canvas, (0, 0))


@pytest.mark.parametrize("camera", [Camera(x=0.0, y=0.0), Camera(x=250.4, y=77.9),
                                    Camera(x=-30.5, y=-12.2), Camera(x=511.0, y=300.0),
                                    Camera(x=700.75, y=250.5)])
@pytest.mark.parametrize("layer", [pattern_layer("plain"),
                                   pattern_layer("faded", opacity=0.5),
                                   pattern_layer("offset", offset=(5.0, -7.0))])
def test_a_cached_layer_shows_exactly_the_tiles_drawn_one_by_one(camera: Camera,
                                                                  layer: TileLayer) -> None:
    level = tile_level((layer,))
    cached, plain = pygame.Surface((320, 180)), pygame.Surface((320, 180))
    cached.fill((0, 0, 0))
    plain.fill((0, 0, 0))
    (cache,) = layer_caches(level, level.layers)
    cache.draw(cached, screen_offset(camera))
    tile_by_tile(plain, level, layer, camera)
    # Equal to within 1 of 255 per channel: SDL's run-length blitter rounds translucent
    # pixels differently from its plain one; a tile out of place differs by far more.
    cached_bytes, plain_bytes = (pygame.image.tobytes(s, "RGB") for s in (cached, plain))
    assert max(abs(a - b) for a, b in zip(cached_bytes, plain_bytes, strict=True)) <= 1


def test_a_static_layer_is_drawn_into_each_chunk_once_however_many_frames() -> None:
    level = tile_level((pattern_layer("plain"),))
    (cache,) = layer_caches(level, level.layers)
    target = pygame.Surface((320, 180))
    seen: set[tuple[int, int]] = set()
    for frame in range(600):  # pan right and back, ten seconds of frames
        x = 400 - abs(frame % 200 - 100) * 4
        offset = (x, 100)
        cache.draw(target, offset)
        seen |= {(cx, cy) for cx in range(x // CHUNK_PX, (x + 319) // CHUNK_PX + 1)
                 for cy in range(100 // CHUNK_PX, (100 + 179) // CHUNK_PX + 1)}
    assert cache.chunks_drawn == len(seen) <= 6


def test_an_empty_stretch_of_a_layer_costs_no_surface() -> None:
    empty = TileLayer("empty", tuple(tuple(0 for _ in range(60)) for _ in range(30)))
    level = tile_level((empty,))
    cache = LayerCache(empty, level.tile_images, (16, 16), (1, 2))
    cache.draw(pygame.Surface((320, 180)), (0, 0))
    assert cache.chunks_drawn == 0 and set(cache.chunks.values()) == {None}
