"""The ghost: the best run's inputs, saved beside the progress and replayed in a second world,
reach the same positions tick by tick as the run did; a map changed since shows no ghost; a
bad ghost file is kept aside with one sentence; the window saves a best run without an
assist, and none with one."""

from __future__ import annotations

from pathlib import Path

import pygame
import pytest

from game.app import window as window_module
from game.app.assets import Assets
from game.app.cli import parser
from game.app.ghosts import (
    GHOSTS_DIR,
    Ghost,
    Replay,
    draw_ghost,
    ghost_file,
    load_replay,
    recorded,
    save_ghost,
)
from game.app.run import Run, input_script
from game.app.saves import Attempt, Finish
from game.app.window import GameWindow
from game.levels import FIRST_LEVEL, load_level
from game.sim.camera import VIEW_H_PX, VIEW_W_PX, Camera
from game.sim.campaign import Campaign
from game.sim.inputs import Action
from game.sim.tuning import Tuning
from tests.maps import write_tmx

SCRIPTS = Path(__file__).resolve().parent / "scripts"
FLOOR_TO_EXIT = ["              ", " P    E     D ", "##############"]


def _played(level_path: Path) -> tuple[Finish, Attempt, list[tuple[float, float]], Campaign]:
    """The first level played by its recorded win: the finish, the attempt that watched it,
    and the player's place after each tick."""
    campaign = Campaign(level_path, loader=load_level)
    script = input_script(SCRIPTS / "01-first-steps.txt")
    attempt, places, finish = Attempt(), [], None
    while finish is None and campaign.ticks < 60 * 60:
        attempt.before_tick(campaign)
        held = script.held_at(campaign.ticks)
        world = campaign.world
        events = campaign.tick(held)
        places.append((world.player.box.x, world.player.box.y))
        finish = attempt.after_tick(campaign, events, held)
    assert finish is not None
    return finish, attempt, places, campaign


def test_a_saved_ghost_replays_the_run_to_the_same_places_tick_by_tick(tmp_path: Path) -> None:
    finish, attempt, places, campaign = _played(FIRST_LEVEL)
    ghost = recorded(attempt.inputs, finish.ticks, FIRST_LEVEL)
    assert ghost is not None and save_ghost(ghost, finish.level, tmp_path) is None
    assert (tmp_path / GHOSTS_DIR / "01-first-steps.tmx.json").is_file()
    level = load_level(FIRST_LEVEL)
    replay, problem = load_replay(level, campaign.tuning, tmp_path)
    assert replay is not None and problem is None
    replayed = []
    while not replay.done:
        replay.step()
        replayed.append((replay.world.player.box.x, replay.world.player.box.y))
    assert len(replayed) == finish.ticks == len(places)
    assert replayed == places
    replay.step()  # at the exit the ghost stays where it ended
    assert replay.tick == finish.ticks


def test_a_map_changed_since_the_run_shows_no_ghost(tmp_path: Path) -> None:
    map_path = write_tmx(tmp_path, FLOOR_TO_EXIT)
    ghost = recorded(Attempt().inputs, 10, map_path)
    assert ghost is not None and save_ghost(ghost, map_path.name, tmp_path) is None
    level = load_level(map_path, images=False)
    assert load_replay(level, Campaign(map_path, loader=load_level).tuning, tmp_path)[0]
    map_path.write_text(map_path.read_text("utf-8").replace('"Enemy"', '"Coin"'), "utf-8")
    changed = load_level(map_path, images=False)
    assert load_replay(changed, Campaign(map_path, loader=load_level).tuning,
                       tmp_path) == (None, None)


