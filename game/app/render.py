"""Draw one frame of the world: sky, tile layers, exits, coins, enemies, the player, foreground.

Where it sits: after the frame's ticks, before the HUD. :func:`draw_world` paints the
320x180 logical screen from what :meth:`game.sim.world.World.step` left behind; it only *reads*
the world (positions, velocities, facing) and never moves, adds or removes anything.

What it teaches:
  * **World space to screen space** is one subtraction: ``screen = floor(world - camera)``.
    ``math.floor``, never ``int()``: ``int(-0.5)`` is 0, which would make everything left or
    above the camera jump a pixel as it crosses zero.
  * **Draw only what is in view.** The visible columns and rows are found by dividing the
    camera's edges by the tile size (the same trick :mod:`game.sim.tilegrid` uses for collisions),
    so a map a hundred screens wide costs the same per frame as one screen.
  * **Painter's order** gives depth: far things first, then the level, the sprites, and
    the foreground layers last so the player can walk *behind* a bush.
  * **Parallax**: the sky scrolls at a fraction of the camera's speed, so it looks far away;
    it repeats horizontally, so it never runs out.
  * **Sprites are anchored bottom-centre on the hitbox.** The art is bigger than the box
    (hair, ears), but the feet must sit exactly on the floor the physics stands on.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence

import pygame

from game.app.assets import Assets
from game.collision.aabb import Box
from game.sim.camera import Camera
from game.sim.enemy import Enemy, EnemyKind
from game.sim.level import TileLayer
from game.sim.player import Player
from game.sim.world import World

ANIMATION_HZ = 60  # ``frame`` advances this many times per second (one per tick or frame)

SKY_PARALLAX = 0.25  # the sky moves this fraction of a pixel per pixel the camera moves
DEFAULT_SKY_COLOR = (110, 170, 240)  # behind the sky picture, if a level does not set one

COIN_FPS = 8  # spin frames per second
COIN_PHASE_PER_COL = 1  # neighbouring coins (by 16 px column) are one spin frame apart
COIN_PHASE_COL_PX = 16

ENEMY_WALK_FPS = 4
ENEMY_WALK_FRAMES = (0, 1)
SQUASHED_FRAME = 2
HOPPER_SITTING_FRAME = 3
HOPPER_AIRBORNE_FRAME = 4

PLAYER_IDLE_FPS = 2
PLAYER_IDLE_FRAMES = (0, 1)
PLAYER_RUN_FPS = 12
PLAYER_RUN_FRAMES = (2, 3, 4, 5)
PLAYER_JUMP_FRAME = 6  # rising
PLAYER_FALL_FRAME = 7
PLANK_COLOR = (150, 98, 52)
PLANK_TOP_COLOR = (204, 150, 84)
PLANK_EDGE_COLOR = (62, 36, 20)
PLANK_TOP_PX = 2
PLANK_BOLT_INSET_PX = 3
PLANK_BOLT_GAP_PX = 8
UNREACHED_TINT = (120, 120, 140)  # a checkpoint flag not yet touched is drawn greyed
BLINK_HZ = 10  # while invulnerable after a hit, the player flickers at this rate

OPAQUE = 255  # surface alpha of a fully opaque layer
ARGB_HEX_DIGITS = 8  # Tiled writes "#aarrggbb" when the background colour has alpha


def to_screen(x: float, y: float, camera: Camera) -> tuple[int, int]:
    """World pixel to screen pixel: ``floor(world - camera)`` on each axis.

    >>> to_screen(10.0, 5.5, Camera(x=3.5, y=6.0))
    (6, -1)
    """
    return math.floor(x - camera.x), math.floor(y - camera.y)


def animation_index(frame: int, fps: int, frames: Sequence[int], phase: int = 0) -> int:
    """The sprite frame to show at ``frame`` for a loop of ``frames`` played at ``fps``.

    >>> [animation_index(f, 8, (2, 3, 4, 5)) for f in (0, 7, 8, 15, 23, 30)]
    [2, 2, 3, 4, 5, 2]
    """
    step = frame * fps // ANIMATION_HZ + phase
    return frames[step % len(frames)]


def parse_tiled_color(text: str | None) -> pygame.Color | None:
    """A Tiled colour (``#rrggbb`` or ``#aarrggbb``) as a pygame Color, None if unreadable.

    >>> tuple(parse_tiled_color("#80ff0000") or ())
    (255, 0, 0, 128)
    >>> tuple(parse_tiled_color("#102030") or ())
    (16, 32, 48, 255)
    >>> parse_tiled_color("nonsense") is None
    True
    """
    if not text:
        return None
    digits = text.strip().lstrip("#")
    if len(digits) == ARGB_HEX_DIGITS:
        digits = digits[2:] + digits[:2]  # Tiled puts alpha first, pygame last
    try:
        return pygame.Color("#" + digits)
    except ValueError:
        return None


def _draw_sky(target: pygame.Surface, world: World, assets: Assets) -> None:
    color = parse_tiled_color(world.level.background_color)
    target.fill(color if color is not None else DEFAULT_SKY_COLOR)
    sky = assets.background
    sky_w = sky.get_width()
    scroll = math.floor(world.camera.x * SKY_PARALLAX)
    x = -(scroll % sky_w)
    while x < target.get_width():
        target.blit(sky, (x, 0))
        x += sky_w


def _visible_range(view_lo: float, view_len: int, cell: int, count: int,
                   extra_before: int, extra_after: int) -> range:
    """Indices of the cells of size ``cell`` overlapping ``[view_lo, view_lo + view_len)``,
    widened by ``extra`` cells each side (for images larger than their cell), in the map."""
    first = math.floor(view_lo / cell) - extra_before
    last = math.floor((view_lo + view_len) / cell) + extra_after
    return range(max(0, first), min(count - 1, last) + 1)


def _overhang_cells(images: Iterable[pygame.Surface], tile_w: int, tile_h: int
                    ) -> tuple[int, int]:
    """How many extra cells the largest tile image reaches right and up beyond its own."""
    max_w = max((image.get_width() for image in images), default=tile_w)
    max_h = max((image.get_height() for image in images), default=tile_h)
    return max(0, math.ceil(max_w / tile_w) - 1), max(0, math.ceil(max_h / tile_h) - 1)


def _draw_layer(target: pygame.Surface, layer: TileLayer, images: Mapping[int, pygame.Surface],
                world: World, overhang: tuple[int, int]) -> None:
    """Blit the visible tiles of one layer. Tiles larger than a cell are anchored at the
    cell's bottom-left corner, as Tiled draws them."""
    if layer.opacity <= 0 or not layer.gids:
        return
    grid, camera = world.grid, world.camera
    tile_w, tile_h = grid.tile_w, grid.tile_h
    off_x, off_y = layer.offset
    view_w, view_h = target.get_size()
    reach_right, reach_up = overhang
    rows = _visible_range(camera.y - off_y, view_h, tile_h, len(layer.gids), 0, reach_up)
    cols = _visible_range(camera.x - off_x, view_w, tile_w, len(layer.gids[0]), reach_right, 0)

    canvas = target
    if layer.opacity < 1:
        canvas = pygame.Surface(target.get_size(), pygame.SRCALPHA)
    blits: list[tuple[pygame.Surface, tuple[int, int]]] = []
    for row in rows:
        gids = layer.gids[row]
        bottom = (row + 1) * tile_h + off_y
        for col in cols:
            gid = gids[col] if col < len(gids) else 0
            image = images.get(gid) if gid else None
            if image is None:
                continue
            blits.append((image, to_screen(col * tile_w + off_x, bottom - image.get_height(),
                                           camera)))
    canvas.blits(blits, doreturn=False)
    if canvas is not target:
        canvas.set_alpha(round(layer.opacity * OPAQUE))
        target.blit(canvas, (0, 0))


def _blit_anchored(target: pygame.Surface, image: pygame.Surface, box: Box, camera: Camera,
                   *, flip: bool = False, centre_y: bool = False) -> None:
    """Draw ``image`` centred on the box horizontally, its bottom on the box's bottom (or
    centred vertically), mirrored if ``flip``."""
    if flip:
        image = pygame.transform.flip(image, True, False)
    w, h = image.get_size()
    top = box.y + (box.h - h) / 2 if centre_y else box.bottom - h
    target.blit(image, to_screen(box.x + (box.w - w) / 2, top, camera))


def player_frame(player: Player, frame: int) -> int:
    """Which strip frame shows the player: jump or fall in the air, run or idle on the ground."""
    if not player.on_ground:
        return PLAYER_JUMP_FRAME if player.vy < 0 else PLAYER_FALL_FRAME
    if player.vx != 0:
        return animation_index(frame, PLAYER_RUN_FPS, PLAYER_RUN_FRAMES)
    return animation_index(frame, PLAYER_IDLE_FPS, PLAYER_IDLE_FRAMES)


def _draw_platform(target: pygame.Surface, box: Box, camera: Camera) -> None:
    """A bolted wooden plank filling the platform's box exactly (its hitbox is its look)."""
    rect = box.moved(-camera.x, -camera.y).to_rect()
    pygame.draw.rect(target, PLANK_COLOR, rect)
    pygame.draw.rect(target, PLANK_TOP_COLOR, (rect.x, rect.y, rect.w, PLANK_TOP_PX))
    pygame.draw.rect(target, PLANK_EDGE_COLOR, rect, width=1)
    for bolt_x in range(rect.x + PLANK_BOLT_INSET_PX, rect.right - 1, PLANK_BOLT_GAP_PX):
        target.set_at((bolt_x, rect.centery), PLANK_EDGE_COLOR)


def _draw_sprites(target: pygame.Surface, world: World, assets: Assets, frame: int) -> None:
    camera = world.camera
    for platform in world.platforms:
        _draw_platform(target, platform.box, camera)
    for number, flag in enumerate(world.checkpoints):
        image = assets.exit_image
        if number != world.checkpoint_reached:
            image = image.copy()
            image.fill(UNREACHED_TINT, special_flags=pygame.BLEND_RGB_MULT)
        _blit_anchored(target, image, flag.box, camera)
    for goal in world.exits:
        _blit_anchored(target, assets.exit_image, goal.box, camera)
    for coin in world.coins:
        phase = math.floor(coin.box.x / COIN_PHASE_COL_PX) * COIN_PHASE_PER_COL
        index = animation_index(frame, COIN_FPS, range(len(assets.coin_frames)), phase)
        _blit_anchored(target, assets.coin_frames[index], coin.box, camera, centre_y=True)
    enemy: Enemy
    for number, enemy in enumerate(world.enemies):
        if enemy.kind is EnemyKind.HOPPER:
            index = HOPPER_SITTING_FRAME if enemy.on_ground else HOPPER_AIRBORNE_FRAME
        else:
            index = animation_index(frame, ENEMY_WALK_FPS, ENEMY_WALK_FRAMES, number)
        _blit_anchored(target, assets.enemy_frames[index], enemy.box, camera,
                       flip=enemy.direction < 0)
    for squash in world.squashed:
        _blit_anchored(target, assets.enemy_frames[SQUASHED_FRAME], squash.box, camera)
    player = world.player
    blink_off = player.invulnerable and (frame * 2 * BLINK_HZ // ANIMATION_HZ) % 2 == 1
    if not blink_off:
        _blit_anchored(target, assets.player_frames[player_frame(player, frame)], player.box,
                       camera, flip=player.facing < 0)


def draw_world(target: pygame.Surface, world: World, assets: Assets, frame: int) -> None:
    """Paint the whole world view onto ``target`` (the 320x180 logical screen).

    ``frame`` drives the animations at :data:`ANIMATION_HZ` steps per second; pass the
    campaign's tick count so animations freeze while the game is paused.
    """
    _draw_sky(target, world, assets)
    level = world.level
    images = level.tile_images
    overhang = _overhang_cells(images.values(), world.grid.tile_w, world.grid.tile_h)
    for layer in level.layers:
        _draw_layer(target, layer, images, world, overhang)
    _draw_sprites(target, world, assets, frame)
    for layer in level.foreground:
        _draw_layer(target, layer, images, world, overhang)
