"""The collision lab: its command line, and every scene driven by posted mouse and key events.

Each scene test posts events with ``pygame.event.post``, runs one testbed frame, and checks
that what the panel says is what the collision reference answers for the same shapes.
"""

from __future__ import annotations

import hashlib
import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pygame
import pytest

from game.collision.aabb import Box
from game.collision.circles import bounding_circle, circles_may_touch
from game.collision.masks import contact_point
from game.collision.sat import Polygon, collide
from game.collision.swept import discrete_hit, sweep
from game.lab.catalogue import SCENES
from game.lab.circle_precheck import CirclePrecheck
from game.lab.circles import Circles
from game.lab.cli import main
from game.lab.composite import CompositeScene
from game.lab.contacts import Contacts
from game.lab.masks import Masks
from game.lab.overlap import WALL, Overlap, collision_status
from game.lab.party_grid import PartyGrid
from game.lab.platformer import ORIGIN, Platformer
from game.lab.polygons import Polygons
from game.lab.quadtree import QuadtreeScene
from game.lab.response import ARENA, Response
from game.lab.rotated_box import RotatedBox
from game.lab.scene import AREA, GROUPS, LAB_H_PX, LAB_W_PX, Layer, Scene
from game.lab.screen_grid import ScreenGrid
from game.lab.sort_and_sweep import SortAndSweepScene
from game.lab.testbed import MENU_ROW_PX, MENU_TOP_PX, Lab
from game.lab.tunnelling import LANES, Tunnelling, wall_of
from game.lab.xray import XRay
from tests.in_process import call_main

ROOT = Path(__file__).resolve().parent.parent
NAMES = [scene.name for scene in SCENES]


pytestmark = pytest.mark.usefixtures("lab_display")


# --- posting events ------------------------------------------------------------------------
def key(bed: Lab, *keys: int) -> None:
    """Press and release each key, one frame each."""
    for k in keys:
        pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=k, mod=0, unicode=""))
        pygame.event.post(pygame.event.Event(pygame.KEYUP, key=k, mod=0, unicode=""))
        bed.frame()


def hold(bed: Lab, k: int) -> None:
    pygame.event.post(pygame.event.Event(pygame.KEYDOWN, key=k, mod=0, unicode=""))


def drag(bed: Lab, start: tuple[float, float], end: tuple[float, float]) -> None:
    """Press at ``start``, move to ``end``, let go: one frame."""
    a = (round(start[0]), round(start[1]))
    b = (round(end[0]), round(end[1]))
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=a, button=1))
    pygame.event.post(pygame.event.Event(pygame.MOUSEMOTION, pos=b, rel=(b[0] - a[0], b[1] - a[1]),
                                         buttons=(1, 0, 0)))
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONUP, pos=b, button=1))
    bed.frame()


def hover(bed: Lab, at: tuple[float, float]) -> None:
    spot = (round(at[0]), round(at[1]))
    pygame.event.post(pygame.event.Event(pygame.MOUSEMOTION, pos=spot, rel=(0, 0),
                                         buttons=(0, 0, 0)))
    bed.frame()


def click(bed: Lab, at: tuple[float, float]) -> None:
    spot = (round(at[0]), round(at[1]))
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONDOWN, pos=spot, button=1))
    pygame.event.post(pygame.event.Event(pygame.MOUSEBUTTONUP, pos=spot, button=1))
    bed.frame()


def open_scene(name: str) -> tuple[Lab, Scene]:
    bed = Lab(SCENES, start=name)
    bed.frame()
    assert bed.scene is not None
    return bed, bed.scene


def status(scene: Scene) -> str:
    return "\n".join(scene.status())


def centre(box: Box) -> tuple[float, float]:
    return box.center


