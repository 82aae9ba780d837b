"""The menus without a window: keys and pad events in, screens and commands out."""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from pathlib import Path

import pygame
import pytest

from game.app.gamepad import BUTTON_A, BUTTON_B, BUTTON_START, STICK_Y_AXIS, StickEdges, pad_nav
from game.app.menus import (
    LEVEL_SELECT,
    OPTIONS,
    PAUSE_ITEMS,
    PLAY,
    QUIT,
    QUIT_TO_TITLE,
    RESTART,
    RETRY,
    TITLE_ITEMS,
    HeldOver,
    LevelEntry,
    LevelInfo,
    Menus,
    QuitGame,
    RestartLevel,
    RetryLevel,
    Screen,
    StartLevel,
    campaign_levels,
    cleared,
    ended,
    key_nav,
    level_entries,
    next_to_play,
    press,
)
from game.app.saves import Progress
from game.levels import FIRST_LEVEL, LevelError
from game.sim.inputs import Action
from game.sim.level import Level
from game.sim.tuning import TICK_HZ
from tests.maps import level_from_ascii

ONE, TWO, THREE = Path("01-one.tmx"), Path("02-two.tmx"), Path("03-three.tmx")
CAMPAIGN = (LevelInfo(ONE, "One"), LevelInfo(TWO, "Two"), LevelInfo(THREE, "Three"))


def key(code: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.KEYDOWN, key=code)


def button(number: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYBUTTONDOWN, button=number, instance_id=0)


def hat(x: int, y: int) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYHATMOTION, hat=0, value=(x, y), instance_id=0)


def stick(y: float) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYAXISMOTION, axis=STICK_Y_AXIS, value=y, instance_id=0)


def entries(progress: Progress | None = None) -> tuple[LevelEntry, ...]:
    return level_entries(CAMPAIGN, progress or Progress())


class Driver:
    """Feeds events through the input mapping and the menus, as the window does."""

    def __init__(self, levels: Sequence[LevelEntry], menus: Menus | None = None) -> None:
        self.levels = levels
        self.menus = menus or Menus()
        self.edges = StickEdges()
        self.commands: list[object] = []

    def send(self, *events: pygame.event.Event) -> Driver:
        for event in events:
            playing = self.menus.screen is Screen.PLAYING
            nav = key_nav(event) or pad_nav(event, self.edges, playing=playing)
            if nav is not None:
                self.menus, command = press(self.menus, nav, self.levels)
                if command is not None:
                    self.commands.append(command)
        return self

    @property
    def lit_title(self) -> str:
        return TITLE_ITEMS[self.menus.title_item]

    @property
    def lit_pause(self) -> str:
        return PAUSE_ITEMS[self.menus.pause_item]


# The title menu.

def test_the_title_menu_moves_with_arrows_and_w_s_and_wraps_round() -> None:
    drive = Driver(entries())
    assert drive.menus.screen is Screen.TITLE and drive.lit_title == PLAY
    assert drive.send(key(pygame.K_DOWN)).lit_title == LEVEL_SELECT
    assert drive.send(key(pygame.K_s)).lit_title == OPTIONS
    assert drive.send(key(pygame.K_s)).lit_title == QUIT
    assert drive.send(key(pygame.K_DOWN)).lit_title == PLAY
    assert drive.send(key(pygame.K_w)).lit_title == QUIT
    assert drive.send(key(pygame.K_UP)).lit_title == OPTIONS


def test_the_title_menu_moves_with_the_dpad_and_one_stick_flick_is_one_step() -> None:
    drive = Driver(entries())
    assert drive.send(hat(0, -1), hat(0, 0)).lit_title == LEVEL_SELECT
    assert drive.send(stick(0.3), stick(0.8), stick(1.0), stick(0.9)).lit_title == OPTIONS
    assert drive.send(stick(0.0), stick(-0.9)).lit_title == LEVEL_SELECT
    assert drive.send(hat(0, 1)).lit_title == PLAY


def test_quit_on_the_title_quits_by_key_and_by_button() -> None:
    assert Driver(entries()).send(key(pygame.K_UP), key(pygame.K_RETURN)).commands \
        == [QuitGame()]
    assert Driver(entries()).send(hat(0, 1), button(BUTTON_A)).commands == [QuitGame()]


