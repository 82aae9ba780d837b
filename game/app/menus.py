"""The menus as plain state: which screen is up, which item is lit, and what a press does.

Where it sits: between the input and the window. Keys (:func:`key_nav`) and pads
(:func:`game.app.gamepad.pad_nav`) become :class:`Nav` moves; :func:`press` turns the current
:class:`Menus` and one move into the next :class:`Menus` and, sometimes, a
:data:`Command` for the window to carry out (start a level, restart it, quit). Nothing here
draws or opens a file but :func:`campaign_levels`, so a test can walk title -> level select
-> play -> pause -> title without a window.

What it teaches:
  * **A menu is a state machine.** Each screen is a state, each press a transition, and the
    whole table is one function per screen. The window keeps one value and replaces it.
  * **Decide, then do.** :func:`press` never touches the campaign; it names what should
    happen, and the window does it. That split is what makes the menus testable.
  * **Menus are data.** :data:`TITLE_ITEMS` and :data:`PAUSE_ITEMS` are the lists both this
    logic and the drawing code (:mod:`game.app.screens`) index with the same number.

Play on the title starts at the first level of the campaign not yet completed (the first
one with no best time), or at the first level once every one has been finished.

>>> levels = (LevelEntry(Path("01.tmx"), "One", unlocked=True),
...           LevelEntry(Path("02.tmx"), "Two", unlocked=False))
>>> menus, command = press(Menus(), Nav.DOWN, levels)   # Play -> Level select
>>> menus, command = press(menus, Nav.CONFIRM, levels)
>>> menus.screen, command
(<Screen.LEVEL_SELECT: 'level_select'>, None)
>>> menus, command = press(menus, Nav.CONFIRM, levels)
>>> menus.screen, command == StartLevel(Path("01.tmx"))
(<Screen.PLAYING: 'playing'>, True)
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from enum import Enum
from pathlib import Path

import pygame

from game.app.goals import earns_medal, target_ticks
from game.app.options import BACK, OPTION_ITEMS, key_action
from game.app.saves import Progress
from game.levels import LevelError, load_level
from game.sim.inputs import NOTHING, Action, Actions
from game.sim.level import Level
from game.sim.tuning import TICK_S


class Screen(Enum):
    TITLE = "title"
    LEVEL_SELECT = "level_select"
    PLAYING = "playing"
    PAUSED = "paused"
    CLEARED = "cleared"  # the level-end banner (game.app.banner), between two levels
    ENDED = "ended"  # game over or won; the campaign's outcome says which
    OPTIONS = "options"  # volumes, timer, fullscreen, ghost, keys, assists (game.app.options)
    CREDITS = "credits"  # after the win: who made what, rolling up


class Nav(Enum):
    """One press in a menu, whatever it came from."""

    UP = "up"
    DOWN = "down"
    CONFIRM = "confirm"  # Enter, Space, pad A
    BACK = "back"  # Esc, pad B: leave this screen (and, on the keyboard, pause)
    PAUSE = "pause"  # P, pad Start: pause or resume
    LEFT = "left"  # on the options screen: a value down
    RIGHT = "right"  # on the options screen: a value up


NAV_FOR_KEY: Mapping[int, Nav] = {
    pygame.K_UP: Nav.UP, pygame.K_w: Nav.UP,
    pygame.K_DOWN: Nav.DOWN, pygame.K_s: Nav.DOWN,
    pygame.K_LEFT: Nav.LEFT, pygame.K_a: Nav.LEFT,
    pygame.K_RIGHT: Nav.RIGHT, pygame.K_d: Nav.RIGHT,
    pygame.K_RETURN: Nav.CONFIRM, pygame.K_KP_ENTER: Nav.CONFIRM, pygame.K_SPACE: Nav.CONFIRM,
    pygame.K_ESCAPE: Nav.BACK, pygame.K_BACKSPACE: Nav.BACK,
    pygame.K_p: Nav.PAUSE,
}



def key_nav(event: pygame.event.Event) -> Nav | None:
    """The menu move a key press makes, if any (pads: :func:`game.app.gamepad.pad_nav`).

    >>> key_nav(pygame.event.Event(pygame.KEYDOWN, key=pygame.K_s))
    <Nav.DOWN: 'down'>
    """
    return NAV_FOR_KEY.get(event.key) if event.type == pygame.KEYDOWN else None


PLAY, LEVEL_SELECT, OPTIONS, QUIT = "Play", "Level select", "Options", "Quit"
TITLE_ITEMS = (PLAY, LEVEL_SELECT, OPTIONS, QUIT)
RESUME, RESTART, TIMER, QUIT_TO_TITLE = "Resume", "Restart level", "Timer", "Quit to title"
PAUSE_ITEMS = (RESUME, RESTART, TIMER, OPTIONS, QUIT_TO_TITLE)
RETRY = "Retry this level"
GAME_OVER_ITEMS = (RETRY, QUIT_TO_TITLE)


@dataclass(frozen=True)
class StartLevel:
    """Start a new campaign at ``level``."""

    level: Path


@dataclass(frozen=True)
class RestartLevel:
    """Start the level in play again from its spawn."""


@dataclass(frozen=True)
class RetryLevel:
    """After game over: the level lost starts again from its spawn with full lives."""


@dataclass(frozen=True)
class QuitGame:
    """Close the window."""


@dataclass(frozen=True)
class ToggleTimer:
    """Show the HUD's timer if it is hidden, hide it if it is shown (a setting, saved)."""