# --- the command line ---------------------------------------------------------------------
def test_list_prints_bare_names_one_a_line_for_a_script(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--list"]) == 0  # captured: not a terminal, so the public one-name-a-line form
    rows = capsys.readouterr().out.splitlines()
    assert rows == NAMES
    assert all(re.fullmatch(r"[A-Za-z0-9-]+", row) for row in rows)


def test_list_long_names_at_least_twelve_scenes_each_first_on_its_line_with_group_and_title(
        capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["--list", "--long"]) == 0
    rows = capsys.readouterr().out.splitlines()
    names = [row.split()[0] for row in rows]
    assert names == NAMES
    assert len(names) >= 12 and len(set(names)) == len(names)
    assert all(re.fullmatch(r"[A-Za-z0-9-]+", name) for name in names)
    for row, scene in zip(rows, SCENES, strict=True):
        assert row.split(None, 1)[1].split() == f"{scene.group} {scene.title}".split()
    assert [scene.group for scene in SCENES] == sorted(
        (scene.group for scene in SCENES), key=GROUPS.index)  # the list keeps groups together


def test_an_unknown_scene_is_bad_usage_with_the_list_on_stderr() -> None:
    result = call_main(main, ["--scene", "no-such-scene", "--screenshot", "unused.png"],
                       cwd=ROOT)
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    assert "no-such-scene" in result.stderr
    assert all(name in result.stderr.split() for name in NAMES)
    assert not (ROOT / "unused.png").exists()


def test_zero_frames_is_bad_usage() -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["--scene", "overlap", "--screenshot", "x.png", "--frames", "0"])
    assert exit_info.value.code == 2


def test_every_scene_draws_headless_and_no_two_pictures_are_the_same(tmp_path: Path) -> None:
    digests = {}
    for name in NAMES:
        path = tmp_path / f"{name}.png"
        assert main(["--scene", name, "--screenshot", str(path), "--frames", "2"]) == 0
        image = pygame.image.load(str(path))
        assert image.get_size() == (LAB_W_PX, LAB_H_PX)
        digests[name] = hashlib.sha256(pygame.image.tobytes(image, "RGB")).hexdigest()
    assert len(set(digests.values())) == len(NAMES)


def test_the_screenshot_command_runs_as_a_program(tmp_path: Path) -> None:
    env = {**os.environ, "SDL_VIDEODRIVER": "dummy", "SDL_AUDIODRIVER": "dummy"}
    path = tmp_path / "overlap.png"
    result = subprocess.run([sys.executable, "-m", "game.lab", "--scene", "overlap",
                             "--screenshot", str(path)], cwd=ROOT, env=env,
                            capture_output=True, text=True, timeout=60, check=False)
    assert result.returncode == 0, result.stderr
    assert path.stat().st_size > 1000