def test_back_on_the_title_lights_quit_without_quitting() -> None:
    for back in (key(pygame.K_ESCAPE), button(BUTTON_B)):
        drive = Driver(entries()).send(back)
        assert drive.lit_title == QUIT and drive.commands == []
        assert drive.menus.screen is Screen.TITLE


def test_play_on_a_fresh_save_starts_at_the_first_level() -> None:
    drive = Driver(entries()).send(key(pygame.K_RETURN))
    assert drive.menus.screen is Screen.PLAYING and drive.commands == [StartLevel(ONE)]


def test_play_starts_at_the_first_level_not_yet_completed() -> None:
    progress = Progress()
    progress.complete_level(ONE.name, ticks=900, coins=2, next_level=TWO.name)
    drive = Driver(entries(progress)).send(button(BUTTON_A))
    assert drive.commands == [StartLevel(TWO)]


def test_play_starts_at_the_first_level_once_every_level_is_completed() -> None:
    progress = Progress()
    for level, following in ((ONE, TWO), (TWO, THREE), (THREE, None)):
        progress.complete_level(level.name, 900, 2, None if following is None else following.name)
    assert next_to_play(entries(progress)) == 0


# The level select.

def to_level_select(levels: Sequence[LevelEntry]) -> Driver:
    drive = Driver(levels).send(key(pygame.K_DOWN), key(pygame.K_RETURN))
    assert drive.menus.screen is Screen.LEVEL_SELECT
    return drive


def test_the_level_select_lists_the_campaign_with_only_the_first_level_unlocked() -> None:
    assert [(entry.title, entry.unlocked) for entry in entries()] \
        == [("One", True), ("Two", False), ("Three", False)]


def test_a_finished_level_shows_its_best_time_in_seconds_and_its_coins() -> None:
    progress = Progress()
    progress.complete_level(ONE.name, ticks=3 * TICK_HZ, coins=4, next_level=TWO.name)
    one, two, three = entries(progress)
    assert one.best_s == pytest.approx(3.0) and one.best_coins == 4
    assert two.unlocked and two.best_s is None and two.best_coins is None
    assert not three.unlocked


def test_a_locked_level_cannot_be_chosen_by_key_or_button() -> None:
    drive = to_level_select(entries())
    drive.send(key(pygame.K_DOWN))
    lit = drive.menus
    drive.send(key(pygame.K_RETURN), key(pygame.K_SPACE), button(BUTTON_A))
    assert drive.menus == lit and drive.commands == []


def test_an_unlocked_level_starts_there() -> None:
    progress = Progress()
    progress.complete_level(ONE.name, 900, 2, next_level=TWO.name)
    drive = to_level_select(entries(progress))
    assert drive.menus.level_item == 1  # it opens on the level Play would start
    drive.send(hat(0, 1), button(BUTTON_A))
    assert drive.menus.screen is Screen.PLAYING and drive.commands == [StartLevel(ONE)]


def test_back_leaves_the_level_select_for_the_title() -> None:
    for back in (key(pygame.K_ESCAPE), button(BUTTON_B)):
        drive = to_level_select(entries()).send(back)
        assert drive.menus.screen is Screen.TITLE and drive.lit_title == LEVEL_SELECT


def test_a_level_that_cannot_be_loaded_is_listed_but_cannot_be_chosen() -> None:
    broken = (CAMPAIGN[0], LevelInfo(TWO, "02-two", problem="02-two.tmx: not a map"))
    progress = Progress(unlocked={TWO.name})
    drive = to_level_select(level_entries(broken, progress)).send(key(pygame.K_DOWN))
    assert drive.send(key(pygame.K_RETURN)).commands == []


# Pause, resume, restart, quit to title, and the end of a run.

def playing() -> Driver:
    return Driver(entries(), Menus(Screen.PLAYING))


@pytest.mark.parametrize("pause", [pygame.K_ESCAPE, pygame.K_p])
def test_esc_or_p_pauses_and_resumes(pause: int) -> None:
    drive = playing().send(key(pause))
    assert drive.menus.screen is Screen.PAUSED and drive.lit_pause == PAUSE_ITEMS[0]
    assert drive.send(key(pause)).menus.screen is Screen.PLAYING


