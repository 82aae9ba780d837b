"""The debug overlay draws only the truth: the cells each lookup of the last tick visited and
the shapes it tested, read from the tick's query log, and nothing else; and it paints exactly
what the plain way of drawing it paints (:mod:`tests.overlay_reference`)."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pygame
import pytest

from game.app import debug_overlay
from game.app.assets import Assets
from game.app.debug_overlay import Checked, draw_debug
from game.app.hud import draw_hud
from game.app.render import WorldRenderer, screen_offset
from game.app.run import input_script
from game.collision.aabb import Box
from game.levels import load_level
from game.sim.campaign import Campaign, Outcome
from game.sim.inputs import NOTHING
from game.sim.tuning import Tuning
from game.sim.world import Measure, World
from tests.maps import TILE, level_from_ascii
from tests.overlay_reference import draw_debug_plainly

ROOT = Path(__file__).resolve().parent.parent
SCRIPTS = ROOT / "tests" / "scripts"
EVERY_NTH_TICK = 3  # the ticks whose overlays are compared, to keep the test quick
BIGGER_TARGET = (357, 203)  # wider and taller than the camera's view, by no whole cell

FALL_PX_PER_TICK = 10 * TILE
BLACK = pygame.Color(0, 0, 0)

# A shaft 40 tiles deep at the right of a wide map, so the panel (on the left, away from the
# player) covers none of it.
SHAFT = ["#" * 24 + ".P." + "#" * 3, *(["#" * 24 + "..." + "#" * 3] * 38), "#" * 30]
FLOOR = ["            ", "            ", "        P   ", "############"]


def overlay_alone(world: World, assets: Assets) -> pygame.Surface:
    """The overlay drawn on black, so every pixel that is not black is the overlay's."""
    target = pygame.Surface((320, 180))
    target.fill(BLACK)
    draw_debug(target, world, assets, fps=60.0, update_ms=0.0)
    return target


def cell_corner_on_screen(world: World, col: int, row: int) -> tuple[int, int]:
    dx, dy = screen_offset(world.camera)
    return col * TILE - dx, row * TILE - dy


