"""The lab as a testbed: scenes by group with next and previous keys, a view to zoom and pan
with the mouse, layers and parameters on screen and clickable, nothing carried over from the
scene before, a timing with its spread (or a reason for none) in every scene, and panels that
say what the shapes in them do. Everything is driven by posted mouse and key events, headless,
and read back from the panel."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pygame
import pytest

from game.app.window import DESKTOP_SHARE_PERCENT, window_size
from game.collision.aabb import Box
from game.lab import canvas
from game.lab.catalogue import SCENES
from game.lab.overlap import WALL, Overlap, collision_status
from game.lab.party_grid import PartyGrid
from game.lab.platformer import MAP, TILE_PX, on_screen
from game.lab.scene import AREA, GROUPS, LAB_H_PX, LAB_W_PX, PANEL, Layer, Scene
from game.lab.testbed import (
    COMMON_HELP,
    HELP_Y,
    KEY_Y,
    MENU_TOP_PX,
    PAUSED,
    Lab,
    fit_window,
    menu_rows,
    paused_x,
    screen,
    title_line,
)
from game.lab.tunnelling import LANES, TICKS_PER_STEP_RUNNING, Tunnelling, verdict_color
from game.sim.camera import VIEW_H_PX, VIEW_W_PX
from game.tools.lab_screenshots import DEFAULT_FRAMES, FRAMES

ROOT = Path(__file__).resolve().parent.parent
NAMES = [scene.name for scene in SCENES]
TIMING_FRAMES = 5


pytestmark = pytest.mark.usefixtures("lab_display")


def post(kind: int, **fields: Any) -> None:
    pygame.event.post(pygame.event.Event(kind, **fields))


def key(bed: Lab, *keys: int) -> None:
    for k in keys:
        post(pygame.KEYDOWN, key=k, mod=0, unicode="")
        post(pygame.KEYUP, key=k, mod=0, unicode="")
        bed.frame()


def click(bed: Lab, at: tuple[int, int], button: int = 1) -> None:
    post(pygame.MOUSEBUTTONDOWN, pos=at, button=button)
    post(pygame.MOUSEBUTTONUP, pos=at, button=button)
    bed.frame()


def drag(bed: Lab, start: tuple[int, int], end: tuple[int, int], button: int = 1) -> None:
    post(pygame.MOUSEBUTTONDOWN, pos=start, button=button)
    post(pygame.MOUSEMOTION, pos=end, rel=(end[0] - start[0], end[1] - start[1]),
         buttons=(1, 0, 0))
    post(pygame.MOUSEBUTTONUP, pos=end, button=button)
    bed.frame()


def move_mouse(bed: Lab, at: tuple[int, int]) -> None:
    post(pygame.MOUSEMOTION, pos=at, rel=(0, 0), buttons=(0, 0, 0))
    bed.frame()


def wheel(bed: Lab, clicks: int) -> None:
    post(pygame.MOUSEWHEEL, x=0, y=clicks, flipped=False)
    bed.frame()


def open_scene(name: str) -> tuple[Lab, Scene]:
    bed = Lab(SCENES, start=name)
    bed.frame()
    assert bed.scene is not None
    return bed, bed.scene


def row_of(bed: Lab, starts: str) -> tuple[int, int]:
    """The middle of the first panel row whose words start with ``starts`` (stripped)."""
    row = next(r for r in bed.panel_rows() if r.text.strip().startswith(starts))
    return row.rect.center


def picture(bed: Lab) -> bytes:
    surface = screen()
    bed.draw(surface)
    return pygame.image.tobytes(surface.subsurface(AREA), "RGB")


def without_timing(lines: list[str]) -> list[str]:
    """The panel's words less the timings, which move from frame to frame."""
    return [line for line in lines if not re.search(r"\d (ns|us|ms) to \d", line)
            and "takes" not in line and "per pair test" not in line and "brute " not in line]


# --- groups and the next and previous keys --------------------------------------------------
def test_every_scene_is_in_a_group_and_the_list_keeps_each_group_together() -> None:
    assert {scene.group for scene in SCENES} == set(GROUPS)
    seen = [scene.group for scene in SCENES]
    assert seen == sorted(seen, key=GROUPS.index)


def test_page_down_and_page_up_walk_every_scene_in_the_lists_order_and_wrap() -> None:
    bed, _ = open_scene(NAMES[0])
    walked = [NAMES[0]]
    for _ in NAMES:
        key(bed, pygame.K_PAGEDOWN)
        assert bed.scene is not None
        walked.append(bed.scene.name)
    assert walked == [*NAMES, NAMES[0]]
    key(bed, pygame.K_PAGEUP)
    assert bed.scene is not None and bed.scene.name == NAMES[-1]