@dataclass(frozen=True)
class ChangeOption:
    """Change the options row ``item`` one notch: ``step`` +1 or -1 (game.app.options)."""

    item: str
    step: int


@dataclass(frozen=True)
class RebindKey:
    """Wait for a key press, and bind ``action`` to that key."""

    action: str


Command = (StartLevel | RestartLevel | RetryLevel | QuitGame | ToggleTimer | ChangeOption
           | RebindKey)


@dataclass(frozen=True)
class LevelInfo:
    """A level of the campaign as the level select lists it, read once."""

    path: Path
    title: str
    problem: str | None = None  # why it cannot be loaded, if it cannot
    coins_total: int = 0  # the coins the level holds
    target_ticks: int | None = None  # its target time (game.app.goals), if it has one


@dataclass(frozen=True)
class LevelEntry:
    """A row of the level select: a level, whether it may be played, and its bests."""

    path: Path
    title: str
    unlocked: bool
    best_s: float | None = None  # fastest finish, in seconds of game time
    best_coins: int | None = None  # most coins taken in one finish
    problem: str | None = None
    coins_total: int = 0  # the coins the level holds
    medal: bool = False  # the best time is within the level's target time

    @property
    def playable(self) -> bool:
        return self.unlocked and self.problem is None


@dataclass(frozen=True)
class Menus:
    """The screen that is up and the item lit on each menu."""

    screen: Screen = Screen.TITLE
    title_item: int = 0  # index into TITLE_ITEMS
    level_item: int = 0  # index into the level select's entries
    pause_item: int = 0  # index into PAUSE_ITEMS
    options_item: int = 0  # index into game.app.options.OPTION_ITEMS
    options_from: Screen = Screen.TITLE  # where Back on the options screen returns to
    game_over_item: int = 0  # index into GAME_OVER_ITEMS
    won: bool = False  # on Screen.ENDED: the win (then the credits), else game over


def outline(path: Path) -> Level:
    """A level read for its title and ``next_level`` only: no images, so it is cheap."""
    return load_level(path, images=False)


def campaign_levels(first: Path, load: Callable[[Path], Level] = outline
                    ) -> tuple[LevelInfo, ...]:
    """The campaign's levels in order, following ``next_level`` from ``first``.

    A level that cannot be loaded ends the list (its successor is unknown); a ``next_level``
    that leads back to a level already listed ends it too, instead of looping for ever.
    """
    levels: list[LevelInfo] = []
    seen: set[Path] = set()
    path: Path | None = first
    while path is not None and path.resolve() not in seen:
        seen.add(path.resolve())
        try:
            level = load(path)
        except LevelError as error:
            levels.append(LevelInfo(path, path.stem, str(error)))
            break
        levels.append(LevelInfo(path, level.title or path.stem, None, len(level.coins),
                                target_ticks(level.properties)))
        path = level.next_level
    return tuple(levels)


