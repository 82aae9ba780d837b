"""Gamepads without a gamepad: stick, d-pad and buttons as numbers and synthetic events."""

from __future__ import annotations

import pygame
import pytest

from game.app.gamepad import (
    BUTTON_A,
    BUTTON_B,
    BUTTON_START,
    STICK_DEAD_ZONE,
    STICK_MENU_PUSH,
    STICK_X_AXIS,
    STICK_Y_AXIS,
    Gamepads,
    PadReading,
    StickEdges,
    button_actions,
    hat_actions,
    pad_actions,
    pad_in_use,
    pad_nav,
    stick_actions,
)
from game.app.menus import Nav
from game.app.settings import Settings
from game.sim.inputs import NOTHING, Action

LEFT, RIGHT, UP, DOWN, JUMP = Action.LEFT, Action.RIGHT, Action.UP, Action.DOWN, Action.JUMP
BUTTONS = Settings().button_numbers()


def button(number: int, pad: int = 0) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYBUTTONDOWN, button=number, instance_id=pad)


def hat(x: int, y: int, pad: int = 0) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYHATMOTION, hat=0, value=(x, y), instance_id=pad)


def axis(number: int, value: float, pad: int = 0) -> pygame.event.Event:
    return pygame.event.Event(pygame.JOYAXISMOTION, axis=number, value=value, instance_id=pad)


class FakeJoystick:
    """Answers the questions :func:`game.app.gamepad.read_pad` asks a real joystick."""

    def __init__(self, axes: tuple[float, ...] = (0.0, 0.0),
                 hats: tuple[tuple[int, int], ...] = ((0, 0),), down: frozenset[int] = frozenset(),
                 buttons: int = 11) -> None:
        self.axes, self.hats, self.down, self.buttons = axes, hats, down, buttons

    def get_numaxes(self) -> int:
        return len(self.axes)

    def get_axis(self, number: int) -> float:
        return self.axes[number]

    def get_numhats(self) -> int:
        return len(self.hats)

    def get_hat(self, number: int) -> tuple[int, int]:
        return self.hats[number]

    def get_numbuttons(self) -> int:
        return self.buttons

    def get_button(self, number: int) -> bool:
        return number in self.down


@pytest.mark.parametrize("x, y", [(0.0, 0.0), (STICK_DEAD_ZONE * 0.9, -STICK_DEAD_ZONE * 0.9),
                                  (-0.1, 0.2)])
def test_a_stick_inside_the_dead_zone_moves_nothing(x: float, y: float) -> None:
    assert stick_actions(x, y) == NOTHING


def test_a_stick_past_the_dead_zone_moves_that_way_and_up_is_negative_y() -> None:
    assert stick_actions(0.9, 0.0) == {RIGHT}
    assert stick_actions(-0.9, 0.0) == {LEFT}
    assert stick_actions(0.0, -0.9) == {UP}
    assert stick_actions(0.7, 0.7) == {RIGHT, DOWN}


def test_the_dpad_hat_has_up_as_positive_y_and_diagonals_hold_both() -> None:
    assert hat_actions((0, 0)) == NOTHING
    assert hat_actions((0, 1)) == {UP}
    assert hat_actions((0, -1)) == {DOWN}
    assert hat_actions((1, -1)) == {RIGHT, DOWN}


def test_buttons_map_to_actions_by_the_settings_bindings() -> None:
    assert button_actions({BUTTON_A}, BUTTONS) == {JUMP}  # the default: A jumps
    assert button_actions({BUTTON_B, BUTTON_START}, BUTTONS) == NOTHING
    custom, _ = Settings.from_json({"buttons": {"jump": [2, 3], "down": [1]}})
    assert button_actions({3, 1}, custom.button_numbers()) == {JUMP, DOWN}


def test_a_pad_holds_its_stick_its_dpad_and_its_buttons_together() -> None:
    pad = PadReading(stick=(0.8, 0.0), hat=(0, 1), buttons=frozenset({BUTTON_A}))
    assert pad_actions(pad, BUTTONS) == {RIGHT, UP, JUMP}


def test_one_flick_of_the_stick_is_one_menu_step() -> None:
    edges = StickEdges()
    readings = [0.1, 0.4, STICK_MENU_PUSH + 0.1, 0.95, 1.0, 0.7]
    assert [edges.push(0, STICK_Y_AXIS, value) for value in readings] == [0, 0, 1, 0, 0, 0]


def test_the_stick_must_come_back_inside_the_dead_zone_before_it_steps_again() -> None:
    edges = StickEdges()
    assert edges.push(0, STICK_Y_AXIS, 0.9) == 1
    assert edges.push(0, STICK_Y_AXIS, STICK_DEAD_ZONE + 0.05) == 0  # hysteresis: not yet
    assert edges.push(0, STICK_Y_AXIS, 0.9) == 0
    assert edges.push(0, STICK_Y_AXIS, 0.0) == 0
    assert edges.push(0, STICK_Y_AXIS, -0.9) == -1