# --- layers: only the scene's own, all on when it opens, clickable ---------------------------
@pytest.mark.parametrize("name", NAMES)
def test_the_legend_lists_only_the_layers_the_scene_draws_and_a_click_switches_one(
        name: str) -> None:
    bed, scene = open_scene(name)
    for _ in range(TIMING_FRAMES):
        bed.frame()
    key(bed, pygame.K_p)
    text = "\n".join(bed.panel_text())
    for layer in Layer:
        assert (f"] {layer.value}" in text) == (layer in scene.draws), layer
    assert scene.layers == set(scene.draws)
    for number, layer in enumerate(Layer, start=1):
        if layer not in scene.draws:
            key(bed, pygame.K_0 + number)  # a layer the scene does not draw: no effect
            assert scene.layers == set(scene.draws)
    for layer in scene.draws:
        before = picture(bed)
        click(bed, row_of(bed, f"{list(Layer).index(layer) + 1} [x] {layer.value}"))
        assert layer not in scene.layers
        assert f"[ ] {layer.value}" in "\n".join(bed.panel_text())
        after = picture(bed)
        click(bed, row_of(bed, f"{list(Layer).index(layer) + 1} [ ] {layer.value}"))
        assert layer in scene.layers
        if layer is Layer.SHAPES:  # the others may have nothing to show in this state
            assert after != before, f"{name}: switching off the shapes changed nothing"


class Asked(set[Layer]):
    """A set of layers that remembers which layers it was asked about."""

    def __init__(self, layers: set[Layer]) -> None:
        super().__init__(layers)
        self.asked: set[Layer] = set()

    def __contains__(self, layer: object) -> bool:
        if isinstance(layer, Layer):
            self.asked.add(layer)
        return super().__contains__(layer)


@pytest.mark.parametrize("name", NAMES)
def test_a_scene_draws_exactly_the_layers_its_legend_lists(name: str) -> None:
    bed, scene = open_scene(name)
    layers = Asked(set(Layer))
    for _ in range(3):
        bed.frame()
        scene.draw(screen(), layers)
    assert layers.asked == set(scene.draws)


def test_a_layer_switched_off_does_not_carry_over_to_the_next_scene() -> None:
    bed, first = open_scene("overlap")
    key(bed, pygame.K_1)
    assert Layer.SHAPES not in first.layers
    key(bed, pygame.K_PAGEDOWN)
    assert bed.scene is not None and bed.scene.layers == set(bed.scene.draws)
    key(bed, pygame.K_PAGEUP)
    assert bed.scene is not None and Layer.SHAPES in bed.scene.layers  # opened afresh


def test_the_rotated_box_speaks_of_its_orange_dots_only_while_they_are_drawn() -> None:
    bed, scene = open_scene("rotated-box")
    assert any("(orange dots)" in line for line in scene.status())
    key(bed, pygame.K_3)
    assert not any("orange" in line for line in scene.status())
    assert any("(layer 3 shows them)" in line for line in scene.status())


# --- parameters: on screen with their values, and clickable ------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_every_parameter_button_does_what_its_key_does_and_the_panel_says_so(name: str) -> None:
    bed, scene = open_scene(name)
    key(bed, pygame.K_p)  # paused: only the clicks change anything
    for control in scene.controls():
        for k in control.keys:
            label = pygame.key.name(k)
            before = without_timing(bed.panel_text())
            buttons = [r for r in bed.panel_rows() if r.button and r.text.lower() == label]
            assert buttons, f"{name}: no button for {label}"
            click(bed, buttons[0].rect.center)
            after = without_timing(bed.panel_text())
            nothing_to_do = "nothing to push" in " ".join(before)
            assert (after != before) or nothing_to_do, f"{name}: {label} changed nothing"


def test_tunnelling_speed_buttons_and_keys_change_the_same_number() -> None:
    bed, scene = open_scene("tunnelling")
    assert isinstance(scene, Tunnelling)
    up = next(r for r in bed.panel_rows() if r.button and r.text == "Up")
    click(bed, up.rect.center)
    assert scene.speed_px == 48 and "speed 48 px a tick" in bed.panel_text()[1]
    key(bed, pygame.K_DOWN)
    assert scene.speed_px == 40


