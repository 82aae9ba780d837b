"""The player's choices: volumes, fullscreen, the HUD's timer, the ghost, the assists, and
which keys and buttons do what.

Where it sits: read once by the app before the window opens, written when the player changes
something. It lives as ``settings.json`` in the data folder beside the progress, and is read
and written with the same care (:class:`game.app.saves.JsonFile`): written atomically, and a
file that cannot be used in full is kept aside as a backup, never silently wiped.

What it teaches:
  * **Check data at the edge.** Every value from the file is checked once, here, as it is
    read; the rest of the game can trust a :class:`Settings`. An unknown key is ignored (a
    newer version's file still loads); a bad value gets its default and one line in the
    report returned to the caller, which decides whether to show it.
  * **Check what the values mean together, not only one by one.** A file that binds
    left and right to the same key, or a button numbered 10**29, is refused with the reason
    and the defaults are kept, rather than leaving a player who cannot move.
  * **Store what a person can read.** Keys are stored by name (``"left"``, ``"a"``,
    ``"space"``), as pygame names them, and turned into key codes only when the game needs
    them (:meth:`Settings.key_codes`).

>>> settings, problems = Settings.from_json({"music_volume": 0.25, "keys": {"jump": ["X"]},
...                                          "theme": "dark"})
>>> settings.music_volume, settings.keys["jump"], problems
(0.25, ['x'], [])
>>> settings, problems = Settings.from_json({"effects_volume": 7, "keys": {"jump": ["spcae"]}})
>>> settings.effects_volume, settings.keys["jump"]
(0.8, ['space', 'z', 'up', 'w'])
>>> problems  # doctest: +NORMALIZE_WHITESPACE
['effects_volume is 7, not a number from 0 to 1 (using 0.8)',
 'keys.jump: "spcae" is not a key name pygame knows (left out)',
 'keys.jump has no usable entry (using space, z, up, w)']
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TypeVar

import pygame

from game.app.saves import JsonFile, data_dir, quoted
from game.sim.inputs import Action

T = TypeVar("T")

SETTINGS_FILE = "settings.json"
SETTINGS_VERSION = 1  # written into the file; bump it if its layout ever changes

DEFAULT_EFFECTS_VOLUME = 0.8  # 0 is mute, 1 is full
DEFAULT_MUSIC_VOLUME = 0.5  # quieter than the effects, which carry the game's feedback
DEFAULT_FULLSCREEN = False
GAME_SPEEDS = (50, 60, 70, 80, 90, 100)  # the assist's game speeds, in % of real time
DEFAULT_GAME_SPEED = 100  # %: the game as it is meant to be played
DEFAULT_KEYS: dict[str, tuple[str, ...]] = {  # action name -> pygame key names
    Action.LEFT.value: ("left", "a"),
    Action.RIGHT.value: ("right", "d"),
    Action.UP.value: ("up", "w"),
    Action.DOWN.value: ("down", "s"),
    Action.JUMP.value: ("space", "z", "up", "w"),
}
# Gamepad buttons by number, as ``JOYBUTTONDOWN`` events report them. Button 0 is the bottom
# face button (A on an Xbox-style pad) on most pads; moving uses the stick or the d-pad.
DEFAULT_BUTTONS: dict[str, tuple[int, ...]] = {Action.JUMP.value: (0,)}
MAX_BUTTON = 63  # SDL numbers a pad's buttons from 0; pads have a few dozen at most
# Actions that may not share a key or a button: opposite directions cancel out, and down
# with jump is the drop through a one-way platform, so it needs two separate presses.
# (Up and jump share keys by default: the simulation never reads up.)
CLASHING_ACTIONS = ((Action.LEFT.value, Action.RIGHT.value),
                    (Action.UP.value, Action.DOWN.value),
                    (Action.DOWN.value, Action.JUMP.value))


def key_code(name: str) -> int | None:
    """The pygame key code for a key name (any case), or None if pygame knows no such key.

    It works before ``pygame.init()``: SDL turns names into codes with a fixed table, so
    the warning pygame gives when the display is not open does not apply and is hushed.

    >>> key_code("space") == pygame.K_SPACE, key_code("Left") == pygame.K_LEFT
    (True, True)
    >>> key_code("spcae") is None
    True
    """
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"pygame\.init\(\) has not been called")
        try:
            return pygame.key.key_code(name)
        except ValueError:
            return None


def key_name(code: int) -> str:
    """pygame's name for a key code, the form settings are stored in: ``"left"``, ``"a"``."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", message=r"pygame\.init\(\) has not been called")
        return pygame.key.name(code)


