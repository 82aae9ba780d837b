"""Draw the world: the sky, the cached tile layers, then every sprite through the camera.

Where it sits: after the frame's ticks, before the HUD. A :class:`WorldRenderer` paints the
320x180 logical screen from what :meth:`game.sim.world.World.step` left behind; it only
*reads* the world's positions and state, and what it changes on a sprite is its picture.

A frame, in order (:meth:`WorldRenderer.draw`):

1. **Sky**: the level's place (:mod:`game.app.places`, the map property ``setting``) gives
   the still sky with its sun, then the scenery, scrolled by parallax and standing on the
   level's floor line, and below that line the darkness a pit falls into; over it, the
   moving platforms' tracks (:mod:`game.app.tracks`).
2. **Tile layers behind the sprites**, each from its cache of pre-drawn chunks.
3. **Sprites**: every sprite's ``update(frame)`` picks its picture, then one
   :class:`CameraGroup` blits each ``image`` at its ``rect`` minus the camera, in the
   layer order of :class:`Layer` (platforms, flags, coins, enemies, squashed, player).
4. **Foreground tile layers**, cached the same way, so the player walks *behind* a bush.

In the window, the :mod:`game.app.effects` it is given shake the view (steps 2 to 4 are
drawn a few pixels off the camera, over the still sky, so nothing is smeared or left
behind), squash or stretch the player's picture before step 3 and add their particles
after it.

What it teaches:
  * **World space to screen space** is one subtraction. The camera's position is floored
    once per frame (:func:`screen_offset`) and every tile and sprite is drawn at its whole
    pixel minus that, so nothing shimmers against the tiles it stands on. ``math.floor``,
    never ``int()``: ``int(-0.5)`` is 0, which would make everything left of or above the
    camera jump a pixel as it crosses zero.
  * **The Group draws; the sprites say what.** There is no per-kind drawing code here: a
    sprite's ``image`` and ``rect`` are exactly what appears, so the picture, the rect and
    the physics box cannot disagree (:mod:`game.sim.sprite`). The renderer only hands each
    new sprite its pictures once (:meth:`WorldRenderer.strip_for`).
  * **Draw static things once.** A layer's still tiles never change in play (its animated
    ones are drawn each frame over them), so they are drawn into
    chunks of :data:`CHUNK_PX` pixels square the first time they come into view, and each
    frame blits the two to six chunks of each layer that the camera sees instead of up to
    252 tiles one by one. Chunks, not one picture of the whole map, so a huge map costs
    memory only where the camera has been, and at most :data:`MAX_CACHED_CHUNKS` of a layer
    are kept.
  * **Parallax**: the clouds and hills scroll at a fraction of the camera's speed, so they
    look far away, and repeat horizontally, so they never run out; the sky and its sun,
    further still, do not move at all. The sky, the scenery and the pits' darkness depend
    on the camera's whole-pixel place alone, so they are painted together into one opaque
    backdrop, and painted again only when that place changes: a still camera costs one
    plain blit a frame.
  * **The background must not lie about the ground.** Scenery that reaches below the floor
    looks like somewhere to land; so it ends at the level's floor line (:func:`floor_line_px`)
    and a pit shows only darkness below it.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from collections.abc import Iterable, Mapping
from enum import IntEnum
from typing import TYPE_CHECKING

import pygame

from game.app.assets import Assets
from game.app.effects import Effects
from game.app.places import (
    PLACES,
    SCENERY_FLOOR_ROW,
    Place,
    pit_darkness,
    place_of,
    recolour,
)
from game.app.tracks import Tracks
from game.collision.shapes import TileKind
from game.collision.tile_grid import TileGrid
from game.sim.camera import Camera
from game.sim.enemy import Enemy, Squashed
from game.sim.level import Animation, Level, TileLayer
from game.sim.pickups import Checkpoint, Coin, Exit
from game.sim.platforms import Platform
from game.sim.player import Player
from game.sim.sprite import ANIMATION_HZ, BoxSprite, Strip
from game.sim.world import World

SKY_PARALLAX = 0.25  # the sky moves this fraction of a pixel per pixel the camera moves
DEFAULT_SKY_COLOR = (110, 170, 240)  # behind the sky picture, if a level does not set one

CHUNK_PX = 256  # a cached piece of a tile layer is this many pixels square
MAX_CACHED_CHUNKS = 96  # per layer: at 256 KiB a chunk, at most 24 MiB of its tiles

PLANK_COLOR = (150, 98, 52)
PLANK_TOP_COLOR = (204, 150, 84)
PLANK_EDGE_COLOR = (62, 36, 20)
PLANK_TOP_PX = 2
PLANK_BOLT_INSET_PX = 3
PLANK_BOLT_GAP_PX = 8

OPAQUE = 255  # surface alpha of a fully opaque layer
ARGB_HEX_DIGITS = 8  # Tiled writes "#aarrggbb" when the background colour has alpha


class Layer(IntEnum):
    """The order sprites are drawn in, back to front."""

    PLATFORMS = 0
    FLAGS = 1  # checkpoints and exits
    COINS = 2
    ENEMIES = 3
    SQUASHED = 4
    PLAYER = 5


def screen_offset(camera: Camera) -> tuple[int, int]:
    """What to subtract from a whole map pixel to get its screen pixel, for this frame.

    >>> screen_offset(Camera(x=3.5, y=-6.25))
    (3, -7)
    """
    return math.floor(camera.x), math.floor(camera.y)


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


if TYPE_CHECKING:
    _LayeredSprites = pygame.sprite.LayeredUpdates[BoxSprite]
else:  # pygame's groups are generic only to the type checker
    _LayeredSprites = pygame.sprite.LayeredUpdates


class CameraGroup(_LayeredSprites):
    """A layered group that draws through a camera: each ``image`` at ``rect`` minus it."""

    def draw_through(self, target: pygame.Surface, offset: tuple[int, int]) -> None:
        """Blit every sprite, back layer first, at its ``rect`` moved by ``-offset``."""
        dx, dy = offset
        target.blits([(sprite.image, sprite.rect.move(-dx, -dy)) for sprite in self.sprites()],
                     doreturn=False)


def plank(size: tuple[int, int]) -> pygame.Surface:
    """A bolted wooden plank of exactly ``size``: a moving platform's picture."""
    image = pygame.Surface(size)
    rect = image.get_rect()
    image.fill(PLANK_COLOR)
    image.fill(PLANK_TOP_COLOR, (0, 0, rect.w, PLANK_TOP_PX))
    pygame.draw.rect(image, PLANK_EDGE_COLOR, rect, width=1)
    for bolt_x in range(PLANK_BOLT_INSET_PX, rect.right - 1, PLANK_BOLT_GAP_PX):
        image.set_at((bolt_x, rect.centery), PLANK_EDGE_COLOR)
    return image