def test_a_bad_ghost_file_is_kept_aside_with_one_sentence(tmp_path: Path) -> None:
    file = ghost_file("01-first-steps.tmx", tmp_path)
    file.path.parent.mkdir(parents=True)
    file.path.write_text('{"map_sha256": "ab", "ticks": "fast", "inputs": "0 +fly"}', "utf-8")
    replay, problem = load_replay(load_level(FIRST_LEVEL, images=False),
                                  Campaign(FIRST_LEVEL, loader=load_level).tuning, tmp_path)
    assert replay is None and problem is not None and "\n" not in problem
    assert "ticks is \"fast\"" in problem and "kept as" in problem
    assert not file.path.exists()  # moved aside, not wiped
    assert Ghost.from_json([])[0] is None


def _finish_in_the_window(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                          settings: str) -> Path:
    """A person walking right to the exit of a copy of a one-screen level in the window,
    with ``settings`` in their settings file; the ghosts folder afterwards."""
    monkeypatch.setenv("XDG_DATA_HOME", str(tmp_path / "data"))
    (tmp_path / "data" / "tile-hopper").mkdir(parents=True)
    (tmp_path / "data" / "tile-hopper" / "settings.json").write_text(settings, "utf-8")
    folder = tmp_path / "maps"
    folder.mkdir()
    level = write_tmx(folder, ["              ", " P          D ", "##############"])
    monkeypatch.setattr(window_module, "FIRST_LEVEL", level)
    monkeypatch.setattr(window_module, "held_keys", lambda *_: frozenset({Action.RIGHT}))
    run = Run(Campaign(level, loader=load_level), None, parser().parse_args(["--level",
                                                                              str(level)]))
    game = GameWindow(run)
    frames = 0

    def next_batch(*_: object, **__: object) -> list[pygame.event.Event]:
        nonlocal frames
        frames += 1
        done = game.banner is not None or frames > 600
        return [pygame.event.Event(pygame.QUIT)] if done else []

    monkeypatch.setattr(pygame.event, "get", next_batch)
    assert game.play() == 0
    assert run.campaign.results, "the level was not finished"
    return tmp_path / "data" / "tile-hopper" / GHOSTS_DIR


def test_the_window_keeps_a_best_run_as_the_ghost(display: None, tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    ghosts = _finish_in_the_window(tmp_path, monkeypatch, "{}")
    assert [path.name for path in ghosts.iterdir()] == ["level.tmx.json"]


def test_an_assisted_run_leaves_no_ghost(display: None, tmp_path: Path,
                                         monkeypatch: pytest.MonkeyPatch) -> None:
    ghosts = _finish_in_the_window(tmp_path, monkeypatch, '{"no_damage": true}')
    assert not ghosts.exists()


def test_the_ghost_is_drawn_see_through_where_its_run_is_and_not_once_it_is_done(
        tmp_path: Path, assets: Assets) -> None:
    map_path = write_tmx(tmp_path, FLOOR_TO_EXIT)
    level = load_level(map_path, images=False)
    replay = Replay(Ghost("0" * 64, 2, "0 +right\n"), level, Tuning())
    camera = Camera()
    target = pygame.Surface((VIEW_W_PX, VIEW_H_PX))
    draw_ghost(target, assets, replay, camera)
    drawn = pygame.image.tobytes(target, "RGB")
    assert drawn != bytes(len(drawn))  # something was drawn on the black
    box = replay.world.player.box
    x, y = round(box.x + box.w / 2), round(box.bottom) - 1  # a pixel of its feet
    colour = target.get_at((x, y))
    picture = assets.player_frames[0].get_at((assets.player_frames[0].get_width() // 2,
                                              assets.player_frames[0].get_height() - 1))
    if picture.a:  # see-through: darker than the picture's own pixel on black
        assert sum(colour[:3]) < sum(picture[:3])
    target.fill((0, 0, 0))
    draw_ghost(target, assets, replay, camera)
    assert pygame.image.tobytes(target, "RGB") == drawn  # the same picture every frame
    while not replay.done:
        replay.step()
    target.fill((0, 0, 0))
    draw_ghost(target, assets, replay, camera)
    assert pygame.image.tobytes(target, "RGB") == bytes(len(drawn))