# --- the view: zoom and pan with the mouse -----------------------------------------------------
def test_the_wheel_zooms_about_the_mouse_and_a_drag_then_moves_shapes_in_scene_pixels() -> None:
    bed, scene = open_scene("overlap")
    assert isinstance(scene, Overlap)
    key(bed, pygame.K_p)
    player = scene.player()
    spot = (round(player.center[0]), round(player.center[1]))
    move_mouse(bed, spot)
    wheel(bed, 2)  # 1x -> 1.5x -> 2x
    assert bed.view.zoom == 2.0
    under = bed.view.to_scene(spot)
    assert under == pytest.approx(spot)  # the point under the mouse stays put
    drag(bed, spot, (spot[0] + 20, spot[1] + 10))
    moved = scene.player()
    assert (moved.x - player.x, moved.y - player.y) == (10, 5)  # half as far, at 2x
    assert "zoom 2x" in bed.panel_text()[-1]
    before = (bed.view.left, bed.view.top)
    drag(bed, (300, 300), (260, 280), button=3)  # right-drag pans
    assert (bed.view.left - before[0], bed.view.top - before[1]) == (20, 10)
    assert picture(bed) != picture(Lab(SCENES, start="overlap"))
    key(bed, pygame.K_0)
    assert bed.view.zoom == 1.0 and bed.panel_text()[-1].startswith("view: whole scene")
    wheel(bed, -3)
    assert bed.view.zoom == 1.0  # never smaller than the whole scene


def test_a_new_scene_opens_with_the_whole_view() -> None:
    bed, _ = open_scene("overlap")
    wheel(bed, 3)
    key(bed, pygame.K_PAGEDOWN)
    assert bed.view.zoom == 1.0


# --- timing: a median with its spread, or a reason ----------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_every_scene_times_what_it_teaches_with_a_spread_or_says_why_not(name: str) -> None:
    bed, scene = open_scene(name)
    for _ in range(TIMING_FRAMES):
        bed.frame()
    text = bed.panel_text()
    labels = scene.meter.labels()
    if not labels:
        assert scene.timing_note
        assert any(line.startswith("no timing:") for line in text)
        return
    assert any("median (p10 to p90)" in line for line in text)
    for label in labels:
        history = scene.meter.history(label)
        # One a frame, and one as the scene is made (if it has a move to time by then).
        assert TIMING_FRAMES + 1 <= len(history) <= TIMING_FRAMES + 2
        low, high = scene.meter.spread(label)
        assert low <= scene.meter.median(label) <= high
        assert any(line.strip().startswith(f"{label}: ") and " to " in line for line in text)
    graphs = [row for row in bed.panel_rows() if row.graph is not None]
    assert len(graphs) == len(labels)


def test_the_window_of_measurements_keeps_the_last_120() -> None:
    bed, scene = open_scene("overlap")
    for _ in range(130):
        bed.frame()
    assert len(scene.meter.history("Box.overlaps")) == 120


# --- panels computed from the state they describe ----------------------------------------------
def last_lines(scene: Scene) -> str:
    return " ".join(scene.status()[-2:])


def test_overlap_panel_follows_the_player_through_apart_touching_and_colliding() -> None:
    bed, scene = open_scene("overlap")
    assert isinstance(scene, Overlap)
    key(bed, pygame.K_p)
    assert "right edge = wall's left edge" in last_lines(scene)
    assert last_lines(scene).endswith("touching, not colliding (strict <)")
    key(bed, pygame.K_RIGHT)  # 1 px into the wall
    assert scene.status()[0] == "Collision status: colliding"
    assert "the edges cross: 1 px deep along x" in last_lines(scene)
    assert "not colliding" not in last_lines(scene)
    key(bed, pygame.K_LEFT, pygame.K_LEFT, pygame.K_LEFT)  # 2 px short of it
    assert scene.status()[0] == "Collision status: apart"
    assert last_lines(scene) == "a gap of 2 px along x:   apart"
    # Every position from 3 px short to 3 px deep, and the words agree with the status.
    key(bed, *[pygame.K_LEFT])
    for _ in range(7):
        key(bed, pygame.K_RIGHT)
        status = scene.status()[0].removeprefix("Collision status: ")
        assert status == collision_status(scene.player(), WALL)
        assert last_lines(scene).endswith({"apart": "apart",
                                           "touching": "touching, not colliding (strict <)",
                                           "colliding": "colliding (strict < holds both ways)"
                                           }[status])