def _default_keys() -> dict[str, list[str]]:
    return {action: list(names) for action, names in DEFAULT_KEYS.items()}


def _default_buttons() -> dict[str, list[int]]:
    return {action.value: list(DEFAULT_BUTTONS.get(action.value, ())) for action in Action}


@dataclass
class Settings:
    """Everything the player can change, with a valid value for each."""

    effects_volume: float = DEFAULT_EFFECTS_VOLUME
    music_volume: float = DEFAULT_MUSIC_VOLUME
    fullscreen: bool = DEFAULT_FULLSCREEN
    screen_shake: bool = True  # a stomp shakes the picture (game.app.effects); false: never
    hud_timer: bool = True  # the HUD shows the level's time (the pause menu's Timer row)
    ghost: bool = True  # the best run of the level in play is replayed beside the player
    game_speed: int = DEFAULT_GAME_SPEED  # an assist: % of real time the game plays at
    no_damage: bool = False  # an assist: enemies and spikes never hurt
    keys: dict[str, list[str]] = field(default_factory=_default_keys)  # action -> key names
    buttons: dict[str, list[int]] = field(default_factory=_default_buttons)  # action -> numbers

    def key_codes(self) -> dict[Action, tuple[int, ...]]:
        """The key codes bound to each action, ready to test against ``key.get_pressed()``.

        >>> Settings().key_codes()[Action.LEFT] == (pygame.K_LEFT, pygame.K_a)
        True
        """
        return {action: tuple(code for name in self.keys.get(action.value, [])
                              if (code := key_code(name)) is not None)
                for action in Action}

    def button_numbers(self) -> dict[Action, tuple[int, ...]]:
        """The gamepad buttons bound to each action."""
        return {action: tuple(self.buttons.get(action.value, [])) for action in Action}

    def to_json(self) -> dict[str, Any]:
        return {"version": SETTINGS_VERSION, "effects_volume": self.effects_volume,
                "music_volume": self.music_volume, "fullscreen": self.fullscreen,
                "screen_shake": self.screen_shake, "hud_timer": self.hud_timer,
                "ghost": self.ghost, "game_speed": self.game_speed,
                "no_damage": self.no_damage, "keys": self.keys, "buttons": self.buttons}

    @property
    def assisted(self) -> bool:
        """An assist is on: a finish then sets no best time and leaves no ghost."""
        return self.no_damage or self.game_speed < DEFAULT_GAME_SPEED

    def rebind(self, action: str, name: str) -> str | None:
        """Bind ``action`` to the one key ``name`` (taken off the actions it may not share
        with); None when done, else why not (the bindings are then unchanged).

        >>> settings = Settings()
        >>> settings.rebind("jump", "x"), settings.keys["jump"]
        (None, ['x'])
        >>> settings.rebind("left", "d")
        "'d' is bound to both left and right, which cannot work together"
        """
        keys = {other: list(names) for other, names in self.keys.items()}
        keys[action] = [name]
        clash = _clash(keys)
        if clash is not None:
            return clash
        self.keys = keys
        return None

    @classmethod
    def from_json(cls, data: Any) -> tuple[Settings, list[str]]:
        """Settings from decoded JSON, and what had to be replaced by a default, and why."""
        settings = cls()
        if not isinstance(data, dict):
            return settings, ["it does not hold a JSON object, so every setting is a default"]
        problems: list[str] = []
        for name in ("effects_volume", "music_volume"):
            if name in data:
                value = data[name]
                if _is_number(value) and 0.0 <= value <= 1.0:
                    setattr(settings, name, float(value))
                else:
                    problems.append(f"{name} is {quoted(value)}, not a number from 0 to 1 "
                                    f"(using {getattr(settings, name)})")
        if "game_speed" in data:
            speed = data["game_speed"]
            if _is_number(speed) and speed in GAME_SPEEDS:
                settings.game_speed = int(speed)
            else:
                problems.append(f"game_speed is {quoted(speed)}, not one of "
                                f"{', '.join(map(str, GAME_SPEEDS))} (using "
                                f"{settings.game_speed})")
        for name in ("fullscreen", "screen_shake", "hud_timer", "ghost", "no_damage"):
            if name not in data:
                continue
            if isinstance(data[name], bool):
                setattr(settings, name, data[name])
            else:
                problems.append(f"{name} is {quoted(data[name])}, not true or false "
                                f"(using {json.dumps(getattr(settings, name))})")
        if "keys" in data:  # every action needs a key: the keyboard is always there
            _read_bindings(data["keys"], "keys", settings.keys, _key_name_or_none,
                           "key name pygame knows", False, problems)
        if "buttons" in data:  # a button list may be empty: the stick and d-pad still move
            _read_bindings(data["buttons"], "buttons", settings.buttons, _button_or_none,
                           f"button number from 0 to {MAX_BUTTON}", True, problems)
        for section, defaults in (("keys", _default_keys), ("buttons", _default_buttons)):
            clash = _clash(getattr(settings, section))
            if clash is not None:
                problems.append(f"{section}: {clash} (using the default {section})")
                setattr(settings, section, defaults())
        return settings, problems