def test_each_pad_and_axis_has_its_own_edges_and_an_unplugged_pad_is_forgotten() -> None:
    edges = StickEdges()
    assert edges.push(0, STICK_Y_AXIS, 0.9) == 1
    assert edges.push(1, STICK_Y_AXIS, 0.9) == 1
    assert edges.push(0, STICK_X_AXIS, 0.9) == 1
    edges.forget(0)
    assert edges.push(0, STICK_Y_AXIS, 0.9) == 1
    assert edges.push(1, STICK_Y_AXIS, 0.9) == 0


def test_in_menus_a_confirms_b_goes_back_and_start_pauses() -> None:
    edges = StickEdges()
    assert pad_nav(button(BUTTON_A), edges, playing=False) is Nav.CONFIRM
    assert pad_nav(button(BUTTON_B), edges, playing=False) is Nav.BACK
    assert pad_nav(button(BUTTON_START), edges, playing=False) is Nav.PAUSE
    assert pad_nav(button(4), edges, playing=False) is None


def test_in_menus_the_dpad_and_the_stick_move_up_and_down() -> None:
    edges = StickEdges()
    assert pad_nav(hat(0, 1), edges, playing=False) is Nav.UP
    assert pad_nav(hat(0, -1), edges, playing=False) is Nav.DOWN
    assert pad_nav(hat(0, 0), edges, playing=False) is None  # letting go is not a press
    assert pad_nav(axis(STICK_Y_AXIS, 0.9), edges, playing=False) is Nav.DOWN
    assert pad_nav(axis(STICK_Y_AXIS, 1.0), edges, playing=False) is None
    assert pad_nav(axis(STICK_Y_AXIS, 0.0), edges, playing=False) is None
    assert pad_nav(axis(STICK_Y_AXIS, -0.9), edges, playing=False) is Nav.UP
    assert pad_nav(axis(STICK_X_AXIS, -0.9), edges, playing=False) is None


def test_while_playing_only_start_reaches_the_menus() -> None:
    edges = StickEdges()
    for event in (button(BUTTON_A), button(BUTTON_B), hat(0, -1), axis(STICK_Y_AXIS, 0.9)):
        assert pad_nav(event, edges, playing=True) is None
    assert pad_nav(button(BUTTON_START), edges, playing=True) is Nav.PAUSE


def test_the_stick_held_through_play_does_not_step_the_menu_that_opens() -> None:
    edges = StickEdges()
    assert pad_nav(axis(STICK_Y_AXIS, 0.9), edges, playing=True) is None
    assert pad_nav(axis(STICK_Y_AXIS, 0.95), edges, playing=False) is None


def test_a_pad_pulled_out_mid_play_pauses_but_not_in_a_menu() -> None:
    removed = pygame.event.Event(pygame.JOYDEVICEREMOVED, instance_id=0)
    assert pad_nav(removed, StickEdges(), playing=True) is Nav.PAUSE
    assert pad_nav(removed, StickEdges(), playing=False) is None


def test_the_last_device_pressed_is_the_one_in_use() -> None:
    key = pygame.event.Event(pygame.KEYDOWN, key=pygame.K_a)
    assert pad_in_use(button(BUTTON_A), False) is True
    assert pad_in_use(key, True) is False
    assert pad_in_use(pygame.event.Event(pygame.MOUSEMOTION, pos=(0, 0)), True) is True


def test_gamepads_hold_nothing_until_a_pad_is_plugged_in() -> None:
    pads = Gamepads()
    pads.handle(pygame.event.Event(pygame.JOYDEVICEREMOVED, instance_id=42))  # unknown: fine
    assert pads.held(BUTTONS) == NOTHING


def test_every_pad_plugged_in_adds_what_it_holds_and_a_removed_one_stops() -> None:
    pads = Gamepads()
    pads.pads[3] = FakeJoystick(axes=(-0.9, 0.0))
    pads.pads[5] = FakeJoystick(hats=((0, 1),), down=frozenset({BUTTON_A}))
    assert pads.held(BUTTONS) == {LEFT, UP, JUMP}
    pads.handle(pygame.event.Event(pygame.JOYDEVICEREMOVED, instance_id=5))
    assert pads.held(BUTTONS) == {LEFT}


def test_a_pad_with_no_hat_and_one_axis_reads_as_centred() -> None:
    pads = Gamepads()
    pads.pads[0] = FakeJoystick(axes=(0.0,), hats=(), down=frozenset({1}), buttons=2)
    assert pads.held(BUTTONS) == NOTHING