def test_start_pauses_and_resumes_and_b_resumes() -> None:
    drive = playing()
    assert drive.send(button(BUTTON_START)).menus.screen is Screen.PAUSED
    assert drive.send(button(BUTTON_START)).menus.screen is Screen.PLAYING
    assert drive.send(button(BUTTON_START)).menus.screen is Screen.PAUSED
    assert drive.send(button(BUTTON_B)).menus.screen is Screen.PLAYING
    assert drive.commands == []


def test_while_playing_the_pads_other_buttons_do_not_pause() -> None:
    drive = playing().send(button(BUTTON_A), button(BUTTON_B), hat(0, -1), stick(0.9))
    assert drive.menus.screen is Screen.PLAYING


def test_resume_continues_without_a_command() -> None:
    drive = playing().send(key(pygame.K_ESCAPE), key(pygame.K_RETURN))
    assert drive.menus.screen is Screen.PLAYING and drive.commands == []


def test_restart_level_from_the_dpad_restarts_and_plays_on() -> None:
    drive = playing().send(button(BUTTON_START), hat(0, -1))
    assert drive.lit_pause == RESTART
    drive.send(button(BUTTON_A))
    assert drive.menus.screen is Screen.PLAYING and drive.commands == [RestartLevel()]


def test_quit_to_title_goes_to_the_title() -> None:
    drive = playing().send(key(pygame.K_p), key(pygame.K_UP))
    assert drive.lit_pause == QUIT_TO_TITLE
    drive.send(key(pygame.K_RETURN))
    assert drive.menus.screen is Screen.TITLE and drive.commands == []


def test_the_pause_menu_opens_on_resume_every_time() -> None:
    drive = playing().send(key(pygame.K_p), key(pygame.K_DOWN), key(pygame.K_p), key(pygame.K_p))
    assert drive.lit_pause == PAUSE_ITEMS[0]


def test_game_over_waits_for_enter_or_a_and_quit_to_title_shows_the_title() -> None:
    for confirm in (key(pygame.K_RETURN), button(BUTTON_A)):
        drive = Driver(entries(), ended(Menus(Screen.PLAYING)))
        assert drive.menus.screen is Screen.ENDED
        assert drive.send(key(pygame.K_DOWN), confirm).menus.screen is Screen.TITLE
        assert drive.commands == []


def test_game_over_opens_on_retry_this_level_which_plays_the_level_again() -> None:
    for confirm in (key(pygame.K_RETURN), button(BUTTON_A)):
        drive = Driver(entries(), ended(Menus(Screen.PLAYING)))
        assert RETRY == "Retry this level"
        assert drive.send(confirm).menus.screen is Screen.PLAYING
        assert drive.commands == [RetryLevel()]


def test_the_win_rolls_the_credits_then_enter_or_a_shows_the_title() -> None:
    for confirm in (key(pygame.K_RETURN), button(BUTTON_A)):
        drive = Driver(entries(), ended(Menus(Screen.PLAYING), won=True))
        assert drive.send(key(pygame.K_DOWN)).menus.screen is Screen.ENDED
        assert drive.send(confirm).menus.screen is Screen.CREDITS
        assert drive.send(key(pygame.K_DOWN)).menus.screen is Screen.CREDITS
        assert drive.send(confirm).menus.screen is Screen.TITLE
        assert drive.menus.title_item == TITLE_ITEMS.index(PLAY) and drive.commands == []


def test_enter_after_a_game_over_reached_from_the_level_select_plays_on() -> None:
    progress = Progress()
    progress.complete_level(ONE.name, 900, 2, next_level=TWO.name)
    drive = Driver(entries(progress))
    drive.send(key(pygame.K_DOWN), key(pygame.K_RETURN), key(pygame.K_RETURN))  # select, play
    assert drive.menus.screen is Screen.PLAYING
    drive.menus = ended(drive.menus)                          # the last life is lost
    drive.send(key(pygame.K_DOWN), key(pygame.K_RETURN))       # Quit to title
    drive.send(key(pygame.K_RETURN))                           # then Enter
    assert drive.menus.screen is Screen.PLAYING
    assert drive.commands == [StartLevel(TWO), StartLevel(TWO)]