def level_entries(levels: Sequence[LevelInfo], progress: Progress) -> tuple[LevelEntry, ...]:
    """The level select's rows: the first level is always unlocked, a finished one too."""
    entries = []
    for number, info in enumerate(levels):
        name = info.path.name
        ticks = progress.best_ticks.get(name)
        unlocked = number == 0 or name in progress.unlocked or ticks is not None
        entries.append(LevelEntry(info.path, info.title, unlocked,
                                  None if ticks is None else ticks * TICK_S,
                                  progress.best_coins.get(name), info.problem, info.coins_total,
                                  ticks is not None and earns_medal(ticks, info.target_ticks)))
    return tuple(entries)


def next_to_play(levels: Sequence[LevelEntry]) -> int:
    """Where Play starts: the first playable level with no best time, else the first."""
    for number, entry in enumerate(levels):
        if entry.playable and entry.best_s is None:
            return number
    return 0


def press(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]) -> tuple[Menus, Command | None]:
    """What ``nav`` does on the screen that is up: the next menus and, maybe, a command."""
    return _SCREENS[menus.screen](menus, nav, levels)


def ended(menus: Menus, won: bool = False) -> Menus:
    """The run is over (won or lost): show the result until it is confirmed; game over
    opens on Retry this level."""
    return replace(menus, screen=Screen.ENDED, won=won, game_over_item=0)


def cleared(menus: Menus) -> Menus:
    """A level was finished: show its banner until it ends or is confirmed."""
    return replace(menus, screen=Screen.CLEARED)


def _step(item: int, nav: Nav, count: int) -> int:
    """Move a lit item up or down, wrapping round at either end."""
    if nav is Nav.UP:
        return (item - 1) % count
    if nav is Nav.DOWN:
        return (item + 1) % count
    return item


def _title(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
           ) -> tuple[Menus, Command | None]:
    if nav is Nav.BACK:  # Esc lights Quit rather than quitting: one more press to leave
        return replace(menus, title_item=TITLE_ITEMS.index(QUIT)), None
    if nav is not Nav.CONFIRM:
        return replace(menus, title_item=_step(menus.title_item, nav, len(TITLE_ITEMS))), None
    chosen = TITLE_ITEMS[menus.title_item]
    if chosen == QUIT:
        return menus, QuitGame()
    if chosen == OPTIONS:
        return replace(menus, screen=Screen.OPTIONS, options_from=Screen.TITLE), None
    if not levels:
        return menus, None
    start = next_to_play(levels)
    if chosen == LEVEL_SELECT:
        return replace(menus, screen=Screen.LEVEL_SELECT, level_item=start), None
    return replace(menus, screen=Screen.PLAYING), StartLevel(levels[start].path)


def _level_select(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
                  ) -> tuple[Menus, Command | None]:
    if nav is Nav.BACK:
        return replace(menus, screen=Screen.TITLE), None
    if not levels:
        return menus, None
    if nav is not Nav.CONFIRM:
        return replace(menus, level_item=_step(menus.level_item, nav, len(levels))), None
    chosen = levels[menus.level_item % len(levels)]
    if not chosen.playable:  # locked (or broken): the row says why; nothing happens
        return menus, None
    return replace(menus, screen=Screen.PLAYING), StartLevel(chosen.path)


def _playing(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
             ) -> tuple[Menus, Command | None]:
    if nav in (Nav.BACK, Nav.PAUSE):
        return replace(menus, screen=Screen.PAUSED, pause_item=0), None
    return menus, None


def _paused(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
            ) -> tuple[Menus, Command | None]:
    if nav in (Nav.BACK, Nav.PAUSE):
        return replace(menus, screen=Screen.PLAYING), None
    if nav is not Nav.CONFIRM:
        return replace(menus, pause_item=_step(menus.pause_item, nav, len(PAUSE_ITEMS))), None
    chosen = PAUSE_ITEMS[menus.pause_item]
    if chosen == RESTART:
        return replace(menus, screen=Screen.PLAYING), RestartLevel()
    if chosen == TIMER:  # a setting: the menu stays up, showing the new state
        return menus, ToggleTimer()
    if chosen == OPTIONS:
        return replace(menus, screen=Screen.OPTIONS, options_from=Screen.PAUSED), None
    if chosen == QUIT_TO_TITLE:
        return replace(menus, screen=Screen.TITLE), None
    return replace(menus, screen=Screen.PLAYING), None


