"""The options screen's rows: what each one shows and what a press on it changes.

Where it sits: between the menus (:mod:`game.app.menus`, which moves the lit row and turns a
press into a :class:`~game.app.menus.ChangeOption` or a
:class:`~game.app.menus.RebindKey`) and the settings (:mod:`game.app.settings`), which keep
the values and save them where ``settings.json`` has always been. The window carries out
the change and applies it at once (:meth:`game.app.window.GameWindow.change_option`); the
screen (:func:`game.app.screens.draw_options`) shows :func:`option_rows`.

The rows: music and effect volumes, the HUD's timer, fullscreen, the ghost of the best run
(:mod:`game.app.ghosts`), a key for each of left, right, down and jump, and the **Assist**
section: game speed (50 to 100 % of real time) and no damage. A level played with an assist
on is marked in the tally and the win table and sets no best time and no ghost.

What it teaches: **the options are a table of rows over one value.** Each row is a name, a
way to show its value and a way to change it; :func:`change` returns new settings rather
than poking the window's, so a test can walk every row without a window.

>>> settings = change(Settings(), MUSIC, +1)
>>> settings.music_volume, option_rows(settings)[0]
(0.6, ('Music volume', '60 %'))
>>> change(Settings(), GAME_SPEED, -1).game_speed, change(Settings(), NO_DAMAGE, +1).no_damage
(90, True)
"""

from __future__ import annotations

from dataclasses import replace

from game.app.settings import GAME_SPEEDS, Settings
from game.sim.inputs import Action

MUSIC, EFFECTS, TIMER, FULLSCREEN, GHOST = (
    "Music volume", "Effects volume", "Timer", "Fullscreen", "Ghost")
KEY_ACTIONS = (Action.LEFT.value, Action.RIGHT.value, Action.DOWN.value, Action.JUMP.value)
KEY_ROWS = tuple(f"Key: {action}" for action in KEY_ACTIONS)  # the simulation never reads up
GAME_SPEED, NO_DAMAGE, BACK = "Game speed", "No damage", "Back"
OPTION_ITEMS = (MUSIC, EFFECTS, TIMER, FULLSCREEN, GHOST, *KEY_ROWS, GAME_SPEED, NO_DAMAGE, BACK)
ASSIST_FIRST = OPTION_ITEMS.index(GAME_SPEED)  # the Assist section's heading goes above it
VOLUME_STEPS = 10  # a volume moves in tenths, from 0 to 1
PRESS_A_KEY = "press a key"  # a key row's value while it waits for the new key


def key_action(item: str) -> str | None:
    """The action a key row rebinds, or None for any other row.

    >>> key_action("Key: jump"), key_action(GHOST)
    ('jump', None)
    """
    return KEY_ACTIONS[KEY_ROWS.index(item)] if item in KEY_ROWS else None


def _volume(value: float, step: int) -> float:
    return min(VOLUME_STEPS, max(0, round(value * VOLUME_STEPS) + step)) / VOLUME_STEPS


def _with(settings: Settings, name: str, value: object) -> Settings:
    """A copy of ``settings`` with one value changed."""
    changed = replace(settings)
    setattr(changed, name, value)
    return changed


def change(settings: Settings, item: str, step: int) -> Settings:
    """The settings after a press on ``item``: ``step`` +1 (right, or Enter) or -1 (left).
    A volume or the game speed moves one notch and stops at its ends; a switch flips either
    way; a key row and Back change nothing here."""
    if item in (MUSIC, EFFECTS):
        name = "music_volume" if item == MUSIC else "effects_volume"
        return _with(settings, name, _volume(getattr(settings, name), step))
    if item == GAME_SPEED:
        at = GAME_SPEEDS.index(settings.game_speed)
        return replace(settings, game_speed=GAME_SPEEDS[
            min(len(GAME_SPEEDS) - 1, max(0, at + step))])
    switches = {TIMER: "hud_timer", FULLSCREEN: "fullscreen", GHOST: "ghost",
                NO_DAMAGE: "no_damage"}
    if item in switches:
        return _with(settings, switches[item], not getattr(settings, switches[item]))
    return settings


def _on_off(value: bool) -> str:
    return "on" if value else "off"


def option_rows(settings: Settings, waiting_for: str | None = None
                ) -> list[tuple[str, str]]:
    """Each row's name and value as shown; ``waiting_for`` is the action whose key row waits
    for a key press."""
    values = {MUSIC: f"{round(settings.music_volume * 100)} %",
              EFFECTS: f"{round(settings.effects_volume * 100)} %",
              TIMER: _on_off(settings.hud_timer), FULLSCREEN: _on_off(settings.fullscreen),
              GHOST: _on_off(settings.ghost), GAME_SPEED: f"{settings.game_speed} %",
              NO_DAMAGE: _on_off(settings.no_damage), BACK: ""}
    for row, action in zip(KEY_ROWS, KEY_ACTIONS, strict=True):
        values[row] = (PRESS_A_KEY if action == waiting_for
                       else ", ".join(settings.keys.get(action, [])))
    return [(item, values[item]) for item in OPTION_ITEMS]