def test_an_unwritable_screenshot_says_so_in_one_line(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "missing-folder" / "x.png"
    assert main(["--scene", "overlap", "--screenshot", str(target)]) == 1
    err = capsys.readouterr().err
    assert "its folder does not exist" in err and len(err.strip().splitlines()) == 1
    assert not target.parent.exists()  # no folder is made


# --- the testbed ----------------------------------------------------------------------------
def test_the_list_opens_a_scene_with_keys_and_esc_goes_back() -> None:
    bed = Lab(SCENES)
    key(bed, pygame.K_DOWN, pygame.K_RETURN)
    assert bed.scene is not None and bed.scene.name == NAMES[1]
    key(bed, pygame.K_ESCAPE)
    assert bed.scene is None and bed.running
    key(bed, pygame.K_ESCAPE)
    assert not bed.running


def test_a_click_in_the_list_opens_that_scene() -> None:
    bed = Lab(SCENES)
    click(bed, (60, MENU_TOP_PX + MENU_ROW_PX * 3 + 5))
    assert bed.scene is not None and bed.scene.name == NAMES[3]


def test_pause_single_step_and_restart() -> None:
    bed, scene = open_scene("response")
    assert isinstance(scene, Response)
    start = {k: c.box for k, c in scene.crates.items()}
    key(bed, pygame.K_p)
    paused = {k: c.box for k, c in scene.crates.items()}
    bed.frame()
    bed.frame()
    assert {k: c.box for k, c in scene.crates.items()} == paused
    key(bed, pygame.K_n)
    assert {k: c.box for k, c in scene.crates.items()} != paused
    key(bed, pygame.K_r)
    assert bed.scene is not None and bed.scene is not scene
    assert isinstance(bed.scene, Response)
    fresh = bed.scene
    assert {k: c.box for k, c in fresh.crates.items()} == start  # back to its first frame


def test_number_keys_switch_the_debug_layers() -> None:
    bed, scene = open_scene("rotated-box")
    assert Layer.BOUNDS in scene.layers
    key(bed, pygame.K_2)
    assert Layer.BOUNDS not in scene.layers
    key(bed, pygame.K_2)
    assert Layer.BOUNDS in scene.layers


@pytest.mark.parametrize("name", NAMES)
def test_every_scene_follows_a_drag_and_answers_in_its_panel(name: str) -> None:
    bed, scene = open_scene(name)
    key(bed, pygame.K_p)  # paused: only the drag moves anything
    grabbable = scene.grab_boxes()
    assert grabbable, f"{name} has nothing to drag"
    # The first shape whose middle no later (higher) shape covers: a press there grabs it.
    shape, box = next((k, b) for i, (k, b) in enumerate(grabbable.items())
                      if not any(o.overlaps(Box(*b.center, 1, 1))
                                 for o in list(grabbable.values())[i + 1:]))
    before = scene.pos[shape]
    drag(bed, centre(box), (box.center[0] + 12, box.center[1] + 8))
    after = scene.grab_boxes()[shape]
    if name == "tunnelling":  # the walls only slide along x
        assert (after.x - box.x, after.y - box.y) == (12, 0)
    else:
        assert (after.x - box.x, after.y - box.y) == (12, 8)
    assert scene.pos[shape] != before
    assert any(line.strip() for line in scene.status())


# --- each scene against the reference --------------------------------------------------------
def test_overlap_dragged_flush_against_the_wall_reads_touching_not_colliding() -> None:
    bed, scene = open_scene("overlap")
    assert isinstance(scene, Overlap)
    player = scene.player()
    drag(bed, player.center, (player.center[0] - 100, player.center[1]))
    assert scene.status()[0] == "Collision status: apart"
    drag(bed, (player.center[0] - 100, player.center[1]), player.center)
    player = scene.player()
    assert player.right == WALL.left
    assert scene.status()[0] == "Collision status: touching"
    assert not player.overlaps(WALL) and player.touches(WALL)
    key(bed, pygame.K_RIGHT)
    assert scene.status()[0] == "Collision status: colliding"
    assert scene.player().overlaps(WALL)
    key(bed, pygame.K_z)  # a zero-width box inside the wall overlaps nothing
    assert scene.player().w == 0
    assert scene.status()[0] == f"Collision status: {collision_status(scene.player(), WALL)}"
    assert scene.status()[0] == "Collision status: apart"
    key(bed, pygame.K_z)
    wall = scene.wall()  # now drag the wall off the player: flush on its other side
    shift = scene.player().left - wall.right
    drag(bed, wall.center, (wall.center[0] + shift, wall.center[1]))
    assert scene.wall().right == scene.player().left
    assert scene.status()[0] == "Collision status: touching"


def test_the_window_opens_a_scene_and_closes_on_quit() -> None:
    from game.lab.cli import window

    pygame.display.quit()  # the window is made afresh, as by a reader's first run
    pygame.display.init()
    pygame.event.post(pygame.event.Event(pygame.QUIT))
    assert window("overlap") == 0
    assert not pygame.display.get_init()  # it closed behind itself
    pygame.display.init()


def test_screen_grid_floors_a_negative_position_where_int_would_not() -> None:
    bed, scene = open_scene("screen-grid")
    assert isinstance(scene, ScreenGrid)
    key(bed, pygame.K_LEFT, pygame.K_UP, pygame.K_UP)
    world = scene.world()
    assert world.x == -53.0 and world.y == 29.75
    rect = world.to_rect()
    assert (rect.x, rect.y) == (math.floor(world.x), math.floor(world.y))
    assert f"Box.to_rect(): Rect({rect.x}, {rect.y}, 16, 16)" in scene.status()
    assert "grid cell (40 px, floor): (-2, 0)" in scene.status()


def test_rotated_box_aabb_is_wrong_in_the_empty_corner_and_sat_is_not() -> None:
    bed, scene = open_scene("rotated-box")
    assert isinstance(scene, RotatedBox)
    bar, probe = scene.bar(), scene.probe()
    assert probe.overlaps(bar.bounds()) and collide(Polygon.from_box(probe), bar) is None
    assert "AABB is wrong: a false hit in an empty corner" in scene.status()
    assert scene.false_spots and len(scene.false_spots) < scene.spots_sampled
    width = bar.bounds().w
    key(bed, *[pygame.K_RIGHT] * 12)  # 30 + 60 = 90 degrees: upright
    assert "angle: 90 degrees" in scene.status()
    assert scene.bar().bounds().w < width
    drag(bed, scene.probe().center, scene.pos["bar"])
    assert scene.aabb_hit and scene.sat_hit
    assert "both agree" in scene.status()


def test_polygons_name_the_separating_axis_then_push_out_to_touching() -> None:
    bed, scene = open_scene("polygons")
    assert isinstance(scene, Polygons)
    assert collide(scene.shape("a"), scene.shape("b")) is None
    assert any(line.startswith("separating axis:") for line in scene.status())
    drag(bed, scene.pos["a"], (scene.pos["a"][0] + 90, scene.pos["a"][1]))
    mtv = collide(scene.shape("a"), scene.shape("b"))
    assert mtv is not None and scene.separating is None
    assert f"push-out for A: ({mtv.vector[0]:+.1f}, {mtv.vector[1]:+.1f}) px" in scene.status()
    key(bed, pygame.K_m)
    left = collide(scene.shape("a"), scene.shape("b"))
    assert left is None or left.depth < 1e-9  # touching, give or take float rounding
    key(bed, pygame.K_TAB)
    assert scene.status()[-3].startswith("drawn: axis #")


def test_circles_answer_with_the_circle_functions_and_flag_the_square() -> None:
    bed, scene = open_scene("circles")
    assert isinstance(scene, Circles)
    assert scene.square_box and not scene.ball_box
    assert any("wrong: a corner" in line for line in scene.status())
    drag(bed, scene.pos["ball"], (scene.pos["other"][0] + 100, scene.pos["other"][1]))
    assert scene.ball_ball == scene.ball().overlaps(scene.other())
    assert scene.ball_ball  # 100 px apart, radii sum 110
    assert "Circle.overlaps:     hit" in scene.status()[0]


def test_circle_precheck_counts_the_box_tests_it_skipped() -> None:
    _, scene = open_scene("circle-precheck")
    assert isinstance(scene, CirclePrecheck)
    probe = scene.probe()
    mine = bounding_circle(Box.from_rect(probe))
    maybe = [r for r in scene.crowd if circles_may_touch(mine, bounding_circle(Box.from_rect(r)))]
    skipped = len(scene.crowd) - len(maybe)
    assert f"box tests skipped by the pre-check: {skipped}" in scene.status()
    assert 0 < skipped < len(scene.crowd)
    assert scene.hits == [r for r in scene.crowd if probe.colliderect(r)]
    assert "  same hits: yes" in scene.status()


def test_masks_show_the_first_overlapping_pixel() -> None:
    bed, scene = open_scene("masks")
    assert isinstance(scene, Masks)
    assert scene.rects_hit and not scene.pixel_hit
    assert "  the rects alone are wrong here" in scene.status()
    drag(bed, scene.pos["ball"], scene.pos["bar"])
    first = contact_point(scene.placed("ball"), scene.placed("bar"))
    assert first is not None and scene.first == first
    assert f"first overlapping pixel: {first}" in scene.status()


def test_composite_parts_see_the_notch_the_bounding_box_covers() -> None:
    bed, scene = open_scene("composite")
    assert isinstance(scene, CompositeScene)
    assert scene.bounds_hit and not scene.parts_hit
    crate = scene.crate()
    column = crate.world_parts()[0]
    drag(bed, scene.coin().center, column.center)
    assert scene.crate().overlaps(scene.coin())
    assert scene.status()[1] == "Composite.overlaps:    hit"


def test_party_grid_hover_shows_the_query_the_grid_really_made() -> None:
    bed, scene = open_scene("party-grid")
    assert isinstance(scene, PartyGrid)
    key(bed, pygame.K_p)
    body = scene.crowd.boxes[5]
    hover(bed, body.center)
    assert scene.hovered == 5
    n = len(scene.crowd.boxes)
    # The query tests the hovered body and every body sharing one of its cells, once each.
    assert scene.query_tests == len(scene.neighbours) + 1
    tested = "1 body" if scene.query_tests == 1 else f"{scene.query_tests} bodies"
    assert f"  tests {tested} (itself too)," in scene.status()
    assert scene.hover_cells == list(scene.grid.cell_range(body).cells())
    assert scene.pairs == scene.brute_pairs
    assert scene.brute_tests == n * (n - 1) // 2
    assert scene.grid_tests < scene.brute_tests // 10


def test_quadtree_splits_as_bodies_are_added() -> None:
    bed, scene = open_scene("quadtree")
    assert isinstance(scene, QuadtreeScene)
    nodes = scene.tree.node_count()
    count = len(scene.crowd.boxes)
    click(bed, (AREA.right - 20, AREA.bottom - 20))
    assert len(scene.crowd.boxes) == count + 1
    key(bed, *[pygame.K_a] * 5)
    assert scene.tree.node_count() > nodes
    assert any("same as brute force: yes" in line for line in scene.status())
    key(bed, pygame.K_BACKSPACE)
    assert len(scene.crowd.boxes) == count + 30


def test_sort_and_sweep_stacked_in_a_column_tests_far_more_pairs() -> None:
    bed, scene = open_scene("sort-and-sweep")
    assert isinstance(scene, SortAndSweepScene)
    key(bed, pygame.K_p)
    spread = scene.sweep.stats.pair_tests
    key(bed, pygame.K_s)
    stacked = scene.sweep.stats.pair_tests
    assert stacked > 5 * spread
    assert any("same as brute force: yes" in line for line in scene.status())


def test_tunnelling_raise_the_speed_and_the_discrete_test_misses_but_the_sweep_does_not() -> None:
    bed, scene = open_scene("tunnelling")
    assert isinstance(scene, Tunnelling)
    key(bed, pygame.K_p, pygame.K_DOWN, pygame.K_DOWN)  # 24 px a tick: slower than 20 + 8
    assert scene.speed_px == 24
    while not all(f.done for f in scene.flights):
        key(bed, pygame.K_n)
    assert all(f.outcome.startswith("hit") for f in scene.flights)
    key(bed, pygame.K_UP, pygame.K_UP)  # 40 px a tick: faster than 20 + 8
    assert scene.speed_px == 40
    for _ in range(30):
        key(bed, pygame.K_n)
    outcome = dict(zip(LANES, scene.flights, strict=True))
    assert outcome["discrete"].outcome.startswith("TUNNELLED")
    assert outcome["swept"].outcome.startswith("hit")
    swept_lane = LANES.index("swept")
    assert outcome["swept"].box.right == wall_of(swept_lane).left  # flush
    # The reference agrees, move by move: the sweep catches the move the discrete check missed.
    wall = wall_of(LANES.index("discrete"))
    crossing = next(b for b in [*outcome["discrete"].trail, outcome["discrete"].box]
                    if b.right + 40 > wall.left)
    assert not discrete_hit(crossing, 40, 0, wall)
    assert sweep(crossing, 40, 0, wall) is not None
    assert "discrete: TUNNELLED" in status(scene)


def test_response_conserves_energy_when_perfectly_bouncy_and_never_gains_it_otherwise() -> None:
    bed, scene = open_scene("response")
    assert isinstance(scene, Response)
    key(bed, pygame.K_e, pygame.K_v, pygame.K_v)  # restitution 1.0, friction 0.0
    assert scene.restitution == 1.0 and scene.friction == 0.0
    assert "restitution 1.0  (E up, D down)" in scene.status()
    energy = scene.energy
    for _ in range(120):
        bed.frame()
    assert scene.energy == pytest.approx(energy, rel=1e-9)
    key(bed, *[pygame.K_d] * 5, pygame.K_f, pygame.K_f)
    previous = scene.energy
    for _ in range(120):
        bed.frame()
        assert scene.energy <= previous * (1 + 1e-12)
        previous = scene.energy
    for crate in scene.crates.values():
        assert ARENA.left <= crate.box.left and crate.box.right <= ARENA.right


def test_contacts_log_one_start_for_a_long_touch() -> None:
    bed, scene = open_scene("contacts")
    assert isinstance(scene, Contacts)
    key(bed, pygame.K_p)
    target = scene.boxes()["0"]
    drag(bed, scene.boxes()["slider"].center, target.center)
    key(bed, pygame.K_p)  # run: the slider is no longer held, so it swings on
    started = [e for e in scene.tracker.log if str(e).endswith("('0', 'slider') started")]
    assert len(started) == 1
    for _ in range(200):
        bed.frame()
    assert len(scene.tracker.log) <= 10
    assert scene.events < scene.flood_lines
    assert f"'print every tick' would have printed {scene.flood_lines} lines" in scene.status()


def test_the_tunnelling_picture_says_what_the_readme_says() -> None:
    bed, scene = open_scene("tunnelling")
    for _ in range(390 - 1):
        bed.frame()
    assert isinstance(scene, Tunnelling)
    lanes = dict(zip(LANES, scene.flights, strict=True))
    assert lanes["discrete"].outcome.startswith("TUNNELLED")
    assert lanes["sub-steps"].outcome.endswith(", 8 px inside")
    assert lanes["swept"].outcome.startswith("hit") and "flush" in lanes["swept"].outcome
    assert lanes["speed clamp"].ticks - lanes["swept"].ticks == 14
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "two sub-steps catch it 8 px deep, the clamp catches it 14 ticks late" in readme
    assert '"tunnelling": 390' in (ROOT / "game/tools/lab_screenshots.py").read_text("utf-8")


def test_the_contacts_picture_says_what_the_readme_says() -> None:
    """The README quotes the contacts picture's figures; they come from a deterministic run."""
    bed, scene = open_scene("contacts")
    for _ in range(420 - 1):
        bed.frame()
    assert scene.ticks == 420
    assert "events so far: 16 (starts and ends)" in scene.status()
    assert "'print every tick' would have printed 557 lines" in scene.status()
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "after 420 ticks the tracker has logged 16 starts and ends" in readme
    assert "would have written 557 lines" in readme
    assert '"contacts": 420' in (ROOT / "game/tools/lab_screenshots.py").read_text("utf-8")


def test_xray_the_round_sprites_square_box_is_wrong_in_its_corner() -> None:
    bed, scene = open_scene("x-ray")
    assert isinstance(scene, XRay)
    assert scene.ball_rect_hit and not scene.ball_true_hit
    assert "  the square box is wrong: empty corner" in scene.status()
    key(bed, pygame.K_x)
    assert scene.status()[0] == "x-ray: off (X)"
    ball = scene.grab_boxes()["ball"]
    drag(bed, scene.grab_boxes()["player"].center, ball.center)
    assert scene.ball_true_hit and scene.ball_rect_hit


def test_platformer_runs_into_a_wall_and_stops_flush_recording_the_cells_it_swept() -> None:
    bed, scene = open_scene("platformer")
    assert isinstance(scene, Platformer)
    hold(bed, pygame.K_RIGHT)
    for _ in range(90):
        bed.frame()
    body = scene.body()
    assert body.right == 352  # the wall column starts at 11 * 32
    assert "on ground (ground_under): yes" in scene.status()
    for _axis, move, cells, visited, _tested in scene.last:
        assert visited == len(cells) == len(list(scene.grid.cells_covering(move.swept)))
    x_move = scene.last[0][1]
    assert x_move.hit is not None and x_move.hit.face == 352
    key(bed, pygame.K_f)  # twenty times faster: 50 px a tick, into the same wall
    body = scene.body()
    key(bed, pygame.K_p)
    drag(bed, scene.grab_boxes()["body"].center,
         (ORIGIN[0] + 196 + body.w / 2, ORIGIN[1] + 228 - 60 + body.h / 2))
    assert scene.body().x == 196  # 156 px from the wall: a bit over three ticks
    key(bed, pygame.K_p)
    for _ in range(30):
        bed.frame()
        assert scene.body().right <= 352
    assert scene.body().right == 352


def test_the_readme_shows_every_scene_and_links_the_techniques_to_them() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    for scene in SCENES:
        picture = f"assets/screenshots/lab/{scene.name}.png"
        assert f"![{scene.name}]({picture})" in readme
        assert (ROOT / picture).exists()
        module = sys.modules[scene.__module__].__file__
        assert module is not None
        link = f"(game/lab/{Path(module).name})"
        assert link in readme, f"no technique row links to {scene.name}"
    table = readme.split("| technique | module |")[1].split("\n\n")[0]
    rows = [row for row in table.splitlines() if row.startswith("| ") and "---" not in row]
    assert len(rows) >= 15 and all("(game/lab/" in row.rsplit("|", 2)[1] for row in rows)


def test_the_lab_adds_nothing_to_the_game() -> None:
    """No module of the game outside the lab imports it, so a tick cannot run lab code."""
    offenders = [p for p in (ROOT / "game").rglob("*.py")
                 if "lab" not in p.relative_to(ROOT / "game").parts
                 and re.search(r"^\s*(from|import)\s+game\.lab", p.read_text(encoding="utf-8"),
                               re.MULTILINE)]
    assert offenders == []


def test_the_pictures_run_long_enough_to_fill_the_timing_window() -> None:
    from game.lab.cost import WINDOW
    from game.tools.lab_screenshots import DEFAULT_FRAMES, FRAMES

    assert DEFAULT_FRAMES == WINDOW + 1
    assert all(frames > WINDOW for frames in FRAMES.values())