def settings_file(directory: Path | None = None) -> JsonFile:
    """The settings file, in :func:`game.app.saves.data_dir` unless another folder is given."""
    return JsonFile((directory or data_dir()) / SETTINGS_FILE)


def _is_number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _key_name_or_none(value: object) -> str | None:
    """A stored key name in pygame's spelling (``"Left"`` -> ``"left"``), or None."""
    if not isinstance(value, str):
        return None
    code = key_code(value)
    return None if code is None else key_name(code)


def _button_or_none(value: object) -> int | None:
    """A gamepad button number, or None."""
    if isinstance(value, int) and not isinstance(value, bool) and 0 <= value <= MAX_BUTTON:
        return value
    return None


def _clash(bindings: dict[str, list[T]]) -> str | None:
    """Why these bindings cannot be played, or None: one key or button bound to two actions
    that cancel out or must be pressed apart.

    >>> _clash({"left": ["a"], "right": ["a", "d"]})
    "'a' is bound to both left and right, which cannot work together"
    >>> _clash({"up": ["w"], "jump": ["w"]}) is None
    True
    """
    for first, second in CLASHING_ACTIONS:
        shared = [entry for entry in bindings.get(first, []) if entry in
                  bindings.get(second, [])]
        if shared:
            return (f"{quoted_entry(shared[0])} is bound to both {first} and {second}, "
                    "which cannot work together")
    return None


def quoted_entry(entry: object) -> str:
    return repr(entry) if isinstance(entry, str) else str(entry)


def _read_bindings(data: object, section: str, bindings: dict[str, list[T]],
                   check: Callable[[object], T | None], what: str, allow_none: bool,
                   problems: list[str]) -> None:
    """Replace the defaults in ``bindings`` with each action's valid entries from ``data``.

    ``check`` turns one stored entry into its valid form, or None. Actions the game does
    not have are ignored. Bad entries are left out; an action left with none keeps its
    defaults, unless the file binds it to nothing on purpose (``[]``) and ``allow_none``.
    """
    if not isinstance(data, dict):
        problems.append(f"{section} is not an object of action names and lists "
                        "(using the defaults)")
        return
    actions = {action.value for action in Action}
    for action, entries in data.items():
        if action not in actions:
            continue
        if not isinstance(entries, list):
            problems.append(f"{section}.{action} is {quoted(entries)}, not a list "
                            f"(using {_listed(bindings[action])})")
            continue
        valid: list[T] = []
        for entry in entries:
            checked = check(entry)
            if checked is None:
                problems.append(f"{section}.{action}: {quoted(entry)} is not a {what} "
                                "(left out)")
            else:
                valid.append(checked)
        if valid or (allow_none and not entries):
            bindings[action] = valid
        else:
            problems.append(f"{section}.{action} has no usable entry "
                            f"(using {_listed(bindings[action])})")


def _listed(entries: list[T]) -> str:
    return ", ".join(str(entry) for entry in entries) or "none"