def test_overlap_panel_names_the_edges_that_meet_on_top_and_at_a_corner() -> None:
    bed, scene = open_scene("overlap")
    assert isinstance(scene, Overlap)
    key(bed, pygame.K_p)
    player = scene.player()
    on_top = (WALL.x + 5 + player.w / 2, WALL.top - player.h + player.h / 2)
    drag(bed, (round(player.center[0]), round(player.center[1])),
         (round(on_top[0]), round(on_top[1])))
    assert scene.player().bottom == WALL.top
    assert "bottom edge = wall's top edge" in last_lines(scene)
    key(bed, *[pygame.K_LEFT] * (5 + round(player.w)))  # off to the left: only corners meet
    assert scene.player().right == WALL.left
    assert "(corner: no shared inside)" in last_lines(scene)
    assert scene.status()[0] == "Collision status: touching"
    key(bed, pygame.K_z)
    assert "overlaps nothing" in last_lines(scene)


def test_party_grid_explains_its_per_test_figures_from_its_own_counts() -> None:
    bed, scene = open_scene("party-grid")
    assert isinstance(scene, PartyGrid)
    for _ in range(TIMING_FRAMES):
        bed.frame()
    text = " ".join(scene.status())
    fewer = scene.brute_tests / scene.grid_tests
    assert f"it makes {fewer:.0f}x fewer tests" in text
    per_grid = scene.meter.median("grid, all pairs") / scene.grid_tests
    per_brute = scene.meter.median("brute force, all pairs") / scene.brute_tests
    assert ("as the grid also files boxes and walks cells" in text) == (per_grid > per_brute)
    assert f"a grid test costs {per_grid / per_brute:.1f}x a brute one" in text


def test_tunnelling_says_it_runs_in_slow_motion_and_does() -> None:
    bed, scene = open_scene("tunnelling")
    assert isinstance(scene, Tunnelling)
    assert scene.status()[0].startswith("SLOW MOTION: 4 ticks a second")
    for _ in range(TICKS_PER_STEP_RUNNING * 2 - 1):
        bed.frame()
    assert [flight.ticks for flight in scene.flights] == [2] * len(LANES)


def test_tunnelling_colours_exact_approximate_right_and_approximate_wrong_apart() -> None:
    bed, scene = open_scene("tunnelling")
    assert isinstance(scene, Tunnelling)
    for _ in range(390 - 1):
        bed.frame()
    colors = {lane: verdict_color(lane, flight)
              for lane, flight in zip(LANES, scene.flights, strict=True)}
    assert colors == {"discrete": canvas.WRONG, "sub-steps": canvas.APPROX_RIGHT,
                      "speed clamp": canvas.APPROX_RIGHT, "swept": canvas.EXACT}
    assert len({canvas.EXACT, canvas.APPROX_RIGHT, canvas.WRONG}) == 3
    assert [color for color, _ in canvas.VERDICTS] == [canvas.EXACT, canvas.APPROX_RIGHT,
                                                      canvas.WRONG]


def test_the_party_grid_picture_says_what_the_readme_says() -> None:
    """The README quotes the party-grid picture's ratio of tests; counts are exact, and the
    crowd drifts the same way every run."""
    bed = Lab(SCENES, start="party-grid")
    for _ in range(121):  # as game.tools.lab_screenshots draws it
        bed.frame()
    assert bed.scene is not None
    assert any("it makes 18x fewer tests" in line for line in bed.scene.status())
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "(18x fewer in the picture)" in readme


# --- the window ----------------------------------------------------------------------------
LAB = (LAB_W_PX, LAB_H_PX)


def test_the_lab_draws_an_800_by_450_screen_that_opens_at_2x_on_1920_by_1080() -> None:
    assert LAB == (800, 450) and screen().get_size() == LAB
    assert window_size((1920, 1080), LAB) == (1600, 900)


@pytest.mark.parametrize("desktop", [(1920, 1080), (3840, 2160), (2000, 1200)])
def test_the_lab_and_the_game_open_the_same_window_where_both_scales_are_whole(
        desktop: tuple[int, int]) -> None:
    """The lab's screen is 2.5 times the game's each way, so wherever the game's scale is
    a multiple of 5 (5x on 1920x1080, 10x on 3840x2160) the two windows are one size."""
    assert LAB_W_PX * 2 == VIEW_W_PX * 5 and LAB_H_PX * 2 == VIEW_H_PX * 5
    assert window_size(desktop, LAB) == window_size(desktop)


@pytest.mark.parametrize("desktop", [(1920, 1080), (1280, 720), (2560, 1440), (3840, 2160)])
def test_the_lab_window_fits_inside_ninety_percent_of_the_desktop_like_the_game(
        desktop: tuple[int, int]) -> None:
    size = window_size(desktop, LAB)
    assert size[0] * LAB_H_PX == size[1] * LAB_W_PX and size[0] % LAB_W_PX == 0  # whole scale
    if size != LAB:  # a 1x window is kept even on a small desktop
        assert all(s * 100 <= d * DESKTOP_SHARE_PERCENT for s, d in zip(size, desktop,
                                                                         strict=True))
    bigger = (size[0] + LAB_W_PX, size[1] + LAB_H_PX)
    assert any(s * 100 > d * DESKTOP_SHARE_PERCENT for s, d in zip(bigger, desktop, strict=True))