def _cleared(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
             ) -> tuple[Menus, Command | None]:
    if nav is Nav.CONFIRM:
        return replace(menus, screen=Screen.PLAYING), None
    return menus, None


def _ended(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
           ) -> tuple[Menus, Command | None]:
    """The win gives way to the credits. Game over retries the level lost, or goes back to
    the title (Back does too)."""
    if menus.won:
        if nav in (Nav.CONFIRM, Nav.BACK):
            return replace(menus, screen=Screen.CREDITS), None
        return menus, None
    if nav is Nav.BACK:
        return _to_title(menus), None
    if nav is not Nav.CONFIRM:
        return replace(menus, game_over_item=_step(menus.game_over_item, nav,
                                                   len(GAME_OVER_ITEMS))), None
    if GAME_OVER_ITEMS[menus.game_over_item] == RETRY:
        return replace(menus, screen=Screen.PLAYING), RetryLevel()
    return _to_title(menus), None


def _credits(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
             ) -> tuple[Menus, Command | None]:
    if nav in (Nav.CONFIRM, Nav.BACK):
        return _to_title(menus), None
    return menus, None


def _to_title(menus: Menus) -> Menus:
    """Back to the title with Play lit, whatever was lit when this run began: a second
    Enter plays on (from the first level not yet finished)."""
    return replace(menus, screen=Screen.TITLE, title_item=TITLE_ITEMS.index(PLAY))
def _options(menus: Menus, nav: Nav, levels: Sequence[LevelEntry]
             ) -> tuple[Menus, Command | None]:
    """Up and down pick a row; left and right change its value, Enter changes it up (a key
    row: waits for the new key); Back (the row, Esc or B) returns where the screen came from."""
    chosen = OPTION_ITEMS[menus.options_item]
    if nav in (Nav.BACK, Nav.PAUSE) or (nav is Nav.CONFIRM and chosen == BACK):
        return replace(menus, screen=menus.options_from), None
    if nav in (Nav.UP, Nav.DOWN):
        return replace(menus, options_item=_step(menus.options_item, nav,
                                                 len(OPTION_ITEMS))), None
    if (action := key_action(chosen)) is not None:
        return menus, RebindKey(action) if nav is Nav.CONFIRM else None
    if chosen == BACK:
        return menus, None
    return menus, ChangeOption(chosen, -1 if nav is Nav.LEFT else +1)


_SCREENS: dict[Screen, Callable[[Menus, Nav, Sequence[LevelEntry]],
                                tuple[Menus, Command | None]]] = {
    Screen.TITLE: _title,
    Screen.LEVEL_SELECT: _level_select,
    Screen.PLAYING: _playing,
    Screen.PAUSED: _paused,
    Screen.CLEARED: _cleared,
    Screen.ENDED: _ended,
    Screen.OPTIONS: _options,
    Screen.CREDITS: _credits,
}


class HeldOver:
    """A jump still held from the press that started play is not a jump.

    Space and pad A both confirm a menu and jump; without this, choosing a level or Resume
    with them would make the hero jump on the first tick. The actions in ``fresh_only``
    that are held when play begins are ignored until they are let go; the others (a
    direction held through a resume) carry straight on.

    >>> held_over = HeldOver()
    >>> held_over.begin(frozenset({Action.JUMP, Action.RIGHT}))
    >>> [sorted(a.value for a in held_over.filter(held)) for held in (
    ...     frozenset({Action.JUMP, Action.RIGHT}), frozenset(), frozenset({Action.JUMP}))]
    [['right'], [], ['jump']]
    """

    def __init__(self, fresh_only: Actions = frozenset({Action.JUMP})) -> None:
        self.fresh_only = fresh_only
        self.stale: Actions = NOTHING

    def begin(self, held: Actions) -> None:
        """Play starts (or resumes) now, with ``held`` held."""
        self.stale = held & self.fresh_only

    def filter(self, held: Actions) -> Actions:
        """``held`` without what is still down from before play began."""
        self.stale &= held
        return held - self.stale