def test_a_body_falling_10_tiles_per_tick_shows_every_cell_its_sweep_covered(
        assets: Assets) -> None:
    fast = Tuning(gravity_px_s2=FALL_PX_PER_TICK * 60 * 60,
                  max_fall_speed_px_s=FALL_PX_PER_TICK * 60)
    world = World(level_from_ascii(SHAFT), fast, measure=Measure(queries=True))
    world.step(NOTHING)
    fall = world.moves[world.player].y
    assert fall.hit is None
    assert fall.box.y - fall.start.y == FALL_PX_PER_TICK
    swept = set(world.grid.cells_covering(fall.swept))
    assert len({row for _, row in swept}) >= 10            # a column of at least 10 cells
    tested = Checked(world.grid, world.query_log)
    assert tested.cells["y sweep"] == swept                # every cell the sweep covered
    # ... and each of them is washed on screen, the ones in view at least.
    picture = overlay_alone(world, assets)
    shown = 0
    for col, row in sorted(swept):
        x, y = cell_corner_on_screen(world, col, row)
        if 0 <= x < 320 and 0 <= y + TILE // 2 < 180:
            assert picture.get_at((x, y + TILE // 2)) != BLACK, (col, row)
            shown += 1
    assert shown >= 5


def test_a_body_at_rest_shows_only_what_its_sweeps_and_probe_touched(assets: Assets) -> None:
    world = World(level_from_ascii(FLOOR), measure=Measure(queries=True))
    for _ in range(30):
        world.step(NOTHING)
    player = world.player
    assert player.on_ground and player.vx == 0
    world.step(NOTHING)
    # What the player's own lookups could have touched, worked out from its moves alone:
    # no x sweep (it did not move along x), the y sweep that landed it where it stands, and
    # the probe only if that sweep did not already find the floor under the feet.
    moves = world.moves[player]
    expected = set(world.grid.cells_covering(moves.y.swept))
    hit = moves.y.hit
    if hit is None or hit.face != player.box.bottom:
        probe = Box(player.box.x, player.box.bottom, player.box.w, 1)
        expected |= set(world.grid.cells_covering(probe))
    tested = Checked(world.grid, world.query_log)
    assert "x sweep" not in tested.cells
    assert tested.all_cells() == expected
    assert set(tested.shapes) == {s for cell in expected for s in world.grid.shapes_at(*cell)}
    # The ring of cells around the body that the old overlay washed is not drawn.
    col, row = int(player.box.x // TILE), int(player.box.y // TILE)
    ring = {(c, r) for c in range(col - 1, col + 2) for r in range(row - 1, row + 3)}
    untested = ring - expected
    assert untested
    picture = overlay_alone(world, assets)
    hitbox = player.box.to_rect().move(*(-v for v in screen_offset(world.camera)))
    for cell in sorted(untested):
        x, y = cell_corner_on_screen(world, *cell)
        inside = pygame.Rect(x + 1, y + 1, TILE - 2, TILE - 2)
        for px in range(inside.left, inside.right):
            for py in range(inside.top, inside.bottom):
                if not hitbox.inflate(2, 2).collidepoint(px, py):
                    assert picture.get_at((px, py)) == BLACK, (cell, px, py)


def test_without_the_query_log_the_overlay_washes_no_cell(assets: Assets) -> None:
    world = World(level_from_ascii(FLOOR))
    world.step(NOTHING)
    assert world.query_log.queries == []
    assert Checked(world.grid, world.query_log).all_cells() == set()


def frames_of(level: Path, assets: Assets) -> Iterator[tuple[pygame.Surface, World]]:
    """Play ``level`` with the overlay's query log on, by its winning script if it has one
    (standing still if not), and yield the picture under the overlay every few ticks."""
    campaign = Campaign(level, loader=lambda path: load_level(path, images=True),
                        measure=Measure(queries=True))
    script_path = SCRIPTS / f"{level.stem}.txt"
    script = input_script(script_path) if script_path.exists() else None
    renderer = WorldRenderer(assets)
    while campaign.outcome is Outcome.RUNNING and campaign.world.level.path == level:
        campaign.tick(script.held_at(campaign.ticks) if script else NOTHING)
        if campaign.ticks % EVERY_NTH_TICK or campaign.world.level.path != level:
            continue
        if script is None and campaign.ticks > 600:
            break
        frame = pygame.Surface((320, 180))
        renderer.draw(frame, campaign.world, campaign.ticks)
        draw_hud(frame, campaign, assets)
        yield frame, campaign.world


def same_pixels(a: pygame.Surface, b: pygame.Surface) -> bool:
    """Do the two surfaces show the same colours everywhere? Equal memory says so at once;
    otherwise the colours alone are compared (the unused fourth byte of a pixel may differ)."""
    return a.get_buffer().raw == b.get_buffer().raw or (
        pygame.image.tobytes(a, "RGB") == pygame.image.tobytes(b, "RGB"))


@pytest.mark.parametrize("level", ["levels/01-first-steps.tmx", "levels/04-moving-parts.tmx",
                                   "levels/06-the-summit.tmx", "levels/showcase/fast-fall.tmx"])
def test_the_overlay_paints_exactly_what_drawing_it_the_plain_way_paints(
        assets: Assets, level: str) -> None:
    compared = 0
    for frame, world in frames_of(ROOT / level, assets):
        if compared % 2:  # every other frame, on a target bigger than the camera's view
            bigger = pygame.Surface(BIGGER_TARGET)
            bigger.blit(frame, (0, 0))
            frame = bigger
        quick, plain = frame.copy(), frame.copy()
        draw_debug(quick, world, assets, fps=60.0, update_ms=1.25)
        draw_debug_plainly(plain, world, assets, fps=60.0, update_ms=1.25)
        assert same_pixels(quick, plain), (level, world.player.box)
        compared += 1
    assert compared > 100


def test_a_frame_drawn_again_renders_no_panel_line_and_no_cell_squares_again(
        assets: Assets) -> None:
    world = World(level_from_ascii(FLOOR), measure=Measure(queries=True))
    world.step(NOTHING)
    overlay_alone(world, assets)
    lines = debug_overlay._line_face.cache_info().misses
    squares = debug_overlay._squares.cache_info()
    overlay_alone(world, assets)
    assert debug_overlay._line_face.cache_info().misses == lines
    assert debug_overlay._squares.cache_info().misses == squares.misses
    assert debug_overlay._squares.cache_info().hits > squares.hits  # the cells were stamped