def test_fitting_sizes_the_lab_window_for_its_desktop() -> None:
    pygame.display.quit()  # a scaled window is made afresh, as the lab's own is
    pygame.display.init()
    pygame.display.set_mode(LAB, pygame.SCALED | pygame.RESIZABLE)
    window = fit_window()
    desktop = pygame.display.get_desktop_sizes()[window.display_index]
    assert tuple(window.size) == window_size(desktop, LAB)
    pygame.display.quit()
    pygame.display.init()


# --- the layout: everything on the screen, nothing over anything else -------------------------
SCREEN = pygame.Rect(0, 0, LAB_W_PX, LAB_H_PX)


def text_rect(words: str, at: tuple[int, int], size_pt: int = canvas.TEXT_PT) -> pygame.Rect:
    return pygame.Rect(at, canvas.font(size_pt).size(words))


def disjoint(rects: list[pygame.Rect]) -> bool:
    return all(a.collidelist(rects[i + 1:]) == -1 for i, a in enumerate(rects))


def test_the_area_the_panel_and_the_lines_around_them_fit_the_screen_apart() -> None:
    help_line = pygame.Rect(0, HELP_Y, LAB_W_PX, KEY_Y - HELP_Y)
    title_row = pygame.Rect(0, 0, LAB_W_PX, min(AREA.y, PANEL.y))
    assert all(SCREEN.contains(part) for part in (AREA, PANEL, help_line, title_row))
    assert disjoint([AREA, PANEL, help_line, title_row])
    assert text_rect("Xg", (8, 6), canvas.TITLE_PT).bottom <= AREA.y
    assert text_rect("Xg", (8, HELP_Y)).bottom <= KEY_Y
    assert text_rect("Xg", (8, KEY_Y)).bottom <= LAB_H_PX


@pytest.mark.parametrize("name", NAMES)
def test_no_row_of_a_scenes_panel_leaves_the_panel_or_covers_another(name: str) -> None:
    """As the README's picture shows the scene (the frames the pictures run), and then
    paused, which adds PAUSED to the title line."""
    bed, scene = open_scene(name)
    for _ in range(FRAMES.get(name, DEFAULT_FRAMES) - 1):
        bed.frame()
    key(bed, pygame.K_p)
    rows = bed.panel_rows()
    inked = canvas.font().get_height()  # a row of text is drawn this tall; the rest is gap
    boxes = [row.rect if row.button or row.graph is not None
             else pygame.Rect(row.rect.topleft, (row.rect.w, inked)) for row in rows]
    outside = [row.text for row in rows if not PANEL.contains(row.rect)]
    assert not outside, f"{name}: rows past the panel: {outside}"
    assert disjoint(boxes), f"{name}: panel rows drawn over each other"
    title = text_rect(title_line(scene), (8, 6), canvas.TITLE_PT)
    paused = text_rect(PAUSED, (paused_x(), 6), canvas.TITLE_PT)
    assert SCREEN.contains(paused) and title.right < paused.left, f"{name}: title under PAUSED"
    help_line = text_rect(f"{scene.keys_help}  |  {COMMON_HELP}", (8, HELP_Y))
    assert SCREEN.contains(help_line), f"{name}: the help line is cut off"
    key_x = 8
    for _, meaning in canvas.VERDICTS:
        key_x = text_rect(meaning, (key_x, KEY_Y)).right + 16
    assert key_x - 16 <= LAB_W_PX
    grabbable = [box.to_rect() for box in scene.grab_boxes().values()]
    assert all(AREA.contains(box) for box in grabbable), f"{name}: a shape starts off its area"


def test_every_row_of_the_list_fits_above_its_help_line() -> None:
    rows = menu_rows(Lab(SCENES))
    assert rows[0].top >= MENU_TOP_PX and all(SCREEN.contains(row) for row in rows)
    assert max(row.bottom for row in rows) <= HELP_Y
    assert disjoint(rows)


def test_the_platformers_whole_tile_map_is_drawn_inside_the_area() -> None:
    whole = on_screen(Box(0, 0, len(MAP[0]) * TILE_PX, len(MAP) * TILE_PX)).to_rect()
    assert AREA.contains(whole)