def test_the_level_end_banner_gives_way_to_play_on_enter_or_a() -> None:
    for confirm in (key(pygame.K_RETURN), button(BUTTON_A)):
        drive = Driver(entries(), cleared(Menus(Screen.PLAYING)))
        assert drive.menus.screen is Screen.CLEARED
        assert drive.send(key(pygame.K_p), key(pygame.K_DOWN)).menus.screen is Screen.CLEARED
        assert drive.send(confirm).menus.screen is Screen.PLAYING


def test_a_whole_session_title_to_level_to_pause_to_title_to_quit() -> None:
    progress = Progress()
    progress.complete_level(ONE.name, 900, 2, next_level=TWO.name)
    drive = Driver(entries(progress))
    drive.send(stick(0.9), stick(0.0), button(BUTTON_A))       # Level select
    drive.send(key(pygame.K_RETURN))                            # level 2, lit on opening
    assert drive.menus.screen is Screen.PLAYING
    down_to_quit = (hat(0, -1),) * PAUSE_ITEMS.index(QUIT_TO_TITLE)
    quit_to_title = (button(BUTTON_START), *down_to_quit, button(BUTTON_A))
    assert drive.send(*quit_to_title).menus.screen is Screen.TITLE
    drive.send(key(pygame.K_DOWN), key(pygame.K_DOWN), key(pygame.K_RETURN))  # Quit
    assert drive.commands == [StartLevel(TWO), QuitGame()]


# Play starts without a jump from the press that chose it.

def test_a_jump_held_from_the_confirm_press_waits_for_a_fresh_press() -> None:
    held_over = HeldOver()
    held_over.begin(frozenset({Action.JUMP, Action.LEFT}))
    assert held_over.filter(frozenset({Action.JUMP, Action.LEFT})) == {Action.LEFT}
    assert held_over.filter(frozenset()) == frozenset()
    assert held_over.filter(frozenset({Action.JUMP})) == {Action.JUMP}


# Reading the campaign's levels.

def test_the_shipped_campaign_starts_at_the_first_level_and_follows_next_level() -> None:
    levels = campaign_levels(FIRST_LEVEL)
    assert levels[0].path == FIRST_LEVEL and levels[0].title
    assert len({info.path.resolve() for info in levels}) == len(levels)
    assert all(info.problem is None for info in levels)


def chain(links: dict[str, str | None], broken: Sequence[str] = ()) -> dict[Path, Level]:
    base = level_from_ascii(["P ", "##"])
    return {Path(name): dataclasses.replace(base, path=Path(name), title=name.upper(),
                                            next_level=None if following is None
                                            else Path(following))
            for name, following in links.items() if name not in broken}


def test_a_next_level_that_loops_back_ends_the_list() -> None:
    levels = chain({"a.tmx": "b.tmx", "b.tmx": "a.tmx"})
    listed = campaign_levels(Path("a.tmx"), levels.__getitem__)
    assert [info.title for info in listed] == ["A.TMX", "B.TMX"]


def test_a_level_that_will_not_load_ends_the_list_and_says_why() -> None:
    levels = chain({"a.tmx": "b.tmx", "b.tmx": "c.tmx", "c.tmx": None}, broken=["b.tmx"])

    def load(path: Path) -> Level:
        if path not in levels:
            raise LevelError(path, "map", "not a map", "save it again in Tiled")
        return levels[path]

    listed = campaign_levels(Path("a.tmx"), load)
    assert [info.path.name for info in listed] == ["a.tmx", "b.tmx"]
    assert listed[1].problem is not None and "b.tmx" in listed[1].problem
    assert not level_entries(listed, Progress(unlocked={"b.tmx"}))[1].playable


def test_a_level_with_no_title_is_listed_by_its_file_name() -> None:
    base = level_from_ascii(["P ", "##"])
    listed = campaign_levels(Path("04-untitled.tmx"), lambda path: base)
    assert listed[0].title == "04-untitled"