def floor_line_px(grid: TileGrid) -> int:
    """The map row, in px, where the level's floor is: the top of the solid ground that
    stands on the map's bottom edge, in the most columns (the lower one on a tie). A map
    whose bottom row holds no solid tile has its floor at its bottom edge.

    >>> grid = TileGrid(cols=4, rows=4, tile_w=16, tile_h=16)
    >>> floor_line_px(grid)
    64
    """
    tops: dict[int, int] = {}
    for col in range(grid.cols):
        row = grid.rows
        while row > 0 and any(shape.kind is TileKind.SOLID
                              for shape in grid.shapes_at(col, row - 1)):
            row -= 1
        if row < grid.rows:
            tops[row] = tops.get(row, 0) + 1
    if not tops:
        return grid.rows * grid.tile_h
    row = max(tops, key=lambda top: (tops[top], top))
    return row * grid.tile_h


def pit_spans_px(grid: TileGrid, floor_px: int) -> list[tuple[int, int]]:
    """The stretches of the map, ``(left, right)`` in px, with no solid tile at the floor
    line or anywhere below it: the pits, where the background shows darkness below that
    line. Ground lower than the floor line (a lowered floor, a dip) is somewhere to land,
    not a pit, and keeps the scenery behind it.

    >>> grid = TileGrid(cols=4, rows=4, tile_w=16, tile_h=16)
    >>> pit_spans_px(grid, 48)
    [(0, 64)]
    """
    row = min(floor_px // grid.tile_h, grid.rows - 1)
    spans: list[tuple[int, int]] = []
    for col in range(grid.cols):
        if any(shape.kind is TileKind.SOLID for below in range(row, grid.rows)
               for shape in grid.shapes_at(col, below)):
            continue
        left = col * grid.tile_w
        if spans and spans[-1][1] == left:
            spans[-1] = (spans[-1][0], left + grid.tile_w)
        else:
            spans.append((left, left + grid.tile_w))
    return spans


def _visible_range(lo_px: float, hi_px: float, cell: int, count: int,
                   extra_before: int, extra_after: int) -> range:
    """Indices of the cells of size ``cell`` overlapping ``[lo_px, hi_px)``, widened by
    ``extra`` cells each side (for images larger than their cell), within ``count``.

    >>> _visible_range(20.0, 52.0, 16, 10, 0, 0)
    range(1, 4)
    >>> _visible_range(-40.0, -1.0, 16, 10, 0, 0)     # above the map: nothing
    range(0, 0)
    >>> _visible_range(-40.0, -1.0, 16, 10, 0, 1)     # unless row 0's pictures reach up
    range(0, 1)
    """
    first = math.floor(lo_px / cell) - extra_before
    last = math.ceil(hi_px / cell) - 1 + extra_after
    return range(max(0, first), min(count - 1, last) + 1)


def _overhang_cells(images: Iterable[pygame.Surface], tile_w: int, tile_h: int
                    ) -> tuple[int, int]:
    """How many extra cells the largest tile image reaches right and up beyond its own."""
    max_w = max((image.get_width() for image in images), default=tile_w)
    max_h = max((image.get_height() for image in images), default=tile_h)
    return max(0, math.ceil(max_w / tile_w) - 1), max(0, math.ceil(max_h / tile_h) - 1)


def animation_frame(animation: Animation, ms: int) -> int:
    """The tile id an animation shows ``ms`` milliseconds after it started (it loops).

    >>> [animation_frame(((7, 100), (8, 300)), ms) for ms in (0, 99, 100, 399, 400)]
    [7, 7, 8, 8, 7]
    """
    ms %= sum(duration for _, duration in animation)
    for gid, duration in animation:
        if ms < duration:
            return gid
        ms -= duration
    return animation[-1][0]  # pragma: no cover (the loop always returns)


class LayerCache:
    """One tile layer, drawn chunk by chunk into surfaces the first time each is seen.

    Tiles larger than a cell are anchored at the cell's bottom-left corner, as Tiled draws
    them, so a chunk also draws the neighbours whose pictures reach into it. Animated tiles
    (Tiled's Tile Animation Editor) are left out of the chunks and drawn each frame with the
    frame their animation has reached. A layer's parallax factor scales how far it scrolls
    with the camera, as in Tiled (1: with the map; 0: fixed on screen).
    """

    def __init__(self, layer: TileLayer, images: Mapping[int, pygame.Surface],
                 tile_size: tuple[int, int], overhang: tuple[int, int],
                 animations: Mapping[int, Animation] | None = None) -> None:
        self.layer = layer
        self.images = images
        self.tile_w, self.tile_h = tile_size
        self.overhang = overhang
        self.animations = animations or {}
        self.animated = [(col, row, gid) for row, line in enumerate(layer.gids)
                         for col, gid in enumerate(line) if gid in self.animations]
        self.chunks: OrderedDict[tuple[int, int], pygame.Surface | None] = OrderedDict()
        self.chunks_drawn = 0  # how many chunks have been drawn from tiles, ever

    def chunk(self, cx: int, cy: int) -> pygame.Surface | None:
        """Chunk ``(cx, cy)``, drawing it now if it is not cached; None if it is empty."""
        key = (cx, cy)
        if key in self.chunks:
            self.chunks.move_to_end(key)
            return self.chunks[key]
        surface = self._draw_chunk(cx, cy)
        self.chunks[key] = surface
        if len(self.chunks) > MAX_CACHED_CHUNKS:
            self.chunks.popitem(last=False)  # forget the one seen longest ago
        return surface

    def _draw_chunk(self, cx: int, cy: int) -> pygame.Surface | None:
        gids = self.layer.gids
        left, top = cx * CHUNK_PX, cy * CHUNK_PX
        reach_right, reach_up = self.overhang
        rows = _visible_range(top, top + CHUNK_PX, self.tile_h, len(gids), 0, reach_up)
        cols = _visible_range(left, left + CHUNK_PX, self.tile_w, len(gids[0]), reach_right, 0)
        blits: list[tuple[pygame.Surface, tuple[int, int]]] = []
        for row in rows:
            line = gids[row]
            bottom = (row + 1) * self.tile_h - top
            for col in cols:
                gid = line[col] if col < len(line) else 0
                image = self.images.get(gid) if gid and gid not in self.animations else None
                if image is not None:
                    blits.append((image, (col * self.tile_w - left,
                                          bottom - image.get_height())))
        if not blits:
            return None
        surface = pygame.Surface((CHUNK_PX, CHUNK_PX), pygame.SRCALPHA)
        surface.blits(blits, doreturn=False)
        # Run-length encoded, a chunk's empty stretches are skipped rather than blended.
        surface.set_alpha(round(self.layer.opacity * OPAQUE), pygame.RLEACCEL)
        self.chunks_drawn += 1
        return surface

    def draw(self, target: pygame.Surface, offset: tuple[int, int], frame: int = 0) -> None:
        """Blit the chunks in view; ``offset`` is :func:`screen_offset` of the camera and
        ``frame`` the count that drives animations (:data:`ANIMATION_HZ` a second)."""
        if self.layer.opacity <= 0 or not self.layer.gids:
            return
        layer_x = math.floor(self.layer.offset[0])
        layer_y = math.floor(self.layer.offset[1])
        scroll_x = math.floor(offset[0] * self.layer.parallax[0])
        scroll_y = math.floor(offset[1] * self.layer.parallax[1])
        view_x, view_y = scroll_x - layer_x, scroll_y - layer_y  # the view, in layer pixels
        view_w, view_h = target.get_size()
        for cy in range(view_y // CHUNK_PX, (view_y + view_h - 1) // CHUNK_PX + 1):
            for cx in range(view_x // CHUNK_PX, (view_x + view_w - 1) // CHUNK_PX + 1):
                surface = self.chunk(cx, cy)
                if surface is not None:
                    target.blit(surface, (cx * CHUNK_PX - view_x, cy * CHUNK_PX - view_y))
        if self.animated:
            self._draw_animated(target, view_x, view_y, frame * 1000 // ANIMATION_HZ)

    def _draw_animated(self, target: pygame.Surface, view_x: int, view_y: int,
                       ms: int) -> None:
        view_w, view_h = target.get_size()
        shown: dict[int, int] = {}  # each animation's frame worked out once a frame
        for col, row, gid in self.animated:
            if gid not in shown:
                shown[gid] = animation_frame(self.animations[gid], ms)
            image = self.images.get(shown[gid])
            if image is None:
                continue
            x = col * self.tile_w - view_x
            y = (row + 1) * self.tile_h - image.get_height() - view_y
            if x < view_w and y < view_h and x + image.get_width() > 0 \
                    and y + image.get_height() > 0:
                if self.layer.opacity < 1.0:
                    image = image.copy()
                    image.set_alpha(round(self.layer.opacity * OPAQUE))
                target.blit(image, (x, y))


def layer_caches(level: Level, layers: Iterable[TileLayer],
                 images: Mapping[int, pygame.Surface] | None = None) -> list[LayerCache]:
    """A cache for each of ``layers`` of ``level``, drawn with ``images`` (default: the
    level's own tile images)."""
    grid = level.grid
    images = level.tile_images if images is None else images
    overhang = _overhang_cells(images.values(), grid.tile_w, grid.tile_h)
    return [LayerCache(layer, images, (grid.tile_w, grid.tile_h), overhang, level.animations)
            for layer in layers]


def cast(world: World) -> tuple[tuple[Layer, Iterable[BoxSprite]], ...]:
    """Every group of the world's sprites that is drawn, with the layer it is drawn in."""
    return ((Layer.PLATFORMS, world.platforms), (Layer.FLAGS, world.checkpoints),
            (Layer.FLAGS, world.exits), (Layer.COINS, world.coins),
            (Layer.ENEMIES, world.enemies), (Layer.SQUASHED, world.squashed),
            (Layer.PLAYER, world.players))


class WorldRenderer:
    """Draws worlds with ``assets``; keeps the sprites' group and the tile caches of the
    world it last drew, so a window should keep one renderer for the whole run."""

    def __init__(self, assets: Assets) -> None:
        self.assets = assets
        self.player_strip = Strip.of(assets.player_frames)
        self.enemy_strip = Strip.of(assets.enemy_frames)
        self.coin_strip = Strip.of(assets.coin_frames)
        self.exit_strip = Strip.of([assets.exit_image])
        self.checkpoint_strip = Strip.of(assets.checkpoint_frames)  # unlit, then lit
        self.plank_strips: dict[tuple[int, int], Strip] = {}
        sky = assets.sky  # an opaque sky hides the level's colour: no need to fill
        opaque_px = pygame.mask.from_surface(sky, OPAQUE - 1).count()
        self.sky_covers = opaque_px == sky.get_width() * sky.get_height()
        self.world: World | None = None
        self.effects: Effects | None = None  # the window's dust, squash and shake, if any
        self.sprites = CameraGroup()
        self.back: list[LayerCache] = []
        self.front: list[LayerCache] = []
        self.place: Place = PLACES["meadow"]
        self.floor_px = 0  # the level's floor line, in map px
        self.pits: list[tuple[int, int]] = []  # where the floor line has no ground, in map px
        self.pit: pygame.Surface | None = None  # the place's pit darkness, made once a level
        self.backdrop: pygame.Surface | None = None  # sky, scenery and pits, painted together
        self.backdrop_at: tuple[int, int] | None = None  # the camera place it was painted for
        self.tracks = Tracks(())  # the moving platforms' routes, made once a level

    def draw(self, target: pygame.Surface, world: World, frame: int) -> None:
        """Paint the world view onto ``target`` (the 320x180 logical screen).

        ``frame`` drives the animations at :data:`game.sim.sprite.ANIMATION_HZ` steps a second.
        """
        if world is not self.world:
            self._begin(world)
        offset = screen_offset(world.camera)
        if self.effects is not None:  # a stomp's shake: the world swings, the sky stays
            shake_x, shake_y = self.effects.shake_offset()
            offset = (offset[0] - shake_x, offset[1] - shake_y)
        # 1. Sky, and the platforms' tracks over it.
        self._draw_sky(target, world)
        self.tracks.draw(target, offset)
        # 2. Tile layers behind the sprites.
        for cache in self.back:
            cache.draw(target, offset, frame)
        # 3. Sprites: new ones get their pictures, each picks its frame, the group draws.
        self._cast_new_sprites(world)
        self.sprites.update(frame)
        if self.effects is not None:
            self.effects.dress(world)
        self.sprites.draw_through(target, offset)
        if self.effects is not None:
            self.effects.draw(target, offset)
        # 4. Foreground tile layers.
        for cache in self.front:
            cache.draw(target, offset, frame)

    def _begin(self, world: World) -> None:
        """A new world (a level started, restarted or reloaded): fresh group and caches."""
        self.world = world
        self.sprites = CameraGroup()
        level = world.level
        self.place = place_of(level.properties)
        swap = self.place.ground_swap()  # the place's grass and dirt, once per level
        images = {gid: recolour(image, swap) for gid, image in level.tile_images.items()}
        self.back = layer_caches(level, level.layers, images)
        self.front = layer_caches(level, level.foreground, images)
        self.floor_px = floor_line_px(level.grid)
        self.pits = pit_spans_px(level.grid, self.floor_px)
        self.pit = None
        self.backdrop_at = None
        self.tracks = Tracks(level.platforms)

    def _cast_new_sprites(self, world: World) -> None:
        """Add the world's sprites the group does not hold yet (all at first, then a squashed
        enemy now and then). A sprite that leaves play is ``kill()``-ed by the world, which
        takes it out of this group too."""
        for layer, members in cast(world):
            for sprite in members:
                if not self.sprites.has(sprite):
                    sprite.dress(self.strip_for(sprite))
                    self.sprites.add(sprite, layer=layer)

    def strip_for(self, sprite: BoxSprite) -> Strip:
        """The pictures a sprite wears (chosen once per sprite, never per frame)."""
        if isinstance(sprite, Player):
            return self.player_strip
        if isinstance(sprite, Enemy | Squashed):
            return self.enemy_strip
        if isinstance(sprite, Coin):
            return self.coin_strip
        if isinstance(sprite, Checkpoint):
            return self.checkpoint_strip
        if isinstance(sprite, Exit):
            return self.exit_strip
        if isinstance(sprite, Platform):
            size = (max(1, math.ceil(sprite.box.w)), max(1, math.ceil(sprite.box.h)))
            if size not in self.plank_strips:
                self.plank_strips[size] = Strip.of([plank(size)])
            return self.plank_strips[size]
        raise TypeError(f"no pictures for a {type(sprite).__name__}")

    def _draw_sky(self, target: pygame.Surface, world: World) -> None:
        """The backdrop (:meth:`_paint_sky`), painted again only when the camera's whole-pixel
        place or the screen's size has changed since it was last painted."""
        at = screen_offset(world.camera)
        size = target.get_size()
        if self.backdrop is None or self.backdrop.get_size() != size:
            self.backdrop, self.backdrop_at = pygame.Surface(size).convert(target), None
        if at != self.backdrop_at:
            self._paint_sky(self.backdrop, world)
            self.backdrop_at = at
        target.blit(self.backdrop, (0, 0))

    def _paint_sky(self, target: pygame.Surface, world: World) -> None:
        """The place's sky and its one sun stand still (they are far away); its scenery in
        front scrolls by parallax, repeats, and stands on the floor line; below that line
        is the pit's darkness. None of it shakes with a stomp."""
        sky, scenery = self.assets.places.get(self.place.name,
                                              (self.assets.sky, self.assets.background))
        if not self.sky_covers or sky.get_height() < target.get_height():
            color = parse_tiled_color(world.level.background_color)
            target.fill(color if color is not None else DEFAULT_SKY_COLOR)
        target.blit(sky, (0, 0))
        floor_y = self.floor_px - screen_offset(world.camera)[1]  # on screen
        scenery_w = scenery.get_width()
        scroll = math.floor(world.camera.x * SKY_PARALLAX)
        x = -(scroll % scenery_w)
        while x < target.get_width():
            target.blit(scenery, (x, floor_y - SCENERY_FLOOR_ROW))
            x += scenery_w
        height, width = target.get_height(), target.get_width()
        under = floor_y - SCENERY_FLOOR_ROW + scenery.get_height()  # the scenery's bottom
        if under < height:  # a floor lowered far below the line: the scenery goes on down
            target.fill(scenery.get_at((0, scenery.get_height() - 1)),
                        (0, under, width, height - under))
        if floor_y >= height or not self.pits:
            return
        if self.pit is None or self.pit.get_width() != width:
            self.pit = pit_darkness(self.place, width)
        below = floor_y + self.pit.get_height()
        world_x = screen_offset(world.camera)[0]
        for left, right in self.pits:  # each pit in view: the dark, clipped to its width
            span = pygame.Rect(left - world_x, floor_y, right - left, height - floor_y)
            span = span.clip(target.get_rect())
            if span.w <= 0:
                continue
            target.blit(self.pit, span.topleft, (span.x, 0, span.w, span.h))
            if below < height:
                target.fill((0, 0, 0), (span.x, below, span.w, height - below))
